// Timeline: keyframes and replay give back the run's own states, to the bit; scrubbing from the
// window puts the bodies back where they were; memory stays within its budget.

#include "controller/simulation.h"
#include "model/example_scenes.h"
#include "test_settings.h"
#include "test_worlds.h"
#include "view/canvas_instruments.h"
#include "view/canvas_view.h"
#include "view/graph_quantity.h"
#include "view/main_window.h"
#include "view/scene_document.h"
#include "view/scene_loading.h"
#include "view/simulation_runner.h"
#include "view/timeline.h"
#include "view/timeline_bar.h"
#include "view/view_constants.h"

#include <QAction>
#include <QLabel>
#include <QSignalSpy>
#include <QSlider>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QTest>

#include <algorithm>
#include <vector>

using impetus::view::MainWindow;
using impetus::view::SimulationRunner;
using impetus::view::Timeline;
namespace model = impetus::model;
namespace constants = impetus::view::constants;
namespace test = impetus::view::test;

namespace {

/// The default example scene: springs, a pendulum and bodies that collide and come to rest.
model::World defaultScene()
{
    model::SceneLoadResult result = impetus::view::loadScene(QString::fromLatin1(impetus::view::kDefaultScenePath));
    return std::move(*result.world);
}

/// `world` after each of `steps` steps taken in one plain loop: the first run, as a reference.
std::vector<model::World> referenceRun(model::World world, int steps)
{
    impetus::controller::Simulation simulation;
    std::vector<model::World> states{world};
    for (int i = 0; i < steps; ++i) {
        simulation.step(world);
        states.push_back(world);
    }
    return states;
}

} // namespace

class TimelineTest : public QObject {
    Q_OBJECT

private slots:
    void scrubBackThenReplayGivesTheSameBits();
    void playFromThePastDiscardsTheFuture();
    void editInThePastStartsANewRun();
    void resetAndUndoKeepTheRun();
    void memoryStaysWithinTheBudget();
    void fiveMinutesOfTheLargeSceneFitIn500MB();
    void leftArrowStepsBackOneStepInTheWindow();
    void clickingTheSliderPutsTheBodiesWhereTheyWere();

private:
    static bool showActive(MainWindow& window);
    test::TemporarySettings m_settings;
};

bool TimelineTest::showActive(MainWindow& window)
{
    window.resize(900, 650);
    window.show();
    window.activateWindow();
    return QTest::qWaitForWindowActive(&window);
}

void TimelineTest::scrubBackThenReplayGivesTheSameBits()
{
    const std::vector<model::World> reference = referenceRun(defaultScene(), 1000);
    SimulationRunner runner;
    runner.setWorld(defaultScene());
    Timeline timeline(runner);
    for (int i = 0; i < 10; ++i)
        runner.stepBy(100); // batches, as a run takes them
    QCOMPARE(runner.world().stepCount, 1000);
    QVERIFY(runner.world() == reference[1000]);
    QCOMPARE(timeline.lastStep(), 1000);

    // Back to any step: the state the run had there, to the bit.
    for (const int step : {0, 1, 239, 240, 517, 999}) {
        timeline.seek(step);
        QCOMPARE(runner.world().stepCount, step);
        QVERIFY2(runner.world() == reference[static_cast<std::size_t>(step)], qPrintable(QString::number(step)));
    }
    // And forward from there again: the same bits as the first run.
    timeline.seek(517);
    runner.stepBy(483);
    QVERIFY(runner.world() == reference[1000]);
    QCOMPARE(timeline.lastStep(), 1000); // stepping along the run forgets nothing
}

void TimelineTest::playFromThePastDiscardsTheFuture()
{
    const std::vector<model::World> reference = referenceRun(defaultScene(), 600);
    SimulationRunner runner;
    runner.setWorld(defaultScene());
    Timeline timeline(runner);
    runner.stepBy(600);
    timeline.seek(300);
    QSignalSpy discarded(&timeline, &Timeline::futureDiscarded);
    runner.play();
    QCOMPARE(timeline.lastStep(), 300);
    QCOMPARE(discarded.count(), 1);
    QCOMPARE(discarded.front().front().toLongLong(), 300);
    runner.pause();
    runner.stepBy(300);
    QVERIFY(runner.world() == reference[600]);
    QCOMPARE(timeline.lastStep(), 600);
}

void TimelineTest::editInThePastStartsANewRun()
{
    MainWindow window;
    window.setScene(defaultScene(), QStringLiteral("default"));
    SimulationRunner& runner = window.runner();
    Timeline& timeline = window.timeline();
    runner.stepBy(600);
    timeline.seek(300);
    const model::BodyState& state = runner.world().bodies[1].state;
    window.document().setPoses({1}, {impetus::view::BodyPose{state.position + impetus::Vec2(0.5, 0), state.angle}},
                               QStringLiteral("Move"), window.document().newGesture());
    QCOMPARE(timeline.lastStep(), 300);
    const model::World edited = runner.world();
    runner.stepBy(100);
    // The edited world is where the new run starts: going back finds it, not the old step 300.
    timeline.seek(300);
    QVERIFY(runner.world() == edited);
    const std::vector<model::World> replay = referenceRun(edited, 100);
    timeline.seek(400);
    QVERIFY(runner.world() == replay[100]);
}

void TimelineTest::resetAndUndoKeepTheRun()
{
    MainWindow window;
    window.setScene(defaultScene(), QStringLiteral("default"));
    SimulationRunner& runner = window.runner();
    Timeline& timeline = window.timeline();
    runner.play();
    runner.advanceWallTime(0.5); // 120 steps
    runner.pause();
    const std::int64_t end = timeline.lastStep();
    QVERIFY(end > 0);
    window.resetAction()->trigger();
    QCOMPARE(runner.world().stepCount, 0);
    QCOMPARE(timeline.lastStep(), end); // the run is still there to scrub along
    window.undoAction()->trigger(); // undo the reset
    QCOMPARE(runner.world().stepCount, end);
    QCOMPARE(timeline.lastStep(), end);
}

void TimelineTest::memoryStaysWithinTheBudget()
{
    const std::vector<model::World> reference = referenceRun(defaultScene(), 4000);
    SimulationRunner runner;
    runner.setWorld(defaultScene());
    Timeline timeline(runner);
    const std::size_t budget = 6 * impetus::view::worldBytes(reference.back());
    timeline.setMemoryBudget(budget);
    for (int i = 0; i < 40; ++i) {
        runner.stepBy(100);
        QVERIFY(timeline.memoryUsed() <= budget);
    }
    QVERIFY(timeline.keyframeInterval() > constants::kKeyframeIntervalSteps); // it had to thin
    QVERIFY(timeline.keyframeCount() <= 6);
    // Thinning costs replay time, never states: every step is still there, to the bit.
    for (const int step : {0, 777, 2001, 3999, 4000}) {
        timeline.seek(step);
        QVERIFY2(runner.world() == reference[static_cast<std::size_t>(step)], qPrintable(QString::number(step)));
    }
}

void TimelineTest::fiveMinutesOfTheLargeSceneFitIn500MB()
{
    // The 2000-body scene once its circles have landed (they fall for about 1.2 s, in columns),
    // with its contacts, one under each circle: the size of a keyframe. It stays that size from
    // then on.
    model::World world = model::makeRotatingBoxWithCircles(2000);
    impetus::controller::Simulation simulation;
    for (int i = 0; i < 720; ++i)
        simulation.step(world);
    QVERIFY(world.contacts.size() >= 2000);
    const std::size_t keyframe = impetus::view::worldBytes(world);
    const double runSteps = 300.0 / world.settings.timeStep;
    const double keyframes = runSteps / static_cast<double>(constants::kKeyframeIntervalSteps) + 1;
    const double total = keyframes * static_cast<double>(keyframe);
    qInfo("2000-body keyframe: %.2f MB (%zu contacts); 5 min = %.0f keyframes = %.0f MB", static_cast<double>(keyframe) / 1e6,
          world.contacts.size(), keyframes, total / 1e6);
    // The timeline thins its keyframes when they would pass the budget (memoryStaysWithinTheBudget
    // checks that it keeps to it), so they never take more than the budget.
    const double keyframesAtMost = std::min(total, static_cast<double>(constants::kTimelineMemoryBudgetBytes));
    // Beside them in the window, with the arrows, the trails and one graph on: the trails at their
    // cap, five minutes of the graph's records, and the rest of the window, which
    // bench/timeline_memory.cpp measured at about 90 MB besides trails and graph (67 MB with the
    // scene loaded, before any step; docs/app.md, "Timeline").
    const double trails = static_cast<double>(constants::kMaxTrailPointsInAll * sizeof(impetus::view::TrailPoint));
    const double graph = runSteps * static_cast<double>(sizeof(impetus::view::GraphRecord));
    constexpr double kRestOfTheWindow = 100e6;
    const double whole = keyframesAtMost + trails + graph + kRestOfTheWindow;
    qInfo("keyframes at most %.0f MB + trails %.0f MB + a graph %.0f MB + the window %.0f MB = %.0f MB",
          keyframesAtMost / 1e6, trails / 1e6, graph / 1e6, kRestOfTheWindow / 1e6, whole / 1e6);
    QVERIFY(whole < 500e6);
}

void TimelineTest::leftArrowStepsBackOneStepInTheWindow()
{
    MainWindow window;
    window.setScene(defaultScene(), QStringLiteral("default"));
    QVERIFY(showActive(window));
    const std::vector<model::World> reference = referenceRun(defaultScene(), 10);
    QVERIFY(!window.stepBackAction()->isEnabled()); // nothing before the start
    for (int i = 0; i < 10; ++i)
        QTest::keyClick(window.canvas().viewport(), Qt::Key_Right);
    QTRY_COMPARE(window.runner().world().stepCount, 10);
    QVERIFY(window.stepBackAction()->isEnabled());
    QTest::keyClick(window.canvas().viewport(), Qt::Key_Left);
    QCOMPARE(window.runner().world().stepCount, 9);
    QVERIFY(window.runner().world() == reference[9]);
    QTest::keyClick(window.canvas().viewport(), Qt::Key_Left);
    QTest::keyClick(window.canvas().viewport(), Qt::Key_Left);
    QVERIFY(window.runner().world() == reference[7]);
    QCOMPARE(window.timeline().lastStep(), 10);
    QCOMPARE(window.timelineBar()->slider()->value(), 7);
}

void TimelineTest::clickingTheSliderPutsTheBodiesWhereTheyWere()
{
    MainWindow window;
    window.setScene(defaultScene(), QStringLiteral("default"));
    QVERIFY(showActive(window));
    const std::vector<model::World> reference = referenceRun(defaultScene(), 720);
    window.runner().stepBy(720);
    QSlider* slider = window.timelineBar()->slider();
    QCOMPARE(slider->maximum(), 720);
    QCOMPARE(slider->value(), 720);

    // A click in the groove left of the handle goes back one page (240 steps), as on any slider.
    QStyleOptionSlider option;
    option.initFrom(slider);
    option.orientation = Qt::Horizontal;
    option.minimum = slider->minimum();
    option.maximum = slider->maximum();
    option.sliderPosition = slider->sliderPosition();
    option.sliderValue = slider->value();
    const QRect handle = slider->style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderHandle, slider);
    const QPoint groove(handle.left() / 2, handle.center().y());
    QTest::mouseClick(slider, Qt::LeftButton, Qt::NoModifier, groove);
    QTRY_COMPARE(window.runner().world().stepCount, 720 - constants::kTimelinePageSteps);
    const model::World& shown = window.runner().world();
    const model::World& then = reference[720 - constants::kTimelinePageSteps];
    for (std::size_t i = 0; i < shown.bodies.size(); ++i)
        QVERIFY(shown.bodies[i].state.position == then.bodies[i].state.position);
    QVERIFY(shown == then);
    QVERIFY(window.timelineBar()->label()->text().startsWith(QStringLiteral("t = 2.000 s of 3.000 s")));
    QVERIFY(!window.runner().isRunning());
}

QTEST_MAIN(TimelineTest)
#include "timeline_test.moc"
