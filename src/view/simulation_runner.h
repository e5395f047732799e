#pragma once
/// \file simulation_runner.h
/// The one adapter between Qt and the engine: owns the world, runs it with the fixed time step on a
/// worker thread paced by a timer, and tells the view when it changed.

#include "controller/simulation.h"
#include "controller/soft/soft_stability.h"
#include "model/world.h"
#include "view/step_worker.h"
#include "view/view_constants.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>

#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

namespace impetus::view {

/// How a run keeps up with the wall clock, and what its steps cost: what the window shows when the
/// simulation runs slower than real time, and why. Measured by the runner, never by the engine.
struct RunPace {
    /// True when the last measuring window (constants::kPaceWindowSeconds of running) had to drop
    /// more than constants::kBehindTolerance of the simulated time it owed: simulated time runs
    /// slower than speed() asks.
    bool behind = false;
    /// Simulated seconds per wall-clock second over the last constants::kPaceWindowsAveraged
    /// windows (1: real time). Meaningful once a window has been measured.
    double achievedSpeed = 0;
    double requestedSpeed = 1; ///< speed() when the window was measured
    double timeStep = 0; ///< the world's fixed step, s
    /// Wall time the batch being computed has taken so far, s; 0 when none is under way.
    double busySeconds = 0;
    /// A batch of steps was computed since setWorld(): the fields below hold (they are kept over
    /// pauses and plays, and describe the last batch shown).
    bool costKnown = false;
    /// Wall time one step took to compute, s, in the last batch (its wall time over its steps).
    double wallSecondsPerStep = 0;
    controller::StepProfile profile; ///< Simulation::profile() of the last step computed
    controller::SoftStability stability; ///< Simulation::stability() of the last step computed
};

/// Owns a model::World and advances it in real time without ever holding up the window.
///
/// The steps are computed by a StepWorker on its own thread, on a copy of the world; the runner's
/// world() is the last state computed in full, which is what the view shows. While running, each
/// timer tick adds the elapsed wall time × speed() to an accumulator, and whenever the worker is
/// idle the runner hands it a batch: Simulation::step() with the world's fixed time step while
/// the accumulator holds at least one step, at most maxStepsPerFrame() steps, and for at most
/// constants::kMaxBatchWallTimeMs of wall time. The backlog beyond either is dropped, and while a
/// batch is computed the accumulator keeps at most maxStepsPerFrame() steps: a slow step (or a
/// tiny time step) slows simulated time down but never changes the step, and the window keeps
/// painting and answering while the worker computes. pace() says how far behind the wall clock
/// the run falls and why.
///
/// The steps are those of one synchronous loop: every step goes through one Simulation in order,
/// none is taken twice or skipped, so the physics gives the same bits whatever the frame rate or
/// the cost of a step. A batch that is overtaken — the run paused, the world edited, replaced or
/// reset while it is computed — is thrown away when it ends: the world shown is the one kept, and
/// the next batch starts from it (with an edit in it). Nothing but the worker's own copy is ever
/// touched off the GUI thread.
///
/// After every batch (a run's, a Step's, stepBy()'s) the worker checks the world with
/// controller::firstNonFiniteBody(). A batch that left a body's state not finite is not shown:
/// the runner keeps the world from before it (the last finite one, which the view still shows),
/// pauses and emits diverged(). The world at the last play() stays for a reset.
class SimulationRunner : public QObject {
    Q_OBJECT

public:
    /// A runner holding an empty world, paused; its worker thread is started, idle.
    explicit SimulationRunner(QObject* parent = nullptr);
    /// Stops the worker, waiting for a step under way to end.
    ~SimulationRunner() override;

    /// The world in its current state: the last one computed in full.
    const model::World& world() const { return m_world; }

    /// Replaces the world (pausing first, dropping any step being computed) and forgets the world
    /// saved at the last play(). Emits worldChanged(), then sceneReplaced().
    void setWorld(model::World world);

    /// Pauses (dropping any step being computed) and shows `world`, a state of the same run taken
    /// from its timeline: not an edit, and the world saved at the last play() stays. Emits
    /// worldChanged().
    void showState(model::World world);

    /// What to record after every step from the next batch on (sampled() hands it over).
    void setSampleRequest(SampleRequest request);
    /// What is recorded after every step.
    const SampleRequest& sampleRequest() const { return m_sampling; }

    /// Changes the world in place by calling `edit` on it: an edit from the editor. A batch being
    /// computed is overtaken (see the class comment), so the edit never races the worker; a
    /// running simulation keeps running, the next step starts from the edited world, and Steps
    /// asked for and not yet taken are taken from it. The world saved at the last play() stays.
    /// Emits worldChanged().
    void editWorld(const std::function<void(model::World&)>& edit);

    /// True while the timer runs the simulation.
    bool isRunning() const { return m_timer.isActive(); }

    /// True while the worker computes a batch, shown or overtaken.
    bool isComputing() const;

    /// True while a Step (stepOnce()) is computed in the background: it took longer than
    /// constants::kStepWaitMs and is shown when it ends.
    bool isComputingStep() const { return m_computingStep; }

    /// Simulated seconds per wall-clock second (1: real time).
    double speed() const { return m_speed; }

    /// Sets the speed factor; values that are not finite and positive are ignored.
    void setSpeed(double speed);

    /// How the run keeps up with the wall clock (measured afresh from each play()) and what the
    /// last steps shown cost.
    RunPace pace() const;

    /// Replaces the function that takes one step (Simulation::step by default), from the next
    /// batch on. It runs on the worker's thread. For tests, which make steps slow on purpose.
    void setStepFunction(StepFunction step);

    /// The world as it was at the last play() since setWorld(), if any: what a reset goes back to.
    const std::optional<model::World>& worldAtLastPlay() const { return m_worldAtLastPlay; }

    /// The most fixed steps one batch takes: the steps in constants::kMaxSimulatedTimePerFrame,
    /// at least one, and at most 10¹⁸ (however small the time step).
    std::int64_t maxStepsPerFrame() const;

    /// What a timer tick does, but waiting for the batch: adds `wallSeconds` × speed() to the
    /// accumulator and takes fixed steps while it holds one, up to maxStepsPerFrame() and for at
    /// most constants::kMaxBatchWallTimeMs of wall time; a backlog beyond either is dropped.
    /// Emits stepped() once if it stepped (or diverged() instead, see the class comment). Returns
    /// the number of steps taken. The timer does the same without waiting; tests call this to
    /// step a run without a clock.
    std::int64_t advanceWallTime(double wallSeconds);

public slots:
    /// Starts running in real time. Saves a copy of the world for a later reset. Steps asked for
    /// and not yet taken are dropped: the run starts from the world shown.
    void play();

    /// Stops running, and drops Steps asked for and not yet taken: the world stays as shown.
    void pause();

    /// play() when `running`, else pause().
    void setRunning(bool running);

    /// Stops running if it runs, then takes one more fixed step and emits stepped() when it is
    /// done. Waits for it up to constants::kStepWaitMs; a slower step goes on in the background
    /// (isComputingStep(), computingStepChanged()) while the window keeps answering, and is shown
    /// when it ends. Steps asked for while one is computed are taken one after the other.
    void stepOnce();

    /// Takes `count` fixed steps at once and emits stepped() once, waiting for them however long
    /// they take (headless: the screenshot mode, tests). Does nothing for count ≤ 0.
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

    /// The steps of a batch about to be shown were recorded as sampleRequest() asks: one sample
    /// per step, in order. Emitted just before the stepped() of the same batch.
    void sampled(const std::vector<StepSample>& samples);

    /// The world advanced by one or more fixed steps; the bodies are the same.
    void stepped();

    /// The runner started (true) or stopped (false).
    void runningChanged(bool running);

    /// pace() changed: a measuring window ended, or the run started or stopped.
    void paceChanged();

    /// A Step went on in the background (true), or it was shown or dropped (false).
    void computingStepChanged(bool computing);

    /// A batch of steps gave body `bodyName` a position, angle or velocity that is not a finite
    /// number by simulated time `time` (s): the step is too large for a stiff spring or a fast
    /// motion. The runner has paused and kept the world from before that batch.
    void diverged(const QString& bodyName, double time);

    /// A batch of steps about to be shown had the engine's fixed-body guard put body `bodyName`
    /// back out of fixed body `fixedName` at simulated time `time` (s), and `others` more pairs
    /// besides: the solve let a centre into a wall there (controller::FixedBodyGuard). Emitted
    /// just before the batch's stepped().
    void keptOut(const QString& bodyName, const QString& fixedName, double time, int others);

private:
    /// What the batch in flight was for.
    enum class BatchKind : std::uint8_t { Run, Steps };

    /// The batch the worker computes, as the runner sees it.
    struct InFlight {
        BatchKind kind = BatchKind::Run;
        double owed = 0; ///< simulated time a run's batch took off the accumulator, s
        bool overtaken = false; ///< its outcome is thrown away when it ends
        bool ticked = false; ///< a timer tick came while it was computed: it is late for that frame
        bool held = false; ///< a run's batch that ended early, held for the next tick (onBatchFinished)
        QElapsedTimer clock; ///< started when the batch was handed over
    };

    /// Simulated and wall time of one measuring window while running.
    struct PaceWindow {
        double wall = 0; ///< wall time, s
        double owed = 0; ///< simulated time asked for (wall × speed), s
        double dropped = 0; ///< simulated time given up (backlogs dropped, batches overtaken), s
        double advanced = 0; ///< simulated time taken in steps that were shown, s
    };

    void onTimerTick();
    void onBatchFinished();
    /// Adds `wallSeconds` × speed() to the accumulator (and to the measuring window while
    /// running); while a batch is computed, keeps at most maxStepsPerFrame() steps of it.
    void addWallTime(double wallSeconds);
    /// Hands the worker its next batch when it is idle: the Steps asked for first, else, with
    /// `runOwed`, the simulated time owed. Returns true when it handed one over.
    bool startNextBatch(bool runOwed);
    /// Takes the outcome of the batch in flight if it has ended and shows it (or throws it away
    /// when overtaken). Returns the steps shown.
    std::int64_t collectBatch();
    /// Marks the batch in flight as overtaken and asks the worker to stop it.
    void overtakeBatch();
    /// Waits for the batch in flight and the Steps asked for, until `deadline` (none: however
    /// long they take). True when nothing is left to compute.
    bool finishSteps(std::optional<std::chrono::steady_clock::time_point> deadline);
    /// Stops the timer if it runs and emits runningChanged(false).
    void stopTimer();
    void setComputingStep(bool computing);
    /// Gives up `lost` seconds of owed simulated time (counted in the measuring window).
    void dropSimulatedTime(double lost);
    /// Closes the measuring window when it is long enough, updating pace().
    void closePaceWindowIfDue();
    void resetPace();

    model::World m_world;
    std::optional<model::World> m_worldAtLastPlay;
    QTimer m_timer;
    QElapsedTimer m_clock;
    double m_accumulator = 0; ///< simulated time owed to the world, s
    double m_speed = 1;
    std::optional<InFlight> m_inFlight;
    std::int64_t m_stepsAsked = 0; ///< Steps asked for and not yet shown
    bool m_computingStep = false;
    PaceWindow m_window;
    /// The last measuring windows (wall time, simulated time advanced), s, oldest first.
    std::array<PaceWindow, constants::kPaceWindowsAveraged> m_pastWindows{};
    RunPace m_pace;
    SampleRequest m_sampling;
    /// Last: destroyed first, so that its thread has stopped before anything it reports to goes.
    std::unique_ptr<StepWorker> m_worker;
};

} // namespace impetus::view
