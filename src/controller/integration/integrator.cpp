#include "controller/integration/integrator.h"

namespace impetus::controller {

void Integrator::integrate(model::World& world, Scalar h)
{
    gatherStates(world, m_currentStates);
    computeDerivatives(world, m_currentStates, m_currentDerivatives);
    step(world, m_currentStates, m_currentDerivatives, h, m_nextStates);
    scatterStates(world, m_nextStates);
}

std::unique_ptr<Integrator> makeIntegrator(model::IntegratorKind kind)
{
    switch (kind) {
    case model::IntegratorKind::Euler:
        return std::make_unique<ExplicitEulerIntegrator>();
    case model::IntegratorKind::SemiImplicitEuler:
        return std::make_unique<SemiImplicitEulerIntegrator>();
    case model::IntegratorKind::Rk4:
        return std::make_unique<Rk4Integrator>();
    }
    return std::make_unique<Rk4Integrator>();
}

} // namespace impetus::controller
