// ContactSolver, phase 1: the constraints of a step built from its manifolds, numbered, matched
// with the last step's records for warm starting, and written into their batch lanes.

#include "controller/dynamics/contact_solver.h"
#include "controller/dynamics/contact_solver_detail.h"
#include "controller/dynamics/prefetch.h"

#include "controller/large_arrays.h"
#include "controller/transform.h"
#include "model/constants.h"

#include <algorithm>
#include <array>
#include <variant>

namespace impetus::controller {

using detail::fastestApproach;
using detail::kMaxBlockConditionNumber;
using detail::normalK;
using detail::tangentOf;

namespace {

/// v turned by −θ into a body's frame, given (cos θ, sin θ): the same bits as rotate(v, −θ), since
/// cos(−θ) = cos θ and sin(−θ) = −sin θ exactly.
Vec2 intoFrame(const Vec2& v, const Vec2& rotation)
{
    const Scalar c = rotation.x();
    const Scalar s = -rotation.y();
    return Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y());
}

/// Identifies a pair of pieces; lexicographic order is the broad phase's pair order.
using PairKey = std::array<std::uint32_t, 4>;

PairKey keyOf(const model::ContactRecord& r) { return {r.bodyA.index, r.pieceA, r.bodyB.index, r.pieceB}; }

/// The part of a constraint's record that is known when it is built: its pieces, its points'
/// feature ids, and whether a point is within the touch distance. A contact touches when a point
/// is within the touch distance, or when any impulse acted on it this step (a speculative contact
/// that stopped a fast body a hair before the surface touched): solveImpacts and
/// finishVelocities add the impulses.
void startRecord(const ContactConstraint& c, model::ContactRecord& r)
{
    r.bodyA = model::BodyId{c.ownerA};
    r.pieceA = c.pieceA;
    r.bodyB = model::BodyId{c.ownerB};
    r.pieceB = c.pieceB;
    r.pointCount = static_cast<std::uint8_t>(c.pointCount);
    r.featureIds = {};
    r.normalImpulses = {};
    r.tangentImpulses = {};
    r.touching = false;
    for (std::size_t i = 0; i < static_cast<std::size_t>(c.pointCount); ++i) {
        r.featureIds[i] = c.points[i].id;
        r.touching = r.touching || c.points[i].separation <= constants::kTouchDistance;
    }
}

/// How many constraints ahead buildConstraints() asks for the memory it will read and write.
constexpr std::size_t kBuildPrefetchAhead = 4;

} // namespace

void ContactSolver::prepare(const model::World& world, std::span<const PairManifold> manifolds,
                            std::span<SolverBody> bodies, std::span<const BodyDerivative> derivatives, Scalar h)
{
    // A large world's manifolds are split between two threads. Empty ones (bounding boxes that
    // overlap without contact) make no constraint: counted first, so that each half numbers its
    // constraints straight into their final slots, in order.
    const bool split = m_tasks && manifolds.size() >= constants::kParallelMinConstraints;
    const std::size_t half = split ? manifolds.size() / 2 : manifolds.size();
    const auto nonEmpty = [&](std::size_t begin, std::size_t end) {
        return static_cast<std::size_t>(std::count_if(manifolds.begin() + static_cast<std::ptrdiff_t>(begin),
                                                      manifolds.begin() + static_cast<std::ptrdiff_t>(end),
                                                      [](const PairManifold& pm) { return pm.manifold.count > 0; }));
    };
    std::array<std::size_t, 2> counts{};
    if (split) {
        m_tasks->run([&](int part) {
            counts[static_cast<std::size_t>(part)] = part == 0 ? nonEmpty(0, half) : nonEmpty(half, manifolds.size());
        });
    } else {
        counts[0] = nonEmpty(0, manifolds.size());
    }
    const std::size_t firstCount = counts[0];
    const std::size_t count = counts[0] + counts[1];
    resizeLarge(m_constraints, count);
    resizeLarge(m_constraintBodies, count);
    resizeLarge(m_records, count);
    m_manifoldOf.resize(count);
    m_previousOf.resize(count);
    // Every contact needs its bodies' frames: each body's cosine and sine are taken once.
    computeRotations(bodies, split);
    const std::vector<model::ContactRecord>& previous = world.contacts;
    if (split) {
        m_tasks->run([&](int part) {
            part == 0 ? numberConstraints(manifolds, previous, 0, half, 0)
                      : numberConstraints(manifolds, previous, half, manifolds.size(), firstCount);
        });
    } else {
        numberConstraints(manifolds, previous, 0, manifolds.size(), 0);
    }

    // The solving order comes next, as it needs only the constraints' bodies. Then each group's
    // constraints are built on that group's thread; a batched world writes each into its batch
    // lane while it is at hand.
    partition(bodies);
    if (m_batched) {
        resizeLarge(m_batches, m_batchLanes.size() / kBatchLanes);
        resizeLarge(m_positionBatches, m_batches.size());
        m_touched.assign(m_batches.size(), 0);
    }
    runGroups([&](int g) {
        const auto ug = static_cast<std::size_t>(g);
        buildConstraints(world, manifolds, bodies, derivatives, m_groups[ug], h, ug);
        if (!m_batched)
            return;
        for (std::size_t lane = m_batchGroupStart[ug] * kBatchLanes; lane < m_batchGroupStart[ug + 1] * kBatchLanes; ++lane) {
            if (m_batchLanes[lane] == kNoConstraint)
                packLane(bodies, h, ug, lane);
        }
    });
}

void ContactSolver::numberConstraints(std::span<const PairManifold> manifolds,
                                      const std::vector<model::ContactRecord>& previous, std::size_t begin,
                                      std::size_t end, std::size_t out)
{
    if (begin >= end)
        return;
    // Both lists are sorted by (bodyA, pieceA, bodyB, pieceB): walk them together, from where this
    // range starts.
    const PairManifold& first = manifolds[begin];
    const PairKey firstKey{first.ownerA, first.pieceA, first.ownerB, first.pieceB};
    std::size_t cursor = static_cast<std::size_t>(
        std::lower_bound(previous.begin(), previous.end(), firstKey,
                         [](const model::ContactRecord& r, const PairKey& key) { return keyOf(r) < key; }) -
        previous.begin());
    for (std::size_t k = begin; k < end; ++k) {
        const PairManifold& pm = manifolds[k];
        if (pm.manifold.count == 0)
            continue;
        const PairKey want{pm.ownerA, pm.pieceA, pm.ownerB, pm.pieceB};
        while (cursor < previous.size() && keyOf(previous[cursor]) < want)
            ++cursor;
        m_manifoldOf[out] = static_cast<std::uint32_t>(k);
        m_previousOf[out] =
            cursor < previous.size() && keyOf(previous[cursor]) == want ? static_cast<std::uint32_t>(cursor) : kNoRecord;
        m_constraintBodies[out] = {pm.bodyA, pm.bodyB};
        ++out;
    }
}

void ContactSolver::prefetchForBuild(std::uint32_t index, std::span<const PairManifold> manifolds,
                                     const std::vector<model::ContactRecord>& previous) const
{
    detail::prefetchObject(manifolds[m_manifoldOf[index]]);
    detail::prefetchObject<true>(m_constraints[index]);
    __builtin_prefetch(&m_records[index], 1);
    if (m_previousOf[index] != kNoRecord)
        __builtin_prefetch(&previous[m_previousOf[index]]);
}

void ContactSolver::buildConstraints(const model::World& world, std::span<const PairManifold> manifolds,
                                     std::span<SolverBody> bodies, std::span<const BodyDerivative> derivatives,
                                     std::span<const std::uint32_t> indices, Scalar h, std::size_t part)
{
    const std::vector<model::ContactRecord>& previous = world.contacts;
    m_preparedCandidates[part].clear();
    // Counted in a local and stored once at the end: the m_preparedPoints share a cache line, and
    // the two threads adding to them on every constraint made this loop slower on two threads
    // than on one (0.88 against 0.80 ms on the benchmark pyramid; 0.45 ms without).
    std::size_t points = 0;
    for (std::size_t k = 0; k < indices.size(); ++k) {
        // As in refresh(): the memory of a constraint a few ahead is asked for while this one is
        // built (its bodies later than the rest, as their indices come with its manifold).
        if (k + kBuildPrefetchAhead < indices.size())
            prefetchForBuild(indices[k + kBuildPrefetchAhead], manifolds, previous);
        if (k + kBuildPrefetchAhead / 2 < indices.size()) {
            const PairManifold& later = manifolds[m_manifoldOf[indices[k + kBuildPrefetchAhead / 2]]];
            prefetchPairBodies(later.bodyA, later.bodyB, bodies, derivatives);
        }
        const std::uint32_t index = indices[k];
        const PairManifold& pm = manifolds[m_manifoldOf[index]];
        ContactConstraint& c = m_constraints[index];
        c = ContactConstraint{};
        c.bodyA = pm.bodyA;
        c.pieceA = pm.pieceA;
        c.bodyB = pm.bodyB;
        c.pieceB = pm.pieceB;
        c.ownerA = pm.ownerA;
        c.ownerB = pm.ownerB;
        c.normal = pm.manifold.normal;
        c.pointCount = pm.manifold.count;
        const SolverBody& a = bodies[c.bodyA];
        const SolverBody& b = bodies[c.bodyB];
        c.friction = mixFriction(a.friction, b.friction);
        c.restitution = mixRestitution(a.restitution, b.restitution);
        c.localNormalA = intoFrame(c.normal, m_rotations[c.bodyA]);
        c.roundA = a.round;
        c.roundB = b.round;

        const model::ContactRecord* match = m_previousOf[index] == kNoRecord ? nullptr : &previous[m_previousOf[index]];

        const Vec2 t = tangentOf(c.normal);
        const BodyDerivative& da = derivatives[c.bodyA];
        const BodyDerivative& db = derivatives[c.bodyB];
        for (int i = 0; i < c.pointCount; ++i) {
            const ContactPoint& mp = pm.manifold.points[static_cast<std::size_t>(i)];
            ContactConstraintPoint& p = c.points[static_cast<std::size_t>(i)];
            p.id = mp.id;
            p.separation = mp.separation;
            p.closingGap = mp.separation;
            p.point = mp.point;
            p.rA = mp.point - a.position;
            p.rB = mp.point - b.position;
            const Vec2 surfaceA = mp.point - 0.5 * mp.separation * c.normal;
            const Vec2 surfaceB = mp.point + 0.5 * mp.separation * c.normal;
            p.localAnchorA = intoFrame(Vec2(surfaceA - a.position), m_rotations[c.bodyA]);
            p.localAnchorB = intoFrame(Vec2(surfaceB - b.position), m_rotations[c.bodyB]);
            p.normalMass = effectiveMass(a, b, p.rA, p.rB, c.normal);
            p.tangentMass = effectiveMass(a, b, p.rA, p.rB, t);
            // Relative acceleration of the two material points along the normal under the smooth
            // forces (the centripetal terms are second order over one step and left out).
            const Vec2 accA = da.acceleration + cross(da.angularAcceleration, p.rA);
            const Vec2 accB = db.acceleration + cross(db.angularAcceleration, p.rB);
            p.normalAcceleration = (accB - accA).dot(c.normal);
            p.startNormalVelocity = relativeVelocity(a, b, p.rA, p.rB).dot(c.normal);
            if (match) {
                for (std::size_t j = 0; j < match->pointCount; ++j) {
                    if (match->featureIds[j] == p.id) {
                        p.normalImpulse = match->normalImpulses[j];
                        p.tangentImpulse = match->tangentImpulses[j];
                    }
                }
            }
        }

        // A manifold that carried load in the last step is resting as a whole: its points share
        // the load unevenly from step to step, and an unloaded corner of a resting box is not
        // struck when the box settles onto it.
        // A manifold that still approaches faster than a resting one can did not rest: its load
        // was a speculative contact's, which stopped the bodies at the surface with their approach
        // left over (a ball whose step ends on the floor while it falls). It is struck as an
        // impact, or an elastic ball would stop dead (issue 17, F1).
        bool loaded = false;
        bool approaching = false;
        for (int i = 0; i < c.pointCount; ++i) {
            const ContactConstraintPoint& p = c.points[static_cast<std::size_t>(i)];
            loaded = loaded || p.normalImpulse > 0;
            approaching = approaching || p.startNormalVelocity < -constants::kRestingImpactThreshold;
        }
        loaded = loaded && !approaching;
        for (int i = 0; i < c.pointCount; ++i)
            c.points[static_cast<std::size_t>(i)].carriesLoad = loaded;

        if (c.pointCount == 2) {
            const Eigen::Matrix2d twoPoint = normalK(c, a, b);
            c.blockSolve = twoPoint(0, 0) * twoPoint(0, 0) < kMaxBlockConditionNumber * twoPoint.determinant();
        }

        // What solveImpacts() starts from, the record and the batch lane, while the constraint is
        // at hand.
        startRecord(c, m_records[index]);
        points += static_cast<std::size_t>(c.pointCount);
        if (const Scalar fastest = fastestApproach(c, bodies, h); fastest < 0)
            m_preparedCandidates[part].push_back({fastest, index, 0});
        if (m_batched)
            packLane(bodies, h, part, m_laneOf[index]);
    }
    m_preparedPoints[part] = points;
}

} // namespace impetus::controller
