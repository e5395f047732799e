#include "controller/integrator.h"

namespace impetus::controller {

void SemiImplicitEulerIntegrator::integrate(model::World& world, Scalar h)
{
    m_states.clear();
    for (const model::Body& body : world.bodies)
        m_states.push_back(body.state);
    computeDerivatives(world, m_states, m_derivatives);

    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        model::Body& body = world.bodies[i];
        const BodyDerivative& d = m_derivatives[i];
        // Velocity first, then position with the *new* velocity: the symplectic order.
        body.state.velocity += h * d.acceleration;
        body.state.angularVelocity += h * d.angularAcceleration;
        body.state.position += h * body.state.velocity;
        body.state.angle += h * body.state.angularVelocity;
    }
}

} // namespace impetus::controller
