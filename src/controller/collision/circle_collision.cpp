// Circle–circle and polygon–circle contact in closed form: one point each, exact distances.

#include "controller/collision/narrow_phase.h"

#include <cstddef>

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

Manifold polygonCircle(const PolygonShape& a, const CircleShape& b, Scalar speculativeDistance)
{
    const std::size_t n = a.vertices.size();
    if (n < 3 || a.normals.size() != n) // not a proper polygon: the general algorithm copes
        return collideConvexGeneral(a, b, speculativeDistance);

    // The face with the largest signed distance to the centre. For a centre outside the polygon the
    // closest boundary point always lies on this face (interior or an end vertex): every other face's
    // line is at most as far, by convexity. For a centre inside it is the face of least penetration.
    std::size_t face = 0;
    Scalar maxSeparation = a.normals[0].dot(b.center - a.vertices[0]);
    for (std::size_t i = 1; i < n; ++i) {
        const Scalar s = a.normals[i].dot(b.center - a.vertices[i]);
        if (s > maxSeparation) {
            maxSeparation = s;
            face = i;
        }
    }
    // The distance to the polygon is at least the distance to any face line: an early out.
    if (maxSeparation - b.radius > speculativeDistance)
        return {};

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
            if (distance - b.radius > speculativeDistance)
                return {};
            const Vec2 normal = d / distance;
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

Manifold collideCircles(const CircleShape& a, const CircleShape& b, Scalar speculativeDistance)
{
    const Vec2 d = b.center - a.center;
    const Scalar distance = d.norm();
    if (distance - a.radius - b.radius > speculativeDistance)
        return {};
    // Coincident centres leave every direction equally good; +y is as arbitrary as any but fixed,
    // so the same scene always gets the same push.
    const Vec2 normal = distance > 0 ? Vec2(d / distance) : Vec2(0, 1);
    return discardNonFinite(onePoint(normal, a.center + a.radius * normal, b.center - b.radius * normal, 0));
}

Manifold collidePolygonCircle(const PolygonShape& a, const CircleShape& b, Scalar speculativeDistance)
{
    return discardNonFinite(polygonCircle(a, b, speculativeDistance));
}

} // namespace impetus::controller
