// ContactSolver's solving order: the two halves of a large world, the colours and batch lanes of
// a batched step, and the slots its bodies are copied into (docs/physics.md, "Two threads" and
// "Batches").

#include "controller/dynamics/contact_solver.h"
#include "controller/dynamics/contact_solver_detail.h"

#include "model/constants.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>

namespace impetus::controller {

using detail::tangentOf;

namespace {

/// The allowed approach speed of a batch lane's missing second point, m/s: so large that the
/// point can never become active, and still finite, so that no lane ever computes ∞ − ∞.
constexpr Scalar kUnreachableGapSpeed = 1e300;

} // namespace

void ContactSolver::partition(std::span<const SolverBody> bodies)
{
    for (std::vector<std::uint32_t>& group : m_groups)
        group.clear();
    m_split = m_constraints.size() >= constants::kParallelMinConstraints;
    m_batched = m_constraints.size() >= m_batchMinConstraints && !m_constraints.empty();
    // Passes that go one contact at a time take a group's contacts with a fixed body (the floor,
    // a wall) after those between two movable bodies, each in the broad phase's order. The last
    // word in a pass is then the fixed body's: a light body pressed into the floor by a heavy one
    // ends each pass moving no further into the floor, and the heavy one is slowed by what the
    // floor gives back through it, pass by pass. In the broad phase's order the floor (the first
    // body of a scene, as a rule) came first, and the heavy body's contact after it pushed the
    // light one on into the floor every pass: a 0.3 kg ellipse under a 4.5 t soft body was 0.13 m
    // inside the floor in five steps (soak seed 111; 104 alike). The batches of a large world go
    // by colours instead, and keep their order.
    // Called before the constraints are built: the bodies are in m_constraintBodies.
    const auto fixedLast = [&](std::vector<std::uint32_t>& group) {
        if (m_batched)
            return;
        std::stable_partition(group.begin(), group.end(), [&](std::uint32_t ci) {
            return movable(bodies[m_constraintBodies[ci][0]]) && movable(bodies[m_constraintBodies[ci][1]]);
        });
    };
    if (!m_split) {
        m_groups[0].resize(m_constraints.size());
        for (std::uint32_t ci = 0; ci < m_constraints.size(); ++ci)
            m_groups[0][ci] = ci;
        fixedLast(m_groups[0]);
        if (m_batched) {
            assignSlots(bodies);
            colour(bodies);
        }
        return;
    }
    // Cut the movable bodies into two halves at the median of their positions along the longer
    // side of their bounding box, ties broken by index so the cut is the same on every machine.
    // A constraint whose movable bodies all lie in one half belongs to that half; the two halves
    // share no movable body and can be solved side by side. The few that join the halves follow.
    Vec2 lower = Vec2::Constant(std::numeric_limits<Scalar>::infinity());
    Vec2 upper = -lower;
    m_sortKeys.clear();
    for (std::uint32_t i = 0; i < bodies.size(); ++i) {
        if (!movable(bodies[i]))
            continue;
        lower = lower.cwiseMin(bodies[i].position);
        upper = upper.cwiseMax(bodies[i].position);
    }
    const int axis = (upper - lower).x() >= (upper - lower).y() ? 0 : 1;
    for (std::uint32_t i = 0; i < bodies.size(); ++i) {
        if (movable(bodies[i]))
            m_sortKeys.emplace_back(bodies[i].position(axis), i);
    }
    m_half.assign(bodies.size(), kFixedHalf);
    const auto middle = m_sortKeys.begin() + static_cast<std::ptrdiff_t>(m_sortKeys.size() / 2);
    std::nth_element(m_sortKeys.begin(), middle, m_sortKeys.end());
    for (auto it = m_sortKeys.begin(); it != m_sortKeys.end(); ++it)
        m_half[it->second] = it < middle ? 0 : 1;
    for (std::uint32_t ci = 0; ci < m_constraints.size(); ++ci) {
        const std::uint8_t ha = m_half[m_constraintBodies[ci][0]];
        const std::uint8_t hb = m_half[m_constraintBodies[ci][1]];
        const std::uint8_t half = ha == kFixedHalf ? hb : (hb == kFixedHalf || hb == ha ? ha : 2);
        m_groups[half == kFixedHalf ? 0 : half].push_back(ci);
    }
    for (std::vector<std::uint32_t>& group : m_groups)
        fixedLast(group);
    if (m_batched) {
        assignSlots(bodies);
        colour(bodies);
    }
}

void ContactSolver::assignSlots(std::span<const SolverBody> bodies)
{
    const std::size_t count = bodies.size();
    m_slotOf.resize(count);
    m_bodyOfSlot.resize(count);
    m_batchBodies.resize(count + kScratchSlots);
    m_poses.resize(count + kScratchSlots);
    if (!m_split) {
        for (std::uint32_t i = 0; i < count; ++i) {
            m_slotOf[i] = i;
            m_bodyOfSlot[i] = i;
        }
        m_firstHalfSlots = count;
        m_movableSlots = count;
        return;
    }
    // Each half's movable bodies in their own order, then the rest (m_half is kFixedHalf).
    std::uint32_t next = 0;
    for (const std::uint8_t half : {std::uint8_t{0}, std::uint8_t{1}, kFixedHalf}) {
        for (std::uint32_t i = 0; i < count; ++i) {
            if (m_half[i] != half)
                continue;
            m_slotOf[i] = next;
            m_bodyOfSlot[next++] = i;
        }
        if (half == 0)
            m_firstHalfSlots = next;
        else if (half == 1)
            m_movableSlots = next;
    }
}

void ContactSolver::inSlotHalves(std::size_t count, const std::function<void(std::size_t, std::size_t)>& work)
{
    inTwoParts(m_split ? m_tasks : nullptr, std::min(m_firstHalfSlots, count), count, work);
}

void ContactSolver::copyVelocitiesIn(std::span<const SolverBody> bodies)
{
    for (std::size_t g = 0; g < m_groups.size(); ++g)
        m_batchBodies[scratchSlot(g)] = BatchBody{};
    inSlotHalves(m_bodyOfSlot.size(), [&](std::size_t begin, std::size_t end) {
        for (std::size_t slot = begin; slot < end; ++slot) {
            const SolverBody& body = bodies[m_bodyOfSlot[slot]];
            BatchBody& copy = m_batchBodies[slot];
            copy.velocity = body.velocity;
            copy.angularVelocity = body.angularVelocity;
            copy.invMass = body.invMass;
            copy.invInertia = body.invInertia;
            copy.contactForce = false;
        }
    });
}

void ContactSolver::copyVelocitiesOut(std::span<SolverBody> bodies)
{
    // Only the slots the passes write to: a split world's fixed bodies, which both threads read,
    // are never written.
    inSlotHalves(m_movableSlots, [&](std::size_t begin, std::size_t end) {
        for (std::size_t slot = begin; slot < end; ++slot) {
            SolverBody& body = bodies[m_bodyOfSlot[slot]];
            body.velocity = m_batchBodies[slot].velocity;
            body.angularVelocity = m_batchBodies[slot].angularVelocity;
            body.hadContactForce = body.hadContactForce || m_batchBodies[slot].contactForce;
        }
    });
}

void ContactSolver::colour(std::span<const SolverBody> bodies)
{
    // Halves 0 and 1 share no movable body, so they are coloured side by side; the constraints
    // joining them follow. Then the groups' lanes are laid one after the other.
    m_laneOf.resize(m_constraints.size());
    m_colourMasks.assign(bodies.size(), 0);
    runGroups([&](int g) { colourGroup(bodies, static_cast<std::size_t>(g)); });
    m_batchLanes.clear();
    for (std::size_t g = 0; g < m_groups.size(); ++g) {
        m_batchGroupStart[g] = m_batchLanes.size() / kBatchLanes;
        const auto offset = static_cast<std::uint32_t>(m_batchLanes.size());
        m_batchLanes.insert(m_batchLanes.end(), m_groupLanes[g].begin(), m_groupLanes[g].end());
        if (offset != 0) {
            for (const std::uint32_t ci : m_groups[g])
                m_laneOf[ci] += offset;
        }
    }
    m_batchGroupStart[m_groups.size()] = m_batchLanes.size() / kBatchLanes;
}

void ContactSolver::colourGroup(std::span<const SolverBody> bodies, std::size_t g)
{
    // Greedy colouring in the group's order: each constraint takes the lowest colour that none of
    // its movable bodies' constraints has taken yet. Fixed bodies are shared freely, as the batches
    // never write to them. A pile needs about a dozen colours. A body's colours are the 64 bits of
    // its mask: the constraints that find all 64 taken are coloured again among themselves, with
    // 64 new colours, for up to kColourRounds rounds; what is left after the last gets a pair of
    // batches of its own, after the others. (One round alone left 35,000 of the spinner's 151,000
    // contacts in its fast opening each in a pair of batches of its own, seven lanes of eight
    // padding: 397,000 lanes for 151,000 contacts, most of the velocity passes' work.)
    constexpr std::size_t kColours = 64;
    constexpr std::size_t kColourRounds = 3;
    constexpr std::size_t kAllColours = kColours * kColourRounds;
    static_assert(kAllColours <= UINT8_MAX, "a colour and the mark of none fit in a byte");
    const std::vector<std::uint32_t>& group = m_groups[g];
    std::vector<std::uint32_t>& lanesOut = m_groupLanes[g];
    lanesOut.clear();
    if (group.empty())
        return;
    std::vector<std::uint8_t>& colourOf = m_colourOf[g];
    colourOf.resize(group.size());
    std::array<std::size_t, kAllColours + 1> count{};
    std::vector<std::uint32_t>& left = m_uncoloured[g];
    std::vector<std::uint32_t>& leftAfter = m_uncolouredNext[g];
    left.resize(group.size());
    std::iota(left.begin(), left.end(), 0U);
    for (std::size_t round = 0; round < kColourRounds && !left.empty(); ++round) {
        // Each round's colours start afresh on the bodies it colours. (In the first, the
        // constraints joining the halves meet bodies that the halves have coloured already.)
        // Only movable bodies have masks: a fixed body may be shared with the other half, which
        // is coloured at the same time on the other thread.
        if (round > 0 || g == 2) {
            for (const std::uint32_t k : left) {
                for (const std::uint32_t body : m_constraintBodies[group[k]]) {
                    if (movable(bodies[body]))
                        m_colourMasks[body] = 0;
                }
            }
        }
        leftAfter.clear();
        for (const std::uint32_t k : left) {
            const auto [bodyA, bodyB] = m_constraintBodies[group[k]];
            const bool moveA = movable(bodies[bodyA]);
            const bool moveB = movable(bodies[bodyB]);
            const std::uint64_t taken = (moveA ? m_colourMasks[bodyA] : 0) | (moveB ? m_colourMasks[bodyB] : 0);
            const auto colour = static_cast<std::size_t>(std::countr_one(taken));
            if (colour == kColours) {
                leftAfter.push_back(k);
                continue;
            }
            colourOf[k] = static_cast<std::uint8_t>(round * kColours + colour);
            ++count[round * kColours + colour];
            const std::uint64_t bit = std::uint64_t{1} << colour;
            if (moveA)
                m_colourMasks[bodyA] |= bit;
            if (moveB)
                m_colourMasks[bodyB] |= bit;
        }
        left.swap(leftAfter);
    }
    for (const std::uint32_t k : left)
        colourOf[k] = static_cast<std::uint8_t>(kAllColours);
    count[kAllColours] = left.size();
    // Each colour fills whole pairs of batches (kBatchPair), the last one padded: lay the lanes
    // out colour by colour, keeping the group's order within a colour.
    constexpr std::size_t kColourStep = kBatchLanes * kBatchPair;
    std::array<std::size_t, kAllColours> firstLane{};
    std::size_t lanes = 0;
    for (std::size_t colour = 0; colour < kAllColours; ++colour) {
        firstLane[colour] = lanes;
        lanes += (count[colour] + kColourStep - 1) / kColourStep * kColourStep;
    }
    // A constraint that found every colour of every round taken gets a pair of batches of its
    // own, after the others.
    lanesOut.resize(lanes + count[kAllColours] * kColourStep, kNoConstraint);
    for (std::size_t k = 0; k < group.size(); ++k) {
        const std::size_t lane = colourOf[k] < kAllColours ? firstLane[colourOf[k]]++ : lanes;
        if (colourOf[k] == kAllColours)
            lanes += kColourStep;
        lanesOut[lane] = group[k];
        m_laneOf[group[k]] = static_cast<std::uint32_t>(lane);
    }
}

void ContactSolver::packLane(std::span<SolverBody> bodies, Scalar h, std::size_t g, std::size_t laneIndex)
{
    // Every field of the lane is written, padding included: nothing is cleared first.
    const std::uint32_t scratch = scratchSlot(g);
    const std::size_t bi = laneIndex / kBatchLanes;
    const auto lane = static_cast<int>(laneIndex % kBatchLanes);
    const auto ul = static_cast<std::size_t>(lane);
    ContactBatch& batch = m_batches[bi];
    PositionBatch& positions = m_positionBatches[bi];
    const std::uint32_t ci = m_batchLanes[laneIndex];
    // Padding is a contact without mass or normal between two bodies that cannot move; it never
    // acts.
    const ContactConstraint* c = ci == kNoConstraint ? nullptr : &m_constraints[ci];
    const bool two = c && c->pointCount == 2;
    const auto side = [&](std::uint32_t ContactConstraint::*body, std::array<const BatchBody*, kBatchLanes>& read,
                          std::array<BatchBody*, kBatchLanes>& write, std::array<std::uint32_t, kBatchLanes>& readPose,
                          std::array<std::uint32_t, kBatchLanes>& writePose) {
        const std::uint32_t index = c ? c->*body : 0;
        const bool moves = c && movable(bodies[index]);
        const std::uint32_t readSlot = c ? m_slotOf[index] : scratch;
        const std::uint32_t writeSlot = moves ? readSlot : scratch;
        read[ul] = &m_batchBodies[readSlot];
        write[ul] = &m_batchBodies[writeSlot];
        readPose[ul] = readSlot;
        writePose[ul] = writeSlot;
    };
    side(&ContactConstraint::bodyA, batch.bodyA, batch.writeA, positions.readA, positions.writeA);
    side(&ContactConstraint::bodyB, batch.bodyB, batch.writeB, positions.readB, positions.writeB);
    // A padding lane's bodies cannot move.
    static const SolverBody fixedBody;
    const SolverBody& a = c ? bodies[c->bodyA] : fixedBody;
    const SolverBody& b = c ? bodies[c->bodyB] : fixedBody;
    const Vec2 n = c ? c->normal : Vec2::Zero();
    const Vec2 t = tangentOf(n);
    batch.normalX[lane] = n.x();
    batch.normalY[lane] = n.y();
    batch.friction[lane] = c ? c->friction : 0;
    batch.acted[lane] = 0;
    positions.invMassA[lane] = a.invMass;
    positions.invInertiaA[lane] = a.invInertia;
    positions.invMassB[lane] = b.invMass;
    positions.invInertiaB[lane] = b.invInertia;
    // A one-point contact's second point has no arms or mass and can never close its gap: only
    // the "first point alone" and "none" cases can hold, which is the one-point solve.
    batch.blockSolve[lane] = two && c->blockSolve ? -1 : 0;
    const Vec2 localNormal = c ? c->localNormalA : Vec2::Zero();
    positions.localNormalX[lane] = localNormal.x();
    positions.localNormalY[lane] = localNormal.y();
    positions.secondPoint[lane] = two ? -1 : 0;
    positions.pushX[lane] = 0;
    positions.pushY[lane] = 0;
    for (std::size_t i = 0; i < 2; ++i) {
        const ContactConstraintPoint* p = c && i < static_cast<std::size_t>(c->pointCount) ? &c->points[i] : nullptr;
        const ContactConstraintPoint none;
        const ContactConstraintPoint& q = p ? *p : none;
        BatchPoint& v = batch.points[i];
        v.normalArmA[lane] = cross(q.rA, n);
        v.normalArmB[lane] = cross(q.rB, n);
        v.tangentArmA[lane] = cross(q.rA, t);
        v.tangentArmB[lane] = cross(q.rB, t);
        v.normalMass[lane] = q.normalMass;
        v.tangentMass[lane] = q.tangentMass;
        v.normalImpulse[lane] = q.normalImpulse;
        v.tangentImpulse[lane] = q.tangentImpulse;
        v.gapSpeed[lane] = p ? std::max(q.closingGap, 0.0) / h : kUnreachableGapSpeed;
        PositionBatch::Anchors& anchors = positions.anchors[i];
        anchors.ax[lane] = q.localAnchorA.x();
        anchors.ay[lane] = q.localAnchorA.y();
        anchors.bx[lane] = q.localAnchorB.x();
        anchors.by[lane] = q.localAnchorB.y();
    }
}

} // namespace impetus::controller
