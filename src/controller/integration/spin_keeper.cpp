#include "controller/integration/spin_keeper.h"

#include "controller/union_find.h"

namespace impetus::controller {

bool SpinKeeper::begin(const model::World& world)
{
    m_members.clear();
    m_first.clear();
    m_mass.clear();
    m_inertia.clear();
    const auto add = [&](std::uint32_t index, Scalar mass, Scalar inertia) {
        m_members.push_back(index);
        m_mass.push_back(mass);
        m_inertia.push_back(inertia);
    };
    // Rigid bodies joined by springs, both ends dynamic and rigid.
    const auto joins = [&](std::uint32_t index) {
        const model::Body& body = world.bodies[index];
        return !body.fixed && !body.soft;
    };
    bool anySpring = false;
    for (const model::Spring& spring : world.springs)
        anySpring = anySpring || (spring.bodyB && joins(spring.bodyA.index) && joins(spring.bodyB->index));
    if (anySpring) {
        const auto count = static_cast<std::uint32_t>(world.bodies.size());
        m_parent.resize(count);
        for (std::uint32_t i = 0; i < count; ++i)
            m_parent[i] = i;
        std::vector<std::int64_t> joined(count, -1); // the body itself, once a spring joins it
        for (const model::Spring& spring : world.springs) {
            if (!spring.bodyB || !joins(spring.bodyA.index) || !joins(spring.bodyB->index))
                continue;
            m_parent[findRoot(m_parent, spring.bodyA.index)] = findRoot(m_parent, spring.bodyB->index);
            joined[spring.bodyA.index] = spring.bodyA.index;
            joined[spring.bodyB->index] = spring.bodyB->index;
        }
        // The groups in the order of their first body, each body in list order.
        const auto groups = groupBySet(m_parent, joined);
        for (const std::vector<std::uint32_t>& group : groups) {
            m_first.push_back(static_cast<std::uint32_t>(m_members.size()));
            for (const std::uint32_t i : group)
                add(i, world.bodies[i].mass, world.bodies[i].inertia);
        }
    }
    // Each soft grid's ellipses.
    auto index = static_cast<std::uint32_t>(world.bodies.size());
    for (const model::SoftGrid& grid : world.softBodies) {
        const auto count = static_cast<std::uint32_t>(grid.size());
        if (count > 1 && !world.bodies[grid.body.index].fixed) {
            m_first.push_back(static_cast<std::uint32_t>(m_members.size()));
            for (std::uint32_t i = 0; i < count; ++i)
                add(index + i, grid.ellipseMass, 0);
        }
        index += count;
    }
    m_first.push_back(static_cast<std::uint32_t>(m_members.size()));
    m_torques.assign(m_first.size() - 1, 0);
    return !m_torques.empty();
}

void SpinKeeper::addTorques(std::span<const model::BodyState> states, std::span<const BodyDerivative> rates, Scalar weight)
{
    for (std::size_t g = 0; g + 1 < m_first.size(); ++g) {
        Scalar mass = 0;
        Vec2 centre = Vec2::Zero();
        for (std::uint32_t k = m_first[g]; k < m_first[g + 1]; ++k) {
            mass += m_mass[k];
            centre += m_mass[k] * states[m_members[k]].position;
        }
        centre /= mass;
        Scalar torque = 0;
        for (std::uint32_t k = m_first[g]; k < m_first[g + 1]; ++k) {
            const std::uint32_t i = m_members[k];
            torque += m_mass[k] * cross(states[i].position - centre, rates[i].acceleration) +
                      m_inertia[k] * rates[i].angularAcceleration;
        }
        m_torques[g] += weight * torque;
    }
}

void SpinKeeper::keep(std::span<const model::BodyState> start, std::vector<model::BodyState>& end, Scalar h) const
{
    for (std::size_t g = 0; g + 1 < m_first.size(); ++g) {
        // The group's angular momentum about its centre of mass in `states`, and its moment of
        // inertia there.
        const auto spin = [&](std::span<const model::BodyState> states, Vec2& centre, Scalar& inertia) {
            Scalar mass = 0;
            Vec2 velocity = Vec2::Zero();
            centre = Vec2::Zero();
            for (std::uint32_t k = m_first[g]; k < m_first[g + 1]; ++k) {
                mass += m_mass[k];
                centre += m_mass[k] * states[m_members[k]].position;
                velocity += m_mass[k] * states[m_members[k]].velocity;
            }
            centre /= mass;
            velocity /= mass;
            Scalar momentum = 0;
            inertia = 0;
            for (std::uint32_t k = m_first[g]; k < m_first[g + 1]; ++k) {
                const model::BodyState& s = states[m_members[k]];
                const Vec2 r = s.position - centre;
                momentum += m_mass[k] * cross(r, s.velocity - velocity) + m_inertia[k] * s.angularVelocity;
                inertia += m_mass[k] * r.squaredNorm() + m_inertia[k];
            }
            return momentum;
        };
        Vec2 centre = Vec2::Zero();
        Scalar inertia = 0;
        const Scalar before = spin(start, centre, inertia);
        const Scalar after = spin(end, centre, inertia);
        if (!(inertia > 0))
            continue;
        const Scalar turn = (before + h * m_torques[g] - after) / inertia;
        for (std::uint32_t k = m_first[g]; k < m_first[g + 1]; ++k) {
            model::BodyState& s = end[m_members[k]];
            s.velocity += cross(turn, s.position - centre);
            if (m_inertia[k] > 0)
                s.angularVelocity += turn;
        }
    }
}

} // namespace impetus::controller
