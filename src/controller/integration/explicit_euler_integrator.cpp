#include "controller/integration/integrator.h"

namespace impetus::controller {

void ExplicitEulerIntegrator::step(const model::World& world, std::span<const model::BodyState> start,
                                    std::span<const BodyDerivative> startDerivative, Scalar h,
                                    std::vector<model::BodyState>& end)
{
    end.assign(start.begin(), start.end());
    for (std::size_t i = 0; i < end.size(); ++i) {
        model::BodyState& state = end[i];
        const BodyDerivative& d = startDerivative[i];
        // Both updates use the derivative at the start of the step: this is what makes the method
        // explicit, and what makes it gain energy on oscillators.
        state.position += h * d.velocity;
        state.angle += h * d.angularVelocity;
        state.velocity += h * d.acceleration;
        state.angularVelocity += h * d.angularAcceleration;
    }
    if (m_spin.begin(world)) {
        m_spin.addTorques(start, startDerivative, 1);
        m_spin.keep(start, end, h);
    }
}

} // namespace impetus::controller
