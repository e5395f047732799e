#include "view/simulation_runner.h"

#include "controller/soft/soft_body_builder.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace impetus::view {

namespace {

/// Largest step count maxStepsPerFrame() reports: far beyond what a batch can take, and below
/// 2⁶³ ≈ 9.2·10¹⁸, so that converting it to std::int64_t is defined.
constexpr double kLargestStepCount = 1e18;

/// Seconds in a millisecond and in a nanosecond.
constexpr double kSecondsPerMs = 1e-3;
constexpr double kSecondsPerNs = 1e-9;

double seconds(std::chrono::nanoseconds duration) { return static_cast<double>(duration.count()) * kSecondsPerNs; }

} // namespace

SimulationRunner::SimulationRunner(QObject* parent)
    : QObject(parent)
    , m_worker(std::make_unique<StepWorker>([this] {
        // On the worker's thread: only hand the news over to this object's thread, which takes
        // the outcome when its event loop comes round to it.
        QMetaObject::invokeMethod(this, &SimulationRunner::onBatchFinished, Qt::QueuedConnection);
    }))
{
    m_timer.setInterval(constants::kFrameIntervalMs);
    // PreciseTimer: a coarse timer may fire up to 5 % late, which shows as judder at 60 Hz.
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &SimulationRunner::onTimerTick);
}

SimulationRunner::~SimulationRunner()
{
    // The worker reports to this object: stop its thread while the object is still whole. Its
    // last report, if any, is still queued and goes with the object.
    m_worker.reset();
}

void SimulationRunner::setWorld(model::World world)
{
    pause(); // also overtakes a batch being computed: its outcome belongs to the old scene
    m_world = std::move(world);
    // Soft bodies get their grids now, not at the first step: the canvas draws them from the
    // start, and an "auto" density is measured at load time and shown before Play.
    controller::prepareSoftBodies(m_world);
    m_worldAtLastPlay.reset();
    m_accumulator = 0;
    m_pace = {};
    resetPace();
    emit worldChanged();
    emit sceneReplaced();
}

void SimulationRunner::editWorld(const std::function<void(model::World&)>& edit)
{
    // The worker steps a copy of the world from before the edit: what it brings back no longer
    // holds. The steps it was asked for are taken again from the edited world.
    overtakeBatch();
    edit(m_world);
    controller::prepareSoftBodies(m_world); // a body just made soft, or a soft body resized
    emit worldChanged();
}

bool SimulationRunner::isComputing() const { return m_inFlight.has_value(); }

void SimulationRunner::setSpeed(double speed)
{
    if (std::isfinite(speed) && speed > 0)
        m_speed = speed;
}

RunPace SimulationRunner::pace() const
{
    RunPace pace = m_pace;
    pace.timeStep = m_world.settings.timeStep;
    pace.busySeconds = m_inFlight && !m_inFlight->held ? static_cast<double>(m_inFlight->clock.elapsed()) * kSecondsPerMs : 0;
    return pace;
}

void SimulationRunner::setStepFunction(StepFunction step) { m_worker->setStepFunction(std::move(step)); }

std::int64_t SimulationRunner::maxStepsPerFrame() const
{
    // A time step of 1e-300 s asks for 10²⁹⁹ steps, which no integer holds: clamp before converting
    // (a NaN, from a step that is not positive, fails the comparison and clamps too).
    const double steps = std::floor(constants::kMaxSimulatedTimePerFrame / m_world.settings.timeStep);
    return std::max<std::int64_t>(1, static_cast<std::int64_t>(steps < kLargestStepCount ? steps : kLargestStepCount));
}

std::int64_t SimulationRunner::advanceWallTime(double wallSeconds)
{
    const double dt = m_world.settings.timeStep;
    if (!(dt > 0) || !std::isfinite(wallSeconds) || wallSeconds < 0)
        return 0;
    // Whatever the worker is doing first, so that this batch starts from the newest world.
    finishSteps(std::nullopt);
    addWallTime(wallSeconds);
    if (!startNextBatch(true))
        return 0;
    m_worker->waitUntilDone(std::nullopt);
    return collectBatch();
}

void SimulationRunner::play()
{
    if (isRunning())
        return;
    // The run starts from the world shown: Steps still being computed would land on it later.
    m_stepsAsked = 0;
    overtakeBatch();
    setComputingStep(false);
    m_worldAtLastPlay = m_world;
    m_accumulator = 0;
    resetPace();
    m_clock.start();
    m_timer.start();
    emit runningChanged(true);
}

void SimulationRunner::pause()
{
    m_stepsAsked = 0;
    overtakeBatch();
    setComputingStep(false);
    stopTimer();
}

void SimulationRunner::setRunning(bool running)
{
    if (running)
        play();
    else
        pause();
}

void SimulationRunner::stepOnce()
{
    stopTimer();
    ++m_stepsAsked;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(constants::kStepWaitMs);
    if (!finishSteps(deadline))
        setComputingStep(true);
}

void SimulationRunner::stepBy(std::int64_t count)
{
    if (count <= 0)
        return;
    m_stepsAsked += count;
    finishSteps(std::nullopt);
}

void SimulationRunner::resetToLastPlay()
{
    if (!m_worldAtLastPlay)
        return;
    pause();
    m_world = *m_worldAtLastPlay;
    m_accumulator = 0;
    emit worldChanged();
}

void SimulationRunner::showState(model::World world)
{
    pause();
    m_world = std::move(world);
    m_accumulator = 0;
    emit worldChanged();
}

void SimulationRunner::setSampleRequest(SampleRequest request) { m_sampling = std::move(request); }

void SimulationRunner::onTimerTick()
{
    // Measure the real time since the last tick rather than trusting the timer interval: timers
    // fire late under load, and the simulation must follow the wall clock, not the tick count.
    const double elapsed = static_cast<double>(m_clock.nsecsElapsed()) * kSecondsPerNs;
    m_clock.restart();
    addWallTime(elapsed);
    // The batch held for this tick is shown now; one still computing is late for it.
    if (m_inFlight && m_inFlight->held)
        collectBatch();
    else if (m_inFlight)
        m_inFlight->ticked = true;
    startNextBatch(true);
    closePaceWindowIfDue();
}

void SimulationRunner::onBatchFinished()
{
    // A run's batch that ends before the next tick waits for it, so that new states come at the
    // timer's even 60 Hz rather than whenever a batch ends: a batch started at a tick and another
    // started on the heels of a late one made frames of 11 and 22 ms in turn, 16.7 on average but
    // half of them over the budget (docs/benchmarks.md, "Frames at the timer's pace"). One that
    // a tick found still computing is late, and is shown at once as before.
    const bool ready = m_inFlight && m_worker->waitUntilDone(std::chrono::steady_clock::now());
    if (ready && m_inFlight->kind == BatchKind::Run && !m_inFlight->overtaken && !m_inFlight->ticked &&
        isRunning()) {
        m_inFlight->held = true;
        return;
    }
    // Its outcome may have been taken already by a caller that waited for it: nothing to do then.
    collectBatch();
    // Straight on with the next batch rather than at the next tick: a worker that cannot keep up
    // never sits idle, and Steps asked for while one was computed follow at once.
    startNextBatch(isRunning());
    if (m_stepsAsked == 0)
        setComputingStep(false);
}

void SimulationRunner::addWallTime(double wallSeconds)
{
    const double owed = wallSeconds * m_speed;
    m_accumulator += owed;
    if (isRunning()) {
        m_window.wall += wallSeconds;
        m_window.owed += owed;
    }
    // While a batch is computed, time owed piles up for the next one: no more than one batch
    // takes, or a long step would leave a backlog that the following steps could never work off.
    const double most = static_cast<double>(maxStepsPerFrame()) * m_world.settings.timeStep;
    if (m_inFlight && m_accumulator > most) {
        dropSimulatedTime(m_accumulator - most);
        m_accumulator = most;
    }
}

bool SimulationRunner::startNextBatch(bool runOwed)
{
    if (m_inFlight)
        return false;
    const double dt = m_world.settings.timeStep;
    InFlight batch;
    if (m_stepsAsked > 0) {
        batch.kind = BatchKind::Steps;
        m_worker->start(StepBatch{m_world, m_stepsAsked, std::nullopt, std::nullopt, m_sampling});
    } else if (runOwed && dt > 0 && m_accumulator >= dt) {
        batch.kind = BatchKind::Run;
        batch.owed = m_accumulator;
        const auto budget = std::chrono::duration_cast<std::chrono::nanoseconds>(
            std::chrono::duration<double, std::milli>(constants::kMaxBatchWallTimeMs));
        m_worker->start(StepBatch{m_world, maxStepsPerFrame(), m_accumulator, budget, m_sampling});
        m_accumulator = 0;
    } else {
        return false;
    }
    batch.clock.start();
    m_inFlight = batch;
    return true;
}

std::int64_t SimulationRunner::collectBatch()
{
    if (!m_inFlight)
        return 0;
    std::optional<StepOutcome> outcome = m_worker->takeOutcome();
    if (!outcome)
        return 0;
    const InFlight batch = *m_inFlight;
    m_inFlight.reset();
    const double dt = outcome->world.settings.timeStep;
    if (batch.overtaken) {
        if (batch.kind == BatchKind::Run)
            dropSimulatedTime(batch.owed);
        return 0;
    }
    if (outcome->nonFiniteBody) {
        // Not a number spreads to every body it touches and cannot be drawn: keep the last finite
        // world, which the view still shows, and stop, so that the user can read it, reset or undo.
        const QString name = QString::fromStdString(outcome->world.bodies[*outcome->nonFiniteBody].name);
        const double time = outcome->world.time;
        m_accumulator = 0;
        pause();
        emit diverged(name, time);
        return 0;
    }
    if (batch.kind == BatchKind::Run) {
        // The batch owed more than it could take (steps or wall time): drop the backlog so that
        // simulated time slows down instead of later batches trying, and failing, to catch up.
        if (outcome->leftover >= dt)
            dropSimulatedTime(outcome->leftover);
        else
            m_accumulator += outcome->leftover;
    } else {
        m_stepsAsked -= outcome->steps;
    }
    const std::int64_t steps = outcome->steps;
    if (isRunning())
        m_window.advanced += static_cast<double>(steps) * dt;
    m_pace.costKnown = true;
    m_pace.wallSecondsPerStep = seconds(outcome->wallTime) / static_cast<double>(steps);
    m_pace.profile = outcome->profile;
    m_pace.stability = std::move(outcome->stability);
    m_world = std::move(outcome->world);
    if (!outcome->keptOut.empty()) {
        const controller::KeptOut& first = outcome->keptOut.front();
        emit keptOut(QString::fromStdString(m_world.bodies[first.body].name),
                     QString::fromStdString(m_world.bodies[first.fixedBody].name), outcome->firstKeptOutTime,
                     static_cast<int>(outcome->keptOut.size()) - 1);
    }
    if (!outcome->samples.empty())
        emit sampled(outcome->samples);
    emit stepped();
    return steps;
}

void SimulationRunner::overtakeBatch()
{
    if (!m_inFlight || m_inFlight->overtaken)
        return;
    m_inFlight->overtaken = true;
    m_worker->cancel();
    // A batch held for the next tick has ended: nothing will report it again, so it goes now.
    if (m_inFlight->held)
        collectBatch();
}

bool SimulationRunner::finishSteps(std::optional<std::chrono::steady_clock::time_point> deadline)
{
    for (;;) {
        if (!m_inFlight && !startNextBatch(false))
            return true;
        if (!m_worker->waitUntilDone(deadline))
            return false;
        collectBatch();
    }
}

void SimulationRunner::stopTimer()
{
    if (!isRunning())
        return;
    m_timer.stop();
    // A run's batch still being computed would move the world on after the pause: not shown.
    if (m_inFlight && m_inFlight->kind == BatchKind::Run)
        overtakeBatch();
    resetPace();
    emit runningChanged(false);
}

void SimulationRunner::setComputingStep(bool computing)
{
    if (computing == m_computingStep)
        return;
    m_computingStep = computing;
    emit computingStepChanged(computing);
}

void SimulationRunner::dropSimulatedTime(double lost)
{
    if (isRunning())
        m_window.dropped += lost;
}

void SimulationRunner::closePaceWindowIfDue()
{
    if (m_window.wall < constants::kPaceWindowSeconds)
        return;
    std::shift_left(m_pastWindows.begin(), m_pastWindows.end(), 1);
    m_pastWindows.back() = m_window;
    double wall = 0;
    double advanced = 0;
    for (const PaceWindow& window : m_pastWindows) {
        wall += window.wall;
        advanced += window.advanced;
    }
    m_pace.behind = m_window.dropped > constants::kBehindTolerance * m_window.owed;
    m_pace.achievedSpeed = advanced / wall;
    m_pace.requestedSpeed = m_speed;
    m_window = {};
    emit paceChanged();
}

void SimulationRunner::resetPace()
{
    m_window = {};
    m_pastWindows = {};
    m_pace.behind = false;
    m_pace.achievedSpeed = 0;
    m_pace.requestedSpeed = m_speed;
    emit paceChanged();
}

} // namespace impetus::view
