// ContactSolver, phase 4: position correction by non-linear Gauss–Seidel, which moves bodies and
// never changes a velocity.

#include "controller/dynamics/contact_solver.h"
#include "controller/dynamics/contact_solver_detail.h"

#include "controller/transform.h"
#include "model/constants.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace impetus::controller {

namespace {

/// One non-linear Gauss–Seidel update of one constraint's positions. `rotations` holds every
/// body's cos and sin of its current angle, kept up to date here when a body turns (with the angle
/// they are of in `rotationAngles`, which ContactSolver::turnRotations reads). Returns the
/// deepest separation it saw (≤ 0), m. Adds the linear position impulse it applied to `push`.
Scalar solvePositionConstraint(const ContactConstraint& c, std::span<SolverBody> bodies, std::span<Vec2> rotations,
                               std::span<Scalar> rotationAngles, Vec2& push)
{
    Scalar deepest = 0;
    SolverBody& a = bodies[c.bodyA];
    SolverBody& b = bodies[c.bodyB];
    for (int i = 0; i < c.pointCount; ++i) {
        const ContactConstraintPoint& p = c.points[static_cast<std::size_t>(i)];
        const detail::PositionCorrection look =
            detail::positionCorrection(c, p, a, b, rotations[c.bodyA], rotations[c.bodyB]);
        deepest = std::min(deepest, look.separation);
        if (look.impulse.isZero())
            continue;
        applyPositionImpulse(a, b, look.rA, look.rB, look.impulse);
        push += look.impulse;
        // A resting point within the slop moves nothing: the sine and cosine are computed again
        // only for a body that turned, not at every look.
        if (movable(a)) {
            rotations[c.bodyA] = Vec2(std::cos(a.angle), std::sin(a.angle));
            rotationAngles[c.bodyA] = a.angle;
        }
        if (movable(b)) {
            rotations[c.bodyB] = Vec2(std::cos(b.angle), std::sin(b.angle));
            rotationAngles[c.bodyB] = b.angle;
        }
    }
    return deepest;
}

} // namespace

void ContactSolver::beginPositions(bool measured)
{
    m_pushesMeasured = measured;
    if (!m_batched) {
        m_pushes.assign(m_constraints.size(), Vec2::Zero());
        return;
    }
    if (!measured)
        return; // the passes add to stale pushes, which nothing reads
    for (PositionBatch& batch : m_positionBatches) {
        batch.pushX = Lanes{};
        batch.pushY = Lanes{};
    }
}

void ContactSolver::measurePushes(std::span<const SolverBody> bodies)
{
    // What each contact's position passes changed in the angular momentum, from the velocities
    // they saw: all are measured before any is answered (takeBackPushes).
    assert(m_pushesMeasured);
    m_pushedPairs.clear();
    const auto look = [&](std::uint32_t ci, const Vec2& push) {
        if (push.isZero())
            return;
        const SolverBody& a = bodies[m_constraints[ci].bodyA];
        const SolverBody& b = bodies[m_constraints[ci].bodyB];
        if (a.invMass > 0 && b.invMass > 0)
            m_pushedPairs.push_back({m_constraints[ci].bodyA, m_constraints[ci].bodyB,
                                     cross(push, Vec2(b.velocity - a.velocity)), push});
    };
    if (!m_batched) {
        for (std::uint32_t ci = 0; ci < m_pushes.size(); ++ci)
            look(ci, m_pushes[ci]);
    } else {
        for (std::size_t bi = 0; bi < m_positionBatches.size(); ++bi) {
            const PositionBatch& batch = m_positionBatches[bi];
            for (std::size_t lane = 0; lane < static_cast<std::size_t>(kBatchLanes); ++lane) {
                const std::uint32_t ci = m_batchLanes[bi * kBatchLanes + lane];
                if (ci != kNoConstraint)
                    look(ci, Vec2(batch.pushX[static_cast<int>(lane)], batch.pushY[static_cast<int>(lane)]));
            }
        }
    }
}

void ContactSolver::takeBackPushes(std::span<SolverBody> bodies) const
{
    for (const PushedPair& pair : m_pushedPairs)
        restoreAngularMomentum(bodies[pair.bodyA], bodies[pair.bodyB], pair.change, pair.push);
}

bool ContactSolver::solvePositions(std::span<SolverBody> bodies, bool turnedElsewhere)
{
    if (m_batched)
        return solvePositionsInBatches(bodies, turnedElsewhere);
    // Each pass keeps the sines and cosines of the bodies it turns up to date, so they need
    // computing afresh only when something else has turned bodies since: a large world's thousands
    // of them cost as much as a pass.
    if (turnedElsewhere)
        computeRotations(bodies, m_split);
    std::array<Scalar, 3> deepest{};
    // Each group keeps its deepest in a local and writes it once: the two threads writing to
    // neighbouring elements on every constraint would pass that cache line back and forth.
    forEachGroupIndex([&](std::span<const std::uint32_t> group, int index) {
        Scalar groupDeepest = 0;
        for (const std::uint32_t ci : group)
            groupDeepest = std::min(groupDeepest, solvePositionConstraint(m_constraints[ci], bodies, m_rotations, m_rotationAngles, m_pushes[ci]));
        deepest[static_cast<std::size_t>(index)] = groupDeepest;
    });
    // Allow a little more than the slop before calling it solved, as the iterations converge
    // towards −slop from either side.
    return std::min({deepest[0], deepest[1], deepest[2]}) >= -3 * constants::kLinearSlop;
}

bool ContactSolver::solvePositionsInBatches(std::span<SolverBody> bodies, bool turnedElsewhere)
{
    // The poses, with their cosines and sines, are taken from the bodies only when something else
    // may have moved them; the passes keep both up to date, and hand the poses back after each
    // pass. Each half of a split world does its own bodies.
    // They are kept by slot, as the velocities are (assignSlots).
    // Their cosines and sines are the rotations the substep began with, turned by what the bodies
    // turned since (turnRotations).
    if (turnedElsewhere) {
        turnRotations(bodies, m_split);
        inSlotHalves(m_bodyOfSlot.size(), [&](std::size_t begin, std::size_t end) {
            for (std::size_t slot = begin; slot < end; ++slot) {
                const std::uint32_t index = m_bodyOfSlot[slot];
                const SolverBody& body = bodies[index];
                const Vec2& rotation = m_rotations[index];
                m_poses[slot] = BatchPose{body.position.x(), body.position.y(), body.angle, rotation.x(), rotation.y()};
            }
        });
    }
    std::array<Scalar, 3> deepest{};
    runGroups([&](int g) {
        const auto ug = static_cast<std::size_t>(g);
        deepest[ug] = solvePositionBatches(std::span<PositionBatch>(m_positionBatches)
                                               .subspan(m_batchGroupStart[ug], m_batchGroupStart[ug + 1] - m_batchGroupStart[ug]),
                                           m_poses);
    });
    inSlotHalves(m_movableSlots, [&](std::size_t begin, std::size_t end) {
        for (std::size_t slot = begin; slot < end; ++slot) {
            SolverBody& body = bodies[m_bodyOfSlot[slot]];
            if (!movable(body))
                continue;
            body.position = Vec2(m_poses[slot].x, m_poses[slot].y);
            body.angle = m_poses[slot].angle;
        }
    });
    return std::min({deepest[0], deepest[1], deepest[2]}) >= -3 * constants::kLinearSlop;
}

} // namespace impetus::controller
