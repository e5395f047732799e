#include "controller/integration/integrator.h"

namespace impetus::controller {

void SemiImplicitEulerIntegrator::step(const model::World&, std::span<const model::BodyState> start,
                                        std::span<const BodyDerivative> startDerivative, Scalar h,
                                        std::vector<model::BodyState>& end)
{
    end.assign(start.begin(), start.end());
    for (std::size_t i = 0; i < end.size(); ++i) {
        model::BodyState& state = end[i];
        const BodyDerivative& d = startDerivative[i];
        // Velocity first, then position with the *new* velocity: the symplectic order.
        state.velocity += h * d.acceleration;
        state.angularVelocity += h * d.angularAcceleration;
        state.position += h * state.velocity;
        state.angle += h * state.angularVelocity;
    }
}

} // namespace impetus::controller
