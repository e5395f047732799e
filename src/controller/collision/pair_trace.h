#pragma once
/// \file pair_trace.h
/// The narrow phase's recorded work on every pair of convex pieces of two bodies, as the
/// Separating Axes explainer shows it (docs/explainers.md).

#include "controller/collision/colliders.h"
#include "controller/collision/collision_trace.h"
#include "model/body.h"
#include "model/scalar.h"
#include "model/world.h"

#include <cstdint>
#include <vector>

namespace impetus::controller {

/// One convex piece of a body, placed in the world, as the narrow phase saw it.
struct TracedPiece {
    ColliderPiece::Kind kind = ColliderPiece::Kind::Polygon;
    std::uint32_t body = 0; ///< index into World::bodies
    std::uint32_t piece = 0; ///< the body's convex piece (ColliderPiece::piece)
    std::vector<Vec2> vertices; ///< polygon: counter-clockwise, world frame, m
    Vec2 center = Vec2::Zero(); ///< polygon centroid, or circle / ellipse centre, m
    Scalar radiusX = 0; ///< circle radius, or ellipse semi-axis along its x, m
    Scalar radiusY = 0; ///< ellipse semi-axis along its y, m
    Scalar c = 1; ///< ellipse: cos(angle)
    Scalar s = 0; ///< ellipse: sin(angle)
};

/// The narrow phase's trace of one pair of pieces: A belongs to the body of lower index, as in
/// the step, so the normal points from it to the other.
struct PiecePairTrace {
    TracedPiece a;
    TracedPiece b;
    CollisionTrace trace;
};

/// Runs the real narrow phase (narrow_phase.h, with a trace) on every pair of convex pieces of the
/// bodies `first` and `second` at their present states, with no speculative distance: "separated"
/// then means a gap. A concave polygon gives one pair per pair of its convex pieces. In the order
/// of A's pieces, then B's. Empty when either body does not exist or both are the same body.
std::vector<PiecePairTrace> traceBodyPair(const model::World& world, model::BodyId first, model::BodyId second);

} // namespace impetus::controller
