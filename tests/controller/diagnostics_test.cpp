// Energy, momentum and angular momentum of small worlds, worked by hand.

#include "controller/diagnostics.h"
#include "support/world_builders.h"

#include <gtest/gtest.h>

#include <limits>

namespace impetus::controller {
namespace {

using model::IntegratorKind;
using testing::makeBall;
using testing::makeEmptyWorld;

TEST(Diagnostics, EnergyOfOneBodyWorkedByHand)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 0.01, Vec2(0, -9.81));
    // m = 2 kg, r = 0.5 m: I = ½·2·0.25 = 0.25 kg·m².
    world.bodies.push_back(makeBall("ball", 2.0, 0.5, Vec2(1, 3), Vec2(3, 4)));
    world.bodies[0].state.angularVelocity = 2.0;
    const Energy e = computeEnergy(world);
    EXPECT_NEAR(e.kinetic, 0.5 * 2 * 25 + 0.5 * 0.25 * 4, 1e-12); // 25 + 0.5
    EXPECT_NEAR(e.potential, 2 * 9.81 * 3, 1e-12);
    EXPECT_EQ(e.elastic, 0);
    EXPECT_NEAR(e.total(), 25.5 + 58.86, 1e-12);
}

TEST(Diagnostics, PotentialIsMeasuredFromYZeroAndNegativeBelowIt)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 0.01, Vec2(0, -9.81));
    world.bodies.push_back(makeBall("low", 1.0, 0.1, Vec2(0, -2)));
    EXPECT_NEAR(computeEnergy(world).potential, -19.62, 1e-12);
}

TEST(Diagnostics, ElasticEnergyOfAStretchedSpring)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 0.01);
    world.bodies.push_back(makeBall("a", 1.0, 0.1, Vec2(0, 0)));
    world.bodies.push_back(makeBall("b", 1.0, 0.1, Vec2(3, 4))); // 5 m apart
    model::Spring spring;
    spring.bodyA = model::BodyId{0};
    spring.bodyB = model::BodyId{1};
    spring.stiffness = 8;
    spring.restLength = 4;
    world.springs.push_back(spring);
    EXPECT_NEAR(computeEnergy(world).elastic, 0.5 * 8 * 1 * 1, 1e-12);
}

TEST(Diagnostics, MomentumAndAngularMomentumAboutTheOrigin)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 0.01);
    world.bodies.push_back(makeBall("a", 2.0, 0.5, Vec2(0, 1), Vec2(3, 0)));
    world.bodies.push_back(makeBall("b", 1.0, 0.5, Vec2(2, 0), Vec2(0, -1)));
    world.bodies[1].state.angularVelocity = 4.0;
    EXPECT_NEAR((linearMomentum(world) - Vec2(6, -1)).norm(), 0.0, 1e-12);
    // a: m·(x × v) = 2·(0·0 − 1·3) = −6. b: 1·(2·(−1) − 0) = −2, plus I·ω = 0.125·4 = 0.5.
    EXPECT_NEAR(angularMomentum(world), -6 - 2 + 0.5, 1e-12);
}

TEST(Diagnostics, FixedBodiesAreLeftOut)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 0.01, Vec2(0, -9.81));
    world.bodies.push_back(makeBall("wall", 50.0, 1.0, Vec2(0, 10), Vec2(1, 1)));
    world.bodies[0].fixed = true;
    world.bodies[0].updateDerived();
    const Energy e = computeEnergy(world);
    EXPECT_EQ(e.kinetic, 0);
    EXPECT_EQ(e.potential, 0);
    EXPECT_EQ(linearMomentum(world), Vec2::Zero());
    EXPECT_EQ(angularMomentum(world), 0);
}

TEST(Diagnostics, FirstNonFiniteBodyNamesTheFirstBodyThatIsNotANumber)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 0.01);
    world.bodies.push_back(makeBall("a", 1.0, 0.1, Vec2(0, 0)));
    world.bodies.push_back(makeBall("b", 1.0, 0.1, Vec2(1, 0)));
    world.bodies.push_back(makeBall("c", 1.0, 0.1, Vec2(2, 0)));
    EXPECT_EQ(firstNonFiniteBody(world), std::nullopt);
    world.bodies[2].state.angularVelocity = std::numeric_limits<double>::infinity();
    EXPECT_EQ(firstNonFiniteBody(world), std::optional<std::size_t>(2));
    world.bodies[1].state.velocity.y() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(firstNonFiniteBody(world), std::optional<std::size_t>(1));
    world.bodies[1].state.velocity.y() = 0;
    world.bodies[1].state.angle = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(firstNonFiniteBody(world), std::optional<std::size_t>(1));
    world.bodies[0].state.position.x() = -std::numeric_limits<double>::infinity();
    EXPECT_EQ(firstNonFiniteBody(world), std::optional<std::size_t>(0));
}

} // namespace
} // namespace impetus::controller
