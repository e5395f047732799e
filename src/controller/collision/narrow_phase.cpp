// The narrow-phase dispatcher: each pair of shape kinds goes to the algorithm that is exact and
// cheapest for it. The algorithms live in sat_collision.cpp, circle_collision.cpp and gjk_epa.cpp.

#include "controller/collision/narrow_phase.h"

#include <cmath>

namespace impetus::controller {

namespace {

/// The manifold of (B, A) turned into the manifold of (A, B). Contact points lie midway between
/// the surfaces and separations are symmetric, so only the normal changes sign; the feature ids
/// still name the same features, which is all the solver compares.
Manifold flipped(Manifold m)
{
    m.normal = -m.normal;
    return m;
}

} // namespace

Manifold collide(const ConvexShape& a, const ConvexShape& b, Scalar speculativeDistance)
{
    // Ellipses have no closed form against anything, so any pair holding one goes to GJK/EPA
    // before the polygon and circle cases are considered.
    if (std::holds_alternative<EllipseShape>(a) || std::holds_alternative<EllipseShape>(b))
        return collideConvexGeneral(a, b, speculativeDistance);

    if (const auto* polygonA = std::get_if<PolygonShape>(&a)) {
        if (const auto* polygonB = std::get_if<PolygonShape>(&b))
            return collidePolygons(*polygonA, *polygonB, speculativeDistance);
        return collidePolygonCircle(*polygonA, std::get<CircleShape>(b), speculativeDistance);
    }
    const CircleShape& circleA = std::get<CircleShape>(a);
    if (const auto* polygonB = std::get_if<PolygonShape>(&b))
        return flipped(collidePolygonCircle(*polygonB, circleA, speculativeDistance));
    return collideCircles(circleA, std::get<CircleShape>(b), speculativeDistance);
}

Manifold discardNonFinite(const Manifold& m)
{
    return manifoldIsFinite(m) ? m : Manifold{};
}

} // namespace impetus::controller
