#include "controller/integrator.h"

namespace impetus::controller {

void ExplicitEulerIntegrator::integrate(model::World& world, Scalar h, std::span<const BodyDerivative> start)
{
    gatherStates(world, m_states);

    for (std::size_t i = 0; i < m_states.size(); ++i) {
        model::BodyState& state = m_states[i];
        const BodyDerivative& d = start[i];
        // Both updates use the derivative at the start of the step: this is what makes the method
        // explicit, and what makes it gain energy on oscillators.
        state.position += h * d.velocity;
        state.angle += h * d.angularVelocity;
        state.velocity += h * d.acceleration;
        state.angularVelocity += h * d.angularAcceleration;
    }
    scatterStates(world, m_states);
}

} // namespace impetus::controller
