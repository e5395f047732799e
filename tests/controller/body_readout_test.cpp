// One body's readout worked by hand.

#include "controller/body_readout.h"
#include "controller/diagnostics.h"
#include "support/world_builders.h"

#include <gtest/gtest.h>

namespace impetus::controller {
namespace {

TEST(BodyReadout, StateMomentumAndEnergiesWorkedByHand)
{
    model::World world = testing::makeEmptyWorld(model::IntegratorKind::Rk4, 0.01, Vec2(0, -9.81));
    // m = 2 kg, r = 0.5 m: I = ½·2·0.25 = 0.25 kg·m².
    world.bodies.push_back(testing::makeBall("ball", 2.0, 0.5, Vec2(1, 3), Vec2(3, 4)));
    world.bodies[0].state.angularVelocity = 2.0;
    const BodyReadout r = readBody(world, model::BodyId{0});
    EXPECT_EQ(r.position, Vec2(1, 3));
    EXPECT_DOUBLE_EQ(r.speed, 5);
    EXPECT_EQ(r.momentum, Vec2(6, 8));
    EXPECT_NEAR(r.kinetic, 25 + 0.5, 1e-12);
    EXPECT_NEAR(r.potential, 2 * 9.81 * 3, 1e-12);
    // One body: its readout is the world's total.
    const Energy total = computeEnergy(world);
    EXPECT_NEAR(r.kinetic, total.kinetic, 1e-12);
    EXPECT_NEAR(r.potential, total.potential, 1e-12);
}

TEST(BodyReadout, FixedBodyHasNoEnergyOrMomentum)
{
    model::World world = testing::makeEmptyWorld(model::IntegratorKind::Rk4, 0.01, Vec2(0, -9.81));
    world.bodies.push_back(testing::makeGround("floor", 4, 0.2, Vec2(0, 5)));
    world.bodies[0].state.velocity = Vec2(1, 0);
    const BodyReadout r = readBody(world, model::BodyId{0});
    EXPECT_EQ(r.momentum, Vec2::Zero());
    EXPECT_EQ(r.kinetic, 0);
    EXPECT_EQ(r.potential, 0);
    EXPECT_DOUBLE_EQ(r.speed, 1);
}

} // namespace
} // namespace impetus::controller
