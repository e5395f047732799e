// Polygon–polygon contact by the Separating Axis Theorem over both polygons' face normals, then
// reference-face clipping of the incident edge (the idea of Box2D's b2CollidePolygons and Erin
// Catto's GDC talks, written afresh here).
//
// Feature ids. A contact point is either
//   - an incident vertex lying within the reference face: (reference edge i, incident vertex j), or
//   - a clip point, where the incident edge j crosses the side plane through reference vertex k:
//     (reference vertex k, incident edge j).
// Packed as
//   bits  0–14  i (reference edge) or k (reference vertex)
//   bits 15–29  j (incident vertex or incident edge)
//   bit  30     1 for a clip point, 0 for an incident vertex
//   bit  31     1 when the reference face is on B (the roles of A and B are swapped)
// so a box resting on a box keeps both ids from step to step, and a point that slides off the end
// of the reference face (a vertex turning into a clip point) gets a new one.

#include "controller/collision/narrow_phase.h"

#include "controller/collision/collision_trace.h"
#include "model/constants.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>

namespace impetus::controller {

namespace {

constexpr int kIndexBits = 15;
constexpr FeatureId kIndexMask = (FeatureId{1} << kIndexBits) - 1;
constexpr FeatureId kClipPointBit = FeatureId{1} << 30;
constexpr FeatureId kFlipBit = FeatureId{1} << 31;

FeatureId packId(std::size_t referenceFeature, std::size_t incidentFeature, bool clipPoint)
{
    // Indices wrap past 32767 vertices; ids then may collide, which costs warm starting only.
    return (static_cast<FeatureId>(referenceFeature) & kIndexMask) |
           ((static_cast<FeatureId>(incidentFeature) & kIndexMask) << kIndexBits) |
           (clipPoint ? kClipPointBit : FeatureId{0});
}

std::size_t nextIndex(std::size_t i, std::size_t n) { return i + 1 == n ? 0 : i + 1; }

/// The face of `p` whose SAT separation from `q` is largest: max over faces i of
/// min over vertices w of q of nᵢ·(w − vᵢ), m. Ties keep the lower index, for determinism.
struct FaceSeparation {
    std::size_t face = 0;
    Scalar separation = 0;
};

/// Takes face i with SAT separation `deepest` into `best`, in face order. Returns true when it
/// is a separating axis with room to spare: no contact, whatever the other faces give.
bool offerFace(FaceSeparation& best, std::size_t i, Scalar deepest, Scalar speculativeDistance)
{
    if (!(deepest > best.separation))
        return false;
    best = {i, deepest};
    return deepest > speculativeDistance;
}

/// Records face i of `p` (piece `owner`: 0 for A, 1 for B) with the separation the search found
/// for it, and both pieces' projections on its normal. For the explainers only.
void noteFace(CollisionTrace& trace, int owner, const PolygonShape& p, const PolygonShape& q, std::size_t i,
              Scalar separation)
{
    TracedAxis axis;
    axis.owner = owner;
    axis.face = i;
    axis.normal = p.normals[i];
    axis.faceStart = p.vertices[i];
    axis.faceEnd = p.vertices[nextIndex(i, p.vertices.size())];
    axis.separation = separation;
    const auto interval = [&](const PolygonShape& shape, Scalar& low, Scalar& high) {
        low = std::numeric_limits<Scalar>::infinity();
        high = -low;
        for (const Vec2& v : shape.vertices) {
            low = std::min(low, axis.normal.dot(v));
            high = std::max(high, axis.normal.dot(v));
        }
    };
    interval(p, axis.ownerMin, axis.ownerMax);
    interval(q, axis.otherMin, axis.otherMax);
    trace.axes.push_back(axis);
}

/// maxFaceSeparation for a q of `QCount` vertices, or of any number when QCount is 0. A fixed
/// count lets the compiler unroll the loop over q and keep q's vertices, each copied into both
/// lanes once, in registers for all of p's faces (GCC 12 does).
template <std::size_t QCount>
FaceSeparation maxFaceSeparationOf(const PolygonShape& p, const PolygonShape& q, Scalar speculativeDistance,
                                   CollisionTrace* trace, int owner)
{
    // Two faces at a time, one in each lane of a two-element array: each lane does exactly what
    // the scalar nᵢ·(w − vᵢ) and std::min would, vertex by vertex in the same order, so the
    // result has the same bits; the two lanes share the loads of q's vertices.
    using Lanes = Eigen::Array2d;
    FaceSeparation best{0, -std::numeric_limits<Scalar>::infinity()};
    const std::size_t n = p.vertices.size();
    std::size_t i = 0;
    for (; i + 1 < n; i += 2) {
        const Lanes nx(p.normals[i].x(), p.normals[i + 1].x());
        const Lanes ny(p.normals[i].y(), p.normals[i + 1].y());
        const Lanes vx(p.vertices[i].x(), p.vertices[i + 1].x());
        const Lanes vy(p.vertices[i].y(), p.vertices[i + 1].y());
        Lanes deepest = Lanes::Constant(std::numeric_limits<Scalar>::infinity());
        const std::size_t qCount = QCount > 0 ? QCount : q.vertices.size();
        for (std::size_t j = 0; j < qCount; ++j) {
            const Vec2& w = q.vertices[j];
            deepest = deepest.min(nx * (w.x() - vx) + ny * (w.y() - vy));
        }
        // Face i is offered before face i + 1 is looked at, so that a trace ends where the search did.
        if (trace != nullptr)
            noteFace(*trace, owner, p, q, i, deepest[0]);
        if (offerFace(best, i, deepest[0], speculativeDistance))
            return best;
        if (trace != nullptr)
            noteFace(*trace, owner, p, q, i + 1, deepest[1]);
        if (offerFace(best, i + 1, deepest[1], speculativeDistance))
            return best;
    }
    if (i < n) {
        const Vec2& normal = p.normals[i];
        const Vec2& v = p.vertices[i];
        Scalar deepest = std::numeric_limits<Scalar>::infinity();
        for (const Vec2& w : q.vertices)
            deepest = std::min(deepest, normal.x() * (w.x() - v.x()) + normal.y() * (w.y() - v.y()));
        if (trace != nullptr)
            noteFace(*trace, owner, p, q, i, deepest);
        offerFace(best, i, deepest, speculativeDistance);
    }
    return best;
}

FaceSeparation maxFaceSeparation(const PolygonShape& p, const PolygonShape& q, Scalar speculativeDistance,
                                 CollisionTrace* trace, int owner)
{
    // Boxes, the most common polygons, take the unrolled loop.
    return q.vertices.size() == 4 ? maxFaceSeparationOf<4>(p, q, speculativeDistance, trace, owner)
                                  : maxFaceSeparationOf<0>(p, q, speculativeDistance, trace, owner);
}

/// The index in trace.axes of the last axis noted (the one a search ended on, or its best).
std::optional<std::size_t> lastNoted(const CollisionTrace* trace)
{
    return trace != nullptr && !trace->axes.empty() ? std::optional<std::size_t>(trace->axes.size() - 1)
                                                    : std::nullopt;
}

/// The index in trace.axes of `owner`'s face `face`.
std::optional<std::size_t> notedFace(const CollisionTrace& trace, int owner, std::size_t face)
{
    for (std::size_t k = 0; k < trace.axes.size(); ++k) {
        if (trace.axes[k].owner == owner && trace.axes[k].face == face)
            return k;
    }
    return std::nullopt;
}

/// The largest distance from the centroid to a vertex, m: the size that scales the reference-face
/// hysteresis.
Scalar polygonSize(const PolygonShape& p)
{
    Scalar r = 0;
    for (const Vec2& v : p.vertices)
        r = std::max(r, (v - p.centroid).norm());
    return r;
}

struct ClipVertex {
    Vec2 point = Vec2::Zero();
    FeatureId id = 0;
};

/// Keeps the part of segment `in` where normal·x ≤ offset. A crossing point takes `crossingId`.
/// Returns how many points were written to `out` (0 or 2; 1 only for a degenerate segment).
int clipSegment(const std::array<ClipVertex, 2>& in, const Vec2& normal, Scalar offset, FeatureId crossingId,
                std::array<ClipVertex, 2>& out)
{
    const Scalar d0 = normal.dot(in[0].point) - offset;
    const Scalar d1 = normal.dot(in[1].point) - offset;
    int count = 0;
    if (d0 <= 0)
        out[static_cast<std::size_t>(count++)] = in[0];
    if (d1 <= 0)
        out[static_cast<std::size_t>(count++)] = in[1];
    // Exactly one end kept: the segment crosses the plane, and d0 − d1 cannot be zero.
    if ((d0 <= 0) != (d1 <= 0)) {
        const Scalar t = d0 / (d0 - d1);
        out[static_cast<std::size_t>(count++)] = {in[0].point + t * (in[1].point - in[0].point), crossingId};
    }
    return count;
}

Manifold polygons(const PolygonShape& a, const PolygonShape& b, Scalar speculativeDistance, CollisionTrace* trace)
{
    const FaceSeparation faceA = maxFaceSeparation(a, b, speculativeDistance, trace, 0);
    if (faceA.separation > speculativeDistance) {
        if (trace != nullptr)
            trace->separatingAxis = lastNoted(trace);
        return {};
    }
    const FaceSeparation faceB = maxFaceSeparation(b, a, speculativeDistance, trace, 1);
    if (faceB.separation > speculativeDistance) {
        if (trace != nullptr)
            trace->separatingAxis = lastNoted(trace);
        return {};
    }

    // Hysteresis: keep A's face unless B's is clearly better, so resting stacks do not swap
    // reference faces on rounding noise (see kReferenceFaceRelativeTolerance). The tolerance is
    // not negative, so B's face cannot win unless it is better at all: the sizes (square roots)
    // are needed only then.
    const bool flip = faceB.separation > faceA.separation &&
                      faceB.separation > faceA.separation + constants::kReferenceFaceRelativeTolerance *
                                                                std::min(polygonSize(a), polygonSize(b));
    const PolygonShape& ref = flip ? b : a;
    const PolygonShape& inc = flip ? a : b;
    const std::size_t refCount = ref.vertices.size();
    const std::size_t incCount = inc.vertices.size();
    const std::size_t i1 = flip ? faceB.face : faceA.face;
    const std::size_t i2 = nextIndex(i1, refCount);
    const Vec2& normal = ref.normals[i1];
    if (trace != nullptr) {
        trace->bestAxisA = notedFace(*trace, 0, faceA.face);
        trace->bestAxisB = notedFace(*trace, 1, faceB.face);
        trace->contactAxis = flip ? trace->bestAxisB : trace->bestAxisA;
        trace->flipped = flip;
    }

    // The incident edge is the one most anti-parallel to the reference normal: it holds the
    // incident polygon's deepest vertex along −normal, and faces the reference face.
    std::size_t j1 = 0;
    Scalar mostAntiParallel = std::numeric_limits<Scalar>::infinity();
    for (std::size_t j = 0; j < incCount; ++j) {
        const Scalar d = inc.normals[j].dot(normal);
        if (d < mostAntiParallel) {
            mostAntiParallel = d;
            j1 = j;
        }
    }
    const std::size_t j2 = nextIndex(j1, incCount);

    const Vec2& v1 = ref.vertices[i1];
    const Vec2& v2 = ref.vertices[i2];
    // Unit tangent along the reference face (v1 → v2) from the outward normal of a CCW polygon.
    const Vec2 tangent(-normal.y(), normal.x());

    const std::array<ClipVertex, 2> incident{
        ClipVertex{inc.vertices[j1], packId(i1, j1, false)},
        ClipVertex{inc.vertices[j2], packId(i1, j2, false)},
    };
    std::array<ClipVertex, 2> clipped1{};
    std::array<ClipVertex, 2> clipped2{};
    int count = clipSegment(incident, -tangent, -tangent.dot(v1), packId(i1, j1, true), clipped1);
    if (count == 2)
        count = clipSegment(clipped1, tangent, tangent.dot(v2), packId(i2, j1, true), clipped2);
    if (trace != nullptr) {
        trace->incidentFace = j1;
        trace->incidentStart = inc.vertices[j1];
        trace->incidentEnd = inc.vertices[j2];
        trace->cornerToCorner = count < 2;
        if (count == 2)
            trace->clipped = {clipped2[0].point, clipped2[1].point};
    }

    const FeatureId flipBit = flip ? kFlipBit : FeatureId{0};
    Manifold m;
    m.normal = flip ? Vec2(-normal) : normal;
    if (count < 2) {
        // The incident edge lies wholly beyond one end of the reference face. This happens when
        // the polygons are apart corner to corner (closest features vertex–vertex): the face-normal
        // SAT separation then underestimates the true distance, which is conservative for a
        // speculative contact, so report one point rather than nothing. Its separation is the SAT
        // separation (the deeper incident vertex); it sits at the incident vertex nearer the end of
        // the reference face, where the corners would meet.
        const Scalar faceLength = tangent.dot(v2 - v1);
        const auto beyondFace = [&](const Vec2& w) {
            const Scalar u = tangent.dot(w - v1);
            return std::max({Scalar{0}, -u, u - faceLength});
        };
        const ClipVertex& nearer =
            beyondFace(incident[1].point) < beyondFace(incident[0].point) ? incident[1] : incident[0];
        const Scalar separation =
            std::min(normal.dot(incident[0].point - v1), normal.dot(incident[1].point - v1));
        if (separation > speculativeDistance)
            return {};
        m.points[0] = {nearer.point - 0.5 * separation * normal, separation, nearer.id | flipBit};
        m.count = 1;
        return m;
    }
    for (const ClipVertex& c : clipped2) {
        const Scalar separation = normal.dot(c.point - v1);
        if (separation > speculativeDistance)
            continue;
        // The incident point is on the incident surface; halfway back to the reference face line
        // is the midpoint between the surfaces.
        m.points[static_cast<std::size_t>(m.count++)] = {c.point - 0.5 * separation * normal, separation,
                                                          c.id | flipBit};
    }
    return m;
}

} // namespace

Manifold collidePolygons(const PolygonShape& a, const PolygonShape& b, Scalar speculativeDistance,
                         CollisionTrace* trace)
{
    const bool wellFormed = a.vertices.size() >= 3 && a.normals.size() == a.vertices.size() &&
                            b.vertices.size() >= 3 && b.normals.size() == b.vertices.size();
    if (trace != nullptr) {
        trace->method = wellFormed ? TraceMethod::Sat : TraceMethod::Gjk;
        trace->speculativeDistance = speculativeDistance;
        trace->candidateCount = wellFormed ? a.vertices.size() + b.vertices.size() : 0;
    }
    // A segment or a point has no face normals to test: GJK copes with it.
    Manifold m = wellFormed ? polygons(a, b, speculativeDistance, trace)
                            : collideConvexGeneral(a, b, speculativeDistance);
    if (wellFormed && !manifoldIsFinite(m))
        m = Manifold{};
    if (trace != nullptr)
        trace->result = m;
    return m;
}

} // namespace impetus::controller
