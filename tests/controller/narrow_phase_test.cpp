// Narrow phase: polygon–polygon (SAT and clipping), circles, and ellipses (GJK/EPA), checked
// against hand-computed contacts and, for ellipses, against brute-force geometry.

#include "controller/collision/narrow_phase.h"

#include "model/polygon.h"
#include "support/polygon_shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <ostream>
#include <string>
#include <variant>
#include <vector>

namespace impetus::controller {
namespace {

constexpr Scalar kExact = 1e-12; ///< m: closed-form results, up to rounding
constexpr Scalar kEllipseAccuracy = 1e-6; ///< m: the accuracy narrow_phase.h promises for ellipses

/// Names each TEST_P instance after its table row (`name` field).
struct CaseName {
    template <class Case>
    std::string operator()(const ::testing::TestParamInfo<Case>& row) const
    {
        return row.param.name;
    }
};

// ---------------------------------------------------------------------------------------------
// Shapes

using testing::makePolygon;
using testing::Polygon;

/// The axis-aligned box [x0, x1]×[y0, y1], vertices counter-clockwise from the lower left, so edge
/// 0 is the bottom, 1 the right side, 2 the top and 3 the left side.
Polygon box(Scalar x0, Scalar y0, Scalar x1, Scalar y1)
{
    return makePolygon({Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)});
}

/// p rotated by `angle` about the world origin, then moved by `offset`.
Vec2 moved(const Vec2& p, Scalar angle, const Vec2& offset) { return rotate(p, angle) + offset; }

Polygon moved(const Polygon& polygon, Scalar angle, const Vec2& offset)
{
    std::vector<Vec2> vertices;
    for (const Vec2& v : polygon.vertices)
        vertices.push_back(moved(v, angle, offset));
    return makePolygon(vertices);
}

/// A box of half-extents (hx, hy) centred at `centre` and turned by `angle`.
Polygon orientedBox(const Vec2& centre, Scalar hx, Scalar hy, Scalar angle)
{
    return moved(box(-hx, -hy, hx, hy), angle, centre);
}

EllipseShape ellipse(const Vec2& centre, Scalar radiusX, Scalar radiusY, Scalar angle)
{
    return EllipseShape{centre, radiusX, radiusY, std::cos(angle), std::sin(angle)};
}

/// Any test shape, owning its data.
using Shape = std::variant<Polygon, CircleShape, EllipseShape>;

ConvexShape view(const Shape& s)
{
    if (const auto* p = std::get_if<Polygon>(&s))
        return p->shape();
    if (const auto* c = std::get_if<CircleShape>(&s))
        return *c;
    return std::get<EllipseShape>(s);
}

// ---------------------------------------------------------------------------------------------
// Expectations

struct ExpectedPoint {
    Vec2 point;
    Scalar separation;
};

/// Checks a manifold against the expected normal and points (in any order), within `tolerance`.
void expectManifold(const Manifold& m, const Vec2& normal, std::vector<ExpectedPoint> expected, Scalar tolerance)
{
    ASSERT_EQ(m.count, static_cast<int>(expected.size()));
    if (expected.empty())
        return;
    EXPECT_NEAR(m.normal.x(), normal.x(), tolerance);
    EXPECT_NEAR(m.normal.y(), normal.y(), tolerance);
    // Both lists ordered along the contact tangent, so the comparison is order-free.
    const Vec2 tangent(-normal.y(), normal.x());
    std::vector<ContactPoint> actual(m.points.begin(), m.points.begin() + m.count);
    std::sort(actual.begin(), actual.end(), [&](const ContactPoint& p, const ContactPoint& q) {
        return tangent.dot(p.point) < tangent.dot(q.point);
    });
    std::sort(expected.begin(), expected.end(), [&](const ExpectedPoint& p, const ExpectedPoint& q) {
        return tangent.dot(p.point) < tangent.dot(q.point);
    });
    for (std::size_t i = 0; i < expected.size(); ++i) {
        SCOPED_TRACE("point " + std::to_string(i));
        EXPECT_NEAR(actual[i].point.x(), expected[i].point.x(), tolerance);
        EXPECT_NEAR(actual[i].point.y(), expected[i].point.y(), tolerance);
        EXPECT_NEAR(actual[i].separation, expected[i].separation, tolerance);
    }
}

Scalar minSeparation(const Manifold& m)
{
    Scalar s = std::numeric_limits<Scalar>::infinity();
    for (int i = 0; i < m.count; ++i)
        s = std::min(s, m.points[static_cast<std::size_t>(i)].separation);
    return s;
}

// ---------------------------------------------------------------------------------------------
// Polygon–polygon (SAT)

/// A is given as one or more convex pieces (several for a concave polygon); exactly one piece is
/// expected to touch B, with the expected manifold, and the others to report no contact.
struct PolygonCase {
    std::string name;
    std::vector<Polygon> a;
    Polygon b;
    Scalar margin;
    Vec2 normal;
    std::vector<ExpectedPoint> points;
};

void PrintTo(const PolygonCase& c, std::ostream* os) { *os << c.name; }

/// The floor of most cases: [−2, 2]×[−1, 0], top face at y = 0.
Polygon floorBox() { return box(-2, -1, 2, 0); }

/// A unit box resting on the floor, sunk 1/128 m into it (dyadic, so every number is exact).
Polygon restingBox() { return box(-0.5, -1.0 / 128, 0.5, 1 - 1.0 / 128); }

/// A square turned 45° standing on its lowest vertex (0, tip).
Polygon diamond(Scalar tip)
{
    return makePolygon({Vec2(0, tip), Vec2(1, tip + 1), Vec2(0, tip + 2), Vec2(-1, tip + 1)});
}

/// The L of 2×1 plus 1×1 squares, placed in the world by (angle, offset) and cut into convex pieces.
std::vector<Polygon> lPieces(Scalar angle, const Vec2& offset)
{
    std::vector<Vec2> l;
    for (const Vec2& v : {Vec2(0, 0), Vec2(2, 0), Vec2(2, 1), Vec2(1, 1), Vec2(1, 2), Vec2(0, 2)})
        l.push_back(moved(v, angle, offset));
    std::vector<Polygon> pieces;
    for (std::vector<Vec2>& piece : model::decomposeConvex(l))
        pieces.push_back(makePolygon(std::move(piece)));
    return pieces;
}

std::vector<PolygonCase> polygonCases()
{
    const Scalar d = 1.0 / 128; // sink depth of restingBox
    const Scalar angle = 0.3;
    const Vec2 offset(3, -2);
    const Vec2 lOffset(-1, 3);
    return {
        {"box_on_box_resting", {floorBox()}, restingBox(), 0.1, Vec2(0, 1),
         {{Vec2(-0.5, -d / 2), -d}, {Vec2(0.5, -d / 2), -d}}},
        // Face to face along x, overlapping 1/8 m, side by side over half their height.
        {"edge_edge", {box(0, 0, 1, 1)}, box(0.875, 0.5, 1.875, 1.5), 0.1, Vec2(1, 0),
         {{Vec2(0.9375, 0.5), -0.125}, {Vec2(0.9375, 1), -0.125}}},
        // A diamond's lowest vertex 1/8 m into the floor; its other incident vertex is far above.
        {"vertex_edge", {floorBox()}, diamond(-0.125), 0.1, Vec2(0, 1), {{Vec2(0, -0.0625), -0.125}}},
        // The same pair the other way round: the reference face is now B's, the normal flips.
        {"vertex_edge_reference_on_b", {diamond(-0.125)}, floorBox(), 0.1, Vec2(0, -1),
         {{Vec2(0, -0.0625), -0.125}}},
        // A box sunk three quarters of its height: the top face is still the least penetration.
        {"deep", {floorBox()}, box(-0.25, -0.75, 0.75, 0.25), 0.1, Vec2(0, 1),
         {{Vec2(-0.25, -0.375), -0.75}, {Vec2(0.75, -0.375), -0.75}}},
        {"just_touching", {floorBox()}, box(-0.5, 0, 0.5, 1), 0, Vec2(0, 1), {{Vec2(-0.5, 0), 0}, {Vec2(0.5, 0), 0}}},
        {"separated_within_margin", {floorBox()}, box(-0.5, 0.0625, 0.5, 1.0625), 0.125, Vec2(0, 1),
         {{Vec2(-0.5, 0.03125), 0.0625}, {Vec2(0.5, 0.03125), 0.0625}}},
        {"separated_beyond_margin", {floorBox()}, box(-0.5, 0.25, 0.5, 1.25), 0.125, Vec2(0, 1), {}},
        // box_on_box_resting turned by 0.3 rad and moved: the same manifold, turned and moved.
        {"rotated", {moved(floorBox(), angle, offset)}, moved(restingBox(), angle, offset), 0.1,
         rotate(Vec2(0, 1), angle),
         {{moved(Vec2(-0.5, -d / 2), angle, offset), -d}, {moved(Vec2(0.5, -d / 2), angle, offset), -d}}},
        // A box pressed 1/16 m into the top of the L's upper arm (world top face y = 5, x ∈ [−1, 0]).
        // Whatever the decomposition, exactly one piece holds that face and the others are more
        // than the margin away.
        {"concave_pieces", lPieces(0, lOffset), box(-0.75, 4.9375, -0.25, 5.4375), 0.05, Vec2(0, 1),
         {{Vec2(-0.75, 4.96875), -0.0625}, {Vec2(-0.25, 4.96875), -0.0625}}},
        // The same against the end face of the L's lower arm (world x = 1, y ∈ [3, 4]).
        {"concave_pieces_side", lPieces(0, lOffset), box(0.9375, 3.25, 1.4375, 3.75), 0.05, Vec2(1, 0),
         {{Vec2(0.96875, 3.25), -0.0625}, {Vec2(0.96875, 3.75), -0.0625}}},
    };
}

class PolygonCollision : public ::testing::TestWithParam<PolygonCase> {};

TEST_P(PolygonCollision, matchesHandComputedManifold)
{
    const PolygonCase& c = GetParam();
    int touching = 0;
    for (const Polygon& piece : c.a) {
        const Manifold m = collidePolygons(piece.shape(), c.b.shape(), c.margin);
        if (m.count == 0)
            continue;
        ++touching;
        expectManifold(m, c.normal, c.points, kExact);
        // Through the dispatcher too.
        expectManifold(collide(piece.shape(), c.b.shape(), c.margin), c.normal, c.points, kExact);
    }
    EXPECT_EQ(touching, c.points.empty() ? 0 : 1);
}

INSTANTIATE_TEST_SUITE_P(Sat, PolygonCollision, ::testing::ValuesIn(polygonCases()), CaseName{});

TEST(PolygonCollision, concavePiecesAreSeveral)
{
    // Otherwise the concave_pieces cases would not test pieces at all.
    EXPECT_GE(lPieces(0, Vec2(-1, 3)).size(), 2u);
}

// ---------------------------------------------------------------------------------------------
// Manifold points and feature ids

std::vector<FeatureId> idsOf(const Manifold& m)
{
    std::vector<FeatureId> ids;
    for (int i = 0; i < m.count; ++i)
        ids.push_back(m.points[static_cast<std::size_t>(i)].id);
    std::sort(ids.begin(), ids.end());
    return ids;
}

TEST(ContactManifold, offsetBoxOnWiderBoxGivesItsTwoBottomCorners)
{
    const Scalar d = 1.0 / 64;
    const Manifold m = collidePolygons(floorBox().shape(), box(0.75, -d, 1.75, 1 - d).shape(), 0.1);
    expectManifold(m, Vec2(0, 1), {{Vec2(0.75, -d / 2), -d}, {Vec2(1.75, -d / 2), -d}}, kExact);
}

TEST(ContactManifold, overhangingBoxIsClippedAtTheEndOfTheFloor)
{
    // The top box reaches past x = 2: its right point is cut by the floor's side plane there.
    const Scalar d = 1.0 / 64;
    const Manifold m = collidePolygons(floorBox().shape(), box(1.5, -d, 2.5, 1 - d).shape(), 0.1);
    expectManifold(m, Vec2(0, 1), {{Vec2(1.5, -d / 2), -d}, {Vec2(2, -d / 2), -d}}, kExact);
}

TEST(ContactManifold, featureIdsAreStableWhileTheSameFeaturesTouch)
{
    const Polygon floor = floorBox();
    const Manifold before = collidePolygons(floor.shape(), box(0.75, -1.0 / 64, 1.75, 1 - 1.0 / 64).shape(), 0.1);
    // Slid, sunk a little deeper and tilted by a hair: still the same two corners on the same face.
    const Polygon nudged = orientedBox(Vec2(1.26, 0.48), 0.5, 0.5, 1e-4);
    const Manifold after = collidePolygons(floor.shape(), nudged.shape(), 0.1);
    ASSERT_EQ(before.count, 2);
    ASSERT_EQ(after.count, 2);
    EXPECT_NE(before.points[0].id, before.points[1].id);
    EXPECT_EQ(idsOf(before), idsOf(after));
}

TEST(ContactManifold, featureIdsChangeWhenDifferentFeaturesTouch)
{
    const Polygon floor = floorBox();
    const Manifold inside = collidePolygons(floor.shape(), box(0.75, -1.0 / 64, 1.75, 1 - 1.0 / 64).shape(), 0.1);
    // Slid past the end: the left corner still touches, the right one is now a clip point.
    const Manifold overhanging = collidePolygons(floor.shape(), box(1.5, -1.0 / 64, 2.5, 1 - 1.0 / 64).shape(), 0.1);
    ASSERT_EQ(inside.count, 2);
    ASSERT_EQ(overhanging.count, 2);
    const auto idAtX = [](const Manifold& m, Scalar x) {
        return std::abs(m.points[0].point.x() - x) < 1e-9 ? m.points[0].id : m.points[1].id;
    };
    EXPECT_NE(idsOf(inside), idsOf(overhanging));
    EXPECT_NE(idAtX(overhanging, 2.0), idAtX(inside, 1.75));
    // Turned upside down: its other two corners (vertices 2 and 3) touch instead.
    const Manifold upsideDown = collidePolygons(floor.shape(), orientedBox(Vec2(1.25, 0.5 - 1.0 / 64), 0.5, 0.5,
                                                                           std::numbers::pi).shape(), 0.1);
    ASSERT_EQ(upsideDown.count, 2);
    for (const FeatureId id : idsOf(upsideDown))
        for (const FeatureId other : idsOf(inside))
            EXPECT_NE(id, other);
    // The same features with the reference face on B instead of A are a different pairing.
    const Manifold onVertex = collidePolygons(floor.shape(), diamond(-0.125).shape(), 0.1);
    const Manifold swapped = collidePolygons(diamond(-0.125).shape(), floor.shape(), 0.1);
    ASSERT_EQ(onVertex.count, 1);
    ASSERT_EQ(swapped.count, 1);
    EXPECT_NE(swapped.points[0].id, onVertex.points[0].id);
}

TEST(ContactManifold, cornerToCornerGapGivesOneConservativePoint)
{
    // Boxes apart diagonally: the true gap is |(0.1, 0.05)|, the face-normal SAT reports the
    // larger axis gap 0.1 along x, an underestimate of the distance, which is safe for a
    // speculative contact.
    const Manifold m = collidePolygons(box(0, 0, 1, 1).shape(), box(1.1, 1.05, 2.1, 2.05).shape(), 0.2);
    ASSERT_EQ(m.count, 1);
    EXPECT_NEAR(m.normal.x(), 1, kExact);
    EXPECT_NEAR(m.normal.y(), 0, kExact);
    EXPECT_NEAR(m.points[0].separation, 0.1, kExact);
    EXPECT_LT(m.points[0].separation, std::hypot(0.1, 0.05));
    EXPECT_NEAR(m.points[0].point.x(), 1.05, kExact);
    EXPECT_NEAR(m.points[0].point.y(), 1.05, kExact);
}

// ---------------------------------------------------------------------------------------------
// Circles

struct CurvedCase {
    std::string name;
    Shape a;
    Shape b;
    Scalar margin;
    Vec2 normal;
    std::vector<ExpectedPoint> points;
    FeatureId id = 0;
};

void PrintTo(const CurvedCase& c, std::ostream* os) { *os << c.name; }

constexpr FeatureId kVertexBit = FeatureId{1} << 30;

std::vector<CurvedCase> circleCases()
{
    const CircleShape unit{Vec2(0, 0), 1};
    return {
        {"circle_circle_overlapping", unit, CircleShape{Vec2(1.5, 0), 1}, 0.1, Vec2(1, 0), {{Vec2(0.75, 0), -0.5}}},
        {"circle_circle_within_margin", unit, CircleShape{Vec2(2.0625, 0), 1}, 0.1, Vec2(1, 0),
         {{Vec2(1.03125, 0), 0.0625}}},
        {"circle_circle_beyond_margin", unit, CircleShape{Vec2(2.25, 0), 1}, 0.1, Vec2(1, 0), {}},
        // A 3-4-5 triangle: centres 5 m apart, surfaces 2.5 m apart.
        {"circle_circle_diagonal", unit, CircleShape{Vec2(3, 4), 1.5}, 3, Vec2(0.6, 0.8),
         {{Vec2(1.35, 1.8), 2.5}}},
        {"circle_circle_coincident", unit, CircleShape{Vec2(0, 0), 1}, 0.1, Vec2(0, 1), {{Vec2(0, 0), -2}}},
        {"polygon_circle_face", floorBox(), CircleShape{Vec2(0.25, 0.375), 0.5}, 0.1, Vec2(0, 1),
         {{Vec2(0.25, -0.0625), -0.125}}, 2},
        // Centre (2.3, 0.4) is (0.3, 0.4) from the corner (2, 0): 0.5 m away.
        {"polygon_circle_vertex", floorBox(), CircleShape{Vec2(2.3, 0.4), 0.75}, 0.1, Vec2(0.6, 0.8),
         {{Vec2(1.925, -0.1), -0.25}}, kVertexBit | 2},
        {"polygon_circle_vertex_within_margin", floorBox(), CircleShape{Vec2(2.6, 0.8), 0.5}, 0.75,
         Vec2(0.6, 0.8), {{Vec2(2.15, 0.2), 0.5}}, kVertexBit | 2},
        {"polygon_circle_vertex_beyond_margin", floorBox(), CircleShape{Vec2(2.6, 0.8), 0.5}, 0.25, Vec2(0.6, 0.8),
         {}},
        // Centre inside the floor, nearest the top face (1/8 m below it).
        {"polygon_circle_centre_inside", floorBox(), CircleShape{Vec2(0.75, -0.125), 0.5}, 0.1, Vec2(0, 1),
         {{Vec2(0.75, -0.3125), -0.625}}, 2},
        {"circle_polygon_face", CircleShape{Vec2(0.25, 0.375), 0.5}, floorBox(), 0.1, Vec2(0, -1),
         {{Vec2(0.25, -0.0625), -0.125}}, 2},
    };
}

class CircleCollision : public ::testing::TestWithParam<CurvedCase> {};

TEST_P(CircleCollision, matchesClosedForm)
{
    const CurvedCase& c = GetParam();
    const Manifold m = collide(view(c.a), view(c.b), c.margin);
    expectManifold(m, c.normal, c.points, kExact);
    if (m.count == 1) {
        EXPECT_EQ(m.points[0].id, c.id);
    }
}

INSTANTIATE_TEST_SUITE_P(Closed, CircleCollision, ::testing::ValuesIn(circleCases()), CaseName{});

// ---------------------------------------------------------------------------------------------
// Ellipses, against brute force

/// The boundary point of `e` at parameter t: centre + R·(a cos t, b sin t).
Vec2 ellipsePoint(const EllipseShape& e, Scalar t)
{
    const Vec2 local(e.radiusX * std::cos(t), e.radiusY * std::sin(t));
    return e.center + Vec2(e.c * local.x() - e.s * local.y(), e.s * local.x() + e.c * local.y());
}

/// d/dt of ellipsePoint.
Vec2 ellipseTangent(const EllipseShape& e, Scalar t)
{
    const Vec2 local(-e.radiusX * std::sin(t), e.radiusY * std::cos(t));
    return Vec2(e.c * local.x() - e.s * local.y(), e.s * local.x() + e.c * local.y());
}

/// The parameter minimising f over the ellipse boundary, given f and its derivative df: a fine
/// sweep, then bisection on the sign of df in the winning cell. (Bisecting on the derivative keeps
/// full precision where f itself is flat.)
template <class F, class DF>
Scalar argminOnBoundary(F f, DF df)
{
    const int samples = 20000;
    const Scalar step = 2 * std::numbers::pi / samples;
    Scalar bestT = 0;
    Scalar best = f(0.0);
    for (int i = 1; i < samples; ++i) {
        const Scalar t = i * step;
        if (const Scalar v = f(t); v < best) {
            best = v;
            bestT = t;
        }
    }
    Scalar lo = bestT - step;
    Scalar hi = bestT + step;
    EXPECT_LT(df(lo), 0);
    EXPECT_GT(df(hi), 0);
    for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
        const Scalar mid = 0.5 * (lo + hi);
        (df(mid) < 0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

/// The lowest boundary point of `e`.
Vec2 lowestPoint(const EllipseShape& e)
{
    return ellipsePoint(e, argminOnBoundary([&](Scalar t) { return ellipsePoint(e, t).y(); },
                                            [&](Scalar t) { return ellipseTangent(e, t).y(); }));
}

/// The boundary point of `e` nearest the outside point p.
Vec2 nearestPoint(const EllipseShape& e, const Vec2& p)
{
    const auto squaredDistance = [&](Scalar t) { return (ellipsePoint(e, t) - p).squaredNorm(); };
    const auto halfSlope = [&](Scalar t) { return (ellipsePoint(e, t) - p).dot(ellipseTangent(e, t)); };
    return ellipsePoint(e, argminOnBoundary(squaredDistance, halfSlope));
}

/// Ellipse B resting on the floor's top face y = 0 with its lowest point at height `gap`.
CurvedCase ellipseOnFloor(std::string name, Scalar angle, Scalar gap)
{
    const EllipseShape atOrigin = ellipse(Vec2(0.2, 0), 1, 0.5, angle);
    const Vec2 low = lowestPoint(atOrigin);
    const EllipseShape e = ellipse(Vec2(0.2, gap - low.y()), 1, 0.5, angle);
    return {std::move(name), floorBox(), e, 0.1, Vec2(0, 1), {{Vec2(low.x(), gap / 2), gap}}};
}

/// Circle B near ellipse A, outside it: the contact follows the nearest boundary point.
CurvedCase circleNearEllipse(std::string name, const EllipseShape& e, const Vec2& centre, Scalar radius)
{
    const Vec2 q = nearestPoint(e, centre);
    const Scalar distance = (centre - q).norm();
    const Vec2 n = (centre - q) / distance;
    const Scalar separation = distance - radius;
    return {std::move(name), e, CircleShape{centre, radius}, 0.5, n, {{q + 0.5 * separation * n, separation}}};
}

/// A diamond whose lowest vertex v is near ellipse A: the nearest boundary point to v decides it,
/// provided the direction from there to v is within the vertex's normal cone (checked by the test).
CurvedCase vertexNearEllipse(std::string name, const EllipseShape& e, const Vec2& v)
{
    const Vec2 q = nearestPoint(e, v);
    const Scalar distance = (v - q).norm();
    const Vec2 n = (v - q) / distance;
    const Scalar s = 0.3;
    return {std::move(name), e, makePolygon({v, v + Vec2(s, s), v + Vec2(0, 2 * s), v + Vec2(-s, s)}), 0.5, n,
            {{q + 0.5 * distance * n, distance}}};
}

std::vector<CurvedCase> ellipseCases()
{
    const EllipseShape tilted = ellipse(Vec2(0.5, -0.2), 2, 1, 0.3);
    return {
        // Axis-aligned, semi-axis b = 0.5 above the face at height h: separation h − b exactly.
        {"ellipse_on_box_overlapping", floorBox(), ellipse(Vec2(0.3, 0.45), 1.5, 0.5, 0), 0.1, Vec2(0, 1),
         {{Vec2(0.3, -0.025), -0.05}}},
        {"ellipse_on_box_within_margin", floorBox(), ellipse(Vec2(0.3, 0.55), 1.5, 0.5, 0), 0.1, Vec2(0, 1),
         {{Vec2(0.3, 0.025), 0.05}}},
        {"ellipse_on_box_beyond_margin", floorBox(), ellipse(Vec2(0.3, 0.75), 1.5, 0.5, 0), 0.1, Vec2(0, 1), {}},
        // Tip to tip along x: A reaches x = 2, B (3×1 turned upright) reaches back 1 from its centre.
        {"ellipse_ellipse_axis_apart", ellipse(Vec2(0, 0), 2, 1, 0), ellipse(Vec2(3.5, 0), 3, 1, std::numbers::pi / 2),
         1, Vec2(1, 0), {{Vec2(2.25, 0), 0.5}}},
        {"ellipse_ellipse_axis_overlapping", ellipse(Vec2(0, 0), 2, 1, 0),
         ellipse(Vec2(2.75, 0), 3, 1, std::numbers::pi / 2), 1, Vec2(1, 0), {{Vec2(1.875, 0), -0.25}}},
        ellipseOnFloor("rotated_ellipse_on_box_overlapping", 0.6, -0.03),
        ellipseOnFloor("rotated_ellipse_on_box_within_margin", 0.6, 0.04),
        vertexNearEllipse("rotated_ellipse_vertex_within_margin", tilted, Vec2(1.2, 1.3)),
        circleNearEllipse("ellipse_circle_within_margin", tilted, Vec2(2.3, 1.3), 0.3),
        circleNearEllipse("ellipse_circle_overlapping", tilted, Vec2(2.3, 1.3), 0.8),
    };
}

class EllipseCollision : public ::testing::TestWithParam<CurvedCase> {};

TEST_P(EllipseCollision, matchesBruteForceGeometry)
{
    const CurvedCase& c = GetParam();
    if (const auto* p = std::get_if<Polygon>(&c.b); p != nullptr && p->vertices.size() == 4 && c.points.size() == 1 &&
                                                    c.name.find("vertex") != std::string::npos) {
        // The expected value assumes the diamond's lowest vertex is its nearest feature.
        ASSERT_GT(c.normal.y(), std::abs(c.normal.x()));
    }
    const Manifold m = collide(view(c.a), view(c.b), c.margin);
    expectManifold(m, c.normal, c.points, kEllipseAccuracy);
    // The same through the general algorithm called directly.
    expectManifold(collideConvexGeneral(view(c.a), view(c.b), c.margin), c.normal, c.points, kEllipseAccuracy);
}

INSTANTIATE_TEST_SUITE_P(GjkEpa, EllipseCollision, ::testing::ValuesIn(ellipseCases()), CaseName{});

// ---------------------------------------------------------------------------------------------
// Cross-check: the general algorithm agrees with SAT and the circle formulas

struct CrossCase {
    std::string name;
    Shape a;
    Shape b;
};

void PrintTo(const CrossCase& c, std::ostream* os) { *os << c.name; }

std::vector<CrossCase> crossCases()
{
    std::vector<CrossCase> cases{
        {"box_on_box_resting", floorBox(), restingBox()},
        {"edge_edge", box(0, 0, 1, 1), box(0.875, 0.5, 1.875, 1.5)},
        {"vertex_edge", floorBox(), diamond(-0.125)},
        {"deep", floorBox(), box(-0.25, -0.75, 0.75, 0.25)},
        {"separated_within_margin", floorBox(), box(-0.5, 0.0625, 0.5, 1.0625)},
        {"vertex_edge_separated", floorBox(), diamond(0.05)},
        {"tilted_corner_overlapping", floorBox(), orientedBox(Vec2(0.3, 0.4), 0.5, 0.3, 0.4)},
        {"tilted_corner_separated", orientedBox(Vec2(0, -0.5), 2, 0.5, 0.1),
         orientedBox(Vec2(0.3, 0.55), 0.5, 0.3, 0.4)},
        {"tilted_boxes_overlapping", orientedBox(Vec2(0, 0), 1, 0.5, 0.7), orientedBox(Vec2(0.9, 0.9), 0.6, 0.4, -0.3)},
        {"circle_box_face", floorBox(), CircleShape{Vec2(0.25, 0.375), 0.5}},
        {"circle_box_vertex", floorBox(), CircleShape{Vec2(2.3, 0.4), 0.75}},
        {"circle_box_vertex_separated", floorBox(), CircleShape{Vec2(2.6, 0.8), 0.5}},
        {"circle_box_centre_inside", floorBox(), CircleShape{Vec2(0.75, -0.125), 0.5}},
        {"circle_tilted_box_separated", orientedBox(Vec2(1, 1), 1, 0.5, 0.5), CircleShape{Vec2(1.2, 2.4), 0.4}},
        {"circle_tilted_box_overlapping", orientedBox(Vec2(1, 1), 1, 0.5, 0.5), CircleShape{Vec2(1.4, 1.8), 0.4}},
        {"circle_circle", CircleShape{Vec2(0, 0), 1}, CircleShape{Vec2(1.2, 0.9), 0.7}},
    };
    return cases;
}

class GeneralCrossCheck : public ::testing::TestWithParam<CrossCase> {};

TEST_P(GeneralCrossCheck, agreesWithTheDedicatedAlgorithm)
{
    const CrossCase& c = GetParam();
    const Scalar margin = 1;
    const Manifold dedicated = collide(view(c.a), view(c.b), margin);
    const Manifold general = collideConvexGeneral(view(c.a), view(c.b), margin);
    ASSERT_GE(dedicated.count, 1);
    ASSERT_EQ(general.count, 1);
    EXPECT_NEAR(general.normal.x(), dedicated.normal.x(), kEllipseAccuracy);
    EXPECT_NEAR(general.normal.y(), dedicated.normal.y(), kEllipseAccuracy);
    EXPECT_NEAR(general.points[0].separation, minSeparation(dedicated), kEllipseAccuracy);
}

INSTANTIATE_TEST_SUITE_P(Narrow, GeneralCrossCheck, ::testing::ValuesIn(crossCases()), CaseName{});

// ---------------------------------------------------------------------------------------------
// Symmetry: collide(a, b) and collide(b, a)

std::vector<CrossCase> symmetryCases()
{
    std::vector<CrossCase> cases = crossCases();
    const EllipseShape tilted = ellipse(Vec2(0.5, -0.2), 2, 1, 0.3);
    cases.push_back({"ellipse_box", floorBox(), ellipse(Vec2(0.3, 0.45), 1.5, 0.5, 0.2)});
    cases.push_back({"ellipse_circle", tilted, CircleShape{Vec2(2.0, 1.0), 0.6}});
    cases.push_back({"ellipse_ellipse", tilted, ellipse(Vec2(2.2, 1.4), 1, 0.4, -0.8)});
    cases.push_back({"ellipse_ellipse_apart", tilted, ellipse(Vec2(2.6, 1.9), 1, 0.4, -0.8)});
    return cases;
}

class Symmetry : public ::testing::TestWithParam<CrossCase> {};

TEST_P(Symmetry, swappingTheShapesFlipsTheNormalOnly)
{
    const CrossCase& c = GetParam();
    const bool curved = std::holds_alternative<EllipseShape>(c.a) || std::holds_alternative<EllipseShape>(c.b);
    const Scalar tolerance = curved ? kEllipseAccuracy : kExact;
    const Manifold ab = collide(view(c.a), view(c.b), 1);
    const Manifold ba = collide(view(c.b), view(c.a), 1);
    ASSERT_GE(ab.count, 1);
    std::vector<ExpectedPoint> points;
    for (int i = 0; i < ab.count; ++i) {
        const ContactPoint& p = ab.points[static_cast<std::size_t>(i)];
        points.push_back({p.point, p.separation});
    }
    expectManifold(ba, -ab.normal, points, tolerance);
}

INSTANTIATE_TEST_SUITE_P(Narrow, Symmetry, ::testing::ValuesIn(symmetryCases()), CaseName{});

// ---------------------------------------------------------------------------------------------
// Degenerate input

bool allFinite(const Manifold& m)
{
    bool ok = isFinite(m.normal);
    for (int i = 0; i < m.count; ++i)
        ok = ok && isFinite(m.points[static_cast<std::size_t>(i)].point) &&
             std::isfinite(m.points[static_cast<std::size_t>(i)].separation);
    return ok;
}

TEST(DegenerateInput, nanPositionsGiveNoContact)
{
    const Scalar nan = std::numeric_limits<Scalar>::quiet_NaN();
    const Polygon floor = floorBox();
    const Polygon bad = box(nan, 0, 1, 1);
    const CircleShape badCircle{Vec2(nan, 0), 1};
    const EllipseShape badEllipse = ellipse(Vec2(0, nan), 1, 0.5, 0);
    EXPECT_EQ(collide(floor.shape(), bad.shape(), 0.1).count, 0);
    EXPECT_EQ(collide(floor.shape(), badCircle, 0.1).count, 0);
    EXPECT_EQ(collide(badCircle, CircleShape{Vec2(0, 0), 1}, 0.1).count, 0);
    EXPECT_EQ(collide(floor.shape(), badEllipse, 0.1).count, 0);
    EXPECT_EQ(collide(badEllipse, badCircle, 0.1).count, 0);
}

TEST(DegenerateInput, identicalShapesOverlapByTheirThinnestExtent)
{
    // A 4×1 box on itself: the least penetration is the height, 1 m, along ±y.
    const Polygon floor = floorBox();
    const Manifold sat = collide(floor.shape(), floor.shape(), 0.1);
    ASSERT_EQ(sat.count, 2);
    EXPECT_NEAR(std::abs(sat.normal.y()), 1, kExact);
    EXPECT_NEAR(minSeparation(sat), -1, kExact);
    const Manifold general = collideConvexGeneral(floor.shape(), floor.shape(), 0.1);
    ASSERT_EQ(general.count, 1);
    EXPECT_NEAR(std::abs(general.normal.y()), 1, kEllipseAccuracy);
    EXPECT_NEAR(general.points[0].separation, -1, kEllipseAccuracy);
    // An ellipse on itself: A − A is the same ellipse doubled, so the least penetration is across
    // the minor axis, 2b = 1 m, along ±y.
    const EllipseShape e = ellipse(Vec2(1, 1), 1, 0.5, 0);
    const Manifold same = collide(e, e, 0.1);
    ASSERT_EQ(same.count, 1);
    EXPECT_TRUE(allFinite(same));
    EXPECT_NEAR(std::abs(same.normal.y()), 1, kEllipseAccuracy);
    EXPECT_NEAR(same.points[0].separation, -1, kEllipseAccuracy);
}

TEST(DegenerateInput, segmentsPointsAndZeroRadiiStayFinite)
{
    const Polygon floor = floorBox();
    const std::vector<Vec2> segmentVertices{Vec2(-0.5, -0.1), Vec2(0.5, -0.1)};
    const PolygonShape segment{segmentVertices, {}, Vec2(0, -0.1)};
    const PolygonShape empty{};
    const Manifold m = collide(floor.shape(), segment, 0.1);
    ASSERT_EQ(m.count, 1);
    EXPECT_TRUE(allFinite(m));
    EXPECT_NEAR(m.points[0].separation, -0.1, kEllipseAccuracy);
    EXPECT_EQ(collide(floor.shape(), empty, 0.1).count, 0);
    EXPECT_TRUE(allFinite(collide(floor.shape(), CircleShape{Vec2(0, 0), 0}, 0.1)));
    EXPECT_TRUE(allFinite(collide(floor.shape(), ellipse(Vec2(0, -0.5), 0, 0, 0), 0.1)));
    EXPECT_TRUE(allFinite(collide(ellipse(Vec2(0, 0), 0, 0, 0), ellipse(Vec2(0, 0), 0, 0, 0), 0.1)));
    EXPECT_TRUE(allFinite(collide(CircleShape{Vec2(0, 0), 0}, ellipse(Vec2(0, 0), 1, 0, 0), 0.1)));
}

} // namespace
} // namespace impetus::controller
