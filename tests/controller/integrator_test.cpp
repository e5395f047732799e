// The integrators against analytic solutions: the projectile, the harmonic oscillator (error order
// and energy behaviour of each method) and a two-body spring system (coupled integration).

#include "controller/diagnostics.h"
#include "controller/integration/integrator.h"
#include "controller/simulation.h"
#include "model/scene_warnings.h"
#include "support/world_builders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace impetus::controller {
namespace {

using model::IntegratorKind;
using testing::makeBall;
using testing::makeEmptyWorld;
using testing::makeOscillator;

constexpr Scalar kPi = std::numbers::pi_v<Scalar>;

/// Runs `steps` fixed steps of `world`.
void run(model::World& world, int steps)
{
    Simulation simulation;
    for (int i = 0; i < steps; ++i)
        simulation.step(world);
}

// A projectile's position is quadratic in t, which every stage of RK4 integrates exactly: after
// 2 s the position matches x₀ + v₀t + ½gt² to rounding, for any step.
TEST(Rk4, IsExactForAProjectile)
{
    const Vec2 g(0, -9.81);
    const Vec2 x0(-1.5, 2.0);
    const Vec2 v0(3.0, 7.5);
    for (const Scalar h : {1.0 / 240.0, 1.0 / 30.0, 0.25}) {
        model::World world = makeEmptyWorld(IntegratorKind::Rk4, h, g);
        world.bodies.push_back(makeBall("ball", 0.3, 0.1, x0, v0));
        world.bodies[0].state.angularVelocity = 1.25;
        const int steps = static_cast<int>(std::lround(2.0 / h));
        run(world, steps);

        const Scalar t = steps * h;
        const Vec2 expected = x0 + v0 * t + 0.5 * g * t * t;
        const model::BodyState& s = world.bodies[0].state;
        EXPECT_NEAR(s.position.x(), expected.x(), 1e-12) << "h = " << h;
        EXPECT_NEAR(s.position.y(), expected.y(), 1e-12) << "h = " << h;
        EXPECT_NEAR(s.velocity.y(), v0.y() + g.y() * t, 1e-12) << "h = " << h;
        EXPECT_NEAR(s.angle, 1.25 * t, 1e-12) << "h = " << h;
    }
}

/// Largest |x(t) − A·cos(ωt)| over [0, duration] on the oscillator of makeOscillator.
Scalar oscillatorMaxError(IntegratorKind kind, Scalar h, Scalar duration)
{
    const Scalar mass = 2.0;
    const Scalar omega = 2 * kPi; // one period per second
    const Scalar amplitude = 0.5;
    model::World world = makeOscillator(kind, h, mass, mass * omega * omega, amplitude);
    Simulation simulation;
    Scalar maxError = 0;
    const int steps = static_cast<int>(std::lround(duration / h));
    for (int i = 1; i <= steps; ++i) {
        simulation.step(world);
        const Scalar t = i * h;
        const Vec2 exact(amplitude * std::cos(omega * t), 0);
        maxError = std::max(maxError, (world.bodies[0].state.position - exact).norm());
    }
    return maxError;
}

// Halving h divides a p-th order method's error by 2ᵖ: about 16 for RK4.
TEST(HarmonicOscillator, Rk4ErrorRatioShowsFourthOrder)
{
    const Scalar coarse = oscillatorMaxError(IntegratorKind::Rk4, 0.01, 2.0);
    const Scalar fine = oscillatorMaxError(IntegratorKind::Rk4, 0.005, 2.0);
    const Scalar ratio = coarse / fine;
    RecordProperty("rk4_error_ratio", std::to_string(ratio));
    std::cout << "RK4 max error h=0.01: " << coarse << ", h=0.005: " << fine << ", ratio " << ratio << '\n';
    EXPECT_GE(ratio, 14.0);
    EXPECT_LE(ratio, 18.0);
}

// And by about 2 for explicit Euler (first order). The steps are small enough that the error is in
// its asymptotic regime (the amplitude has grown by only ~4% over the run).
TEST(HarmonicOscillator, EulerErrorRatioShowsFirstOrder)
{
    const Scalar coarse = oscillatorMaxError(IntegratorKind::Euler, 0.001, 2.0);
    const Scalar fine = oscillatorMaxError(IntegratorKind::Euler, 0.0005, 2.0);
    const Scalar ratio = coarse / fine;
    RecordProperty("euler_error_ratio", std::to_string(ratio));
    std::cout << "Euler max error h=0.001: " << coarse << ", h=0.0005: " << fine << ", ratio " << ratio << '\n';
    EXPECT_GE(ratio, 1.9);
    EXPECT_LE(ratio, 2.1);
}

// Semi-implicit Euler is first order too.
TEST(HarmonicOscillator, SemiImplicitEulerErrorRatioShowsFirstOrder)
{
    const Scalar coarse = oscillatorMaxError(IntegratorKind::SemiImplicitEuler, 0.001, 2.0);
    const Scalar fine = oscillatorMaxError(IntegratorKind::SemiImplicitEuler, 0.0005, 2.0);
    const Scalar ratio = coarse / fine;
    std::cout << "Semi-implicit Euler ratio " << ratio << '\n';
    EXPECT_GE(ratio, 1.9);
    EXPECT_LE(ratio, 2.1);
}

// Explicit Euler on x'' = −ω²x multiplies the energy by exactly (1 + ω²h²) each step:
// E' = ½m[(v − hω²x)² + ω²(x + hv)²] = (1 + ω²h²)·½m(v² + ω²x²).
TEST(HarmonicOscillator, ExplicitEulerEnergyGrowsAsOnePlusOmegaSquaredHSquaredToTheN)
{
    const Scalar mass = 1.5;
    const Scalar omega = 3.0;
    const Scalar h = 0.01;
    model::World world = makeOscillator(IntegratorKind::Euler, h, mass, mass * omega * omega, 0.4);
    const Scalar e0 = computeEnergy(world).total();
    Simulation simulation;
    for (int n = 1; n <= 1000; ++n) {
        simulation.step(world);
        if (n % 250 == 0) {
            const Scalar expected = e0 * std::pow(1 + omega * omega * h * h, n);
            EXPECT_NEAR(computeEnergy(world).total() / expected, 1.0, 1e-10) << "after " << n << " steps";
        }
    }
    // And it really has grown: by (1.0009)^1000 ≈ 2.46.
    EXPECT_GT(computeEnergy(world).total(), 2.4 * e0);
}

// Semi-implicit Euler is symplectic: over 100 periods its energy oscillates within O(ωh) of the
// true value and does not drift.
TEST(HarmonicOscillator, SemiImplicitEulerKeepsEnergyBounded)
{
    const Scalar mass = 1.0;
    const Scalar omega = 2 * kPi;
    const Scalar h = 0.01;
    model::World world = makeOscillator(IntegratorKind::SemiImplicitEuler, h, mass, mass * omega * omega, 1.0);
    const Scalar e0 = computeEnergy(world).total();
    Simulation simulation;
    Scalar maxDeviation = 0;
    Scalar firstPeriodMax = 0;
    Scalar lastPeriodMax = 0;
    const int stepsPerPeriod = 100;
    const int periods = 100;
    for (int n = 1; n <= stepsPerPeriod * periods; ++n) {
        simulation.step(world);
        const Scalar deviation = std::abs(computeEnergy(world).total() / e0 - 1);
        maxDeviation = std::max(maxDeviation, deviation);
        if (n <= stepsPerPeriod)
            firstPeriodMax = std::max(firstPeriodMax, deviation);
        if (n > stepsPerPeriod * (periods - 1))
            lastPeriodMax = std::max(lastPeriodMax, deviation);
    }
    EXPECT_LT(maxDeviation, omega * h);
    // No secular drift: the last period's band is the first period's band.
    EXPECT_NEAR(lastPeriodMax, firstPeriodMax, 1e-3 * firstPeriodMax);
}

// The warning for a spring too stiff for the step (model::sceneWarnings, docs/scene-format.md)
// sits where the engine's own oscillator starts to grow: semi-implicit Euler at ω·h = 2, RK4 at
// 2√2, and explicit Euler, which grows at any step, where its energy doubles within a period
// (ω·h ≈ 0.11 undamped, later with a dashpot). Each integrator just inside its limit is not
// warned about and does not run away; just outside, it is warned about and does.
TEST(HarmonicOscillator, TheStiffSpringWarningSitsWhereTheEngineStartsToGrow)
{
    const Scalar mass = 2.0;
    const Scalar h = 1.0 / 240.0;
    // A ball on a spring to a pivot, released 0.1 m out along x. With a zero rest length the force
    // −k·r is linear in every direction, so the ball swings through the pivot exactly as the
    // oscillator does; but its swing across the spring, as fast, is one the dashpot (along the
    // spring) does not damp, and the warning rightly counts it. So a damped oscillator is a spring
    // of rest length 0.2 m released 1 mm short of it: across, its tension then pushes rather than
    // pulls, and the fastest motion is the damped one along it, which stays within 0.2 m of rest
    // over the periods measured here.
    const auto oscillator = [&](IntegratorKind kind, Scalar omegaStep, Scalar zeta) {
        const Scalar omega = omegaStep / h;
        model::World world = makeOscillator(kind, h, mass, mass * omega * omega, 0.1);
        world.springs[0].damping = 2 * zeta * mass * omega;
        if (zeta > 0) {
            world.springs[0].restLength = 0.2;
            world.bodies[0].state.position = Vec2(0.199, 0);
        }
        return world;
    };
    const auto warned = [&](IntegratorKind kind, Scalar omegaStep, Scalar zeta) {
        const std::vector<model::SceneProblem> warnings = model::sceneWarnings(oscillator(kind, omegaStep, zeta));
        return !warnings.empty() && warnings[0].path == "springs[0]";
    };
    // The energy's growth per period of 2π/(ωh) steps over `periods` periods: the largest energy
    // of the last five periods against the largest of the first five, so that neither the swing
    // of energy between the spring and the ball within a period nor a period of a few steps that
    // samples it unevenly counts.
    const auto growthPerPeriod = [&](IntegratorKind kind, Scalar omegaStep, Scalar zeta, int periods) {
        model::World world = oscillator(kind, omegaStep, zeta);
        const Scalar stepsPerPeriod = 2 * kPi / omegaStep;
        const int window = static_cast<int>(std::ceil(5 * stepsPerPeriod));
        const int steps = static_cast<int>(std::ceil(periods * stepsPerPeriod));
        Simulation simulation;
        Scalar first = 0;
        Scalar last = 0;
        for (int n = 1; n <= steps; ++n) {
            simulation.step(world);
            const Scalar energy = computeEnergy(world).total();
            if (n <= window)
                first = std::max(first, energy);
            if (n > steps - window)
                last = std::max(last, energy);
        }
        return std::pow(last / first, stepsPerPeriod / (steps - window));
    };

    // The largest stable ω·h of each, undamped, and of semi-implicit Euler at ζ = 0.5.
    EXPECT_NEAR(*model::stableOmegaStep(IntegratorKind::SemiImplicitEuler, 0), 2.0, 1e-9);
    EXPECT_NEAR(*model::stableOmegaStep(IntegratorKind::Rk4, 0), 2 * std::sqrt(2.0), 1e-9);
    const std::optional<double> semiImplicit = model::stableOmegaStep(IntegratorKind::SemiImplicitEuler, 0.5);
    ASSERT_TRUE(semiImplicit.has_value());
    EXPECT_NEAR(*semiImplicit, 2 * (std::sqrt(1.25) - 0.5), 1e-9);

    // Each row: an integrator at ω·h and ζ, whether it is warned about, and the range its energy's
    // growth per period falls in, over that many periods.
    struct Row {
        IntegratorKind kind;
        Scalar omegaStep;
        Scalar zeta;
        int periods;
        bool warned;
        Scalar growthAbove;
        Scalar growthBelow;
    };
    constexpr Scalar kAny = std::numeric_limits<Scalar>::infinity();
    const Row rows[] = {
        // Semi-implicit Euler keeps its energy bounded inside ω·h = 2 and runs away outside.
        {IntegratorKind::SemiImplicitEuler, 1.95, 0, 200, false, 1 - 1e-3, 1 + 1e-3},
        {IntegratorKind::SemiImplicitEuler, 2.05, 0, 50, true, 10, kAny},
        // RK4 damps its oscillation inside its limit and amplifies it outside: |R(iωh)| < 1 at
        // 2.75, > 1 at 2.9, with R(z) = 1 + z + z²/2 + z³/6 + z⁴/24.
        {IntegratorKind::Rk4, 2.75, 0, 50, false, 0, 1},
        {IntegratorKind::Rk4, 2.9, 0, 50, true, 1, kAny},
        // With a dashpot, both hold less: semi-implicit Euler takes the damping from the velocity
        // at the start of the step, stable to ω·h = 2(√(1 + ζ²) − ζ), 1.24 at ζ = 0.5; RK4 to
        // about 2.62 near ζ = 0.5. The undamped limits would call these steps safe.
        {IntegratorKind::SemiImplicitEuler, 1.2, 0.5, 50, false, 0, 1},
        {IntegratorKind::SemiImplicitEuler, 1.3, 0.5, 50, true, 1, kAny},
        {IntegratorKind::Rk4, 2.55, 0.5, 50, false, 0, 1},
        {IntegratorKind::Rk4, 2.75, 0.5, 50, true, 1, kAny},
        // Explicit Euler grows at any step: warned about once its energy doubles within a period.
        {IntegratorKind::Euler, 0.10, 0, 20, false, 0, 2},
        {IntegratorKind::Euler, 0.12, 0, 20, true, 2, kAny},
        // A dashpot of ζ = 0.05 takes 1 − 2ζωh a step back: at ω·h = 0.12 the energy no longer
        // doubles within a period, and no warning is given; at 0.3 it does again, and one is.
        {IntegratorKind::Euler, 0.12, 0.05, 20, false, 0, 2},
        {IntegratorKind::Euler, 0.3, 0.05, 20, true, 2, kAny},
    };
    for (const Row& row : rows) {
        SCOPED_TRACE(::testing::Message() << "integrator " << static_cast<int>(row.kind) << ", ω·h = " << row.omegaStep
                                          << ", ζ = " << row.zeta);
        EXPECT_EQ(warned(row.kind, row.omegaStep, row.zeta), row.warned);
        const Scalar growth = growthPerPeriod(row.kind, row.omegaStep, row.zeta, row.periods);
        EXPECT_GT(growth, row.growthAbove);
        EXPECT_LT(growth, row.growthBelow);
    }
}

// RK4's energy error on the oscillator is tiny at the default step.
TEST(HarmonicOscillator, Rk4ConservesEnergyAtTheDefaultStep)
{
    const Scalar omega = 2 * kPi;
    model::World world = makeOscillator(IntegratorKind::Rk4, 1.0 / 240.0, 1.0, omega * omega, 1.0);
    const Scalar e0 = computeEnergy(world).total();
    run(world, 240 * 10);
    EXPECT_NEAR(computeEnergy(world).total() / e0, 1.0, 1e-7);
}

// Two free balls joined by a spring form one coupled system: their separation oscillates with
// ω = √(k/μ), μ = m₁m₂/(m₁+m₂), while the centre of mass moves uniformly. RK4 over the whole
// state must follow this to fourth order; integrating the bodies one at a time would not.
TEST(CoupledSpring, TwoBodiesOscillateAtTheReducedMassFrequency)
{
    const Scalar m1 = 1.0;
    const Scalar m2 = 3.0;
    const Scalar k = 50.0;
    const Scalar rest = 1.0;
    const Scalar stretch = 0.2;
    const Scalar mu = m1 * m2 / (m1 + m2);
    const Scalar omega = std::sqrt(k / mu);

    auto maxError = [&](Scalar h) {
        model::World world = makeEmptyWorld(IntegratorKind::Rk4, h);
        world.bodies.push_back(makeBall("a", m1, 0.1, Vec2(0, 0), Vec2(0, 0.3)));
        world.bodies.push_back(makeBall("b", m2, 0.1, Vec2(rest + stretch, 0), Vec2(0, 0.3)));
        model::Spring spring;
        spring.bodyA = model::BodyId{0};
        spring.bodyB = model::BodyId{1};
        spring.stiffness = k;
        spring.restLength = rest;
        world.springs.push_back(spring);
        Simulation simulation;
        Scalar worst = 0;
        const int steps = static_cast<int>(std::lround(1.0 / h));
        for (int i = 1; i <= steps; ++i) {
            simulation.step(world);
            const Scalar t = i * h;
            // Both move up at 0.3 m/s; the separation along x is rest + stretch·cos(ωt).
            const Scalar separation = world.bodies[1].state.position.x() - world.bodies[0].state.position.x();
            worst = std::max(worst, std::abs(separation - (rest + stretch * std::cos(omega * t))));
            EXPECT_NEAR(world.bodies[0].state.position.y(), 0.3 * t, 1e-12);
        }
        return worst;
    };
    const Scalar coarse = maxError(0.01);
    const Scalar fine = maxError(0.005);
    EXPECT_LT(coarse, 1e-5);
    EXPECT_GE(coarse / fine, 14.0);
    EXPECT_LE(coarse / fine, 18.0);
}

// Every integrator leaves a fixed body where it is, and moves a fixed body that has a velocity at
// exactly that velocity: no gravity, no spring changes it (infinite mass, prescribed motion).
TEST(Integrators, FixedBodiesFeelNoForce)
{
    for (const IntegratorKind kind : {IntegratorKind::Euler, IntegratorKind::SemiImplicitEuler, IntegratorKind::Rk4}) {
        model::World world = makeEmptyWorld(kind, 0.01, Vec2(0, -9.81));
        world.bodies.push_back(makeBall("anchor", 1.0, 0.1, Vec2(1, 2)));
        world.bodies[0].fixed = true;
        world.bodies[0].updateDerived();
        world.bodies.push_back(makeBall("belt", 1.0, 0.1, Vec2(-3, 0), Vec2(0.5, -0.25)));
        world.bodies[1].fixed = true;
        world.bodies[1].state.angularVelocity = 2.0;
        world.bodies[1].updateDerived();
        world.bodies.push_back(makeBall("bob", 1.0, 0.1, Vec2(1, 0)));
        for (const std::uint32_t other : {0u, 1u}) {
            model::Spring spring;
            spring.bodyA = model::BodyId{2};
            spring.bodyB = model::BodyId{other};
            spring.stiffness = 20;
            spring.damping = 0.5;
            spring.restLength = 1;
            world.springs.push_back(spring);
        }
        const model::BodyState still = world.bodies[0].state;
        run(world, 100);
        EXPECT_EQ(world.bodies[0].state, still) << model::integratorName(kind);
        const model::BodyState& moving = world.bodies[1].state;
        EXPECT_NEAR(moving.position.x(), -3 + 0.5 * 1.0, 1e-12) << model::integratorName(kind);
        EXPECT_NEAR(moving.position.y(), -0.25 * 1.0, 1e-12) << model::integratorName(kind);
        EXPECT_NEAR(moving.angle, 2.0, 1e-12) << model::integratorName(kind);
        EXPECT_EQ(moving.velocity, Vec2(0.5, -0.25)) << model::integratorName(kind);
        EXPECT_NE(world.bodies[2].state.position, Vec2(1, 0)) << model::integratorName(kind);
    }
}

} // namespace
} // namespace impetus::controller
