// The fixed-step driver: the clock, the choice of integrator, copies and determinism.

#include "controller/simulation.h"
#include "support/world_builders.h"

#include <gtest/gtest.h>

namespace impetus::controller {
namespace {

using model::IntegratorKind;
using testing::makeBall;
using testing::makeEmptyWorld;
using testing::makeOscillator;

TEST(Simulation, StepAdvancesTheClockByTheFixedStep)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 0.02, Vec2(0, -9.81));
    world.bodies.push_back(makeBall("ball", 1.0, 0.1, Vec2(0, 0)));
    Simulation simulation;
    for (int i = 0; i < 5; ++i)
        simulation.step(world);
    EXPECT_EQ(world.stepCount, 5);
    EXPECT_NEAR(world.time, 0.1, 1e-15);
}

// The world's integrator setting picks the method: one explicit Euler step of a dropped ball
// leaves it where it was (x += h·v with v = 0), semi-implicit Euler moves it by −g·h².
TEST(Simulation, UsesTheIntegratorTheWorldNames)
{
    const Scalar h = 0.1;
    model::World euler = makeEmptyWorld(IntegratorKind::Euler, h, Vec2(0, -10));
    euler.bodies.push_back(makeBall("ball", 1.0, 0.1, Vec2(0, 0)));
    model::World semi = euler;
    semi.settings.integrator = IntegratorKind::SemiImplicitEuler;
    model::World rk4 = euler;
    rk4.settings.integrator = IntegratorKind::Rk4;

    Simulation simulation;
    simulation.step(euler);
    simulation.step(semi);
    simulation.step(rk4);
    EXPECT_NEAR(euler.bodies[0].state.position.y(), 0.0, 1e-15);
    EXPECT_NEAR(semi.bodies[0].state.position.y(), -0.1, 1e-15);
    EXPECT_NEAR(rk4.bodies[0].state.position.y(), -0.05, 1e-15); // exact: ½gh²
    for (const model::World* w : {&euler, &semi, &rk4})
        EXPECT_NEAR(w->bodies[0].state.velocity.y(), -1.0, 1e-15);
}

// A World is a value: a copy taken before a run is the state to reset to, untouched by the run.
TEST(Simulation, WorldCopiesWithAssignment)
{
    model::World world = makeOscillator(IntegratorKind::Rk4, 0.01, 1.0, 10.0, 0.3);
    const model::World start = world;
    Simulation simulation;
    for (int i = 0; i < 50; ++i)
        simulation.step(world);
    EXPECT_NE(world, start);
    world = start;
    EXPECT_EQ(world, start);
    EXPECT_EQ(world.time, 0);
}

// The same scene gives the same bits on every run.
TEST(Simulation, TwoRunsAreBitIdentical)
{
    auto runOnce = [] {
        model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240.0, Vec2(0, -9.81));
        world.settings.drag = 0.1;
        world.bodies.push_back(makeBall("a", 1.0, 0.3, Vec2(-1, 0.2), Vec2(0.5, 1.0)));
        world.bodies.push_back(makeBall("b", 2.5, 0.4, Vec2(1.2, -0.3), Vec2(-0.2, 0.1)));
        model::Spring spring;
        spring.bodyA = model::BodyId{0};
        spring.anchorA = Vec2(0.2, 0.1);
        spring.bodyB = model::BodyId{1};
        spring.stiffness = 40;
        spring.damping = 0.3;
        spring.restLength = 1.0;
        world.springs.push_back(spring);
        Simulation simulation;
        for (int i = 0; i < 1000; ++i)
            simulation.step(world);
        return world;
    };
    EXPECT_EQ(runOnce(), runOnce());
}

} // namespace
} // namespace impetus::controller
