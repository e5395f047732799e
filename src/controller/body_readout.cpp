#include "controller/body_readout.h"

namespace impetus::controller {

BodyReadout readBody(const model::World& world, model::BodyId id)
{
    const model::Body& body = world.body(id);
    BodyReadout r;
    r.position = body.state.position;
    r.angle = body.state.angle;
    r.velocity = body.state.velocity;
    r.angularVelocity = body.state.angularVelocity;
    r.speed = body.state.velocity.norm();
    r.colliding = body.colliding;
    r.collisions = body.collisionCount;
    // A fixed body is left out of energy and momentum, as in the world's totals (diagnostics.h).
    if (!body.fixed) {
        r.momentum = body.mass * body.state.velocity;
        r.kinetic = 0.5 * body.mass * body.state.velocity.squaredNorm() +
                    0.5 * body.inertia * body.state.angularVelocity * body.state.angularVelocity;
        r.potential = -body.mass * world.settings.gravity.dot(body.state.position);
    }
    return r;
}

} // namespace impetus::controller
