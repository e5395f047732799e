#pragma once
/// \file simulation.h
/// The fixed-step driver. Simulation::step reads top to bottom as the phases it runs.

#include "controller/integrator.h"
#include "model/world.h"

#include <memory>

namespace impetus::controller {

/// Wall-clock time spent in each phase of the last step, ms. For benchmarks and profiling only;
/// nothing physical depends on it.
struct StepProfile {
    double integrateMs = 0; ///< forces and integration
    double totalMs = 0; ///< the whole step
};

/// Steps a world with its fixed time step. Holds only scratch state (the integrators' buffers),
/// so one Simulation can step any world; the world itself carries everything physical.
class Simulation {
public:
    Simulation();

    /// Advances `world` by one fixed step world.settings.timeStep with world.settings.integrator.
    void step(model::World& world);

    /// Timing of the last step().
    const StepProfile& profile() const { return m_profile; }

private:
    Integrator& integratorFor(model::IntegratorKind kind);

    std::unique_ptr<Integrator> m_euler;
    std::unique_ptr<Integrator> m_semiImplicitEuler;
    std::unique_ptr<Integrator> m_rk4;
    StepProfile m_profile;
};

} // namespace impetus::controller
