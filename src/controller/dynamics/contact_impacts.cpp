// ContactSolver, phase 2: impacts with restitution, resolved one at a time at their time of
// impact, the fastest approach first (docs/physics.md, "Collisions and contacts").

#include "controller/dynamics/contact_solver.h"
#include "controller/dynamics/contact_solver_detail.h"

#include "model/constants.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>
#include <utility>

namespace impetus::controller {

using detail::fastestApproach;
using detail::kMaxBlockConditionNumber;
using detail::kMaxFixedImpactsPerContact;
using detail::kMaxImpactVisitsPerContact;
using detail::kMinImpactVisits;
using detail::tangentOf;

namespace {

/// The least fraction of a step a struck body's speculative contacts count as left after its last
/// impact: an impact at the very end of the step leaves its gap to the next step.
constexpr Scalar kShortestRemainder = 1e-9;

/// A fixed body that moves (an arm, a turning wall): it can close on a body without giving way.
bool moving(const SolverBody& body) { return body.velocity != Vec2::Zero() || body.angularVelocity != 0; }

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

/// Where the gap of point p stands at τ₀·h, the latest impact on either body so far this step:
/// from then on both bodies keep the velocities they have now (until the next impact), so a gap
/// that the impacts opened or closed is measured there, not at the step's start. The surface
/// points move with their bodies, turning with them.
struct GapAt {
    Scalar gap = 0; ///< m
    Scalar velocity = 0; ///< relative normal velocity then, without the smooth forces' share, m/s
};

/// A rigid circle's surface point facing the other piece stays facing it however the circle
/// turns (ContactSolver::refresh does the same): only other shapes' surface points turn.
Scalar surfaceTurnAt(std::uint32_t index, const SolverBody& body, Scalar tau, Scalar h, const ContactSolver& impacts)
{
    return body.round > 0 ? 0 : impacts.turnAt(index, body, tau, h);
}

/// Where an impact acts, world frame, m, given the two surface points of its contact point at its
/// time: half-way between them, or, when exactly one of the two pieces is a rigid circle, at the
/// circle's own surface point facing the other piece.
/// The two surface points were matched at the step's start: a circle that slides fast along the
/// other piece before it meets it (600 m/s along a wall, soak seed 176) leaves its start's mate
/// far behind, and the point half-way to it is off the circle's normal line, where the circle's
/// spin (800 rad/s) made up a normal velocity of hundreds of m/s that the impact then "answered",
/// sending the circle into the wall. The circle's facing point is where it meets a flat face
/// wherever it slid to, and on its normal line its spin adds nothing to the approach.
Vec2 impactPointOf(const ContactConstraint& c, std::span<const SolverBody> bodies, const Vec2& surfaceA,
                   const Vec2& surfaceB)
{
    const bool roundA = bodies[c.bodyA].round > 0;
    const bool roundB = bodies[c.bodyB].round > 0;
    if (roundA != roundB)
        return roundA ? surfaceA : surfaceB;
    return 0.5 * (surfaceA + surfaceB);
}

/// Point p of a contact at τ·h of the step, world frame, m: both bodies' centres and p's two
/// surface points, each moved and turned with its body as solveImpacts has left it so far (the
/// surface points meet at the time of impact), and the lever arms from the centres to the point
/// where an impact then acts (impactPointOf), which is also where its approach is measured.
struct PointAt {
    Vec2 surfaceA = Vec2::Zero();
    Vec2 surfaceB = Vec2::Zero();
    Vec2 armA = Vec2::Zero();
    Vec2 armB = Vec2::Zero();
};

PointAt pointAt(const ContactConstraint& c, const ContactConstraintPoint& p, std::span<const SolverBody> bodies,
                Scalar tau, Scalar h, const ContactSolver& impacts)
{
    const SolverBody& a = bodies[c.bodyA];
    const SolverBody& b = bodies[c.bodyB];
    const Vec2 centreA = impacts.positionAt(c.bodyA, a, tau, h);
    const Vec2 centreB = impacts.positionAt(c.bodyB, b, tau, h);
    PointAt at;
    at.surfaceA = centreA + impacts.turnedWith(c.bodyA, Vec2(p.rA - 0.5 * p.separation * c.normal),
                                               surfaceTurnAt(c.bodyA, a, tau, h, impacts));
    at.surfaceB = centreB + impacts.turnedWith(c.bodyB, Vec2(p.rB + 0.5 * p.separation * c.normal),
                                               surfaceTurnAt(c.bodyB, b, tau, h, impacts));
    const Vec2 common = impactPointOf(c, bodies, at.surfaceA, at.surfaceB);
    at.armA = common - centreA;
    at.armB = common - centreB;
    return at;
}

GapAt gapAtLastImpact(const ContactConstraint& c, const ContactConstraintPoint& p, std::span<const SolverBody> bodies,
                      Scalar tau0, Scalar h, const ContactSolver& impacts)
{
    const PointAt now = pointAt(c, p, bodies, tau0, h, impacts);
    const Scalar elapsed = tau0 * h;
    GapAt result;
    result.gap = (now.surfaceB - now.surfaceA).dot(c.normal) + 0.5 * p.normalAcceleration * elapsed * elapsed;
    // At the arms an impact at τ₀ would use: measured anywhere else, a turning body's approach
    // differs from what the impact then finds. A circle spinning at 21 rad/s against a wall, its
    // arm turned with it, was found approaching here and separating there, and struck again and
    // again with almost no impulse, up to the pass's cap.
    result.velocity = relativeVelocity(bodies[c.bodyA], bodies[c.bodyB], now.armA, now.armB).dot(c.normal);
    return result;
}

Approach approachOf(const ContactConstraint& c, const ContactConstraintPoint& p, std::span<const SolverBody> bodies,
                    Scalar h, const ContactSolver* impacts)
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
    // A body already struck this step moved on from its start with other velocities: its gaps
    // close from where they stood at its last impact (issue 16, review point 1).
    const Scalar tau0 = impacts && (a.hadImpact || b.hadImpact) ? std::max(a.lastImpactTau, b.lastImpactTau) : 0;
    if (tau0 > 0) {
        const GapAt at = gapAtLastImpact(c, p, bodies, tau0, h, *impacts);
        if (at.gap <= constants::kTouchDistance) {
            result.tau = tau0;
        } else {
            const Scalar t = timeToClose(at.gap, at.velocity + p.normalAcceleration * tau0 * h, p.normalAcceleration,
                                         (1 - tau0) * h);
            if (t < 0)
                return result;
            result.tau = tau0 + t / h;
        }
        result.velocity = at.velocity + p.normalAcceleration * result.tau * h;
        if (result.velocity >= -threshold)
            result.tau = -1;
        return result;
    }
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

/// Whether every point of a contact certainly stays open from τ₀·h, the latest impact of its two
/// bodies so far, to the step's end: judged from bounds alone, without turning any surface point
/// or finding where an impact would act. Most contacts a struck body's impact looks at again are
/// speculative ones, its neighbours some centimetres off (in Box2D v3's spinner, 88 % of them),
/// which gapAtLastImpact and timeToClose only find open; this is true only where they would find
/// every point open too, so the impact pass does the same work in the same order, to the bit.
///
/// The bounds, for each point with surface arms sA and sB (at the step's start, from the centres):
/// a surface arm turned by θ moves by |R(θ)s − s| ≤ |θ|·|s|, so the gap at τ₀ is at least the
/// unturned one less |θA|·|sA| + |θB|·|sB|; the point where an impact acts lies between the two
/// surface points (or is one of them), so its arm from A's centre is at most max(|sA|,
/// |cB − cA| + |sB|), and the relative normal velocity there is at least the centres' less each
/// spin times its arm's bound. Over the rest of the step, t ≤ T, the gap then closes by at most
/// min(0, v)·T + min(0, ½a)·T². Lengths are taken as |x| + |y| (never less than the length), the
/// points' worst values are used for all of them, and the gap must stay open by a micrometre
/// beyond the touching distance, far above the rounding of either computation.
bool staysOpen(const detail::ImpactReach& reach, std::span<const SolverBody> bodies, Scalar tau0, Scalar h,
               const ContactSolver& impacts)
{
    constexpr Scalar kRoundingAllowance = 1e-6; // m
    const SolverBody& a = bodies[reach.bodyA];
    const SolverBody& b = bodies[reach.bodyB];
    const Vec2 apart = impacts.positionAt(reach.bodyB, b, tau0, h) - impacts.positionAt(reach.bodyA, a, tau0, h);
    const Scalar turnA = surfaceTurnAt(reach.bodyA, a, tau0, h, impacts);
    const Scalar turnB = surfaceTurnAt(reach.bodyB, b, tau0, h, impacts);
    const Scalar distance = std::abs(apart.x()) + std::abs(apart.y());
    const Scalar elapsed = tau0 * h;
    const Scalar gap = apart.dot(reach.normal) + reach.shift - std::abs(turnA) * reach.armA -
                       std::abs(turnB) * reach.armB + 0.5 * reach.acceleration * elapsed * elapsed;
    const Scalar velocity = (b.velocity - a.velocity).dot(reach.normal) -
                            std::abs(a.angularVelocity) * std::max(reach.armA, distance + reach.armB) -
                            std::abs(b.angularVelocity) * std::max(reach.armB, distance + reach.armA) +
                            reach.acceleration * elapsed;
    const Scalar rest = (1 - tau0) * h;
    const Scalar closing =
        std::min<Scalar>(0, velocity) * rest + std::min<Scalar>(0, 0.5 * reach.acceleration) * rest * rest;
    return gap + closing > constants::kTouchDistance + kRoundingAllowance;
}

} // namespace

void ContactSolver::fillImpactReach(std::uint32_t body)
{
    for (std::uint32_t at = m_bodyConstraintStart[body]; at < m_bodyConstraintStart[body + 1]; ++at) {
        const ContactConstraint& c = m_constraints[m_bodyConstraints[at]];
        detail::ImpactReach& reach = m_bodyConstraintReach[at];
        reach.bodyA = c.bodyA;
        reach.bodyB = c.bodyB;
        reach.normal = c.normal;
        reach.shift = std::numeric_limits<Scalar>::infinity(); // no point: nothing can meet
        reach.armA = 0;
        reach.armB = 0;
        reach.acceleration = std::numeric_limits<Scalar>::infinity();
        for (int i = 0; i < c.pointCount; ++i) {
            const ContactConstraintPoint& p = c.points[static_cast<std::size_t>(i)];
            const Vec2 surfaceA = p.rA - 0.5 * p.separation * c.normal;
            const Vec2 surfaceB = p.rB + 0.5 * p.separation * c.normal;
            reach.shift = std::min(reach.shift, (surfaceB - surfaceA).dot(c.normal));
            reach.armA = std::max(reach.armA, std::abs(surfaceA.x()) + std::abs(surfaceA.y()));
            reach.armB = std::max(reach.armB, std::abs(surfaceB.x()) + std::abs(surfaceB.y()));
            reach.acceleration = std::min(reach.acceleration, p.normalAcceleration);
        }
        if (c.pointCount == 0)
            reach.acceleration = 0;
    }
    m_reachReady[body] = 1;
}

namespace detail {

/// The fastest approach among c's points that is an impact this step, m/s (< 0); nothing when none is.
Scalar fastestApproach(const ContactConstraint& c, std::span<const SolverBody> bodies, Scalar h,
                       const ContactSolver* impacts)
{
    Scalar fastest = -constants::kRestitutionThreshold;
    bool approaching = false;
    for (int i = 0; i < c.pointCount; ++i) {
        const Approach ap = approachOf(c, c.points[static_cast<std::size_t>(i)], bodies, h, impacts);
        if (ap.tau >= 0 && ap.velocity < fastest) {
            fastest = ap.velocity;
            approaching = true;
        }
    }
    return approaching ? fastest : 0;
}

} // namespace detail

int ContactSolver::solveImpacts(std::span<SolverBody> bodies, Scalar h)
{
    m_impulseTimeline.clear();
    m_struckBodies.clear();
    m_lastTimedImpulse.assign(bodies.size(), kNoImpulse);
    m_impactFrictionWork = 0;
    m_impactNormalWork = 0;
    m_impactVisits = 0;
    m_impactLooks = 0;
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
    const auto pinchedOut = [&](std::uint32_t ci) {
        if (m_fixedImpacts[ci] < kMaxFixedImpactsPerContact)
            return false;
        const auto& [bodyA, bodyB] = m_constraintBodies[ci];
        return m_pinched[movable(bodies[bodyA]) ? bodyA : bodyB] != 0;
    };
    const auto consider = [&](std::uint32_t ci) {
        if (pinchedOut(ci))
            return;
        if (const Scalar fastest = fastestApproach(m_constraints[ci], bodies, h, this); fastest < 0) {
            heap.push_back({fastest, ci, m_versions[ci]});
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
        m_fixedImpacts.assign(m_constraints.size(), 0);
        m_turnCache.assign(bodies.size(), TurnCache{});
        m_fixedStriker.assign(bodies.size(), kNoStriker);
        m_pinched.assign(bodies.size(), 0);
        m_bodyConstraintStart.assign(bodies.size() + 1, 0);
        for (const auto& [bodyA, bodyB] : m_constraintBodies) {
            ++m_bodyConstraintStart[bodyA + 1];
            ++m_bodyConstraintStart[bodyB + 1];
        }
        for (std::size_t i = 0; i < bodies.size(); ++i)
            m_bodyConstraintStart[i + 1] += m_bodyConstraintStart[i];
        m_bodyConstraints.resize(m_bodyConstraintStart.back());
        if (m_impactReachBounds) {
            m_bodyConstraintReach.resize(m_bodyConstraints.size());
            m_reachReady.assign(bodies.size(), 0);
        }
        std::vector<std::uint32_t>& fill = m_bodyConstraintFill;
        fill.assign(m_bodyConstraintStart.begin(), m_bodyConstraintStart.end() - 1);
        for (std::uint32_t ci = 0; ci < m_constraints.size(); ++ci) {
            m_bodyConstraints[fill[m_constraintBodies[ci][0]]++] = ci;
            m_bodyConstraints[fill[m_constraintBodies[ci][1]]++] = ci;
        }
    }

    int resolved = 0;
    std::size_t visits = 0; // contacts looked at again after an impact
    const std::size_t maxVisits = std::max(kMinImpactVisits, kMaxImpactVisitsPerContact * m_constraints.size());
    while (!heap.empty() && static_cast<std::size_t>(resolved) < maxImpacts && visits < maxVisits) {
        std::pop_heap(heap.begin(), heap.end(), later);
        const Candidate top = heap.back();
        heap.pop_back();
        if (top.version != m_versions[top.constraint])
            continue;
        const std::size_t best = top.constraint;

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
        // One time for the whole impact: the first of its points to meet (a two-point impact is
        // one simultaneous collision), and never before an impact either body has already taken
        // this step. Each body's impulses then come in the order of their times, so the place
        // each acts from (positionAt) already holds every impulse before it, and angular momentum
        // stays exact however the impacts were ordered (fastest approach first).
        Scalar tau = 1;
        for (int i = 0; i < c.pointCount; ++i) {
            const auto ui = static_cast<std::size_t>(i);
            const Approach ap = approachOf(c, c.points[ui], bodies, h, this);
            if (ap.tau < 0)
                continue;
            ImpactPoint& ip = points[static_cast<std::size_t>(count++)];
            ip.index = ui;
            tau = std::min(tau, ap.tau);
        }
        tau = std::max({tau, a.lastImpactTau, b.lastImpactTau});
        // Each body has moved and turned by then: its surface point turns with it (issue 16,
        // review point 2). The impulse acts at one point for both bodies (pointAt: half-way
        // between the two surface points, or a sole circle's own), and the approach is measured
        // at those arms, so that the impulse, its effective mass and the speed it answers all use
        // one point.
        for (int i = 0; i < count; ++i) {
            ImpactPoint& ip = points[static_cast<std::size_t>(i)];
            const ContactConstraintPoint& p = c.points[ip.index];
            ip.tau = tau;
            const PointAt at = pointAt(c, p, bodies, tau, h, *this);
            ip.rA = at.armA;
            ip.rB = at.armB;
            ip.velocity = relativeVelocity(a, b, ip.rA, ip.rB).dot(c.normal) + p.normalAcceleration * tau * h;
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
        // No point approaches at the impact's own arms: nothing happens, and nothing changed that
        // could make the contact approach later, so it leaves the queue. (Put back, it would be
        // found approaching and struck with no impulse until the pass's cap.)
        if (!(x(0) > 0) && (count < 2 || !(x(1) > 0)))
            continue;
        ++resolved;
        if (!movable(a) || !movable(b)) {
            if (m_fixedImpacts[best] < UINT8_MAX)
                ++m_fixedImpacts[best];
            const std::uint32_t fixedBody = movable(a) ? c.bodyB : c.bodyA;
            const std::uint32_t struck = movable(a) ? c.bodyA : c.bodyB;
            std::uint32_t& first = m_fixedStriker[struck];
            if (first == kNoStriker)
                first = fixedBody;
            else if (first != fixedBody && (moving(bodies[first]) || moving(bodies[fixedBody])))
                m_pinched[struck] = 1;
        }

        const Vec2 t = tangentOf(c.normal);
        // The collision inspector's record (none in a normal step): the state before the impulses.
        ImpactRecord* record = nullptr;
        if (m_impactLog != nullptr) {
            record = &m_impactLog->emplace_back();
            record->ownerA = c.ownerA;
            record->ownerB = c.ownerB;
            record->normal = c.normal;
            record->tangent = t;
            record->restitution = c.restitution;
            record->friction = c.friction;
            record->count = count;
            record->beforeA = {a.invMass, a.invInertia, a.velocity, a.angularVelocity};
            record->beforeB = {b.invMass, b.invInertia, b.velocity, b.angularVelocity};
            for (int i = 0; i < count; ++i) {
                const ImpactPoint& ip = points[static_cast<std::size_t>(i)];
                ImpactPointRecord& rp = record->points[static_cast<std::size_t>(i)];
                rp = {ip.rA, ip.rB, ip.tau, ip.velocity, ip.velocity - bias(i), x(i)};
                for (int j = 0; j < count; ++j)
                    record->k[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = k(i, j);
            }
        }
        // For the energy ledger: the relative normal velocities on the start-of-step velocities
        // before the impulses (see the sum after them).
        std::array<Scalar, 2> normalBefore{};
        for (int i = 0; m_measureImpactWork && i < count; ++i) {
            const ImpactPoint& ip = points[static_cast<std::size_t>(i)];
            normalBefore[static_cast<std::size_t>(i)] = relativeVelocity(a, b, ip.rA, ip.rB).dot(c.normal);
        }
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

        if (record != nullptr) {
            record->afterNormalA = {a.invMass, a.invInertia, a.velocity, a.angularVelocity};
            record->afterNormalB = {b.invMass, b.invInertia, b.velocity, b.angularVelocity};
        }
        // The impulses x change the kinetic energy at the time of impact by Σ x·(u⁻ + u⁺)/2, with
        // u⁻ the approach velocity then and u⁺ = u⁻ + the change the impulses made.
        for (int i = 0; m_measureImpactWork && i < count; ++i) {
            const ImpactPoint& ip = points[static_cast<std::size_t>(i)];
            const Scalar change = relativeVelocity(a, b, ip.rA, ip.rB).dot(c.normal) -
                                  normalBefore[static_cast<std::size_t>(i)];
            m_impactNormalWork += x(i) * (ip.velocity + 0.5 * change);
        }

        // Coulomb friction during the impact: stop the sliding at each point, within μ·jn.
        for (int i = 0; i < count; ++i) {
            const ImpactPoint& ip = points[static_cast<std::size_t>(i)];
            const Scalar vt = relativeVelocity(a, b, ip.rA, ip.rB).dot(t);
            const Scalar limit = c.friction * x(i);
            const Scalar tangentMass = effectiveMass(a, b, ip.rA, ip.rB, t);
            const Scalar jt = std::clamp(-vt * tangentMass, -limit, limit);
            applyImpactImpulse(c, ip.rA, ip.rB, ip.tau, jt * t, bodies);
            if (record != nullptr) {
                ImpactPointRecord& rp = record->points[static_cast<std::size_t>(i)];
                rp.tangentSpeed = vt;
                rp.tangentMass = tangentMass;
                rp.frictionLimit = limit;
                rp.frictionImpulse = jt;
            }
            // For the energy ledger: one impulse along t changes the kinetic energy by exactly
            // jt·(vt before + vt after)/2.
            if (m_measureImpactWork)
                m_impactFrictionWork += 0.5 * jt * (vt + relativeVelocity(a, b, ip.rA, ip.rB).dot(t));
        }
        if (record != nullptr) {
            record->afterA = {a.invMass, a.invInertia, a.velocity, a.angularVelocity};
            record->afterB = {b.invMass, b.invInertia, b.velocity, b.angularVelocity};
        }
        // Only a body that can move has been struck (a fixed body's contacts keep their status).
        for (const std::uint32_t index : {c.bodyA, c.bodyB}) {
            SolverBody& body = bodies[index];
            if (movable(body) && !body.hadImpact) {
                body.hadImpact = true;
                m_struckBodies.push_back(index);
            }
        }

        // Everything touching a body that just changed velocity may now approach (or stop).
        // Fixed bodies never change, so their many contacts need no second look.
        for (const std::uint32_t body : {c.bodyA, c.bodyB}) {
            if (!movable(bodies[body]))
                continue;
            if (m_impactReachBounds && m_reachReady[body] == 0)
                fillImpactReach(body);
            for (std::uint32_t at = m_bodyConstraintStart[body]; at < m_bodyConstraintStart[body + 1]; ++at) {
                const std::uint32_t cj = m_bodyConstraints[at];
                ++m_versions[cj];
                if (m_impactReachBounds) {
                    // The body was just struck, so approachOf measures every point from τ₀, the
                    // later of the two bodies' last impacts. (The entries are filled only where
                    // the bounds are on.)
                    const detail::ImpactReach& reach = m_bodyConstraintReach[at];
                    const Scalar tau0 = std::max(bodies[reach.bodyA].lastImpactTau, bodies[reach.bodyB].lastImpactTau);
                    if (staysOpen(reach, bodies, tau0, h, *this))
                        continue;
                }
                ++m_impactLooks;
                consider(cj);
            }
            visits += m_bodyConstraintStart[body + 1] - m_bodyConstraintStart[body];
        }
    }
    m_impactVisits = visits;
    if (resolved > 0)
        moveArmsToImpactTimes(bodies, h);
    return resolved;
}

void ContactSolver::moveArmsToImpactTimes(std::span<SolverBody> bodies, Scalar h)
{
    // A struck body's contact impulses act after its last impact (Simulation::finishBodyPosition),
    // so their lever arms are taken from where it is then. Both bodies of a contact then push at
    // one point in space, each at its own time, which keeps the angular momentum about any point
    // to rounding (docs/physics.md, "Conservation"). The arms move by how far the body travelled
    // before the impact, millimetres: the contact's geometry is otherwise the start's.
    // Only the struck bodies' contacts are visited (a pile with one impact has thousands of
    // others); a contact between two struck bodies is done from its body A.
    for (const std::uint32_t i : m_struckBodies)
        bodies[i].impulseOrigin = positionAt(i, bodies[i], bodies[i].lastImpactTau, h);
    for (const std::uint32_t struck : m_struckBodies) {
        for (std::uint32_t at = m_bodyConstraintStart[struck]; at < m_bodyConstraintStart[struck + 1]; ++at) {
            const std::uint32_t ci = m_bodyConstraints[at];
            ContactConstraint& c = m_constraints[ci];
            const SolverBody& a = bodies[c.bodyA];
            const SolverBody& b = bodies[c.bodyB];
            if (a.hadImpact && b.hadImpact && struck != c.bodyA)
                continue;
            const Vec2 t = tangentOf(c.normal);
            const Vec2 originA = impulseOrigin(a);
            const Vec2 originB = impulseOrigin(b);
            // The bodies end the step at their end velocities only from their last impact on: a
            // speculative contact may close the gap left then over what remains of the step, not
            // the start's gap over all of it (a ball struck late in the step does not reach the
            // one a few centimetres ahead, and must not be held back from it).
            const Scalar tau0 = std::max(a.hadImpact ? a.lastImpactTau : 0.0, b.hadImpact ? b.lastImpactTau : 0.0);
            const Scalar remaining = std::max(1 - tau0, kShortestRemainder);
            for (std::size_t k = 0; k < static_cast<std::size_t>(c.pointCount); ++k) {
                ContactConstraintPoint& p = c.points[k];
                if (tau0 > 0)
                    p.closingGap = gapAtLastImpact(c, p, bodies, tau0, h, *this).gap / remaining;
                // One point for both bodies, chosen as the impacts choose it (impactPointOf): a
                // sole circle's own facing point, else half-way between the two surface points,
                // summed in the order it always was so that no other contact changes by a bit.
                Vec2 common = 0.5 * (originA + p.rA + originB + p.rB);
                if ((a.round > 0) != (b.round > 0))
                    common = a.round > 0 ? Vec2(originA + p.rA) : Vec2(originB + p.rB);
                p.rA = common - originA;
                p.rB = common - originB;
                p.normalMass = effectiveMass(a, b, p.rA, p.rB, c.normal);
                p.tangentMass = effectiveMass(a, b, p.rA, p.rB, t);
            }
            if (m_batched)
                packLane(bodies, h, groupOfLane(m_laneOf[ci]), m_laneOf[ci]);
        }
    }
}

Scalar ContactSolver::turnAt(std::uint32_t index, const SolverBody& body, Scalar tau, Scalar h) const
{
    // As positionAt, for the angle: τh·ω − h·Σⱼ min(τ, τⱼ)·Δωⱼ from the step's start.
    Scalar turn = (tau * h) * body.angularVelocity;
    if (tau >= body.lastImpactTau) // after every impact so far: Σⱼ min(τ, τⱼ)·Δωⱼ = Σⱼ τⱼ·Δωⱼ
        return turn - h * body.impactLateAngularVelocity;
    for (std::uint32_t k = m_lastTimedImpulse[index]; k != kNoImpulse; k = m_impulseTimeline[k].previous)
        turn -= (h * std::min(tau, m_impulseTimeline[k].tau)) * m_impulseTimeline[k].angularVelocityChange;
    return turn;
}

Vec2 ContactSolver::turnedWith(std::uint32_t index, const Vec2& r, Scalar turn) const
{
    if (turn == 0)
        return r; // cos 0 = 1 and sin 0 = 0 exactly: rotate() would give r
    TurnCache& cache = m_turnCache[index];
    if (turn != cache.turn)
        cache = {turn, std::cos(turn), std::sin(turn)};
    return Vec2(cache.cosine * r.x() - cache.sine * r.y(), cache.sine * r.x() + cache.cosine * r.y());
}

Vec2 ContactSolver::positionAt(std::uint32_t index, const SolverBody& body, Scalar tau, Scalar h) const
{
    // x(τ) = x₀ + τh·v₀ + Σⱼ max(0, τ − τⱼ)·h·Δvⱼ, written with the current velocity
    // v = v₀ + Σⱼ Δvⱼ as x₀ + τh·v − h·Σⱼ min(τ, τⱼ)·Δvⱼ, over this body's impulses only.
    Vec2 x = body.position + (tau * h) * body.velocity;
    // The common case, and the only one solveImpacts asks for: τ at or after every impact so far
    // (a body's impacts come in time order), where Σⱼ min(τ, τⱼ)·Δvⱼ = Σⱼ τⱼ·Δvⱼ, which the body
    // keeps summed. Walking the body's impulses instead made a body struck n times cost O(n²).
    if (tau >= body.lastImpactTau)
        return x - h * body.impactLateVelocity;
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
    const Vec2 dvA = -a.invMass * impulse;
    const Vec2 dvB = b.invMass * impulse;
    const Scalar dwA = -a.invInertia * cross(rA, impulse);
    const Scalar dwB = b.invInertia * cross(rB, impulse);
    for (auto [body, dv, dw] : {std::tuple{&a, dvA, dwA}, std::tuple{&b, dvB, dwB}}) {
        if (!movable(*body))
            continue; // a fixed body's motion never changes: its impacts keep no time
        body->lastImpactTau = std::max(body->lastImpactTau, tau);
        body->impactVelocity += dv;
        body->impactAngularVelocity += dw;
    }
    a.impactLateVelocity += tau * dvA;
    a.impactLateAngularVelocity += tau * dwA;
    b.impactLateVelocity += tau * dvB;
    b.impactLateAngularVelocity += tau * dwB;
    for (const auto& [body, dv, dw] : {std::tuple{c.bodyA, dvA, dwA}, std::tuple{c.bodyB, dvB, dwB}}) {
        if (!movable(bodies[body]))
            continue; // a fixed body's motion never changes: nothing to remember
        m_impulseTimeline.push_back({m_lastTimedImpulse[body], tau, dv, dw});
        m_lastTimedImpulse[body] = static_cast<std::uint32_t>(m_impulseTimeline.size() - 1);
    }
}

} // namespace impetus::controller
