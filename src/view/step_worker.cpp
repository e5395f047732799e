#include "view/step_worker.h"

#include <algorithm>

#include "controller/diagnostics.h"
#include "view/view_constants.h"

#include <utility>

namespace impetus::view {

namespace {

/// The engine's settings on the worker: its second thread only where the machine has a core for
/// it besides the GUI thread and this one. On two cores the GUI thread's paint and the engine's
/// two threads took turns on them: the 2000-body example's live frame was 22 ms at the median
/// with the second thread and 16 ms without it, its physics as fast either way (same bits).
controller::SolverSettings workerSettings()
{
    controller::SolverSettings settings;
    settings.secondThread = std::thread::hardware_concurrency() > constants::kCoresForGuiAndWorker;
    return settings;
}

} // namespace

StepWorker::StepWorker(std::function<void()> finished)
    : m_finished(std::move(finished))
    , m_simulation(workerSettings())
    , m_step([](controller::Simulation& simulation, model::World& world) { simulation.step(world); })
    , m_thread([this] { run(); })
{
}

StepWorker::~StepWorker()
{
    {
        const std::lock_guard lock(m_mutex);
        m_quit = true;
    }
    m_cancel = true;
    m_changed.notify_all();
    m_thread.join();
}

void StepWorker::setStepFunction(StepFunction step)
{
    const std::lock_guard lock(m_mutex);
    m_step = std::move(step);
}

void StepWorker::start(StepBatch batch)
{
    // Cleared before the thread can pick the batch up: a cancel() is only ever for this batch.
    m_cancel = false;
    {
        const std::lock_guard lock(m_mutex);
        m_batch = std::move(batch);
        m_outcome.reset();
    }
    m_busy = true;
    m_changed.notify_all();
}

void StepWorker::cancel()
{
    if (m_busy)
        m_cancel = true;
}

bool StepWorker::waitUntilDone(std::optional<std::chrono::steady_clock::time_point> deadline)
{
    if (!m_busy)
        return true;
    std::unique_lock lock(m_mutex);
    const auto done = [this] { return m_outcome.has_value(); };
    if (!deadline) {
        m_changed.wait(lock, done);
        return true;
    }
    return m_changed.wait_until(lock, *deadline, done);
}

std::optional<StepOutcome> StepWorker::takeOutcome()
{
    std::optional<StepOutcome> outcome;
    {
        const std::lock_guard lock(m_mutex);
        outcome.swap(m_outcome);
    }
    if (outcome)
        m_busy = false;
    return outcome;
}

void StepWorker::run()
{
    for (;;) {
        StepBatch batch;
        StepFunction step;
        {
            std::unique_lock lock(m_mutex);
            m_changed.wait(lock, [this] { return m_quit || m_batch.has_value(); });
            if (m_quit)
                return;
            batch = std::move(*m_batch);
            m_batch.reset();
            step = m_step;
        }
        StepOutcome outcome = compute(std::move(batch), step);
        {
            const std::lock_guard lock(m_mutex);
            m_outcome = std::move(outcome);
        }
        m_changed.notify_all();
        m_finished();
    }
}

StepOutcome StepWorker::compute(StepBatch batch, const StepFunction& step)
{
    StepOutcome outcome;
    const double dt = batch.world.settings.timeStep;
    double owed = batch.owed.value_or(0);
    const auto start = std::chrono::steady_clock::now();
    m_simulation.setLedger(batch.sampling.ledger ? &m_ledger : nullptr);
    // The same loop the window ran on its own thread before: a run takes steps while a whole step
    // is owed, one time step off the debt each, so the simulated time never depends on the frame.
    while (outcome.steps < batch.maxSteps && (!batch.owed || owed >= dt)) {
        if (m_cancel) {
            outcome.cancelled = true;
            break;
        }
        step(m_simulation, batch.world);
        ++outcome.steps;
        for (const controller::KeptOut& kept : m_simulation.keptOut()) {
            if (outcome.keptOut.empty())
                outcome.firstKeptOutTime = batch.world.time;
            if (std::find(outcome.keptOut.begin(), outcome.keptOut.end(), kept) == outcome.keptOut.end())
                outcome.keptOut.push_back(kept);
        }
        if (!batch.sampling.empty()) {
            outcome.samples.push_back(takeSample(batch.world, batch.sampling));
            if (batch.sampling.ledger && m_ledger.started()) {
                outcome.samples.back().ledger = controller::LedgerSample{
                    m_ledger.startTime(), m_ledger.initialEnergy(), m_ledger.currentEnergy(), m_ledger.losses()};
            }
        }
        if (batch.owed)
            owed -= dt;
        if (batch.wallBudget && std::chrono::steady_clock::now() - start >= *batch.wallBudget)
            break;
    }
    outcome.wallTime = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start);
    outcome.leftover = owed;
    if (outcome.steps > 0) {
        outcome.profile = m_simulation.profile();
        outcome.stability = m_simulation.stability();
        outcome.nonFiniteBody = controller::firstNonFiniteBody(batch.world);
    }
    outcome.world = std::move(batch.world);
    return outcome;
}

} // namespace impetus::view
