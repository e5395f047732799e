// The force model against Newton's laws: Hooke springs with damping, Stokes drag, and the
// conservation laws that internal forces must respect.

#include "controller/diagnostics.h"
#include "controller/integration/force_model.h"
#include "controller/simulation.h"
#include "model/constants.h"
#include "support/world_builders.h"

#include <gtest/gtest.h>

#include <cmath>

namespace impetus::controller {
namespace {

using model::IntegratorKind;
using testing::makeBall;
using testing::makeEmptyWorld;

std::vector<model::BodyState> statesOf(const model::World& world)
{
    std::vector<model::BodyState> states;
    for (const model::Body& body : world.bodies)
        states.push_back(body.state);
    return states;
}

// A stretched spring pulls with k·(L − L₀) along its line; a compressed one pushes.
TEST(ForceModel, SpringFollowsHookesLaw)
{
    for (const Scalar length : {1.5, 0.6}) {
        model::World world = makeEmptyWorld(IntegratorKind::Rk4, 0.01);
        world.bodies.push_back(makeBall("a", 2.0, 0.1, Vec2(0, 0)));
        world.bodies.push_back(makeBall("b", 4.0, 0.1, Vec2(0, length)));
        model::Spring spring;
        spring.bodyA = model::BodyId{0};
        spring.bodyB = model::BodyId{1};
        spring.stiffness = 30;
        spring.restLength = 1.0;
        world.springs.push_back(spring);
        std::vector<BodyDerivative> d;
        computeDerivatives(world, statesOf(world), d);
        const Scalar tension = 30 * (length - 1.0); // positive: pulls together
        EXPECT_NEAR(d[0].acceleration.y(), tension / 2.0, 1e-12);
        EXPECT_NEAR(d[1].acceleration.y(), -tension / 4.0, 1e-12);
        EXPECT_EQ(d[0].acceleration.x(), 0);
        EXPECT_EQ(d[0].angularAcceleration, 0); // anchors at the centres: no torque
    }
}

// Damping acts along the spring only: it resists the rate of change of length, and ignores
// relative motion across the spring.
TEST(ForceModel, SpringDampingActsAlongTheSpringOnly)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 0.01);
    // At rest length, moving apart along x at 2 m/s and sideways along y at 5 m/s.
    world.bodies.push_back(makeBall("a", 1.0, 0.1, Vec2(0, 0), Vec2(-1, 0)));
    world.bodies.push_back(makeBall("b", 1.0, 0.1, Vec2(1, 0), Vec2(1, 5)));
    model::Spring spring;
    spring.bodyA = model::BodyId{0};
    spring.bodyB = model::BodyId{1};
    spring.stiffness = 10;
    spring.damping = 3;
    spring.restLength = 1.0;
    world.springs.push_back(spring);
    std::vector<BodyDerivative> d;
    computeDerivatives(world, statesOf(world), d);
    // dL/dt = 2 m/s, so the damping tension is 3·2 = 6 N pulling the ends together.
    EXPECT_NEAR(d[0].acceleration.x(), 6.0, 1e-12);
    EXPECT_NEAR(d[1].acceleration.x(), -6.0, 1e-12);
    EXPECT_NEAR(d[0].acceleration.y(), 0.0, 1e-12);
    EXPECT_NEAR(d[1].acceleration.y(), 0.0, 1e-12);
}

// An anchor off the centre of mass turns the body: τ = r × F.
TEST(ForceModel, OffCentreAnchorGivesTorque)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 0.01);
    world.bodies.push_back(makeBall("wheel", 2.0, 0.5, Vec2(0, 0)));
    model::Spring spring;
    spring.bodyA = model::BodyId{0};
    spring.anchorA = Vec2(0.5, 0); // on the rim, to the right
    spring.anchorB = Vec2(0.5, 2.0); // a world point straight above the anchor
    spring.stiffness = 10;
    spring.restLength = 1.0;
    world.springs.push_back(spring);
    std::vector<BodyDerivative> d;
    computeDerivatives(world, statesOf(world), d);
    // F = 10·(2 − 1) = 10 N up at r = (0.5, 0): τ = 0.5·10 = 5 N·m; I = ½·2·0.25 = 0.25 kg·m².
    EXPECT_NEAR(d[0].acceleration.y(), 5.0, 1e-12);
    EXPECT_NEAR(d[0].angularAcceleration, 20.0, 1e-12);
}

// Gravity gives every body the same acceleration, whatever its mass.
TEST(ForceModel, GravityIsIndependentOfMass)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 0.01, Vec2(0.5, -9.81));
    world.bodies.push_back(makeBall("light", 0.1, 0.1, Vec2(0, 0)));
    world.bodies.push_back(makeBall("heavy", 100.0, 0.1, Vec2(3, 0)));
    std::vector<BodyDerivative> d;
    computeDerivatives(world, statesOf(world), d);
    for (const BodyDerivative& di : d) {
        EXPECT_NEAR(di.acceleration.x(), 0.5, 1e-12);
        EXPECT_NEAR(di.acceleration.y(), -9.81, 1e-12);
    }
}

// Falling under gravity with Stokes drag F = −b·v, v(t) = −(mg/b)(1 − e^(−bt/m)): the body
// follows this curve and reaches the terminal speed mg/b.
TEST(StokesDrag, ReachesTerminalSpeedMgOverB)
{
    const Scalar m = 0.5;
    const Scalar b = 2.0;
    const Scalar g = 9.81;
    const Scalar terminal = m * g / b;
    const Scalar tau = m / b;
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240.0, Vec2(0, -g));
    world.settings.drag = b;
    world.bodies.push_back(makeBall("drop", m, 0.05, Vec2(0, 100)));
    Simulation simulation;
    const int steps = 240 * 5; // 5 s = 20 τ
    for (int i = 1; i <= steps; ++i) {
        simulation.step(world);
        const Scalar t = i * world.settings.timeStep;
        EXPECT_NEAR(world.bodies[0].state.velocity.y(), -terminal * (1 - std::exp(-t / tau)), 1e-9);
    }
    EXPECT_NEAR(world.bodies[0].state.velocity.y(), -terminal, 1e-6 * terminal);
    EXPECT_EQ(world.bodies[0].state.velocity.x(), 0);
}

// Drag with no gravity decays a coasting body's velocity as e^(−bt/m) and stops it.
TEST(StokesDrag, CoastingBodyDecaysExponentially)
{
    const Scalar m = 2.0;
    const Scalar b = 0.8;
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 0.01);
    world.settings.drag = b;
    world.bodies.push_back(makeBall("puck", m, 0.1, Vec2(0, 0), Vec2(3, -4)));
    Simulation simulation;
    for (int i = 0; i < 300; ++i)
        simulation.step(world);
    const Scalar factor = std::exp(-b * 3.0 / m);
    EXPECT_NEAR(world.bodies[0].state.velocity.x(), 3 * factor, 1e-9);
    EXPECT_NEAR(world.bodies[0].state.velocity.y(), -4 * factor, 1e-9);
}

// A 1 g pebble under b = 1 N·s/m (drag rate b/m = 1000/s, far faster than the 1/60 s step) comes
// to rest without changing direction and then falls at its terminal speed m·g/b, under every
// integrator. Taken whole, the step multiplied its velocity by 1 − b·h/m = −15.7 every step (soak
// seed 136): the step is split so that b·h/m stays at most constants::kMaxDragRateStep.
TEST(StokesDrag, LightBodyUnderStrongDragStaysStable)
{
    const Scalar m = 1e-3;
    const Scalar b = 1.0;
    const Scalar g = 9.81;
    const Scalar h = 1.0 / 60.0;
    for (const IntegratorKind kind : {IntegratorKind::Euler, IntegratorKind::SemiImplicitEuler, IntegratorKind::Rk4}) {
        model::World world = makeEmptyWorld(kind, h, Vec2(0, -g));
        world.settings.drag = b;
        world.bodies.push_back(makeBall("pebble", m, 0.01, Vec2(0, 100), Vec2(5, 0)));
        EXPECT_EQ(dragSubsteps(world, h), static_cast<int>(std::ceil(b / m * h / constants::kMaxDragRateStep)));
        Simulation simulation;
        Scalar previousVx = 5;
        for (int i = 0; i < 60; ++i) {
            simulation.step(world);
            const Scalar vx = world.bodies[0].state.velocity.x();
            EXPECT_GE(vx, 0) << model::integratorName(kind) << ", step " << i;
            EXPECT_LE(vx, previousVx) << model::integratorName(kind) << ", step " << i;
            previousVx = vx;
        }
        // After 1 s = 1000 drag times the velocity is the terminal one to rounding: each
        // integrator's fixed point of v' = g − (b/m)·v is v = −m·g/b.
        EXPECT_NEAR(world.bodies[0].state.velocity.y(), -m * g / b, 1e-12) << model::integratorName(kind);
        EXPECT_NEAR(world.bodies[0].state.velocity.x(), 0, 1e-12) << model::integratorName(kind);
    }
    // Without drag, or with a heavy body, the step is not split for it.
    model::World heavy = makeEmptyWorld(IntegratorKind::Rk4, h);
    heavy.settings.drag = b;
    heavy.bodies.push_back(makeBall("ball", 1.0, 0.1, Vec2(0, 0)));
    EXPECT_EQ(dragSubsteps(heavy, h), 1);
    heavy.settings.drag = 0;
    EXPECT_EQ(dragSubsteps(heavy, h), 1);
}

// A spring between two free bodies is an internal force: with no gravity, every integrator keeps
// the total linear momentum (a linear invariant) to rounding. Anchors off the centres make the
// bodies spin too; RK4 then keeps angular momentum and energy to its truncation error.
TEST(SpringMomentum, TwoFreeBodiesConserveMomentum)
{
    for (const IntegratorKind kind : {IntegratorKind::Euler, IntegratorKind::SemiImplicitEuler, IntegratorKind::Rk4}) {
        model::World world = makeEmptyWorld(kind, 1.0 / 240.0);
        world.bodies.push_back(makeBall("a", 1.0, 0.3, Vec2(-1, 0.2), Vec2(0.5, 1.0)));
        world.bodies.push_back(makeBall("b", 2.5, 0.4, Vec2(1.2, -0.3), Vec2(-0.2, 0.1)));
        world.bodies[0].state.angularVelocity = 0.7;
        model::Spring spring;
        spring.bodyA = model::BodyId{0};
        spring.anchorA = Vec2(0.2, 0.1);
        spring.bodyB = model::BodyId{1};
        spring.anchorB = Vec2(-0.3, 0.0);
        spring.stiffness = 40;
        // Near the starting distance, so the balls swing about 2 m apart and never touch.
        spring.restLength = 2.2;
        world.springs.push_back(spring);

        const Vec2 p0 = linearMomentum(world);
        const Scalar l0 = angularMomentum(world);
        const Scalar e0 = computeEnergy(world).total();
        Simulation simulation;
        for (int i = 0; i < 240 * 5; ++i) {
            simulation.step(world);
            EXPECT_NEAR((linearMomentum(world) - p0).norm(), 0.0, 1e-12) << model::integratorName(kind);
        }
        if (kind == IntegratorKind::Rk4) {
            EXPECT_NEAR(angularMomentum(world), l0, 1e-6 * std::abs(l0));
            EXPECT_NEAR(computeEnergy(world).total(), e0, 1e-6 * e0);
        }
        // The spring really acted (the balls spin) and they never touched.
        EXPECT_NE(world.bodies[1].state.angularVelocity, 0) << model::integratorName(kind);
        EXPECT_EQ(world.collisionCount, 0) << model::integratorName(kind);
    }
}

} // namespace
} // namespace impetus::controller
