// Determinism: the same scene gives the same bits on every run, and a golden hash of a pyramid's
// final poses catches any unintended change to the physics.

#include "controller/energy_ledger.h"
#include "controller/simulation.h"
#include "controller/solver_under_test.h"
#include "model/example_scenes.h"
#include "support/world_builders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

/// Runs a copy of `start` for `steps` steps with the second thread and another without it, expects
/// a world large enough to be split and the same bits either way, and returns the first.
model::World runOnOneThreadAndTwo(const model::World& start, const SolverSettings& settings, int steps)
{
    model::World twoThreads = start;
    model::World oneThread = start;
    SolverSettings single = settings;
    single.secondThread = false;
    Simulation withThread(settings);
    Simulation withoutThread(single);
    for (int i = 0; i < steps; ++i) {
        withThread.step(twoThreads);
        withoutThread.step(oneThread);
    }
    EXPECT_GE(static_cast<std::size_t>(withThread.profile().contacts), constants::kParallelMinConstraints);
    EXPECT_EQ(twoThreads, oneThread);
    return twoThreads;
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
    const std::uint64_t golden = kEveryWorldBatched ? 0x0dddd0cc2b1a83aeull : 0x365a91d698390bedull;
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

// A large world whose bodies move fast takes its strike shares from a broad phase of its own
// (Simulation::addStrikeShares), after the two threads have placed each half of its colliders:
// 2000 circles falling in the (still) box, through their landing, give the same bits on one
// thread or two.
TEST(Determinism, LocalStrikeSharesGiveTheSameBitsOnOneThreadOrTwo)
{
    model::World start = model::makeRotatingBoxWithCircles(2000);
    // Falling at 3 m/s or more, the circles' strike shares pass the constant margin.
    for (model::Body& body : start.bodies) {
        if (!body.fixed)
            body.state.velocity = Vec2(0, -3);
    }
    ASSERT_GE(start.bodies.size(), constants::kParallelMinBodies);
    runOnOneThreadAndTwo(start, settingsUnderTest(), 400);
}

// A split world with joints: the joints change the bodies' velocities between the contacts'
// passes, which then start from the bodies and hand their result back every pass. Rods tie each
// box of the pyramid's fifth row to its right-hand neighbour, a pin holds the top box to the world
// where it stands, and off to the side a bob on a rod leans on a frictionless block (as in
// Pendulum.BobLeaningOnAWallFeelsMgTanTheta). One thread and two give the same bits, the rods
// keep their length, and the block pushes the bob with m·g·tan θ.
TEST(Determinism, ASplitWorldWithJointsGivesTheSameBitsOnOneThreadOrTwo)
{
    const int base = 40;
    model::World world = model::makePyramid(base);
    // makePyramid adds the ground, then the rows from the bottom up, each from left to right.
    const std::size_t rowStart = 1 + static_cast<std::size_t>(base + (base - 1) + (base - 2) + (base - 3));
    const std::size_t rowCount = static_cast<std::size_t>(base - 4);
    for (std::size_t k = rowStart; k + 1 < rowStart + rowCount; ++k) {
        model::Joint rod;
        rod.type = model::JointType::Rod;
        rod.bodyA = model::BodyId{static_cast<std::uint32_t>(k)};
        rod.bodyB = model::BodyId{static_cast<std::uint32_t>(k + 1)};
        rod.length = (world.bodies[k + 1].state.position - world.bodies[k].state.position).norm();
        world.joints.push_back(rod);
    }
    const auto topId = model::BodyId{static_cast<std::uint32_t>(world.bodies.size() - 1)};
    model::Joint pin;
    pin.type = model::JointType::Pin;
    pin.bodyA = topId;
    pin.worldAnchor = world.body(topId).state.position;
    pin.anchorA = Vec2::Zero();
    pin.anchorB = pin.worldAnchor;
    world.joints.push_back(pin);
    // The block's right face is at x = 0.5 from the pivot, the bob's left face rests on it.
    const Vec2 pivot(2.0 * base, 20);
    const Scalar length = 1.5;
    const Scalar x = 0.6;
    const Scalar y = -std::sqrt(length * length - x * x);
    world.bodies.push_back(
        testing::withMaterial(testing::makeGround("block", 1.0, 2.0, pivot + Vec2(0.0, -0.5)), 0.0, 0.0));
    world.bodies.push_back(
        testing::withMaterial(testing::makeBox("bob", 1.0, 0.2, 0.2, pivot + Vec2(x, y)), 0.0, 0.0));
    const auto bobId = model::BodyId{static_cast<std::uint32_t>(world.bodies.size() - 1)};
    model::Joint hang;
    hang.type = model::JointType::Rod;
    hang.bodyA = bobId;
    hang.bodyB = std::nullopt;
    hang.anchorB = pivot;
    hang.length = length;
    world.joints.push_back(hang);

    world = runOnOneThreadAndTwo(world, settingsUnderTest(), 120);
    Scalar push = 0;
    for (const model::ContactRecord& r : world.contacts) {
        if (r.bodyB == bobId || r.bodyA == bobId)
            push += (r.normalImpulses[0] + r.normalImpulses[1]) / world.settings.timeStep;
    }
    const Scalar weight = world.body(bobId).mass * -world.settings.gravity.y();
    EXPECT_NEAR(push, weight * (x / -y), 1e-6 * weight);
    for (const model::Joint& joint : world.joints) {
        const Vec2 end = joint.bodyB ? world.body(*joint.bodyB).state.position : joint.anchorB;
        if (joint.type == model::JointType::Rod) {
            EXPECT_NEAR((end - world.body(joint.bodyA).state.position).norm(), joint.length, 1e-3);
        }
    }
    EXPECT_NEAR((world.body(topId).state.position - pin.worldAnchor).norm(), 0.0, 1e-3);
}

// The same without batches: a split world's constraints are built by group, one contact at a time.
TEST(Determinism, ASplitWorldWithoutBatchesGivesTheSameBitsOnOneThreadOrTwo)
{
    const model::World start = model::makePyramid(40);
    SolverSettings unbatched = settingsUnderTest();
    unbatched.batchMinConstraints = std::numeric_limits<std::size_t>::max();
    const model::World twoThreads = runOnOneThreadAndTwo(start, unbatched, 120);
    const Vec2 topStart = start.bodies.back().state.position;
    // And the pyramid stands: its top box has not moved by more than the settling of its rows.
    EXPECT_LT((twoThreads.bodies.back().state.position - topStart).norm(), 0.05);
}

// Batches of their own for contacts that find every colour taken, in a world split over two
// threads: 8 planks carrying 70 balls each (over 512 contacts) give the same bits either way.
TEST(Determinism, OverflowingColoursGiveTheSameBitsOnOneThreadOrTwo)
{
    SolverSettings batched = settingsUnderTest();
    batched.batchMinConstraints = 0;
    runOnOneThreadAndTwo(testing::makeLoadedPlanks(8, 70), batched, 120);
}

// A split step that finds its contacts once keeps its later substeps' impulses in the batch lanes
// and writes the contact records only as it hands them on; a ledger, which reads the records
// every substep, has them written every substep. Either way the same bits: the poses, and the
// records (impulses and which contacts touch) that the next step warm-starts from and the events
// read. A base-12 pyramid at 1/60 s (four substeps, its contacts found once a step once it rests).
TEST(Determinism, RecordsWrittenEverySubstepOrOnlyAtTheStepsEndGiveTheSameBits)
{
    model::World plain = model::makePyramid(12);
    plain.settings.timeStep = 1.0 / 60.0;
    model::World ledgered = plain;
    Simulation quiet(settingsUnderTest());
    Simulation watched(settingsUnderTest());
    EnergyLedger ledger;
    watched.setLedger(&ledger);
    for (int step = 0; step < 120; ++step) {
        quiet.step(plain);
        watched.step(ledgered);
    }
    EXPECT_EQ(quiet.profile().substeps, 4);
    EXPECT_EQ(quiet.profile().collisionPasses, 1); // the contacts were found once for the step
    EXPECT_EQ(hashPoses(plain), hashPoses(ledgered));
    ASSERT_FALSE(plain.contacts.empty());
    EXPECT_TRUE(plain.contacts == ledgered.contacts);
    EXPECT_TRUE(std::all_of(plain.contacts.begin(), plain.contacts.end(),
                            [](const model::ContactRecord& r) { return r.touching; }));
}

// The impact pass rules out from bounds the contacts of a struck body that cannot meet within the
// step before looking at them in full. The bounds only skip work: the same impacts in the same
// order, so the same bits, with them or without. Box2D v3's spinner at its debug size (499 bodies
// stirred by an arm whose tip goes at 200 m/s) at 1/60 s: thousands of impacts a step, each
// looking again at dozens of speculative contacts of the body it struck, most of them centimetres
// from meeting.
TEST(Determinism, ImpactReachBoundsSkipWorkButChangeNoBit)
{
    model::World bounded = model::makeSpinner(499);
    bounded.settings.timeStep = 1.0 / 60.0;
    model::World exhaustive = bounded;
    SolverSettings withBounds = settingsUnderTest();
    SolverSettings withoutBounds = withBounds;
    withoutBounds.impactReachBounds = false;
    Simulation fast(withBounds);
    Simulation full(withoutBounds);
    std::size_t impacts = 0;
    std::size_t visits = 0;
    std::size_t looks = 0;
    for (int step = 0; step < 20; ++step) {
        fast.step(bounded);
        full.step(exhaustive);
        ASSERT_EQ(hashPoses(bounded), hashPoses(exhaustive)) << "step " << step;
        EXPECT_EQ(fast.profile().impacts, full.profile().impacts);
        EXPECT_EQ(fast.profile().impactVisits, full.profile().impactVisits);
        EXPECT_EQ(full.profile().impactLooks, full.profile().impactVisits);
        impacts += static_cast<std::size_t>(fast.profile().impacts);
        visits += fast.profile().impactVisits;
        looks += fast.profile().impactLooks;
    }
    EXPECT_TRUE(bounded.contacts == exhaustive.contacts);
    EXPECT_GT(impacts, 10'000u);
    // Most of what the impacts look at again cannot meet: the bounds leave under a third to look at.
    EXPECT_LT(3 * looks, visits);
}

} // namespace
} // namespace impetus::controller
