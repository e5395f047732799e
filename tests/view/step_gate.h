#pragma once
/// \file step_gate.h
/// A step function for the view tests whose steps are as slow as the test wants: each one waits
/// until the test lets it through. No clock decides anything, so the tests count and compare
/// states instead of timing them.

#include "controller/simulation.h"
#include "model/world.h"
#include "view/step_worker.h"

#include <QSemaphore>

#include <atomic>

namespace impetus::view::test {

/// Hands out a StepFunction (SimulationRunner::setStepFunction) whose every step waits for a
/// permit from open() (or for openForGood()) and then runs Simulation::step as usual. A step
/// waits at most kMaxWaitMs, so that a test that fails with the gate shut still ends.
///
/// The gate must outlive the runner that steps with it. Call openForGood() before the runner
/// goes (a qScopeGuard declared after the runner does it), so that no step is left waiting.
class StepGate {
public:
    /// The longest a step waits for its permit, ms: far longer than any test waits for a state.
    static constexpr int kMaxWaitMs = 20000;

    /// The step function; it refers to this gate.
    StepFunction function()
    {
        return [this](controller::Simulation& simulation, model::World& world) {
            ++m_started;
            if (!m_open)
                m_permits.tryAcquire(1, kMaxWaitMs);
            simulation.step(world);
        };
    }

    /// Lets `steps` more steps through.
    void open(int steps) { m_permits.release(steps); }

    /// Lets every step through from now on, the one waiting too.
    void openForGood()
    {
        m_open = true;
        m_permits.release(1);
    }

    /// Steps begun so far: those taken, and the one waiting if any.
    int started() const { return m_started; }

private:
    QSemaphore m_permits;
    std::atomic<int> m_started = 0;
    std::atomic<bool> m_open = false;
};

} // namespace impetus::view::test
