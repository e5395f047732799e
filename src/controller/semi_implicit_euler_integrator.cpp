#include "controller/integrator.h"

namespace impetus::controller {

void SemiImplicitEulerIntegrator::integrate(model::World& world, Scalar h, std::span<const BodyDerivative> start)
{
    gatherStates(world, m_states);

    for (std::size_t i = 0; i < m_states.size(); ++i) {
        model::BodyState& state = m_states[i];
        const BodyDerivative& d = start[i];
        // Velocity first, then position with the *new* velocity: the symplectic order.
        state.velocity += h * d.acceleration;
        state.angularVelocity += h * d.angularAcceleration;
        state.position += h * state.velocity;
        state.angle += h * state.angularVelocity;
    }
    scatterStates(world, m_states);
}

} // namespace impetus::controller
