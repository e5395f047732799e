// The random-scene soak's findings (soak/known_findings.txt, issue 16), one scene file each in
// data/ (soak-seed-N.json; soak-seed-N-g2.json for a scene of the generator since it draws both
// ways of giving a soft body's damping): bodies leaving the closed box, and energy growing past
// the bound of docs/physics.md, "Energy in a closed box". The fixed ones run as regression tests (each failed before its fix);
// an open one would be disabled (there is none). When a seed is fixed, take it off
// known_findings.txt and out of the disabled list here, into the enabled one. Run them all with
//   soak_tests --gtest_also_run_disabled_tests --gtest_filter='*SoakFindings*'

#include "model/scene_io.h"
#include "soak/soak_constants.h"
#include "soak/soak_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace impetus::soak {
namespace {

class SoakFinding : public ::testing::TestWithParam<std::string> {};

TEST_P(SoakFinding, RunsTenSecondsInTheBoxWithinTheEnergyBound)
{
    const std::string path = std::string(IMPETUS_SOAK_DATA_DIR) + "/soak-seed-" + GetParam() + ".json";
    const model::SceneLoadResult loaded = model::loadSceneFile(path);
    ASSERT_TRUE(loaded.ok()) << path;
    const SoakResult result = runSoakScene(*loaded.world, kSoakTime);
    EXPECT_FALSE(result.finding) << "seed " << GetParam() << ": " << result.finding->check << " at t = "
                                 << result.finding->time << " s: " << result.finding->detail;
}

std::string seedName(const ::testing::TestParamInfo<std::string>& seed)
{
    std::string name = "seed" + seed.param;
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
}

// Fixed: 30, 65, 141, 145 and 166 by main's impact and angular-momentum work (merged at
// b52cb64); 68 and 136, a body of a few grams under drag whose velocity the whole step made grow,
// by the drag substeps (Simulation, dragSubsteps); 3, 4, 8, 17, 117, 142, 149, 153, 182, 183, 188
// and 193, joints that asked a body struck late in the step for an unbounded velocity, by the
// floor on its share of the step (joint_solver.cpp, kMinStruckShare); 176, an 18 g circle spinning
// at 800 rad/s that slid a metre along the ceiling before meeting it and was struck half-way back
// to where the contact was found, off its normal line, by the impact pass striking a sole circle at
// its own facing point (contact_impacts.cpp, impactPointOf). 65 and 86 no longer failed at main's
// 30e9f6e, before that fix (in the release build and the sanitized soak alike). 18, 27, 49, 51,
// 61, 66, 69, 87, 121 and 195, jointed scenes that gained energy or left the box, by joints that
// no longer close their error with velocity (joint_solver.cpp, solveVelocities). 144 and 191, a
// light body on a short rod sent off at thousands of m/s by passes that pulled the wrong way, by
// the rod's pass holding the velocity along the rod there instead. 111 (this build only) and 189,
// soft bodies pinned to rigid ones, by the soft body following its joints' position passes and
// their take-back of the angular momentum pass by pass (Simulation::substep). 104-g2 and 111-g2,
// light bodies pressed into the floor by a heavy soft body or a heap above them, and the earlier
// generator's 92, by passes that take the contacts with fixed bodies last (ContactSolver::partition).
// 31, a 3.2 g body wedged into the ceiling's corner by a 797 kg box sliding along the ceiling, by
// props (ContactSolver::findProps): the box now rests on the light body as on the wall behind it.
// 131, 131-g2, 201, 264, 306 and 335, soft bodies that spun themselves up under explicit Euler
// (or, 201, were flung out of a corner under RK4), by each grid keeping the angular momentum the
// outside torque gives it through the integrator's step (SpinKeeper, integration/spin_keeper.h).
// 239, a 7 kg box between a pin to the world and a pin to a 0.6 t polygon, spun to 360 rad/s by
// pin passes one at a time (the energy grew 56,000-fold in 0.2 s), by pins that share moving
// bodies being solved together (joint_solver.cpp, PinBlock). 1135, a 5 t ellipse and a 4.6 t
// circle pinned to the world and to each other, the hinges almost in a line, sent off at 626 m/s
// in the first step by the pins' arcs, by such a block keeping its tangents
// (JointSolver::keepArcsIfSound). 1437 and 2163, light bodies joined by rods and pins to heavy
// ones pressed through a wall, by islands of unlike masses solved whole (dynamics/unlike_masses.h);
// 1995 and 2638, zero-g scenes whose energy the turn that keeps a closed island's angular momentum
// pumped up (a rod's stretch pulled in, a soft body), by that turn adding no more than a millionth
// of the island's kinetic energy a step (IslandSpin::keep). 2429, a soft box so small that its
// grid was one ellipse, pinned 2 m from its centre to a circle: the grid's angle, fitted to no
// lattice, came out 0 instead of 1.8 rad, and the pin tore the bodies apart in the first step;
// a grid now has two cells at least, and a grid of one ellipse keeps its angle. 3419, a soft
// star whose one ellipse is the only cell centre of four inside it, pinned to the world 1 m from
// its centre: out of the box in the first step, for the same reason. 3433, a soft ball of
// 449 kg at 25 m/s that pressed a 0.33 kg ellipse through the right wall, and 2323 and 2822, light
// bodies pressed through the floor beside soft bodies, by a soft body's ellipses being heavy
// bodies that props stop, and props from ten times the mass (ContactSolver::findProps). 3503, a
// spinning soft circle whose energy seemed to grow 18 % in the first step, as the soak measured
// the start's on the rigid body, and the rest on its grid (soak_run.cpp). 3641, an ellipse at
// 83 m/s on a rod of 0.3 m to the world, whose world gained a fifth of its energy in one step of
// 1/240 s, by steps split until a rod turns 0.2 rad at most a substep (spinSubsteps); and with it
// 2468, a soft polygon pinned to the world beside a circle on a rod and a pin to the world, whose
// energy rose 87 % in 0.9 s. 331, 417, 520, 1352, 1489, 2026, 2833, 2840, 2932, 3937 and 4386
// (described below, with the open ones, as they were found), bodies spun up against a wall by an
// impact or a joint's pull among masses more than ten times apart, whose contact and joint rows,
// linear in the spin, the spin met while the bodies went on into the wall (or, 1352, fed its
// energy), by such worlds' steps being split until no body turns more than 0.1 rad a substep
// (spinSubsteps; an eighth of a turn before). 5812, a 4.4 t polygon at 51 m/s on a rod to the
// world, whose energy grew 2.6 % a second (RK4, drag, 1/240 s; 0.100011 of the energy above the
// floor at 6.2 s), by rods being split to 0.1 rad a substep (0.2 before). 3446, 3785, 6097, 6257
// and 7042 (soft bodies joined to far heavier or lighter bodies, or beside such an island), and
// 1210, 4458, 4870 and 6327 (light bodies on rods and pins to heavy ones; all described below as
// they were found), by the islands of unlike masses taking soft bodies in as their grids'
// aggregates (in the velocity solve; an island with one is left to the position passes) and their
// joints starting the next step cold (JointSolver::forgetImpulses): the passes' sums of a step
// whose outcome the island replaced, handed on as the next warm start, grew step by step (a soft
// box welded by a pin and a rod to a polygon, 1352, spun its grid to 2,357 rad/s in the passes).
// 5292, whose 106 kg ellipse on a rod of 2.8 cm to the world gained 8 % of its energy a second, by
// a rod to the world following its anchor on the arc of the body's turn as each pass finds it
// (JointSolver::solveVelocities; test RodJoint.AFastTumblingEllipseOnAShortRodKeepsItsEnergy).
// 8426, new with that rule and fixed with it: a 3.7 t soft box at 64 m/s on a rod to the world,
// on stiff springs to a pinned circle and a polygon (RK4, sideways gravity, 1/240 s), following
// its grid's turn, fitted afresh each pass, was flung out of the box at 7.3 s; a soft body's rod
// keeps the first turn's arc.
// 2087, 2146, 4062, 6118, 6715, 6738, 8187, 8336, 9217 and 9742 (light bodies, or a soft body's
// ellipses, driven into a wall by joints to far heavier bodies; described below as they were
// found) by the fixed-body guard (collision/fixed_body_guard.h): a centre whose path in a substep
// enters a fixed body is put back where it entered, as Box2D v3 sweeps a shape's centroid against
// static shapes. It stops the escape, not the solve's failure: those bodies still end a substep
// half in the wall where the passes cannot hold them (FixedBodyGuard tests, docs/physics.md).
// 2173 and 3477, found by the run of the 10⁴ seeds again with the guard (docs/testing.md): a soft
// body whose grid was crushed until its ellipses nearly met (2173: a 44 kg box of two ellipses,
// 3 mm apart, pressed against the right wall by a 2 t circle, pinned and on a rod to a 269 kg
// ellipse; RK4, zero gravity, 1/240 s; 75 kJ became 10.6 MJ in one step at 4.4 s), whose moment
// of inertia, near zero, turned the springs' and joints' torque on it into millions of rad/s²,
// by the smooth forces turning a grid as if it kept a quarter of its rest lattice's inertia at
// least (constants::kSoftMinInertiaFraction; SoftBody.ASpringTurnsAGridCrushedUntil...). 3239 (a
// two-ellipse soft body pinned 4 m from its centre to a 1 t ellipse at 70 m/s: 0.5 MJ to 3.4 MJ
// in two steps) failed when the floor was first put on the aggregate itself, which the joints see
// too: they then handed the ellipses a turn of the momentum they computed for the larger inertia.
// 1014 and 4961 (told of below, as they were found), soft bodies whose grids were struck through
// themselves or torn while a joint held them metres from their centres, by the grid's frame
// turning continuously (softAggregate): a turn of the best fit is taken in the half turn nearest
// (a flip is not followed), and a grid crushed, turned inside out or torn turns its frame as its
// ellipses turn about their centre, not as its best fit, a guess, does (tests
// SoftGrid.TwoEllipsesThatSwapPlaces... and SoftBody.TwoEllipsesStruckThroughEachOther...).
INSTANTIATE_TEST_SUITE_P(SoakFindings, SoakFinding,
                         ::testing::Values("2", "3", "4", "8", "17", "18", "27", "30", "31", "49", "51", "61",
                                           "65", "66", "68", "69", "86", "87", "92", "111", "117", "121", "131",
                                           "136", "141", "142", "144", "145", "146", "149", "153", "166", "176",
                                           "182", "183", "188", "189", "191", "193", "195", "201", "239", "264",
                                           "306", "335", "1135", "1437", "1995", "2163", "2323", "2429", "2638",
                                           "2468", "2822", "3419", "3433", "3503", "3641", "331", "417",
                                           "520", "1352", "1489", "2026", "2833", "2840", "2932", "3937",
                                           "4386", "5812", "104-g2", "111-g2", "131-g2", "1210", "3446", "3785",
                                           "4458", "4870", "6097", "6257", "6327", "7042", "5292",
                                           "8426", "104", "140", "177", "2087", "2146", "4062", "6118", "6715",
                                           "6738", "8187", "8336", "9217", "9742", "2173", "3477", "3239",
                                           "1014", "4961"),
                         seedName);

// Fixed, the earlier generators' 104, 140 and 177 (in the list above since 2026-11-29): they were
// kept disabled after they began to pass, until they had kept passing for a while, which they
// have through every change since the props came. Their story: the soak as it runs now has no known finding (soak/known_findings.txt); 131-g2 was its
// last, until the soft grids kept their angular momentum; 104-g2 and 111-g2 were too until the contacts with fixed bodies went last, which brought 31 (a
// 3.2 g body pressed into the ceiling by a 797 kg one: the same kind as 104 and 111), fixed by props. The generator draws a soft
// body's damping as a ratio or as a coefficient since 2026-11-27 (before, the coefficient it drew
// was left unused and every soft body had the default ratio), which changed every scene with a
// soft body. 104, 131, 140 and 177 are the earlier generators' scenes: 104 and 140 passed in the
// sanitized soak build (-O1) while one or the other failed in this one (-O3), as the scenes are
// chaotic and the two builds round differently; both pass in this one since props came. 177's
// scene was stored again on 2026-11-27 as the generator then made it (its soft body with the
// default damping ratio; the file had the unused coefficient). 131-g2's first finding, an ellipse
// struck to 2,233 rad/s that passed through the wall at 0.25 s, was fixed by splitting
// fast-spinning steps (controller::spinSubsteps; its own test is
// Tunnelling.FastSpinningEllipseBouncesOffAWall); it then failed at 1.04 s on a soft body
// driven to hundreds of m/s under explicit Euler, which the grids' kept angular momentum fixed.

// Beyond the 200 seeds that ctest runs (docs/testing.md, "Beyond the 200"), none is open: every
// one told of here is fixed (above). 1014, found by the run of the 10⁴ seeds with the
// guard and the inertia floor: a 31 kg soft polygon of two ellipses pinned 3 m from its centre to
// a 21 kg circle on stiff springs to the world (RK4, 1/240 s), whose grid collapses in one step at
// 0.33 s (its inertia from 1.0 to 0.06 of its rest lattice's) with a 35 % rise of the energy; it
// passed without the floor, which 2173 and 3477 need (its grid was struck through itself by the
// circle, and its best fit flipped by half a turn: 5.44 to 2.09 rad). Of the six findings of seeds 201 to 400, 201, 239, 264, 306 and 335 are fixed (above),
// and so are 331, 417, 520, 1352, 1437, 1489, 1995, 2026, 2163, 2323, 2429, 2468, 2638, 2822, 2833, 2840, 2932,
// 3937 and 4386 of those below, which tell each one as it was found. 331: a light
// ellipse squeezed into a wall by a heavy body dragged along by a pin. From the long run of seeds
// 401 on: 417, a soft circle pinned and on rods to a 2 t ellipse flying at 76 m/s, pressed
// through the right wall at 0.1 s (RK4, zero gravity); 520, a soft circle in a triangle of pins
// with a 158 t/m² polygon and a 1.1 t circle, springs of 0.6 and 9.4 MN/m, leaving by the
// ceiling's corner at 1.7 s (explicit Euler). From seeds 1001–1300: 1210, a 49 g polygon on a
// rod to a 121 g one pinned to an 11 kg one, among bodies of 1.3 t, pressed through the floor
// at 0.25 s (explicit Euler, zero gravity). From seeds 1301–1600, all three of joints between
// bodies of very unlike masses: 1352, a 3.2 t box welded to a polygon by a pin and a rod side by
// side, the pin's hinge metres from both, which after 2.2 s on the floor flings the polygon off at
// 1,500 m/s (RK4, drag); 1437, a 13.8 kg polygon on a rod to a 1.2 t one that the pin to an
// ellipse and a 9.3 t circle at 88 m/s press through the ceiling in 8 steps of 1/120 s (RK4,
// zero gravity); 1489, a soft box on a rod to an ellipse, one of its ellipses through the floor
// at 1.9 s (RK4, 1/60 s). From seeds 1601–2199 and 2501–2800, joints or stiff springs between
// bodies of unlike masses again: 1995, a rod from a 68 kg polygon at 47 m/s to a box, whose energy
// grows by 84 % in 3.5 s (semi-implicit Euler, zero gravity); 2026, a 15 g ellipse on two springs
// to a polygon, out of the box at 0.17 s (RK4, sideways gravity); 2087, a 3.2 kg ellipse on a rod
// to an 82 kg polygon pinned to a 4.9 t one, out in 2 steps of 1/60 s (semi-implicit Euler);
// 2146, a 7 g ellipse on a rod and a pin to another ellipse, through the floor at 1.5 s (explicit
// Euler); 2163, an ellipse pinned to a polygon pinned to the world, beside an 8.6 t ellipse pinned
// to the world on a spring of 29 kN/m to that polygon, through the floor at 5.8 s (RK4); 2638, a
// 1.4 g soft circle in a box with an ellipse pinned to the world, its energy ten times its start's
// in 0.46 s (semi-implicit Euler, zero gravity).
// From seeds 2200–2500, all three with a soft body joined by joints (which the islands of unlike
// masses then left to the passes): 2323, a 1 g box on a rod to a 2.6 g polygon, among a soft ellipse
// on two rods to a circle, through the floor at 1.7 s (explicit Euler); 2429, a soft box of
// 150 t/m² pinned twice to a circle pinned to a 373 kg one, the energy 39 % up in the first step
// of 1/60 s (RK4, drag); 2468, a soft polygon pinned to the world and a circle on a rod and a pin
// to it, 87 % up in 0.9 s (RK4, sideways gravity). From seeds 2801–3400: 2822, a 1 g polygon
// pinned to a light ellipse pinned to a 3 g circle, beside a soft box, through the floor at 2.1 s
// (RK4); 2833, a 413 kg ellipse on a rod to a polygon of 11 t/m² at 52 m/s, spinning at 200 rad/s
// against the right wall, out in 11 steps (explicit Euler; the masses under ten times apart);
// 2840, a soft ellipse pinned twice to a 1.9 t polygon at 83 m/s, an ellipse through the floor at
// 0.23 s (semi-implicit Euler); 2932, a soft polygon on a rod to a polygon of 24 t/m² and on a
// spring of 68 kN/m to a circle, an ellipse through the left wall at 0.72 s (explicit Euler,
// zero gravity, 1/60 s). From seeds 3401 on: 3446, a 50 g L-shaped polygon on a rod to a 4.1 kg
// box at 46 m/s, pinned to a 127 kg soft polygon, out at the top-left corner at 0.7 s (RK4,
// sideways gravity, drag, 1/60 s); 4458, a 4 kg ellipse on a rod to a 354 kg circle at 45 m/s,
// through the left wall at 0.075 s (semi-implicit Euler, 1/120 s): the island's exact answer
// spins the ellipse at 1,100 rad/s about its contact, which the island's guard refuses, as in 2087.
// From seeds 3782-4400: 3785, a 406 kg soft box pinned to the world and on a spring of 212 kN/m
// to an 8.1 t polygon at 74 m/s, one of its ellipses through the right wall at 1.6 s
// (semi-implicit Euler, zero gravity, 1/240 s); 3937, a 1.2 kg ellipse on a rod to a 113 kg
// circle that a rod to a 2.2 t triangle at 97 m/s yanks, through the ceiling at 0.05 s (RK4,
// sideways gravity, drag, 1/60 s; a circle or a box in its place stays in); 4062, a 10 kg soft
// polygon on a pin and a rod to a 440 kg box on a rod to a 1.4 t polygon at 78 m/s, out at the
// ceiling's left corner at 0.37 s (semi-implicit Euler, 1/60 s); 4386, a 54 g ellipse on a rod
// to a 0.59 kg ellipse that pushes it into the ceiling, out at 0.28 s (explicit Euler, 1/120 s):
// its impact and the passes spin it at 89, then 148 rad/s, which meets the contact's row (linear
// in the velocities: the touching point leaves the ceiling) while the centre goes on into it.
// From seeds 4813-5490, three whose energy grew just past the bound, 0.10-0.18 of the energy above
// the floor (found with the eighth of a turn; 4858 and 4868, two escapes, passed once worlds of
// unlike masses were split to 0.1 rad): 4870, a 24 kg box pinned to the world and on rods to a
// 203 kg and a 7.8 kg polygon (RK4, 1/120 s), at 5.0 s; 4961, a 1.8 t soft polygon pinned to a
// 480 kg circle at 50 m/s, with springs of 413 and 6.7 kN/m beside the pin (semi-implicit Euler,
// zero gravity, 1/240 s), at 0.77 s; 5292, a 106 kg ellipse at 77 m/s on a rod to the world, beside
// a 1 g soft circle on soft springs (RK4, 1/60 s), at 3.9 s. From seeds 5491-6457, three more soft
// bodies joined by joints to other bodies: 6097, a 1.2 t soft ellipse on a rod and a pin to a 33 kg
// polygon and on a rod to an 863 kg one, its energy ten times its start's at 0.23 s (semi-implicit
// Euler, 1/240 s); 6118, a 1 t soft body on two pins and a rod to a 3.4 t polygon, an ellipse
// through the ceiling at 0.04 s (semi-implicit Euler, zero gravity, 1/240 s); 6257, a 0.86 kg soft
// body on a rod to a 76 kg polygon at 68 m/s and pinned to a 0.53 kg body, which leaves by the left
// wall at 0.44 s (RK4, drag, zero gravity, 1/240 s). And 6327, a 43 g box welded by a pin and two
// rods to a 3.4 kg circle on a spring to the world, out through the ceiling at 2.35 s (explicit
// Euler, 1/240 s). From seeds 7033 on, with 0.1 rad splits for spins among unlike masses and for
// rods: 7042, a 42 g box on a pin and a rod to a 1.1 kg polygon pinned to a 12 kg ellipse at 98
// m/s, beside a 3.4 t soft box at 81 m/s, through the floor at 0.125 s (semi-implicit Euler, 1/240
// s; the islands of unlike masses then left worlds with soft bodies to the passes). From seeds
// 6458-10000, run once the islands took soft bodies in: 6715, a 908 kg soft ellipse at 42 m/s
// pinned to a 30 kg polygon pinned to the world, which goes out through the floor at 1.6 s (RK4,
// 1/120 s; it failed before too, at 1.9 s); 6738, a 4.4 kg soft polygon pinned to a 401 kg polygon
// pinned to a 519 kg one at 87 m/s, whipped into the left wall at 75 m/s and through it at 0.4 s
// (semi-implicit Euler, 1/120 s), which passed while the islands left soft bodies to the passes
// (the island treats the grid, crushed against the wall, as rigid). And three that failed before
// this session's changes too: 8187, a 236 kg soft ellipse at 35 m/s on a rod to a 2.8 t polygon
// pinned to a 118 kg one on a rod to a 5.6 t one, with springs of 124 and 262 kN/m, through the
// ceiling at 0.26 s (explicit Euler, zero gravity, 1/120 s); 8336, a 18 kg soft circle at 71 m/s
// pinned to a 59 kg circle pinned to a 0.69 kg ellipse, the ellipse out by the right wall at 1.0 s
// (semi-implicit Euler, zero gravity, 1/60 s); 9217, a 290 kg soft circle pinned to a 3.9 t and a
// 1.5 t polygon, one of its ellipses through the ceiling at 1.4 s (RK4, sideways gravity, 1/120 s).
// 9742, new with the joints of solved islands starting cold: a 1.4 g polygon on a rod to a 13 g
// one pinned to a 95 g one, through the floor at 1.44 s (semi-implicit Euler, 1/240 s); it passes
// with the warm start kept, which 1210, 1352, 4458, 4870, 6097 and 6327 need gone (halved, 1210
// and 2932 fail).

} // namespace
} // namespace impetus::soak
