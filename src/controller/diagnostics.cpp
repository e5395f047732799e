#include "controller/diagnostics.h"

#include "controller/force_model.h"

#include <cmath>
#include <vector>

namespace impetus::controller {

Energy computeEnergy(const model::World& world)
{
    Energy e;
    std::vector<model::BodyState> states;
    states.reserve(world.bodies.size());
    for (const model::Body& body : world.bodies) {
        states.push_back(body.state);
        if (body.fixed)
            continue;
        const model::BodyState& s = body.state;
        e.kinetic += 0.5 * body.mass * s.velocity.squaredNorm() +
                     0.5 * body.inertia * s.angularVelocity * s.angularVelocity;
        e.potential -= body.mass * world.settings.gravity.dot(s.position);
    }
    for (const model::Spring& spring : world.springs) {
        const auto [endA, endB] = springEnds(spring, states);
        const Scalar stretch = (endB - endA).norm() - spring.restLength;
        e.elastic += 0.5 * spring.stiffness * stretch * stretch;
    }
    return e;
}

Vec2 linearMomentum(const model::World& world)
{
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
    for (const model::Body& body : world.bodies) {
        if (body.fixed)
            continue;
        const model::BodyState& s = body.state;
        l += body.inertia * s.angularVelocity + body.mass * cross(s.position, s.velocity);
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
