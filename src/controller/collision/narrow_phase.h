#pragma once
/// \file narrow_phase.h
/// Contact manifolds between convex shapes in world coordinates: polygon–polygon by the Separating
/// Axis Theorem with reference-face clipping, circle pairs in closed form, and any pair with an
/// ellipse by GJK (distance when apart) and EPA (penetration when overlapping).

#include "controller/collision/collision_types.h"
#include "model/scalar.h"

#include <span>
#include <variant>

namespace impetus::controller {

struct CollisionTrace;

/// A convex polygon in world coordinates: counter-clockwise vertices and the outward unit normal
/// of each edge (normals[i] belongs to the edge from vertices[i] to vertices[i+1]).
struct PolygonShape {
    std::span<const Vec2> vertices; ///< counter-clockwise, world frame, m
    std::span<const Vec2> normals; ///< outward unit normal of each edge
    Vec2 centroid = Vec2::Zero(); ///< any interior point serves; the centroid is used
};

/// A disc in world coordinates.
struct CircleShape {
    Vec2 center = Vec2::Zero(); ///< m
    Scalar radius = 0; ///< m, > 0
};

/// An ellipse in world coordinates, with semi-axes radiusX and radiusY along its own axes, which
/// are turned counter-clockwise by the angle whose cosine and sine are c and s.
struct EllipseShape {
    Vec2 center = Vec2::Zero(); ///< m
    Scalar radiusX = 0; ///< m, > 0
    Scalar radiusY = 0; ///< m, > 0
    Scalar c = 1; ///< cos(angle)
    Scalar s = 0; ///< sin(angle)
};

/// Any convex shape the narrow phase handles.
using ConvexShape = std::variant<PolygonShape, CircleShape, EllipseShape>;

/// The contact manifold of A and B. Points whose separation exceeds `speculativeDistance` (m, ≥ 0)
/// are left out; a manifold with count 0 means the shapes are farther apart than that. The normal
/// points from A to B. For two polygons there are up to two points, found by clipping the
/// incident face against the reference face (the face of least penetration); everything curved
/// gives one point. Feature ids are stable from step to step while the same features touch.
/// Ellipse results are accurate to 1e-6 m.
/// With `trace` (collision_trace.h), the routine records what it did there, axis by axis: for the
/// explainers only; the step passes none, and then nothing is recorded.
Manifold collide(const ConvexShape& a, const ConvexShape& b, Scalar speculativeDistance,
                 CollisionTrace* trace = nullptr);

/// Polygon–polygon (SAT over both polygons' face normals, then clipping).
Manifold collidePolygons(const PolygonShape& a, const PolygonShape& b, Scalar speculativeDistance,
                         CollisionTrace* trace = nullptr);

/// Polygon–circle.
Manifold collidePolygonCircle(const PolygonShape& a, const CircleShape& b, Scalar speculativeDistance,
                              CollisionTrace* trace = nullptr);

/// Circle–circle.
Manifold collideCircles(const CircleShape& a, const CircleShape& b, Scalar speculativeDistance,
                        CollisionTrace* trace = nullptr);

/// `m`, or no contact when any of its numbers is NaN or infinite: a body flung to infinity must
/// not reach the solver as a NaN impulse; the simulation's own checks notice the bad state.
Manifold discardNonFinite(const Manifold& m);

/// True when every number discardNonFinite looks at is finite: the points' positions and
/// separations, and the normal of a manifold with points.
inline bool manifoldIsFinite(const Manifold& m)
{
    if (m.count == 0)
        return true;
    // x − x is 0 for a finite x and NaN for NaN or ±∞, and a NaN survives the sums: one test
    // instead of a branch per number.
    Scalar probe = (m.normal.x() - m.normal.x()) + (m.normal.y() - m.normal.y());
    for (int i = 0; i < m.count; ++i) {
        const ContactPoint& p = m.points[static_cast<std::size_t>(i)];
        probe += (p.point.x() - p.point.x()) + (p.point.y() - p.point.y()) + (p.separation - p.separation);
    }
    return probe == 0;
}

/// Any pair in which one shape (or both) is an ellipse: GJK + EPA on support functions.
Manifold collideConvexGeneral(const ConvexShape& a, const ConvexShape& b, Scalar speculativeDistance);

} // namespace impetus::controller
