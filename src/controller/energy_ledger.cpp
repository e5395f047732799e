#include "controller/energy_ledger.h"

#include "controller/dynamics/contact_solver_detail.h"
#include "controller/integration/force_model.h"
#include "controller/soft/soft_body_builder.h"
#include "model/constants.h"

#include <algorithm>
#include <cmath>

namespace impetus::controller {

namespace {

/// The power the smooth forces dissipate in one state of the world, W (≥ 0 each).
struct Dissipation {
    Scalar drag = 0;
    Scalar springDamping = 0;
    Scalar softDamping = 0;
};

/// Velocity of the material point at world point `at` of a body in state s, m/s.
Vec2 pointVelocity(const model::BodyState& s, const Vec2& at)
{
    return s.velocity + cross(s.angularVelocity, Vec2(at - s.position));
}

/// c·(dL/dt)² of a damper of coefficient c between two points, W.
Scalar damperPower(Scalar c, const Vec2& endA, const Vec2& endB, const Vec2& velocityA, const Vec2& velocityB)
{
    const Vec2 d = endB - endA;
    const Scalar length = d.norm();
    if (c == 0 || !(length > 0))
        return 0;
    const Scalar rate = d.dot(velocityB - velocityA) / length;
    return c * rate * rate;
}

/// The drag, spring damping and soft damping power of the world in `states`, by the laws of
/// force_model.h: the forces' own terms, evaluated apart so that each cause gets its share.
Dissipation dissipation(const model::World& world, std::span<const model::BodyState> states)
{
    Dissipation p;
    const Scalar b = world.settings.drag;
    for (std::uint32_t i = 0; i < world.bodies.size(); ++i) {
        const model::Body& body = world.bodies[i];
        if (!body.fixed && !world.softGrid(model::BodyId{i}))
            p.drag += b * states[i].velocity.squaredNorm();
    }
    for (const model::Spring& spring : world.springs) {
        const auto [endA, endB] = springEnds(spring, states);
        const Vec2 velocityA = pointVelocity(states[spring.bodyA.index], endA);
        const Vec2 velocityB = spring.bodyB ? pointVelocity(states[spring.bodyB->index], endB) : Vec2::Zero();
        p.springDamping += damperPower(spring.damping, endA, endB, velocityA, velocityB);
    }
    std::size_t offset = world.bodies.size();
    for (const model::SoftGrid& grid : world.softBodies) {
        const model::Body& body = world.bodies[grid.body.index];
        const model::BodyState* s = states.data() + offset;
        offset += grid.size();
        const Scalar m = grid.ellipseMass;
        // Each ellipse's share b·m/M of the body's drag.
        for (std::size_t i = 0; i < grid.size(); ++i)
            p.drag += b * m * body.invMass * s[i].velocity.squaredNorm();
        for (const model::SoftSpring& spring : grid.springs) {
            p.softDamping += damperPower(spring.damping, s[spring.a].position, s[spring.b].position,
                                         s[spring.a].velocity, s[spring.b].velocity);
        }
        // Internal damping β·m·(v − v_rigid) with the grid's rigid motion: the mean velocity and
        // the angular velocity Σ p × (v − v_c) / Σ |p|² about the centre.
        if (grid.size() == 0)
            continue;
        Vec2 centre = Vec2::Zero();
        Vec2 velocity = Vec2::Zero();
        for (std::size_t i = 0; i < grid.size(); ++i) {
            centre += s[i].position;
            velocity += s[i].velocity;
        }
        const auto n = static_cast<Scalar>(grid.size());
        centre /= n;
        velocity /= n;
        Scalar spin = 0;
        Scalar spread = 0;
        for (std::size_t i = 0; i < grid.size(); ++i) {
            const Vec2 q = s[i].position - centre;
            spin += cross(q, Vec2(s[i].velocity - velocity));
            spread += q.squaredNorm();
        }
        const Scalar omega = spread > 0 ? spin / spread : 0;
        const Scalar rate = constants::kSoftInternalDampingRate + softShapeMatchingDamping(grid, body) / m;
        for (std::size_t i = 0; i < grid.size(); ++i) {
            const Vec2 rigid = velocity + cross(omega, Vec2(s[i].position - centre));
            p.softDamping += m * rate * (s[i].velocity - rigid).dot(s[i].velocity);
        }
    }
    return p;
}

} // namespace

void EnergyLedger::reset()
{
    *this = EnergyLedger{};
}

Scalar EnergyLedger::closure() const
{
    if (!m_started)
        return 0;
    const EnergyLosses& l = m_losses;
    const Scalar magnitude = std::abs(l.impacts) + std::abs(l.friction) + std::abs(l.drag) +
                             std::abs(l.springDamping) + std::abs(l.softDamping) + std::abs(l.joints) +
                             std::abs(l.correction) + std::abs(l.drift);
    const Scalar scale = std::max({std::abs(m_initial.total()), std::abs(m_current.total()), magnitude});
    if (!(scale > 0))
        return 0;
    return std::abs(m_initial.total() - m_current.total() - l.total()) / scale;
}

Scalar EnergyLedger::kinetic(std::span<const SolverBody> bodies) const
{
    Scalar e = 0;
    for (std::size_t i = 0; i < bodies.size() && i < m_mass.size(); ++i) {
        const SolverBody& b = bodies[i];
        e += 0.5 * m_mass[i] * b.velocity.squaredNorm() + 0.5 * m_inertia[i] * b.angularVelocity * b.angularVelocity;
    }
    return e;
}

void EnergyLedger::beginSubstep(const model::World& world)
{
    const Energy now = computeEnergy(world);
    // The world as the last substep left it has exactly these bits; anything else was changed by
    // a hand, and the ledger starts again from it.
    const bool continues = m_started && now.kinetic == m_current.kinetic && now.potential == m_current.potential &&
                           now.elastic == m_current.elastic;
    if (!continues) {
        *this = EnergyLedger{};
        m_started = true;
        m_initial = now;
        m_startTime = world.time;
    }
    m_current = now;
    m_substepStart = now.total();
    m_smoothLoss = 0;
    m_jointCorrection = 0;

    // Which entries of the state list carry kinetic energy: dynamic rigid bodies and ellipses (a
    // soft body's own entry is its grid's aggregate, whose energy the ellipses already hold).
    m_mass.assign(stateCount(world), 0.0);
    m_inertia.assign(m_mass.size(), 0.0);
    for (std::uint32_t i = 0; i < world.bodies.size(); ++i) {
        const model::Body& body = world.bodies[i];
        if (body.fixed || world.softGrid(model::BodyId{i}))
            continue;
        m_mass[i] = body.mass;
        m_inertia[i] = body.inertia;
    }
    std::size_t next = world.bodies.size();
    for (const model::SoftGrid& grid : world.softBodies) {
        std::fill_n(m_mass.begin() + static_cast<std::ptrdiff_t>(next), grid.size(), grid.ellipseMass);
        next += grid.size();
    }
}

void EnergyLedger::beforeImpacts(std::span<const SolverBody> bodies)
{
    m_kineticBeforeImpacts = kinetic(bodies);
}

void EnergyLedger::afterImpacts(std::span<const SolverBody> bodies, Scalar normalWork, Scalar frictionWork)
{
    // Positions do not move in the impact pass: the change of E is the change of kinetic energy.
    // The impacts act on the start-of-step velocities, but an impact happens at τ·h, when the
    // smooth forces have already changed the approach: the kinetic energy changes by j·a·τh more
    // than the impact loses, which is the smooth forces' share and goes with them (to the drift).
    const Scalar change = kinetic(bodies) - m_kineticBeforeImpacts;
    m_afterImpacts = m_substepStart + change;
    m_losses.impacts -= normalWork;
    m_losses.friction -= frictionWork;
    m_losses.drift -= change - normalWork - frictionWork;
}

void EnergyLedger::afterIntegration(const model::World& world, std::span<const model::BodyState> start,
                                    std::span<const model::BodyState> end, Scalar h)
{
    // The trapezoidal rule over the substep: its error, O(h³) a substep, lands in the drift.
    const Dissipation a = dissipation(world, start);
    const Dissipation b = dissipation(world, end);
    const Scalar drag = 0.5 * h * (a.drag + b.drag);
    const Scalar springDamping = 0.5 * h * (a.springDamping + b.springDamping);
    const Scalar softDamping = 0.5 * h * (a.softDamping + b.softDamping);
    m_losses.drag += drag;
    m_losses.springDamping += springDamping;
    m_losses.softDamping += softDamping;
    m_smoothLoss += drag + springDamping + softDamping;
}

void EnergyLedger::beforeVelocities(std::span<const SolverBody> bodies,
                                    const std::vector<ContactConstraint>& constraints)
{
    m_tangentBefore.clear();
    for (const ContactConstraint& c : constraints) {
        const Vec2 t = detail::tangentOf(c.normal);
        for (int i = 0; i < c.pointCount; ++i) {
            const ContactConstraintPoint& p = c.points[static_cast<std::size_t>(i)];
            m_tangentBefore.push_back(relativeVelocity(bodies[c.bodyA], bodies[c.bodyB], p.rA, p.rB).dot(t));
        }
    }
}

void EnergyLedger::afterVelocities(std::span<const SolverBody> bodies, const std::vector<ContactConstraint>& constraints,
                                   const std::vector<model::ContactRecord>& records)
{
    // Every velocity change of the passes is an impulse λ along a constraint row J, so the change
    // of kinetic energy is exactly Σ λ·(u⁻ + u⁺)/2 over the rows, u = J·v before and after, with λ
    // the impulse the passes applied in all: the final accumulated one (the warm start applied the
    // starting value). The friction rows are friction's. The normal rows of a resting or sliding
    // contact, and the joints' rows, stand for forces that do no work: what they take out is what
    // the integrator put into the approach (g·h on a resting body, the outward speed of a
    // pendulum's bob), so they stay in the drift with it.
    Scalar frictionWork = 0;
    std::size_t row = 0;
    for (std::size_t ci = 0; ci < constraints.size() && ci < records.size(); ++ci) {
        const ContactConstraint& c = constraints[ci];
        const Vec2 t = detail::tangentOf(c.normal);
        for (std::size_t i = 0; i < static_cast<std::size_t>(c.pointCount); ++i, ++row) {
            const ContactConstraintPoint& p = c.points[i];
            const Vec2 u = relativeVelocity(bodies[c.bodyA], bodies[c.bodyB], p.rA, p.rB);
            frictionWork += 0.5 * records[ci].tangentImpulses[i] * (m_tangentBefore[row] + u.dot(t));
        }
    }
    m_losses.friction -= frictionWork;
    m_smoothLoss -= frictionWork;
}

void EnergyLedger::beforeCorrection(const model::World& world, std::span<const model::BodyState> states)
{
    m_beforeCorrection = computeEnergy(world, states).total();
    // Whatever the integrator, the contact step and the finishing of the positions changed
    // beyond the causes booked since the impacts.
    m_losses.drift += m_afterImpacts - m_beforeCorrection - m_smoothLoss;
}

Scalar EnergyLedger::storedEnergy(const model::World& world, std::span<const SolverBody> bodies)
{
    m_poses.resize(bodies.size());
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        m_poses[i].position = bodies[i].position;
        m_poses[i].angle = bodies[i].angle;
    }
    const Energy e = computeEnergy(world, m_poses);
    return e.potential + e.elastic;
}

void EnergyLedger::beforeJointCorrection(const model::World& world, std::span<const SolverBody> bodies)
{
    if (!world.joints.empty())
        m_storedBeforeJoints = storedEnergy(world, bodies);
}

void EnergyLedger::afterJointCorrection(const model::World& world, std::span<const SolverBody> bodies)
{
    // The joints' position correction: it moves bodies back onto their rods and pins, and so
    // changes their height and their springs' stretch.
    if (!world.joints.empty())
        m_jointCorrection += m_storedBeforeJoints - storedEnergy(world, bodies);
}

void EnergyLedger::endSubstep(const model::World& world)
{
    m_current = computeEnergy(world);
    m_losses.joints += m_jointCorrection;
    m_losses.correction += m_beforeCorrection - m_current.total() - m_jointCorrection;
}

} // namespace impetus::controller
