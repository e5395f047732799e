#pragma once
/// \file spring.h
/// A Hooke spring between two bodies, or between a body and a fixed world point.

#include "model/body.h"
#include "model/scalar.h"

#include <optional>

namespace impetus::model {

/// A linear spring with damping along its length: F = −k·(L − L₀) − c·dL/dt, acting along the
/// line between the anchors, on both ends, equal and opposite.
struct Spring {
    BodyId bodyA; ///< the first body
    Vec2 anchorA = Vec2::Zero(); ///< m, in body A's frame (origin at its centre of mass)
    std::optional<BodyId> bodyB; ///< nullopt: anchorB is a fixed world point
    Vec2 anchorB = Vec2::Zero(); ///< m, in body B's frame, or a world point when bodyB is nullopt
    Scalar stiffness = 100; ///< k, N/m, ≥ 0
    Scalar damping = 0; ///< c, N·s/m, ≥ 0
    Scalar restLength = 0; ///< L₀, m, ≥ 0 (the scene loader defaults it to the load-time length)
    bool operator==(const Spring&) const = default; ///< memberwise equality
};

} // namespace impetus::model
