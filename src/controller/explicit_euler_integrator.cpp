#include "controller/integrator.h"

namespace impetus::controller {

void ExplicitEulerIntegrator::integrate(model::World& world, Scalar h)
{
    m_states.clear();
    for (const model::Body& body : world.bodies)
        m_states.push_back(body.state);
    computeDerivatives(world, m_states, m_derivatives);

    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        model::Body& body = world.bodies[i];
        const BodyDerivative& d = m_derivatives[i];
        // Both updates use the derivative at the start of the step: this is what makes the method
        // explicit, and what makes it gain energy on oscillators.
        body.state.position += h * d.velocity;
        body.state.angle += h * d.angularVelocity;
        body.state.velocity += h * d.acceleration;
        body.state.angularVelocity += h * d.angularAcceleration;
    }
}

} // namespace impetus::controller
