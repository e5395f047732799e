#pragma once
/// \file step_worker.h
/// The thread that computes the simulation's steps for the window, so that a slow step never
/// holds up painting and input.

#include "controller/energy_ledger.h"
#include "controller/simulation.h"
#include "controller/soft/soft_stability.h"
#include "model/world.h"
#include "view/step_sample.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace impetus::view {

/// Advances `world` by one fixed step with `simulation`. The default is Simulation::step; a test
/// puts in a step that waits for it, to see what the window does while a step is slow.
using StepFunction = std::function<void(controller::Simulation& simulation, model::World& world)>;

/// A batch of fixed steps for the StepWorker to take on its own copy of a world.
struct StepBatch {
    model::World world; ///< the world to step (a copy: the caller keeps showing its own)
    std::int64_t maxSteps = 0; ///< the most steps to take
    /// Simulated time owed, s, for a run: steps are taken while it holds at least one time step,
    /// each taking one time step off it (at most maxSteps). Without it, exactly maxSteps are taken.
    std::optional<double> owed;
    /// Wall time after which the batch stops at the end of its current step (it takes at least
    /// one), so that a run shows a new state about once a frame. None: no limit.
    std::optional<std::chrono::nanoseconds> wallBudget;
    /// What to record after each step (takeSample); nothing when empty.
    SampleRequest sampling;
};

/// What a StepBatch did.
struct StepOutcome {
    model::World world; ///< the world after the steps taken
    std::int64_t steps = 0; ///< steps taken
    double leftover = 0; ///< simulated time still owed, s (what was owed minus the steps taken)
    bool cancelled = false; ///< StepWorker::cancel() stopped it; the world is not meant to be shown
    std::chrono::nanoseconds wallTime{0}; ///< wall time spent stepping
    controller::StepProfile profile; ///< Simulation::profile() after the last step taken
    controller::SoftStability stability; ///< Simulation::stability() after the last step taken
    /// controller::firstNonFiniteBody() of the world after the steps: the body that blew up.
    std::optional<std::size_t> nonFiniteBody;
    /// The bodies the engine's fixed-body guard put back in the batch's steps (Simulation::keptOut),
    /// once per pair of body and fixed body, and the simulated time of the step of the first, s.
    std::vector<controller::KeptOut> keptOut;
    double firstKeptOutTime = 0;
    /// One record per step taken, in order, when the batch's sampling asked for any.
    std::vector<StepSample> samples;
};

/// Owns a thread and a controller::Simulation and takes one StepBatch at a time on that thread.
/// All the public functions are called from one thread (the GUI's), which hands a batch over with
/// start() and takes its outcome back with takeOutcome(); the worker never touches anything else,
/// so the caller's world can be shown, edited and copied while a batch is computed.
///
/// Every step goes through the one Simulation, in the order the batches came, so the steps are
/// exactly those a single synchronous loop of Simulation::step would take: the same bits.
class StepWorker {
public:
    /// Starts the thread, idle. `finished` is called on the worker's thread each time a batch
    /// ends (its outcome is then ready): it must only hand the news over to the caller's thread.
    explicit StepWorker(std::function<void()> finished);
    /// Cancels the batch in flight, waits for its current step to end and stops the thread.
    ~StepWorker();

    StepWorker(const StepWorker&) = delete;
    StepWorker& operator=(const StepWorker&) = delete;

    /// Replaces the step function (the default is Simulation::step). Takes effect from the next
    /// batch.
    void setStepFunction(StepFunction step);

    /// Hands `batch` to the thread. Precondition: !busy().
    void start(StepBatch batch);

    /// True from start() until takeOutcome() took the batch's outcome.
    bool busy() const { return m_busy; }

    /// Asks the batch in flight to stop before its next step: a step under way is finished, no
    /// other is started, and the outcome says cancelled. Does nothing when idle.
    void cancel();

    /// Waits until the batch in flight has ended or `deadline` has passed (no deadline: until it
    /// ends). True when its outcome is ready; true at once when not busy.
    bool waitUntilDone(std::optional<std::chrono::steady_clock::time_point> deadline);

    /// The outcome of the batch in flight if it has ended (the worker is then idle), else none.
    std::optional<StepOutcome> takeOutcome();

private:
    void run();
    StepOutcome compute(StepBatch batch, const StepFunction& step);

    std::function<void()> m_finished;
    controller::Simulation m_simulation; ///< used on the worker's thread only
    /// Books the steps by cause while a batch's sampling asks for it (SampleRequest::ledger); it
    /// starts again by itself when the world it is shown was edited or replaced.
    controller::EnergyLedger m_ledger;
    mutable std::mutex m_mutex;
    std::condition_variable m_changed; ///< a batch came, an outcome is ready, or quitting
    std::optional<StepBatch> m_batch; ///< handed over, not yet picked up by the thread
    std::optional<StepOutcome> m_outcome; ///< ready, not yet taken
    StepFunction m_step;
    bool m_quit = false;
    bool m_busy = false; ///< caller's thread only
    std::atomic<bool> m_cancel = false;
    std::thread m_thread; ///< last: started once everything above exists
};

} // namespace impetus::view
