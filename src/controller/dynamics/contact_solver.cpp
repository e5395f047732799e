#include "controller/dynamics/contact_solver.h"

#include "controller/transform.h"
#include "model/constants.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <optional>

namespace impetus::controller {

namespace {

/// The 2×2 block solve is used only when K's condition number stays below this: two contact
/// points that (nearly) coincide make K singular, and then the points are solved one at a time.
constexpr Scalar kMaxBlockConditionNumber = 1000.0;

/// The allowed approach speed of a batch lane's missing second point, m/s: so large that the
/// point can never become active, and still finite, so that no lane ever computes ∞ − ∞.
constexpr Scalar kUnreachableGapSpeed = 1e300;

/// The tangent of a contact: the normal turned clockwise, so (n, t) is a right-handed pair.
Vec2 tangentOf(const Vec2& n) { return Vec2(n.y(), -n.x()); }

/// Time t in (0, h] at which a gap s closes under relative normal velocity vn and acceleration a:
/// the smallest root of s + vn·t + ½a·t² = 0. Negative when the gap does not close within h.
Scalar timeToClose(Scalar s, Scalar vn, Scalar a, Scalar h)
{
    // Evaluate at h first: most gaps stay open, and this keeps the common case cheap.
    if (s + vn * h + 0.5 * a * h * h > 0) {
        // Still open at h; it may have closed and reopened inside the step only if it turns
        // around, i.e. vn < 0 < a. Check the minimum of the parabola.
        if (!(vn < 0 && a > 0))
            return -1;
        const Scalar tMin = -vn / a;
        if (tMin > h || s + vn * tMin + 0.5 * a * tMin * tMin > 0)
            return -1;
    }
    if (std::abs(a) < 1e-12)
        return vn < 0 ? -s / vn : -1;
    // Stable form of the smaller positive root of ½a·t² + vn·t + s = 0.
    const Scalar disc = vn * vn - 2 * a * s;
    if (disc < 0)
        return -1;
    const Scalar q = -(vn - std::sqrt(disc)); // vn < 0 on the approaching branch, so q > 0
    const Scalar t1 = q / a;
    const Scalar t2 = 2 * s / q;
    Scalar t = std::numeric_limits<Scalar>::infinity();
    for (const Scalar candidate : {t1, t2}) {
        if (candidate > 0 && candidate < t)
            t = candidate;
    }
    return t <= h ? t : -1;
}

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

/// Solves the complementarity problem x ≥ 0, w = b + K·x ≥ 0, xᵢwᵢ = 0 for one or two points by
/// enumerating the active sets (exact for two points). Returns x.
/// `kInverse` is K⁻¹ when count is 2 and K is regular (any value otherwise).
Eigen::Vector2d solveTwoPointLcp(const Eigen::Matrix2d& k, const Eigen::Matrix2d& kInverse, const Eigen::Vector2d& b,
                                 int count)
{
    if (count == 1) {
        const Scalar x = k(0, 0) > 0 ? std::max(0.0, -b(0) / k(0, 0)) : 0.0;
        return Eigen::Vector2d(x, 0);
    }
    const Scalar det = k(0, 0) * k(1, 1) - k(0, 1) * k(1, 0);
    if (std::abs(det) > 0) {
        const Eigen::Vector2d x = -kInverse * b;
        if (x(0) >= 0 && x(1) >= 0)
            return x;
    }
    if (k(0, 0) > 0) {
        const Scalar x1 = -b(0) / k(0, 0);
        if (x1 >= 0 && k(1, 0) * x1 + b(1) >= 0)
            return Eigen::Vector2d(x1, 0);
    }
    if (k(1, 1) > 0) {
        const Scalar x2 = -b(1) / k(1, 1);
        if (x2 >= 0 && k(0, 1) * x2 + b(0) >= 0)
            return Eigen::Vector2d(0, x2);
    }
    return Eigen::Vector2d::Zero();
}

/// When point p of constraint c meets this step (as a fraction τ of h), and how fast it
/// approaches then. τ < 0: it does not meet within the step, or it is a resting contact: one
/// that carried load in the last step is held by contact forces, not struck (otherwise the
/// small residual sinking of a tall stack would set off a cascade of plastic "impacts").
struct Approach {
    Scalar tau = -1;
    Scalar velocity = 0;
};

Approach approachOf(const ContactConstraint& c, const ContactConstraintPoint& p, std::span<const SolverBody> bodies,
                    Scalar h)
{
    Approach result;
    const SolverBody& a = bodies[c.bodyA];
    const SolverBody& b = bodies[c.bodyB];
    // A resting contact stays out of the impact pass until an impact strikes one of its
    // bodies: then the blow travels on through it (a ball dropped on a ball resting on the
    // floor bounces back up, as a vertical Newton's cradle does). A plastic one (e = 0) stays
    // out for good: the contact forces already give a plastic blow its exact outcome, and
    // passing it on impact by impact through a landing pile costs thousands of impacts.
    if (p.carriesLoad && (c.restitution == 0 || (!a.hadImpact && !b.hadImpact)))
        return result;
    // Two plastic surfaces already touching are left to the contact forces too, whatever their
    // approach: the forces stop the approach exactly as a plastic impact would, with friction
    // within μ times the same normal impulse. Struck one at a time instead, a pile whose contacts
    // lose and regain their load (a tall stack at a long step) passed each blow on impact by
    // impact: 10,000 impacts and 75 ms in one step of a 50-row pyramid at 1/60 s.
    if (c.restitution == 0 && p.separation <= constants::kTouchDistance)
        return result;
    const Scalar threshold = p.carriesLoad ? constants::kRestingImpactThreshold : constants::kRestitutionThreshold;
    const Scalar vn = relativeVelocity(a, b, p.rA, p.rB).dot(c.normal);
    if (p.separation <= constants::kTouchDistance) {
        result.tau = 0;
    } else {
        const Scalar t = timeToClose(p.separation, vn, p.normalAcceleration, h);
        if (t < 0)
            return result;
        result.tau = t / h;
    }
    result.velocity = vn + p.normalAcceleration * result.tau * h;
    if (result.velocity >= -threshold)
        result.tau = -1; // not an impact: too slow for this kind of contact
    return result;
}

/// The fastest approach among c's points that is an impact this step, m/s (< 0); nothing when none is.
std::optional<Scalar> fastestApproach(const ContactConstraint& c, std::span<const SolverBody> bodies, Scalar h)
{
    Scalar fastest = -constants::kRestitutionThreshold;
    bool approaching = false;
    for (int i = 0; i < c.pointCount; ++i) {
        const Approach ap = approachOf(c, c.points[static_cast<std::size_t>(i)], bodies, h);
        if (ap.tau >= 0 && ap.velocity < fastest) {
            fastest = ap.velocity;
            approaching = true;
        }
    }
    return approaching ? std::optional<Scalar>(fastest) : std::nullopt;
}

/// The effective-mass matrix K of a contact's normal impulses, 1/kg: for two points the 2×2 matrix
/// of the block solve; for one, K₁₁ = 1/(its normal mass) and the rest 0.
Eigen::Matrix2d normalK(const ContactConstraint& c, const SolverBody& a, const SolverBody& b)
{
    Eigen::Matrix2d k = Eigen::Matrix2d::Zero();
    const ContactConstraintPoint& p1 = c.points[0];
    if (c.pointCount != 2) {
        k(0, 0) = p1.normalMass > 0 ? 1 / p1.normalMass : 0;
        return k;
    }
    const ContactConstraintPoint& p2 = c.points[1];
    const Scalar rn1A = cross(p1.rA, c.normal);
    const Scalar rn1B = cross(p1.rB, c.normal);
    const Scalar rn2A = cross(p2.rA, c.normal);
    const Scalar rn2B = cross(p2.rB, c.normal);
    const Scalar m = a.invMass + b.invMass;
    const Scalar k11 = m + a.invInertia * rn1A * rn1A + b.invInertia * rn1B * rn1B;
    const Scalar k22 = m + a.invInertia * rn2A * rn2A + b.invInertia * rn2B * rn2B;
    const Scalar k12 = m + a.invInertia * rn1A * rn2A + b.invInertia * rn1B * rn2B;
    k << k11, k12, k12, k22;
    return k;
}

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

/// One non-linear Gauss–Seidel update of one constraint's positions. `rotations` holds every
/// body's cos and sin of its current angle, kept up to date here when a body turns. Returns the
/// deepest separation it saw (≤ 0), m.
Scalar solvePositionConstraint(const ContactConstraint& c, std::span<SolverBody> bodies, std::span<Vec2> rotations)
{
    Scalar deepest = 0;
    SolverBody& a = bodies[c.bodyA];
    SolverBody& b = bodies[c.bodyB];
    for (int i = 0; i < c.pointCount; ++i) {
        const ContactConstraintPoint& p = c.points[static_cast<std::size_t>(i)];
        // Current separation of the two surface points along the normal, which turns with A.
        const Vec2& rotationA = rotations[c.bodyA];
        const Vec2& rotationB = rotations[c.bodyB];
        const Transform frameA{a.position, rotationA.x(), rotationA.y()};
        const Transform frameB{b.position, rotationB.x(), rotationB.y()};
        const Vec2 n = frameA.rotate(c.localNormalA);
        const Vec2 pointA = frameA.apply(p.localAnchorA);
        const Vec2 pointB = frameB.apply(p.localAnchorB);
        const Scalar separation = (pointB - pointA).dot(n);
        deepest = std::min(deepest, separation);

        const Scalar correction =
            std::clamp(constants::kPositionCorrectionFactor * (separation + constants::kLinearSlop),
                       -constants::kMaxPositionCorrection, 0.0);
        if (correction == 0)
            continue;
        const Vec2 mid = 0.5 * (pointA + pointB);
        const Vec2 rA = mid - a.position;
        const Vec2 rB = mid - b.position;
        const Scalar mass = effectiveMass(a, b, rA, rB, n);
        applyPositionImpulse(a, b, rA, rB, Vec2((-correction * mass) * n));
        // A resting point within the slop moves nothing: the sine and cosine are computed again
        // only for a body that turned, not at every look.
        if (movable(a))
            rotations[c.bodyA] = Vec2(std::cos(a.angle), std::sin(a.angle));
        if (movable(b))
            rotations[c.bodyB] = Vec2(std::cos(b.angle), std::sin(b.angle));
    }
    return deepest;
}

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

/// Ends point i of a record with the impulses of the velocity passes; a point that carries a
/// normal impulse touches.
void finishRecord(model::ContactRecord& r, std::size_t i, Scalar normalImpulse, Scalar tangentImpulse)
{
    r.normalImpulses[i] = normalImpulse;
    r.tangentImpulses[i] = tangentImpulse;
    r.touching = r.touching || normalImpulse > 0;
}

} // namespace

Scalar mixRestitution(Scalar a, Scalar b) { return std::max(a, b); }

Scalar mixFriction(Scalar a, Scalar b) { return std::sqrt(a * b); }

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
    m_constraints.resize(count);
    m_constraintBodies.resize(count);
    m_records.resize(count);
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
        m_batches.resize(m_batchLanes.size() / kBatchLanes);
        m_positionBatches.resize(m_batches.size());
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
    for (const std::uint32_t index : indices) {
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

        const model::ContactRecord* match = m_previousOf[index] == kNoRecord ? nullptr : &previous[m_previousOf[index]];

        const Vec2 t = tangentOf(c.normal);
        const BodyDerivative& da = derivatives[c.bodyA];
        const BodyDerivative& db = derivatives[c.bodyB];
        for (int i = 0; i < c.pointCount; ++i) {
            const ContactPoint& mp = pm.manifold.points[static_cast<std::size_t>(i)];
            ContactConstraintPoint& p = c.points[static_cast<std::size_t>(i)];
            p.id = mp.id;
            p.separation = mp.separation;
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
        bool loaded = false;
        for (int i = 0; i < c.pointCount; ++i)
            loaded = loaded || c.points[static_cast<std::size_t>(i)].normalImpulse > 0;
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
        if (const std::optional<Scalar> fastest = fastestApproach(c, bodies, h))
            m_preparedCandidates[part].push_back({*fastest, index, 0});
        if (m_batched)
            packLane(bodies, h, part, m_laneOf[index]);
    }
    m_preparedPoints[part] = points;
}

int ContactSolver::solveImpacts(std::span<SolverBody> bodies, Scalar h)
{
    m_impulseTimeline.clear();
    m_lastTimedImpulse.assign(bodies.size(), kNoImpulse);
    const std::size_t totalPoints = m_preparedPoints[0] + m_preparedPoints[1] + m_preparedPoints[2];
    const std::size_t maxImpacts = totalPoints * static_cast<std::size_t>(constants::kMaxImpactsPerPoint);

    // The fastest approach first: a collision happens before the ones it causes. A heap holds the
    // approaching constraints by their fastest point; an impact changes only its two bodies, so
    // only their constraints are looked at again (entries made stale by that carry an old
    // version and are skipped).
    const auto later = [](const Candidate& x, const Candidate& y) {
        return x.velocity != y.velocity ? x.velocity > y.velocity : x.constraint > y.constraint;
    };
    std::vector<Candidate>& heap = m_candidates;
    heap.clear();
    m_versions.assign(m_constraints.size(), 0);
    const auto consider = [&](std::uint32_t ci) {
        if (const std::optional<Scalar> fastest = fastestApproach(m_constraints[ci], bodies, h)) {
            heap.push_back({*fastest, ci, m_versions[ci]});
            std::push_heap(heap.begin(), heap.end(), later);
        }
    };
    // prepare() found the constraints that approach at the start, while it had them at hand.
    for (const std::vector<Candidate>& found : m_preparedCandidates)
        heap.insert(heap.end(), found.begin(), found.end());
    std::make_heap(heap.begin(), heap.end(), later);

    // Which constraints each body takes part in, to find those an impact affects. Built only
    // when some contact approaches: a resting scene, the common case, never needs it.
    if (!heap.empty()) {
        m_bodyConstraintStart.assign(bodies.size() + 1, 0);
        for (const auto& [bodyA, bodyB] : m_constraintBodies) {
            ++m_bodyConstraintStart[bodyA + 1];
            ++m_bodyConstraintStart[bodyB + 1];
        }
        for (std::size_t i = 0; i < bodies.size(); ++i)
            m_bodyConstraintStart[i + 1] += m_bodyConstraintStart[i];
        m_bodyConstraints.resize(m_bodyConstraintStart.back());
        std::vector<std::uint32_t>& fill = m_bodyConstraintFill;
        fill.assign(m_bodyConstraintStart.begin(), m_bodyConstraintStart.end() - 1);
        for (std::uint32_t ci = 0; ci < m_constraints.size(); ++ci) {
            m_bodyConstraints[fill[m_constraintBodies[ci][0]]++] = ci;
            m_bodyConstraints[fill[m_constraintBodies[ci][1]]++] = ci;
        }
    }

    int resolved = 0;
    while (!heap.empty() && static_cast<std::size_t>(resolved) < maxImpacts) {
        std::pop_heap(heap.begin(), heap.end(), later);
        const Candidate top = heap.back();
        heap.pop_back();
        if (top.version != m_versions[top.constraint])
            continue;
        const std::size_t best = top.constraint;
        ++resolved;

        ContactConstraint& c = m_constraints[best];
        SolverBody& a = bodies[c.bodyA];
        SolverBody& b = bodies[c.bodyB];

        // The points that meet this step, with their lever arms at the time of impact: both
        // bodies have moved on to where they are at τh, and so has the contact point (half-way
        // between the two surface points, which move with the material). One common point for
        // both bodies keeps every impulse's angular effect exactly internal, so angular momentum
        // is conserved to rounding by the impacts.
        struct ImpactPoint {
            std::size_t index = 0;
            Scalar tau = 0;
            Scalar velocity = 0;
            Vec2 rA = Vec2::Zero();
            Vec2 rB = Vec2::Zero();
        };
        std::array<ImpactPoint, 2> points{};
        int count = 0;
        for (int i = 0; i < c.pointCount; ++i) {
            const auto ui = static_cast<std::size_t>(i);
            const ContactConstraintPoint& p = c.points[ui];
            const Approach ap = approachOf(c, p, bodies, h);
            if (ap.tau < 0)
                continue;
            const Vec2 centreA = positionAt(c.bodyA, a, ap.tau, h);
            const Vec2 centreB = positionAt(c.bodyB, b, ap.tau, h);
            const Vec2 common = 0.5 * (centreA + p.rA + centreB + p.rB);
            ImpactPoint& ip = points[static_cast<std::size_t>(count++)];
            ip.index = ui;
            ip.tau = ap.tau;
            ip.velocity = ap.velocity;
            ip.rA = common - centreA;
            ip.rB = common - centreB;
        }

        // Effective-mass matrix at those arms, and each point's distance from its target: a point
        // approaching faster than the threshold must leave at e times its approach speed, any
        // other may only stop approaching.
        Eigen::Matrix2d k = Eigen::Matrix2d::Zero();
        Eigen::Vector2d bias = Eigen::Vector2d::Zero();
        for (int i = 0; i < count; ++i) {
            const ImpactPoint& pi = points[static_cast<std::size_t>(i)];
            for (int j = 0; j < count; ++j) {
                const ImpactPoint& pj = points[static_cast<std::size_t>(j)];
                k(i, j) = a.invMass + b.invMass + a.invInertia * cross(pi.rA, c.normal) * cross(pj.rA, c.normal) +
                          b.invInertia * cross(pi.rB, c.normal) * cross(pj.rB, c.normal);
            }
            const Scalar target = pi.velocity < -constants::kRestitutionThreshold ? -c.restitution * pi.velocity : 0;
            bias(i) = pi.velocity - target;
        }
        if (count == 2 && !(k(0, 0) * k(0, 0) < kMaxBlockConditionNumber * k.determinant())) {
            // Two (nearly) coincident points: resolve the faster one alone.
            if (bias(1) < bias(0)) {
                std::swap(points[0], points[1]);
                bias(0) = bias(1);
                k(0, 0) = k(1, 1);
            }
            count = 1;
        }
        const Eigen::Vector2d x = solveTwoPointLcp(k, count == 2 ? Eigen::Matrix2d(k.inverse()) : k, bias, count);

        const Vec2 t = tangentOf(c.normal);
        for (int i = 0; i < count; ++i) {
            const ImpactPoint& ip = points[static_cast<std::size_t>(i)];
            ContactConstraintPoint& p = c.points[ip.index];
            applyImpactImpulse(c, ip.rA, ip.rB, ip.tau, x(i) * c.normal, bodies);
            if (!p.impacted) {
                p.approachVelocity = ip.velocity;
                p.point = positionAt(c.bodyA, a, ip.tau, h) + ip.rA;
            }
            p.impacted = true;
            p.impactImpulse += x(i);
            if (p.impactImpulse > 0)
                m_records[best].touching = true;
        }

        // Coulomb friction during the impact: stop the sliding at each point, within μ·jn.
        for (int i = 0; i < count; ++i) {
            const ImpactPoint& ip = points[static_cast<std::size_t>(i)];
            const Scalar vt = relativeVelocity(a, b, ip.rA, ip.rB).dot(t);
            const Scalar limit = c.friction * x(i);
            const Scalar jt = std::clamp(-vt * effectiveMass(a, b, ip.rA, ip.rB, t), -limit, limit);
            applyImpactImpulse(c, ip.rA, ip.rB, ip.tau, jt * t, bodies);
        }
        // Only a body that can move has been struck (a fixed body's contacts keep their status).
        for (SolverBody* body : {&a, &b}) {
            if (movable(*body))
                body->hadImpact = true;
        }

        // Everything touching a body that just changed velocity may now approach (or stop).
        // Fixed bodies never change, so their many contacts need no second look.
        for (const std::uint32_t body : {c.bodyA, c.bodyB}) {
            if (!movable(bodies[body]))
                continue;
            for (std::uint32_t at = m_bodyConstraintStart[body]; at < m_bodyConstraintStart[body + 1]; ++at) {
                const std::uint32_t cj = m_bodyConstraints[at];
                ++m_versions[cj];
                consider(cj);
            }
        }
    }
    return resolved;
}

Vec2 ContactSolver::positionAt(std::uint32_t index, const SolverBody& body, Scalar tau, Scalar h) const
{
    // x(τ) = x₀ + τh·v₀ + Σⱼ max(0, τ − τⱼ)·h·Δvⱼ, written with the current velocity
    // v = v₀ + Σⱼ Δvⱼ as x₀ + τh·v − h·Σⱼ min(τ, τⱼ)·Δvⱼ, over this body's impulses only.
    Vec2 x = body.position + (tau * h) * body.velocity;
    for (std::uint32_t k = m_lastTimedImpulse[index]; k != kNoImpulse; k = m_impulseTimeline[k].previous)
        x -= (h * std::min(tau, m_impulseTimeline[k].tau)) * m_impulseTimeline[k].velocityChange;
    return x;
}

void ContactSolver::applyImpactImpulse(const ContactConstraint& c, const Vec2& rA, const Vec2& rB, Scalar tau,
                                       const Vec2& impulse, std::span<SolverBody> bodies)
{
    SolverBody& a = bodies[c.bodyA];
    SolverBody& b = bodies[c.bodyB];
    applyImpulse(a, b, rA, rB, impulse);
    a.firstImpactTau = std::min(a.firstImpactTau, tau);
    b.firstImpactTau = std::min(b.firstImpactTau, tau);
    const Vec2 dvA = -a.invMass * impulse;
    const Vec2 dvB = b.invMass * impulse;
    a.impactLateVelocity += tau * dvA;
    a.impactLateAngularVelocity -= tau * a.invInertia * cross(rA, impulse);
    b.impactLateVelocity += tau * dvB;
    b.impactLateAngularVelocity += tau * b.invInertia * cross(rB, impulse);
    for (const auto& [body, dv] : {std::pair{c.bodyA, dvA}, std::pair{c.bodyB, dvB}}) {
        if (!movable(bodies[body]))
            continue; // a fixed body's motion never changes: nothing to remember
        m_impulseTimeline.push_back({m_lastTimedImpulse[body], tau, dv});
        m_lastTimedImpulse[body] = static_cast<std::uint32_t>(m_impulseTimeline.size() - 1);
    }
}

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
                q.gapSpeed = std::max(p.separation, 0.0) / h;
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

void ContactSolver::finishVelocities(std::span<SolverBody> bodies)
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
    // The velocities go back to the bodies, each half's on its own thread (unless every pass has
    // handed them back already). Each group writes its own records and marks its own movable
    // bodies, so the halves of a split world can do this side by side too.
    if (!m_sharedVelocities)
        copyVelocitiesOut(bodies);
    runGroups([&](int g) {
        const auto ug = static_cast<std::size_t>(g);
        for (std::size_t bi = m_batchGroupStart[ug]; bi < m_batchGroupStart[ug + 1]; ++bi) {
            const ContactBatch& batch = m_batches[bi];
            for (int lane = 0; lane < kBatchLanes; ++lane) {
                const auto ul = static_cast<std::size_t>(lane);
                const std::uint32_t ci = m_batchLanes[bi * kBatchLanes + ul];
                if (ci == kNoConstraint)
                    continue;
                model::ContactRecord& r = m_records[ci];
                for (std::size_t i = 0; i < r.pointCount; ++i)
                    finishRecord(r, i, batch.points[i].normalImpulse[lane], batch.points[i].tangentImpulse[lane]);
                if (batch.acted[lane] != 0)
                    markContactForce(bodies[m_constraintBodies[ci][0]], bodies[m_constraintBodies[ci][1]]);
            }
        }
    });
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
            groupDeepest = std::min(groupDeepest, solvePositionConstraint(m_constraints[ci], bodies, m_rotations));
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
    if (turnedElsewhere) {
        inSlotHalves(m_bodyOfSlot.size(), [&](std::size_t begin, std::size_t end) {
            for (std::size_t slot = begin; slot < end; ++slot) {
                const SolverBody& body = bodies[m_bodyOfSlot[slot]];
                m_poses[slot] = BatchPose{body.position.x(), body.position.y(), body.angle, std::cos(body.angle),
                                          std::sin(body.angle)};
            }
        });
    }
    std::array<Scalar, 3> deepest{};
    runGroups([&](int g) {
        const auto ug = static_cast<std::size_t>(g);
        deepest[ug] = solvePositionBatches(std::span<const PositionBatch>(m_positionBatches)
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

void ContactSolver::partition(std::span<const SolverBody> bodies)
{
    for (std::vector<std::uint32_t>& group : m_groups)
        group.clear();
    m_split = m_constraints.size() >= constants::kParallelMinConstraints;
    m_batched = m_constraints.size() >= m_batchMinConstraints && !m_constraints.empty();
    if (!m_split) {
        m_groups[0].resize(m_constraints.size());
        for (std::uint32_t ci = 0; ci < m_constraints.size(); ++ci)
            m_groups[0][ci] = ci;
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
    // never write to them. A pile needs about a dozen colours; a constraint that finds all 64
    // taken is solved on its own after the batches.
    constexpr int kColours = 64;
    const std::vector<std::uint32_t>& group = m_groups[g];
    std::vector<std::uint32_t>& lanesOut = m_groupLanes[g];
    lanesOut.clear();
    if (group.empty())
        return;
    // The constraints joining the halves meet bodies that the halves have coloured already.
    if (g == 2) {
        for (const std::uint32_t ci : group) {
            m_colourMasks[m_constraintBodies[ci][0]] = 0;
            m_colourMasks[m_constraintBodies[ci][1]] = 0;
        }
    }
    std::vector<std::uint8_t>& colourOf = m_colourOf[g];
    colourOf.resize(group.size());
    std::array<std::size_t, kColours + 1> count{};
    for (std::size_t k = 0; k < group.size(); ++k) {
        const auto [bodyA, bodyB] = m_constraintBodies[group[k]];
        const bool moveA = movable(bodies[bodyA]);
        const bool moveB = movable(bodies[bodyB]);
        const std::uint64_t taken = (moveA ? m_colourMasks[bodyA] : 0) | (moveB ? m_colourMasks[bodyB] : 0);
        const int colour = std::countr_one(taken);
        colourOf[k] = static_cast<std::uint8_t>(colour);
        ++count[static_cast<std::size_t>(colour)];
        if (colour == kColours)
            continue;
        const std::uint64_t bit = std::uint64_t{1} << colour;
        if (moveA)
            m_colourMasks[bodyA] |= bit;
        if (moveB)
            m_colourMasks[bodyB] |= bit;
    }
    // Each colour fills whole pairs of batches (kBatchPair), the last one padded: lay the lanes
    // out colour by colour, keeping the group's order within a colour.
    constexpr std::size_t kColourStep = kBatchLanes * kBatchPair;
    std::array<std::size_t, kColours> firstLane{};
    std::size_t lanes = 0;
    for (std::size_t colour = 0; colour < kColours; ++colour) {
        firstLane[colour] = lanes;
        lanes += (count[colour] + kColourStep - 1) / kColourStep * kColourStep;
    }
    // A constraint that found every colour taken gets a pair of batches of its own, after the
    // others.
    lanesOut.resize(lanes + count[kColours] * kColourStep, kNoConstraint);
    for (std::size_t k = 0; k < group.size(); ++k) {
        const std::size_t lane = colourOf[k] < kColours ? firstLane[colourOf[k]]++ : lanes;
        if (colourOf[k] == kColours)
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
        v.gapSpeed[lane] = p ? std::max(q.separation, 0.0) / h : kUnreachableGapSpeed;
        PositionBatch::Anchors& anchors = positions.anchors[i];
        anchors.ax[lane] = q.localAnchorA.x();
        anchors.ay[lane] = q.localAnchorA.y();
        anchors.bx[lane] = q.localAnchorB.x();
        anchors.by[lane] = q.localAnchorB.y();
    }
}

void ContactSolver::computeRotations(std::span<const SolverBody> bodies, bool split)
{
    m_rotations.resize(bodies.size());
    inHalves(split ? m_tasks : nullptr, bodies.size(), [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
            m_rotations[i] = Vec2(std::cos(bodies[i].angle), std::sin(bodies[i].angle));
    });
}

void ContactSolver::runGroups(const std::function<void(int)>& solve)
{
    if (m_split && m_tasks) {
        m_tasks->run(solve);
    } else {
        solve(0);
        solve(1);
    }
    solve(2);
}

void ContactSolver::forEachGroupIndex(const std::function<void(std::span<const std::uint32_t>, int)>& solve)
{
    runGroups([&](int g) { solve(m_groups[static_cast<std::size_t>(g)], g); });
}

void ContactSolver::forEachGroup(const std::function<void(std::span<VelocityConstraint>, int)>& solve)
{
    runGroups([&](int g) {
        const auto ug = static_cast<std::size_t>(g);
        solve(std::span<VelocityConstraint>(m_velocityConstraints).subspan(m_groupStart[ug],
                                                                           m_groupStart[ug + 1] - m_groupStart[ug]),
              g);
    });
}

} // namespace impetus::controller
