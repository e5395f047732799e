// Polygon validation finds every crossing without trying every pair of edges (issue 17, item 7):
// its answers are checked here against the plain all-pairs definition on random polygons.

#include "model/polygon.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace impetus::model {
namespace {

/// Which side of the line a→b the point c is on (random points are never on it).
int side(const Vec2& a, const Vec2& b, const Vec2& c) { return cross(Vec2(b - a), Vec2(c - a)) > 0 ? 1 : -1; }

/// Non-adjacent edge pairs that cross, tried pair by pair: the definition, for points in general
/// position (no three on a line, no edge touching another without crossing it).
std::set<std::pair<std::size_t, std::size_t>> crossingsByDefinition(const std::vector<Vec2>& p)
{
    std::set<std::pair<std::size_t, std::size_t>> out;
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 2; j < n; ++j) {
            if (i == 0 && j == n - 1)
                continue;
            const Vec2& a = p[i];
            const Vec2& b = p[(i + 1) % n];
            const Vec2& c = p[j];
            const Vec2& d = p[(j + 1) % n];
            if (side(a, b, c) != side(a, b, d) && side(c, d, a) != side(c, d, b))
                out.insert({i, j});
        }
    }
    return out;
}

std::set<std::pair<std::size_t, std::size_t>> reportedCrossings(const std::vector<Vec2>& p)
{
    std::set<std::pair<std::size_t, std::size_t>> out;
    for (const PolygonIssue& issue : validatePolygon(p)) {
        EXPECT_EQ(issue.kind, PolygonIssueKind::SelfIntersection) << issue.message;
        std::size_t i = 0;
        std::size_t j = 0;
        EXPECT_EQ(std::sscanf(issue.message.c_str(), "polygon self-intersects (edges %zu and %zu)", &i, &j), 2)
            << issue.message;
        out.insert({i, j});
    }
    return out;
}

TEST(PolygonCrossings, EveryCrossingOfRandomPolygonsIsFoundOnce)
{
    std::mt19937_64 random(17);
    std::uniform_real_distribution<Scalar> coordinate(-10, 10);
    for (const std::size_t n : {5u, 12u, 40u, 150u}) {
        for (int trial = 0; trial < 20; ++trial) {
            std::vector<Vec2> p;
            for (std::size_t k = 0; k < n; ++k)
                p.emplace_back(coordinate(random), coordinate(random));
            const std::vector<PolygonIssue> issues = validatePolygon(p);
            EXPECT_EQ(reportedCrossings(p), crossingsByDefinition(p)) << "n = " << n << ", trial " << trial;
            // Each pair is reported once.
            EXPECT_EQ(issues.size(), crossingsByDefinition(p).size());
        }
    }
}

// A long thin polygon (a comb of many teeth) puts many edges in few grid rows; it is still valid.
TEST(PolygonCrossings, AFineCombIsSimple)
{
    std::vector<Vec2> comb;
    constexpr int kTeeth = 2000;
    for (int k = 0; k < kTeeth; ++k) {
        comb.emplace_back(k, 0.001);
        comb.emplace_back(k + 0.5, 1.0);
    }
    comb.emplace_back(kTeeth, 0.001);
    comb.emplace_back(kTeeth, -1);
    comb.emplace_back(0, -1);
    EXPECT_TRUE(validatePolygon(comb).empty());
}

} // namespace
} // namespace impetus::model
