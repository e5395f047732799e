#include "controller/integration/integrator.h"
#include "controller/soft/soft_spin.h"

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
    if (!world.softBodies.empty()) {
        m_gridTorques.assign(world.softBodies.size(), 0);
        addGridTorques(world, start, startDerivative, 1, m_gridTorques);
        keepGridAngularMomentum(world, start, end, h, m_gridTorques);
    }
}

} // namespace impetus::controller
