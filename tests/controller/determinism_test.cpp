// Determinism: the same scene gives the same bits on every run, and a golden hash of a pyramid's
// final poses catches any unintended change to the physics.

#include "controller/simulation.h"
#include "controller/solver_under_test.h"
#include "model/example_scenes.h"
#include "support/world_builders.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <limits>

namespace impetus::controller {
namespace {

/// FNV-1a over the bytes of every body's position, angle and velocity.
std::uint64_t hashPoses(const model::World& world)
{
    std::uint64_t hash = 14695981039346656037ull;
    auto mix = [&](double value) {
        unsigned char bytes[sizeof(double)];
        std::memcpy(bytes, &value, sizeof(double));
        for (const unsigned char byte : bytes) {
            hash ^= byte;
            hash *= 1099511628211ull;
        }
    };
    for (const model::Body& body : world.bodies) {
        mix(body.state.position.x());
        mix(body.state.position.y());
        mix(body.state.angle);
        mix(body.state.velocity.x());
        mix(body.state.velocity.y());
        mix(body.state.angularVelocity);
    }
    return hash;
}

model::World runPyramid(int steps)
{
    model::World world = model::makePyramid(10);
    Simulation simulation(settingsUnderTest());
    for (int i = 0; i < steps; ++i)
        simulation.step(world);
    return world;
}

TEST(Determinism, TwoRunsOfAPyramidAreBitIdentical)
{
    const model::World first = runPyramid(300);
    const model::World second = runPyramid(300);
    EXPECT_EQ(first, second);
    EXPECT_EQ(hashPoses(first), hashPoses(second));
}

// A World copied mid-run and stepped on gives the same bits as the original run: everything the
// physics depends on (warm-start impulses included) lives in the World, none in the Simulation.
TEST(Determinism, ACopiedWorldContinuesIdentically)
{
    model::World world = model::makePyramid(10);
    Simulation simulation(settingsUnderTest());
    for (int i = 0; i < 150; ++i)
        simulation.step(world);
    model::World copy = world;
    Simulation fresh(settingsUnderTest());
    for (int i = 0; i < 150; ++i) {
        simulation.step(world);
        fresh.step(copy);
    }
    EXPECT_EQ(world, copy);
}

// The golden hash of a base-10 pyramid after 300 steps (1.25 s). It changes whenever the physics
// changes; when a change is intended, check the physics tests and update the value here.
TEST(Determinism, GoldenHashOfAPyramid)
{
    const model::World world = runPyramid(300);
    // The batched velocity passes solve colour by colour, a different order: another golden value.
    const std::uint64_t golden = kEveryWorldBatched ? 0x0dddd0cc2b1a83aeull : 0x0c694ae922c3aafbull;
    EXPECT_EQ(hashPoses(world), golden) << std::hex << "hash is 0x" << hashPoses(world);
}

// A world large enough to be solved in two halves (base 40: 820 boxes, about 2400 contacts, over
// constants::kParallelMinConstraints and kParallelMinPairs) gives the same bits with the second
// thread as without it: the halves share no movable body, and the order is the world's, not the
// machine's.
TEST(Determinism, ASplitWorldGivesTheSameBitsOnOneThreadOrTwo)
{
    model::World twoThreads = model::makePyramid(40);
    model::World oneThread = twoThreads;
    Simulation withThread(settingsUnderTest());
    SolverSettings single = settingsUnderTest();
    single.secondThread = false;
    Simulation withoutThread(single);
    std::size_t events = 0;
    for (int i = 0; i < 120; ++i) {
        withThread.step(twoThreads);
        withoutThread.step(oneThread);
        // The collision log too: each half of the records finds its own events, and together they
        // must be the one-thread list, in the same order.
        ASSERT_EQ(withThread.events().size(), withoutThread.events().size()) << "step " << i;
        for (std::size_t k = 0; k < withThread.events().size(); ++k) {
            const CollisionEvent& two = withThread.events()[k];
            const CollisionEvent& one = withoutThread.events()[k];
            EXPECT_EQ(two.bodyA, one.bodyA);
            EXPECT_EQ(two.bodyB, one.bodyB);
            EXPECT_EQ(two.point, one.point);
            EXPECT_EQ(two.normal, one.normal);
            EXPECT_EQ(two.normalImpulse, one.normalImpulse);
            EXPECT_EQ(two.normalSpeedBefore, one.normalSpeedBefore);
            EXPECT_EQ(two.normalSpeedAfter, one.normalSpeedAfter);
        }
        events += withThread.events().size();
    }
    ASSERT_GE(static_cast<std::size_t>(withThread.profile().contacts), constants::kParallelMinConstraints);
    // The pyramid is built touching, so every touching pair begins in the first step.
    EXPECT_GE(events, static_cast<std::size_t>(withThread.profile().contacts));
    EXPECT_EQ(twoThreads.collisionCount, static_cast<std::int64_t>(events));
    EXPECT_EQ(twoThreads, oneThread);
}

// The same without batches: a split world's constraints are built by group, one contact at a time.
TEST(Determinism, ASplitWorldWithoutBatchesGivesTheSameBitsOnOneThreadOrTwo)
{
    model::World twoThreads = model::makePyramid(40);
    model::World oneThread = twoThreads;
    SolverSettings unbatched = settingsUnderTest();
    unbatched.batchMinConstraints = std::numeric_limits<std::size_t>::max();
    SolverSettings single = unbatched;
    single.secondThread = false;
    Simulation withThread(unbatched);
    Simulation withoutThread(single);
    const Vec2 topStart = twoThreads.bodies.back().state.position;
    for (int i = 0; i < 120; ++i) {
        withThread.step(twoThreads);
        withoutThread.step(oneThread);
    }
    ASSERT_GE(static_cast<std::size_t>(withThread.profile().contacts), constants::kParallelMinConstraints);
    EXPECT_EQ(twoThreads, oneThread);
    // And the pyramid stands: its top box has not moved by more than the settling of its rows.
    EXPECT_LT((twoThreads.bodies.back().state.position - topStart).norm(), 0.05);
}

// Batches of their own for contacts that find every colour taken, in a world split over two
// threads: 8 planks carrying 70 balls each (over 512 contacts) give the same bits either way.
TEST(Determinism, OverflowingColoursGiveTheSameBitsOnOneThreadOrTwo)
{
    model::World twoThreads = testing::makeLoadedPlanks(8, 70);
    model::World oneThread = twoThreads;
    SolverSettings batched = settingsUnderTest();
    batched.batchMinConstraints = 0;
    SolverSettings single = batched;
    single.secondThread = false;
    Simulation withThread(batched);
    Simulation withoutThread(single);
    for (int i = 0; i < 120; ++i) {
        withThread.step(twoThreads);
        withoutThread.step(oneThread);
    }
    ASSERT_GE(static_cast<std::size_t>(withThread.profile().contacts), constants::kParallelMinConstraints);
    EXPECT_EQ(twoThreads, oneThread);
}

} // namespace
} // namespace impetus::controller
