#pragma once
/// \file collision_types.h
/// The data that flows from collision detection to the contact solver.

#include "model/scalar.h"

#include <array>
#include <cstdint>

namespace impetus::controller {

/// An axis-aligned bounding box, m.
struct Aabb {
    Vec2 lower = Vec2::Zero(); ///< the corner with the smallest x and y, m
    Vec2 upper = Vec2::Zero(); ///< the corner with the largest x and y, m

    /// True when the boxes overlap or touch.
    bool overlaps(const Aabb& other) const
    {
        return lower.x() <= other.upper.x() && other.lower.x() <= upper.x() && lower.y() <= other.upper.y() &&
               other.lower.y() <= upper.y();
    }

    /// The smallest box that holds both.
    static Aabb merged(const Aabb& a, const Aabb& b)
    {
        return Aabb{a.lower.cwiseMin(b.lower), a.upper.cwiseMax(b.upper)};
    }
};

/// Names the pair of features (vertices, edges) that produced a contact point, so that the same
/// point can be recognised in the next step and warm-started with last step's impulse. Only
/// equality matters; the packing is the narrow phase's business.
using FeatureId = std::uint32_t;

/// One point of contact between two convex shapes.
struct ContactPoint {
    /// World position, m: midway between the two surfaces along the normal.
    Vec2 point = Vec2::Zero();
    /// Signed distance between the surfaces along the normal, m: negative when they overlap,
    /// positive for a speculative point (not yet touching, but close enough to matter this step).
    Scalar separation = 0;
    FeatureId id = 0; ///< the features that made the point, to match it in the next step
};

/// Up to two contact points between convex shapes A and B that share one normal.
struct Manifold {
    /// Unit normal pointing from A to B, world frame.
    Vec2 normal = Vec2::Zero();
    std::array<ContactPoint, 2> points{}; ///< the first `count` are valid
    int count = 0; ///< 0 (no contact), 1 or 2
};

} // namespace impetus::controller
