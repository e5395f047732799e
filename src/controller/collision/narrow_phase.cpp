// The narrow-phase dispatcher: each pair of shape kinds goes to the algorithm that is exact and
// cheapest for it. The algorithms live in sat_collision.cpp, circle_collision.cpp and gjk_epa.cpp.

#include "controller/collision/narrow_phase.h"

#include "controller/collision/collision_trace.h"

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

Manifold collide(const ConvexShape& a, const ConvexShape& b, Scalar speculativeDistance, CollisionTrace* trace)
{
    // Ellipses have no closed form against anything, so any pair holding one goes to GJK/EPA
    // before the polygon and circle cases are considered.
    if (std::holds_alternative<EllipseShape>(a) || std::holds_alternative<EllipseShape>(b)) {
        const Manifold m = collideConvexGeneral(a, b, speculativeDistance);
        if (trace != nullptr) {
            trace->method = TraceMethod::Gjk;
            trace->speculativeDistance = speculativeDistance;
            trace->result = m;
        }
        return m;
    }

    if (const auto* polygonA = std::get_if<PolygonShape>(&a)) {
        if (const auto* polygonB = std::get_if<PolygonShape>(&b))
            return collidePolygons(*polygonA, *polygonB, speculativeDistance, trace);
        return collidePolygonCircle(*polygonA, std::get<CircleShape>(b), speculativeDistance, trace);
    }
    const CircleShape& circleA = std::get<CircleShape>(a);
    if (const auto* polygonB = std::get_if<PolygonShape>(&b)) {
        const Manifold m = flipped(collidePolygonCircle(*polygonB, circleA, speculativeDistance, trace));
        if (trace != nullptr) {
            // The trace was taken with the polygon as A: hand each axis back to its real owner.
            for (TracedAxis& axis : trace->axes)
                axis.owner = 1 - axis.owner;
            trace->result = m;
        }
        return m;
    }
    return collideCircles(circleA, std::get<CircleShape>(b), speculativeDistance, trace);
}

Manifold discardNonFinite(const Manifold& m)
{
    return manifoldIsFinite(m) ? m : Manifold{};
}

} // namespace impetus::controller
