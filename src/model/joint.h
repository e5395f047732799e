#pragma once
/// \file joint.h
/// Pin and rod joints, as data. The collisions-and-constraints work (issue 3) solves them.

#include "model/body.h"
#include "model/scalar.h"

#include <optional>

namespace impetus::model {

/// The two joint types of scene format v1.
enum class JointType {
    Pin, ///< a hinge: the bodies share one point and turn freely about it
    Rod, ///< a massless rod: the two anchors keep their load-time distance
};

/// A joint between body A and body B, or between body A and the world (bodyB nullopt).
struct Joint {
    JointType type = JointType::Pin; ///< pin or rod
    BodyId bodyA; ///< the first body
    std::optional<BodyId> bodyB; ///< nullopt: attached to the world
    /// Pin only: the hinge point in world coordinates as the scene gave it, m.
    Vec2 worldAnchor = Vec2::Zero();
    /// Rod: the anchor in body A's frame as the scene gave it. Pin: derived at load, the hinge in
    /// body A's frame. m.
    Vec2 anchorA = Vec2::Zero();
    /// Rod: the anchor in body B's frame (or a world point when bodyB is nullopt), as given.
    /// Pin: derived at load, the hinge in body B's frame (or the world point). m.
    Vec2 anchorB = Vec2::Zero();
    /// Rod only: the distance the rod keeps, derived at load from the anchors, m.
    Scalar length = 0;
    /// Solver state, not part of the scene file: the impulse the joint applied in the last step
    /// (pin: the 2D impulse; rod: x holds the impulse along the rod), N·s. Warm-starts the next.
    Vec2 impulse = Vec2::Zero();
    bool operator==(const Joint&) const = default; ///< memberwise equality
};

} // namespace impetus::model
