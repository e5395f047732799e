#pragma once
/// \file polygon_shapes.h
/// Convex polygons for the narrow-phase tests, which the collision code only views (PolygonShape).

#include "controller/collision/narrow_phase.h"

#include <cstddef>
#include <utility>
#include <vector>

namespace impetus::testing {

/// A convex polygon that owns its vertices and normals (PolygonShape only views them).
struct Polygon {
    std::vector<Vec2> vertices;
    std::vector<Vec2> normals;
    Vec2 centroid = Vec2::Zero();

    controller::PolygonShape shape() const { return controller::PolygonShape{vertices, normals, centroid}; }
};

/// A polygon from counter-clockwise vertices: outward unit normals and the vertex average.
inline Polygon makePolygon(std::vector<Vec2> vertices)
{
    Polygon p;
    p.vertices = std::move(vertices);
    for (std::size_t i = 0; i < p.vertices.size(); ++i) {
        const Vec2 e = p.vertices[(i + 1) % p.vertices.size()] - p.vertices[i];
        p.normals.push_back(Vec2(e.y(), -e.x()).normalized());
        p.centroid += p.vertices[i] / static_cast<Scalar>(p.vertices.size());
    }
    return p;
}

} // namespace impetus::testing
