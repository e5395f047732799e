#include "controller/simulation.h"

#include <chrono>

namespace impetus::controller {

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

} // namespace

Simulation::Simulation()
    : m_euler(makeIntegrator(model::IntegratorKind::Euler))
    , m_semiImplicitEuler(makeIntegrator(model::IntegratorKind::SemiImplicitEuler))
    , m_rk4(makeIntegrator(model::IntegratorKind::Rk4))
{
}

Integrator& Simulation::integratorFor(model::IntegratorKind kind)
{
    switch (kind) {
    case model::IntegratorKind::Euler:
        return *m_euler;
    case model::IntegratorKind::SemiImplicitEuler:
        return *m_semiImplicitEuler;
    case model::IntegratorKind::Rk4:
        return *m_rk4;
    }
    return *m_rk4;
}

void Simulation::step(model::World& world)
{
    const Clock::time_point stepStart = Clock::now();
    const Scalar h = world.settings.timeStep;

    // Phase 1: smooth forces (gravity, springs, drag) integrated over the whole world state.
    const Clock::time_point integrateStart = Clock::now();
    integratorFor(world.settings.integrator).integrate(world, h);
    m_profile.integrateMs = millisecondsSince(integrateStart);

    // Phase 2: the clock.
    world.time += h;
    ++world.stepCount;

    m_profile.totalMs = millisecondsSince(stepStart);
}

} // namespace impetus::controller
