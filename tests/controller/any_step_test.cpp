// The physics that matters, at the steps users pick and not only at the engine's own 1/240 s:
// 1/60 s (the step most engines and teachers use), 1/30 s, and 1/1000 s. Each case is checked
// against the same textbook result as at the default step (docs/physics.md, "Time step and
// substeps"), and the work a long step costs is counted.

#include "controller/diagnostics.h"
#include "controller/dynamics/contact_solver_detail.h"
#include "controller/simulation.h"
#include "controller/solver_under_test.h"
#include "model/example_scenes.h"
#include "model/scene_warnings.h"
#include "support/pendulum_theory.h"
#include "support/world_builders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <ostream>
#include <random>
#include <string>
#include <vector>

namespace impetus::controller {
namespace {

using model::IntegratorKind;
using testing::makeBall;
using testing::makeBox;
using testing::makeEmptyWorld;
using testing::makeGround;
using testing::withMaterial;

constexpr Scalar kPi = std::numbers::pi_v<Scalar>;
constexpr Scalar kG = 9.81;

/// Steps of `world` that make `seconds` of simulated time at its own step.
int stepsFor(const model::World& world, Scalar seconds)
{
    return static_cast<int>(std::lround(seconds / world.settings.timeStep));
}

void runFor(model::World& world, Simulation& simulation, Scalar seconds)
{
    for (int i = stepsFor(world, seconds); i > 0; --i)
        simulation.step(world);
}

/// The step under test, and its name for the test's label.
struct StepCase {
    Scalar h;
    const char* name;
};

/// Names the step in a failure message (GoogleTest otherwise prints the case's bytes).
void PrintTo(const StepCase& step, std::ostream* out) { *out << step.name; }

class AnyStep : public ::testing::TestWithParam<StepCase> {
protected:
    Scalar h() const { return GetParam().h; }
};

std::string stepName(const ::testing::TestParamInfo<StepCase>& info) { return info.param.name; }

INSTANTIATE_TEST_SUITE_P(Steps, AnyStep,
                         ::testing::Values(StepCase{1.0 / 30.0, "h_1_30"}, StepCase{1.0 / 60.0, "h_1_60"},
                                           StepCase{1.0 / 1000.0, "h_1_1000"}),
                         stepName);

// ---- The substeps --------------------------------------------------------------------------

// A step is split into ⌈h / 1/240 s⌉ equal substeps, and a step that is a whole number of
// 1/240 s by rounding only is not split once more.
TEST(SolverSubsteps, SplitsLongStepsIntoSubstepsOfAtMostTheSolverStep)
{
    const Scalar s = constants::kMaxSolverStep;
    EXPECT_EQ(solverSubsteps(1.0 / 240.0, s), 1);
    EXPECT_EQ(solverSubsteps(1.0 / 1000.0, s), 1);
    EXPECT_EQ(solverSubsteps(1.0 / 60.0, s), 4);
    EXPECT_EQ(solverSubsteps(1.0 / 30.0, s), 8);
    EXPECT_EQ(solverSubsteps(1.0 / 100.0, s), 3); // 3 substeps of 1/300 s
    EXPECT_EQ(solverSubsteps(4 * (1.0 / 240.0), s), 4);
    EXPECT_EQ(solverSubsteps(1.0, s), constants::kMaxSolverSubsteps);
    EXPECT_EQ(solverSubsteps(1e6, s), constants::kMaxSolverSubsteps);
    EXPECT_EQ(solverSubsteps(std::nan(""), s), 1);
}

// A rod whose ends go round each other is split like a spinning body: its row holds the ends
// along the line they had at the substep's start. A 1.9 kg ball at 83 m/s on a rod of 0.3 m to a
// world point goes round at 277 rad/s, 1.15 rad a step of 1/240 s. Not split (the ball is a
// circle, whose own spin never splits), it slowed from 83 to 60 m/s within a second, and an
// ellipse on such a rod gained a fifth of its world's energy in one step (soak seed 3641).
TEST(SolverSubsteps, ARodGoingRoundFastSplitsTheStepAndKeepsItsEnergy)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240.0, Vec2::Zero());
    world.bodies.push_back(makeBall("ball", 1.9, 0.1, Vec2(0, 0.3), Vec2(83, 0)));
    model::Joint rod;
    rod.type = model::JointType::Rod;
    rod.bodyA = model::BodyId{0};
    rod.anchorB = Vec2::Zero(); // a world point
    rod.length = 0.3;
    world.joints.push_back(rod);
    // Split until the rod turns 0.1 rad at most a substep.
    const Scalar rate = 83 / 0.3; // rad/s
    EXPECT_EQ(spinSubsteps(world, 1.0 / 240.0), static_cast<int>(std::ceil(rate / 240 / 0.1))); // 12
    EXPECT_EQ(spinSubsteps(world, 1.0 / 60.0),
              std::min(constants::kMaxSolverSubsteps, static_cast<int>(std::ceil(rate / 60 / 0.1)))); // 47

    for (const Scalar h : {1.0 / 240.0, 1.0 / 60.0}) {
        model::World run = world;
        run.settings.timeStep = h;
        const Scalar energy = computeEnergy(run).total();
        Simulation simulation(settingsUnderTest());
        for (int i = 0; i < static_cast<int>(std::lround(1 / h)); ++i) {
            simulation.step(run);
            // The rod's pass (SHAKE) keeps the energy to about (θ/2)², θ the turn in a substep:
            // under 1 % at 0.2 rad for a ball, bounded, not growing.
            ASSERT_LT(computeEnergy(run).total(), energy * (1 + 0.01)) << "h = " << h << ", step " << i;
            ASSERT_NEAR(run.bodies[0].state.position.norm(), 0.3, 1e-3) << "h = " << h << ", step " << i; // m
        }
        // Nothing but the rod acts: the ball goes round at its speed (a rod never adds energy,
        // and takes out only what the position passes' rounding does).
        EXPECT_NEAR(run.bodies[0].state.velocity.norm(), 83, 0.83) << "h = " << h; // m/s
    }
}

// A step is split until no body but a circle turns by more than an eighth of a turn in a substep;
// a world in free flight is not split, however fast its bodies spin.
TEST(SolverSubsteps, FastSpinsSplitStepsWithContactsToAnEighthOfATurn)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240.0, Vec2::Zero());
    world.bodies.push_back(makeBox("box", 1.0, 0.5, 0.1, Vec2(0, 5)));
    world.bodies.push_back(makeBall("ball", 1.0, 0.1, Vec2(50, 5)));
    world.bodies[1].state.angularVelocity = 5000; // a circle: its outline does not change
    const Scalar eighth = std::numbers::pi / 4;
    world.bodies[0].state.angularVelocity = 0.99 * eighth * 240; // just under an eighth a step
    EXPECT_EQ(spinSubsteps(world, 1.0 / 240.0), 1);
    world.bodies[0].state.angularVelocity = -2.5 * eighth * 240; // either way round
    EXPECT_EQ(spinSubsteps(world, 1.0 / 240.0), 3);
    EXPECT_EQ(spinSubsteps(world, 1.0 / 60.0), 10);
    world.bodies[0].state.angularVelocity = 1e9;
    EXPECT_EQ(spinSubsteps(world, 1.0 / 240.0), constants::kMaxSolverSubsteps);

    // In free flight the box keeps the user's step; beside a floor it is split.
    world.bodies[0].state.angularVelocity = 2.5 * eighth * 240;
    Simulation simulation(settingsUnderTest());
    simulation.step(world);
    EXPECT_EQ(simulation.profile().substeps, 1);
    world.bodies.push_back(makeGround("floor", 10, 1, Vec2(0, 4.7)));
    simulation.step(world);
    EXPECT_EQ(simulation.profile().substeps, 3);
}

// Where masses lie more than ten times apart, a step is split until no body but a circle turns by
// more than 0.1 rad in a substep: a light body that a heavy one drives against a wall meets its
// contact rows, linear in its spin, by spinning (soak seed 4386: a 54 g ellipse at 148 rad/s on a
// rod to a 0.59 kg one went through the ceiling at 0.6 rad a substep). The same spins in a world
// of like masses split at an eighth of a turn. Among free bodies of unlike masses only a heavy
// body touching a light one drives it: only the light bodies of such contacts are held to 0.1 rad
// (a rain of polygons, whose smallest spun at up to 80 rad/s, split its whole world's step of
// 1/60 s into 14 substeps for them: six times its median step).
TEST(SolverSubsteps, FastSpinsAmongUnlikeMassesSplitStepsToATenthOfARadian)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240.0, Vec2::Zero());
    world.bodies.push_back(makeBox("box", 1.0, 0.5, 0.1, Vec2(0, 5)));
    world.bodies.push_back(makeBall("ball", 1.0, 0.1, Vec2(50, 5)));
    world.bodies.push_back(makeBall("anchor", 1.0, 0.1, Vec2(60, 5)));
    // A spring between the two balls: the world has something that can drive a light body.
    model::Spring spring;
    spring.bodyA = model::BodyId{1};
    spring.bodyB = model::BodyId{2};
    spring.restLength = 10;
    world.springs.push_back(spring);
    const Scalar rate = 0.23 * 240; // rad/s: 0.23 rad a step of 1/240 s, 0.92 rad a step of 1/60 s
    world.bodies[0].state.angularVelocity = rate;
    EXPECT_EQ(spinSubsteps(world, 1.0 / 240.0), 1); // like masses: an eighth of a turn, 0.785 rad
    EXPECT_EQ(spinSubsteps(world, 1.0 / 60.0), 2);
    world.bodies[1] = makeBall("ball", 10.5, 0.1, Vec2(50, 5)); // 10.5 times the box
    EXPECT_EQ(spinSubsteps(world, 1.0 / 240.0), 3);
    EXPECT_EQ(spinSubsteps(world, 1.0 / 60.0), 10);
    // Without the spring the same masses are free bodies, 50 m apart: the eighth of a turn again.
    world.springs.clear();
    EXPECT_EQ(spinSubsteps(world, 1.0 / 240.0), 1);
    EXPECT_EQ(spinSubsteps(world, 1.0 / 60.0), 2);
    // Touching (as the last step ended), the heavy ball can drive the box: 0.1 rad for the box.
    model::ContactRecord touch;
    touch.bodyA = model::BodyId{0};
    touch.bodyB = model::BodyId{1};
    touch.pointCount = 1;
    touch.touching = true;
    world.contacts.push_back(touch);
    EXPECT_EQ(spinSubsteps(world, 1.0 / 240.0), 3);
    EXPECT_EQ(spinSubsteps(world, 1.0 / 60.0), 10);
    // The heavy body's own spin is not held to it (a ball turns freely; a heavy box keeps the
    // eighth): the box at rest and the ball spinning leave the step whole.
    world.bodies[0].state.angularVelocity = 0;
    world.bodies[1].state.angularVelocity = rate;
    EXPECT_EQ(spinSubsteps(world, 1.0 / 240.0), 1);
    world.bodies[0].state.angularVelocity = rate;
    world.bodies[1].state.angularVelocity = 0;
    world.contacts.clear();
    // A joint drives as a spring does.
    model::Joint rod;
    rod.type = model::JointType::Rod;
    rod.bodyA = model::BodyId{1};
    rod.bodyB = model::BodyId{2};
    rod.length = 10;
    world.joints.push_back(rod);
    EXPECT_EQ(spinSubsteps(world, 1.0 / 240.0), 3);
    world.bodies[1] = makeBall("ball", 9.5, 0.1, Vec2(50, 5)); // within ten times
    EXPECT_EQ(spinSubsteps(world, 1.0 / 240.0), 1);
    // A fixed body's mass does not count: a light box beside a heavy wall is not unlike anything.
    world.bodies[1] = makeGround("wall", 10, 10, Vec2(50, 5));
    EXPECT_EQ(spinSubsteps(world, 1.0 / 240.0), 1);
}

// A world in free flight integrates over the step the user chose (an integrator lesson sees its
// error at that step); the same world with a contact to solve is split.
TEST(SolverSubsteps, OnlyStepsWithContactsOrJointsAreSplit)
{
    model::World flight = makeEmptyWorld(IntegratorKind::Euler, 1.0 / 30.0, Vec2(0, -kG));
    flight.bodies.push_back(makeBall("ball", 1.0, 0.1, Vec2(0, 10), Vec2(3, 4)));
    Simulation simulation(settingsUnderTest());
    simulation.step(flight);
    EXPECT_EQ(simulation.profile().substeps, 1);
    // Explicit Euler over one whole step of 1/30 s: x = x₀ + h·v₀, v = v₀ + h·g.
    EXPECT_DOUBLE_EQ(flight.bodies[0].state.position.y(), 10 + 4.0 / 30.0);
    EXPECT_DOUBLE_EQ(flight.bodies[0].state.velocity.y(), 4 - kG / 30.0);

    model::World resting = makeEmptyWorld(IntegratorKind::Euler, 1.0 / 30.0, Vec2(0, -kG));
    resting.bodies.push_back(makeGround("ground", 10, 1));
    resting.bodies.push_back(makeBox("box", 1.0, 1.0, 1.0, Vec2(0, 0.5)));
    simulation.step(resting);
    EXPECT_EQ(simulation.profile().substeps, 8);

    model::World pendulum = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 60.0, Vec2(0, -kG));
    pendulum.bodies.push_back(makeBall("bob", 1.0, 0.05, Vec2(1, 0)));
    model::Joint rod;
    rod.type = model::JointType::Rod;
    rod.bodyA = model::BodyId{0};
    rod.anchorB = Vec2::Zero();
    rod.length = 1.0;
    pendulum.joints.push_back(rod);
    simulation.step(pendulum);
    EXPECT_EQ(simulation.profile().substeps, 4);
}

// ---- Stacking --------------------------------------------------------------------------------

// Ten boxes stand for 10 s: none drifts sideways by more than a millimetre or sinks by more than
// the slop per contact.
TEST_P(AnyStep, TenBoxStackStands)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, h(), Vec2(0, -kG));
    world.bodies.push_back(withMaterial(makeGround("ground", 20, 1), 0.0, 0.6));
    for (int i = 0; i < 10; ++i)
        world.bodies.push_back(withMaterial(makeBox("box" + std::to_string(i), 1.0, 1.0, 1.0, Vec2(0, 0.5 + i)), 0.0, 0.6));
    Simulation simulation(settingsUnderTest());
    runFor(world, simulation, 10.0);
    for (int i = 0; i < 10; ++i) {
        const model::BodyState& s = world.bodies[static_cast<std::size_t>(i + 1)].state;
        EXPECT_NEAR(s.position.x(), 0.0, 1e-3) << "box " << i;
        EXPECT_NEAR(s.position.y(), 0.5 + i, (i + 1) * constants::kLinearSlop) << "box " << i;
        EXPECT_NEAR(s.angle, 0.0, 1e-3) << "box " << i;
    }
}

// A pyramid of base 20 (210 boxes) stands for 5 s under RK4, the integrator a user gets by
// default: the top box within a centimetre of where it started, every box still and level.
TEST_P(AnyStep, PyramidOfBase20Stands)
{
    model::SceneOptions options;
    options.timeStep = h();
    model::World world = model::makePyramid(20, options);
    world.settings.integrator = IntegratorKind::Rk4;
    const model::World start = world;
    Simulation simulation(settingsUnderTest());
    runFor(world, simulation, 5.0);
    const Vec2 drift = world.bodies.back().state.position - start.bodies.back().state.position;
    EXPECT_LT(std::abs(drift.x()), 0.01);
    EXPECT_LT(std::abs(drift.y()), 20 * constants::kLinearSlop);
    for (std::size_t i = 1; i < world.bodies.size(); ++i) {
        ASSERT_NEAR(world.bodies[i].state.angle, 0.0, 0.01) << "box " << i;
        ASSERT_LT(world.bodies[i].state.velocity.norm(), 0.01) << "box " << i;
    }
}

// ---- Friction on an incline --------------------------------------------------------------------

model::World makeIncline(Scalar h, Scalar theta, Scalar mu)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, h, Vec2(0, -kG));
    world.bodies.push_back(withMaterial(makeGround("ramp", 40, 1, Vec2::Zero(), -theta), 0.0, mu));
    const Vec2 normal = rotate(Vec2(0, 1), -theta);
    const Vec2 uphill = rotate(Vec2(-1, 0), -theta);
    model::Body block = makeBox("block", 1.0, 0.4, 0.2, 2.0 * uphill + 0.1 * normal, -theta);
    world.bodies.push_back(withMaterial(block, 0.0, mu));
    return world;
}

// μ < tanθ: after 1 s the block slides at g(sinθ − μcosθ)·t.
TEST_P(AnyStep, BlockSlidesDownAnInclineWithTheTheoreticalAcceleration)
{
    const Scalar theta = kPi / 6;
    const Scalar mu = 0.2;
    model::World world = makeIncline(h(), theta, mu);
    Simulation simulation(settingsUnderTest());
    runFor(world, simulation, 1.0);
    const Scalar expected = kG * (std::sin(theta) - mu * std::cos(theta));
    const Scalar speed = world.bodies[1].state.velocity.dot(rotate(Vec2(1, 0), -theta));
    EXPECT_NEAR(speed, expected, 0.01 * expected);
}

// μ > tanθ: the block stays put; creep under 1 mm in 2 s.
TEST_P(AnyStep, BlockSticksOnAnInclineWhenFrictionExceedsTanTheta)
{
    model::World world = makeIncline(h(), kPi / 6, 0.7);
    const Vec2 start = world.bodies[1].state.position;
    Simulation simulation(settingsUnderTest());
    runFor(world, simulation, 2.0);
    EXPECT_LT((world.bodies[1].state.position - start).norm(), 1e-3);
    EXPECT_TRUE(world.bodies[1].colliding);
}

// ---- Impacts ---------------------------------------------------------------------------------

// A ball dropped from 1 m rises after its n-th bounce to e²ⁿ m.
TEST_P(AnyStep, BounceApexesFollowESquaredToTheN)
{
    const Scalar e = 0.8;
    const Scalar r = 0.1;
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, h(), Vec2(0, -kG));
    world.bodies.push_back(withMaterial(makeGround("floor", 10, 1), e, 0.0));
    world.bodies.push_back(withMaterial(makeBall("ball", 1.0, r, Vec2(0, 1.0 + r)), e, 0.0));
    Simulation simulation(settingsUnderTest());
    std::vector<Scalar> apexes{1.0};
    Scalar previousVy = 0;
    for (int i = stepsFor(world, 6.0); i > 0 && apexes.size() < 5; --i) {
        simulation.step(world);
        const model::BodyState& s = world.bodies[1].state;
        if (previousVy > 0 && s.velocity.y() <= 0) {
            // The apex from the last state going up: y + v²/2g (exact in free flight).
            apexes.push_back(s.position.y() - r + s.velocity.y() * s.velocity.y() / (2 * kG));
        }
        previousVy = s.velocity.y();
    }
    ASSERT_EQ(apexes.size(), 5u);
    for (std::size_t n = 1; n < apexes.size(); ++n) {
        const Scalar expected = std::pow(e, 2.0 * static_cast<double>(n));
        EXPECT_NEAR(apexes[n], expected, 0.005 * expected) << "bounce " << n;
    }
    // Each bounce is one contact that begins, also when a step's substeps share its contacts and
    // tell what began once, at the step's end.
    EXPECT_EQ(world.bodies[1].collisionCount, 4);
}

// A ball rolling without slipping on level ground stays on it: it neither sinks nor hops, and
// keeps v = −ω·r. Within a long step the ball turns a long way (0.67 rad a step at 1/30 s); the
// point of it that touches the ground is the lowest one, not the one that touched at the start of
// the step, which has rolled up by r·(1 − cos Δθ), 5 cm at 1/30 s.
TEST_P(AnyStep, BallRollsOnTheGroundWithoutSinking)
{
    const Scalar r = 0.25;
    const Scalar v = 5.0;
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, h(), Vec2(0, -kG));
    world.bodies.push_back(withMaterial(makeGround("ground", 40, 1), 0.0, 0.5));
    model::Body ball = withMaterial(makeBall("ball", 1.0, r, Vec2(-8, r), Vec2(v, 0)), 0.0, 0.5);
    ball.state.angularVelocity = -v / r;
    world.bodies.push_back(ball);
    Simulation simulation(settingsUnderTest());
    Scalar lowest = r;
    Scalar highest = r;
    for (int i = stepsFor(world, 2.0); i > 0; --i) {
        simulation.step(world);
        lowest = std::min(lowest, world.bodies[1].state.position.y());
        highest = std::max(highest, world.bodies[1].state.position.y());
    }
    const model::BodyState& s = world.bodies[1].state;
    EXPECT_GT(lowest, r - 2 * constants::kLinearSlop);
    EXPECT_LT(highest, r + constants::kLinearSlop);
    EXPECT_NEAR(s.velocity.x(), v, 1e-6);
    EXPECT_NEAR(s.angularVelocity * r, -v, 1e-6);
    EXPECT_NEAR(s.position.x(), -8 + 2 * v, 1e-6);
}

// Newton's cradle: one ball in at 2 m/s, one ball out at 2 m/s, the other four at rest.
TEST_P(AnyStep, NewtonsCradleOneBallInOneBallOut)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, h());
    const Scalar r = 0.1;
    for (int i = 0; i < 5; ++i) {
        const Scalar x = 2 * r * i - (i == 0 ? 0.05 : 0.0);
        world.bodies.push_back(
            withMaterial(makeBall("ball" + std::to_string(i), 0.5, r, Vec2(x, 0), Vec2(i == 0 ? 2.0 : 0.0, 0)), 1.0, 0.0));
    }
    Simulation simulation(settingsUnderTest());
    runFor(world, simulation, 0.5);
    for (std::size_t i = 0; i < 4; ++i)
        EXPECT_NEAR(world.bodies[i].state.velocity.norm(), 0.0, 1e-6) << "ball " << i;
    EXPECT_NEAR(world.bodies[4].state.velocity.x(), 2.0, 1e-6);
}

// A 0.1 m ball at 200 m/s against a 0.1 m wall bounces back instead of passing through, even at
// 1/30 s, when it travels 6.7 m in one step.
TEST_P(AnyStep, FastBallDoesNotTunnelThroughAThinWall)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, h());
    model::Body wall = makeGround("wall", 0.1, 2.0, Vec2(5.05, 1.0));
    world.bodies.push_back(withMaterial(wall, 1.0, 0.0));
    world.bodies.push_back(withMaterial(makeBall("bullet", 0.1, 0.05, Vec2(0, 0), Vec2(200, 0)), 1.0, 0.0));
    Simulation simulation(settingsUnderTest());
    runFor(world, simulation, 0.1);
    EXPECT_NEAR(world.bodies[1].state.velocity.x(), -200.0, 1e-6);
    EXPECT_LT(world.bodies[1].state.position.x(), 5.0 - 0.05);
    EXPECT_EQ(world.collisionCount, 1);
}

// An elastic ball between two elastic walls 10 m apart, in zero gravity, as fast as the range
// warning allows (docs/scene-format.md, "Ranges the engine is tested for": a body that crosses
// the whole scene in one solver step is warned about). Up to that speed it bounces back and forth
// many times in 0.1 s and keeps its speed exactly; a hair faster, the warning comes.
TEST_P(AnyStep, ElasticBallBetweenWallsKeepsItsSpeedUpToTheSpeedWarning)
{
    model::World world = makeEmptyWorld(IntegratorKind::SemiImplicitEuler, h());
    world.bodies.push_back(withMaterial(makeGround("left", 0.2, 4.0, Vec2(-5.1, 2.0)), 1.0, 0.0));
    world.bodies.push_back(withMaterial(makeGround("right", 0.2, 4.0, Vec2(5.1, 2.0)), 1.0, 0.0));
    world.bodies.push_back(withMaterial(makeBall("ball", 0.1, 0.1, Vec2(0, 0), Vec2(1, 0)), 1.0, 0.0));
    // The speed at which the ball crosses the scene's extent in one solver step, from the warning.
    const auto warnedAt = [&world](Scalar speed) {
        world.bodies[2].state.velocity = Vec2(speed, 0);
        return !model::sceneWarnings(world).empty();
    };
    Scalar low = 1;
    Scalar high = 1e6;
    ASSERT_FALSE(warnedAt(low));
    ASSERT_TRUE(warnedAt(high));
    for (int i = 0; i < 60; ++i) {
        const Scalar mid = std::sqrt(low * high);
        (warnedAt(mid) ? high : low) = mid;
    }
    const Scalar limit = low;
    EXPECT_TRUE(warnedAt(1.01 * limit));
    ASSERT_FALSE(warnedAt(0.99 * limit));
    // More than one crossing of the 10 m gap in each solver step of 1/240 s or less.
    const Vec2 start = world.bodies[2].state.velocity;
    EXPECT_GT(start.x() * std::min(h(), 1.0 / 240), 10.0) << "limit " << limit << " m/s";
    Simulation simulation(settingsUnderTest());
    runFor(world, simulation, 0.1);
    const model::Body& ball = world.bodies[2];
    EXPECT_NEAR(ball.state.velocity.norm(), start.norm(), 1e-9 * start.norm());
    EXPECT_LT(std::abs(ball.state.position.x()), 5.0 - 0.1 + 1e-3);
    EXPECT_NEAR(ball.state.position.y(), 0.0, 1e-9);
}

// ---- Joints ------------------------------------------------------------------------------------

// A ball on a massless rod released at 60°: the period is 4√(L/g)·K(sin 30°), and the rod keeps
// its length.
TEST_P(AnyStep, RodPendulumHasTheLargeAmplitudePeriod)
{
    const Scalar length = 1.0;
    const Scalar theta0 = kPi / 3;
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, h(), Vec2(0, -kG));
    world.bodies.push_back(makeBall("bob", 1.0, 0.05, Vec2(length * std::sin(theta0), -length * std::cos(theta0))));
    model::Joint rod;
    rod.type = model::JointType::Rod;
    rod.bodyA = model::BodyId{0};
    rod.anchorB = Vec2::Zero();
    rod.length = length;
    world.joints.push_back(rod);

    Simulation simulation(settingsUnderTest());
    std::vector<Scalar> crossings;
    Scalar previousX = world.bodies[0].state.position.x();
    const int steps = stepsFor(world, 12.0);
    for (int i = 1; i <= steps; ++i) {
        simulation.step(world);
        const Scalar x = world.bodies[0].state.position.x();
        if (previousX < 0 && x >= 0)
            crossings.push_back((i - 1 + previousX / (previousX - x)) * h());
        previousX = x;
        ASSERT_NEAR(world.bodies[0].state.position.norm(), length, 1e-3) << "step " << i;
    }
    ASSERT_GE(crossings.size(), 2u);
    const Scalar period = (crossings.back() - crossings.front()) / static_cast<Scalar>(crossings.size() - 1);
    const Scalar expected = testing::pendulumPeriod(length, kG, theta0);
    // The zero crossings are interpolated linearly between samples: at 1/30 s that alone is
    // accurate to about ω²h²/8 of a step's time, well under 1e-3 of the period.
    EXPECT_NEAR(period, expected, 1e-3 * expected);
}

// ---- Conservation ------------------------------------------------------------------------------

// Sixteen random polygons fly together in zero gravity and pile up: linear momentum is conserved
// to rounding, kinetic energy never grows, and angular momentum stays within the bound
// docs/physics.md gives for piles (1e-3).
// Box2D v3's joint grid, 10 × 10 discs joined by 180 pins at their midpoints and hung from the
// top row's middle discs: a net of closed loops, more constraints than its bodies can satisfy one
// at a time, which the passes cannot solve exactly in a step. It used to blow up within 0.4 s
// (every joint's leftover error was closed with velocity the next step, and in the loops those
// velocities fed each other), and the full grid of 10,000 discs reached 1,300 m/s in 74 steps.
// At rest it must stay at rest: no energy beyond what the position passes may lift it (its weight
// times the slop they leave), the pins within a couple of slops of closed.
TEST_P(AnyStep, HangingJointedNetStaysAtRest)
{
    model::World world = model::makeJointGrid(10);
    world.settings.timeStep = h();
    Scalar mass = 0;
    for (const model::Body& body : world.bodies)
        mass += body.fixed ? 0 : body.mass;
    const auto energy = [&] {
        Scalar e = 0;
        for (const model::Body& body : world.bodies) {
            if (body.fixed)
                continue;
            const model::BodyState& s = body.state;
            e += 0.5 * body.mass * s.velocity.squaredNorm() + 0.5 * body.inertia * s.angularVelocity * s.angularVelocity -
                 body.mass * s.position.dot(world.settings.gravity);
        }
        return e;
    };
    const Scalar start = energy();
    Simulation simulation(settingsUnderTest());
    for (int i = stepsFor(world, 2.0); i > 0; --i) {
        simulation.step(world);
        ASSERT_LE(energy(), start + mass * kG * constants::kLinearSlop) << "step " << i;
    }
    for (const model::Joint& joint : world.joints) {
        const model::Body& a = world.bodies[joint.bodyA.index];
        const model::Body& b = world.bodies[joint.bodyB->index];
        const Vec2 gap = b.state.position + rotate(joint.anchorB, b.state.angle) - a.state.position -
                         rotate(joint.anchorA, a.state.angle);
        EXPECT_LT(gap.norm(), 4 * constants::kLinearSlop) << a.name << " to " << b.name;
    }
}

TEST_P(AnyStep, ZeroGravityPileConservesMomentumAndNeverGainsEnergy)
{
    std::mt19937 rng(12345);
    auto uniform = [&](Scalar lo, Scalar hi) {
        return lo + (hi - lo) * static_cast<Scalar>(rng() - std::mt19937::min()) /
                        static_cast<Scalar>(std::mt19937::max() - std::mt19937::min());
    };
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, h());
    for (int i = 0; i < 16; ++i) {
        model::Body body;
        body.name = "p";
        body.name += std::to_string(i);
        std::vector<Vec2> vertices;
        const int n = 3 + i % 5;
        for (int k = 0; k < n; ++k) {
            const Scalar angle = 2 * kPi * (k + uniform(0.1, 0.9)) / n;
            vertices.push_back(uniform(0.25, 0.45) * Vec2(std::cos(angle), std::sin(angle)));
        }
        body.shape = model::Polygon{vertices};
        body.state.position = Vec2(1.2 * (i % 4) - 1.8, 1.2 * (i / 4) - 1.8);
        body.state.velocity = -1.5 * body.state.position.normalized() + Vec2(uniform(-0.3, 0.3), uniform(-0.3, 0.3));
        body.state.angularVelocity = uniform(-2, 2);
        body.material.restitution = uniform(0.0, 1.0);
        body.material.friction = uniform(0.0, 0.8);
        body.updateDerived();
        world.bodies.push_back(body);
    }
    const Vec2 p0 = linearMomentum(world);
    const Scalar l0 = angularMomentum(world);
    Scalar kinetic = computeEnergy(world).kinetic;
    Simulation simulation(settingsUnderTest());
    for (int i = stepsFor(world, 3.0); i > 0; --i) {
        simulation.step(world);
        ASSERT_NEAR((linearMomentum(world) - p0).norm(), 0.0, 1e-9);
        ASSERT_NEAR(angularMomentum(world), l0, 1e-9 * std::abs(l0));
        const Scalar k = computeEnergy(world).kinetic;
        ASSERT_LE(k, kinetic * (1 + 1e-12));
        kinetic = k;
    }
    EXPECT_GT(world.collisionCount, 10);
}

// ---- Work --------------------------------------------------------------------------------------

// The case that took 300 ms a step: a tall pyramid at 1/60 s whose contacts, solved in one long
// step, lose and regain their load. Its plastic contacts were struck one at a time through the
// pile: 10,000 impacts in one step of a 50-row pyramid. Counted, not timed: split as it is by
// default, it takes 4 substeps a step and no step resolves more impacts than a hundredth of its
// contacts. Not split (the solver at its worst, and the pyramid sagging), a step strikes a few
// dozen: where a corner of the rows gives way, three or four boxes meeting at one moment are
// struck in turn until none approaches (40 impacts among 12 pairs at worst, each smaller than the
// last), which stays under a fiftieth of the contacts; a cascade through the pile is hundreds of
// times that.
// A long step of a rigid world at rest finds its contacts once, with margins for the whole step,
// and its substeps refresh them: one collision pass a step, not one per substep. A world whose
// bodies move fast, or with a soft body, finds them again every substep.
TEST(AnyStepWork, ASplitStepOfARigidWorldRunsOneCollisionPass)
{
    model::World world = model::makePyramid(20);
    world.settings.timeStep = 1.0 / 60.0;
    Simulation simulation(settingsUnderTest());
    // Its first steps settle the rows into their slop, at up to 15 cm/s (2.5 mm a step, a small
    // part of a 1 m box: contactsLastTheStep), and every step runs one pass, settling or settled.
    for (int i = 0; i < 30; ++i) {
        simulation.step(world);
        ASSERT_EQ(simulation.profile().substeps, 4) << "step " << i;
        ASSERT_EQ(simulation.profile().collisionPasses, 1) << "step " << i;
    }
    EXPECT_GT(simulation.profile().contacts, 0);

    // Bodies that move fast find their contacts every substep: margins for the whole step would
    // make many more speculative contacts than one pass saves.
    model::World sliding = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 60.0, Vec2(0, -kG));
    sliding.bodies.push_back(withMaterial(makeGround("floor", 40, 1), 0.0, 0.1));
    model::Body crate = withMaterial(makeBox("crate", 1.0, 0.5, 0.5, Vec2(0, 0.25)), 0.0, 0.1);
    crate.state.velocity = Vec2(3, 0);
    sliding.bodies.push_back(crate);
    ASSERT_GT(fastestTravel(sliding, 1.0 / 60.0), constants::kReuseContactsMaxTravel);
    Simulation slidingSimulation(settingsUnderTest());
    slidingSimulation.step(sliding);
    slidingSimulation.step(sliding);
    EXPECT_EQ(slidingSimulation.profile().substeps, 4);
    EXPECT_EQ(slidingSimulation.profile().collisionPasses, 4);

    model::World soft = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 60.0, Vec2(0, -kG));
    soft.bodies.push_back(makeGround("floor", 10, 1));
    model::Body box = makeBox("jelly", 1.0, 0.5, 0.5, Vec2(0, 0.26));
    box.soft = model::SoftSettings{};
    soft.bodies.push_back(box);
    Simulation softSimulation(settingsUnderTest());
    softSimulation.step(soft);
    softSimulation.step(soft);
    EXPECT_GE(softSimulation.profile().substeps, 4);
    EXPECT_EQ(softSimulation.profile().collisionPasses, softSimulation.profile().substeps);
}

TEST(AnyStepWork, TallPyramidAtALongStepStrikesNoCascadeOfImpacts)
{
    model::SceneOptions options;
    options.timeStep = 1.0 / 60.0;
    for (const bool split : {false, true}) {
        model::World world = model::makePyramid(50, options);
        world.settings.integrator = IntegratorKind::Rk4;
        SolverSettings settings = settingsUnderTest();
        if (!split)
            settings.maxSubstep = options.timeStep;
        Simulation simulation(settings);
        for (int i = 0; i < 120; ++i) {
            simulation.step(world);
            const StepProfile& p = simulation.profile();
            EXPECT_EQ(p.substeps, split ? 4 : 1);
            ASSERT_GT(p.contacts, 0);
            ASSERT_LE(p.impacts * (split ? 100 : 50), p.contacts) << "step " << i << (split ? ", split" : ", not split");
        }
    }
}

// The step the frame-rate program hung on: 2000 circles in the turning box (the app's large
// example and the benchmark's rotating-box scene), step 238 at 1/240 s. A circle spinning at
// 21 rad/s was struck against a wall; its approach was then measured at lever arms turned with
// the circle, the impact's own at the point between the surfaces, which does not turn with a
// circle: approaching by one, separating by the other. It was struck with no impulse until the
// impact pass's cap, 31,296 times, each walking all the circle's earlier impulses (30 s a step).
// Counted, not timed: every impact the pass reports moves something; no step runs its impacts to
// the pass's cap (kMaxImpactsPerPoint a contact point), as that one did; and over the run there
// are fewer impacts than contacts. A single step may strike more: where a column of plastic
// circles lands, each impact hands half its blow on to the next circle, and the pair is struck
// again, a dozen times in all until the approach is below the bounce threshold (54 impacts among
// 35 contacts in one step as the first columns land).
TEST(AnyStepWork, TurningBoxOfCirclesStrikesNoImpactWithoutAnImpulse)
{
    model::World world = model::makeRotatingBoxWithCircles(2000);
    Simulation simulation(settingsUnderTest());
    std::vector<ImpactRecord> log;
    simulation.setImpactLog(&log);
    int struck = 0;
    int contacts = 0;
    for (int i = 0; i < 400; ++i) {
        model::spinFixedBodies(world, Vec2::Zero(), model::kRotatingContainerAngularVelocity);
        log.clear();
        simulation.step(world);
        const StepProfile& p = simulation.profile();
        // A circle's contact has one point, so the cap is kMaxImpactsPerPoint a contact.
        ASSERT_LE(p.impacts, (constants::kMaxImpactsPerPoint - 1) * p.contacts) << "step " << i;
        contacts += p.contacts;
        for (const ImpactRecord& r : log) {
            Scalar impulse = 0;
            for (int k = 0; k < r.count; ++k)
                impulse += r.points[static_cast<std::size_t>(k)].normalImpulse;
            ASSERT_GT(impulse, 0) << "step " << i << ", bodies " << r.ownerA << " and " << r.ownerB;
        }
        struck += p.impacts;
    }
    EXPECT_GT(struck, 0); // the box does tumble its circles into each other
    EXPECT_LT(struck, contacts);
}

// Box2D v3's spinner starts its 6076 bodies overlapping each other and the arm, whose tip turns
// at 100 m/s: the first step's impacts pass the arm's blows on through the packed pile. Its impact
// pass used to run to the cap of 8 impacts per contact point, 258,336 impacts, each looking again
// at a dozen or more contacts (4.7 s), and the next step's, among 380,000 speculative contacts,
// took over a minute. The pass now also stops after looking at 16 contacts per contact of the
// step (contact_solver_detail.h); in this packed pile, where each impact looks at more than a
// dozen, that ends it at about one impact per contact.
TEST(AnyStepWork, SpinnerStartingInAPackedPileStrikesAboutOneImpactPerContact)
{
    model::World world = model::makeSpinner(6076);
    Simulation simulation(settingsUnderTest());
    simulation.step(world);
    const StepProfile& p = simulation.profile();
    ASSERT_GT(p.contacts, 10000);
    EXPECT_GT(p.impacts, 0);
    EXPECT_LE(p.impacts, 2 * p.contacts);
}

// A large world gives a body the share of a strike (2·h times the striker's speed) only from the
// bodies that can reach it this step (constants::kLocalStrikeShareMinBodies). The world's share
// gave every body of the spinner's heap a margin as wide as its fastest body's: about 60 contacts
// a body, and steps of seconds. Counted: a field of 400 boxes at rest keeps the contacts it has
// alone when a ball flies past far away at 100 m/s.
model::World fieldOfBoxes(int columns, int rows, Scalar gap)
{
    model::World world = makeEmptyWorld(IntegratorKind::SemiImplicitEuler, 1.0 / 240.0);
    for (int row = 0; row < rows; ++row) {
        for (int column = 0; column < columns; ++column) {
            world.bodies.push_back(
                makeBox("box", 1.0, 0.5, 0.5, Vec2(column * (0.5 + gap), row * (0.5 + gap))));
        }
    }
    return world;
}

/// A large world (kLocalStrikeShareMinBodies bodies or more) for the strike-share tests: 400
/// boxes at rest 50 m above the origin, far from what the test builds there, stepped at h.
model::World largeWorldFarAway(Scalar h)
{
    model::World world = fieldOfBoxes(20, 20, 0.001);
    world.settings.timeStep = h;
    for (model::Body& box : world.bodies)
        box.state.position += Vec2(0, 50);
    return world;
}

/// A thin fixed wall, 2 cm thick and 2 m high, whose face towards −x stands at x = face (e = 1,
/// no friction).
model::Body thinWallAt(Scalar face)
{
    model::Body wall = withMaterial(makeBox("wall", 1.0, 0.02, 2.0, Vec2(face + 0.01, 0)), 1.0, 0);
    wall.fixed = true;
    wall.updateDerived();
    return wall;
}

TEST(AnyStepWork, FastBodyFarAwayAddsNoContactsToALargeField)
{
    constexpr int kSide = 20;
    const model::World alone = fieldOfBoxes(kSide, kSide, 0.001);
    ASSERT_GE(alone.bodies.size(), constants::kLocalStrikeShareMinBodies);
    model::World withBall = alone;
    withBall.bodies.push_back(makeBall("bullet", 1.0, 0.1, Vec2(-30, -30), Vec2(100, 0)));
    Simulation quiet(settingsUnderTest());
    Simulation disturbed(settingsUnderTest());
    model::World a = alone;
    for (int i = 0; i < 5; ++i) {
        quiet.step(a);
        disturbed.step(withBall);
        // Neighbours 1 mm apart, and diagonal ones 1.4 mm apart, touch within their margins:
        // about 3.7 contacts a box.
        ASSERT_GT(quiet.profile().contacts, kSide * kSide);
        ASSERT_EQ(disturbed.profile().contacts, quiet.profile().contacts) << "step " << i;
    }
    // And the field moved as it does alone: the ball never came near.
    for (std::size_t i = 0; i < a.bodies.size(); ++i)
        ASSERT_EQ(withBall.bodies[i].state.position, a.bodies[i].state.position) << "box " << i;
}

// The share is taken from the speed at which a striker approaches, not from its speed in the
// world's frame: bodies flying together strike each other no harder than at rest. A field of 400
// boxes 1 m apart, all flying at 100 m/s in zero gravity, finds no contact: each box's own
// margin (0.42 m at 1/240 s) does not reach the next box. In the world's frame each took a share
// of 2·h·100 m/s (0.83 m) and paired with its neighbours out to 2.5 m, as the spinner's heap
// thrown by its arm did (about 40 contacts a body).
TEST(AnyStepWork, FieldFlyingTogetherTakesNoStrikeShare)
{
    model::World world = fieldOfBoxes(20, 20, 1.0);
    ASSERT_GE(world.bodies.size(), constants::kLocalStrikeShareMinBodies);
    const Vec2 velocity(100, 0);
    for (model::Body& box : world.bodies)
        box.state.velocity = velocity;
    Simulation simulation(settingsUnderTest());
    for (int i = 0; i < 5; ++i) {
        simulation.step(world);
        ASSERT_EQ(simulation.profile().contacts, 0) << "step " << i;
    }
    for (const model::Body& box : world.bodies)
        ASSERT_EQ(box.state.velocity, velocity);
}

// A large world whose bodies travel far in a step, on average more than a quarter of their
// bounding radius, is split so that each substep's margins keep each body among its neighbours
// (the spinner's heap flung by its arm made dozens of speculative contacts a body). A small world
// and a world at rest are not; the fastest body alone does not split a large world.
TEST(SolverSubsteps, LargeWorldsTravellingFarSplitToAQuarterOfTheirSizeOnAverage)
{
    model::World world = fieldOfBoxes(20, 20, 0.1);
    ASSERT_GE(world.bodies.size(), constants::kLocalStrikeShareMinBodies);
    const Scalar radius = world.bodies[0].geometry.boundingRadius; // √2 · 0.25 m
    EXPECT_EQ(crowdSubsteps(world, 1.0 / 240.0), 1);
    // Every box 2.4 radii a step: 9.6 quarters, ten substeps (39 at 1/60 s).
    for (model::Body& box : world.bodies)
        box.state.velocity = Vec2(0, 2.4 * radius * 240);
    EXPECT_EQ(crowdSubsteps(world, 1.0 / 240.0), 10);
    EXPECT_EQ(crowdSubsteps(world, 1.0 / 60.0), 39);
    // Half of them at rest: 4.8 quarters on average.
    for (std::size_t i = 0; i < world.bodies.size(); i += 2)
        world.bodies[i].state.velocity = Vec2::Zero();
    EXPECT_EQ(crowdSubsteps(world, 1.0 / 240.0), 5);
    // One box 50 radii a step and the rest at rest: 0.125 radii on average.
    for (model::Body& box : world.bodies)
        box.state.velocity = Vec2::Zero();
    world.bodies[7].state.velocity = Vec2(50 * radius * 240, 0);
    EXPECT_EQ(crowdSubsteps(world, 1.0 / 240.0), 1);
    // A small world is split for its physics alone.
    model::World small = fieldOfBoxes(4, 4, 0.1);
    for (model::Body& box : small.bodies)
        box.state.velocity = Vec2(0, 2.4 * radius * 240);
    EXPECT_EQ(crowdSubsteps(small, 1.0 / 240.0), 1);
}

// A fixed body that moves (a paddle, the spinner's arm) counts as travelling: a step with one is
// never solved on contacts found once with the whole step's margins, which would give the bodies
// it can strike 2·h times its speed and, at 1/60 s, every body near the spinner's arm a share of
// 6.7 m (its first step: 294,000 contacts a substep and 5.1 s; now 68,000 and 1.1 s).
TEST(SolverSubsteps, AMovingFixedBodyCountsAsTravelling)
{
    model::World world = fieldOfBoxes(2, 1, 0.1);
    EXPECT_EQ(fastestTravel(world, 0.1), 0);
    model::Body paddle = makeBox("paddle", 1.0, 0.1, 2.0, Vec2(-3, 0));
    paddle.fixed = true;
    paddle.state.velocity = Vec2(10, 0);
    paddle.updateDerived();
    world.bodies.push_back(paddle);
    EXPECT_DOUBLE_EQ(fastestTravel(world, 0.1), 1.0);
}

// A step's contacts are found once when each dynamic body travels at most a small part of its own
// size (kReuseContactsMaxTravelFraction of its bounding radius, up to kReuseContactsMaxBodyTravel):
// a pyramid of 1 m boxes settling at a few millimetres a step, not circles of 0.25 m tumbling at
// centimetres a step, and never a moving fixed body beyond the constant margin.
TEST(SolverSubsteps, ContactsLastTheStepWhileEachBodyMovesASmallPartOfItsSize)
{
    const Scalar h = 1.0 / 60.0;
    const auto worldWith = [](model::Body body) {
        model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 60.0);
        body.updateDerived();
        world.bodies.push_back(body);
        return world;
    };
    // A 1 m box (bounding radius √2/2 m): 1.4 cm a step allowed, five times the constant margin.
    model::Body box = makeBox("box", 1.0, 1.0, 1.0, Vec2::Zero());
    const Scalar boxAllowance = constants::kReuseContactsMaxTravelFraction * std::sqrt(0.5);
    ASSERT_GT(boxAllowance, constants::kReuseContactsMaxTravel);
    box.state.velocity = Vec2(0, -0.99 * boxAllowance / h);
    EXPECT_TRUE(contactsLastTheStep(worldWith(box), h));
    box.state.velocity = Vec2(0, -1.01 * boxAllowance / h);
    EXPECT_FALSE(contactsLastTheStep(worldWith(box), h));
    // Its spin counts at its bounding radius, as fastestTravel's.
    box.state.velocity = Vec2::Zero();
    box.state.angularVelocity = 1.01 * boxAllowance / (h * std::sqrt(0.5));
    EXPECT_FALSE(contactsLastTheStep(worldWith(box), h));

    // A ball of 0.25 m: 5 mm a step; the turning box's circles at 1/60 s move 3 cm.
    model::Body ball = makeBall("ball", 1.0, 0.25, Vec2::Zero());
    ball.state.velocity = Vec2(0.006 / h, 0);
    EXPECT_FALSE(contactsLastTheStep(worldWith(ball), h));
    ball.state.velocity = Vec2(0.0045 / h, 0);
    EXPECT_TRUE(contactsLastTheStep(worldWith(ball), h));

    // A plank 10 m long: its bounding radius would allow 10 cm, the cap allows 2 cm.
    model::Body plank = makeBox("plank", 1.0, 10.0, 0.2, Vec2::Zero());
    plank.state.velocity = Vec2(0, -1.01 * constants::kReuseContactsMaxBodyTravel / h);
    EXPECT_FALSE(contactsLastTheStep(worldWith(plank), h));

    // A fixed body that moves gets only the constant margin, whatever its size.
    model::Body paddle = makeBox("paddle", 1.0, 1.0, 1.0, Vec2::Zero());
    paddle.fixed = true;
    paddle.state.velocity = Vec2(1.01 * constants::kReuseContactsMaxTravel / h, 0);
    EXPECT_FALSE(contactsLastTheStep(worldWith(paddle), h));
    // And a body that is not a number never has its contacts kept.
    box.state.angularVelocity = 0;
    box.state.velocity = Vec2(std::nan(""), 0);
    EXPECT_FALSE(contactsLastTheStep(worldWith(box), h));
}

// Nor do they need contacts for their own travel: what brings two surfaces together is the speed
// of one relative to the other. Boxes 0.3 m apart flying together at 100 m/s can meet no
// neighbour within a step, at 1/240 s or at 1/60 s; each box's own margin (0.42 m at 1/240 s,
// 1.7 m over a step of 1/60 s) paired it with every neighbour within twice that, making
// speculative contacts that the passes and the impacts then looked at every step (the spinner's
// heap thrown by its arm kept 182,000 contacts a step in its opening, 144,000 now).
TEST(AnyStepWork, FieldFlyingTogetherKeepsNoContactsForItsOwnTravel)
{
    for (const Scalar h : {1.0 / 240.0, 1.0 / 60.0}) {
        model::World world = fieldOfBoxes(20, 20, 0.3);
        world.settings.timeStep = h;
        ASSERT_GE(world.bodies.size(), constants::kLocalStrikeShareMinBodies);
        for (model::Body& box : world.bodies)
            box.state.velocity = Vec2(100, 20);
        Simulation simulation(settingsUnderTest());
        for (int i = 0; i < 5; ++i) {
            simulation.step(world);
            ASSERT_EQ(simulation.profile().contacts, 0) << "step " << i << " at h = " << h;
        }
        for (const model::Body& box : world.bodies)
            ASSERT_EQ(box.state.velocity, Vec2(100, 20));
    }
}

// What the share is for, in a large world: a light ball at rest 5 cm in front of a thin wall is
// struck by a heavy one at 50 m/s early in a step and leaves at nearly 100 m/s, 0.3 m in the
// rest of the step. Its own margin (2 mm at rest) would not find the wall; the striker's share
// does, and the ball bounces off the wall instead of passing through it. Checked at 1/60 s and
// at 1/240 s, among 400 boxes at rest far away, so on the large world's path (the world's share
// of a small world covers it too).
TEST(AnyStepWork, BallStruckNearAWallInALargeWorldBouncesOffIt)
{
    for (const Scalar h : {1.0 / 240.0, 1.0 / 60.0}) {
        model::World world = largeWorldFarAway(h);
        constexpr Scalar kRadius = 0.05;
        constexpr Scalar kWallX = 1.0; // the wall's face towards the balls
        // The light ball's surface 5 cm from the wall; the heavy one 0.1·h·50 m/s from the light
        // one, so that they meet a tenth into the (sub)step.
        const Scalar substep = h / solverSubsteps(h, constants::kMaxSolverStep);
        const Vec2 lightAt(kWallX - 0.05 - kRadius, 0);
        const Vec2 heavyAt = lightAt - Vec2(2 * kRadius + 0.1 * substep * 50, 0);
        world.bodies.push_back(withMaterial(makeBall("heavy", 100.0, kRadius, heavyAt, Vec2(50, 0)), 1.0, 0));
        world.bodies.push_back(withMaterial(makeBall("light", 0.1, kRadius, lightAt), 1.0, 0));
        world.bodies.push_back(thinWallAt(kWallX));
        ASSERT_GE(world.bodies.size(), constants::kLocalStrikeShareMinBodies);
        const std::size_t heavy = world.bodies.size() - 3;
        const std::size_t light = world.bodies.size() - 2;
        Simulation simulation(settingsUnderTest());
        simulation.step(world);
        // Struck at nearly twice the heavy ball's speed, the light ball has met the wall and
        // turned back; then both balls stay in front of the wall as they knock about.
        EXPECT_LT(world.bodies[light].state.velocity.x(), 0) << "h = " << h;
        for (int i = 0; i < 10; ++i) {
            for (const std::size_t ball : {heavy, light}) {
                ASSERT_LT(world.bodies[ball].state.position.x(), kWallX - kRadius + constants::kLinearSlop)
                    << world.bodies[ball].name << ", step " << i << " at h = " << h;
            }
            simulation.step(world);
        }
    }
}

// A blow passed on down a chain, in a large world: a ball at 20 m/s strikes the first of a row
// of six touching balls at rest (e = 1), and the last one leaves at 20 m/s towards a thin wall
// 3 cm behind it, within the same step. The last ball is five links from the striker, so only a
// share handed on along the row finds the wall; the world's share of a small world found it too.
TEST(AnyStepWork, BlowPassedDownARowInALargeWorldStopsAtTheWall)
{
    for (const Scalar h : {1.0 / 240.0, 1.0 / 60.0}) {
        model::World world = largeWorldFarAway(h);
        constexpr Scalar kRadius = 0.05;
        constexpr int kRow = 6;
        const Scalar substep = h / solverSubsteps(h, constants::kMaxSolverStep);
        // The striker meets the row a tenth into the (sub)step.
        world.bodies.push_back(withMaterial(
            makeBall("striker", 1.0, kRadius, Vec2(-2 * kRadius - 0.1 * substep * 20, 0), Vec2(20, 0)), 1.0, 0));
        for (int k = 0; k < kRow; ++k)
            world.bodies.push_back(withMaterial(makeBall("row", 1.0, kRadius, Vec2(2 * kRadius * k, 0)), 1.0, 0));
        const std::size_t last = world.bodies.size() - 1;
        const Scalar wallX = 2 * kRadius * (kRow - 1) + kRadius + 0.03;
        world.bodies.push_back(thinWallAt(wallX));
        ASSERT_GE(world.bodies.size(), constants::kLocalStrikeShareMinBodies);
        Simulation simulation(settingsUnderTest());
        for (int i = 0; i < 10; ++i) {
            simulation.step(world);
            for (std::size_t b = 400; b < world.bodies.size() - 1; ++b) {
                ASSERT_LT(world.bodies[b].state.position.x(), wallX - kRadius + constants::kLinearSlop)
                    << world.bodies[b].name << " " << b << ", step " << i << " at h = " << h;
            }
        }
        // The blow went down the row, off the wall and back up the row: the striker leaves at
        // the speed it came with (all the balls are alike and e = 1).
        EXPECT_NEAR(world.bodies[400].state.velocity.x(), -20, 1e-9) << "h = " << h;
        EXPECT_NEAR(world.bodies[last].state.velocity.x(), 0, 1e-9) << "h = " << h;
    }
}

// A moving fixed body strikes too: a paddle (a fixed box given 30 m/s, as the spinner's arm or a
// turning box's wall is) meets a ball at rest 15 cm in front of a thin fixed wall a tenth into a
// step of 1/240 s; the ball leaves at 60 m/s (22.5 cm in the rest of the step) and must meet
// the wall, not pass it. Both shares
// left fixed bodies out as strikers, and the ball passed through the wall; now the world's share
// counts the paddle's speed, and a large world's its speed where it meets the ball. In a small
// world and among 400 boxes. One step only: the paddle goes on at 30 m/s whatever it meets, and
// in the next steps it would squeeze the ball against the wall.
TEST(AnyStepWork, BallStruckByAMovingFixedBodyMeetsTheWall)
{
    for (const bool large : {false, true}) {
        const Scalar h = 1.0 / 240.0;
        model::World world = large ? largeWorldFarAway(h) : makeEmptyWorld(IntegratorKind::SemiImplicitEuler, h);
        constexpr Scalar kRadius = 0.05;
        constexpr Scalar kWallX = 1.0;
        // 15 cm from the wall, so that the paddle (12.5 cm a step) leaves it room.
        const Vec2 ballAt(kWallX - 0.15 - kRadius, 0);
        model::Body paddle =
            withMaterial(makeBox("paddle", 1.0, 0.02, 0.5, Vec2(ballAt.x() - kRadius - 0.01 - 0.1 * h * 30, 0)), 1.0, 0);
        paddle.fixed = true;
        paddle.state.velocity = Vec2(30, 0);
        paddle.updateDerived();
        world.bodies.push_back(paddle);
        world.bodies.push_back(withMaterial(makeBall("ball", 0.1, kRadius, ballAt), 1.0, 0));
        world.bodies.push_back(thinWallAt(kWallX));
        const std::size_t ball = world.bodies.size() - 2;
        ASSERT_EQ(world.bodies.size() >= constants::kLocalStrikeShareMinBodies, large);
        Simulation simulation(settingsUnderTest());
        simulation.step(world);
        EXPECT_LT(world.bodies[ball].state.position.x(), kWallX - kRadius + constants::kLinearSlop)
            << (large ? "large world" : "small world");
    }
}

// A box pinched between two fixed bodies that close on it: a paddle tilted by 8° sweeps at
// 30 m/s through a wall (fixed bodies do not collide), as v3's spinner's arm passes over its
// ring. Struck back and forth between the two, the box took every impact the pass allowed (32 a
// step for its two contacts) and one such body in the spinner left at 568 m/s. Counted: each
// contact of the pinched box takes at most kMaxFixedImpactsPerContact impacts a (sub)step, and
// the box leaves the wedge no faster than a few times the paddle.
TEST(AnyStepWork, BoxPinchedBetweenTwoFixedBodiesTakesFewImpacts)
{
    for (const Scalar h : {1.0 / 240.0, 1.0 / 60.0, 1.0 / 30.0}) {
        model::World world = makeEmptyWorld(IntegratorKind::SemiImplicitEuler, h);
        model::Body wall = withMaterial(makeBox("wall", 1.0, 0.2, 2.0, Vec2(1.1, 0)), 0.1, 0.1);
        wall.fixed = true;
        wall.updateDerived();
        constexpr Scalar kPaddleSpeed = 30;
        model::Body paddle = withMaterial(makeBox("paddle", 1.0, 0.2, 0.6, Vec2(0, 0.1)), 0.1, 0);
        paddle.fixed = true;
        paddle.state.angle = 8 * kPi / 180;
        paddle.state.velocity = Vec2(kPaddleSpeed, 0);
        paddle.updateDerived();
        world.bodies.push_back(wall);
        world.bodies.push_back(paddle);
        world.bodies.push_back(withMaterial(makeBox("box", 0.1, 0.5, 0.5, Vec2(0.6, 0)), 0.1, 0.1));
        const model::Body& box = world.bodies.back();
        Simulation simulation(settingsUnderTest());
        int pinchedSteps = 0;
        for (int i = stepsFor(world, 0.2); i > 0; --i) {
            simulation.step(world);
            const StepProfile& p = simulation.profile();
            ASSERT_TRUE(isFinite(box.state.position)) << "h = " << h;
            EXPECT_LE(p.impacts, detail::kMaxFixedImpactsPerContact * p.contacts) << "h = " << h;
            EXPECT_LT(box.state.velocity.norm(), 4 * kPaddleSpeed) << "h = " << h;
            pinchedSteps += p.impacts > p.contacts ? 1 : 0;
        }
        EXPECT_GT(pinchedSteps, 0) << "the box was never struck twice at one contact, h = " << h;
    }
}

} // namespace
} // namespace impetus::controller
