// The sort-and-sweep broad phase against a brute-force O(n²) reference, its filtering rules
// (same body, two fixed), its output order, and the edge cases: touching boxes, NaN boxes, empty
// and single inputs. Then its cache of fat boxes: through a long history of small moves, escapes,
// changed bodies and flags, changed counts and NaNs, every call still matches the reference, and
// the calls that may reuse the fat pairs do.

#include "controller/collision/broad_phase.h"
#include "model/constants.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace impetus::controller {
namespace {

/// A uniform number in [0, 1), the same on every standard library (see example_scenes.cpp).
Scalar unit(std::mt19937& random) { return static_cast<Scalar>(random()) / 4294967296.0; }

BroadPhaseProxy proxy(Vec2 lower, Vec2 upper, std::uint32_t body, bool fixed = false)
{
    return BroadPhaseProxy{Aabb{lower, upper}, body, fixed};
}

/// Random boxes in a square of side `extent`: half-sizes 0.1–1 m, about a fifth of them fixed,
/// and every third proxy sharing its body with the previous one (a body of several convex pieces).
/// With `snap`, corners sit on a 0.5 m grid, so that many boxes touch exactly and many share the
/// same lower bound, which exercises the tie-breaking and the `<=` of touching.
std::vector<BroadPhaseProxy> randomProxies(unsigned seed, int count, Scalar extent, bool snap)
{
    std::mt19937 random(seed);
    std::vector<BroadPhaseProxy> proxies;
    std::uint32_t body = 0;
    for (int i = 0; i < count; ++i) {
        Vec2 centre(extent * unit(random), extent * unit(random));
        Vec2 half(0.1 + 0.9 * unit(random), 0.1 + 0.9 * unit(random));
        if (snap) {
            centre = (centre * 2).array().round() / 2;
            half = (half * 2).array().ceil() / 2;
        }
        const bool fixed = unit(random) < 0.2;
        if (i % 3 != 2)
            ++body;
        proxies.push_back(proxy(centre - half, centre + half, body, fixed));
    }
    return proxies;
}

/// The contract, written the slow and obvious way.
std::vector<ProxyPair> bruteForcePairs(const std::vector<BroadPhaseProxy>& proxies)
{
    std::vector<ProxyPair> pairs;
    for (std::uint32_t i = 0; i < proxies.size(); ++i) {
        for (std::uint32_t j = i + 1; j < proxies.size(); ++j) {
            const BroadPhaseProxy& a = proxies[i];
            const BroadPhaseProxy& b = proxies[j];
            if (a.body != b.body && !(a.fixed && b.fixed) && a.box.overlaps(b.box))
                pairs.push_back({i, j});
        }
    }
    return pairs;
}

std::vector<ProxyPair> findPairs(BroadPhase& broadPhase, const std::vector<BroadPhaseProxy>& proxies)
{
    std::vector<ProxyPair> pairs;
    broadPhase.findPairs(proxies, pairs);
    return pairs;
}

struct RandomCase {
    unsigned seed;
    int count;
    Scalar extent;
    bool snap;
};

class BroadPhaseRandom : public ::testing::TestWithParam<RandomCase> {};

TEST_P(BroadPhaseRandom, MatchesBruteForceExactly)
{
    const RandomCase c = GetParam();
    const std::vector<BroadPhaseProxy> proxies = randomProxies(c.seed, c.count, c.extent, c.snap);
    const std::vector<ProxyPair> expected = bruteForcePairs(proxies);
    BroadPhase broadPhase;
    EXPECT_EQ(findPairs(broadPhase, proxies), expected);
    // A case with no pairs would prove nothing about the sweep.
    EXPECT_FALSE(expected.empty());
}

INSTANTIATE_TEST_SUITE_P(Seeded, BroadPhaseRandom,
                         ::testing::Values(RandomCase{1, 200, 20, false}, RandomCase{2, 500, 40, false},
                                           RandomCase{3, 1000, 30, false}, RandomCase{4, 300, 10, true},
                                           RandomCase{5, 800, 25, true}, RandomCase{6, 40, 3, true}),
                         [](const auto& testInfo) {
                             return "seed" + std::to_string(testInfo.param.seed) + "_n" +
                                    std::to_string(testInfo.param.count) + (testInfo.param.snap ? "_snapped" : "");
                         });

TEST(BroadPhase, MatchesBruteForceWhetherTheSpreadIsAlongXOrY)
{
    // A wide strip of boxes and its mirror image in the diagonal, a tall strip: the sweep axis
    // differs, the answer must not.
    std::vector<BroadPhaseProxy> wide = randomProxies(11, 400, 1, false);
    std::vector<BroadPhaseProxy> tall = wide;
    for (std::size_t i = 0; i < wide.size(); ++i) {
        const Vec2 shift(static_cast<Scalar>(i % 100) * 0.7, 0);
        wide[i].box.lower += shift;
        wide[i].box.upper += shift;
        tall[i].box.lower = wide[i].box.lower.reverse();
        tall[i].box.upper = wide[i].box.upper.reverse();
    }
    BroadPhase broadPhase;
    EXPECT_EQ(findPairs(broadPhase, wide), bruteForcePairs(wide));
    EXPECT_EQ(findPairs(broadPhase, tall), bruteForcePairs(tall));
    EXPECT_EQ(findPairs(broadPhase, wide), findPairs(broadPhase, tall));
}

TEST(BroadPhase, LargeBoxesAndPointsAmongSmallBoxesMatchBruteForce)
{
    // Grounds and walls span many strips and overlap hundreds of boxes each (proxy 0 first, so
    // that one `first` collects the most pairs); zero-size boxes sit on strip boundaries.
    std::vector<BroadPhaseProxy> proxies = {proxy(Vec2(-1, -1), Vec2(31, 0.5), 1000, true)};
    for (const BroadPhaseProxy& p : randomProxies(61, 800, 30, true))
        proxies.push_back(p);
    proxies.push_back(proxy(Vec2(-1, 0), Vec2(0.5, 31), 1001, true));
    proxies.push_back(proxy(Vec2(10, 3), Vec2(20, 25), 1002, false));
    for (int i = 0; i < 30; ++i) {
        const Vec2 point(i, 0.5 * i);
        proxies.push_back(proxy(point, point, 2000 + static_cast<std::uint32_t>(i)));
    }
    const std::vector<ProxyPair> expected = bruteForcePairs(proxies);
    BroadPhase broadPhase;
    EXPECT_EQ(findPairs(broadPhase, proxies), expected);
    EXPECT_GT(std::count_if(expected.begin(), expected.end(), [](const ProxyPair& p) { return p.first == 0; }), 32)
        << "the ground should overlap many boxes";
}

TEST(BroadPhase, AnInfiniteBoxOverlapsEveryOtherBody)
{
    std::vector<BroadPhaseProxy> proxies = randomProxies(71, 100, 20, false);
    const Scalar inf = std::numeric_limits<Scalar>::infinity();
    proxies.push_back(proxy(Vec2(-inf, -inf), Vec2(inf, inf), 5000, false));
    BroadPhase broadPhase;
    const std::vector<ProxyPair> pairs = findPairs(broadPhase, proxies);
    EXPECT_EQ(pairs, bruteForcePairs(proxies));
    EXPECT_EQ(std::count_if(pairs.begin(), pairs.end(), [](const ProxyPair& p) { return p.second == 100; }), 100);
}

TEST(BroadPhase, FollowsMovingBoxesFromStepToStep)
{
    // Small moves keep last call's order nearly right (the insertion-sort path); every call must
    // still match the reference.
    std::vector<BroadPhaseProxy> proxies = randomProxies(21, 600, 25, false);
    std::mt19937 random(99);
    BroadPhase broadPhase;
    for (int step = 0; step < 20; ++step) {
        for (BroadPhaseProxy& p : proxies) {
            const Vec2 move(0.2 * (unit(random) - 0.5), 0.2 * (unit(random) - 0.5));
            p.box.lower += move;
            p.box.upper += move;
        }
        ASSERT_EQ(findPairs(broadPhase, proxies), bruteForcePairs(proxies)) << "step " << step;
    }
}

TEST(BroadPhase, OutputDoesNotDependOnTheHistory)
{
    const std::vector<BroadPhaseProxy> proxies = randomProxies(31, 500, 20, true);
    BroadPhase fresh;
    const std::vector<ProxyPair> expected = findPairs(fresh, proxies);

    // A history that leaves the kept order far from right: the proxies in reverse, then shuffled.
    BroadPhase used;
    std::vector<BroadPhaseProxy> reversed(proxies.rbegin(), proxies.rend());
    findPairs(used, reversed);
    std::vector<BroadPhaseProxy> shuffled = proxies;
    std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(5));
    findPairs(used, shuffled);
    EXPECT_EQ(findPairs(used, proxies), expected);

    // And one that leaves it nearly right: the same call twice.
    EXPECT_EQ(findPairs(used, proxies), expected);

    // Fewer proxies, then the full list again (the kept order no longer fits).
    findPairs(used, std::vector<BroadPhaseProxy>(proxies.begin(), proxies.begin() + 100));
    EXPECT_EQ(findPairs(used, proxies), expected);
}

TEST(BroadPhase, OutputIsSortedWithFirstBeforeSecond)
{
    const std::vector<BroadPhaseProxy> proxies = randomProxies(41, 700, 20, false);
    BroadPhase broadPhase;
    const std::vector<ProxyPair> pairs = findPairs(broadPhase, proxies);
    ASSERT_FALSE(pairs.empty());
    for (const ProxyPair& pair : pairs)
        EXPECT_LT(pair.first, pair.second);
    EXPECT_TRUE(std::is_sorted(pairs.begin(), pairs.end()));
    EXPECT_EQ(std::adjacent_find(pairs.begin(), pairs.end()), pairs.end()) << "a pair is reported twice";
}

TEST(BroadPhase, NeverPairsPiecesOfTheSameBody)
{
    // Three overlapping pieces of body 7 and one of body 8 on top of them all.
    const std::vector<BroadPhaseProxy> proxies = {
        proxy(Vec2(0, 0), Vec2(2, 2), 7), proxy(Vec2(1, 1), Vec2(3, 3), 7),
        proxy(Vec2(0.5, 0.5), Vec2(1.5, 1.5), 7), proxy(Vec2(0, 0), Vec2(3, 3), 8)};
    BroadPhase broadPhase;
    const std::vector<ProxyPair> expected = {{0, 3}, {1, 3}, {2, 3}};
    EXPECT_EQ(findPairs(broadPhase, proxies), expected);
}

TEST(BroadPhase, NeverPairsTwoFixedProxies)
{
    // Two overlapping fixed walls and a dynamic box touching both.
    const std::vector<BroadPhaseProxy> proxies = {proxy(Vec2(0, 0), Vec2(10, 1), 0, true),
                                                  proxy(Vec2(0, 0), Vec2(1, 10), 1, true),
                                                  proxy(Vec2(0.5, 0.5), Vec2(2, 2), 2, false)};
    BroadPhase broadPhase;
    const std::vector<ProxyPair> expected = {{0, 2}, {1, 2}};
    EXPECT_EQ(findPairs(broadPhase, proxies), expected);
}

struct TouchCase {
    const char* name;
    Aabb b; // against the unit square [0, 1]²
    bool paired;
};

class BroadPhaseTouching : public ::testing::TestWithParam<TouchCase> {};

TEST_P(BroadPhaseTouching, TouchingCountsAsOverlapping)
{
    const TouchCase c = GetParam();
    const std::vector<BroadPhaseProxy> proxies = {proxy(Vec2(0, 0), Vec2(1, 1), 0), BroadPhaseProxy{c.b, 1, false}};
    BroadPhase broadPhase;
    EXPECT_EQ(findPairs(broadPhase, proxies).size(), c.paired ? 1u : 0u);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BroadPhaseTouching,
    ::testing::Values(TouchCase{"edge-right", {Vec2(1, 0), Vec2(2, 1)}, true},
                      TouchCase{"edge-above", {Vec2(0, 1), Vec2(1, 2)}, true},
                      TouchCase{"edge-left", {Vec2(-1, 0.2), Vec2(0, 0.8)}, true},
                      TouchCase{"corner", {Vec2(1, 1), Vec2(2, 2)}, true},
                      TouchCase{"same-box", {Vec2(0, 0), Vec2(1, 1)}, true},
                      TouchCase{"point-box", {Vec2(0.5, 0.5), Vec2(0.5, 0.5)}, true},
                      TouchCase{"gap-right", {Vec2(1 + 1e-12, 0), Vec2(2, 1)}, false},
                      TouchCase{"gap-above", {Vec2(0, 1 + 1e-12), Vec2(1, 2)}, false},
                      TouchCase{"overlap-x-only", {Vec2(0.5, 2), Vec2(1.5, 3)}, false},
                      TouchCase{"overlap-y-only", {Vec2(2, 0.5), Vec2(3, 1.5)}, false}),
    [](const auto& testInfo) {
        std::string name = testInfo.param.name;
        std::replace(name.begin(), name.end(), '-', '_');
        return name;
    });

TEST(BroadPhase, ARowOfBoxesRestingEdgeToEdgeIsAChainOfPairs)
{
    // Ten 1 m boxes side by side, every lower bound on the sweep axis equal (y) or touching (x):
    // neighbours pair, others do not.
    std::vector<BroadPhaseProxy> proxies;
    for (std::uint32_t i = 0; i < 10; ++i)
        proxies.push_back(proxy(Vec2(static_cast<Scalar>(i), 0), Vec2(static_cast<Scalar>(i + 1), 1), i));
    BroadPhase broadPhase;
    std::vector<ProxyPair> expected;
    for (std::uint32_t i = 0; i + 1 < 10; ++i)
        expected.push_back({i, i + 1});
    EXPECT_EQ(findPairs(broadPhase, proxies), expected);
}

TEST(BroadPhase, EmptyAndSingleInputsGiveNoPairs)
{
    BroadPhase broadPhase;
    std::vector<ProxyPair> pairs = {{0, 1}}; // stale content must be cleared
    broadPhase.findPairs({}, pairs);
    EXPECT_TRUE(pairs.empty());

    pairs = {{0, 1}};
    const std::vector<BroadPhaseProxy> one = {proxy(Vec2(0, 0), Vec2(1, 1), 0)};
    broadPhase.findPairs(one, pairs);
    EXPECT_TRUE(pairs.empty());

    // And back to empty after a non-empty call.
    broadPhase.findPairs({}, pairs);
    EXPECT_TRUE(pairs.empty());
}

TEST(BroadPhase, ANaNBoxPairsWithNothingAndDisturbsNoOther)
{
    // A body whose state became NaN must neither crash the sort nor hide the other pairs.
    std::vector<BroadPhaseProxy> proxies = randomProxies(51, 200, 10, false);
    const Scalar nan = std::numeric_limits<Scalar>::quiet_NaN();
    proxies[17].box = Aabb{Vec2(nan, nan), Vec2(nan, nan)};
    proxies[90].box.lower.x() = nan;
    proxies[150].box.upper.y() = nan;
    BroadPhase broadPhase;
    const std::vector<ProxyPair> pairs = findPairs(broadPhase, proxies);
    EXPECT_EQ(pairs, bruteForcePairs(proxies));
    for (const ProxyPair& pair : pairs) {
        for (const std::uint32_t bad : {17u, 90u, 150u})
            EXPECT_TRUE(pair.first != bad && pair.second != bad);
    }
}

// ---- The cache of fat boxes ---------------------------------------------------------------

/// A random history for one BroadPhase. Boxes are placed on a grid of 1/16 m and move by steps of
/// 1/256 m (every coordinate exact in binary), so that many of them touch exactly, before and
/// after a move, and the `<=` of touching is tested on the reused pairs too. A step is several
/// times smaller than the fat margin of the smallest box (0.25 m × kBroadPhaseFatFraction), so a
/// small move alone keeps a box inside its fat box, and a run of them takes some out.
class CacheHistory {
public:
    explicit CacheHistory(unsigned seed) : m_random(seed)
    {
        for (int i = 0; i < 300; ++i)
            add();
    }

    std::vector<BroadPhaseProxy> proxies;

    /// Every other box, at random, moves by one step along x or y.
    void nudgeAll()
    {
        for (BroadPhaseProxy& p : proxies) {
            const auto roll = m_random() % 8;
            const Scalar step = roll % 2 == 0 ? kStep : -kStep;
            if (roll < 2)
                shift(p, Vec2(step, 0));
            else if (roll < 4)
                shift(p, Vec2(0, step));
        }
    }
    /// A few boxes jump by up to 2 m along one axis: they leave their fat boxes by one side only.
    void jumpSome()
    {
        for (int k = 0; k < 5; ++k) {
            const Scalar distance = steps(512);
            shift(pick(), m_random() % 2 == 0 ? Vec2(distance, 0) : Vec2(0, distance));
        }
    }
    /// One side of one box moves out by up to 1 m.
    void growOne()
    {
        BroadPhaseProxy& p = pick();
        const Scalar distance = kStep * static_cast<Scalar>(m_random() % 257);
        switch (m_random() % 4) {
        case 0: p.box.lower.x() -= distance; break;
        case 1: p.box.lower.y() -= distance; break;
        case 2: p.box.upper.x() += distance; break;
        default: p.box.upper.y() += distance; break;
        }
    }
    void rebodyOne() { pick().body = static_cast<std::uint32_t>(m_random() % 200); }
    void toggleFixedOne()
    {
        BroadPhaseProxy& p = pick();
        p.fixed = !p.fixed;
    }
    void add() { proxies.push_back(randomProxy()); }
    void removeOne()
    {
        if (proxies.size() > 2)
            proxies.erase(proxies.begin() + static_cast<std::ptrdiff_t>(m_random() % proxies.size()));
    }
    /// One coordinate of one box becomes NaN; it stays until the box is replaced.
    void poisonOne()
    {
        BroadPhaseProxy& p = pick();
        Scalar* coordinates[] = {&p.box.lower.x(), &p.box.lower.y(), &p.box.upper.x(), &p.box.upper.y()};
        *coordinates[m_random() % 4] = std::numeric_limits<Scalar>::quiet_NaN();
    }
    void cureAll()
    {
        for (BroadPhaseProxy& p : proxies) {
            if (std::isnan(p.box.lower.sum() + p.box.upper.sum()))
                p = randomProxy();
        }
    }

    std::mt19937& random() { return m_random; }

private:
    static constexpr Scalar kGrid = 1.0 / 16; ///< where boxes are placed, m
    static constexpr Scalar kStep = 1.0 / 256; ///< how they move, m

    /// A whole number of steps in [-limit, limit], in m.
    Scalar steps(int limit)
    {
        return kStep * static_cast<Scalar>(static_cast<int>(m_random() % static_cast<unsigned>(2 * limit + 1)) - limit);
    }
    static void shift(BroadPhaseProxy& p, Vec2 move)
    {
        p.box.lower += move;
        p.box.upper += move;
    }
    BroadPhaseProxy& pick() { return proxies[m_random() % proxies.size()]; }
    /// Sides of 0.25–1 m on the grid, in a 12 m square: a few overlaps per box.
    BroadPhaseProxy randomProxy()
    {
        const Vec2 lower(kGrid * static_cast<Scalar>(m_random() % 192), kGrid * static_cast<Scalar>(m_random() % 192));
        const Vec2 size(kGrid * static_cast<Scalar>(4 + m_random() % 13), kGrid * static_cast<Scalar>(4 + m_random() % 13));
        return proxy(lower, lower + size, static_cast<std::uint32_t>(m_random() % 200), m_random() % 5 == 0);
    }

    std::mt19937 m_random;
};

TEST(BroadPhaseCache, MatchesBruteForceThroughALongRandomHistory)
{
    for (const unsigned seed : {1u, 2u, 3u}) {
        CacheHistory history(seed);
        BroadPhase broadPhase;
        int reused = 0;
        int swept = 0;
        std::size_t pairsSeen = 0;
        std::size_t touchingSeen = 0;
        for (int call = 0; call < 400; ++call) {
            // Mostly small moves, as in a settling pile, with every other kind of change mixed in.
            // 0–13 small moves, 14 jumps, 15–16 growth, 17 a new body, 18 fixed or freed, 19 one
            // proxy more, 20 one fewer, 21 a NaN, 22–23 the NaNs gone, 24 the same input again.
            const auto event = history.random()() % 25;
            if (event < 14)
                history.nudgeAll();
            else if (event == 14)
                history.jumpSome();
            else if (event < 17)
                history.growOne();
            else if (event == 17)
                history.rebodyOne();
            else if (event == 18)
                history.toggleFixedOne();
            else if (event == 19)
                history.add();
            else if (event == 20)
                history.removeOne();
            else if (event == 21)
                history.poisonOne();
            else if (event < 24)
                history.cureAll();

            const std::vector<ProxyPair> expected = bruteForcePairs(history.proxies);
            const std::vector<ProxyPair> pairs = findPairs(broadPhase, history.proxies);
            ASSERT_EQ(pairs.size(), expected.size()) << "seed " << seed << ", call " << call;
            for (std::size_t k = 0; k < pairs.size(); ++k) {
                ASSERT_EQ(pairs[k].first, expected[k].first) << "seed " << seed << ", call " << call << ", pair " << k;
                ASSERT_EQ(pairs[k].second, expected[k].second) << "seed " << seed << ", call " << call << ", pair " << k;
            }
            (broadPhase.reusedLastCall() ? reused : swept) += 1;
            pairsSeen += pairs.size();
            touchingSeen += static_cast<std::size_t>(std::count_if(pairs.begin(), pairs.end(), [&](const ProxyPair& p) {
                const Aabb& a = history.proxies[p.first].box;
                const Aabb& b = history.proxies[p.second].box;
                return a.lower.x() == b.upper.x() || b.lower.x() == a.upper.x() || a.lower.y() == b.upper.y() ||
                       b.lower.y() == a.upper.y();
            }));
        }
        // The history must have taken both paths many times, and found pairs, touching ones among
        // them, to prove anything.
        EXPECT_GT(reused, 100) << "seed " << seed;
        EXPECT_GT(swept, 100) << "seed " << seed;
        EXPECT_GT(pairsSeen, 400u * 200u) << "seed " << seed;
        EXPECT_GT(touchingSeen, 400u * 2u) << "seed " << seed;
    }
}

TEST(BroadPhaseCache, ARestingOrJitteringSceneReusesItsPairs)
{
    std::vector<BroadPhaseProxy> proxies = randomProxies(81, 500, 20, true);
    const std::vector<ProxyPair> expected = bruteForcePairs(proxies);
    BroadPhase broadPhase;
    EXPECT_EQ(findPairs(broadPhase, proxies), expected);
    EXPECT_FALSE(broadPhase.reusedLastCall()) << "the first call has nothing to reuse";

    // The same boxes again.
    EXPECT_EQ(findPairs(broadPhase, proxies), expected);
    EXPECT_TRUE(broadPhase.reusedLastCall());

    // Every box moved by 1 µm, a different way each time: the pairs are found by the exact test,
    // so boxes that touched and now stand 1 µm apart drop out, and come back when they touch again.
    std::mt19937 random(3);
    for (int step = 0; step < 10; ++step) {
        std::vector<BroadPhaseProxy> moved = proxies;
        for (BroadPhaseProxy& p : moved) {
            const Vec2 move(1e-6 * (unit(random) - 0.5), 1e-6 * (unit(random) - 0.5));
            p.box.lower += move;
            p.box.upper += move;
        }
        EXPECT_EQ(findPairs(broadPhase, moved), bruteForcePairs(moved)) << "step " << step;
        EXPECT_TRUE(broadPhase.reusedLastCall()) << "step " << step;
    }
    EXPECT_EQ(findPairs(broadPhase, proxies), expected);
    EXPECT_TRUE(broadPhase.reusedLastCall());
}

TEST(BroadPhaseCache, AnyChangeBeyondTheFatBoxesSweepsAfresh)
{
    const std::vector<BroadPhaseProxy> proxies = randomProxies(91, 300, 15, false);
    BroadPhase broadPhase;
    findPairs(broadPhase, proxies);

    // Each change comes after a call that reused, and is undone by the next call.
    const auto sweepsAfresh = [&](const std::vector<BroadPhaseProxy>& changed, const char* what) {
        findPairs(broadPhase, proxies);
        findPairs(broadPhase, proxies);
        EXPECT_TRUE(broadPhase.reusedLastCall()) << what;
        const std::vector<ProxyPair> pairs = findPairs(broadPhase, changed);
        EXPECT_EQ(pairs, bruteForcePairs(changed)) << what;
        EXPECT_FALSE(broadPhase.reusedLastCall()) << what;
        EXPECT_EQ(findPairs(broadPhase, proxies), bruteForcePairs(proxies)) << what << ", then back";
        return pairs;
    };
    std::vector<BroadPhaseProxy> changed = proxies;
    changed[40].box.lower.x() -= 1;
    sweepsAfresh(changed, "a box that grew out of its fat box");
    changed = proxies;
    changed[41].body = 100000;
    sweepsAfresh(changed, "a proxy given to another body");
    changed = proxies;
    changed[42].fixed = !changed[42].fixed;
    sweepsAfresh(changed, "a proxy fixed or freed");
    changed = proxies;
    changed.pop_back();
    sweepsAfresh(changed, "one proxy fewer");
    changed = proxies;
    changed.push_back(proxies[7]);
    changed.back().body = 100001;
    sweepsAfresh(changed, "one proxy more");
    for (int corner = 0; corner < 4; ++corner) {
        changed = proxies;
        Scalar* coordinates[] = {&changed[43].box.lower.x(), &changed[43].box.lower.y(), &changed[43].box.upper.x(),
                                 &changed[43].box.upper.y()};
        *coordinates[corner] = std::numeric_limits<Scalar>::quiet_NaN();
        const std::vector<ProxyPair> pairs = sweepsAfresh(changed, "a NaN");
        EXPECT_TRUE(std::none_of(pairs.begin(), pairs.end(),
                                 [](const ProxyPair& p) { return p.first == 43 || p.second == 43; }))
            << "a box with a NaN overlaps nothing";
        // The same NaN twice: a NaN box is never inside its fat box, so this sweeps again.
        EXPECT_EQ(findPairs(broadPhase, changed), pairs);
        EXPECT_FALSE(broadPhase.reusedLastCall());
    }
}

TEST(BroadPhaseCache, TheFatMarginFollowsTheSmallerSideOfEachBox)
{
    // A 200 m × 1 m ground, fixed, under a row of 1 m boxes resting on it. Its margin is a
    // fraction of 1 m, not of 200 m: a move of half that margin keeps the pairs, one of twice
    // that margin does not.
    std::vector<BroadPhaseProxy> proxies = {proxy(Vec2(-100, -1), Vec2(100, 0), 0, true)};
    for (std::uint32_t i = 0; i < 50; ++i)
        proxies.push_back(proxy(Vec2(2 * i, 0), Vec2(2 * i + 1, 1), 1 + i));
    BroadPhase broadPhase;
    EXPECT_EQ(findPairs(broadPhase, proxies).size(), 50u);
    const Scalar margin = constants::kBroadPhaseFatFraction * 1.0;

    std::vector<BroadPhaseProxy> moved = proxies;
    moved[0].box.lower.y() -= margin / 2;
    moved[0].box.upper.y() -= margin / 2;
    EXPECT_TRUE(findPairs(broadPhase, moved).empty()) << "the ground moved away from every box";
    EXPECT_TRUE(broadPhase.reusedLastCall());

    moved[0].box.lower.x() -= 2 * margin;
    EXPECT_TRUE(findPairs(broadPhase, moved).empty());
    EXPECT_FALSE(broadPhase.reusedLastCall());
}

} // namespace
} // namespace impetus::controller
