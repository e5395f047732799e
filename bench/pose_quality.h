#pragma once
/// \file pose_quality.h
/// How good a set of final poses is, measured the same way whichever engine produced them: the
/// deepest overlap between any two bodies, found with a broad phase and a separating-axis test
/// written for the benchmark alone (so no engine grades its own work), and how far the joints
/// have come apart.

#include "peer_engines.h"

#include "model/world.h"

#include <cstdint>
#include <span>

namespace impetus::bench {

/// The deepest overlap between two bodies.
struct Overlap {
    Scalar depth = 0; ///< m, 0 when no two bodies overlap
    std::uint32_t bodyA = 0; ///< indices into World::bodies (meaningful when depth > 0)
    std::uint32_t bodyB = 0;
};

/// The deepest overlap of any two bodies of `world` placed at `poses` (one per body), pairs of
/// fixed bodies excepted. The depth of an overlap is the smallest distance that would separate
/// the two shapes (their penetration depth): for convex polygons the least overlap of their
/// projections onto any edge normal of either (the separating axis theorem, exact for convex
/// shapes); for a circle and a polygon the same over the polygon's edge normals and the axis from
/// its nearest vertex to the centre; for two circles r₁ + r₂ − |c₁ − c₂|. A body of several convex
/// pieces overlaps as deep as its deepest piece. Circles, boxes and polygons only.
Overlap deepestOverlap(const model::World& world, std::span<const Pose> poses);

/// How far the joints of `world` are from holding at `poses` (one per body), m: the largest,
/// over every joint, of the distance between a pin's two anchor points, or of how much a rod's
/// anchors are further apart or closer than its length. 0 for a world without joints.
Scalar worstJointError(const model::World& world, std::span<const Pose> poses);

} // namespace impetus::bench
