#pragma once
/// \file colliders.h
/// The world-space collision shapes of every body for one step, in flat arrays.

#include "controller/collision/collision_types.h"
#include "controller/collision/narrow_phase.h"
#include "controller/task_pair.h"
#include "controller/transform.h"
#include "model/scalar.h"
#include "model/world.h"

#include <cstdint>
#include <vector>

namespace impetus::controller {

/// One convex piece of one body, placed in the world.
struct ColliderPiece {
    /// Which narrow-phase routine handles the piece.
    enum class Kind : std::uint8_t { Polygon, Circle, Ellipse };
    Kind kind = Kind::Polygon; ///< the piece's shape
    std::uint32_t body = 0; ///< index into World::bodies (for a soft body's ellipse: its owner)
    /// index into the body's convex pieces (0 for round shapes), or a soft body's ellipse index
    std::uint32_t piece = 0;
    /// index into the world's state list (force_model.h, stateCount): the body, or the ellipse
    std::uint32_t solver = 0;
    std::uint32_t firstVertex = 0; ///< polygon: first vertex in ColliderSet::vertices
    std::uint32_t vertexCount = 0; ///< polygon: number of vertices
    Vec2 center = Vec2::Zero(); ///< polygon centroid, or circle / ellipse centre, m
    Scalar radiusX = 0; ///< circle radius, or ellipse semi-axis along its x, m
    Scalar radiusY = 0; ///< ellipse semi-axis along its y, m
    Scalar c = 1; ///< ellipse: cos(angle)
    Scalar s = 0; ///< ellipse: sin(angle)
};

/// Every body's convex pieces in world coordinates, with bounding boxes enlarged by each body's
/// speculative margin. Rebuilt each step; keeps its buffers.
class ColliderSet {
public:
    /// Places every piece of every body at its current state. `margins[i]` (m) enlarges the boxes
    /// of body i's pieces: how far the body may travel relative to anything in one step. A soft
    /// body's pieces are the ellipses of its grid (circles when its cells are square), turned by
    /// the body's best-fit angle.
    /// With `tasks`, each half of the bodies is placed on its own thread (the same result).
    void build(const model::World& world, const std::vector<Scalar>& margins, TaskPair* tasks = nullptr);

    /// Enlarges the box of each piece of body i by `extra[i]` (m) on every side.
    void enlargeBoxes(const std::vector<Scalar>& extra);

    /// Every piece, by body in index order, then by piece.
    const std::vector<ColliderPiece>& pieces() const { return m_pieces; }
    /// The bounding box of each piece (same index as pieces()), enlarged by its margin, m.
    const std::vector<Aabb>& boxes() const { return m_boxes; }

    /// Piece i as a shape the narrow phase takes.
    ConvexShape shape(std::uint32_t i) const;

    /// Piece i, which must be a polygon (ColliderPiece::Kind::Polygon), as the narrow phase takes it.
    PolygonShape polygon(std::uint32_t i) const
    {
        const ColliderPiece& piece = m_pieces[i];
        return PolygonShape{std::span<const Vec2>(m_vertices).subspan(piece.firstVertex, piece.vertexCount),
                            std::span<const Vec2>(m_normals).subspan(piece.firstVertex, piece.vertexCount),
                            piece.center};
    }

private:
    /// Where the next piece, vertex and soft-grid ellipse state entry go; or, as a count, how many.
    struct Cursor {
        std::uint32_t piece = 0;
        std::uint32_t vertex = 0;
        std::uint32_t ellipse = 0;
    };
    /// The first soft grid whose body is `body` or later.
    static std::size_t firstGridFrom(const model::World& world, std::uint32_t body);
    /// The pieces, vertices and ellipses of bodies [begin, end).
    static Cursor count(const model::World& world, std::uint32_t begin, std::uint32_t end);
    /// Places the pieces of bodies [begin, end) from `at` on.
    void place(const model::World& world, const std::vector<Scalar>& margins, std::uint32_t begin, std::uint32_t end,
               Cursor at);
    /// Places the ellipses of a soft body's grid from `at` on, moving it past them.
    void addSoftGrid(const model::SoftGrid& grid, std::uint32_t body, Cursor& at, const Transform& xf, Scalar margin);

    std::vector<ColliderPiece> m_pieces;
    std::vector<Aabb> m_boxes;
    std::vector<Vec2> m_vertices;
    std::vector<Vec2> m_normals;
};

} // namespace impetus::controller
