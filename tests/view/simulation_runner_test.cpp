// SimulationRunner: the fixed-step accumulator, its per-frame cap, play/pause/step/reset, and the
// worker thread that keeps the event loop running while a step is slow.

#include "controller/simulation.h"
#include "model/example_scenes.h"
#include "step_gate.h"
#include "test_worlds.h"
#include "view/simulation_runner.h"
#include "view/view_constants.h"

#include "controller/diagnostics.h"

#include <QEventLoop>
#include <QScopeGuard>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>
#include <vector>
#include <algorithm>
#include <chrono>
#include <mutex>

using impetus::view::SimulationRunner;
namespace model = impetus::model;
namespace test = impetus::view::test;

class SimulationRunnerTest : public QObject {
    Q_OBJECT

private slots:
    void setWorldPausesAndEmitsWorldChanged();
    void advanceTakesOnlyFixedSteps();
    void advanceCapsStepsPerFrameAndDropsBacklog();
    void speedScalesSimulatedTime();
    void stepByMatchesSimulationStep();
    void stepOncePausesAndTakesOneStep();
    void playRunsInRealTimeAndPauseStops();
    void resetGoesBackToLastPlay();
    void editWorldKeepsRunningAndTheWorldAtPlay();
    void divergingBatchIsTakenBackPausedAndReported();
    void divergingStepsAreReportedToo();
    void tinyTimeStepCannotFreezeATick();
    void slowStepLeavesTheEventLoopRunning();
    void slowRunFallsBehindAndSaysSo();
    void editDuringASlowStepGoesToTheWorldShown();
    void slowStepGoesOnInTheBackground();
    void workerGivesTheSameBitsAsOneLoop();
    void anEarlyBatchIsShownAtTheNextTick();
    void pauseAndEditDropAHeldBatch();
};

namespace {

/// True once a zero-length timer posted now has fired: the event loop is running.
bool eventLoopRuns()
{
    bool fired = false;
    QTimer::singleShot(0, [&fired] { fired = true; });
    return QTest::qWaitFor([&fired] { return fired; });
}

} // namespace

void SimulationRunnerTest::setWorldPausesAndEmitsWorldChanged()
{
    SimulationRunner runner;
    runner.play();
    QSignalSpy changed(&runner, &SimulationRunner::worldChanged);
    QSignalSpy running(&runner, &SimulationRunner::runningChanged);
    runner.setWorld(test::risingBallWorld());
    QCOMPARE(changed.count(), 1);
    QCOMPARE(running.count(), 1);
    QCOMPARE(running.at(0).at(0).toBool(), false);
    QVERIFY(!runner.isRunning());
    QCOMPARE(runner.world().bodies.size(), std::size_t(2));
    QVERIFY(!runner.worldAtLastPlay().has_value());
}

void SimulationRunnerTest::advanceTakesOnlyFixedSteps()
{
    SimulationRunner runner;
    runner.setWorld(test::risingBallWorld());
    const double dt = runner.world().settings.timeStep;
    QSignalSpy stepped(&runner, &SimulationRunner::stepped);

    // 2.5 steps of wall time: two fixed steps, half a step stays in the accumulator.
    QCOMPARE(runner.advanceWallTime(2.5 * dt), std::int64_t(2));
    QCOMPARE(runner.world().stepCount, std::int64_t(2));
    QCOMPARE(stepped.count(), 1);
    // Less than a step owed: nothing happens, no signal.
    QCOMPARE(runner.advanceWallTime(0.25 * dt), std::int64_t(0));
    QCOMPARE(stepped.count(), 1);
    // The carried 0.75 step plus 0.5 more makes one step.
    QCOMPARE(runner.advanceWallTime(0.5 * dt), std::int64_t(1));
    QCOMPARE(runner.world().stepCount, std::int64_t(3));

    // The ball moves at 1 m/s with no force: after 3 steps of dt it is at 3·dt, which holds only
    // if every step was exactly dt.
    QVERIFY(qAbs(runner.world().bodies[0].state.position.y() - 3 * dt) < 1e-12);
}

void SimulationRunnerTest::advanceCapsStepsPerFrameAndDropsBacklog()
{
    SimulationRunner runner;
    runner.setWorld(test::risingBallWorld());
    const double dt = runner.world().settings.timeStep;
    const std::int64_t cap = runner.maxStepsPerFrame();
    QCOMPARE(cap, std::int64_t(24)); // 0.1 s at 1/240 s

    // A one-second stall takes at most `cap` steps of dt: simulated time slows down...
    QCOMPARE(runner.advanceWallTime(1.0), cap);
    QVERIFY(qAbs(runner.world().time - static_cast<double>(cap) * dt) < 1e-12);
    // ...and the rest of that second is dropped, not caught up later.
    QCOMPARE(runner.advanceWallTime(0.0), std::int64_t(0));
    QCOMPARE(runner.world().stepCount, cap);
}

void SimulationRunnerTest::speedScalesSimulatedTime()
{
    SimulationRunner runner;
    runner.setWorld(test::risingBallWorld());
    const double dt = runner.world().settings.timeStep;
    runner.setSpeed(2.0);
    QCOMPARE(runner.speed(), 2.0);
    QCOMPARE(runner.advanceWallTime(1.5 * dt), std::int64_t(3));
    runner.setSpeed(-1.0); // ignored
    QCOMPARE(runner.speed(), 2.0);
}

void SimulationRunnerTest::stepByMatchesSimulationStep()
{
    SimulationRunner runner;
    runner.setWorld(test::hangingBoxWorld());
    QSignalSpy stepped(&runner, &SimulationRunner::stepped);
    runner.stepBy(100);
    QCOMPARE(stepped.count(), 1);

    model::World expected = test::hangingBoxWorld();
    impetus::controller::Simulation simulation;
    for (int i = 0; i < 100; ++i)
        simulation.step(expected);
    QVERIFY(runner.world() == expected);
}

void SimulationRunnerTest::stepOncePausesAndTakesOneStep()
{
    SimulationRunner runner;
    runner.setWorld(test::hangingBoxWorld());
    runner.play();
    runner.stepOnce();
    QVERIFY(!runner.isRunning());
    const std::int64_t before = runner.world().stepCount;
    runner.stepOnce();
    QCOMPARE(runner.world().stepCount, before + 1);
}

void SimulationRunnerTest::playRunsInRealTimeAndPauseStops()
{
    SimulationRunner runner;
    runner.setWorld(test::hangingBoxWorld());
    QSignalSpy running(&runner, &SimulationRunner::runningChanged);
    runner.play();
    QVERIFY(runner.isRunning());
    QCOMPARE(running.count(), 1);
    QTRY_VERIFY(runner.world().time > 0.05);

    runner.pause();
    QVERIFY(!runner.isRunning());
    QCOMPARE(running.count(), 2);
    const double pausedAt = runner.world().time;
    QTest::qWait(100);
    QCOMPARE(runner.world().time, pausedAt);
}

void SimulationRunnerTest::resetGoesBackToLastPlay()
{
    SimulationRunner runner;
    runner.setWorld(test::hangingBoxWorld());
    runner.stepBy(10);
    const model::World atPlay = runner.world();
    runner.play();
    QTRY_VERIFY(runner.world().stepCount > atPlay.stepCount);
    runner.pause();
    QVERIFY(runner.worldAtLastPlay().has_value());

    QSignalSpy changed(&runner, &SimulationRunner::worldChanged);
    runner.resetToLastPlay();
    QCOMPARE(changed.count(), 1);
    QVERIFY(runner.world() == atPlay);
}

void SimulationRunnerTest::editWorldKeepsRunningAndTheWorldAtPlay()
{
    SimulationRunner runner;
    runner.setWorld(test::risingBallWorld());
    QSignalSpy replaced(&runner, &SimulationRunner::sceneReplaced);
    QSignalSpy changed(&runner, &SimulationRunner::worldChanged);
    runner.play();
    const model::World atPlay = runner.world();
    runner.advanceWallTime(0.05);

    runner.editWorld([](model::World& world) { world.bodies[0].state.velocity = impetus::Vec2(2, 0); });
    QVERIFY(runner.isRunning());
    QCOMPARE(changed.count(), 1);
    QCOMPARE(replaced.count(), 0); // an edit is not a new scene: views do not reframe
    QVERIFY(runner.worldAtLastPlay() && *runner.worldAtLastPlay() == atPlay);
    // The next steps start from the edited world: the ball now moves along x.
    const double x = runner.world().bodies[0].state.position.x();
    runner.advanceWallTime(0.05);
    QVERIFY(runner.world().bodies[0].state.position.x() > x);
    runner.pause();

    runner.setWorld(test::risingBallWorld());
    QCOMPARE(replaced.count(), 1);
}


void SimulationRunnerTest::divergingBatchIsTakenBackPausedAndReported()
{
    SimulationRunner runner;
    runner.setWorld(test::explodingSpringWorld());
    runner.play();
    const model::World atPlay = runner.world();
    QSignalSpy stepped(&runner, &SimulationRunner::stepped);
    QSignalSpy diverged(&runner, &SimulationRunner::diverged);

    // Wall time comes in frames, as from the timer, until a frame's batch blows up.
    model::World lastFinite = runner.world();
    for (int frame = 0; frame < 100 && diverged.isEmpty(); ++frame) {
        lastFinite = runner.world();
        runner.advanceWallTime(1.0 / 60);
    }
    QCOMPARE(diverged.count(), 1);
    QCOMPARE(diverged.at(0).at(0).toString(), QStringLiteral("bob"));
    // The time reported is when the batch ended, later than the world that is kept.
    const double time = diverged.at(0).at(1).toDouble();
    QVERIFY2(time > lastFinite.time, qPrintable(QString::number(time)));
    // Stopped, on the last finite world (the one the view showed), with the world at Play kept.
    QVERIFY(!runner.isRunning());
    QVERIFY(runner.world() == lastFinite);
    QVERIFY(!impetus::controller::firstNonFiniteBody(runner.world()));
    QVERIFY(runner.worldAtLastPlay() && *runner.worldAtLastPlay() == atPlay);
    // The blown-up batch did not tell the view to draw it.
    const qsizetype steppedBefore = stepped.count();
    QCOMPARE(runner.advanceWallTime(0), std::int64_t(0));
    QCOMPARE(stepped.count(), steppedBefore);
    runner.resetToLastPlay();
    QVERIFY(runner.world() == atPlay);
}

void SimulationRunnerTest::divergingStepsAreReportedToo()
{
    // stepBy (the screenshot mode) and stepOnce (the Step button) check as well.
    SimulationRunner runner;
    runner.setWorld(test::explodingSpringWorld());
    QSignalSpy diverged(&runner, &SimulationRunner::diverged);
    const model::World start = runner.world();
    runner.stepBy(1000);
    QCOMPARE(diverged.count(), 1);
    QVERIFY(runner.world() == start);
    while (diverged.count() == 1 && runner.world().stepCount < 1000)
        runner.stepOnce();
    QCOMPARE(diverged.count(), 2);
    QCOMPARE(diverged.at(1).at(0).toString(), QStringLiteral("bob"));
    QVERIFY(!impetus::controller::firstNonFiniteBody(runner.world()));
}

void SimulationRunnerTest::tinyTimeStepCannotFreezeATick()
{
    SimulationRunner runner;
    model::World world = test::risingBallWorld();
    // A step no machine can take 10¹⁷ of in a frame: the per-frame count is huge, and defined.
    world.settings.timeStep = 1e-18;
    runner.setWorld(world);
    QVERIFY2(runner.maxStepsPerFrame() >= std::int64_t(1e15), qPrintable(QString::number(runner.maxStepsPerFrame())));
    // However small the step, the count stays a positive number (1e-300 s would overflow int64).
    world.settings.timeStep = 1e-300;
    runner.setWorld(world);
    QVERIFY2(runner.maxStepsPerFrame() >= std::int64_t(1e15), qPrintable(QString::number(runner.maxStepsPerFrame())));

    // One frame of wall time at dt = 1e-9 s owes 1.7·10⁷ steps, many seconds of work: the tick
    // stops after its wall-clock budget, with far fewer, and drops the rest of the backlog.
    world.settings.timeStep = 1e-9;
    runner.setWorld(world);
    const std::int64_t steps = runner.advanceWallTime(1.0 / 60);
    QVERIFY(steps > 0);
    QVERIFY2(steps < std::int64_t(1e7), qPrintable(QString::number(steps)));
    QCOMPARE(runner.world().stepCount, steps);
    QCOMPARE(runner.advanceWallTime(0), std::int64_t(0));
    // The step itself never changed: the ball rose exactly steps × dt at 1 m/s.
    QVERIFY(qAbs(runner.world().bodies[0].state.position.y() - static_cast<double>(steps) * 1e-9) < 1e-12);
}

void SimulationRunnerTest::slowStepLeavesTheEventLoopRunning()
{
    test::StepGate gate;
    SimulationRunner runner;
    const auto release = qScopeGuard([&gate] { gate.openForGood(); });
    runner.setStepFunction(gate.function());
    runner.setWorld(test::risingBallWorld());
    QSignalSpy stepped(&runner, &SimulationRunner::stepped);

    runner.play();
    QTRY_COMPARE(gate.started(), 1);
    // The first step of the run is under way and does not end: the event loop runs meanwhile.
    QVERIFY(eventLoopRuns());
    QVERIFY(runner.isComputing());
    QCOMPARE(runner.world().stepCount, std::int64_t(0));
    QCOMPARE(stepped.count(), 0);

    // Pause answers at once, with the step still under way, and the world stays as shown.
    runner.pause();
    QVERIFY(!runner.isRunning());
    gate.open(1);
    QTRY_VERIFY(!runner.isComputing());
    QCOMPARE(gate.started(), 1); // the batch stopped after the step under way
    QCOMPARE(runner.world().stepCount, std::int64_t(0));
    QCOMPARE(stepped.count(), 0);
}

void SimulationRunnerTest::slowRunFallsBehindAndSaysSo()
{
    test::StepGate gate;
    SimulationRunner runner;
    const auto release = qScopeGuard([&gate] { gate.openForGood(); });
    runner.setStepFunction(gate.function());
    runner.setWorld(test::hangingBoxWorld());
    QVERIFY(!runner.pace().costKnown);

    // One step goes through: the runner knows what a step costs.
    gate.open(1);
    runner.stepOnce();
    QTRY_COMPARE(runner.world().stepCount, std::int64_t(1));
    QVERIFY(runner.pace().costKnown);
    QVERIFY(!runner.pace().behind);

    // The run's first step never ends: within a measuring window the runner reports that the run
    // falls behind, while its timer goes on ticking.
    QSignalSpy paced(&runner, &SimulationRunner::paceChanged);
    runner.play();
    QTRY_COMPARE(gate.started(), 2);
    QTRY_VERIFY(runner.pace().behind);
    QVERIFY(paced.count() >= 2); // play() reset it, a window ended
    QCOMPARE(runner.pace().requestedSpeed, 1.0);
    QCOMPARE(runner.pace().timeStep, runner.world().settings.timeStep);
    QCOMPARE(runner.world().stepCount, std::int64_t(1));

    runner.pause();
    QVERIFY(!runner.pace().behind);
    gate.openForGood();
    QTRY_VERIFY(!runner.isComputing());
    QCOMPARE(runner.world().stepCount, std::int64_t(1));
}

void SimulationRunnerTest::editDuringASlowStepGoesToTheWorldShown()
{
    test::StepGate gate;
    SimulationRunner runner;
    const auto release = qScopeGuard([&gate] { gate.openForGood(); });
    runner.setStepFunction(gate.function());
    runner.setWorld(test::risingBallWorld());
    const double dt = runner.world().settings.timeStep;

    runner.play();
    QTRY_COMPARE(gate.started(), 1);
    // An edit while a step is under way goes to the world shown; the run goes on.
    runner.editWorld([](model::World& world) { world.bodies[0].state.velocity = impetus::Vec2(2, 1); });
    QVERIFY(runner.isRunning());
    QCOMPARE(runner.world().bodies[0].state.velocity, impetus::Vec2(2, 1));
    gate.openForGood();
    QTRY_VERIFY(runner.world().stepCount >= 3);
    runner.pause();

    // Every step shown was taken from the edited world, none twice: the ball moved 2 m/s along x
    // for exactly as many steps as the world counts.
    const auto steps = static_cast<double>(runner.world().stepCount);
    QVERIFY(qAbs(runner.world().bodies[0].state.position.x() - 2 * dt * steps) < 1e-12);
    QVERIFY(qAbs(runner.world().bodies[0].state.position.y() - dt * steps) < 1e-12);
}

void SimulationRunnerTest::slowStepGoesOnInTheBackground()
{
    test::StepGate gate;
    SimulationRunner runner;
    const auto release = qScopeGuard([&gate] { gate.openForGood(); });
    runner.setStepFunction(gate.function());
    runner.setWorld(test::hangingBoxWorld());
    const model::World start = runner.world();
    QSignalSpy computing(&runner, &SimulationRunner::computingStepChanged);
    QSignalSpy stepped(&runner, &SimulationRunner::stepped);

    // A Step that does not end in time goes on in the background; the call returns.
    runner.stepOnce();
    QVERIFY(runner.isComputingStep());
    QCOMPARE(computing.count(), 1);
    QCOMPARE(computing.at(0).at(0).toBool(), true);
    QVERIFY(runner.world() == start);
    QVERIFY(eventLoopRuns());

    // A second Step while the first computes is taken after it.
    runner.stepOnce();
    gate.open(2);
    QTRY_VERIFY(!runner.isComputingStep());
    QCOMPARE(computing.count(), 2);
    QCOMPARE(runner.world().stepCount, std::int64_t(2));
    QCOMPARE(stepped.count(), 2);
    model::World expected = start;
    impetus::controller::Simulation simulation;
    simulation.step(expected);
    simulation.step(expected);
    QVERIFY(runner.world() == expected);

    // Pause drops a Step being computed: the world stays as shown.
    runner.stepOnce();
    QVERIFY(runner.isComputingStep());
    runner.pause();
    QVERIFY(!runner.isComputingStep());
    gate.openForGood();
    QTRY_VERIFY(!runner.isComputing());
    QVERIFY(runner.world() == expected);
}

void SimulationRunnerTest::workerGivesTheSameBitsAsOneLoop()
{
    // A pyramid has contacts that warm-start from step to step: Steps, a run on the timer and
    // stepBy, all on the worker, take exactly the steps one synchronous loop takes.
    const model::World pyramid = model::makePyramid(6);
    SimulationRunner runner;
    runner.setWorld(pyramid);
    runner.stepOnce();
    runner.stepOnce();
    QTRY_COMPARE(runner.world().stepCount, std::int64_t(2));
    runner.play();
    QTRY_VERIFY(runner.world().stepCount >= 40);
    runner.pause();
    runner.stepBy(3);
    QTRY_VERIFY(!runner.isComputing());

    model::World expected = pyramid;
    impetus::controller::Simulation simulation;
    for (std::int64_t i = 0; i < runner.world().stepCount; ++i)
        simulation.step(expected);
    QVERIFY(runner.world() == expected);
}

// A run's batch that ends before the next tick waits for that tick to be shown, so that states
// come at the timer's even pace (docs/benchmarks.md, "Frames at the timer's pace"). Steps of no
// cost at 1/60 s: each tick owes one step, the batch ends at once, and is shown at the next tick,
// most of a frame later; shown on ending, it came within a millisecond.
void SimulationRunnerTest::anEarlyBatchIsShownAtTheNextTick()
{
    SimulationRunner runner;
    model::World world = test::risingBallWorld();
    world.settings.timeStep = 1.0 / 60.0;
    runner.setWorld(world);
    std::mutex mutex;
    std::chrono::steady_clock::time_point lastStepEnded;
    runner.setStepFunction([&](impetus::controller::Simulation& simulation, model::World& w) {
        simulation.step(w);
        const std::lock_guard lock(mutex);
        lastStepEnded = std::chrono::steady_clock::now();
    });
    std::vector<double> delaysMs;
    connect(&runner, &SimulationRunner::stepped, this, [&] {
        const std::lock_guard lock(mutex);
        delaysMs.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - lastStepEnded).count());
    });
    // A real event loop: QTest::qWaitFor sleeps 10 ms between its rounds of events, which would
    // delay every report by as much.
    QEventLoop loop;
    connect(&runner, &SimulationRunner::stepped, &loop, [&] {
        if (delaysMs.size() >= 20)
            loop.quit();
    });
    QTimer::singleShot(5000, &loop, &QEventLoop::quit);
    runner.play();
    loop.exec();
    runner.pause();
    QVERIFY(delaysMs.size() >= 20);
    // The median wait: a held batch waits for the tick (on average half a frame or more, as the
    // batch starts at a tick and ends at once); one shown on ending waits for nothing.
    std::sort(delaysMs.begin(), delaysMs.end());
    const double median = delaysMs[delaysMs.size() / 2];
    QVERIFY2(median > impetus::view::constants::kFrameIntervalMs / 4.0,
             qPrintable(QStringLiteral("states shown a median %1 ms after their batch ended").arg(median)));
}

// A held batch has ended and will not report again: pausing, editing or replacing the world with
// one held throws it away (nothing left computing, the world shown as it was), and a run goes on
// from an edit.
void SimulationRunnerTest::pauseAndEditDropAHeldBatch()
{
    SimulationRunner runner;
    model::World world = test::risingBallWorld();
    world.settings.timeStep = 1.0 / 60.0;
    runner.setWorld(world);
    QSignalSpy stepped(&runner, &SimulationRunner::stepped);
    runner.play();
    QVERIFY(QTest::qWaitFor([&] { return stepped.count() >= 3; }, 5000));
    // A batch is held most of the time here (it takes microseconds, the tick comes every 16 ms).
    // One held goes at once; one whose end is still on its way goes when that report arrives;
    // neither is left computing for good.
    runner.pause();
    QVERIFY(QTest::qWaitFor([&] { return !runner.isComputing(); }, 1000));
    const std::int64_t pausedAt = runner.world().stepCount;
    const int shown = static_cast<int>(stepped.count());
    QTest::qWait(3 * impetus::view::constants::kFrameIntervalMs);
    QCOMPARE(runner.world().stepCount, pausedAt);
    QCOMPARE(static_cast<int>(stepped.count()), shown);

    runner.play();
    QVERIFY(QTest::qWaitFor([&] { return stepped.count() >= shown + 3; }, 5000));
    runner.editWorld([](model::World& w) { w.bodies[0].state.velocity.x() = 1; });
    // Edited while running: the run goes on from the edit.
    QVERIFY(QTest::qWaitFor([&] { return runner.world().bodies[0].state.position.x() > 0; }, 5000));
    QVERIFY(runner.isRunning());
    runner.setWorld(test::risingBallWorld());
    QVERIFY(QTest::qWaitFor([&] { return !runner.isComputing(); }, 1000));
    QCOMPARE(runner.world().stepCount, std::int64_t(0));
}

QTEST_MAIN(SimulationRunnerTest)
#include "simulation_runner_test.moc"
