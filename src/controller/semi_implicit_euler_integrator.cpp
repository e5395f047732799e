#include "controller/integrator.h"

namespace impetus::controller {

void SemiImplicitEulerIntegrator::integrate(model::World& world, Scalar h)
{
    gatherStates(world, m_states);
    computeDerivatives(world, m_states, m_derivatives);

    for (std::size_t i = 0; i < m_states.size(); ++i) {
        model::BodyState& state = m_states[i];
        const BodyDerivative& d = m_derivatives[i];
        // Velocity first, then position with the *new* velocity: the symplectic order.
        state.velocity += h * d.acceleration;
        state.angularVelocity += h * d.angularAcceleration;
        state.position += h * state.velocity;
        state.angle += h * state.angularVelocity;
    }
    scatterStates(world, m_states);
}

} // namespace impetus::controller
