// Integrator ghosts, the engine side (src/controller/integrator_comparison.h): the three runs of
// one scene against the textbook. Explicit Euler's energy on a spring grows by exactly (1 + ω²h²)
// a step; on a projectile its position leads the parabola by ½·g·h·t; the position errors fall
// as h¹ for the Eulers and h⁴ for RK4.

#include "controller/integrator_comparison.h"
#include "model/scene_io.h"
#include "support/world_builders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

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
    EXPECT_EQ(example("pendulum.json"), AnalyticKind::None);
    EXPECT_EQ(example("spring-chain.json"), AnalyticKind::None);
}

} // namespace
} // namespace impetus
