// Stacking: boxes rest at their true height and stacks stand.

#include "controller/simulation.h"
#include "controller/solver_under_test.h"
#include "model/example_scenes.h"
#include "support/world_builders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace impetus::controller {
namespace {

using model::IntegratorKind;
using testing::makeBox;
using testing::makeEmptyWorld;
using testing::makeGround;
using testing::withMaterial;

model::World makeStack(int count)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240.0, Vec2(0, -9.81));
    world.bodies.push_back(withMaterial(makeGround("ground", 20, 1), 0.0, 0.6));
    for (int i = 0; i < count; ++i)
        world.bodies.push_back(withMaterial(makeBox("box" + std::to_string(i), 1.0, 1.0, 1.0, Vec2(0, 0.5 + i)), 0.0, 0.6));
    return world;
}

// One box on the ground sits at its true height: penetration at most the slop (0.5 mm), no gap.
TEST(Stacking, RestingBoxSitsAtItsTrueHeight)
{
    model::World world = makeStack(1);
    Simulation simulation(settingsUnderTest());
    for (int i = 0; i < 240 * 2; ++i)
        simulation.step(world);
    const model::BodyState& s = world.bodies[1].state;
    EXPECT_NEAR(s.position.y(), 0.5, constants::kLinearSlop);
    EXPECT_LE(s.position.y(), 0.5 + 1e-9); // never floats above the floor
    EXPECT_NEAR(s.velocity.norm(), 0.0, 1e-9);
    EXPECT_TRUE(world.bodies[1].colliding);
    EXPECT_EQ(world.collisionCount, 1);
}

// Ten boxes stand for 10 s: none drifts sideways by more than a millimetre or sinks by more than
// the slop per contact.
TEST(Stacking, TenBoxStackStandsForTenSeconds)
{
    model::World world = makeStack(10);
    Simulation simulation(settingsUnderTest());
    for (int i = 0; i < 240 * 10; ++i)
        simulation.step(world);
    for (int i = 0; i < 10; ++i) {
        const model::BodyState& s = world.bodies[static_cast<std::size_t>(i + 1)].state;
        EXPECT_NEAR(s.position.x(), 0.0, 1e-3) << "box " << i;
        EXPECT_NEAR(s.position.y(), 0.5 + i, (i + 1) * constants::kLinearSlop) << "box " << i;
        EXPECT_NEAR(s.angle, 0.0, 1e-3) << "box " << i;
    }
}

// A pyramid of base 20 (210 boxes) stands for 5 s: the top box stays within a centimetre of
// where it started, and every box within a few slops of its resting height.
TEST(Stacking, PyramidOfBase20Stands)
{
    model::World world = model::makePyramid(20);
    const model::World start = world;
    Simulation simulation(settingsUnderTest());
    for (int i = 0; i < 240 * 5; ++i)
        simulation.step(world);
    const Vec2 drift = world.bodies.back().state.position - start.bodies.back().state.position;
    EXPECT_LT(std::abs(drift.x()), 0.01);
    EXPECT_LT(std::abs(drift.y()), 20 * constants::kLinearSlop);
    for (std::size_t i = 1; i < world.bodies.size(); ++i) {
        ASSERT_NEAR(world.bodies[i].state.angle, 0.0, 0.01) << "box " << i;
        ASSERT_LT(world.bodies[i].state.velocity.norm(), 0.01) << "box " << i;
    }
}

// At rest, the ground carries the whole weight: the normal impulses of the ground's contacts over
// one step add up to M·g·h. A pyramid of base 20 (about 600 contacts) runs its velocity passes in
// batches in either build, the ten-box stack one contact at a time in the plain build.
TEST(Stacking, TheGroundCarriesTheWholeWeight)
{
    for (const int base : {1, 20}) {
        model::World world = base == 1 ? makeStack(10) : model::makePyramid(base);
        Simulation simulation(settingsUnderTest());
        for (int i = 0; i < 240 * 2; ++i)
            simulation.step(world);
        Scalar weight = 0;
        for (const model::Body& body : world.bodies)
            weight += body.fixed ? 0 : body.mass * -world.settings.gravity.y();
        Scalar carried = 0;
        for (const model::ContactRecord& record : world.contacts) {
            if (world.body(record.bodyA).fixed || world.body(record.bodyB).fixed)
                carried += record.normalImpulses[0] + record.normalImpulses[1];
        }
        EXPECT_NEAR(carried / world.settings.timeStep, weight, 1e-6 * weight) << "base " << base;
    }
}

// A 1 m box balanced on a fixed pedestal 1 cm wide. The contact's two points are so close that K is
// nearly singular and the points are solved one at a time, not as a 2×2 block: the box must still
// rest at its true height without sinking, as on a wide support.
TEST(Stacking, BoxBalancedOnANarrowPedestalStaysPut)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240.0, Vec2(0, -9.81));
    world.bodies.push_back(withMaterial(makeGround("pedestal", 0.01, 1), 0.0, 0.6));
    world.bodies.push_back(withMaterial(makeBox("box", 1.0, 1.0, 1.0, Vec2(0, 0.5)), 0.0, 0.6));
    Simulation simulation(settingsUnderTest());
    Scalar fastest = 0;
    for (int i = 0; i < 240; ++i) {
        simulation.step(world);
        fastest = std::max(fastest, std::abs(world.bodies[1].state.velocity.y()));
    }
    EXPECT_NEAR(world.bodies[1].state.position.y(), 0.5, constants::kLinearSlop);
    // g·h = 0.04 m/s would mean the contact force is lost every step.
    EXPECT_LT(fastest, 1e-3);
}

// Eighty balls dropped a few millimetres onto a plank (81 contacts at the plank, more than the 64
// colours), every world batched: everything comes to rest at its true height, and the ground
// carries the whole weight.
TEST(Stacking, APlankWithMoreContactsThanColoursComesToRest)
{
    model::World world = testing::makeLoadedPlanks(1, 80);
    SolverSettings settings = settingsUnderTest();
    settings.batchMinConstraints = 0;
    Simulation simulation(settings);
    for (int i = 0; i < 480; ++i)
        simulation.step(world);
    Scalar weight = 0;
    for (std::size_t i = 1; i < world.bodies.size(); ++i) {
        const model::Body& body = world.bodies[i];
        weight += body.mass * -world.settings.gravity.y();
        EXPECT_LT(body.state.velocity.norm(), 1e-6) << body.name;
        EXPECT_NEAR(body.state.position.y(), i == 1 ? 0.1 : 0.3, 2 * constants::kLinearSlop) << body.name;
    }
    Scalar carried = 0;
    for (const model::ContactRecord& record : world.contacts) {
        if (world.body(record.bodyA).fixed || world.body(record.bodyB).fixed)
            carried += record.normalImpulses[0] + record.normalImpulses[1];
    }
    EXPECT_NEAR(carried / world.settings.timeStep, weight, 1e-6 * weight);
}

// Sixteen planks of eighty balls each, every world batched: each plank has 81 contacts, 17 more
// than a body has colours. Those 17 are coloured again with the other planks' (a second round
// of colours), so they fill pairs of batches as the first 64 colours do, where each took a pair
// of batches of its own before (seven lanes of padding to one contact: 1,904 lanes of padding for
// 1,296 contacts). The world is large enough to be solved in two halves of eight planks, whose
// colours then hold eight contacts each, a pair of batches. The planks and balls still come to
// rest at their true heights.
TEST(Stacking, ContactsBeyondTheColoursShareTheirBatches)
{
    constexpr int kPlanks = 16;
    model::World world = testing::makeLoadedPlanks(kPlanks, 80);
    SolverSettings settings = settingsUnderTest();
    settings.batchMinConstraints = 0;
    Simulation simulation(settings);
    int loaded = 0; // steps with every ball on its plank (the balls start a few millimetres up)
    for (int i = 0; i < 240; ++i) {
        simulation.step(world);
        const StepProfile& profile = simulation.profile();
        if (profile.contacts >= kPlanks * 81)
            ++loaded;
        // Padding only where a colour's last pair of batches is not full.
        ASSERT_LE(profile.batchLanes, profile.contacts + profile.contacts / 4) << "step " << i;
    }
    EXPECT_GT(loaded, 200);
    for (const model::Body& body : world.bodies) {
        if (body.fixed)
            continue;
        const bool plank = body.name.starts_with("plank");
        EXPECT_LT(body.state.velocity.norm(), 1e-6) << body.name;
        EXPECT_NEAR(body.state.position.y(), plank ? 0.1 : 0.3, 2 * constants::kLinearSlop) << body.name;
    }
}

// A tonne set down on a 0.3 kg block on the floor, at the default step and at 1/60 s, under
// semi-implicit Euler and RK4: the block holds it at its true height, as a rigid block must. The
// velocity passes alone take about 1/3,300 of the tonne's approach a pass through the block, and
// it sank through the block and the floor (its centre at 0.15 m, on the floor); the block is a
// prop (ContactSolver::findProps).
TEST(Stacking, ATonneRestsOnALightBlockAtEveryStep)
{
    for (const Scalar step : {1.0 / 240.0, 1.0 / 60.0}) {
        for (const IntegratorKind integrator : {IntegratorKind::SemiImplicitEuler, IntegratorKind::Rk4}) {
            model::World world = makeEmptyWorld(integrator, step, Vec2(0, -9.81));
            world.bodies.push_back(withMaterial(makeGround("floor", 20, 2), 0.0, 0.5));
            world.bodies.push_back(withMaterial(makeBox("block", 0.3, 0.4, 0.4, Vec2(0, 0.2)), 0.0, 0.5));
            world.bodies.push_back(withMaterial(makeBox("tonne", 1000.0, 0.3, 0.3, Vec2(0, 0.56)), 0.0, 0.5));
            Simulation simulation(settingsUnderTest());
            Scalar lowest = 1;
            for (int i = 0; i < static_cast<int>(std::lround(2 / step)); ++i) {
                simulation.step(world);
                lowest = std::min(lowest, world.bodies[2].state.position.y());
            }
            const std::string where = "step 1/" + std::to_string(std::lround(1 / step)) + ", integrator " +
                                      std::to_string(static_cast<int>(integrator));
            EXPECT_NEAR(world.bodies[1].state.position.y(), 0.2, constants::kLinearSlop) << where;
            EXPECT_NEAR(world.bodies[2].state.position.y(), 0.55, 2 * constants::kLinearSlop) << where;
            EXPECT_GT(lowest, 0.55 - 2 * constants::kLinearSlop) << where;
            EXPECT_LT(world.bodies[2].state.velocity.norm(), 1e-6) << where;
            // It does not slide off: it stays over the block's centre within the slop.
            EXPECT_NEAR(world.bodies[2].state.position.x(), 0.0, constants::kLinearSlop) << where;
        }
    }
}

// A light block on a frictionless floor, struck from the side by a tonne sliding at 2 m/s (e = 0):
// the floor does not hold it against that push, so it is no prop, and the two go on together at
// the speed momentum gives, 2·1000/1000.3 m/s.
TEST(Stacking, ATonneSlidingIntoALightBlockPushesItAlong)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 60.0, Vec2(0, -9.81));
    world.bodies.push_back(withMaterial(makeGround("floor", 40, 2), 0.0, 0.0));
    world.bodies.push_back(withMaterial(makeBox("block", 0.3, 0.4, 0.4, Vec2(0, 0.2)), 0.0, 0.0));
    model::Body tonne = withMaterial(makeBox("tonne", 1000.0, 0.3, 0.3, Vec2(-1, 0.15)), 0.0, 0.0);
    tonne.state.velocity = Vec2(2, 0);
    world.bodies.push_back(tonne);
    Simulation simulation(settingsUnderTest());
    for (int i = 0; i < 60; ++i)
        simulation.step(world);
    // The floor pushes only upwards: the momentum along it stays 2,000 kg·m/s, and the tonne gives
    // up only the block's share of it (a prop would have stopped it dead).
    const Scalar momentum = 0.3 * world.bodies[1].state.velocity.x() + 1000 * world.bodies[2].state.velocity.x();
    EXPECT_NEAR(momentum, 2000.0, 1e-9 * 2000);
    const Scalar together = 2 * 1000 / 1000.3;
    EXPECT_NEAR(world.bodies[2].state.velocity.x(), together, 1e-6);
    // The block goes on at least as fast as the tonne behind it (the passes leave it a few
    // hundredths of a mm/s ahead).
    EXPECT_GE(world.bodies[1].state.velocity.x(), world.bodies[2].state.velocity.x());
    EXPECT_NEAR(world.bodies[1].state.velocity.x(), together, 1e-4);
    EXPECT_NEAR(world.bodies[1].state.position.y(), 0.2, constants::kLinearSlop);
}

// Box2D's large pyramid (base 100, 5,050 boxes) stands: after 500 steps the top box has moved
// less than 0.1 m sideways (Box2D 2.4 itself: 0.13 m, see docs/benchmarks.md).
TEST(Stacking, LargePyramidStands)
{
    model::World world = model::makePyramid(100);
    const Vec2 start = world.bodies.back().state.position;
    Simulation simulation(settingsUnderTest());
    for (int i = 0; i < 500; ++i)
        simulation.step(world);
    const Vec2 drift = world.bodies.back().state.position - start;
    EXPECT_LT(std::abs(drift.x()), 0.1);
    EXPECT_LT(std::abs(drift.y()), 0.1);
}

} // namespace
} // namespace impetus::controller
