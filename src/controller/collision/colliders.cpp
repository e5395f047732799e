#include "controller/collision/colliders.h"

#include "controller/transform.h"

#include <algorithm>
#include <array>
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

void ColliderSet::addSoftGrid(const model::SoftGrid& grid, std::uint32_t body, Cursor& at, const Transform& xf,
                              Scalar margin)
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
        piece.solver = at.ellipse++;
        piece.center = grid.positions[i];
        piece.radiusX = semi.x();
        piece.radiusY = semi.y();
        piece.c = xf.c;
        piece.s = xf.s;
        m_pieces[at.piece] = piece;
        m_boxes[at.piece] = enlarged(Aabb{Vec2(piece.center - half), Vec2(piece.center + half)}, margin);
        ++at.piece;
    }
}

std::size_t ColliderSet::firstGridFrom(const model::World& world, std::uint32_t body)
{
    // Soft grids come in body order.
    return static_cast<std::size_t>(
        std::partition_point(world.softBodies.begin(), world.softBodies.end(),
                             [&](const model::SoftGrid& grid) { return grid.body.index < body; }) -
        world.softBodies.begin());
}

ColliderSet::Cursor ColliderSet::count(const model::World& world, std::uint32_t begin, std::uint32_t end)
{
    Cursor total;
    std::size_t nextGrid = firstGridFrom(world, begin);
    for (std::uint32_t b = begin; b < end; ++b) {
        const model::Body& body = world.bodies[b];
        if (nextGrid < world.softBodies.size() && world.softBodies[nextGrid].body.index == b) {
            const auto size = static_cast<std::uint32_t>(world.softBodies[nextGrid++].size());
            total.piece += size;
            total.ellipse += size;
        } else if (std::holds_alternative<model::Circle>(body.shape) || std::holds_alternative<model::Ellipse>(body.shape)) {
            ++total.piece;
        } else {
            for (const auto& piece : body.geometry.convexPieces) {
                ++total.piece;
                total.vertex += static_cast<std::uint32_t>(piece.size());
            }
        }
    }
    return total;
}

void ColliderSet::build(const model::World& world, const std::vector<Scalar>& margins, TaskPair* tasks)
{
    // Two passes, so that a large world can place each half of its bodies on its own thread:
    // count each half's pieces and vertices, then write every piece to its place.
    const auto n = static_cast<std::uint32_t>(world.bodies.size());
    const std::uint32_t half = tasks ? n / 2 : n;
    std::array<Cursor, 2> counts{};
    const auto countHalf = [&](int part) {
        counts[static_cast<std::size_t>(part)] = part == 0 ? count(world, 0, half) : count(world, half, n);
    };
    if (tasks) {
        tasks->run(countHalf);
    } else {
        countHalf(0);
        countHalf(1);
    }
    m_pieces.resize(counts[0].piece + counts[1].piece);
    m_boxes.resize(m_pieces.size());
    m_vertices.resize(counts[0].vertex + counts[1].vertex);
    m_normals.resize(m_vertices.size());
    // The ellipses' state entries follow the bodies (force_model.h, stateCount).
    const Cursor first{0, 0, n};
    const Cursor second{counts[0].piece, counts[0].vertex, n + counts[0].ellipse};
    const auto placeHalf = [&](int part) {
        part == 0 ? place(world, margins, 0, half, first) : place(world, margins, half, n, second);
    };
    if (tasks) {
        tasks->run(placeHalf);
    } else {
        placeHalf(0);
        placeHalf(1);
    }
}

void ColliderSet::enlargeBoxes(const std::vector<Scalar>& extra)
{
    for (std::size_t i = 0; i < m_pieces.size(); ++i)
        m_boxes[i] = enlarged(m_boxes[i], extra[m_pieces[i].body]);
}

void ColliderSet::place(const model::World& world, const std::vector<Scalar>& margins, std::uint32_t begin,
                        std::uint32_t end, Cursor at)
{
    std::size_t nextGrid = firstGridFrom(world, begin);
    for (std::uint32_t b = begin; b < end; ++b) {
        const model::Body& body = world.bodies[b];
        const Transform xf = Transform::of(body.state);
        const Scalar margin = margins[b];

        if (nextGrid < world.softBodies.size() && world.softBodies[nextGrid].body.index == b) {
            addSoftGrid(world.softBodies[nextGrid++], b, at, xf, margin);
            continue;
        }

        if (const auto* circle = std::get_if<model::Circle>(&body.shape)) {
            ColliderPiece piece;
            piece.kind = ColliderPiece::Kind::Circle;
            piece.body = b;
            piece.solver = b;
            piece.center = xf.position;
            piece.radiusX = circle->radius;
            const Vec2 r = Vec2::Constant(circle->radius);
            m_pieces[at.piece] = piece;
            m_boxes[at.piece++] = enlarged(Aabb{Vec2(piece.center - r), Vec2(piece.center + r)}, margin);
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
            const Vec2 half = ellipseHalfExtents(ellipse->radiusX, ellipse->radiusY, xf.c, xf.s);
            m_pieces[at.piece] = piece;
            m_boxes[at.piece++] = enlarged(Aabb{Vec2(piece.center - half), Vec2(piece.center + half)}, margin);
            continue;
        }

        const auto& pieces = body.geometry.convexPieces;
        for (std::uint32_t k = 0; k < pieces.size(); ++k) {
            ColliderPiece piece;
            piece.kind = ColliderPiece::Kind::Polygon;
            piece.body = b;
            piece.solver = b;
            piece.piece = k;
            piece.firstVertex = at.vertex;
            piece.vertexCount = static_cast<std::uint32_t>(pieces[k].size());
            Aabb box{Vec2::Constant(INFINITY), Vec2::Constant(-INFINITY)};
            Vec2 sum = Vec2::Zero();
            for (std::size_t i = 0; i < pieces[k].size(); ++i) {
                const Vec2 v = xf.apply(pieces[k][i]);
                m_vertices[at.vertex] = v;
                m_normals[at.vertex++] = xf.rotate(body.geometry.pieceNormals[k][i]);
                box.lower = box.lower.cwiseMin(v);
                box.upper = box.upper.cwiseMax(v);
                sum += v;
            }
            // The vertex mean is inside a convex piece, which is all the narrow phase asks of it.
            piece.center = sum / static_cast<Scalar>(pieces[k].size());
            m_pieces[at.piece] = piece;
            m_boxes[at.piece++] = enlarged(box, margin);
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
