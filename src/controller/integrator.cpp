#include "controller/integrator.h"

namespace impetus::controller {

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
