#include "controller/diagnostics.h"

#include "controller/integration/force_model.h"
#include "controller/soft/soft_body_builder.h"

#include <cmath>
#include <vector>

namespace impetus::controller {

Energy computeEnergy(const model::World& world)
{
    std::vector<model::BodyState> states;
    gatherStates(world, states);
    return computeEnergy(world, states);
}

Energy computeEnergy(const model::World& world, std::span<const model::BodyState> states)
{
    Energy e;
    for (std::uint32_t i = 0; i < world.bodies.size(); ++i) {
        const model::Body& body = world.bodies[i];
        if (body.fixed || world.softGrid(model::BodyId{i}))
            continue;
        const model::BodyState& s = states[i];
        e.kinetic += 0.5 * body.mass * s.velocity.squaredNorm() +
                     0.5 * body.inertia * s.angularVelocity * s.angularVelocity;
        e.potential -= body.mass * world.settings.gravity.dot(s.position);
    }
    for (const model::Spring& spring : world.springs) {
        const auto [endA, endB] = springEnds(spring, states);
        const Scalar stretch = (endB - endA).norm() - spring.restLength;
        e.elastic += 0.5 * spring.stiffness * stretch * stretch;
    }
    // A soft body's energy is its ellipses': their motion (deformation included), their height,
    // and the energy in their springs.
    std::size_t offset = world.bodies.size();
    std::vector<Vec2> positions;
    std::vector<Vec2> velocities;
    for (const model::SoftGrid& grid : world.softBodies) {
        positions.resize(grid.size());
        velocities.resize(grid.size());
        for (std::size_t i = 0; i < grid.size(); ++i) {
            positions[i] = states[offset + i].position;
            velocities[i] = states[offset + i].velocity;
        }
        offset += grid.size();
        for (std::size_t i = 0; i < grid.size(); ++i) {
            e.kinetic += 0.5 * grid.ellipseMass * velocities[i].squaredNorm();
            e.potential -= grid.ellipseMass * world.settings.gravity.dot(positions[i]);
        }
        for (const model::SoftSpring& spring : grid.springs) {
            const Scalar stretch = (positions[spring.b] - positions[spring.a]).norm() - spring.restLength;
            e.elastic += 0.5 * spring.stiffness * stretch * stretch;
        }
        // Shape matching's springs to the goal positions of the best-fit rigid motion.
        const model::Body& body = world.bodies[grid.body.index];
        const SoftAggregate a = softAggregate(grid, positions, velocities, states[grid.body.index].angle);
        const Scalar matching = softShapeMatchingStiffness(grid, body);
        for (std::size_t i = 0; i < grid.size(); ++i) {
            const Vec2 goal = a.position + rotate(grid.restPositions[i], a.bestFit);
            e.elastic += 0.5 * matching * (positions[i] - goal).squaredNorm();
        }
    }
    return e;
}

Vec2 linearMomentum(const model::World& world)
{
    // A soft body's state is its grid's aggregate, whose velocity is momentum / mass.
    Vec2 p = Vec2::Zero();
    for (const model::Body& body : world.bodies) {
        if (!body.fixed)
            p += body.mass * body.state.velocity;
    }
    return p;
}

Scalar angularMomentum(const model::World& world)
{
    Scalar l = 0;
    for (std::uint32_t i = 0; i < world.bodies.size(); ++i) {
        const model::Body& body = world.bodies[i];
        if (body.fixed || world.softGrid(model::BodyId{i}))
            continue;
        const model::BodyState& s = body.state;
        l += body.inertia * s.angularVelocity + body.mass * cross(s.position, s.velocity);
    }
    // A soft body's is the sum over its ellipses (which do not spin).
    for (const model::SoftGrid& grid : world.softBodies) {
        for (std::size_t i = 0; i < grid.size(); ++i)
            l += grid.ellipseMass * cross(grid.positions[i], grid.velocities[i]);
    }
    return l;
}

std::optional<std::size_t> firstNonFiniteBody(const model::World& world)
{
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        const model::BodyState& s = world.bodies[i].state;
        if (!isFinite(s.position) || !isFinite(s.velocity) || !std::isfinite(s.angle) ||
            !std::isfinite(s.angularVelocity))
            return i;
    }
    return std::nullopt;
}

} // namespace impetus::controller
