#pragma once
/// \file constants.h
/// Every tuning constant of the engine, with its unit and the reason for its value.

#include "model/scalar.h"
#include <cstddef>

namespace impetus::constants {

/// Default fixed time step, s. 1/240 s is four physics steps per 60 Hz frame: small enough that
/// RK4 is accurate to ~1e-9 on classroom oscillators (ω ≲ 20 rad/s) and that explicit Euler's
/// energy drift stays visible but slow, which is what a lesson on integrators wants to show.
inline constexpr Scalar kDefaultTimeStep = 1.0 / 240.0;

/// Standard gravity, m/s², used as the default gravity (0, −kStandardGravity).
inline constexpr Scalar kStandardGravity = 9.81;

/// Two polygon vertices closer than this, relative to the polygon's size (the diagonal of its
/// bounding box), are the same point. 1e-9 is far below anything a user can draw (a micrometre on
/// a kilometre-sized shape) but well above double rounding (~1e-16).
inline constexpr Scalar kRelativePointTolerance = 1e-9;

/// A polygon whose area is below this fraction of its bounding-box diagonal squared has no area.
/// Same reasoning as kRelativePointTolerance, squared because it is an area.
inline constexpr Scalar kRelativeAreaTolerance = 1e-12;

// ---- Contacts and joints (controller/contact_solver, joint_solver) -------------------------

/// Penetration the position correction leaves alone, m. Resting bodies sink this far into each
/// other at most, so that contacts stay active from step to step instead of flickering. 0.5 mm is
/// below a pixel at any classroom zoom ("no visible skin") yet keeps 100-box stacks quiet.
inline constexpr Scalar kLinearSlop = 0.0005;

/// Fraction of the remaining penetration (beyond the slop) removed per position iteration. 0.2 is
/// the usual choice for non-linear Gauss–Seidel: larger overshoots and jitters in deep stacks.
inline constexpr Scalar kPositionCorrectionFactor = 0.2;

/// Largest position correction in one iteration, m. Keeps a deep overlap (a body dropped inside
/// another) from being expelled in a single violent jump.
inline constexpr Scalar kMaxPositionCorrection = 0.2;

/// Speculative margin every pair gets even at rest, m: contacts are created this far before the
/// surfaces touch, so resting and slow bodies never start a step already overlapping.
inline constexpr Scalar kSpeculativeMargin = 4 * kLinearSlop;

/// Approach speeds below this are contact, not impact: no bounce, m/s. Tiny (1 cm/s) because the
/// solver measures approach with the velocity from before gravity's step is added, so a resting
/// body approaches at ~0 m/s, not at g·h; a bouncing ball therefore settles only when its bounces
/// are below ~5 µm high.
inline constexpr Scalar kRestitutionThreshold = 0.01;

/// A contact that carried load in the last step (a resting contact) is struck only by a blow
/// faster than this, m/s, and only after an impact has hit one of its bodies in the step. 10 cm/s
/// is ten times the bounce threshold and well above the 1–2 cm/s at which a tall stack settles
/// between steps, so a struck ball passes its blow on through the ball it rests on, while a
/// settling pyramid never sets off a cascade of tiny impacts.
inline constexpr Scalar kRestingImpactThreshold = 0.1;

/// A contact point within this distance (or carrying impulse) counts as touching, m: the same
/// tolerance the position correction allows.
inline constexpr Scalar kTouchDistance = kLinearSlop;

/// The longest step the contact and joint solvers take, s. A world step longer than this is split
/// into equal substeps, each a full pass of every phase (collisions, impacts, forces, contacts,
/// joints, positions), so that stacking, friction, joints and impacts hold at any step a user
/// picks: 1/60 s runs as four substeps of 1/240 s, 1/30 s as eight. 1/240 s is the step at which
/// the solver is tested and tuned (a 100-row pyramid stands, Newton's cradle is exact), and below
/// which it is not split. docs/physics.md, "Time step and substeps".
inline constexpr Scalar kMaxSolverStep = 1.0 / 240.0;

/// A split step of a rigid world finds its contacts once for all its substeps when no body can
/// move farther than this over the whole step (speed plus spin at its bounding radius, times the
/// step), m. Found once, the contacts need margins for the whole step, and every dynamic body's
/// margin also covers twice a striker's travel (a body at rest may be struck and set moving): in a
/// pile at rest that adds nothing, but among bodies moving at metres per second (rain, a tumbling
/// box of circles at 1/60 s) it made three times as many speculative contacts as margins for one
/// substep, and the step cost 2.5 times as much. The constant speculative margin: a step whose
/// fastest body moves less than it keeps margins within twice a substep's.
inline constexpr Scalar kReuseContactsMaxTravel = kSpeculativeMargin;
/// A dynamic body may also travel up to this fraction of its bounding radius in a step whose
/// contacts are found once (and at most kReuseContactsMaxBodyTravel): the speculative contacts
/// that a whole step's margins add are the neighbours within the margin, few while the margin is a
/// small part of the bodies' size. A base-100 pyramid settling at 1/60 s moves thousands of its
/// boxes 2–10 mm a step (1 m boxes, 1.4 % of their bounding radius at the most) for its first four
/// seconds: found per substep they cost 25 ms a step, found once 11.5 ms. Circles tumbling in the
/// turning box at 1/60 s (5 cm a step for a 0.25 m radius) and rain stay above it.
inline constexpr Scalar kReuseContactsMaxTravelFraction = 0.02;
/// The most a dynamic body may travel in a step whose contacts are found once, m, however large
/// it is: a long plank's bounding radius says little about how near its neighbours are.
inline constexpr Scalar kReuseContactsMaxBodyTravel = 0.02;

/// A world with at least this many bodies, some of which move more than 1 mm a step, gives each
/// dynamic body the share of a strike (2·h times the speed at which a striker approaches it, so
/// that a body set moving within the step finds what lies behind it) only from the strikers that
/// can reach it this step, found by a broad phase over the bodies' own margins
/// (Simulation::addStrikeShares); a smaller
/// world gives every dynamic body twice the fastest body's travel. In a large heap that world's
/// share made every body's margin as wide as the fastest body's (one body flung at 100 m/s by Box2D
/// v3's spinner gave each of its 6,076 bodies a margin of 0.83 m at 1/240 s): about 60 speculative
/// contacts a body and steps of seconds. Below 256 bodies, even all n² pairs of bodies are few
/// (under 33,000), and small scenes (the tests' and the soak's) keep the simpler rule.
inline constexpr std::size_t kLocalStrikeShareMinBodies = 256;

/// At most this many solver substeps per step: a step of up to 1 s is split into substeps of at
/// most kMaxSolverStep; a longer step gets substeps longer than that, which the solver does not
/// promise to hold (a step of seconds has no use in a lesson on mechanics).
inline constexpr int kMaxSolverSubsteps = 240;

/// Largest γ·h of a body under Stokes drag, with γ = b/m its drag rate (1/s) and h the substep.
/// Every integrator takes drag from the velocity at the start of a stage: semi-implicit and
/// explicit Euler multiply the velocity by 1 − γ·h a step, which changes sign past γ·h = 1 and
/// grows without bound past 2 (RK4: past 2.79). A 1 g body under b = 1 N·s/m has γ = 1000/s, and
/// a step of 1/240 s made its velocity grow 2.7-fold a step until it left the box (soak seed 136).
/// At 1 the velocity decays without changing sign; steps are split until every body keeps to it.
inline constexpr Scalar kMaxDragRateStep = 1.0;

// ---- Settings the engine is tested for (model/scene_warnings) --------------------------------

/// Largest mass ratio between two dynamic bodies that touch at load time or are joined by a
/// spring or joint, beyond which a warning is given. Measured on a box resting on a box on the
/// ground at the default step: at 100 the lower box sinks 1.2 mm into the ground, at 1000 the
/// upper one pushes it through (the sequential-impulse solver converges slowly on such ratios).
inline constexpr Scalar kMaxContactMassRatio = 100;

/// A run whose total energy grows by more than this fraction of its starting energy (the larger
/// of |E₀| and K₀ + |P₀|) gets a warning, when nothing in it does work (no fixed body moves).
/// Contacts, springs and joints never add energy; explicit Euler does, on every bounce and
/// oscillation, and at the default step a 10 % gain takes it a few tens of bounces, far beyond
/// what rounding or a long RK4 run gives on a single body. docs/physics.md, "Energy over long runs".
inline constexpr Scalar kEnergyGrowthWarning = 0.1;

/// The headless runner compares the energy with its start every this many steps (1 s at the
/// default step): often enough to say when the growth passed the bound, rare enough to cost
/// nothing next to the steps.
inline constexpr int kEnergyCheckSteps = 240;

/// At most this many pairs of bodies are named in mass-ratio warnings; the rest are counted.
inline constexpr int kMaxMassRatioWarnings = 5;

/// At most this many bodies are named in speed warnings (a body that crosses the whole scene in
/// one solver step); the rest are counted.
inline constexpr int kMaxSpeedWarnings = 5;

/// Sequential-impulse iterations per step for velocities, and non-linear Gauss–Seidel iterations
/// for positions. Box2D's defaults, which keep a 10-box stack standing at 60 Hz; at 240 Hz they
/// are generous.
inline constexpr int kVelocityIterations = 8;
inline constexpr int kPositionIterations = 3; ///< see kVelocityIterations
/// Contact forces only take kinetic energy out (a plastic normal impulse stops an approach,
/// friction stops sliding). Warm-started from the last step, the velocity passes can stop short of
/// that and leave a pile with more kinetic energy than they found (issue 16: 6.7e-5 of a zero-g
/// pile's energy in one step). A step whose passes did so runs this many more rounds of
/// kVelocityIterations passes, then starts them over from no impulse, which cannot add energy.
/// Zero-gravity worlds without joints only (Simulation::holdContactEnergy).
inline constexpr int kMaxExtraVelocityRounds = 3;
/// The passes count as adding kinetic energy when it grew by more than this fraction: rounding of
/// a sum over many bodies stays far below.
inline constexpr double kContactEnergyGrowthTolerance = 1e-12;

/// The impact pass resolves at most this many impacts per contact point per step, so a chain of
/// bodies in mutual contact (Newton's cradle, a struck stack) ends in bounded time; what is left
/// is handled by the regular velocity iterations.
inline constexpr int kMaxImpactsPerPoint = 8;

/// A step with at least this many contact constraints is solved in two halves side by side (two
/// threads; docs/physics.md, "Two threads"). Below it, handing work to a second thread costs more
/// than it saves. Whether a step is split depends only on the world, never on the machine, so the
/// result is the same bits everywhere.
inline constexpr std::size_t kParallelMinConstraints = 512;

/// A step with at least this many contact constraints runs its velocity passes in batches of
/// four contacts of one colour (controller/contact_batches.h). A small world keeps the plain
/// sequential order, which converges a little faster per pass and costs nothing to set up; a large
/// one gains about a factor of two in the velocity passes. Like kParallelMinConstraints it depends
/// only on the world.
inline constexpr std::size_t kBatchMinConstraints = 256;

/// A step with at least this many broad-phase pairs finds their contacts on two threads, each
/// taking half of the pairs in order (same results, in the same order).
inline constexpr std::size_t kParallelMinPairs = 1024;

/// A world with at least this many bodies copies and finishes their states on two threads, each
/// taking half of the bodies (each body's work is its own, so the results are the same). Below it,
/// handing over the work costs more than it saves.
inline constexpr std::size_t kParallelMinBodies = 1024;

/// How many times a thread checks for new work before it sleeps: about 0.17 ms, as each check is
/// followed by a pause instruction (about 11 ns here) that leaves the core to the other thread.
/// The solvers hand out work every few tens of microseconds, and waking a sleeping thread costs
/// about as much on a virtual machine (the idle virtual CPU has to be scheduled again): measured
/// here, checks lasting 20 µs in all left two threads no faster than one on 35 µs tasks, 0.1 ms
/// made them 1.84× faster. Between steps the worker sleeps, so an idle app costs nothing.
inline constexpr int kTaskSpinCount = 15000;

// ---- Broad phase (controller/broad_phase) -----------------------------------------------------

/// The broad phase re-sorts last step's order with insertion sort, and falls back to std::sort
/// once insertion sort has moved more than this many entries per proxy. Insertion sort costs
/// n + (entries moved); std::sort costs about n·log2(n) comparisons, 12–14 per proxy for the
/// 5,000–20,000 proxies of the benchmark scenes, so past a few moves per proxy it stops paying.
inline constexpr Scalar kBroadPhaseInsertionMovesPerProxy = 4;

/// The broad phase sweeps strips across the sweep axis separately, each this many mean box sizes
/// high (measured on the other axis). Lower makes more boxes straddle two strips and more strips
/// to visit; higher lets more boxes that are far apart on the other axis meet in the sweep. 4 was
/// fastest on the benchmark pyramids and flat within a factor 2 either way (bench/broad_phase_bench).
inline constexpr Scalar kBroadPhaseStripHeight = 4;

/// Below this many proxies the broad phase runs one plain sweep: strips would save less than they
/// cost to set up.
inline constexpr int kBroadPhaseMinProxiesForStrips = 64;

/// The broad phase keeps a "fat" box per proxy, enlarged on every side by this fraction of the
/// box's smaller side (dimensionless; 0.1 m for a 1 m box, and a 200 m × 1 m ground also gets
/// 0.1 m), and reuses last step's pairs while every box stays inside its fat box. Larger lets
/// bodies move further before the pairs are found afresh, but makes more fat pairs to filter on
/// every step and to sweep on the steps that do find them afresh. Measured over 500 steps of
/// bench/compare_engines (fractions 0.05 / 0.1 / 0.2 / 0.4): the pairs were reused in 492 / 498 /
/// 499 / 499 steps of the pyramid, 60 / 222 / 340 / 413 of the polygon rain and 135 / 304 / 389 /
/// 441 of the rotating box, with 1.0 / 1.0 / 1.0 / 1.6, 1.2 / 1.5 / 2.0 / 3.1 and 1.2 / 1.5 / 1.9 /
/// 3.3 times as many fat pairs as pairs. 0.05 made the rain and the rotating box slower than no
/// cache (a sweep on most steps, of fatter boxes), 0.4 made every step filter more; 0.1 and 0.2
/// were alike within the noise, and 0.1 keeps fewer fat pairs.
inline constexpr Scalar kBroadPhaseFatFraction = 0.1;

// --- Narrow phase --------------------------------------------------------------------------------

/// Reference-face hysteresis of polygon–polygon collision, relative to the smaller polygon's size
/// (its largest centroid-to-vertex distance). B's face becomes the reference face only when its SAT
/// separation beats A's by more than this fraction; otherwise A's face is kept. Without it, two
/// nearly parallel faces (a box resting on a box) swap roles from step to step on rounding noise,
/// the feature ids change and warm starting is lost. 5e-4 is 0.5 mm on a 1 m box, the same order
/// as Box2D's 0.1 × linear slop, and costs at most that much underestimated penetration.
inline constexpr Scalar kReferenceFaceRelativeTolerance = 5e-4;

/// Two directions whose angle is below this, rad, are parallel: a polygon edge that is this close
/// to perpendicular to the contact normal is a face contact rather than a vertex contact. Far
/// below any angle a user can draw, far above the ~1e-16 rad of double rounding.
inline constexpr Scalar kParallelAngleTolerance = 1e-9;

/// GJK and EPA stop when the support point along the current direction improves the distance
/// bound by less than this fraction of the shapes' size (m per m). Convergence on curved shapes is
/// only linear, and the normal converges as the square root of this gap, so the answer is then
/// polished by a 1-D search (see kContactNormalSearch*); 1e-10 keeps GJK under 20 iterations and
/// EPA near 20 on average on random ellipse pairs, while putting the normal well inside the
/// search bracket.
inline constexpr Scalar kGjkEpaRelativeTolerance = 1e-10;

/// Iteration cap of GJK (distance). In 2D it converges in a handful of iterations on polygons and
/// in at most 18 on random ellipse pairs at kGjkEpaRelativeTolerance; the cap only guards
/// degenerate input.
inline constexpr int kGjkMaxIterations = 100;

/// Iteration cap of EPA (penetration). Each iteration adds one vertex to the polytope: about 20 on
/// average for random ellipse pairs, up to ~175 for round ellipses overlapping almost concentrically,
/// where the Minkowski difference is nearly a circle about the origin and every edge is nearly the
/// closest. There the separation is flat in the normal, so stopping at the cap costs no accuracy in
/// the separation (the normal is then ill-defined anyway); the cap bounds the O(n²) cost.
inline constexpr int kEpaMaxIterations = 200;

/// Half-width, rad, of the bracket around the GJK/EPA normal in which the contact normal of a
/// curved pair is refined (bisection on the slope of the separation along the normal). It must
/// cover GJK/EPA's normal error, √(8·gap/ρ) for a surface of curvature radius ρ, which is below
/// 2e-3 rad even for an ellipse with a 1:100 axis ratio; 1e-2 rad is small enough that no second
/// local maximum of the separation lies inside for any shape a user draws.
inline constexpr Scalar kContactNormalSearchHalfAngle = 1e-2;

/// The refinement of the contact normal stops when its bracket is narrower than this, rad. At
/// 1e-12 rad the contact point on a 1 m curvature radius moves 1e-12 m, below the 1e-6 m promised
/// for ellipses by six orders of magnitude.
inline constexpr Scalar kContactNormalSearchTolerance = 1e-12;

/// Iteration cap of the normal refinement: halving 2·kContactNormalSearchHalfAngle down to
/// kContactNormalSearchTolerance takes 35 steps; the cap only guards against NaN brackets.
inline constexpr int kContactNormalSearchMaxIterations = 100;

// --- Soft mode (controller/soft_body_builder, soft_stability, soft_density) ----------------------

/// The densities "auto" chooses from, ellipses per m², lowest first. Powers of two from seed S1's
/// 64 (collisions look right) up to 1024 (16 times finer): each step doubles the cost.
inline constexpr Scalar kSoftAutoDensities[] = {64, 128, 256, 512, 1024};

/// A 60 Hz display frame, s: "auto" asks that simulating this much time fit in the budget below.
inline constexpr Scalar kSoftFrameTime = 1.0 / 60.0;

/// Fraction of a frame's wall time that simulating one frame may take under "auto": half leaves
/// the other half for drawing and for the machine's other work.
inline constexpr Scalar kSoftFrameBudgetFraction = 0.5;

/// Frames of trial simulation per candidate density when "auto" measures; the fastest one counts
/// (the first pays for allocations and cold caches).
inline constexpr int kSoftAutoTrialFrames = 3;

/// The headless runner picks `"auto"` without timing anything, so that a run gives the same grid
/// on every machine and under any load: the highest of kSoftAutoDensities for which the world's
/// ellipses times its soft substeps per step stay within this budget (the work of one step grows
/// with both). 16384 is what the timing picks on an idle classroom desktop: measured here, a step
/// costs about 0.14 µs per ellipse-substep on an idle core (0.28 µs with the machine loaded), and
/// half a 60 Hz frame (four steps) then holds about 15,000 of them; the 1 m² test jelly gets
/// 1024 per m² (1024 ellipses × 14 substeps), as the timing gave there when idle. docs/cli.md.
inline constexpr std::size_t kSoftAutoHeadlessBudget = 16384;

/// Largest ω·h at which RK4 is used on a soft grid, with ω the fastest grid vibration. RK4's
/// stability region reaches 2.83 along the imaginary axis, and followed by the grid's damping pass
/// (soft_damping.h) it stays stable there whatever share of the velocity the pass keeps (3.46 when
/// it keeps none); 2.5 keeps a margin for the bound on ω.
inline constexpr Scalar kRk4SoftStabilityLimit = 2.5;

/// Semi-implicit Euler followed by the grid's damping pass (soft_damping.h), which keeps a share e
/// of a mode's velocity, is stable while ω²h² < 2·(1 + e): 4 undamped, 2 for the fastest modes of a
/// strongly damped grid, whose velocity the pass all but stops. The soft grid is stepped with ω²h²
/// at most this, (0.9)² of the limit for e = 0, whatever the damping.
inline constexpr Scalar kSemiImplicitEulerSoftStabilityLimit = 1.62;

/// An ellipse held by a contact force ends its step at x₀ + h·v (so that it rests exactly, as a
/// rigid body does): semi-implicit Euler's position update, stable while ω·h < 2 undamped (with
/// RK4's velocity, < 2.45 whatever the damping pass keeps). Every soft grid is therefore stepped
/// with ω·h at most this, whatever the integrator (0.9 of 2); under semi-implicit and explicit
/// Euler, kSemiImplicitEulerSoftStabilityLimit bounds it further.
/// Measured: a resting 256/m² box keeps a residual jitter of ~1e-6 J here and ~1e-7 J at half of it.
inline constexpr Scalar kSoftContactStabilityLimit = 1.8;

/// Explicit Euler grows an undamped mode by √(1 + ω²h²) a step; the grid's damping pass, which
/// for its stiffness-proportional damping keeps e = exp(−(c/k)·ω²·h) of the mode's velocity, makes
/// up for it while e·(1 + ω²h²) ≤ 1, for every mode while h ≤ c/k. The step is kept at this
/// fraction of c/k.
inline constexpr Scalar kExplicitEulerSoftSafety = 0.9;

/// Largest 2c·h/m per substep, dimensionless, for a soft grid's damping pass (soft_damping.h),
/// with 2c/m the rate at which a grid spring of damping c alone stops the relative motion of its
/// two ellipses of mass m. The pass is exact for each spring alone and stable at any step, but a
/// pass that all but stops the springs' relative motion (2c·h/m ≫ 1) leaves the grid undamped
/// for the rest of the substep, and it meets a landing more elastically than its damping says:
/// the default soft box (ζ = 2) dropped on plastic ground rebounds at 0.38 with 3 substeps of
/// 1/240 s (2c·h/m = 2.8), 0.29 with 10, 0.27 with 14 and 0.24 in the limit. This bound keeps the
/// landing within a few hundredths of the limit (docs/physics.md, "Soft landings").
inline constexpr Scalar kSoftDampingPassLimit = 0.75;

/// Relative residual |M·v' + h·C·v' − M·v| / |M·v| at which the soft grids' damping pass stops its
/// conjugate gradients (soft_damping.h): far below anything the kinetic energy or the momentum
/// checks would see, and reached in a few dozen iterations at any damping the substeps allow.
inline constexpr Scalar kSoftDampingSolveTolerance = 1e-12;

/// Most conjugate-gradient iterations of the damping pass: a safety bound, never reached in the
/// tests (the residual falls by at least 3× an iteration when 2c·h/m ≤ kSoftDampingPassLimit).
inline constexpr int kSoftDampingSolveIterations = 200;

/// Most substeps one step is split into for a soft grid. Beyond it the grid is too stiff for the
/// step (or explicit Euler has no damping to be stable with) and the user is told so; 64 substeps
/// of the default 1/240 s step are 65 µs.
inline constexpr int kMaxSoftSubsteps = 64;

/// Default damping ratio ζ of a soft body's grid springs (SoftSettings::dampingRatio), dimensionless.
/// Each spring gets c = 2ζ·√(k·m/2) for ellipses of mass m. Chosen so that the default soft box
/// (1 m, 1 kg, 64 per m², 2000 N/m) dropped on plastic ground rebounds at well under 0.3 of its
/// landing speed at 1/240 s and 1/60 s (tests/controller/soft_landing_test.cpp), while a crushed
/// box still recovers its shape. Measured values are in docs/physics.md, "Soft landings".
inline constexpr Scalar kDefaultSoftDampingRatio = 2.0;

/// Rate of the soft grids' internal damping, 1/s: every ellipse feels F = −β·m·(v − v_rigid),
/// where v_rigid is the velocity it would have if the grid moved rigidly (the aggregate's v + ω × r).
/// It damps every deformation alike and leaves the body's translation and rotation alone (the
/// forces sum to zero and have zero torque about the centre of mass). The springs' own damping is
/// stiffness-proportional and hardly touches the slow wobble of a large grid; 5/s lets that wobble
/// lose its energy (∝ e^(−2βt)) within about half a second without making impacts look viscous.
inline constexpr Scalar kSoftInternalDampingRate = 5.0;

/// Shape matching of the soft grids: the whole body is pulled back to its rest shape (moved and
/// turned by its best-fit rigid motion) with this many times the stiffness of its grid springs.
/// Springs alone hold a grid under moderate loads, but a soft grid crushed hard (500 N/m under
/// 20 kg) folds: ellipses pass between their neighbours, cells turn inside out, and the springs
/// then hold the folded shape for good (KDE Step's "lose their internal structure"). The goal
/// positions do not care how tangled the grid is, so they always pull it back out; 10 keeps a
/// 500 N/m box from folding under 20 kg and adds only ~10% to a 2000 N/m box's stiffness.
inline constexpr Scalar kSoftShapeMatching = 10.0;

/// Soft-grid springs shorter than this, m, pull as if they were this long (their direction is
/// still the ends' own). It keeps 1/L finite, so that a spring whose two ends meet exactly pulls
/// with 0 (its (dx, dy) is 0) without a branch in the force loop. A picometre is ten orders of
/// magnitude below a cell (≥ 1 mm): no grid that still has a shape comes near it.
inline constexpr Scalar kSoftMinSpringLength = 1e-12;

/// The least moment of inertia a soft grid's aggregate has for the smooth forces (scene springs,
/// their damping), as a fraction of its rest lattice's, m·Σ|r|² (a grid squeezed to half its size
/// in both directions has a quarter). A grid crushed until its ellipses nearly meet (two ellipses
/// of a 44 kg box pressed against a wall, 3 mm apart: soak seed 2173) has almost none, and the
/// springs' torque on it, spread over the ellipses as a turn (force_model.cpp), turned them at
/// millions of rad/s² within one RK4 step: 75 kJ became 10.6 MJ. Real bodies do not shrink to a
/// point; the floor acts only on grids crushed past any shape a user means.
inline constexpr Scalar kSoftMinInertiaFraction = 0.25;

/// The fit quality (soft_body_builder.h, softAggregate) from which a soft grid's frame follows its
/// best-fit angle in full: a grid squeezed to half its size in both directions, whose inertia is
/// then kSoftMinInertiaFraction of its rest lattice's. Below it the frame follows in proportion.
inline constexpr Scalar kSoftFullFitQuality = 0.5;

/// Points on the outline of a round soft body (circle, ellipse) mapped through its grid.
inline constexpr int kSoftRoundOutlinePoints = 64;

} // namespace impetus::constants
