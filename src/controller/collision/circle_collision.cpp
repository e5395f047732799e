// Circle–circle and polygon–circle contact in closed form: one point each, exact distances.

#include "controller/collision/narrow_phase.h"

#include "controller/collision/collision_trace.h"

#include <algorithm>
#include <cstddef>
#include <limits>

namespace impetus::controller {

namespace {

/// Set in a polygon–circle feature id when the circle touches a vertex rather than a face.
constexpr FeatureId kVertexFeatureBit = FeatureId{1} << 30;

/// A manifold with one point, midway between the surface point of A and that of B.
Manifold onePoint(const Vec2& normal, const Vec2& surfaceA, const Vec2& surfaceB, FeatureId id)
{
    Manifold m;
    m.normal = normal;
    m.points[0].point = 0.5 * (surfaceA + surfaceB);
    m.points[0].separation = normal.dot(surfaceB - surfaceA);
    m.points[0].id = id;
    m.count = 1;
    return m;
}

/// Records an axis of a polygon–circle or circle–circle test into `trace`: the owner's interval
/// is `owner`'s projection, the circle's is its centre's ± its radius.
void noteAxis(CollisionTrace& trace, AxisKind kind, std::size_t feature, const Vec2& normal, const Vec2& start,
              const Vec2& end, std::span<const Vec2> owner, Scalar ownerMax, const CircleShape& circle,
              Scalar separation)
{
    TracedAxis axis;
    axis.kind = kind;
    axis.owner = 0;
    axis.face = feature;
    axis.normal = normal;
    axis.faceStart = start;
    axis.faceEnd = end;
    axis.separation = separation;
    axis.ownerMin = std::numeric_limits<Scalar>::infinity();
    for (const Vec2& v : owner)
        axis.ownerMin = std::min(axis.ownerMin, normal.dot(v));
    axis.ownerMax = ownerMax;
    axis.otherMin = normal.dot(circle.center) - circle.radius;
    axis.otherMax = normal.dot(circle.center) + circle.radius;
    trace.axes.push_back(axis);
}

Manifold polygonCircle(const PolygonShape& a, const CircleShape& b, Scalar speculativeDistance, CollisionTrace* trace)
{
    const std::size_t n = a.vertices.size();
    if (n < 3 || a.normals.size() != n) { // not a proper polygon: the general algorithm copes
        if (trace != nullptr)
            trace->method = TraceMethod::Gjk;
        return collideConvexGeneral(a, b, speculativeDistance);
    }
    const auto noteFace = [&](std::size_t i, Scalar s) {
        if (trace != nullptr)
            noteAxis(*trace, AxisKind::Face, i, a.normals[i], a.vertices[i], a.vertices[i + 1 == n ? 0 : i + 1],
                     a.vertices, a.normals[i].dot(a.vertices[i]), b, s - b.radius);
    };
    if (trace != nullptr) {
        trace->method = TraceMethod::PolygonCircle;
        trace->candidateCount = n;
    }

    // The face with the largest signed distance to the centre. For a centre outside the polygon the
    // closest boundary point always lies on this face (interior or an end vertex): every other face's
    // line is at most as far, by convexity. For a centre inside it is the face of least penetration.
    std::size_t face = 0;
    Scalar maxSeparation = a.normals[0].dot(b.center - a.vertices[0]);
    noteFace(0, maxSeparation);
    for (std::size_t i = 1; i < n; ++i) {
        const Scalar s = a.normals[i].dot(b.center - a.vertices[i]);
        noteFace(i, s);
        if (s > maxSeparation) {
            maxSeparation = s;
            face = i;
        }
    }
    if (trace != nullptr)
        trace->contactAxis = face;
    // The distance to the polygon is at least the distance to any face line: an early out.
    if (maxSeparation - b.radius > speculativeDistance) {
        if (trace != nullptr)
            trace->separatingAxis = face;
        return {};
    }

    const std::size_t next = face + 1 == n ? 0 : face + 1;
    const Vec2& v1 = a.vertices[face];
    const Vec2& v2 = a.vertices[next];
    if (maxSeparation > 0) {
        // Outside: a vertex region when the centre projects beyond an end of the face.
        const Vec2 edge = v2 - v1;
        std::size_t vertex = n; // n means "face region"
        if ((b.center - v1).dot(edge) <= 0)
            vertex = face;
        else if ((b.center - v2).dot(edge) >= 0)
            vertex = next;
        if (vertex != n) {
            const Vec2& v = a.vertices[vertex];
            const Vec2 d = b.center - v;
            const Scalar distance = d.norm(); // ≥ maxSeparation > 0, so the division is safe
            const Vec2 normal = d / distance;
            if (trace != nullptr) {
                noteAxis(*trace, AxisKind::ClosestVertex, vertex, normal, v, v, a.vertices, normal.dot(v), b,
                         distance - b.radius);
                trace->contactAxis = trace->axes.size() - 1;
            }
            if (distance - b.radius > speculativeDistance) {
                if (trace != nullptr)
                    trace->separatingAxis = trace->contactAxis;
                return {};
            }
            return onePoint(normal, v, b.center - b.radius * normal,
                            kVertexFeatureBit | static_cast<FeatureId>(vertex));
        }
    }
    // Face region, or the centre inside the polygon: the face normal, and the centre's projection
    // onto the face line as the polygon's surface point.
    const Vec2& normal = a.normals[face];
    return onePoint(normal, b.center - maxSeparation * normal, b.center - b.radius * normal,
                    static_cast<FeatureId>(face));
}

} // namespace

Manifold collideCircles(const CircleShape& a, const CircleShape& b, Scalar speculativeDistance, CollisionTrace* trace)
{
    const Vec2 d = b.center - a.center;
    const Scalar distance = d.norm();
    // Coincident centres leave every direction equally good; +y is as arbitrary as any but fixed,
    // so the same scene always gets the same push.
    const Vec2 normal = distance > 0 ? Vec2(d / distance) : Vec2(0, 1);
    const bool apart = distance - a.radius - b.radius > speculativeDistance;
    if (trace != nullptr) {
        trace->method = TraceMethod::Circles;
        trace->speculativeDistance = speculativeDistance;
        trace->candidateCount = 1;
        const Vec2 rim = a.center + a.radius * normal;
        noteAxis(*trace, AxisKind::CentreLine, 0, normal, a.center, rim, std::span<const Vec2>(&a.center, 1),
                 normal.dot(rim), b, distance - a.radius - b.radius);
        trace->axes.back().ownerMin = normal.dot(a.center) - a.radius;
        trace->contactAxis = 0;
        if (apart)
            trace->separatingAxis = 0;
    }
    if (apart)
        return {};
    const Manifold m =
        discardNonFinite(onePoint(normal, a.center + a.radius * normal, b.center - b.radius * normal, 0));
    if (trace != nullptr)
        trace->result = m;
    return m;
}

Manifold collidePolygonCircle(const PolygonShape& a, const CircleShape& b, Scalar speculativeDistance,
                              CollisionTrace* trace)
{
    if (trace != nullptr)
        trace->speculativeDistance = speculativeDistance;
    const Manifold m = discardNonFinite(polygonCircle(a, b, speculativeDistance, trace));
    if (trace != nullptr)
        trace->result = m;
    return m;
}

} // namespace impetus::controller
