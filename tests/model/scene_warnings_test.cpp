// Warnings for legal settings outside the ranges the engine is tested for (issue 17, item 6).

#include "model/constants.h"
#include "model/example_scenes.h"
#include "model/scene_warnings.h"

#include <gtest/gtest.h>

#include <string>

namespace impetus::model {
namespace {

Body box(const std::string& name, Vec2 position, Scalar mass, bool fixed = false)
{
    Body body;
    body.name = name;
    body.shape = Box{1, 1};
    body.state.position = position;
    body.massSpec = MassSpec{MassMode::Mass, mass};
    body.fixed = fixed;
    body.updateDerived();
    return body;
}

/// In zero gravity under `integrator` at `timeStep`: a 1 kg box of 1 m at the origin, on a spring
/// of `stiffness` from its centre to the world point (0, 1), at its rest length of 1 m.
World boxOnASpring(IntegratorKind integrator, Scalar timeStep, Scalar stiffness)
{
    World world;
    world.settings.gravity = Vec2::Zero();
    world.settings.integrator = integrator;
    world.settings.timeStep = timeStep;
    world.bodies = {box("box", Vec2(0, 0), 1)};
    Spring spring;
    spring.bodyA = BodyId{0};
    spring.anchorB = Vec2(0, 1);
    spring.restLength = 1;
    spring.stiffness = stiffness;
    world.springs = {spring};
    return world;
}

std::string joined(const std::vector<SceneProblem>& warnings)
{
    std::string text;
    for (const SceneProblem& w : warnings)
        text += w.toString() + '\n';
    return text;
}

TEST(SceneWarnings, DefaultSettingsAndTheStressScenesGiveNone)
{
    EXPECT_TRUE(sceneWarnings(World{}).empty());
    for (const World& world : {makePyramid(20), makeNewtonsCradle(), makeBoxStack(), makeRotatingBoxWithCircles(200)})
        EXPECT_TRUE(sceneWarnings(world).empty()) << joined(sceneWarnings(world));
}

// The gravity bound is |g|·h² against the contact margin: 115 m/s² at 1/240 s, four times that
// at half the step, and the solver step of a long time step is its substep.
TEST(SceneWarnings, GravityIsJudgedAgainstTheSolverStep)
{
    World world;
    const Scalar h = constants::kDefaultTimeStep;
    const Scalar limit = constants::kSpeculativeMargin / (h * h);
    world.settings.gravity = Vec2(0, -0.99 * limit);
    EXPECT_TRUE(sceneWarnings(world).empty());
    world.settings.gravity = Vec2(0.8 * limit, -0.8 * limit); // |g| = 1.13 × limit
    ASSERT_EQ(sceneWarnings(world).size(), 1u);
    EXPECT_EQ(sceneWarnings(world)[0].path, "world.gravity");
    world.settings.timeStep = h / 2;
    EXPECT_TRUE(sceneWarnings(world).empty());
    // 1/60 s is split into four substeps of 1/240 s: the same bound as 1/240 s.
    world.settings.timeStep = 4 * h;
    EXPECT_EQ(sceneWarnings(world).size(), 1u);
}

TEST(SceneWarnings, AStepBeyondWhatSubstepsSplitIsWarned)
{
    World world;
    world.settings.gravity = Vec2::Zero();
    world.settings.timeStep = 1.0;
    EXPECT_TRUE(sceneWarnings(world).empty());
    world.settings.timeStep = 1.5;
    const std::vector<SceneProblem> warnings = sceneWarnings(world);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].path, "world.timeStep");
}

// Touching bodies (bounding circles overlap) and joined bodies, dynamic ones only, beyond 100:1.
TEST(SceneWarnings, MassRatiosOfTouchingOrJoinedDynamicBodies)
{
    World world;
    world.bodies = {box("floor", Vec2(0, -0.5), 1, true), box("light", Vec2(0, 0.5), 1),
                    box("heavy", Vec2(0, 1.5), 100), box("far", Vec2(10, 0.5), 1e6)};
    EXPECT_TRUE(sceneWarnings(world).empty()) << joined(sceneWarnings(world));
    world.bodies[2] = box("heavy", Vec2(0, 1.5), 101);
    std::vector<SceneProblem> warnings = sceneWarnings(world);
    ASSERT_EQ(warnings.size(), 1u) << joined(warnings);
    EXPECT_EQ(warnings[0].path, "bodies[1]");

    // The far heavy body touches nothing but is joined to the light one by a rod: named by the rod.
    world.bodies[2] = box("heavy", Vec2(0, 1.5), 1);
    Joint rod;
    rod.type = JointType::Rod;
    rod.bodyA = BodyId{3};
    rod.bodyB = BodyId{1};
    world.joints.push_back(rod);
    warnings = sceneWarnings(world);
    ASSERT_EQ(warnings.size(), 1u) << joined(warnings);
    EXPECT_EQ(warnings[0].path, "joints[0]");
    EXPECT_NE(warnings[0].reason.find("joins 'far' (1e+06 kg) to 'light' (1 kg)"), std::string::npos)
        << warnings[0].reason;
}

TEST(SceneWarnings, ManyPairsAreCountedNotListed)
{
    World world;
    for (int k = 0; k < 20; ++k) {
        world.bodies.push_back(box("light" + std::to_string(k), Vec2(3 * k, 0.5), 1));
        world.bodies.push_back(box("heavy" + std::to_string(k), Vec2(3 * k, 1.5), 1e6));
    }
    const std::vector<SceneProblem> warnings = sceneWarnings(world);
    ASSERT_EQ(warnings.size(), static_cast<std::size_t>(constants::kMaxMassRatioWarnings) + 1);
    EXPECT_EQ(warnings.back().toString(), "bodies: and 15 more pairs of bodies with a mass ratio above 100");
}

// A spring's stiffness against the masses it moves: a 1 kg box on a spring of 1 m to the world,
// at its rest length, anchored at its centre, swings at ω = √k along it; at 1/240 s semi-implicit
// Euler is stable up to ω·h = 2, so up to k = 480² N/m.
TEST(SceneWarnings, ASpringTooStiffForTheStepNamesItsFrequencyAndTheLongestStep)
{
    World world = boxOnASpring(IntegratorKind::SemiImplicitEuler, 1.0 / 240, 0.98 * 480 * 480);
    const Spring spring = world.springs[0];
    EXPECT_TRUE(sceneWarnings(world).empty()) << joined(sceneWarnings(world));
    world.springs[0].stiffness = 1.02 * 480 * 480;
    std::vector<SceneProblem> warnings = sceneWarnings(world);
    ASSERT_EQ(warnings.size(), 1u) << joined(warnings);
    EXPECT_EQ(warnings[0].path, "springs[0]");
    EXPECT_EQ(warnings[0].reason,
              "k = 2.35e+05 N/m swings the bodies on it at ω = 485 rad/s (its fastest motion, the bodies' turns "
              "included; damping ratio 0): ω·h = 2.02 at the integrators' step of 4.17 ms, past the 2 at which "
              "semi-implicit Euler stays stable: the bodies on it will swing ever wider and fly apart; make the step "
              "at most 4.13 ms, or the spring softer");

    // Anchored half a metre across the box, the spring also turns it (I = 1/6 kg·m², so along the
    // spring 1/m = 1 + 0.5²·6 = 2.5 /kg): a 2.5 times softer spring is as fast.
    world.springs[0].anchorA = Vec2(0.5, 0);
    world.springs[0].anchorB = Vec2(0.5, 1);
    world.springs[0].stiffness = 1.02 * 480 * 480 / 2.5;
    ASSERT_EQ(sceneWarnings(world).size(), 1u) << joined(sceneWarnings(world));
    EXPECT_NE(sceneWarnings(world)[0].reason.find("ω·h = 2.02"), std::string::npos) << joined(sceneWarnings(world));
    world.springs[0].stiffness = 0.98 * 480 * 480 / 2.5;
    EXPECT_TRUE(sceneWarnings(world).empty()) << joined(sceneWarnings(world));

    // RK4 holds to ω·h = 2√2 undamped: the spring semi-implicit Euler could not take passes.
    world.springs[0].stiffness = 1.02 * 480 * 480 / 2.5;
    world.settings.integrator = IntegratorKind::Rk4;
    EXPECT_TRUE(sceneWarnings(world).empty()) << joined(sceneWarnings(world));

    // A dashpot alone (k = 0) of c = 600 N·s/m on 1 kg slows the box at 600 /s: explicit Euler
    // holds while 600·h ≤ 2, a step of 3.33 ms.
    world.settings.integrator = IntegratorKind::Euler;
    world.springs[0] = spring;
    world.springs[0].stiffness = 0;
    world.springs[0].damping = 600;
    warnings = sceneWarnings(world);
    ASSERT_EQ(warnings.size(), 1u) << joined(warnings);
    EXPECT_EQ(warnings[0].reason,
              "c = 600 N·s/m slows the bodies on it at 600 /s: at the integrators' step of 4.17 ms that is 2.5 a step, "
              "past the 2 at which explicit Euler stays stable: the bodies on it will shake ever harder and fly apart; "
              "make the step at most 3.33 ms, or the damping smaller");
    world.springs[0].damping = 450;
    EXPECT_TRUE(sceneWarnings(world).empty()) << joined(sceneWarnings(world));
}

// Stretched, a spring's tension also pulls its ends back onto its line: a box hanging by its top
// edge's middle turns about that point like a pendulum, a box pulled from its far side tips over
// (no oscillation at all, not the integrator's doing). Both are judged from the motions the
// spring's energy really has at the present poses.
TEST(SceneWarnings, AStretchedSpringsTensionCountsWithTheBodysTurn)
{
    World world = boxOnASpring(IntegratorKind::SemiImplicitEuler, 1.0 / 240, 0);
    world.springs[0].anchorA = Vec2(0, 0.5);
    world.springs[0].anchorB = Vec2(0, 2.5); // 2 m from the anchor
    world.springs[0].restLength = 1; // stretched to twice its length: T = k, T/L = k/2
    // Along the spring the box moves as a mass of 1 kg: ω² = k. Across it, the anchor swings with
    // the stiffness T/L = k/2 on 1/m = 1 + 0.5²·6 = 2.5, and the tension stiffens the turn by
    // T·(u·arm) = k·0.5 on I = 1/6: the fastest of the coupled motion is faster than √k.
    world.springs[0].stiffness = 0.98 * 480 * 480;
    const std::optional<Scalar> longest = longestStableSpringStep(world, world.springs[0]);
    ASSERT_TRUE(longest.has_value());
    EXPECT_LT(*longest, 2.0 / 480 * 0.98) << "the turn's stiffening makes it faster than along the spring";
    EXPECT_EQ(sceneWarnings(world).size(), 1u) << joined(sceneWarnings(world));

    // Anchored on the far side instead, the tension tips the box: that motion does not oscillate,
    // and the fastest one left is the stretch along the spring, ω = √k.
    world.springs[0].anchorA = Vec2(0, -0.5);
    world.springs[0].anchorB = Vec2(0, 1.5);
    const SpringMode mode = springMode(world, world.springs[0]);
    EXPECT_NEAR(mode.omega, std::sqrt(world.springs[0].stiffness), 1e-6 * mode.omega);
    EXPECT_TRUE(sceneWarnings(world).empty()) << joined(sceneWarnings(world));
}

// The step judged is the integrators': in a world with a joint, steps are split into substeps of
// at most 1/240 s, so a spring that 1/60 s would not hold is held.
TEST(SceneWarnings, ASpringIsJudgedAtTheSubstepOfAWorldWithJoints)
{
    // ω = 400: ω·h = 6.7 at 1/60 s, 1.7 at 1/240 s
    World world = boxOnASpring(IntegratorKind::Rk4, 1.0 / 60, 400 * 400);
    world.bodies.push_back(box("other", Vec2(3, 0), 1));
    ASSERT_EQ(sceneWarnings(world).size(), 1u) << joined(sceneWarnings(world));
    EXPECT_NE(sceneWarnings(world)[0].reason.find("integrators' step of 16.7 ms"), std::string::npos);
    Joint pin;
    pin.type = JointType::Pin;
    pin.bodyA = BodyId{1};
    pin.worldAnchor = Vec2(3, 0);
    pin.anchorB = pin.worldAnchor;
    world.joints = {pin};
    EXPECT_TRUE(sceneWarnings(world).empty()) << joined(sceneWarnings(world));
}

// A body that crosses the whole scene in one solver step is named with its speed, the scene's
// extent and the fastest speed that holds; a lone body has nothing to meet and is not.
TEST(SceneWarnings, ABodyThatCrossesTheSceneInOneSolverStepIsNamed)
{
    World world;
    world.settings.gravity = Vec2::Zero();
    world.settings.timeStep = 1.0 / 60; // split into solver steps of 1/240 s
    world.bodies = {box("wall", Vec2(-4.5, 0), 1, true), box("wall2", Vec2(4.5, 0), 1, true), box("fast", Vec2(0, 0), 1)};
    // The scene is 10 m wide and 1 m tall (boxes of 1 m, bounding circles of √2/2 m): its extent is
    // 9 + √2 m, crossed in 1/240 s at 240·(9 + √2) m/s.
    const Scalar limit = 240 * (9 + std::sqrt(2.0));
    world.bodies[2].state.velocity = Vec2(0.999 * limit, 0);
    EXPECT_TRUE(sceneWarnings(world).empty()) << joined(sceneWarnings(world));
    world.bodies[2].state.velocity = Vec2(0, -1.001 * limit);
    const std::vector<SceneProblem> warnings = sceneWarnings(world);
    ASSERT_EQ(warnings.size(), 1u) << joined(warnings);
    EXPECT_EQ(warnings[0].path, "bodies[2]");
    // 0.1 % past the limit: the numbers are shown with the digits it takes to tell them apart.
    EXPECT_NE(warnings[0].reason.find("'fast' moves at 2502 m/s, 10.42 m in one solver step of 4.17 ms, more "
                                      "than the 10.41 m across the whole scene"),
              std::string::npos)
        << warnings[0].reason;
    EXPECT_NE(warnings[0].reason.find("8 impacts per contact point"), std::string::npos) << warnings[0].reason;
    EXPECT_NE(warnings[0].reason.find("keep its speed at most 2499 m/s at this step"), std::string::npos)
        << warnings[0].reason;
    // A fixed body's velocity moves nothing, and a body alone has nothing to meet.
    world.bodies[2].fixed = true;
    EXPECT_TRUE(sceneWarnings(world).empty()) << joined(sceneWarnings(world));
    World alone;
    alone.settings.gravity = Vec2::Zero();
    alone.bodies = {box("fast", Vec2(0, 0), 1)};
    alone.bodies[0].state.velocity = Vec2(1e9, 0);
    EXPECT_TRUE(sceneWarnings(alone).empty()) << joined(sceneWarnings(alone));
}

// More than five fast bodies: five are named, the rest counted.
TEST(SceneWarnings, ManyFastBodiesAreNamedFiveAndCounted)
{
    World world;
    world.settings.gravity = Vec2::Zero();
    const char* const names[] = {"b0", "b1", "b2", "b3", "b4", "b5", "b6", "b7"};
    for (int i = 0; i < 8; ++i) {
        world.bodies.push_back(box(names[i], Vec2(2 * i, 0), 1));
        world.bodies.back().state.velocity = Vec2(1e6, 0);
    }
    const std::vector<SceneProblem> warnings = sceneWarnings(world);
    ASSERT_EQ(warnings.size(), 6u) << joined(warnings);
    EXPECT_EQ(warnings[4].path, "bodies[4]");
    EXPECT_EQ(warnings[5].path, "bodies");
    EXPECT_EQ(warnings[5].reason, "and 3 more bodies that cross the whole scene in one solver step");
}

} // namespace
} // namespace impetus::model
