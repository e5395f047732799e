// The force report against hand-worked statics: each part of the force on a body in a state
// whose forces are known in closed form.

#include "controller/force_report.h"
#include "controller/simulation.h"
#include "support/world_builders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace impetus::controller {
namespace {

using model::IntegratorKind;
using testing::makeBall;
using testing::makeBox;
using testing::makeEmptyWorld;
using testing::makeGround;
using testing::withMaterial;

constexpr Scalar kG = 9.81;

/// Steps `world` `steps` times.
void run(model::World& world, int steps)
{
    Simulation simulation;
    for (int i = 0; i < steps; ++i)
        simulation.step(world);
}

TEST(ForceReport, GravitySpringAndDragWorkedByHand)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240, Vec2(0, -kG));
    world.settings.drag = 0.5;
    // m = 2 kg at (1, 0) moving at (0, 3) m/s, on a spring k = 40 N/m, c = 0 to the world origin,
    // rest length 0.25 m: stretched by 0.75 m, it pulls with 30 N toward the origin.
    world.bodies.push_back(makeBall("ball", 2.0, 0.1, Vec2(1, 0), Vec2(0, 3)));
    model::Spring spring;
    spring.bodyA = model::BodyId{0};
    spring.anchorB = Vec2(0, 0);
    spring.stiffness = 40;
    spring.restLength = 0.25;
    world.springs.push_back(spring);

    const std::vector<BodyForces> forces = reportForces(world);
    ASSERT_EQ(forces.size(), 1u);
    EXPECT_NEAR(forces[0].gravity.x(), 0, 1e-12);
    EXPECT_NEAR(forces[0].gravity.y(), -2 * kG, 1e-12);
    EXPECT_NEAR(forces[0].springs.x(), -30, 1e-9);
    EXPECT_NEAR(forces[0].springs.y(), 0, 1e-9);
    EXPECT_NEAR(forces[0].drag.x(), 0, 1e-12);
    EXPECT_NEAR(forces[0].drag.y(), -1.5, 1e-12); // −b·v = −0.5 · 3
    EXPECT_EQ(forces[0].contactNormal, Vec2::Zero());
    EXPECT_EQ(forces[0].joints, Vec2::Zero());
    EXPECT_NEAR(forces[0].net().x(), -30, 1e-9);
    EXPECT_NEAR(forces[0].net().y(), -2 * kG - 1.5, 1e-9);
    EXPECT_NEAR(forces[0].acceleration.x(), -15, 1e-9); // a = F/m
    EXPECT_NEAR(forces[0].acceleration.y(), -kG - 0.75, 1e-9);
}

TEST(ForceReport, FixedBodiesFeelNothing)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240, Vec2(0, -kG));
    world.bodies.push_back(makeGround("floor", 4, 0.2));
    const std::vector<BodyForces> forces = reportForces(world);
    ASSERT_EQ(forces.size(), 1u);
    EXPECT_EQ(forces[0].net(), Vec2::Zero());
}

TEST(ForceReport, BoxRestingOnTheFloorIsHeldUpByMg)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240, Vec2(0, -kG));
    world.bodies.push_back(makeGround("floor", 4, 0.2));
    world.bodies.push_back(makeBox("box", 3.0, 0.5, 0.4, Vec2(0, 0.2)));
    run(world, 480); // 2 s: settled

    const BodyForces box = reportForces(world)[1];
    // At rest the floor carries the weight: N = m·g upward, no friction, no net force.
    EXPECT_NEAR(box.contactNormal.x(), 0, 1e-6);
    EXPECT_NEAR(box.contactNormal.y(), 3 * kG, 1e-3 * 3 * kG);
    EXPECT_NEAR(box.contactFriction.norm(), 0, 1e-6);
    EXPECT_NEAR(box.net().norm(), 0, 1e-3 * 3 * kG);
}

TEST(ForceReport, BlockAtRestOnAnInclineHasFrictionMgSinTheta)
{
    const Scalar theta = 20 * std::numbers::pi / 180; // tan 20° = 0.36 < μ = 0.8: it sticks
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240, Vec2(0, -kG));
    world.bodies.push_back(withMaterial(makeGround("ramp", 6, 0.2, Vec2::Zero(), theta), 0, 0.8));
    const Vec2 up(-std::sin(theta), std::cos(theta)); // the ramp's outward normal
    const Vec2 along(std::cos(theta), std::sin(theta)); // up the slope
    world.bodies.push_back(withMaterial(makeBox("block", 2.0, 0.4, 0.4, 0.2 * up, theta), 0, 0.8));
    run(world, 480);
    ASSERT_LT(world.bodies[1].state.velocity.norm(), 1e-3); // it stuck

    const BodyForces block = reportForces(world)[1];
    const Scalar weight = 2 * kG;
    EXPECT_NEAR(block.contactNormal.dot(up), weight * std::cos(theta), 1e-3 * weight);
    EXPECT_NEAR(block.contactNormal.dot(along), 0, 1e-3 * weight);
    EXPECT_NEAR(block.contactFriction.dot(along), weight * std::sin(theta), 1e-3 * weight);
    EXPECT_NEAR(block.contactFriction.dot(up), 0, 1e-3 * weight);
}

TEST(ForceReport, RodHoldsAHangingBobUpWithMg)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240, Vec2(0, -kG));
    world.bodies.push_back(makeBall("bob", 0.5, 0.05, Vec2(0, -1)));
    model::Joint rod;
    rod.type = model::JointType::Rod;
    rod.bodyA = model::BodyId{0};
    rod.anchorB = Vec2(0, 0);
    rod.length = 1;
    world.joints.push_back(rod);
    run(world, 240);

    const BodyForces bob = reportForces(world)[0];
    EXPECT_NEAR(bob.joints.x(), 0, 1e-6);
    EXPECT_NEAR(bob.joints.y(), 0.5 * kG, 1e-3 * 0.5 * kG);
}

TEST(ForceReport, RodTensionAtTheBottomOfTheSwingIsMgPlusMvSquaredOverL)
{
    // Released level with the pivot, the bob passes the bottom with v² = 2gL: T = 3mg there.
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 2400, Vec2(0, -kG));
    const Scalar mass = 0.5;
    world.bodies.push_back(makeBall("bob", mass, 0.05, Vec2(1, 0)));
    model::Joint rod;
    rod.type = model::JointType::Rod;
    rod.bodyA = model::BodyId{0};
    rod.anchorB = Vec2(0, 0);
    rod.length = 1;
    world.joints.push_back(rod);
    Simulation simulation;
    // Step until the bob crosses x = 0 (the bottom), then read the tension there.
    while (world.bodies[0].state.position.x() > 0)
        simulation.step(world);
    const Vec2 v = world.bodies[0].state.velocity;
    const Scalar expected = mass * kG + mass * v.squaredNorm() / 1.0;
    const BodyForces bob = reportForces(world)[0];
    EXPECT_NEAR(bob.joints.norm(), expected, 0.01 * expected);
    EXPECT_NEAR(expected, 3 * mass * kG, 0.01 * 3 * mass * kG);
}

} // namespace
} // namespace impetus::controller
