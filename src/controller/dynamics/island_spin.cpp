#include "controller/dynamics/island_spin.h"

#include "controller/union_find.h"

namespace impetus::controller {

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
    for (std::uint32_t i = 0; i < count; ++i) {
        const std::uint32_t root = findRoot(m_parent, i);
        if (!(m_mass[i] > 0) || m_open[root])
            continue;
        const Vec2 r = bodies[i].position - m_islandMoment[root] / m_islandMass[root];
        m_islandInertia[root] += m_mass[i] * r.squaredNorm() + m_inertia[i];
    }
    // The turn δω = lost / I about the centre of mass: Σ m·(x − x̄) = 0, so the momentum stays,
    // and the angular momentum about the origin changes by exactly I·δω.
    for (std::uint32_t i = 0; i < count; ++i) {
        const std::uint32_t root = findRoot(m_parent, i);
        if (!(m_mass[i] > 0) || m_open[root] || !(m_islandInertia[root] > 0))
            continue;
        const Scalar turn = m_lost[root] / m_islandInertia[root];
        SolverBody& b = bodies[i];
        b.velocity += cross(turn, Vec2(b.position - m_islandMoment[root] / m_islandMass[root]));
        if (m_inertia[i] > 0)
            b.angularVelocity += turn;
    }
}

} // namespace impetus::controller
