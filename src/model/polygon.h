#pragma once
/// \file polygon.h
/// Simple-polygon checks and convex decomposition. Vertices may wind either way; every function
/// that returns vertices returns them counter-clockwise.

#include "model/scalar.h"

#include <array>
#include <span>
#include <string>
#include <vector>

namespace impetus::model {

/// Why a vertex list is not a simple polygon. Each kind has its own message.
enum class PolygonIssueKind {
    TooFewVertices, ///< fewer than 3 vertices, or fewer than 3 distinct ones
    NonFiniteVertex, ///< a coordinate is NaN or infinite
    DuplicateVertex, ///< two vertices are the same point
    ZeroArea, ///< all vertices collinear, or the area is negligible for its size
    SelfIntersection, ///< two edges cross, touch or overlap (edge i runs from vertex i to i+1)
};

/// One reason a polygon is refused. `message` reads well after a JSON path and a colon, e.g.
/// "polygon self-intersects (edges 1 and 3)". Vertex and edge numbers are 0-based, like JSON arrays.
struct PolygonIssue {
    PolygonIssueKind kind; ///< which rule the polygon breaks
    std::string message; ///< the reason in words, naming vertices or edges
};

/// Checks that `vertices` form a simple polygon: at least 3 distinct, finite vertices, non-zero
/// area and no self-intersection. Returns every problem found (empty when the polygon is valid).
/// Consecutive collinear vertices (a vertex in the middle of a straight edge) are allowed.
std::vector<PolygonIssue> validatePolygon(std::span<const Vec2> vertices);

/// Signed area, m²: positive when the vertices wind counter-clockwise (shoelace formula).
Scalar signedArea(std::span<const Vec2> vertices);

/// The same polygon, counter-clockwise, with vertices that lie on a straight edge between their
/// neighbours removed. Precondition: validatePolygon(vertices) is empty.
std::vector<Vec2> normalizedCounterClockwise(std::span<const Vec2> vertices);

/// True when the polygon (either winding) has no reflex vertex.
bool isConvex(std::span<const Vec2> vertices);

/// A triangle, counter-clockwise.
using Triangle = std::array<Vec2, 3>;

/// Ear-clipping triangulation of a simple polygon into n−2 counter-clockwise triangles (n counted
/// after normalizedCounterClockwise). Precondition: validatePolygon(vertices) is empty.
std::vector<Triangle> triangulate(std::span<const Vec2> vertices);

/// Convex decomposition by Hertel–Mehlhorn over the ear-clipping triangulation: diagonals are
/// removed while the two pieces they separate stay convex. Gives at most 4× the optimal number of
/// pieces. Each piece is convex and counter-clockwise; the pieces tile the polygon exactly (same
/// area, same centroid). A convex input comes back as one piece. Precondition: valid polygon.
std::vector<std::vector<Vec2>> decomposeConvex(std::span<const Vec2> vertices);

} // namespace impetus::model
