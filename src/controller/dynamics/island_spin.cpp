#include "controller/dynamics/island_spin.h"

#include "controller/union_find.h"

#include <algorithm>
#include <cmath>

namespace impetus::controller {

namespace {

/// The most kinetic energy a closed island may gain from its turn in one step, relative to its
/// kinetic energy (see keep).
constexpr Scalar kMaxSpinEnergy = 1e-3;

} // namespace

bool IslandSpin::applies(const model::World& world)
{
    return world.settings.gravity.isZero() && world.settings.drag == 0;
}

void IslandSpin::keep(const model::World& world, std::span<const model::BodyState> start, std::span<SolverBody> bodies,
                      std::span<const ContactConstraint> contacts)
{
    const auto count = static_cast<std::uint32_t>(bodies.size());
    m_parent.resize(count);
    m_open.assign(count, 0);
    m_mass.assign(count, 0);
    m_inertia.assign(count, 0);
    for (std::uint32_t i = 0; i < count; ++i)
        m_parent[i] = i;
    const auto join = [&](std::uint32_t a, std::uint32_t b) { m_parent[findRoot(m_parent, a)] = findRoot(m_parent, b); };

    // The members and what is outside. A fixed body (a wall, a turning drum) acts on whatever it
    // touches, and a body that cannot turn or cannot move takes torque or force from nowhere: both
    // open their island, which is then left as it is.
    for (std::uint32_t i = 0; i < world.bodies.size(); ++i) {
        const model::Body& body = world.bodies[i];
        if (body.fixed || (!body.soft && !(body.invMass > 0 && body.invInertia > 0))) {
            m_open[i] = 1;
        } else if (!body.soft) {
            m_mass[i] = body.mass;
            m_inertia[i] = body.inertia;
        }
    }
    auto ellipse = static_cast<std::uint32_t>(world.bodies.size());
    for (const model::SoftGrid& grid : world.softBodies) {
        for (std::size_t k = 0; k < grid.size(); ++k, ++ellipse) {
            m_mass[ellipse] = grid.ellipseMass; // ellipses are points of their grid: no spin
            join(ellipse, grid.body.index);
        }
    }
    // The links: contacts (a soft body's on its ellipses), joints and springs (on a soft body's
    // aggregate, which its ellipses share). A joint or spring to the world opens its island.
    for (const ContactConstraint& c : contacts)
        join(c.bodyA, c.bodyB);
    for (const model::Joint& joint : world.joints) {
        if (joint.bodyB)
            join(joint.bodyA.index, joint.bodyB->index);
        else
            m_open[joint.bodyA.index] = 1;
    }
    for (const model::Spring& spring : world.springs) {
        if (spring.bodyB)
            join(spring.bodyA.index, spring.bodyB->index);
        else
            m_open[spring.bodyA.index] = 1;
    }
    for (std::uint32_t i = 0; i < count; ++i) {
        if (m_open[i])
            m_open[findRoot(m_parent, i)] = 1;
    }

    // Per closed island: its mass, centre of mass at the end, and the angular momentum about the
    // origin the step took from it (start − end).
    m_islandMass.assign(count, 0);
    m_islandMoment.assign(count, Vec2::Zero());
    m_lost.assign(count, 0);
    m_islandInertia.assign(count, 0);
    const auto momentum = [&](std::uint32_t i, const Vec2& x, const Vec2& v, Scalar w) {
        return m_mass[i] * cross(x, v) + m_inertia[i] * w;
    };
    for (std::uint32_t i = 0; i < count; ++i) {
        if (!(m_mass[i] > 0))
            continue;
        const std::uint32_t root = findRoot(m_parent, i);
        if (m_open[root])
            continue;
        const SolverBody& b = bodies[i];
        const model::BodyState& s = start[i];
        m_islandMass[root] += m_mass[i];
        m_islandMoment[root] += m_mass[i] * b.position;
        m_lost[root] += momentum(i, s.position, s.velocity, s.angularVelocity) -
                        momentum(i, b.position, b.velocity, b.angularVelocity);
    }
    m_islandSpin.assign(count, 0);
    m_turn.assign(count, 0);
    m_islandKinetic.assign(count, 0);
    for (std::uint32_t i = 0; i < count; ++i) {
        const std::uint32_t root = findRoot(m_parent, i);
        if (!(m_mass[i] > 0) || m_open[root])
            continue;
        const SolverBody& b = bodies[i];
        const Vec2 r = b.position - m_islandMoment[root] / m_islandMass[root];
        m_islandInertia[root] += m_mass[i] * r.squaredNorm() + m_inertia[i];
        m_islandSpin[root] += m_mass[i] * cross(r, b.velocity) + m_inertia[i] * b.angularVelocity;
        m_islandKinetic[root] += 0.5 * (m_mass[i] * b.velocity.squaredNorm() + m_inertia[i] * b.angularVelocity * b.angularVelocity);
    }
    // The turn δω = lost / I about the centre of mass: Σ m·(x − x̄) = 0, so the momentum stays,
    // and the angular momentum about the origin changes by exactly I·δω. It changes the kinetic
    // energy by δω·L + ½·I·δω², L the island's angular momentum about its centre of mass. The
    // smooth forces' timing asks for small turns either way: at most 4e-5 of the island's kinetic
    // energy in a step of the zero-g piles of conservation_test.cpp. A turn that would add more
    // than kMaxSpinEnergy of it is not that: soak seeds 1995 (a rod between a polygon and a box)
    // and 2638 (a soft circle) asked for 10⁵ times their islands' kinetic energy, islands nearly
    // at rest set spinning, and gained energy without bound (+84 % in 3.5 s, tenfold in 0.46 s).
    // The turn stops at that energy; the island's angular momentum keeps the rest of the change.
    for (std::uint32_t root = 0; root < count; ++root) {
        if (m_parent[root] != root || m_open[root] || !(m_islandInertia[root] > 0))
            continue;
        const Scalar inertia = m_islandInertia[root];
        const Scalar spin = m_islandSpin[root];
        // δω·L + ½·I·δω² ≤ ε·K between its two roots.
        const Scalar allowed = kMaxSpinEnergy * m_islandKinetic[root];
        const Scalar reach = std::sqrt(spin * spin + 2 * inertia * allowed);
        m_turn[root] = std::clamp(m_lost[root] / inertia, (-spin - reach) / inertia, (-spin + reach) / inertia);
    }
    for (std::uint32_t i = 0; i < count; ++i) {
        const std::uint32_t root = findRoot(m_parent, i);
        if (!(m_mass[i] > 0) || m_open[root] || !(m_islandInertia[root] > 0))
            continue;
        const Scalar turn = m_turn[root];
        SolverBody& b = bodies[i];
        b.velocity += cross(turn, Vec2(b.position - m_islandMoment[root] / m_islandMass[root]));
        if (m_inertia[i] > 0)
            b.angularVelocity += turn;
    }
}

} // namespace impetus::controller
