// Soft landings (issue 16, item 6): a soft body's damping given as a damping ratio ζ. What ζ means
// for one spring between two ellipses, checked against the damped oscillator, and what the default
// ζ does to a landing on plastic ground.

#include "controller/simulation.h"
#include "controller/soft/soft_body_builder.h"
#include "controller/soft/soft_body_shape.h"
#include "controller/solver_under_test.h"
#include "model/constants.h"
#include "support/world_builders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace impetus {
namespace {

using testing::makeBall;
using testing::makeBox;
using testing::makeEmptyWorld;
using testing::makeGround;
using testing::withMaterial;

/// The default soft box of the issue: 1 m square, 1 kg, `"soft": {}` (64 per m², 2000 N/m, the
/// default damping ratio), its bottom `drop` above plastic (e = 0) ground, at step `h` under RK4.
model::World defaultSoftBoxAbovePlasticGround(Scalar drop, Scalar h)
{
    model::World world = makeEmptyWorld(model::IntegratorKind::Rk4, h, Vec2(0, -constants::kStandardGravity));
    world.bodies.push_back(withMaterial(makeGround("ground", 20, 1), 0, 0.5));
    model::Body box = withMaterial(makeBox("jelly", 1, 1, 1, Vec2(0, 0.5 + drop)), 0, 0.5);
    box.soft = model::SoftSettings{};
    world.bodies.push_back(box);
    controller::prepareSoftBodies(world);
    return world;
}

/// The rebound's coefficient of restitution: the highest upward speed of the centre of mass after
/// the landing over the fastest downward speed before it.
Scalar measuredRestitution(model::World world, Scalar seconds)
{
    controller::Simulation simulation(controller::settingsUnderTest());
    const auto steps = static_cast<int>(std::lround(seconds / world.settings.timeStep));
    Scalar landing = 0; // most negative vertical velocity so far
    Scalar rebound = 0; // highest upward velocity after the landing began
    bool landed = false;
    for (int i = 0; i < steps; ++i) {
        simulation.step(world);
        const Scalar vy = world.bodies[1].state.velocity.y();
        if (!landed && vy < landing) {
            landing = vy;
        } else if (landing < 0) {
            landed = true;
            rebound = std::max(rebound, vy);
        }
    }
    EXPECT_TRUE(landed);
    return rebound / -landing;
}

TEST(SoftLanding, DefaultBoxLandsNearlyDeadOnPlasticGroundAtTheDefaultStep)
{
    // Dropped 0.5 m: it lands at 3.1 m/s.
    const Scalar e = measuredRestitution(defaultSoftBoxAbovePlasticGround(0.5, constants::kDefaultTimeStep), 1.5);
    EXPECT_LT(e, 0.3);
}

TEST(SoftLanding, DefaultBoxLandsNearlyDeadOnPlasticGroundAtASixtiethOfASecond)
{
    const Scalar e = measuredRestitution(defaultSoftBoxAbovePlasticGround(0.5, 1.0 / 60.0), 1.5);
    EXPECT_LT(e, 0.3);
}

TEST(SoftLanding, DefaultBoxStillRecoversFromBeingCrushed)
{
    // The crush test of soft_body_test.cpp with the default damping ratio: a 1 m² soft box (1 kg)
    // under a 20 kg rigid box for 5 s, then the box is lifted off. The stronger damping must not
    // cost the body its shape.
    model::World world = defaultSoftBoxAbovePlasticGround(0, constants::kDefaultTimeStep);
    world.bodies.push_back(withMaterial(makeBox("weight", 20, 1, 1, Vec2(0, 1.52)), 0, 0.5));
    const Scalar restArea = controller::softRestLatticeArea(world.softBodies[0]);
    controller::Simulation simulation(controller::settingsUnderTest());
    Scalar smallest = INFINITY;
    int inverted = 0;
    const auto steps = [&](Scalar seconds) {
        for (int i = 0; i < static_cast<int>(std::lround(seconds / constants::kDefaultTimeStep)); ++i) {
            simulation.step(world);
            smallest = std::min(smallest, controller::softLatticeArea(world.softBodies[0]) / restArea);
            inverted = std::max(inverted, controller::invertedSoftCells(world.softBodies[0]));
        }
    };
    steps(5.0);
    EXPECT_LT(controller::softLatticeArea(world.softBodies[0]) / restArea, 0.97);
    world.bodies[2].state.position = Vec2(100, 50);
    world.bodies[2].state.velocity = Vec2::Zero();
    steps(3.0);
    EXPECT_NEAR(controller::softLatticeArea(world.softBodies[0]) / restArea, 1.0, 0.01);
    EXPECT_EQ(inverted, 0);
    EXPECT_GT(smallest, 0.5);
}

/// Two balls of mass m joined by one spring of stiffness k, damped with the coefficient a soft
/// grid gives its springs at ratio ζ (controller::softSpringDamping for ellipses of mass m),
/// stretched by `stretch` from its rest length L and released at rest, no gravity. Returns the
/// stretch after every step of `h` for `seconds`.
std::vector<Scalar> pairStretch(Scalar zeta, Scalar mass, Scalar stiffness, Scalar stretch, Scalar h, Scalar seconds)
{
    model::SoftSettings settings;
    settings.stiffness = stiffness;
    settings.dampingRatio = zeta;
    const Scalar c = controller::softSpringDamping(settings, mass);

    constexpr Scalar kRest = 1.0;
    model::World world = makeEmptyWorld(model::IntegratorKind::Rk4, h);
    world.bodies.push_back(makeBall("a", mass, 0.1, Vec2(0, 0)));
    world.bodies.push_back(makeBall("b", mass, 0.1, Vec2(kRest + stretch, 0)));
    model::Spring spring;
    spring.bodyA = model::BodyId{0};
    spring.bodyB = model::BodyId{1};
    spring.stiffness = stiffness;
    spring.damping = c;
    spring.restLength = kRest;
    world.springs.push_back(spring);

    controller::Simulation simulation(controller::settingsUnderTest());
    std::vector<Scalar> x;
    for (int i = 0; i < static_cast<int>(std::lround(seconds / h)); ++i) {
        simulation.step(world);
        x.push_back((world.bodies[1].state.position - world.bodies[0].state.position).norm() - kRest);
    }
    return x;
}

TEST(SoftDampingRatio, GridSpringsGetTheCoefficientOfTheRatio)
{
    // c = 2ζ·√(k·m/2): 1 kg over 64 ellipses, 2000 N/m, ζ = 0.5 gives √(2000/128) = 3.95 N·s/m.
    model::World world = defaultSoftBoxAbovePlasticGround(1, constants::kDefaultTimeStep);
    world.bodies[1].soft->dampingRatio = 0.5;
    world.softBodies.clear();
    controller::prepareSoftBodies(world);
    const model::SoftGrid& grid = world.softBodies.at(0);
    ASSERT_EQ(grid.size(), 64u);
    const Scalar expected = 2 * 0.5 * std::sqrt(2000 * (1.0 / 64) / 2);
    EXPECT_DOUBLE_EQ(grid.springDamping, expected);
    for (const model::SoftSpring& s : grid.springs)
        EXPECT_EQ(s.damping, grid.springDamping);

    // The raw coefficient stays available and is used as given.
    world.bodies[1].soft->dampingMode = model::SoftDampingMode::Coefficient;
    world.bodies[1].soft->damping = 0.25;
    controller::prepareSoftBodies(world);
    EXPECT_EQ(world.softBodies.at(0).springDamping, 0.25);
    EXPECT_EQ(world.softBodies.at(0).springs.front().damping, 0.25);
}

TEST(SoftDampingRatio, CriticallyDampedPairDoesNotOvershoot)
{
    // ζ = 1: x(t) = x₀(1 + ωt)·e^(−ωt) never crosses zero. ω = √(k/μ) = √(2000·2/0.015625) = 506/s,
    // h = 1e-4 s keeps RK4 exact to far below the check.
    const Scalar x0 = 0.01;
    const std::vector<Scalar> x = pairStretch(1.0, 1.0 / 64, 2000, x0, 1e-4, 0.05);
    const Scalar lowest = *std::min_element(x.begin(), x.end());
    EXPECT_GE(lowest, -1e-9 * x0);
    EXPECT_LT(x.back(), 1e-6 * x0); // and it has come back: 25 time constants
    // ζ just below 1 does overshoot: the check can fail.
    const std::vector<Scalar> under = pairStretch(0.9, 1.0 / 64, 2000, x0, 1e-4, 0.05);
    EXPECT_LT(*std::min_element(under.begin(), under.end()), -1e-4 * x0);
}

TEST(SoftDampingRatio, LightlyDampedPairDecaysByTheLogarithmicDecrement)
{
    // ζ = 0.1: successive maxima of x fall by δ = 2πζ/√(1 − ζ²) = 0.6315. A slow pair (ω = 4.5/s) at
    // the default step samples each period 330 times; the peaks are refined by a parabola through
    // the three samples around each, so the stated tolerance 1e-3 (relative) is far above the
    // sampling and RK4 errors (~1e-5).
    const Scalar zeta = 0.1;
    const std::vector<Scalar> x = pairStretch(zeta, 1.0, 10, 0.1, constants::kDefaultTimeStep, 8.0);
    std::vector<Scalar> peaks;
    for (std::size_t i = 1; i + 1 < x.size(); ++i) {
        if (x[i] > x[i - 1] && x[i] >= x[i + 1] && x[i] > 0) {
            const Scalar a = x[i - 1], b = x[i], c = x[i + 1];
            const Scalar offset = 0.5 * (a - c) / (a - 2 * b + c);
            peaks.push_back(b - 0.25 * (a - c) * offset);
        }
    }
    ASSERT_GE(peaks.size(), 3u);
    const Scalar expected = 2 * std::numbers::pi * zeta / std::sqrt(1 - zeta * zeta);
    for (std::size_t i = 0; i + 1 < peaks.size(); ++i)
        EXPECT_NEAR(std::log(peaks[i] / peaks[i + 1]), expected, 1e-3 * expected) << "between peaks " << i << " and " << i + 1;
}

} // namespace
} // namespace impetus
