// Polygon validation, orientation, convexity, triangulation and convex decomposition.

#include "model/polygon.h"

#include "model/mass_properties.h"
#include "shape_fixtures.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <ostream>
#include <string>
#include <vector>

namespace impetus::model {
namespace {

using fixtures::reversed;
using fixtures::translated;

constexpr Scalar kTolerance = 1e-12;
constexpr Scalar kNaN = std::numeric_limits<Scalar>::quiet_NaN();
constexpr Scalar kInfinity = std::numeric_limits<Scalar>::infinity();

/// 1e-12, relative once the expected value is larger than 1.
Scalar tolerance(Scalar expected) { return kTolerance * std::max(1.0, std::abs(expected)); }

/// Names each TEST_P instance after its table row (`name` field).
struct CaseName {
    template <class Case>
    std::string operator()(const ::testing::TestParamInfo<Case>& row) const
    {
        return row.param.name;
    }
};

/// Size of the polygon (largest vertex distance from the origin), for tolerances on positions.
Scalar extent(const std::vector<Vec2>& vertices)
{
    Scalar r = 1;
    for (const Vec2& v : vertices)
        r = std::max(r, v.norm());
    return r;
}

// ---------------------------------------------------------------------------------------------
// validatePolygon

/// A PolygonIssue that compares and prints, so a whole issue list is checked in one expectation.
struct Issue {
    PolygonIssueKind kind;
    std::string message;
    bool operator==(const Issue&) const = default;
};

void PrintTo(const Issue& issue, std::ostream* os)
{
    *os << "{kind " << static_cast<int>(issue.kind) << ", \"" << issue.message << "\"}";
}

std::vector<Issue> issuesOf(const std::vector<Vec2>& vertices)
{
    std::vector<Issue> out;
    for (const PolygonIssue& issue : validatePolygon(vertices))
        out.push_back({issue.kind, issue.message});
    return out;
}

struct ValidationCase {
    std::string name;
    std::vector<Vec2> vertices;
    std::vector<Issue> expected;
};

void PrintTo(const ValidationCase& c, std::ostream* os) { *os << c.name; }

class PolygonValidation : public ::testing::TestWithParam<ValidationCase> {};

TEST_P(PolygonValidation, ReportsEveryProblemWithItsKindAndMessage)
{
    const ValidationCase& c = GetParam();
    EXPECT_EQ(issuesOf(c.vertices), c.expected);
}

/// The five vertices of a regular pentagon taken every other one: a pentagram, where every pair of
/// non-adjacent edges crosses.
std::vector<Vec2> pentagram()
{
    const std::vector<Vec2> pentagon = fixtures::regularPolygon(5, 1);
    return {pentagon[0], pentagon[2], pentagon[4], pentagon[1], pentagon[3]};
}

/// The vertices rotated by `angle` (rad) about the origin, then scaled by `scale`.
std::vector<Vec2> rotatedAndScaled(std::vector<Vec2> vertices, Scalar angle, Scalar scale)
{
    for (Vec2& v : vertices)
        v = scale * rotate(v, angle);
    return vertices;
}

Issue selfIntersection(int i, int j)
{
    return {PolygonIssueKind::SelfIntersection,
        "polygon self-intersects (edges " + std::to_string(i) + " and " + std::to_string(j) + ")"};
}

Issue duplicate(int i, int j)
{
    return {PolygonIssueKind::DuplicateVertex,
        "vertices " + std::to_string(i) + " and " + std::to_string(j) + " are the same point"};
}

const Issue kZeroArea{PolygonIssueKind::ZeroArea, "polygon has zero area (its vertices are collinear)"};

INSTANTIATE_TEST_SUITE_P(Refused, PolygonValidation,
    ::testing::Values(
        ValidationCase{"bowtie", {Vec2(0, 0), Vec2(1, 1), Vec2(1, 0), Vec2(0, 1)}, {selfIntersection(0, 2)}},
        ValidationCase{"pentagram", pentagram(),
            {selfIntersection(0, 2), selfIntersection(0, 3), selfIntersection(1, 3), selfIntersection(1, 4),
                selfIntersection(2, 4)}},
        // Vertex 3 lies on edge 0, so edges 2 and 3, which meet there, both touch edge 0.
        ValidationCase{"vertex_on_edge", {Vec2(0, 0), Vec2(4, 0), Vec2(4, 4), Vec2(2, 0), Vec2(0, 4)},
            {selfIntersection(0, 2), selfIntersection(0, 3)}},
        // Edge 1 runs back along edge 0 (adjacent edges folding over each other), and edge 2 starts
        // on edge 0.
        ValidationCase{"edge_folds_back", {Vec2(0, 0), Vec2(2, 0), Vec2(1, 0), Vec2(1, 1)},
            {selfIntersection(0, 1), selfIntersection(0, 2)}},
        // The same fold across the wrap-around: edge 3 (vertex 3 → 0) and edge 0.
        ValidationCase{"edge_folds_back_at_vertex_0", {Vec2(1, 0), Vec2(2, 0), Vec2(1, 1), Vec2(3, 0)},
            {selfIntersection(0, 3), selfIntersection(1, 3)}},
        ValidationCase{"collinear", {Vec2(0, 0), Vec2(1, 0), Vec2(2, 0)}, {kZeroArea}},
        // Not exactly collinear, but flat far below kRelativeAreaTolerance.
        ValidationCase{"nearly_collinear", {Vec2(0, 0), Vec2(1, 1e-14), Vec2(2, 0)}, {kZeroArea}},
        ValidationCase{"duplicate", {Vec2(0, 0), Vec2(1, 0), Vec2(1, 0), Vec2(0, 1)}, {duplicate(1, 2)}},
        // 1e-12 apart on a shape of size ~1.4: within kRelativePointTolerance.
        ValidationCase{"duplicate_within_tolerance", {Vec2(0, 0), Vec2(1, 0), Vec2(1 + 1e-12, 1e-12), Vec2(0, 1)},
            {duplicate(1, 2)}},
        ValidationCase{"duplicate_not_adjacent", {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 0), Vec2(-1, 1)},
            {duplicate(0, 3)}},
        ValidationCase{"duplicate_and_flat", {Vec2(0, 0), Vec2(1, 0), Vec2(1, 0), Vec2(2, 0)},
            {duplicate(1, 2), kZeroArea}},
        ValidationCase{"two_distinct", {Vec2(0, 0), Vec2(1, 0), Vec2(0, 0)},
            {duplicate(0, 2),
                {PolygonIssueKind::TooFewVertices, "polygon needs at least 3 distinct vertices (got 2)"}}},
        ValidationCase{"all_the_same", {Vec2(1, 1), Vec2(1, 1), Vec2(1, 1)},
            {duplicate(0, 1), duplicate(0, 2), duplicate(1, 2),
                {PolygonIssueKind::TooFewVertices, "polygon needs at least 3 distinct vertices (got 1)"}}},
        ValidationCase{"two_vertices", {Vec2(0, 0), Vec2(1, 0)},
            {{PolygonIssueKind::TooFewVertices, "polygon needs at least 3 vertices (got 2)"}}},
        ValidationCase{"empty", {}, {{PolygonIssueKind::TooFewVertices, "polygon needs at least 3 vertices (got 0)"}}},
        ValidationCase{"non_finite", {Vec2(0, 0), Vec2(kNaN, 0), Vec2(1, 1), Vec2(0, kInfinity)},
            {{PolygonIssueKind::NonFiniteVertex, "vertex 1 is not a finite number"},
                {PolygonIssueKind::NonFiniteVertex, "vertex 3 is not a finite number"}}},
        ValidationCase{"too_few_and_non_finite", {Vec2(0, 0), Vec2(-kInfinity, 1)},
            {{PolygonIssueKind::TooFewVertices, "polygon needs at least 3 vertices (got 2)"},
                {PolygonIssueKind::NonFiniteVertex, "vertex 1 is not a finite number"}}}),
    CaseName{});

INSTANTIATE_TEST_SUITE_P(Accepted, PolygonValidation,
    ::testing::Values(ValidationCase{"triangle", {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)}, {}},
        ValidationCase{"clockwise_square", reversed({Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)}), {}},
        ValidationCase{"square_with_midpoint", {Vec2(0, 0), Vec2(1, 0), Vec2(2, 0), Vec2(2, 2), Vec2(0, 2)}, {}},
        ValidationCase{"midpoint_at_vertex_0", {Vec2(1, 0), Vec2(2, 0), Vec2(2, 2), Vec2(0, 2), Vec2(0, 0)}, {}},
        ValidationCase{"l_shape", fixtures::lShape(), {}},
        ValidationCase{"l_shape_with_midpoints", fixtures::lShapeWithMidpoints(), {}},
        ValidationCase{"clockwise_l_shape", reversed(fixtures::lShape()), {}},
        ValidationCase{"u_shape", fixtures::uShape(), {}},
        ValidationCase{"plus", fixtures::plusShape(), {}},
        ValidationCase{"star", fixtures::star(5, 2, 0.8), {}},
        ValidationCase{"comb", fixtures::comb(5, true), {}},
        ValidationCase{"spiral", fixtures::spiral(), {}},
        // A sharp but honest spike: its tip is 1e-6 m wide on a 10 m shape, far above tolerance.
        ValidationCase{"thin_spike", {Vec2(0, 0), Vec2(10, 0), Vec2(0, 1e-6)}, {}},
        ValidationCase{"far_from_origin", translated(fixtures::lShape(), Vec2(1e6, -3e6)), {}},
        // Regression: edges 3 and 7 lie on one line with a 1-unit gap. Rotated and scaled, the
        // orientation signs of their endpoints were rounding noise and came out opposite on both
        // edges, so the two were reported as crossing.
        ValidationCase{"collinear_edges_with_a_gap_rotated", rotatedAndScaled(
            {Vec2(0, 0), Vec2(0, 5), Vec2(9, 5), Vec2(9, 0), Vec2(4, 0), Vec2(4, 2), Vec2(3, 2), Vec2(3, 0)}, 0.7, 3.3e6),
            {}}),
    CaseName{});

// ---------------------------------------------------------------------------------------------
// signedArea, normalizedCounterClockwise, isConvex

TEST(PolygonArea, SignedAreaIsPositiveCounterClockwise)
{
    const std::vector<Vec2> square = {Vec2(0, 0), Vec2(2, 0), Vec2(2, 3), Vec2(0, 3)};
    EXPECT_NEAR(signedArea(square), 6, kTolerance);
    EXPECT_NEAR(signedArea(reversed(square)), -6, kTolerance);
    EXPECT_NEAR(signedArea(fixtures::lShape()), 3, kTolerance);
    EXPECT_EQ(signedArea(std::vector<Vec2>{}), 0);
}

TEST(PolygonArea, SignedAreaFarFromTheOriginKeepsItsDigits)
{
    // Around the origin, the shoelace terms would be ~1e16 each and cancel down to 3.
    EXPECT_NEAR(signedArea(translated(fixtures::lShape(), Vec2(1e8, -1e8))), 3, kTolerance);
}

TEST(PolygonNormalize, MakesClockwiseCounterClockwiseAndKeepsVertexZeroFirst)
{
    const std::vector<Vec2> clockwise = {Vec2(0, 0), Vec2(0, 2), Vec2(2, 2), Vec2(2, 0)};
    const std::vector<Vec2> expected = {Vec2(0, 0), Vec2(2, 0), Vec2(2, 2), Vec2(0, 2)};
    EXPECT_EQ(normalizedCounterClockwise(clockwise), expected);
    EXPECT_EQ(normalizedCounterClockwise(expected), expected);
}

TEST(PolygonNormalize, DropsVerticesOnStraightEdges)
{
    // Clockwise, with midpoints on two edges.
    const std::vector<Vec2> input = {Vec2(0, 0), Vec2(0, 1), Vec2(0, 2), Vec2(2, 2), Vec2(2, 0), Vec2(1, 0)};
    const std::vector<Vec2> expected = {Vec2(0, 0), Vec2(2, 0), Vec2(2, 2), Vec2(0, 2)};
    EXPECT_EQ(normalizedCounterClockwise(input), expected);
}

TEST(PolygonNormalize, DropsVertexZeroWhenItIsOnAStraightEdge)
{
    const std::vector<Vec2> input = {Vec2(1, 0), Vec2(2, 0), Vec2(2, 2), Vec2(0, 2), Vec2(0, 0)};
    const std::vector<Vec2> expected = {Vec2(2, 0), Vec2(2, 2), Vec2(0, 2), Vec2(0, 0)};
    EXPECT_EQ(normalizedCounterClockwise(input), expected);
}

TEST(PolygonNormalize, CollapsesALongCollinearRun)
{
    // Ten vertices along the bottom edge of a triangle, the run crossing vertex 0.
    std::vector<Vec2> input;
    for (int k = 5; k <= 9; ++k)
        input.emplace_back(0.1 * k, 0.0);
    input.emplace_back(1.0, 0.0);
    input.emplace_back(0.0, 1.0);
    for (int k = 0; k <= 4; ++k)
        input.emplace_back(0.1 * k, 0.0);
    const std::vector<Vec2> expected = {Vec2(1, 0), Vec2(0, 1), Vec2(0, 0)};
    EXPECT_EQ(normalizedCounterClockwise(input), expected);
}

TEST(PolygonNormalize, KeepsConcaveCorners)
{
    EXPECT_EQ(normalizedCounterClockwise(fixtures::lShapeWithMidpoints()), fixtures::lShape());
    EXPECT_EQ(normalizedCounterClockwise(reversed(fixtures::lShape())).size(), 6u);
}

struct ConvexityCase {
    std::string name;
    std::vector<Vec2> vertices;
    bool convex;
};

void PrintTo(const ConvexityCase& c, std::ostream* os) { *os << c.name; }

class PolygonConvexity : public ::testing::TestWithParam<ConvexityCase> {};

TEST_P(PolygonConvexity, HasNoReflexVertex)
{
    EXPECT_EQ(isConvex(GetParam().vertices), GetParam().convex);
}

INSTANTIATE_TEST_SUITE_P(Shapes, PolygonConvexity,
    ::testing::Values(ConvexityCase{"triangle", {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)}, true},
        ConvexityCase{"clockwise_triangle", {Vec2(0, 0), Vec2(0, 1), Vec2(1, 0)}, true},
        ConvexityCase{"hexagon", fixtures::regularPolygon(6, 1), true},
        ConvexityCase{"clockwise_hexagon", reversed(fixtures::regularPolygon(6, 1)), true},
        ConvexityCase{"square_with_midpoint", {Vec2(0, 0), Vec2(1, 0), Vec2(2, 0), Vec2(2, 2), Vec2(0, 2)}, true},
        ConvexityCase{"l_shape", fixtures::lShape(), false},
        ConvexityCase{"clockwise_l_shape", reversed(fixtures::lShape()), false},
        ConvexityCase{"star", fixtures::star(5, 2, 0.8), false},
        // The only reflex vertex is barely in: 1e-3 m on a 2 m shape.
        ConvexityCase{"shallow_dent", {Vec2(0, 0), Vec2(2, 0), Vec2(2, 2), Vec2(1, 1.999), Vec2(0, 2)}, false},
        // Turns left at every tip, but winds round twice.
        ConvexityCase{"pentagram", pentagram(), false},
        ConvexityCase{"bowtie", {Vec2(0, 0), Vec2(1, 1), Vec2(1, 0), Vec2(0, 1)}, false},
        ConvexityCase{"two_points", {Vec2(0, 0), Vec2(1, 0)}, false}),
    CaseName{});

// ---------------------------------------------------------------------------------------------
// triangulate and decomposeConvex

/// True when the interiors of two convex counter-clockwise polygons overlap by more than `slack`
/// (m): no edge normal of either separates them (separating axis theorem).
bool interiorsOverlap(const std::vector<Vec2>& a, const std::vector<Vec2>& b, Scalar slack)
{
    const auto separatedByAnEdgeOf = [slack](const std::vector<Vec2>& edges, const std::vector<Vec2>& other) {
        for (std::size_t i = 0; i < edges.size(); ++i) {
            const Vec2 edge = edges[(i + 1) % edges.size()] - edges[i];
            const Vec2 outward = Vec2(edge.y(), -edge.x()).normalized();
            Scalar nearest = std::numeric_limits<Scalar>::infinity();
            for (const Vec2& p : other)
                nearest = std::min(nearest, outward.dot(p - edges[i]));
            if (nearest >= -slack)
                return true;
        }
        return false;
    };
    return !separatedByAnEdgeOf(a, b) && !separatedByAnEdgeOf(b, a);
}

/// True when `p` is exactly one of the polygon's vertices: decomposition adds no new points.
bool isVertexOf(const Vec2& p, const std::vector<Vec2>& polygon)
{
    return std::find(polygon.begin(), polygon.end(), p) != polygon.end();
}

/// Number of reflex vertices of a counter-clockwise polygon without straight vertices.
std::size_t reflexCount(const std::vector<Vec2>& ccw)
{
    std::size_t count = 0;
    for (std::size_t i = 0; i < ccw.size(); ++i) {
        const Vec2& a = ccw[(i + ccw.size() - 1) % ccw.size()];
        const Vec2& b = ccw[i];
        const Vec2& c = ccw[(i + 1) % ccw.size()];
        if (cross(Vec2(b - a), Vec2(c - b)) < 0)
            ++count;
    }
    return count;
}

struct DecompositionCase {
    std::string name;
    std::vector<Vec2> vertices;
};

void PrintTo(const DecompositionCase& c, std::ostream* os) { *os << c.name; }

class PolygonDecomposition : public ::testing::TestWithParam<DecompositionCase> {};

TEST_P(PolygonDecomposition, InputIsValid)
{
    // Guards the table itself: every other test here assumes a simple polygon.
    EXPECT_TRUE(validatePolygon(GetParam().vertices).empty());
}

TEST_P(PolygonDecomposition, TriangulationTilesThePolygon)
{
    const std::vector<Vec2>& vertices = GetParam().vertices;
    const std::vector<Vec2> polygon = normalizedCounterClockwise(vertices);
    const AreaProperties whole = polygonAreaProperties(vertices);
    const std::vector<Triangle> triangles = triangulate(vertices);
    ASSERT_EQ(triangles.size(), polygon.size() - 2);

    Scalar area = 0;
    for (const Triangle& t : triangles) {
        EXPECT_GT(signedArea(t), 0) << "every triangle counter-clockwise and not flat";
        for (const Vec2& p : t)
            EXPECT_TRUE(isVertexOf(p, polygon));
        area += signedArea(t);
    }
    EXPECT_NEAR(area, whole.area, tolerance(whole.area));

    const Scalar slack = 1e-9 * extent(vertices);
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        for (std::size_t j = i + 1; j < triangles.size(); ++j) {
            const std::vector<Vec2> a(triangles[i].begin(), triangles[i].end());
            const std::vector<Vec2> b(triangles[j].begin(), triangles[j].end());
            EXPECT_FALSE(interiorsOverlap(a, b, slack)) << "triangles " << i << " and " << j;
        }
    }
}

TEST_P(PolygonDecomposition, PiecesAreConvexCounterClockwiseAndTileThePolygon)
{
    const std::vector<Vec2>& vertices = GetParam().vertices;
    const std::vector<Vec2> polygon = normalizedCounterClockwise(vertices);
    const AreaProperties whole = polygonAreaProperties(vertices);
    const std::vector<std::vector<Vec2>> pieces = decomposeConvex(vertices);
    ASSERT_FALSE(pieces.empty());

    Scalar area = 0;
    Vec2 firstMoment = Vec2::Zero();
    for (const std::vector<Vec2>& piece : pieces) {
        EXPECT_TRUE(isConvex(piece));
        EXPECT_GT(signedArea(piece), 0) << "every piece counter-clockwise";
        EXPECT_EQ(normalizedCounterClockwise(piece), piece) << "no vertex on a straight edge";
        for (const Vec2& p : piece)
            EXPECT_TRUE(isVertexOf(p, polygon));
        const AreaProperties part = polygonAreaProperties(piece);
        area += part.area;
        firstMoment += part.area * part.centroid;
    }
    EXPECT_NEAR(area, whole.area, tolerance(whole.area));
    const Vec2 centroid = firstMoment / area;
    EXPECT_NEAR(centroid.x(), whole.centroid.x(), tolerance(extent(vertices)));
    EXPECT_NEAR(centroid.y(), whole.centroid.y(), tolerance(extent(vertices)));

    const Scalar slack = 1e-9 * extent(vertices);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        for (std::size_t j = i + 1; j < pieces.size(); ++j)
            EXPECT_FALSE(interiorsOverlap(pieces[i], pieces[j], slack)) << "pieces " << i << " and " << j;
    }
}

TEST_P(PolygonDecomposition, NoMorePiecesThanHertelMehlhornAllows)
{
    // Every diagonal left is essential to one of its ends, and a reflex vertex keeps at most two
    // essential diagonals: at most 2r + 1 pieces for r reflex vertices. A convex polygon is one.
    const std::vector<Vec2> polygon = normalizedCounterClockwise(GetParam().vertices);
    const std::size_t reflex = reflexCount(polygon);
    const std::vector<std::vector<Vec2>> pieces = decomposeConvex(GetParam().vertices);
    EXPECT_LE(pieces.size(), 2 * reflex + 1);
    EXPECT_LE(pieces.size(), polygon.size() - 2);
}

TEST_P(PolygonDecomposition, IsDeterministic)
{
    // Same input, same bits: repeated calls and a copy of the input give identical output.
    const std::vector<Vec2> copy = GetParam().vertices;
    EXPECT_EQ(decomposeConvex(GetParam().vertices), decomposeConvex(copy));
    const std::vector<Triangle> first = triangulate(GetParam().vertices);
    const std::vector<Triangle> second = triangulate(copy);
    ASSERT_EQ(first.size(), second.size());
    for (std::size_t i = 0; i < first.size(); ++i)
        EXPECT_EQ(first[i], second[i]);
}

INSTANTIATE_TEST_SUITE_P(Concave, PolygonDecomposition,
    ::testing::Values(DecompositionCase{"l_shape", fixtures::lShape()},
        DecompositionCase{"clockwise_l_shape", reversed(fixtures::lShape())},
        DecompositionCase{"l_shape_with_midpoints", fixtures::lShapeWithMidpoints()},
        DecompositionCase{"l_shape_far_from_origin", translated(fixtures::lShape(), Vec2(1000, -500))},
        DecompositionCase{"u_shape", fixtures::uShape()},
        DecompositionCase{"plus", fixtures::plusShape()},
        DecompositionCase{"star", fixtures::star(5, 2, 0.8)},
        DecompositionCase{"clockwise_star", reversed(fixtures::star(7, 3, 1))},
        DecompositionCase{"comb", fixtures::comb(5)},
        DecompositionCase{"comb_with_base_midpoints", fixtures::comb(8, true)},
        DecompositionCase{"clockwise_comb", reversed(fixtures::comb(6))},
        DecompositionCase{"spiral", fixtures::spiral()},
        DecompositionCase{"clockwise_spiral", reversed(fixtures::spiral())}),
    CaseName{});

INSTANTIATE_TEST_SUITE_P(Convex, PolygonDecomposition,
    ::testing::Values(DecompositionCase{"triangle", {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)}},
        DecompositionCase{"square_with_midpoint", {Vec2(0, 0), Vec2(1, 0), Vec2(2, 0), Vec2(2, 2), Vec2(0, 2)}},
        DecompositionCase{"clockwise_hexagon", reversed(fixtures::regularPolygon(6, 1.5))},
        DecompositionCase{"circle_like", fixtures::regularPolygon(64, 2)}),
    CaseName{});

struct ConvexCase {
    std::string name;
    std::vector<Vec2> vertices;
};

void PrintTo(const ConvexCase& c, std::ostream* os) { *os << c.name; }

class ConvexDecomposition : public ::testing::TestWithParam<ConvexCase> {};

TEST_P(ConvexDecomposition, GivesOnePieceEqualToTheNormalizedInput)
{
    const std::vector<std::vector<Vec2>> pieces = decomposeConvex(GetParam().vertices);
    ASSERT_EQ(pieces.size(), 1u);
    EXPECT_EQ(pieces[0], normalizedCounterClockwise(GetParam().vertices));
}

INSTANTIATE_TEST_SUITE_P(Shapes, ConvexDecomposition,
    ::testing::Values(ConvexCase{"triangle", {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)}},
        ConvexCase{"clockwise_square", reversed({Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)})},
        ConvexCase{"square_with_midpoint", {Vec2(0, 0), Vec2(1, 0), Vec2(2, 0), Vec2(2, 2), Vec2(0, 2)}},
        ConvexCase{"hexagon", fixtures::regularPolygon(6, 1)},
        ConvexCase{"clockwise_circle_like", reversed(fixtures::regularPolygon(64, 2))}),
    CaseName{});

TEST(PolygonDecompositionWorked, LShapeSplitsIntoTwoPieces)
{
    // One reflex vertex (1,1): one diagonal from it to a far corner gives two convex pieces, and
    // no single convex piece can hold the whole L.
    const std::vector<std::vector<Vec2>> pieces = decomposeConvex(fixtures::lShape());
    EXPECT_EQ(pieces.size(), 2u);
}

TEST(PolygonDecompositionWorked, CombTeethAreNotBridged)
{
    // The gap bottoms (k, 1) and (k − ½, 1) all lie on y = 1, so a careless clipper can lay a
    // diagonal along that line through other vertices. Whatever happens below y = 1, a convex
    // piece that held the tops of two different teeth would span the gap between them.
    for (const std::vector<Vec2>& piece : decomposeConvex(fixtures::comb(5))) {
        std::vector<Scalar> topXs;
        for (const Vec2& p : piece) {
            if (p.y() > 1)
                topXs.push_back(p.x());
        }
        if (!topXs.empty()) {
            const auto [low, high] = std::minmax_element(topXs.begin(), topXs.end());
            EXPECT_LE(*high - *low, 0.5) << "one tooth is ½ m wide";
        }
    }
}

} // namespace
} // namespace impetus::model
