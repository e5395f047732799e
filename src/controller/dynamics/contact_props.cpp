// ContactSolver, after the velocity and position passes: props, light bodies that a fixed body
// holds against a far heavier one, which the heavy body rests on as on the fixed body itself.

#include "controller/dynamics/contact_solver.h"
#include "controller/dynamics/contact_solver_detail.h"

#include <algorithm>
#include <cmath>

namespace impetus::controller {

using detail::kPropMassRatio;
using detail::kPropMinOpposition;

namespace {

/// The body as a prop sees it: the same pose and velocity, with no inverse mass or inertia, so
/// that the functions of the passes (relativeVelocity, effectiveMass, applyImpulse) move only the
/// heavy body.
SolverBody frozen(const SolverBody& body)
{
    SolverBody copy = body;
    copy.invMass = 0;
    copy.invInertia = 0;
    return copy;
}

/// Whether the direction `d` in which a heavy body pushes a prop is held by the fixed bodies that
/// push the prop along `supports`: against one of them within 45°, or between two of them (a
/// corner), −d = α·s₁ + β·s₂ with α, β ≥ 0.
bool heldAgainst(const Vec2& d, std::span<const Vec2> supports)
{
    for (const Vec2& s : supports) {
        if (-d.dot(s) >= kPropMinOpposition)
            return true;
    }
    for (std::size_t i = 0; i < supports.size(); ++i) {
        for (std::size_t j = i + 1; j < supports.size(); ++j) {
            const Scalar det = cross(supports[i], supports[j]);
            if (std::abs(det) < 1e-9)
                continue;
            const Scalar alpha = cross(Vec2(-d), supports[j]) / det;
            const Scalar beta = cross(supports[i], Vec2(-d)) / det;
            if (alpha >= 0 && beta >= 0)
                return true;
        }
    }
    return false;
}

} // namespace

void ContactSolver::findProps(std::span<const SolverBody> bodies)
{
    m_props.clear();
    m_propFixedContacts.clear();
    // Most worlds have no pair of touching bodies whose masses differ a hundredfold: one look at
    // each constraint's two bodies, and nothing more.
    m_propCandidates.clear();
    for (std::uint32_t ci = 0; ci < m_constraintBodies.size(); ++ci) {
        const SolverBody& a = bodies[m_constraintBodies[ci][0]];
        const SolverBody& b = bodies[m_constraintBodies[ci][1]];
        // The masses first, which the bodies' first cache line holds: the record and the
        // constraint are fetched only for the rare pair that passes (a pile of equal boxes has
        // none, and fetching them cost the base-100 pyramid 3 % of its step).
        const bool aLight = a.invMass > 0 && a.invMass >= kPropMassRatio * b.invMass;
        const bool bLight = b.invMass > 0 && b.invMass >= kPropMassRatio * a.invMass;
        if ((!aLight && !bLight) || !movable(a) || !movable(b) || !touching(ci))
            continue;
        // A soft body's ellipse may be a prop (each is rigid: a soft body crushed under a tonne
        // down to its ellipses holds there), and may be the heavy body too: a soft ball of 450 kg
        // thrown at 25 m/s into a 0.3 kg ellipse at a wall pressed it through the wall, its front
        // ellipses 14 kg each (soak seed 3433). Its springs push the ellipse on again the next
        // step, where the prop stops it again.
        if (aLight)
            m_propCandidates.push_back({ci, m_constraintBodies[ci][0]});
        else if (bLight)
            m_propCandidates.push_back({ci, m_constraintBodies[ci][1]});
    }
    if (m_propCandidates.empty())
        return;

    // The directions in which fixed bodies touching a candidate push it, body by body.
    m_propSupports.clear();
    std::vector<std::uint32_t>& light = m_propLight;
    light.clear();
    for (const PropCandidate& candidate : m_propCandidates)
        light.push_back(candidate.prop);
    std::sort(light.begin(), light.end());
    light.erase(std::unique(light.begin(), light.end()), light.end());
    for (std::uint32_t ci = 0; ci < m_constraintBodies.size(); ++ci) {
        const std::uint32_t ia = m_constraintBodies[ci][0];
        const std::uint32_t ib = m_constraintBodies[ci][1];
        const bool fixedA = !movable(bodies[ia]);
        const bool fixedB = !movable(bodies[ib]);
        if (fixedA == fixedB || !touching(ci))
            continue;
        const std::uint32_t held = fixedA ? ib : ia;
        if (!std::binary_search(light.begin(), light.end(), held))
            continue;
        // The impulse +P goes to B: a fixed A pushes B along the normal, a fixed B pushes A against it.
        const Vec2& n = m_constraints[ci].normal;
        m_propSupports.push_back({held, fixedA ? n : Vec2(-n), ci});
    }
    std::sort(m_propSupports.begin(), m_propSupports.end(),
              [](const PropSupport& x, const PropSupport& y) { return x.body < y.body; });

    std::vector<Vec2>& supports = m_propScratch;
    for (const PropCandidate& candidate : m_propCandidates) {
        const auto first = std::lower_bound(m_propSupports.begin(), m_propSupports.end(), candidate.prop,
                                            [](const PropSupport& s, std::uint32_t body) { return s.body < body; });
        supports.clear();
        for (auto it = first; it != m_propSupports.end() && it->body == candidate.prop; ++it)
            supports.push_back(it->direction);
        if (supports.empty())
            continue;
        const bool propIsA = m_constraintBodies[candidate.constraint][0] == candidate.prop;
        const Vec2& n = m_constraints[candidate.constraint].normal;
        // The heavy body pushes the prop as the impulse would: B along +n, A along −n.
        const Vec2 push = propIsA ? Vec2(-n) : n;
        if (!heldAgainst(push, supports))
            continue;
        m_props.push_back({candidate.constraint, propIsA});
        for (auto it = first; it != m_propSupports.end() && it->body == candidate.prop; ++it)
            m_propFixedContacts.push_back(it->constraint);
    }
    std::sort(m_propFixedContacts.begin(), m_propFixedContacts.end());
    m_propFixedContacts.erase(std::unique(m_propFixedContacts.begin(), m_propFixedContacts.end()),
                              m_propFixedContacts.end());
}

namespace {

/// Stops the approach of c's points as a velocity pass would, with only non-negative impulses
/// (for a contact with a fixed body, which moves only the prop).
void stopApproach(const ContactConstraint& c, SolverBody& a, SolverBody& b, Scalar h)
{
    for (int i = 0; i < c.pointCount; ++i) {
        const ContactConstraintPoint& p = c.points[static_cast<std::size_t>(i)];
        const Scalar vn = relativeVelocity(a, b, p.rA, p.rB).dot(c.normal) + std::max(p.closingGap, 0.0) / h;
        if (vn < 0)
            applyImpulse(a, b, p.rA, p.rB, (-vn * effectiveMass(a, b, p.rA, p.rB, c.normal)) * c.normal);
    }
}

/// Moves c's bodies apart as a position pass would (solvePositions).
void separate(const ContactConstraint& c, SolverBody& a, SolverBody& b)
{
    for (int i = 0; i < c.pointCount; ++i) {
        const detail::PositionCorrection look =
            detail::positionCorrection(c, c.points[static_cast<std::size_t>(i)], a, b,
                                       Vec2(std::cos(a.angle), std::sin(a.angle)), Vec2(std::cos(b.angle), std::sin(b.angle)));
        if (!look.impulse.isZero())
            applyPositionImpulse(a, b, look.rA, look.rB, look.impulse);
    }
}

/// Stops the heavy body's approach at each point of c, the prop frozen (a or b, as propIsA says).
/// The heavy body's own point moves along the impulse's push at u, and an impulse λ changes its
/// kinetic energy by λ·u + λ²/(2·mass). Stopping the approach at a prop at rest takes energy out;
/// a prop that the passes left moving at the heavy body (squeezed out sideways) must not throw it
/// back faster than it came, so λ stops at the impulse that leaves the energy as it was (none, if
/// u ≥ 0). Returns whether an impulse acted.
bool stopAtProp(const ContactConstraint& c, SolverBody& a, SolverBody& b, bool propIsA, Scalar h)
{
    bool acted = false;
    for (int i = 0; i < c.pointCount; ++i) {
        const ContactConstraintPoint& p = c.points[static_cast<std::size_t>(i)];
        const Scalar vn = relativeVelocity(a, b, p.rA, p.rB).dot(c.normal) + std::max(p.closingGap, 0.0) / h;
        if (vn >= 0)
            continue;
        const Scalar mass = effectiveMass(a, b, p.rA, p.rB, c.normal);
        const Vec2 pointVelocity = propIsA ? Vec2(b.velocity + cross(b.angularVelocity, p.rB))
                                           : Vec2(-(a.velocity + cross(a.angularVelocity, p.rA)));
        const Scalar u = pointVelocity.dot(c.normal);
        const Scalar impulse = std::min(-vn * mass, std::max(-2 * u * mass, 0.0));
        if (impulse <= 0)
            continue;
        applyImpulse(a, b, p.rA, p.rB, impulse * c.normal);
        acted = true;
    }
    return acted;
}

/// Calls work(a, b) with the prop contact's two bodies: the prop as a frozen copy (no inverse mass
/// or inertia), the heavy body itself.
template <typename Work>
void withPropFrozen(const ContactConstraint& c, bool propIsA, std::span<SolverBody> bodies, Work&& work)
{
    SolverBody& realA = bodies[c.bodyA];
    SolverBody& realB = bodies[c.bodyB];
    SolverBody still = frozen(propIsA ? realA : realB);
    work(propIsA ? still : realA, propIsA ? realB : still);
}

} // namespace

void ContactSolver::solvePropVelocities(std::span<SolverBody> bodies, Scalar h)
{
    // A few passes, as a two-point contact's points and a body on two props share their impulses.
    // Each pass first stops each prop against its fixed bodies (in batches, the passes do not
    // take the contacts with fixed bodies last, and may leave a prop moving into the floor with
    // what rests on it), then the heavy bodies against the props.
    for (int pass = 0; pass < kPropPasses; ++pass) {
        for (const std::uint32_t ci : m_propFixedContacts) {
            const ContactConstraint& c = m_constraints[ci];
            stopApproach(c, bodies[c.bodyA], bodies[c.bodyB], h);
        }
        for (const Prop& prop : m_props) {
            const ContactConstraint& c = m_constraints[prop.constraint];
            withPropFrozen(c, prop.propIsA, bodies, [&](SolverBody& a, SolverBody& b) {
                if (stopAtProp(c, a, b, prop.propIsA, h))
                    (prop.propIsA ? b : a).hadContactForce = true;
            });
        }
    }
}

void ContactSolver::solvePropPositions(std::span<SolverBody> bodies)
{
    // As the velocities: each prop out of its fixed bodies, then the heavy bodies out of the props.
    for (int pass = 0; pass < kPropPasses; ++pass) {
        for (const std::uint32_t ci : m_propFixedContacts) {
            const ContactConstraint& c = m_constraints[ci];
            separate(c, bodies[c.bodyA], bodies[c.bodyB]);
        }
        for (const Prop& prop : m_props) {
            const ContactConstraint& c = m_constraints[prop.constraint];
            withPropFrozen(c, prop.propIsA, bodies, [&](SolverBody& a, SolverBody& b) { separate(c, a, b); });
        }
    }
}

} // namespace impetus::controller
