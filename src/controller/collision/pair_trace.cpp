// Places both bodies' pieces exactly as the step does (ColliderSet) and hands each pair of pieces
// to the narrow phase with a trace, so the explainer's numbers are the narrow phase's own.

#include "controller/collision/pair_trace.h"

#include "controller/collision/narrow_phase.h"

#include <algorithm>
#include <variant>

namespace impetus::controller {

namespace {

TracedPiece tracedPiece(const ColliderSet& colliders, std::uint32_t index)
{
    const ColliderPiece& p = colliders.pieces()[index];
    TracedPiece piece;
    piece.kind = p.kind;
    piece.body = p.body;
    piece.piece = p.piece;
    piece.center = p.center;
    piece.radiusX = p.radiusX;
    piece.radiusY = p.radiusY;
    piece.c = p.c;
    piece.s = p.s;
    if (p.kind == ColliderPiece::Kind::Polygon) {
        const PolygonShape shape = colliders.polygon(index);
        piece.vertices.assign(shape.vertices.begin(), shape.vertices.end());
    }
    return piece;
}

} // namespace

std::vector<PiecePairTrace> traceBodyPair(const model::World& world, model::BodyId first, model::BodyId second)
{
    std::vector<PiecePairTrace> traces;
    if (first == second || first.index >= world.bodies.size() || second.index >= world.bodies.size())
        return traces;
    const std::uint32_t bodyA = std::min(first.index, second.index);
    const std::uint32_t bodyB = std::max(first.index, second.index);
    ColliderSet colliders;
    // No margins: the explainer asks about the shapes as they are, not as they may move.
    colliders.build(world, std::vector<Scalar>(world.bodies.size(), 0.0));
    const std::vector<ColliderPiece>& pieces = colliders.pieces();
    for (std::uint32_t i = 0; i < pieces.size(); ++i) {
        if (pieces[i].body != bodyA)
            continue;
        for (std::uint32_t j = 0; j < pieces.size(); ++j) {
            if (pieces[j].body != bodyB)
                continue;
            PiecePairTrace pair{tracedPiece(colliders, i), tracedPiece(colliders, j), {}};
            collide(colliders.shape(i), colliders.shape(j), 0.0, &pair.trace);
            traces.push_back(std::move(pair));
        }
    }
    return traces;
}

} // namespace impetus::controller
