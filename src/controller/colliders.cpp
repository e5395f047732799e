#include "controller/colliders.h"

#include "controller/transform.h"

#include <algorithm>
#include <cmath>
#include <span>

namespace impetus::controller {

namespace {

Aabb enlarged(Aabb box, Scalar margin)
{
    box.lower.array() -= margin;
    box.upper.array() += margin;
    return box;
}

} // namespace

void ColliderSet::build(const model::World& world, const std::vector<Scalar>& margins)
{
    m_pieces.clear();
    m_boxes.clear();
    m_vertices.clear();
    m_normals.clear();

    for (std::uint32_t b = 0; b < world.bodies.size(); ++b) {
        const model::Body& body = world.bodies[b];
        const Transform xf = Transform::of(body.state);
        const Scalar margin = margins[b];

        if (const auto* circle = std::get_if<model::Circle>(&body.shape)) {
            ColliderPiece piece;
            piece.kind = ColliderPiece::Kind::Circle;
            piece.body = b;
            piece.center = xf.position;
            piece.radiusX = circle->radius;
            m_pieces.push_back(piece);
            const Vec2 r = Vec2::Constant(circle->radius);
            m_boxes.push_back(enlarged(Aabb{Vec2(piece.center - r), Vec2(piece.center + r)}, margin));
            continue;
        }
        if (const auto* ellipse = std::get_if<model::Ellipse>(&body.shape)) {
            ColliderPiece piece;
            piece.kind = ColliderPiece::Kind::Ellipse;
            piece.body = b;
            piece.center = xf.position;
            piece.radiusX = ellipse->radiusX;
            piece.radiusY = ellipse->radiusY;
            piece.c = xf.c;
            piece.s = xf.s;
            m_pieces.push_back(piece);
            // Half-extents of a rotated ellipse: √(a²c² + b²s²) along x and √(a²s² + b²c²) along y.
            const Scalar a2 = ellipse->radiusX * ellipse->radiusX;
            const Scalar b2 = ellipse->radiusY * ellipse->radiusY;
            const Vec2 half(std::sqrt(a2 * xf.c * xf.c + b2 * xf.s * xf.s),
                            std::sqrt(a2 * xf.s * xf.s + b2 * xf.c * xf.c));
            m_boxes.push_back(enlarged(Aabb{Vec2(piece.center - half), Vec2(piece.center + half)}, margin));
            continue;
        }

        const auto& pieces = body.geometry.convexPieces;
        for (std::uint32_t k = 0; k < pieces.size(); ++k) {
            ColliderPiece piece;
            piece.kind = ColliderPiece::Kind::Polygon;
            piece.body = b;
            piece.piece = k;
            piece.firstVertex = static_cast<std::uint32_t>(m_vertices.size());
            piece.vertexCount = static_cast<std::uint32_t>(pieces[k].size());
            Aabb box{Vec2::Constant(INFINITY), Vec2::Constant(-INFINITY)};
            Vec2 sum = Vec2::Zero();
            for (std::size_t i = 0; i < pieces[k].size(); ++i) {
                const Vec2 v = xf.apply(pieces[k][i]);
                m_vertices.push_back(v);
                m_normals.push_back(xf.rotate(body.geometry.pieceNormals[k][i]));
                box.lower = box.lower.cwiseMin(v);
                box.upper = box.upper.cwiseMax(v);
                sum += v;
            }
            // The vertex mean is inside a convex piece, which is all the narrow phase asks of it.
            piece.center = sum / static_cast<Scalar>(pieces[k].size());
            m_pieces.push_back(piece);
            m_boxes.push_back(enlarged(box, margin));
        }
    }
}

ConvexShape ColliderSet::shape(std::uint32_t i) const
{
    const ColliderPiece& piece = m_pieces[i];
    switch (piece.kind) {
    case ColliderPiece::Kind::Circle:
        return CircleShape{piece.center, piece.radiusX};
    case ColliderPiece::Kind::Ellipse:
        return EllipseShape{piece.center, piece.radiusX, piece.radiusY, piece.c, piece.s};
    case ColliderPiece::Kind::Polygon:
        break;
    }
    return PolygonShape{std::span<const Vec2>(m_vertices).subspan(piece.firstVertex, piece.vertexCount),
                        std::span<const Vec2>(m_normals).subspan(piece.firstVertex, piece.vertexCount),
                        piece.center};
}

} // namespace impetus::controller
