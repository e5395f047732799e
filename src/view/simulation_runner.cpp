#include "view/simulation_runner.h"

#include "controller/diagnostics.h"
#include "controller/soft/soft_body_builder.h"
#include "view/view_constants.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace impetus::view {

namespace {

/// Largest step count maxStepsPerFrame() reports: far beyond what a tick can take, and below
/// 2⁶³ ≈ 9.2·10¹⁸, so that converting it to std::int64_t is defined.
constexpr double kLargestStepCount = 1e18;

} // namespace

SimulationRunner::SimulationRunner(QObject* parent)
    : QObject(parent)
{
    m_timer.setInterval(constants::kFrameIntervalMs);
    // PreciseTimer: a coarse timer may fire up to 5 % late, which shows as judder at 60 Hz.
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &SimulationRunner::onTimerTick);
}

void SimulationRunner::setWorld(model::World world)
{
    pause();
    m_world = std::move(world);
    // Soft bodies get their grids now, not at the first step: the canvas draws them from the
    // start, and an "auto" density is measured at load time and shown before Play.
    controller::prepareSoftBodies(m_world);
    m_worldAtLastPlay.reset();
    m_accumulator = 0;
    emit worldChanged();
    emit sceneReplaced();
}

void SimulationRunner::editWorld(const std::function<void(model::World&)>& edit)
{
    edit(m_world);
    controller::prepareSoftBodies(m_world); // a body just made soft, or a soft body resized
    emit worldChanged();
}

void SimulationRunner::setSpeed(double speed)
{
    if (std::isfinite(speed) && speed > 0)
        m_speed = speed;
}

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
    m_accumulator += wallSeconds * m_speed;
    const std::int64_t maxSteps = maxStepsPerFrame();
    if (!(m_accumulator >= dt))
        return 0;
    model::World before = m_world;
    QElapsedTimer wallClock;
    wallClock.start();
    const auto budgetNs = static_cast<qint64>(constants::kMaxSteppingWallTimePerTickMs * 1e6);
    std::int64_t steps = 0;
    while (m_accumulator >= dt && steps < maxSteps) {
        m_simulation.step(m_world);
        m_accumulator -= dt;
        ++steps;
        if (wallClock.nsecsElapsed() >= budgetNs)
            break;
    }
    // The frame owed more than we may simulate in one tick, or the steps took longer than the
    // tick may: drop the backlog so that simulated time slows down instead of the next frames
    // trying (and failing) to catch up while the window stops answering.
    if (m_accumulator >= dt)
        m_accumulator = 0;
    finishBatch(steps, std::move(before));
    return steps;
}

void SimulationRunner::play()
{
    if (isRunning())
        return;
    m_worldAtLastPlay = m_world;
    m_accumulator = 0;
    m_clock.start();
    m_timer.start();
    emit runningChanged(true);
}

void SimulationRunner::pause()
{
    if (!isRunning())
        return;
    m_timer.stop();
    emit runningChanged(false);
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
    pause();
    takeSteps(1);
}

void SimulationRunner::stepBy(std::int64_t count)
{
    if (count > 0)
        takeSteps(count);
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

void SimulationRunner::onTimerTick()
{
    // Measure the real time since the last tick rather than trusting the timer interval: timers
    // fire late under load, and the simulation must follow the wall clock, not the tick count.
    const double elapsed = static_cast<double>(m_clock.nsecsElapsed()) * 1e-9;
    m_clock.restart();
    advanceWallTime(elapsed);
}

void SimulationRunner::takeSteps(std::int64_t count)
{
    model::World before = m_world;
    for (std::int64_t i = 0; i < count; ++i)
        m_simulation.step(m_world);
    finishBatch(count, std::move(before));
}

void SimulationRunner::finishBatch(std::int64_t steps, model::World before)
{
    if (steps <= 0)
        return;
    const std::optional<std::size_t> bad = controller::firstNonFiniteBody(m_world);
    if (!bad) {
        emit stepped();
        return;
    }
    // Not a number spreads to every body it touches and cannot be drawn: keep the last finite
    // world, which the view still shows, and stop, so that the user can read it, reset or undo.
    const QString name = QString::fromStdString(m_world.bodies[*bad].name);
    const double time = m_world.time;
    m_world = std::move(before);
    m_accumulator = 0;
    pause();
    emit diverged(name, time);
}

} // namespace impetus::view
