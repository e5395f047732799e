#pragma once
/// \file simulation_runner.h
/// The one adapter between Qt and the engine: owns the world, runs it with the fixed time step on a
/// timer, and tells the view when it changed.

#include "controller/simulation.h"
#include "model/world.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>

#include <cstdint>
#include <functional>
#include <optional>

namespace impetus::view {

/// Owns a model::World and a controller::Simulation and advances the world in real time.
///
/// Each timer tick adds the elapsed wall time × speed() to an accumulator and calls
/// Simulation::step() with the world's fixed time step while the accumulator holds at least one
/// step. At most constants::kMaxSimulatedTimePerFrame of simulated time, and at most
/// constants::kMaxSteppingWallTimePerTickMs of wall time spent stepping, are taken per tick; the
/// backlog beyond either is dropped, so a slow frame (or a tiny time step) slows simulated time
/// down but never changes the step. The physics therefore gives the same bits whatever the frame
/// rate.
///
/// After every batch of steps (a tick, a Step, stepBy()) the runner checks the world with
/// controller::firstNonFiniteBody(). A batch that left a body's state not finite is taken back:
/// the runner puts back the world from before that batch (the last finite one, which the view
/// still shows), pauses and emits diverged(). The world at the last play() stays for a reset.
class SimulationRunner : public QObject {
    Q_OBJECT

public:
    /// A runner holding an empty world, paused.
    explicit SimulationRunner(QObject* parent = nullptr);

    /// The world in its current state.
    const model::World& world() const { return m_world; }

    /// Replaces the world (pausing first) and forgets the world saved at the last play().
    /// Emits worldChanged(), then sceneReplaced().
    void setWorld(model::World world);

    /// Changes the world in place by calling `edit` on it: an edit from the editor. A running
    /// simulation keeps running (the next step starts from the edited world), and the world saved
    /// at the last play() stays. Emits worldChanged().
    void editWorld(const std::function<void(model::World&)>& edit);

    /// True while the timer runs the simulation.
    bool isRunning() const { return m_timer.isActive(); }

    /// Simulated seconds per wall-clock second (1: real time).
    double speed() const { return m_speed; }

    /// Sets the speed factor; values that are not finite and positive are ignored.
    void setSpeed(double speed);

    /// The world as it was at the last play() since setWorld(), if any: what a reset goes back to.
    const std::optional<model::World>& worldAtLastPlay() const { return m_worldAtLastPlay; }

    /// The most fixed steps one timer tick takes: the steps in constants::kMaxSimulatedTimePerFrame,
    /// at least one, and at most 10¹⁸ (however small the time step).
    std::int64_t maxStepsPerFrame() const;

    /// Adds `wallSeconds` × speed() to the accumulator and takes fixed steps while it holds one,
    /// up to maxStepsPerFrame() and for at most constants::kMaxSteppingWallTimePerTickMs of wall
    /// time; a backlog beyond either is dropped. Emits stepped() once if it
    /// stepped (or diverged() instead, see the class comment). Returns the number of steps taken. The timer calls this with the measured frame
    /// time; tests call it directly.
    std::int64_t advanceWallTime(double wallSeconds);

public slots:
    /// Starts running in real time. Saves a copy of the world for a later reset.
    void play();

    /// Stops running; the world keeps its current state.
    void pause();

    /// play() when `running`, else pause().
    void setRunning(bool running);

    /// Pauses if running, then takes exactly one fixed step and emits stepped().
    void stepOnce();

    /// Takes `count` fixed steps at once (headless: no timer, no wall time) and emits stepped()
    /// once. Does nothing for count ≤ 0.
    void stepBy(std::int64_t count);

    /// Pauses and puts back the world saved at the last play(); emits worldChanged(). Does nothing
    /// when play() was not called since setWorld().
    void resetToLastPlay();

signals:
    /// The world was replaced or edited (a new scene, a reset, an edit): bodies may have been
    /// added or removed.
    void worldChanged();

    /// setWorld() put in a different scene (after its worldChanged()): a canvas frames it anew.
    void sceneReplaced();

    /// The world advanced by one or more fixed steps; the bodies are the same.
    void stepped();

    /// The runner started (true) or stopped (false).
    void runningChanged(bool running);

    /// A batch of steps gave body `bodyName` a position, angle or velocity that is not a finite
    /// number by simulated time `time` (s): the step is too large for a stiff spring or a fast
    /// motion. The runner has paused and put back the world from before that batch.
    void diverged(const QString& bodyName, double time);

private:
    void onTimerTick();
    void takeSteps(std::int64_t count);
    /// Ends a batch of `steps` steps that began from `before`: emits stepped(), or, when the world
    /// is no longer finite, puts `before` back, pauses and emits diverged().
    void finishBatch(std::int64_t steps, model::World before);

    model::World m_world;
    std::optional<model::World> m_worldAtLastPlay;
    controller::Simulation m_simulation;
    QTimer m_timer;
    QElapsedTimer m_clock;
    double m_accumulator = 0; ///< simulated time owed to the world, s
    double m_speed = 1;
};

} // namespace impetus::view
