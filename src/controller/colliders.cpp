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

/// Half-extents of an ellipse with semi-axes a, b turned by the angle of cosine c and sine s:
/// √(a²c² + b²s²) along x and √(a²s² + b²c²) along y.
Vec2 ellipseHalfExtents(Scalar a, Scalar b, Scalar c, Scalar s)
{
    return Vec2(std::sqrt(a * a * c * c + b * b * s * s), std::sqrt(a * a * s * s + b * b * c * c));
}

} // namespace

void ColliderSet::addSoftGrid(const model::SoftGrid& grid, std::uint32_t body, std::uint32_t& nextEllipse,
                              const Transform& xf, Scalar margin)
{
    const Vec2 semi = grid.semiAxes();
    // Square cells give circles, which collide in closed form; others true ellipses (GJK/EPA).
    const bool round = semi.x() == semi.y();
    const Vec2 half = round ? Vec2(semi) : ellipseHalfExtents(semi.x(), semi.y(), xf.c, xf.s);
    for (std::uint32_t i = 0; i < grid.size(); ++i) {
        ColliderPiece piece;
        piece.kind = round ? ColliderPiece::Kind::Circle : ColliderPiece::Kind::Ellipse;
        piece.body = body;
        piece.piece = i;
        piece.solver = nextEllipse++;
        piece.center = grid.positions[i];
        piece.radiusX = semi.x();
        piece.radiusY = semi.y();
        piece.c = xf.c;
        piece.s = xf.s;
        m_pieces.push_back(piece);
        m_boxes.push_back(enlarged(Aabb{Vec2(piece.center - half), Vec2(piece.center + half)}, margin));
    }
}

void ColliderSet::build(const model::World& world, const std::vector<Scalar>& margins)
{
    m_pieces.clear();
    m_boxes.clear();
    m_vertices.clear();
    m_normals.clear();

    // Soft grids come in body order, and so do their ellipses in the state list.
    std::size_t nextGrid = 0;
    auto nextEllipse = static_cast<std::uint32_t>(world.bodies.size());
    for (std::uint32_t b = 0; b < world.bodies.size(); ++b) {
        const model::Body& body = world.bodies[b];
        const Transform xf = Transform::of(body.state);
        const Scalar margin = margins[b];

        if (nextGrid < world.softBodies.size() && world.softBodies[nextGrid].body.index == b) {
            addSoftGrid(world.softBodies[nextGrid++], b, nextEllipse, xf, margin);
            continue;
        }

        if (const auto* circle = std::get_if<model::Circle>(&body.shape)) {
            ColliderPiece piece;
            piece.kind = ColliderPiece::Kind::Circle;
            piece.body = b;
            piece.solver = b;
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
            piece.solver = b;
            piece.center = xf.position;
            piece.radiusX = ellipse->radiusX;
            piece.radiusY = ellipse->radiusY;
            piece.c = xf.c;
            piece.s = xf.s;
            m_pieces.push_back(piece);
            const Vec2 half = ellipseHalfExtents(ellipse->radiusX, ellipse->radiusY, xf.c, xf.s);
            m_boxes.push_back(enlarged(Aabb{Vec2(piece.center - half), Vec2(piece.center + half)}, margin));
            continue;
        }

        const auto& pieces = body.geometry.convexPieces;
        for (std::uint32_t k = 0; k < pieces.size(); ++k) {
            ColliderPiece piece;
            piece.kind = ColliderPiece::Kind::Polygon;
            piece.body = b;
            piece.solver = b;
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
    return polygon(i);
}


} // namespace impetus::controller
