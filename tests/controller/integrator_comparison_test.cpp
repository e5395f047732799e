// Integrator ghosts, the engine side (src/controller/integrator_comparison.h): the three runs of
// one scene against the textbook. Explicit Euler's energy on a spring grows by exactly (1 + ω²h²)
// a step; on a projectile its position leads the parabola by ½·g·h·t; the position errors fall
// as h¹ for the Eulers and h⁴ for RK4.

#include "controller/integrator_comparison.h"
#include "model/scene_io.h"
#include "support/pendulum_theory.h"
#include "support/world_builders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>

namespace impetus {
namespace {

using controller::AnalyticKind;
using controller::IntegratorComparison;
using model::IntegratorKind;

constexpr std::size_t kEuler = 0;
constexpr std::size_t kSemiImplicit = 1;
constexpr std::size_t kRk4 = 2;

constexpr Scalar kMass = 1.0;
constexpr Scalar kStiffness = 40.0;
constexpr Scalar kAmplitude = 0.5;
constexpr Scalar kStep = 1.0 / 240.0;

model::World oscillator(Scalar h = kStep)
{
    return testing::makeOscillator(IntegratorKind::Rk4, h, kMass, kStiffness, kAmplitude);
}

TEST(IntegratorComparison, ExplicitEulersEnergyGrowsAsOnePlusOmegaSquaredHSquaredToTheN)
{
    IntegratorComparison comparison(oscillator());
    ASSERT_EQ(comparison.analytic(), AnalyticKind::Spring);
    const Scalar omega = std::sqrt(kStiffness / kMass);
    constexpr int kSteps = 480;
    for (int n = 1; n <= kSteps; ++n) {
        comparison.step();
        // x' = x + h·v, v' = v − h·ω²·x multiplies ½kx² + ½mv² by 1 + ω²h² exactly.
        const Scalar growth = std::pow(1 + omega * omega * kStep * kStep, n);
        ASSERT_NEAR(1 + comparison.energyError(kEuler), growth, 1e-12 * growth) << "step " << n;
    }
    // Semi-implicit Euler keeps a modified energy: its error stays within ω·h; RK4's is tiny.
    EXPECT_LT(std::abs(comparison.energyError(kSemiImplicit)), omega * kStep);
    EXPECT_LT(std::abs(comparison.energyError(kRk4)), 1e-6);
}

TEST(IntegratorComparison, ExplicitEulerLeadsAProjectileByHalfGHT)
{
    model::World world = testing::makeEmptyWorld(IntegratorKind::Rk4, kStep, Vec2(0, -9.81));
    world.bodies.push_back(testing::makeBall("ball", 0.5, 0.1, Vec2(0, 1), Vec2(3, 4)));
    IntegratorComparison comparison(world);
    ASSERT_EQ(comparison.analytic(), AnalyticKind::Projectile);
    constexpr int kSteps = 240;
    for (int n = 0; n < kSteps; ++n)
        comparison.step();
    const Scalar t = kSteps * kStep;
    // x_n = x₀ + v₀t + ½gt² − ½ght (explicit; semi-implicit: + ½ght); RK4 is exact.
    const Scalar offset = 0.5 * 9.81 * kStep * t;
    EXPECT_NEAR(*comparison.positionError(kEuler), offset, 1e-12);
    EXPECT_NEAR(*comparison.positionError(kSemiImplicit), offset, 1e-12);
    EXPECT_LT(*comparison.positionError(kRk4), 1e-12);
}

TEST(IntegratorComparison, ErrorFallsAsTheMethodsOrder)
{
    const std::vector<controller::StepError> errors =
        controller::errorAgainstStep(oscillator(), {1.0 / 100, 1.0 / 200, 1.0 / 400}, 1.0);
    ASSERT_EQ(errors.size(), 3u);
    for (std::size_t k = 0; k + 1 < errors.size(); ++k) {
        const auto order = [&](std::size_t i) {
            return std::log2(errors[k].positionError[i] / errors[k + 1].positionError[i]);
        };
        // Halving h divides the error by 2^order, approached as h → 0.
        EXPECT_NEAR(order(kEuler), 1.0, 0.1);
        EXPECT_NEAR(order(kSemiImplicit), 1.0, 0.1);
        EXPECT_NEAR(order(kRk4), 4.0, 0.1);
    }
}

TEST(IntegratorComparison, ADivergedRunStopsAndTheOthersGoOn)
{
    // At ω·h = 1 explicit Euler doubles the energy every step, 1 + ω²h² = 2: past 2¹⁰²⁴ it is no
    // longer a finite number. Semi-implicit Euler (stable for ω·h < 2) and RK4 (for ω·h < 2.8)
    // stay bounded.
    const Scalar h = 1 / std::sqrt(kStiffness / kMass);
    IntegratorComparison comparison(oscillator(h));
    constexpr int kSteps = 1200;
    for (int n = 0; n < kSteps; ++n)
        comparison.step();
    EXPECT_TRUE(comparison.diverged(kEuler));
    EXPECT_FALSE(comparison.diverged(kSemiImplicit));
    EXPECT_FALSE(comparison.diverged(kRk4));
    // The two that did not diverge kept time; the one that did stopped when it did.
    EXPECT_NEAR(comparison.world(kRk4).time, kSteps * h, 1e-9);
    EXPECT_NEAR(comparison.world(kSemiImplicit).time, kSteps * h, 1e-9);
    EXPECT_LT(comparison.world(kEuler).time, kSteps * h);
    EXPECT_LT(std::abs(comparison.energyError(kSemiImplicit)), 1.0);
    // A new time step starts every run again, diverged or not.
    comparison.setTimeStep(kStep);
    EXPECT_FALSE(comparison.diverged(kEuler));
}

/// A bob on a rod of `length` from `pivot`, at θ₀ from straight down (towards +x), swinging at θ̇₀.
model::World rodPendulum(Vec2 pivot, Scalar length, Scalar theta0, Scalar thetaDot0)
{
    model::World world = testing::makeEmptyWorld(IntegratorKind::Rk4, kStep, Vec2(0, -9.81));
    const Vec2 arm(std::sin(theta0), -std::cos(theta0));
    const Vec2 across(std::cos(theta0), std::sin(theta0));
    world.bodies.push_back(testing::makeBall("bob", 1.0, 0.1, pivot + length * arm, length * thetaDot0 * across));
    model::Joint rod;
    rod.type = model::JointType::Rod;
    rod.bodyA = model::BodyId{0};
    rod.anchorB = pivot;
    rod.length = length;
    world.joints.push_back(rod);
    return world;
}

// sin(θ/2) = k·sn(ω₀t + u₀, k) against θ'' = −(g/L)·sin θ integrated on its own, by RK4 with a
// step so small (10⁻⁴ s) that its error is far below the tolerance: the same θ at every time,
// for a start with both an angle and a swing speed (which sets u₀ and k together).
TEST(IntegratorComparison, PendulumFollowsTheExactSolutionAtAnyAmplitude)
{
    constexpr Scalar kLength = 1.5;
    constexpr Scalar kTheta0 = 1.1; // 63°: far from the small-angle case
    constexpr Scalar kThetaDot0 = -1.7; // rad/s, swinging back down
    const Vec2 pivot(0.5, 3.0);
    const model::World world = rodPendulum(pivot, kLength, kTheta0, kThetaDot0);
    ASSERT_EQ(controller::analyticKind(world), AnalyticKind::Pendulum);

    const Scalar rate = 9.81 / kLength;
    const auto accel = [&](Scalar theta) { return -rate * std::sin(theta); };
    Scalar theta = kTheta0;
    Scalar omega = kThetaDot0;
    constexpr Scalar kH = 1e-4;
    constexpr int kPerCheck = 3700; // 0.37 s: checks at unround times, through several swings
    for (int check = 1; check <= 10; ++check) {
        for (int n = 0; n < kPerCheck; ++n) {
            const Scalar k1x = omega;
            const Scalar k1v = accel(theta);
            const Scalar k2x = omega + kH / 2 * k1v;
            const Scalar k2v = accel(theta + kH / 2 * k1x);
            const Scalar k3x = omega + kH / 2 * k2v;
            const Scalar k3v = accel(theta + kH / 2 * k2x);
            const Scalar k4x = omega + kH * k3v;
            const Scalar k4v = accel(theta + kH * k3x);
            theta += kH / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
            omega += kH / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
        }
        const Scalar t = check * kPerCheck * kH;
        const Vec2 expected = pivot + kLength * Vec2(std::sin(theta), -std::cos(theta));
        const std::optional<Vec2> exact = controller::analyticPosition(world, AnalyticKind::Pendulum, 0, t);
        ASSERT_TRUE(exact.has_value());
        EXPECT_LT((*exact - expected).norm(), 1e-9) << "t = " << t;
    }
}

// Released from rest at θ₀ it is back after the large-amplitude period T = 4K(sin(θ₀/2))/ω₀, and
// half a period later it is at −θ₀.
TEST(IntegratorComparison, PendulumReturnsAfterTheLargeAmplitudePeriod)
{
    constexpr Scalar kLength = 2.0;
    constexpr Scalar kTheta0 = std::numbers::pi_v<Scalar> / 4;
    const model::World world = rodPendulum(Vec2::Zero(), kLength, kTheta0, 0);
    const Vec2 start = world.bodies[0].state.position;
    const Scalar period = testing::pendulumPeriod(kLength, 9.81, kTheta0);
    const Vec2 back = *controller::analyticPosition(world, AnalyticKind::Pendulum, 0, period);
    EXPECT_LT((back - start).norm(), 1e-9);
    const Vec2 across = *controller::analyticPosition(world, AnalyticKind::Pendulum, 0, period / 2);
    EXPECT_LT((across - Vec2(-start.x(), start.y())).norm(), 1e-9);
    // Going over the top is no swing: not recognised.
    EXPECT_EQ(controller::analyticKind(rodPendulum(Vec2::Zero(), kLength, kTheta0, 10.0)), AnalyticKind::None);
}

// The bodies a joint holds move by semi-implicit Euler whatever the integrator (docs/physics.md,
// "Collisions and contacts", step 5): on the pendulum example the three runs are one, and they
// keep to the exact swing within the joint solver's accuracy.
TEST(IntegratorComparison, PendulumExampleRunsAlikeUnderEveryIntegrator)
{
    model::SceneLoadResult r = model::loadSceneFile(std::filesystem::path(IMPETUS_EXAMPLES_DIR) / "pendulum.json");
    ASSERT_TRUE(r.ok());
    IntegratorComparison comparison(*r.world);
    ASSERT_EQ(comparison.analytic(), AnalyticKind::Pendulum);
    for (int n = 0; n < 480; ++n)
        comparison.step();
    const Scalar error = *comparison.positionError(kRk4);
    EXPECT_EQ(*comparison.positionError(kEuler), error);
    EXPECT_EQ(*comparison.positionError(kSemiImplicit), error);
    // The engine's swing is semi-implicit Euler with the rod's corrections at 1/240 s: after two
    // seconds of a 3 m/s swing it is 6 mm off the exact one (a timing error of 2 ms).
    EXPECT_LT(error, 0.01);
}

TEST(IntegratorComparison, RecognisesOnlyTheTextbookCases)
{
    EXPECT_EQ(controller::analyticKind(oscillator()), AnalyticKind::Spring);
    model::World damped = oscillator();
    damped.springs[0].damping = 0.1;
    EXPECT_EQ(controller::analyticKind(damped), AnalyticKind::None);
    model::World dragged = oscillator();
    dragged.settings.drag = 0.1;
    EXPECT_EQ(controller::analyticKind(dragged), AnalyticKind::None);
    model::World rested = oscillator();
    rested.springs[0].restLength = 0.2;
    EXPECT_EQ(controller::analyticKind(rested), AnalyticKind::None);
    const auto example = [](const char* name) {
        model::SceneLoadResult r = model::loadSceneFile(std::filesystem::path(IMPETUS_EXAMPLES_DIR) / name);
        EXPECT_TRUE(r.ok()) << name;
        return r.ok() ? controller::analyticKind(*r.world) : AnalyticKind::None;
    };
    EXPECT_EQ(example("projectile.json"), AnalyticKind::Projectile);
    EXPECT_EQ(example("spring.json"), AnalyticKind::Spring);
    EXPECT_EQ(example("pendulum.json"), AnalyticKind::Pendulum);
    EXPECT_EQ(example("spring-chain.json"), AnalyticKind::None);
}

} // namespace
} // namespace impetus
