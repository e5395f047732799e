// ContactSolver, phase 1b: a step's constraints brought up to date for its later substeps. A step
// longer than the solver's longest substep finds its contacts and builds its constraints once, with
// margins for the whole step; each later substep only measures the gaps again at the bodies' new
// poses (docs/physics.md, "Time step and substeps").

#include "controller/dynamics/contact_solver.h"
#include "controller/dynamics/contact_solver_detail.h"
#include "controller/dynamics/prefetch.h"

#include "controller/transform.h"
#include "model/constants.h"

#include <algorithm>

namespace impetus::controller {

using detail::fastestApproach;

namespace {

/// How many constraints ahead refresh() asks for the memory it will read.
constexpr std::size_t kRefreshPrefetchAhead = 4;

/// (frameB.apply(anchorB) − frameA.apply(anchorA))·(nx, ny), the same operations in the same
/// order, one coordinate at a time: built as Vec2s, GCC packed the two coordinates through the
/// stack, and the wide load waiting on two narrow stores stalled half of refreshConstraint's time.
Scalar separationAlong(const Transform& frameA, const Vec2& anchorA, const Transform& frameB, const Vec2& anchorB,
                       Scalar nx, Scalar ny)
{
    const Scalar ax = frameA.position.x() + (frameA.c * anchorA.x() - frameA.s * anchorA.y());
    const Scalar ay = frameA.position.y() + (frameA.s * anchorA.x() + frameA.c * anchorA.y());
    const Scalar bx = frameB.position.x() + (frameB.c * anchorB.x() - frameB.s * anchorB.y());
    const Scalar by = frameB.position.y() + (frameB.s * anchorB.x() + frameB.c * anchorB.y());
    return (bx - ax) * nx + (by - ay) * ny;
}

} // namespace

void ContactSolver::prefetchForRefresh(std::uint32_t index) const
{
    detail::prefetchObject<true>(m_constraints[index]);
    if (m_batched) // only a batched step has lanes, which hold its impulses
        __builtin_prefetch(&m_laneOf[index]);
    else
        __builtin_prefetch(&m_records[index]);
}

void ContactSolver::prefetchPairBodies(std::uint32_t bodyA, std::uint32_t bodyB, std::span<const SolverBody> bodies,
                                       std::span<const BodyDerivative> derivatives) const
{
    for (const std::uint32_t body : {bodyA, bodyB}) {
        detail::prefetchObject(bodies[body]); // both lines: the second has hadImpact and the material
        __builtin_prefetch(&derivatives[body]);
        __builtin_prefetch(&m_rotations[body]);
    }
}

void ContactSolver::refresh(std::span<SolverBody> bodies, std::span<const BodyDerivative> derivatives, Scalar h)
{
    turnRotations(bodies, m_split); // prepare() took them afresh at the step's first substep
    runGroups([&](int g) {
        const auto part = static_cast<std::size_t>(g);
        m_preparedCandidates[part].clear();
        const std::vector<std::uint32_t>& group = m_groups[part];
        for (std::size_t k = 0; k < group.size(); ++k) {
            // The constraints, records and bodies lie far apart in memory and the pass waits on
            // them; ask for a later constraint's lines while this one is worked on.
            if (k + kRefreshPrefetchAhead < group.size())
                prefetchForRefresh(group[k + kRefreshPrefetchAhead]);
            if (k + kRefreshPrefetchAhead / 2 < group.size()) {
                // Asked for later than the constraint itself, whose first line names the bodies,
                // and whose lane (asked for with it) names the batch whose gaps it writes.
                const std::uint32_t index = group[k + kRefreshPrefetchAhead / 2];
                const ContactConstraint& later = m_constraints[index];
                prefetchPairBodies(later.bodyA, later.bodyB, bodies, derivatives);
                if (m_batched) {
                    // The lane's impulses (read) and gaps (written) lie on two lines of each point.
                    const ContactBatch& batch = m_batches[m_laneOf[index] / kBatchLanes];
                    for (const BatchPoint& point : batch.points) {
                        __builtin_prefetch(&point.normalImpulse);
                        __builtin_prefetch(&point.gapSpeed, 1);
                    }
                }
            }
            refreshConstraint(group[k], bodies, derivatives, h, part);
        }
    });
}

void ContactSolver::refreshConstraint(std::uint32_t index, std::span<SolverBody> bodies,
                                      std::span<const BodyDerivative> derivatives, Scalar h, std::size_t part)
{
    ContactConstraint& c = m_constraints[index];
    const SolverBody& a = bodies[c.bodyA];
    const SolverBody& b = bodies[c.bodyB];
    const Vec2& rotationA = m_rotations[c.bodyA];
    const Vec2& rotationB = m_rotations[c.bodyB];
    const Transform frameA{a.position, rotationA.x(), rotationA.y()};
    const Transform frameB{b.position, rotationB.x(), rotationB.y()};

    // The normal turns with A's face, as the position passes see it. A circle has no face: the
    // line of contact stays the line the other piece's face or centre gives. Two circles meet on
    // the line through their centres; a circle A against a polygon keeps prepare()'s normal, now
    // written afresh into A's turned frame.
    // (Kept as two scalars: see separationAlong.)
    const bool round = c.roundA > 0 || c.roundB > 0;
    Scalar nx = frameA.c * c.localNormalA.x() - frameA.s * c.localNormalA.y();
    Scalar ny = frameA.s * c.localNormalA.x() + frameA.c * c.localNormalA.y();
    if (c.roundA > 0) {
        Vec2 n = c.normal;
        if (c.roundB > 0) {
            const Vec2 between = b.position - a.position;
            const Scalar length = between.norm();
            if (length > 0)
                n = between / length;
        }
        c.localNormalA = frameA.inverseRotate(n);
        nx = n.x();
        ny = n.y();
    }

    // The last substep's passes ended with these impulses: a batched step keeps them in its lanes
    // (its records are written only at the step's end), an unbatched one in its records
    // (finishVelocities wrote them).
    const std::uint32_t laneIndex = m_batched ? m_laneOf[index] : 0;
    const std::size_t bi = laneIndex / kBatchLanes;
    const auto lane = static_cast<int>(laneIndex % kBatchLanes);
    const BodyDerivative& da = derivatives[c.bodyA];
    const BodyDerivative& db = derivatives[c.bodyB];
    bool loaded = false;
    bool approaching = false;
    for (std::size_t i = 0; i < static_cast<std::size_t>(c.pointCount); ++i) {
        ContactConstraintPoint& p = c.points[i];
        // A circle's surface point is the one on the line of contact, whichever way it has rolled.
        if (c.roundA > 0)
            p.localAnchorA = frameA.inverseRotate(Vec2(c.roundA * nx, c.roundA * ny));
        if (c.roundB > 0)
            p.localAnchorB = frameB.inverseRotate(Vec2(-c.roundB * nx, -c.roundB * ny));
        p.separation = separationAlong(frameA, p.localAnchorA, frameB, p.localAnchorB, nx, ny);
        p.closingGap = p.separation;
        const Vec2 accA = da.acceleration + cross(da.angularAcceleration, p.rA);
        const Vec2 accB = db.acceleration + cross(db.angularAcceleration, p.rB);
        p.normalAcceleration = (accB - accA).dot(c.normal);
        p.startNormalVelocity = relativeVelocity(a, b, p.rA, p.rB).dot(c.normal);
        if (m_batched) {
            p.normalImpulse = m_batches[bi].points[i].normalImpulse[lane];
            p.tangentImpulse = m_batches[bi].points[i].tangentImpulse[lane];
        } else {
            p.normalImpulse = m_records[index].normalImpulses[i];
            p.tangentImpulse = m_records[index].tangentImpulses[i];
        }
        loaded = loaded || p.normalImpulse > 0;
        approaching = approaching || p.startNormalVelocity < -constants::kRestingImpactThreshold;
    }
    // As in prepare(): a contact that carried load in the last substep is resting as a whole,
    // unless it still approaches faster than a resting contact can (its load was a speculative
    // contact's, which left the approach over; issue 17, F1).
    loaded = loaded && !approaching;
    for (std::size_t i = 0; i < static_cast<std::size_t>(c.pointCount); ++i)
        c.points[i].carriesLoad = loaded;

    if (const Scalar fastest = fastestApproach(c, bodies, h); fastest < 0)
        m_preparedCandidates[part].push_back({fastest, index, 0});
    if (!m_batched)
        return; // warmStart() packs the velocity passes' data from the constraint

    // A batched step keeps its lanes, whose accumulated impulses are already the last pass's: only
    // the gaps change, and a circle's surface points and normal.
    ContactBatch& batch = m_batches[bi];
    PositionBatch& positions = m_positionBatches[bi];
    for (std::size_t i = 0; i < static_cast<std::size_t>(c.pointCount); ++i) {
        const ContactConstraintPoint& p = c.points[i];
        batch.points[i].gapSpeed[lane] = std::max(p.closingGap, 0.0) / h;
        if (!round)
            continue;
        PositionBatch::Anchors& anchors = positions.anchors[i];
        anchors.ax[lane] = p.localAnchorA.x();
        anchors.ay[lane] = p.localAnchorA.y();
        anchors.bx[lane] = p.localAnchorB.x();
        anchors.by[lane] = p.localAnchorB.y();
    }
    if (round) {
        positions.localNormalX[lane] = c.localNormalA.x();
        positions.localNormalY[lane] = c.localNormalA.y();
    }
}

} // namespace impetus::controller
