// Soft landings (issue 16, item 6): a soft body's damping given as a damping ratio ζ. What ζ means
// for one spring between two ellipses, checked against the damped oscillator, and what the default
// ζ does to a landing on plastic ground.

#include "controller/simulation.h"
#include "controller/soft/soft_body_builder.h"
#include "controller/diagnostics.h"
#include "controller/soft/soft_body_shape.h"
#include "controller/soft/soft_damping.h"
#include "controller/soft/soft_stability.h"
#include "controller/solver_under_test.h"
#include "model/constants.h"
#include "support/world_builders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>
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

/// A 1 m, 1 kg soft box of `density` ellipses per m² and `stiffness` N/m at the default damping
/// ratio, with no gravity, stretched by 10% about its centre and released.
model::World stretchedSoftBox(Scalar density, Scalar stiffness, Scalar h, model::IntegratorKind integrator)
{
    model::World world = makeEmptyWorld(integrator, h);
    model::Body box = makeBox("jelly", 1, 1, 1, Vec2::Zero());
    box.soft = model::SoftSettings{};
    box.soft->ellipsesPerSquareMeter = density;
    box.soft->stiffness = stiffness;
    world.bodies.push_back(box);
    controller::prepareSoftBodies(world);
    for (Vec2& p : world.softBodies[0].positions)
        p *= 1.1;
    return world;
}

TEST(SoftDampingPass, TheDefaultBoxIsNotSplitForItsStiffnessAloneAndNotAsFinelyAsBefore)
{
    // Before the damping pass the default box (ζ = 2: c = 15.8 N·s/m, damping rate γ = 8c/m =
    // 8,100/s) took 14 substeps at 1/240 s and 56 at 1/60 s under RK4, for stability. Now its
    // stiffness needs 3 and 10 (ω·h ≤ 1.8 with ω = 1,022/s, as with the old 1 N·s/m), and the pass
    // keeps 2c·h/m ≤ 0.75 for accuracy: 12 and 45.
    const model::World world240 = defaultSoftBoxAbovePlasticGround(0.5, constants::kDefaultTimeStep);
    const model::SoftGrid& grid = world240.softBodies.at(0);
    const Scalar omega = std::sqrt(grid.maxSpringRate);
    const Scalar pairRate = 2 * grid.springDamping / grid.ellipseMass;
    EXPECT_NEAR(omega, 1021.8, 0.1);
    EXPECT_NEAR(pairRate, 2024, 1);
    for (const auto& [h, stiffnessSubsteps, substeps] : {std::tuple{constants::kDefaultTimeStep, 3, 12},
                                                          std::tuple{1.0 / 60.0, 10, 45}}) {
        EXPECT_EQ(static_cast<int>(std::ceil(omega * h / constants::kSoftContactStabilityLimit)), stiffnessSubsteps);
        const controller::SoftStability s = controller::softStability(defaultSoftBoxAbovePlasticGround(0.5, h));
        EXPECT_TRUE(s.stable);
        EXPECT_EQ(s.substeps, substeps) << "at h = " << h;
        EXPECT_LE(pairRate * h / s.substeps, constants::kSoftDampingPassLimit);
        EXPECT_NE(s.message.find("damping"), std::string::npos) << s.message;
    }
}

TEST(SoftDampingPass, AStiffFineGridThatHitTheCapRunsStableAndNeverGainsEnergy)
{
    // 20,000 N/m at 1024 per m² with ζ = 2: the damping rate 8c/m = 102,000/s used to need 180
    // substeps of 1/240 s under RK4, past the cap of 64, and the run diverged. Its stiffness needs
    // 30 (ω = 12,806/s); the pass is stable at any step, so at the cap it runs, and every step
    // loses energy.
    for (const model::IntegratorKind integrator :
         {model::IntegratorKind::Rk4, model::IntegratorKind::SemiImplicitEuler, model::IntegratorKind::Euler}) {
        model::World world = stretchedSoftBox(1024, 20000, constants::kDefaultTimeStep, integrator);
        const controller::SoftStability s = controller::softStability(world);
        EXPECT_TRUE(s.stable) << s.message;
        EXPECT_EQ(s.substeps, constants::kMaxSoftSubsteps);
        controller::Simulation simulation(controller::settingsUnderTest());
        Scalar energy = controller::computeEnergy(world).total();
        const Scalar start = energy;
        for (int i = 0; i < 24; ++i) {
            simulation.step(world);
            const Scalar now = controller::computeEnergy(world).total();
            ASSERT_TRUE(std::isfinite(now));
            // Never more than rounding above the step before (it settles to 1e-26 J).
            EXPECT_LE(now, energy + 1e-15 * start) << model::integratorName(integrator) << " step " << i;
            energy = now;
        }
        EXPECT_LT(energy, 1e-3 * start) << model::integratorName(integrator); // and it settles in 0.1 s
    }
}

TEST(SoftDampingPass, KeepsMomentumAngularMomentumAndTakesOutWhatItReports)
{
    // A spinning, stretched, drifting box: one pass with a strong damping (2c·h/m = 50).
    model::World world = stretchedSoftBox(64, 2000, constants::kDefaultTimeStep, model::IntegratorKind::Rk4);
    model::SoftGrid& grid = world.softBodies.at(0);
    for (std::size_t i = 0; i < grid.size(); ++i)
        grid.velocities[i] = Vec2(1, -2) + cross(3.0, grid.positions[i]) + 0.2 * grid.positions[i];
    const Vec2 momentum = controller::linearMomentum(world);
    const Scalar angular = controller::angularMomentum(world);
    const Scalar kinetic = controller::computeEnergy(world).kinetic;
    // The kinetic energy of the deformation, the motion left over from the rigid one (the box is
    // centred on the origin, and the stretching carries no angular momentum).
    const auto deformation = [&] {
        Scalar sum = 0;
        for (std::size_t i = 0; i < grid.size(); ++i)
            sum += 0.5 * grid.ellipseMass * (grid.velocities[i] - Vec2(1, -2) - cross(3.0, grid.positions[i])).squaredNorm();
        return sum;
    };
    const Scalar deformed = deformation();
    controller::SoftDampingScratch scratch;
    const Scalar taken = controller::dampSoftGrids(world, 50 * grid.ellipseMass / (2 * grid.springDamping), scratch);
    EXPECT_NEAR((controller::linearMomentum(world) - momentum).norm(), 0, 1e-12);
    EXPECT_NEAR(controller::angularMomentum(world), angular, 1e-12 * std::abs(angular));
    EXPECT_GT(taken, 0);
    EXPECT_NEAR(controller::computeEnergy(world).kinetic, kinetic - taken, 1e-12 * kinetic);
    // What it took out is the deformation's, nearly all of it; the rigid motion stays.
    EXPECT_NEAR(taken, deformed - deformation(), 1e-9 * kinetic);
    EXPECT_LT(deformation(), 0.05 * deformed);
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
