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
// at its rest length, swings at ω = √k along it; at 1/240 s semi-implicit Euler is stable up to
// ω·h = 2, so up to k = 480² N/m.
TEST(SceneWarnings, ASpringTooStiffForTheStepNamesItsFrequencyAndTheLongestStep)
{
    World world;
    world.settings.gravity = Vec2::Zero();
    world.settings.integrator = IntegratorKind::SemiImplicitEuler;
    world.settings.timeStep = 1.0 / 240;
    world.bodies = {box("box", Vec2(0, 0), 1)};
    Spring spring;
    spring.bodyA = BodyId{0};
    spring.anchorB = Vec2(0, 1);
    spring.restLength = 1;
    spring.stiffness = 0.98 * 480 * 480;
    world.springs = {spring};
    EXPECT_TRUE(sceneWarnings(world).empty()) << joined(sceneWarnings(world));
    world.springs[0].stiffness = 1.02 * 480 * 480;
    std::vector<SceneProblem> warnings = sceneWarnings(world);
    ASSERT_EQ(warnings.size(), 1u) << joined(warnings);
    EXPECT_EQ(warnings[0].path, "springs[0]");
    EXPECT_NE(warnings[0].reason.find("along it) it oscillates at ω = √(k/m) = 485 rad/s: ω·h = 2.02"), std::string::npos)
        << warnings[0].reason;
    EXPECT_NE(warnings[0].reason.find("semi-implicit Euler"), std::string::npos) << warnings[0].reason;
    EXPECT_NE(warnings[0].reason.find("make the step at most 4.13 ms"), std::string::npos) << warnings[0].reason;

    // The same spring to the box's corner-side point half a metre across it: the box also turns
    // (I = 1/6 kg·m², so 1/m = 1 + 0.5²·6 = 2.5 /kg), and a softer spring is already too stiff.
    world.springs[0].anchorA = Vec2(0.5, 0);
    world.springs[0].anchorB = Vec2(0.5, 1);
    world.springs[0].stiffness = 1.02 * 480 * 480 / 2.5;
    warnings = sceneWarnings(world);
    ASSERT_EQ(warnings.size(), 1u) << joined(warnings);
    EXPECT_NE(warnings[0].reason.find("on 0.4 kg"), std::string::npos) << warnings[0].reason;
    world.springs[0].stiffness = 0.98 * 480 * 480 / 2.5;
    EXPECT_TRUE(sceneWarnings(world).empty()) << joined(sceneWarnings(world));

    // Anchored on the box's far side along the spring and stretched to twice its rest length, it
    // pulls across its line with k/2 at a lever of 0.5 m: ω² = k/2 · 2.5, more than k along it.
    world.springs[0].anchorA = Vec2(0, -0.5);
    world.springs[0].anchorB = Vec2(0, 1.5);
    world.springs[0].restLength = 1;
    world.springs[0].stiffness = 1.02 * 480 * 480 / 1.25;
    warnings = sceneWarnings(world);
    ASSERT_EQ(warnings.size(), 1u) << joined(warnings);
    EXPECT_NE(warnings[0].reason.find("stretched to 2 m (rest length 1 m), pulls its ends across its line"),
              std::string::npos)
        << warnings[0].reason;

    // RK4 is stable to ω·h = 2√2: the spring that semi-implicit Euler could not take passes.
    world.settings.integrator = IntegratorKind::Rk4;
    EXPECT_TRUE(sceneWarnings(world).empty()) << joined(sceneWarnings(world));
}

} // namespace
} // namespace impetus::model
