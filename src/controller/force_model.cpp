#include "controller/force_model.h"

namespace impetus::controller {

namespace {

/// The velocity of the material point of a body at `worldPoint`.
Vec2 velocityOf(const model::BodyState& state, const Vec2& worldPoint)
{
    return state.velocity + cross(state.angularVelocity, Vec2(worldPoint - state.position));
}

} // namespace

std::pair<Vec2, Vec2> springEnds(const model::Spring& spring, std::span<const model::BodyState> states)
{
    const model::BodyState& a = states[spring.bodyA.index];
    const Vec2 endA = a.position + rotate(spring.anchorA, a.angle);
    if (!spring.bodyB)
        return {endA, spring.anchorB};
    const model::BodyState& b = states[spring.bodyB->index];
    return {endA, b.position + rotate(spring.anchorB, b.angle)};
}

void computeDerivatives(const model::World& world, std::span<const model::BodyState> states,
                        std::vector<BodyDerivative>& out)
{
    const std::size_t n = world.bodies.size();
    out.assign(n, BodyDerivative{});

    // Accumulate forces and torques in `acceleration` and `angularAcceleration` first, then divide
    // by mass and inertia once at the end.
    const Vec2 gravity = world.settings.gravity;
    const Scalar drag = world.settings.drag;
    for (std::size_t i = 0; i < n; ++i) {
        const model::Body& body = world.bodies[i];
        const model::BodyState& s = states[i];
        // Every body moves with its velocity; a fixed body's never changes (no force acts on it).
        out[i].velocity = s.velocity;
        out[i].angularVelocity = s.angularVelocity;
        if (!body.fixed)
            out[i].acceleration = body.mass * gravity - drag * s.velocity;
    }

    for (const model::Spring& spring : world.springs) {
        const auto [endA, endB] = springEnds(spring, states);
        const Vec2 d = endB - endA;
        const Scalar length = d.norm();
        // With both ends on one point the direction is undefined; the force is then zero for a
        // zero rest length, and we choose zero for any other (the spring has no line to push along).
        if (!(length > 0))
            continue;
        const Vec2 u = d / length;

        const model::Body& bodyA = world.bodies[spring.bodyA.index];
        const Vec2 velA = velocityOf(states[spring.bodyA.index], endA);
        Vec2 velB = Vec2::Zero();
        if (spring.bodyB)
            velB = velocityOf(states[spring.bodyB->index], endB);
        const Scalar lengthRate = u.dot(velB - velA);
        const Scalar tension =
            spring.stiffness * (length - spring.restLength) + spring.damping * lengthRate;
        const Vec2 forceOnA = tension * u;

        if (!bodyA.fixed) {
            BodyDerivative& da = out[spring.bodyA.index];
            da.acceleration += forceOnA;
            da.angularAcceleration += cross(Vec2(endA - states[spring.bodyA.index].position), forceOnA);
        }
        if (spring.bodyB && !world.bodies[spring.bodyB->index].fixed) {
            BodyDerivative& db = out[spring.bodyB->index];
            db.acceleration -= forceOnA;
            db.angularAcceleration -= cross(Vec2(endB - states[spring.bodyB->index].position), forceOnA);
        }
    }

    for (std::size_t i = 0; i < n; ++i) {
        const model::Body& body = world.bodies[i];
        out[i].acceleration *= body.invMass;
        out[i].angularAcceleration *= body.invInertia;
    }
}

} // namespace impetus::controller
