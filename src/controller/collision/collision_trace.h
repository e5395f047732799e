#pragma once
/// \file collision_trace.h
/// What the narrow phase did for one pair of convex pieces, axis by axis, recorded by the narrow
/// phase itself when it is handed a trace (docs/explainers.md, "Separating axes"). The normal step
/// passes no trace and records nothing.

#include "controller/collision/collision_types.h"
#include "model/scalar.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace impetus::controller {

/// The algorithm the narrow phase chose for a pair of pieces (narrow_phase.h).
enum class TraceMethod : std::uint8_t {
    None, ///< nothing was recorded
    Sat, ///< two polygons: the Separating Axis Theorem over both polygons' face normals, then clipping
    PolygonCircle, ///< the polygon's face normals, then the closest feature to the centre
    Circles, ///< the line through the two centres
    Gjk, ///< any pair with an ellipse: GJK for the distance, EPA for the penetration; no axes
};

/// What an axis the narrow phase tested is.
enum class AxisKind : std::uint8_t {
    Face, ///< the outward normal of a polygon's face
    ClosestVertex, ///< polygon–circle: from the polygon's closest vertex to the circle's centre
    CentreLine, ///< circle–circle: from A's centre to B's
};

/// One axis as the narrow phase tested it. Projections are dot products with `normal`, m.
struct TracedAxis {
    AxisKind kind = AxisKind::Face;
    int owner = 0; ///< 0: the axis belongs to piece A (a face of A), 1: to piece B
    std::size_t face = 0; ///< Face: the face's index on its owner; ClosestVertex: the vertex's index
    Vec2 normal = Vec2::Zero(); ///< unit; a face's outward normal, pointing away from its owner
    Vec2 faceStart = Vec2::Zero(); ///< Face: the face's first vertex (ClosestVertex: the vertex), m
    Vec2 faceEnd = Vec2::Zero(); ///< Face: the face's second vertex, m
    /// The narrow phase's own number for this axis, m: the gap from the owner's extent to the
    /// other shape's nearest extent, otherMin − ownerMax. Negative: the shapes overlap by −separation
    /// along this axis; positive: the axis separates them.
    Scalar separation = 0;
    Scalar ownerMin = 0; ///< the owner's projection interval [ownerMin, ownerMax], m
    Scalar ownerMax = 0;
    Scalar otherMin = 0; ///< the other shape's projection interval, m
    Scalar otherMax = 0;
};

/// The narrow phase's work on one pair of convex pieces A and B, as it did it.
struct CollisionTrace {
    TraceMethod method = TraceMethod::None;
    /// The axes in the order tested. SAT tests A's faces, then B's, and stops at the first axis
    /// that separates the pieces by more than the speculative distance.
    std::vector<TracedAxis> axes;
    std::size_t candidateCount = 0; ///< axes there were to test (every face normal of both pieces)
    Scalar speculativeDistance = 0; ///< m, as passed to the narrow phase
    /// The axis (index into `axes`) that separates the pieces, when one does: no contact.
    std::optional<std::size_t> separatingAxis;
    /// SAT: the face of A with the largest separation, and the face of B (indices into `axes`).
    std::optional<std::size_t> bestAxisA;
    std::optional<std::size_t> bestAxisB;
    /// The axis whose normal the contact takes: SAT's reference face (the axis of least overlap,
    /// kept on A unless B's is clearly better), or the closest feature's axis.
    std::optional<std::size_t> contactAxis;
    /// SAT: the reference face is B's, so the contact normal is minus its face normal.
    bool flipped = false;
    /// SAT: the incident face (on the other piece than the reference face): its index and ends, m.
    std::size_t incidentFace = 0;
    Vec2 incidentStart = Vec2::Zero();
    Vec2 incidentEnd = Vec2::Zero();
    /// SAT: the incident face's points that survived clipping to the reference face's side planes,
    /// before the points too far apart are dropped, m. Empty for a corner-to-corner pair.
    std::vector<Vec2> clipped;
    /// SAT: the incident face lay wholly beyond an end of the reference face (corner to corner).
    bool cornerToCorner = false;
    /// The manifold the narrow phase returned (normal from A to B).
    Manifold result;
};

} // namespace impetus::controller
