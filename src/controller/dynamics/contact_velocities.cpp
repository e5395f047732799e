// ContactSolver, phase 3: the contact forces' velocity passes (sequential impulses with warm
// starting, friction and the two-point block solve), one contact at a time or in batches.

#include "controller/dynamics/contact_solver.h"
#include "controller/dynamics/contact_solver_detail.h"

#include "model/constants.h"

#include <algorithm>

namespace impetus::controller {

using detail::normalK;
using detail::tangentOf;

namespace {

/// Marks the movable ones of a contact's bodies as held by a contact force.
void markContactForce(SolverBody& a, SolverBody& b)
{
    if (movable(a))
        a.hadContactForce = true;
    if (movable(b))
        b.hadContactForce = true;
}

/// One sequential-impulse update of one constraint: friction, then the normal constraints.
void solveVelocityConstraint(ContactSolver::VelocityConstraint& c, std::span<SolverBody> bodies)
{
    SolverBody& a = bodies[c.bodyA];
    SolverBody& b = bodies[c.bodyB];
    const Vec2 n = c.normal;
    const Vec2 t = tangentOf(n);
    bool acted = false;

    // Friction first, limited by the normal impulse of the last pass: the normal constraint is the
    // more important one and so gets the last word.
    for (int i = 0; i < c.pointCount; ++i) {
        ContactSolver::VelocityPoint& p = c.points[static_cast<std::size_t>(i)];
        const Scalar vt = relativeVelocity(a, b, p.rA, p.rB).dot(t);
        const Scalar limit = c.friction * p.normalImpulse;
        const Scalar updated = std::clamp(p.tangentImpulse - vt * p.tangentMass, -limit, limit);
        const Scalar delta = updated - p.tangentImpulse;
        p.tangentImpulse = updated;
        if (delta != 0) {
            applyImpulse(a, b, p.rA, p.rB, delta * t);
            acted = true;
        }
    }

    // Normal: vn ≥ −s⁺/h. A speculative point (s > 0) may approach by its gap and no more, which
    // is what stops a fast body at the surface instead of letting it tunnel; a touching or
    // overlapping point may not approach at all (overlap is the position solver's job).
    if (c.blockSolve) {
        ContactSolver::VelocityPoint& p1 = c.points[0];
        ContactSolver::VelocityPoint& p2 = c.points[1];
        const Scalar old1 = p1.normalImpulse;
        const Scalar old2 = p2.normalImpulse;
        // b = vn − K·old: the velocity without this constraint's accumulated impulse. The total
        // impulse x solves the LCP x ≥ 0, w = b + K·x ≥ 0, xᵢwᵢ = 0, by trying its active sets.
        const Scalar b1 = relativeVelocity(a, b, p1.rA, p1.rB).dot(n) + p1.gapSpeed - (c.k11 * old1 + c.k12 * old2);
        const Scalar b2 = relativeVelocity(a, b, p2.rA, p2.rB).dot(n) + p2.gapSpeed - (c.k12 * old1 + c.k22 * old2);
        Scalar x1 = -(c.inverse11 * b1 + c.inverse12 * b2);
        Scalar x2 = -(c.inverse12 * b1 + c.inverse22 * b2);
        if (!(x1 >= 0 && x2 >= 0)) {
            x1 = -b1 / c.k11; // both points but the first inactive
            x2 = 0;
            if (!(x1 >= 0 && c.k12 * x1 + b2 >= 0)) {
                x1 = 0;
                x2 = -b2 / c.k22;
                if (!(x2 >= 0 && c.k12 * x2 + b1 >= 0))
                    x2 = 0;
            }
        }
        p1.normalImpulse = x1;
        p2.normalImpulse = x2;
        const Scalar delta1 = x1 - old1;
        const Scalar delta2 = x2 - old2;
        if (delta1 != 0 || delta2 != 0) {
            applyImpulse(a, b, p1.rA, p1.rB, delta1 * n);
            applyImpulse(a, b, p2.rA, p2.rB, delta2 * n);
            acted = true;
        }
    } else {
        for (int i = 0; i < c.pointCount; ++i) {
            ContactSolver::VelocityPoint& p = c.points[static_cast<std::size_t>(i)];
            const Scalar vn = relativeVelocity(a, b, p.rA, p.rB).dot(n) + p.gapSpeed;
            const Scalar updated = std::max(p.normalImpulse - vn * p.normalMass, 0.0);
            const Scalar delta = updated - p.normalImpulse;
            p.normalImpulse = updated;
            if (delta != 0) {
                applyImpulse(a, b, p.rA, p.rB, delta * n);
                acted = true;
            }
        }
    }
    c.acted = c.acted || acted;
}

/// How many batches ahead finishVelocities() asks for the records it will write.
constexpr std::size_t kFinishPrefetchBatches = 4;

/// Ends point i of a record with the impulses of the velocity passes; a point that carries a
/// normal impulse touches.
void finishRecord(model::ContactRecord& r, std::size_t i, Scalar normalImpulse, Scalar tangentImpulse)
{
    r.normalImpulses[i] = normalImpulse;
    r.tangentImpulses[i] = tangentImpulse;
    r.touching = r.touching || normalImpulse > 0;
}

} // namespace

void ContactSolver::warmStart(std::span<SolverBody> bodies, Scalar h, bool sharedVelocities)
{
    m_sharedVelocities = sharedVelocities;
    // The velocity passes see only what they need, packed in solving order: a third of the
    // constraint's size, read front to back, eight times a step.
    if (m_batched) {
        // prepare() has filled the batches.
        copyVelocitiesIn(bodies);
        runGroups([&](int g) { warmStartBatches(batchesOf(static_cast<std::size_t>(g))); });
        if (m_sharedVelocities)
            copyVelocitiesOut(bodies);
        return;
    }
    m_velocityConstraints.resize(m_constraints.size());
    std::size_t slot = 0;
    for (std::size_t g = 0; g < m_groups.size(); ++g) {
        m_groupStart[g] = slot;
        for (const std::uint32_t ci : m_groups[g]) {
            const ContactConstraint& c = m_constraints[ci];
            VelocityConstraint& v = m_velocityConstraints[slot++];
            v.bodyA = c.bodyA;
            v.bodyB = c.bodyB;
            v.pointCount = c.pointCount;
            v.blockSolve = c.pointCount == 2 && c.blockSolve;
            v.acted = false;
            v.normal = c.normal;
            v.friction = c.friction;
            const Eigen::Matrix2d k = normalK(c, bodies[c.bodyA], bodies[c.bodyB]);
            const Eigen::Matrix2d inverse = v.blockSolve ? Eigen::Matrix2d(k.inverse()) : Eigen::Matrix2d::Zero();
            v.k11 = k(0, 0);
            v.k12 = k(0, 1);
            v.k22 = k(1, 1);
            v.inverse11 = inverse(0, 0);
            v.inverse12 = inverse(0, 1);
            v.inverse22 = inverse(1, 1);
            for (std::size_t i = 0; i < static_cast<std::size_t>(c.pointCount); ++i) {
                const ContactConstraintPoint& p = c.points[i];
                VelocityPoint& q = v.points[i];
                q.rA = p.rA;
                q.rB = p.rB;
                q.normalMass = p.normalMass;
                q.tangentMass = p.tangentMass;
                q.normalImpulse = p.normalImpulse;
                q.tangentImpulse = p.tangentImpulse;
                q.gapSpeed = std::max(p.closingGap, 0.0) / h;
            }
        }
    }
    m_groupStart[m_groups.size()] = slot;
    forEachGroup([&](std::span<VelocityConstraint> group, int) {
        for (VelocityConstraint& v : group) {
            SolverBody& a = bodies[v.bodyA];
            SolverBody& b = bodies[v.bodyB];
            const Vec2 t = tangentOf(v.normal);
            for (int i = 0; i < v.pointCount; ++i) {
                const VelocityPoint& p = v.points[static_cast<std::size_t>(i)];
                if (p.normalImpulse == 0 && p.tangentImpulse == 0)
                    continue;
                applyImpulse(a, b, p.rA, p.rB, p.normalImpulse * v.normal + p.tangentImpulse * t);
                v.acted = true;
            }
        }
    });
}

void ContactSolver::solveVelocities(std::span<SolverBody> bodies)
{
    if (m_batched) {
        if (m_sharedVelocities)
            copyVelocitiesIn(bodies);
        runGroups([&](int g) { solveBatches(batchesOf(static_cast<std::size_t>(g))); });
        if (m_sharedVelocities)
            copyVelocitiesOut(bodies);
        return;
    }
    forEachGroup([&](std::span<VelocityConstraint> group, int) {
        for (VelocityConstraint& v : group)
            solveVelocityConstraint(v, bodies);
    });
}

void ContactSolver::forgetImpulses()
{
    for (ContactConstraint& c : m_constraints) {
        for (ContactConstraintPoint& p : c.points) {
            p.normalImpulse = 0;
            p.tangentImpulse = 0;
        }
    }
    for (ContactBatch& batch : m_batches) {
        for (BatchPoint& p : batch.points) {
            p.normalImpulse = Lanes{};
            p.tangentImpulse = Lanes{};
        }
        batch.acted = LaneMask{};
    }
}

void ContactSolver::finishVelocities(std::span<SolverBody> bodies, bool writeRecords)
{
    // The impulses go to the records alone, which is what the next step warm-starts from: the
    // constraints, seven cache lines each, are not read or written again.
    if (!m_batched) {
        std::size_t slot = 0;
        for (const std::vector<std::uint32_t>& group : m_groups) {
            for (const std::uint32_t ci : group) {
                const VelocityConstraint& v = m_velocityConstraints[slot++];
                model::ContactRecord& r = m_records[ci];
                for (std::size_t i = 0; i < static_cast<std::size_t>(v.pointCount); ++i)
                    finishRecord(r, i, v.points[i].normalImpulse, v.points[i].tangentImpulse);
                if (v.acted)
                    markContactForce(bodies[v.bodyA], bodies[v.bodyB]);
            }
        }
        return;
    }
    // Each group marks its own movable bodies and writes its own records, so the halves of a
    // split world can do this side by side too. The lanes that carried a normal impulse are
    // remembered for the records' `touching`, which the props read before the records are
    // written.
    runGroups([&](int g) {
        const auto ug = static_cast<std::size_t>(g);
        const std::size_t end = m_batchGroupStart[ug + 1];
        for (std::size_t bi = m_batchGroupStart[ug]; bi < end; ++bi) {
            const ContactBatch& batch = m_batches[bi];
            for (int lane = 0; lane < kBatchLanes; ++lane) {
                if (batch.points[0].normalImpulse[lane] > 0 || batch.points[1].normalImpulse[lane] > 0)
                    m_touched[bi] = static_cast<std::uint8_t>(m_touched[bi] | (1U << lane));
            }
            if (!m_sharedVelocities) {
                // The bodies' copies in the batch slots, next to the velocities they hand back
                // below (a fixed body's lane writes to a scratch slot, which is not handed back).
                for (int lane = 0; lane < kBatchLanes; ++lane) {
                    if (batch.acted[lane] != 0) {
                        batch.writeA[static_cast<std::size_t>(lane)]->contactForce = true;
                        batch.writeB[static_cast<std::size_t>(lane)]->contactForce = true;
                    }
                }
            }
            if (!writeRecords && !m_sharedVelocities)
                continue;
            // The records lie in the constraints' order, not the lanes': ask for those of a batch
            // a few ahead while this one's are written (one ahead was too late: the work on a
            // batch is short).
            const std::size_t ahead = bi + kFinishPrefetchBatches;
            if (ahead < end) {
                for (int lane = 0; lane < kBatchLanes; ++lane) {
                    const std::uint32_t next = m_batchLanes[ahead * kBatchLanes + static_cast<std::size_t>(lane)];
                    if (next != kNoConstraint) {
                        if (writeRecords)
                            __builtin_prefetch(&m_records[next], 1);
                        if (m_sharedVelocities)
                            __builtin_prefetch(&m_constraintBodies[next]);
                    }
                }
            }
            for (int lane = 0; lane < kBatchLanes; ++lane) {
                const auto ul = static_cast<std::size_t>(lane);
                const std::uint32_t ci = m_batchLanes[bi * kBatchLanes + ul];
                if (ci == kNoConstraint)
                    continue;
                if (writeRecords) {
                    model::ContactRecord& r = m_records[ci];
                    for (std::size_t i = 0; i < r.pointCount; ++i)
                        finishRecord(r, i, batch.points[i].normalImpulse[lane], batch.points[i].tangentImpulse[lane]);
                    r.touching = r.touching || (m_touched[bi] >> lane & 1U) != 0;
                }
                // Every pass has handed the velocities back to the bodies already: mark them there.
                if (m_sharedVelocities && batch.acted[lane] != 0)
                    markContactForce(bodies[m_constraintBodies[ci][0]], bodies[m_constraintBodies[ci][1]]);
            }
        }
    });
    // The velocities and the marks go back to the bodies, each half's on its own thread (unless
    // every pass has handed them back already).
    if (!m_sharedVelocities)
        copyVelocitiesOut(bodies);
}

bool ContactSolver::touching(std::uint32_t ci) const
{
    if (m_records[ci].touching)
        return true;
    if (!m_batched)
        return false;
    const std::uint32_t lane = m_laneOf[ci];
    return (m_touched[lane / kBatchLanes] >> (lane % kBatchLanes) & 1U) != 0;
}

} // namespace impetus::controller
