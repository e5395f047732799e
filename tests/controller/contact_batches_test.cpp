// The batch passes give the same bits whether they go through a colour's batches one at a time or
// two side by side (contact_batches.h, BatchOrder).

#include "controller/dynamics/contact_batches.h"
#include "controller/dynamics/small_turn.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <random>
#include <vector>

namespace impetus::controller {
namespace {

constexpr std::size_t kMovable = 40;
constexpr std::size_t kFixed = kMovable; ///< the index of the one fixed body
constexpr std::size_t kScratch = kMovable + 1; ///< where lanes write the fixed body and padding

/// Contacts between random bodies, laid out as ContactSolver lays out one colour: pairs of
/// batches whose eight lanes share no movable body. Some lanes touch the fixed body, some are
/// padding, some have one point.
struct BatchWorld {
    std::vector<BatchBody> bodies;
    std::vector<BatchPose> poses;
    std::vector<ContactBatch> batches;
    std::vector<PositionBatch> positions;
};

BatchWorld makeBatchWorld(unsigned seed, std::size_t pairs)
{
    std::mt19937 random(seed);
    const auto uniform = [&](double low, double high) {
        return low + (high - low) * static_cast<double>(random()) / 4294967296.0;
    };
    BatchWorld world;
    world.bodies.resize(kScratch + 1);
    world.poses.resize(kScratch + 1);
    for (std::size_t i = 0; i < kMovable; ++i) {
        BatchBody& body = world.bodies[i];
        body.velocity = Vec2(uniform(-1, 1), uniform(-1, 1));
        body.angularVelocity = uniform(-2, 2);
        body.invMass = 1 / uniform(0.5, 3);
        body.invInertia = 1 / uniform(0.1, 1);
        const double angle = uniform(-3, 3);
        world.poses[i] = BatchPose{uniform(-5, 5), uniform(-5, 5), angle, std::cos(angle), std::sin(angle)};
    }
    world.bodies[kFixed].velocity = Vec2(0.3, 0); // a fixed body may move (a conveyor)
    world.poses[kFixed] = BatchPose{0, -1, 0, 1, 0};

    std::vector<std::uint32_t> order(kMovable);
    std::iota(order.begin(), order.end(), 0u);
    world.batches.resize(pairs * kBatchPair);
    world.positions.resize(pairs * kBatchPair);
    for (std::size_t p = 0; p < pairs; ++p) {
        std::shuffle(order.begin(), order.end(), random);
        std::size_t next = 0;
        for (std::size_t k = 0; k < kBatchPair; ++k) {
            ContactBatch& batch = world.batches[p * kBatchPair + k];
            PositionBatch& position = world.positions[p * kBatchPair + k];
            for (int lane = 0; lane < kBatchLanes; ++lane) {
                const auto ul = static_cast<std::size_t>(lane);
                const double kind = uniform(0, 1);
                const bool padding = kind < 0.1;
                const bool onFixed = !padding && kind < 0.3;
                const std::uint32_t a = padding ? kScratch : (onFixed ? kFixed : order[next++]);
                const std::uint32_t b = padding ? kScratch : order[next++];
                batch.bodyA[ul] = &world.bodies[a];
                batch.bodyB[ul] = &world.bodies[b];
                batch.writeA[ul] = &world.bodies[a == kFixed ? kScratch : a];
                batch.writeB[ul] = &world.bodies[b];
                position.readA[ul] = a;
                position.readB[ul] = b;
                position.writeA[ul] = a == kFixed ? kScratch : a;
                position.writeB[ul] = b;
                const BatchBody& bodyA = world.bodies[a];
                const BatchBody& bodyB = world.bodies[b];
                position.invMassA[lane] = bodyA.invMass;
                position.invInertiaA[lane] = bodyA.invInertia;
                position.invMassB[lane] = bodyB.invMass;
                position.invInertiaB[lane] = bodyB.invInertia;
                const double normalAngle = uniform(-3, 3);
                batch.normalX[lane] = padding ? 0 : std::cos(normalAngle);
                batch.normalY[lane] = padding ? 0 : std::sin(normalAngle);
                batch.friction[lane] = padding ? 0 : uniform(0, 1);
                const bool two = !padding && uniform(0, 1) < 0.8;
                batch.blockSolve[lane] = two && uniform(0, 1) < 0.7 ? -1 : 0;
                position.secondPoint[lane] = two ? -1 : 0;
                position.localNormalX[lane] = batch.normalX[lane];
                position.localNormalY[lane] = batch.normalY[lane];
                for (std::size_t i = 0; i < 2; ++i) {
                    BatchPoint& point = batch.points[i];
                    const bool real = !padding && (i == 0 || two);
                    const auto arm = [&] { return real ? uniform(-0.7, 0.7) : 0.0; };
                    point.normalArmA[lane] = arm();
                    point.normalArmB[lane] = arm();
                    point.tangentArmA[lane] = arm();
                    point.tangentArmB[lane] = arm();
                    const auto massAlong = [&](double armA, double armB) {
                        const double inverse = bodyA.invMass + bodyB.invMass + bodyA.invInertia * armA * armA +
                                         bodyB.invInertia * armB * armB;
                        return real && inverse > 0 ? 1 / inverse : 0.0;
                    };
                    point.normalMass[lane] = massAlong(point.normalArmA[lane], point.normalArmB[lane]);
                    point.tangentMass[lane] = massAlong(point.tangentArmA[lane], point.tangentArmB[lane]);
                    point.normalImpulse[lane] = real ? uniform(0, 2) : 0;
                    point.tangentImpulse[lane] = real ? uniform(-0.5, 0.5) : 0;
                    point.gapSpeed[lane] = real ? (uniform(0, 1) < 0.5 ? 0.0 : uniform(0, 0.5)) : 1e300;
                    position.anchors[i].ax[lane] = real ? uniform(-0.5, 0.5) : 0;
                    position.anchors[i].ay[lane] = real ? uniform(-0.5, 0.5) : 0;
                    position.anchors[i].bx[lane] = real ? uniform(-0.5, 0.5) : 0;
                    position.anchors[i].by[lane] = real ? uniform(-0.5, 0.5) : 0;
                }
            }
        }
    }
    return world;
}

/// Whether two doubles have the same bits.
bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

TEST(ContactBatches, PairsGiveTheSameBitsAsOneBatchAtATime)
{
    if (fastestBatchOrder() != BatchOrder::InPairs)
        GTEST_SKIP() << "this processor has no AVX-512: the passes go one batch at a time";
    BatchWorld alone = makeBatchWorld(7, 30);
    BatchWorld paired = makeBatchWorld(7, 30);
    const BatchWorld start = makeBatchWorld(7, 30);
    Scalar deepestAlone = 0;
    Scalar deepestPaired = 0;
    for (int pass = 0; pass < 8; ++pass) {
        solveBatches(alone.batches, BatchOrder::OneByOne);
        solveBatches(paired.batches, BatchOrder::InPairs);
        deepestAlone = solvePositionBatches(alone.positions, alone.poses, BatchOrder::OneByOne);
        deepestPaired = solvePositionBatches(paired.positions, paired.poses, BatchOrder::InPairs);
        EXPECT_TRUE(sameBits(deepestAlone, deepestPaired)) << "pass " << pass;
    }
    EXPECT_LT(deepestAlone, 0.0); // the random anchors overlap somewhere

    std::size_t moved = 0;
    for (std::size_t i = 0; i < kMovable; ++i) {
        const BatchBody& a = alone.bodies[i];
        const BatchBody& b = paired.bodies[i];
        EXPECT_TRUE(sameBits(a.velocity.x(), b.velocity.x()) && sameBits(a.velocity.y(), b.velocity.y()) &&
                    sameBits(a.angularVelocity, b.angularVelocity))
            << "body " << i;
        const BatchPose& pa = alone.poses[i];
        const BatchPose& pb = paired.poses[i];
        EXPECT_TRUE(sameBits(pa.x, pb.x) && sameBits(pa.y, pb.y) && sameBits(pa.angle, pb.angle) &&
                    sameBits(pa.cosine, pb.cosine) && sameBits(pa.sine, pb.sine))
            << "pose " << i;
        moved += a.velocity != start.bodies[i].velocity && pa.x != start.poses[i].x ? 1 : 0;
    }
    EXPECT_GT(moved, kMovable / 2); // the passes did something to compare
    for (std::size_t bi = 0; bi < alone.batches.size(); ++bi) {
        for (int lane = 0; lane < kBatchLanes; ++lane) {
            for (std::size_t i = 0; i < 2; ++i) {
                EXPECT_TRUE(sameBits(alone.batches[bi].points[i].normalImpulse[lane],
                                     paired.batches[bi].points[i].normalImpulse[lane]));
                EXPECT_TRUE(sameBits(alone.batches[bi].points[i].tangentImpulse[lane],
                                     paired.batches[bi].points[i].tangentImpulse[lane]));
            }
            EXPECT_EQ(alone.batches[bi].acted[lane], paired.batches[bi].acted[lane]);
        }
    }
}

// The small turns that keep a pose's cosine and sine up to date (small_turn.h): within a few
// units in the last place of std::cos and std::sin of the turned angle, for one number and for
// every lane of a vector, over turns up to the largest they are used for, one after another as
// the substeps of a step and a position pass's looks apply them.
TEST(SmallTurn, MatchesTheCosineAndSineOfTheTurnedAngle)
{
    constexpr double kUlps = 4e-16; // a few units in the last place of a number near 1
    std::mt19937 random(7);
    const auto uniform = [&](double low, double high) {
        return low + (high - low) * static_cast<double>(random()) / 4294967296.0;
    };
    double worst = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        // The angle is summed in long double, so that the reference is the turned angle's and not
        // that of a sum rounded to double (whose rounding near 10 rad alone is 1e-15).
        long double angle = uniform(-10, 10);
        double cosine = std::cos(static_cast<double>(angle));
        double sine = std::sin(static_cast<double>(angle));
        // Four turns in a row, as a body's rotation is carried through the substeps of a step.
        for (int k = 0; k < 4; ++k) {
            const double delta = uniform(-detail::kSmallTurn, detail::kSmallTurn);
            detail::turnSmall(cosine, sine, delta);
            angle += delta;
            worst = std::max({worst, std::abs(cosine - static_cast<double>(std::cos(angle))),
                              std::abs(sine - static_cast<double>(std::sin(angle)))});
        }
    }
    EXPECT_LT(worst, 4 * kUlps); // four turns, each within a few ulps
    EXPECT_GT(worst, 0.0); // rounding does show: the comparison is with another computation

    // Each lane of a vector gets exactly the arithmetic of one number.
    Lanes cosines{};
    Lanes sines{};
    Lanes deltas{};
    for (int lane = 0; lane < kBatchLanes; ++lane) {
        cosines[lane] = std::cos(0.3 * lane);
        sines[lane] = std::sin(0.3 * lane);
        deltas[lane] = detail::kSmallTurn * (lane - 1.5) / 1.5;
    }
    Lanes turnedCosines = cosines;
    Lanes turnedSines = sines;
    detail::turnSmall(turnedCosines, turnedSines, deltas);
    for (int lane = 0; lane < kBatchLanes; ++lane) {
        double cosine = cosines[lane];
        double sine = sines[lane];
        detail::turnSmall(cosine, sine, deltas[lane]);
        EXPECT_TRUE(sameBits(turnedCosines[lane], cosine)) << "lane " << lane;
        EXPECT_TRUE(sameBits(turnedSines[lane], sine)) << "lane " << lane;
        EXPECT_NEAR(cosine, std::cos(0.3 * lane + deltas[lane]), kUlps);
        EXPECT_NEAR(sine, std::sin(0.3 * lane + deltas[lane]), kUlps);
    }
}

} // namespace
} // namespace impetus::controller
