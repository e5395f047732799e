// The narrow phase's trace (collision_trace.h): table cases worked by hand, each checking that the
// recorded axes carry the narrow phase's numbers and that tracing changes nothing it returns.

#include "controller/collision/collision_trace.h"
#include "controller/collision/narrow_phase.h"
#include "controller/collision/pair_trace.h"

#include "support/polygon_shapes.h"
#include "support/world_builders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace impetus::controller {
namespace {

constexpr Scalar kExact = 1e-12; ///< m: hand-worked results, up to rounding

using testing::makePolygon;
using testing::Polygon;

/// [x0, x1]×[y0, y1], counter-clockwise from the lower left: faces bottom, right, top, left.
Polygon makeBox(Scalar x0, Scalar y0, Scalar x1, Scalar y1)
{
    return makePolygon({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
}

/// The unit square turned 45°, centred at `centre`: corners below, right, above, left.
Polygon makeDiamond(Vec2 centre)
{
    const Scalar h = std::sqrt(0.5);
    return makePolygon({centre + Vec2(0, -h), centre + Vec2(h, 0), centre + Vec2(0, h), centre + Vec2(-h, 0)});
}

/// One table row: a pair, what the trace must say, and the manifold.
struct TraceCase {
    std::string name;
    ConvexShape a;
    ConvexShape b;
    TraceMethod method = TraceMethod::Sat;
    std::size_t axesTested = 0; ///< how many axes the narrow phase looked at before it stopped
    std::optional<std::size_t> separatingAxis;
    std::optional<std::size_t> contactAxis;
    int contactOwner = 0; ///< owner of the contact axis
    std::size_t contactFace = 0; ///< its face (or vertex) index
    Scalar contactSeparation = 0; ///< m: its separation (− the overlap, the MTV's length)
    Vec2 normal = Vec2::Zero(); ///< of the manifold, A to B
    std::vector<Vec2> points; ///< the manifold's points
    std::vector<Vec2> clipped; ///< SAT: the clipped incident points
};

// Shapes the rows share (the spans in the rows point into them).
const Polygon kBoxA = makeBox(0, 0, 2, 1);
const Polygon kBoxB = makeBox(1.5, 0.2, 3.5, 1.2);
const Polygon kGround = makeBox(-1, -1, 1, 0);
const Polygon kDiamond = makeDiamond(Vec2(0, std::sqrt(0.5) - 0.1));
const Polygon kLeft = makeBox(0, 0, 1, 1);
const Polygon kRight = makeBox(1.2, 0, 2.2, 1);

std::vector<TraceCase> traceCases()
{
    std::vector<TraceCase> rows;
    {
        // A's right face (x = 2) meets B's left face (x = 1.5): overlap 0.5 along x, 0.8 along y.
        // A's best face (right, −0.5) ties B's (left, −0.5); the tie keeps A's. The incident face
        // is B's left one, (1.5, 1.2)→(1.5, 0.2), clipped to A's right face's span y ∈ [0, 1]:
        // the kept end (1.5, 0.2), then the crossing (1.5, 1), each put halfway back to x = 2.
        TraceCase row;
        row.name = "box_box_overlap_x";
        std::tie(row.a, row.b) = std::pair<ConvexShape, ConvexShape>(kBoxA.shape(), kBoxB.shape());
        row.axesTested = 8;
        row.contactAxis = 1;
        row.contactOwner = 0;
        row.contactFace = 1;
        row.contactSeparation = -0.5;
        row.normal = Vec2(1, 0);
        row.points = {Vec2(1.75, 0.2), Vec2(1.75, 1.0)};
        row.clipped = {Vec2(1.5, 0.2), Vec2(1.5, 1.0)};
        rows.push_back(row);
    }
    {
        // A diamond whose lowest corner is 0.1 below the ground's top face: that face is the
        // axis of least overlap (0.1); the point is the corner put halfway back, (0, −0.05).
        TraceCase row;
        row.name = "rotated_corner_into_face";
        std::tie(row.a, row.b) = std::pair<ConvexShape, ConvexShape>(kGround.shape(), kDiamond.shape());
        row.axesTested = 8;
        row.contactAxis = 2;
        row.contactOwner = 0;
        row.contactFace = 2;
        row.contactSeparation = -0.1;
        row.normal = Vec2(0, 1);
        row.points = {Vec2(0, -0.05)};
        // The incident face runs from that corner to the right one, (√½, √½ − 0.1): both lie within
        // the ground's face, so both survive clipping; the right one is too far up to touch.
        row.clipped = {Vec2(0, -0.1), Vec2(std::sqrt(0.5), std::sqrt(0.5) - 0.1)};
        rows.push_back(row);
    }
    {
        // A gap of 0.2 along x: A's bottom face does not separate (−1), its right face does
        // (0.2), and the search stops there.
        TraceCase row;
        row.name = "separated_boxes";
        std::tie(row.a, row.b) = std::pair<ConvexShape, ConvexShape>(kLeft.shape(), kRight.shape());
        row.axesTested = 2;
        row.separatingAxis = 1;
        row.contactOwner = 0;
        row.contactFace = 1;
        row.contactSeparation = 0.2;
        rows.push_back(row);
    }
    {
        // A circle of radius 0.5 whose centre is 0.4 above the ground's top face: face region,
        // overlap 0.1; surface points (0.3, 0) and (0.3, −0.1).
        TraceCase row;
        row.name = "circle_box_face";
        std::tie(row.a, row.b) = std::pair<ConvexShape, ConvexShape>(kGround.shape(), CircleShape{Vec2(0.3, 0.4), 0.5});
        row.method = TraceMethod::PolygonCircle;
        row.axesTested = 4;
        row.contactAxis = 2;
        row.contactOwner = 0;
        row.contactFace = 2;
        row.contactSeparation = -0.1;
        row.normal = Vec2(0, 1);
        row.points = {Vec2(0.3, -0.05)};
        rows.push_back(row);
    }
    {
        // The centre (1.3, 0.4) lies beyond the corner (1, 0): the closest-feature axis runs from
        // the corner to the centre, (0.3, 0.4)/0.5, and the overlap is 0.6 − 0.5 = 0.1.
        TraceCase row;
        row.name = "circle_box_corner";
        std::tie(row.a, row.b) = std::pair<ConvexShape, ConvexShape>(kGround.shape(), CircleShape{Vec2(1.3, 0.4), 0.6});
        row.method = TraceMethod::PolygonCircle;
        row.axesTested = 5;
        row.contactAxis = 4;
        row.contactOwner = 0;
        row.contactFace = 2;
        row.contactSeparation = -0.1;
        row.normal = Vec2(0.6, 0.8);
        // The circle's surface reaches 0.1 past the corner: the point is halfway, 0.05 past it.
        row.points = {Vec2(1, 0) - 0.05 * Vec2(0.6, 0.8)};
        rows.push_back(row);
    }
    {
        // The circle first: the trace's axes belong to B, the box, and the normal points from the
        // circle to the box.
        TraceCase row;
        row.name = "circle_then_box";
        std::tie(row.a, row.b) = std::pair<ConvexShape, ConvexShape>(CircleShape{Vec2(0.3, 0.4), 0.5}, kGround.shape());
        row.method = TraceMethod::PolygonCircle;
        row.axesTested = 4;
        row.contactAxis = 2;
        row.contactOwner = 1;
        row.contactFace = 2;
        row.contactSeparation = -0.1;
        row.normal = Vec2(0, -1);
        row.points = {Vec2(0.3, -0.05)};
        rows.push_back(row);
    }
    return rows;
}

class CollisionTraceTest : public ::testing::TestWithParam<TraceCase> {};

TEST_P(CollisionTraceTest, RecordsTheNarrowPhasesOwnNumbers)
{
    const TraceCase& row = GetParam();
    CollisionTrace trace;
    const Manifold traced = collide(row.a, row.b, 0.0, &trace);
    const Manifold plain = collide(row.a, row.b, 0.0);

    // Tracing changes nothing the narrow phase returns, to the bit.
    ASSERT_EQ(traced.count, plain.count);
    EXPECT_EQ(traced.normal, plain.normal);
    for (int i = 0; i < plain.count; ++i) {
        EXPECT_EQ(traced.points[static_cast<std::size_t>(i)].point, plain.points[static_cast<std::size_t>(i)].point);
        EXPECT_EQ(traced.points[static_cast<std::size_t>(i)].separation,
                  plain.points[static_cast<std::size_t>(i)].separation);
    }
    EXPECT_EQ(trace.result.count, plain.count);

    EXPECT_EQ(trace.method, row.method);
    ASSERT_EQ(trace.axes.size(), row.axesTested);
    EXPECT_EQ(trace.separatingAxis, row.separatingAxis);
    const std::size_t decisive = row.separatingAxis ? *row.separatingAxis : *row.contactAxis;
    if (row.contactAxis) {
        EXPECT_EQ(trace.contactAxis, row.contactAxis);
    }
    const TracedAxis& axis = trace.axes[decisive];
    EXPECT_EQ(axis.owner, row.contactOwner);
    if (axis.kind == AxisKind::Face) {
        EXPECT_EQ(axis.face, row.contactFace);
    }
    EXPECT_NEAR(axis.separation, row.contactSeparation, kExact);
    // Each axis's separation is the gap between the two projections the trace gives for it.
    for (const TracedAxis& a : trace.axes)
        EXPECT_NEAR(a.separation, a.otherMin - a.ownerMax, kExact) << "axis " << a.face;
    // No axis of the pair separates it by more than the decisive one shows.
    if (!row.separatingAxis) {
        for (const TracedAxis& a : trace.axes)
            EXPECT_LE(a.separation, 0.0);
        EXPECT_NEAR((traced.normal - row.normal).norm(), 0.0, kExact);
    }
    ASSERT_EQ(static_cast<std::size_t>(traced.count), row.points.size());
    for (std::size_t i = 0; i < row.points.size(); ++i) {
        EXPECT_NEAR((traced.points[i].point - row.points[i]).norm(), 0.0, kExact) << "point " << i;
        EXPECT_NEAR(traced.points[i].separation, row.contactSeparation, kExact) << "point " << i;
    }
    ASSERT_EQ(trace.clipped.size(), row.clipped.size());
    for (std::size_t i = 0; i < row.clipped.size(); ++i)
        EXPECT_NEAR((trace.clipped[i] - row.clipped[i]).norm(), 0.0, kExact) << "clipped " << i;
}

INSTANTIATE_TEST_SUITE_P(HandWorked, CollisionTraceTest, ::testing::ValuesIn(traceCases()),
                         [](const ::testing::TestParamInfo<TraceCase>& row) { return row.param.name; });

TEST(CollisionTrace, CirclesTraceTheCentreLine)
{
    // Centres 1.5 apart along (0.6, 0.8), radii 1 and 0.7: overlap 0.2.
    CollisionTrace trace;
    const Manifold m = collide(CircleShape{Vec2(0, 0), 1.0}, CircleShape{Vec2(0.9, 1.2), 0.7}, 0.0, &trace);
    EXPECT_EQ(trace.method, TraceMethod::Circles);
    ASSERT_EQ(trace.axes.size(), 1U);
    EXPECT_EQ(trace.axes[0].kind, AxisKind::CentreLine);
    EXPECT_NEAR(trace.axes[0].separation, -0.2, kExact);
    EXPECT_NEAR(trace.axes[0].otherMin - trace.axes[0].ownerMax, -0.2, kExact);
    ASSERT_EQ(m.count, 1);
    EXPECT_NEAR(m.points[0].separation, -0.2, kExact);
}

TEST(CollisionTrace, EllipsesSayTheyUseGjk)
{
    CollisionTrace trace;
    const Manifold m = collide(EllipseShape{Vec2(0, 0), 1.0, 0.5}, CircleShape{Vec2(0, 0.9), 0.5}, 0.0, &trace);
    EXPECT_EQ(trace.method, TraceMethod::Gjk);
    EXPECT_TRUE(trace.axes.empty());
    ASSERT_EQ(m.count, 1);
    EXPECT_EQ(trace.result.count, 1);
    EXPECT_NEAR(m.points[0].separation, -0.1, 1e-6); // the accuracy narrow_phase.h promises for ellipses
}

TEST(CollisionTrace, BodyPairTracesEveryPairOfConvexPieces)
{
    // An L of two convex pieces resting its foot on a ground box: two piece pairs, each traced.
    model::World world = testing::makeEmptyWorld(model::IntegratorKind::SemiImplicitEuler, 1.0 / 240);
    world.bodies.push_back(testing::makeGround("ground", 10, 1));
    model::Body ell;
    ell.name = "ell";
    ell.shape = model::Polygon{{Vec2(0, 0), Vec2(2, 0), Vec2(2, 0.5), Vec2(0.5, 0.5), Vec2(0.5, 2), Vec2(0, 2)}};
    ell.massSpec = {model::MassMode::Mass, 1.0};
    ell.updateDerived();
    // The L's foot (user y = 0) 0.1 below the ground's top face: the body frame is centred on
    // the centroid, so the position is where the user frame's origin lands, less the offset.
    ell.state.position = Vec2(0, -0.1) + ell.geometry.centroidOffset;
    world.bodies.push_back(ell);
    ASSERT_GE(world.bodies[1].geometry.convexPieces.size(), 2U);

    const std::vector<PiecePairTrace> pairs = traceBodyPair(world, model::BodyId{1}, model::BodyId{0});
    ASSERT_EQ(pairs.size(), world.bodies[1].geometry.convexPieces.size());
    bool someContact = false;
    for (const PiecePairTrace& pair : pairs) {
        EXPECT_EQ(pair.a.body, 0U); // the lower index is A, as in the step
        EXPECT_EQ(pair.b.body, 1U);
        EXPECT_EQ(pair.trace.method, TraceMethod::Sat);
        if (pair.trace.result.count > 0) {
            someContact = true;
            EXPECT_NEAR(pair.trace.result.points[0].separation, -0.1, kExact);
        }
    }
    EXPECT_TRUE(someContact);
    EXPECT_TRUE(traceBodyPair(world, model::BodyId{1}, model::BodyId{1}).empty());
    EXPECT_TRUE(traceBodyPair(world, model::BodyId{1}, model::BodyId{7}).empty());
}

} // namespace
} // namespace impetus::controller
