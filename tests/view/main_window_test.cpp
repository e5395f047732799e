// MainWindow, driven as a user would: keys, the default scene, opening a bad file.

#include "model/example_scenes.h"
#include "model/scene_io.h"
#include "step_gate.h"
#include "test_files.h"
#include "test_settings.h"
#include "test_worlds.h"
#include "view/body_item.h"
#include "view/canvas_view.h"
#include "view/main_window.h"
#include "view/scene_loading.h"
#include "view/simulation_runner.h"
#include "view/view_constants.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QLabel>
#include <QMessageBox>
#include <QRegularExpression>
#include <QScopeGuard>
#include <QSettings>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolBar>
#include <QWheelEvent>

#include <cmath>

using impetus::view::MainWindow;
namespace model = impetus::model;
namespace test = impetus::view::test;

namespace {

/// The text of every permanent label in the status bar, joined.
QString statusText(const MainWindow& window)
{
    QStringList texts;
    for (const QLabel* label : window.statusBar()->findChildren<QLabel*>())
        texts << label->text();
    return texts.join(QLatin1Char(' '));
}

/// Turns the mouse wheel over `viewport` by `notches`, at its centre.
void turnWheel(QWidget* viewport, int notches)
{
    const QPointF at = QRectF(viewport->rect()).center();
    QWheelEvent event(at, viewport->mapToGlobal(at), QPoint(), QPoint(0, QWheelEvent::DefaultDeltasPerStep * notches),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(viewport, &event);
}

/// Counts the paint events a widget gets.
class PaintCounter : public QObject {
public:
    explicit PaintCounter(QWidget* widget) { widget->installEventFilter(this); }
    int count() const { return m_count; }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() == QEvent::Paint)
            ++m_count;
        return QObject::eventFilter(watched, event);
    }

private:
    int m_count = 0;
};

} // namespace

class MainWindowTest : public QObject {
    Q_OBJECT

private slots:
    void showsDefaultScene();
    void spaceStartsAndPauses();
    void rightArrowStepsExactlyOneTimeStep();
    void statusBarShowsTimeAndEnergy();
    void badSceneFileLeavesCurrentSceneUntouched();
    void badSceneFileShowsProblemsInMessageBox();
    void widgetsHaveAccessibleNames();
    void runThatBlowsUpStopsWithAMessage();
    void bodyPutBackOutOfAWallIsToldInTheStatusBar();
    void badSceneOnTheCommandLineOpensTheDefaultSceneAndListsProblems();
    void savedWindowSizeIsKeptAndTheDefaultUsedOnlyWithout();
    void slowRunSaysItRunsSlowerThanRealTimeAndWhy();
    void slowStepIsComputedInTheBackground();

private:
    /// Shows `window` and waits until it is active, so that its shortcuts work.
    static bool showActive(MainWindow& window);

    test::TemporarySettings m_settings;
};

bool MainWindowTest::showActive(MainWindow& window)
{
    window.resize(800, 600);
    window.show();
    window.activateWindow();
    return QTest::qWaitForWindowActive(&window);
}

void MainWindowTest::showsDefaultScene()
{
    MainWindow window;
    const QStringList problems = window.openScene(QString::fromLatin1(impetus::view::kDefaultScenePath));
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
    QVERIFY(showActive(window));

    const model::World& world = window.runner().world();
    QVERIFY(world.bodies.size() >= 3);
    QVERIFY(!world.springs.empty());
    QCOMPARE(window.canvas().bodyItems().size(), world.bodies.size());
    QCOMPARE(window.canvas().springItems().size(), world.springs.size());
    QCOMPARE(window.windowTitle(), QStringLiteral("default[*] — Impetus"));
    QVERIFY(!window.runner().isRunning());

    // Every body is in view at the start.
    const QRectF visible = window.canvas().mapToScene(window.canvas().viewport()->rect()).boundingRect();
    for (const impetus::view::BodyItem* item : window.canvas().bodyItems())
        QVERIFY(visible.contains(item->sceneBoundingRect()));
}

void MainWindowTest::spaceStartsAndPauses()
{
    MainWindow window;
    window.setScene(test::hangingBoxWorld(), QStringLiteral("hanging box"));
    QVERIFY(showActive(window));
    QCOMPARE(window.windowTitle(), QStringLiteral("hanging box[*] — Impetus"));
    QCOMPARE(window.playAction()->text(), QStringLiteral("Play"));

    // Keys go to the focused canvas, as a user's would.
    QVERIFY(window.canvas().hasFocus());
    QTest::keyClick(&window.canvas(), Qt::Key_Space);
    QVERIFY(window.runner().isRunning());
    QVERIFY(window.playAction()->isChecked());
    QCOMPARE(window.playAction()->text(), QStringLiteral("Pause"));
    QTest::qWait(200);
    QVERIFY(window.runner().world().time > 0);

    QTest::keyClick(&window.canvas(), Qt::Key_Space);
    QVERIFY(!window.runner().isRunning());
    QVERIFY(!window.playAction()->isChecked());
    QCOMPARE(window.playAction()->text(), QStringLiteral("Play"));
    const double pausedAt = window.runner().world().time;
    QTest::qWait(100);
    QCOMPARE(window.runner().world().time, pausedAt);
}

void MainWindowTest::rightArrowStepsExactlyOneTimeStep()
{
    MainWindow window;
    window.setScene(test::hangingBoxWorld(), QStringLiteral("hanging box"));
    QVERIFY(showActive(window));
    const double dt = window.runner().world().settings.timeStep;
    const model::BodyState start = window.runner().world().bodies[0].state;

    QTest::keyClick(&window, Qt::Key_Right);
    QCOMPARE(window.runner().world().stepCount, std::int64_t(1));
    QCOMPARE(window.runner().world().time, dt);
    QVERIFY(!window.runner().isRunning());
    // The box, pulled by gravity and the spring, moved, and its item followed.
    const model::BodyState& now = window.runner().world().bodies[0].state;
    QVERIFY(now.position != start.position);
    QCOMPARE(window.canvas().bodyItems()[0]->scenePos(), QPointF(now.position.x(), now.position.y()));

    QTest::keyClick(&window, Qt::Key_Right);
    QCOMPARE(window.runner().world().stepCount, std::int64_t(2));
}

void MainWindowTest::statusBarShowsTimeAndEnergy()
{
    MainWindow window;
    model::World world = test::risingBallWorld();
    world.bodies[0].state.velocity = impetus::Vec2(0, 2); // KE = ½·m·4 = 2m
    const double mass = world.bodies[0].mass;
    window.setScene(world, QStringLiteral("rising"));
    QVERIFY(showActive(window));
    QVERIFY2(statusText(window).contains(QStringLiteral("t = 0.000 s")), qPrintable(statusText(window)));
    QVERIFY2(statusText(window).contains(QStringLiteral("E = %1 J").arg(2 * mass, 0, 'f', 3)),
             qPrintable(statusText(window)));

    QTest::keyClick(&window, Qt::Key_Right);
    QVERIFY2(statusText(window).contains(QStringLiteral("t = 0.004 s")), qPrintable(statusText(window)));
}

void MainWindowTest::badSceneFileLeavesCurrentSceneUntouched()
{
    MainWindow window;
    window.setScene(test::hangingBoxWorld(), QStringLiteral("hanging box"));
    window.runner().stepBy(5);
    const model::World before = window.runner().world();

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("broken.json"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("{ \"format\": \"impetus-scene\", \"version\": 1, \"bodies\": [ { \"name\": ");
    file.close();

    const QStringList problems = window.openScene(path);
    QVERIFY(!problems.isEmpty());
    QVERIFY(window.runner().world() == before);
    QCOMPARE(window.windowTitle(), QStringLiteral("hanging box[*] — Impetus"));
    QCOMPARE(window.canvas().bodyItems().size(), before.bodies.size());

    QVERIFY(!window.openScene(dir.filePath(QStringLiteral("missing.json"))).isEmpty());
    QVERIFY(window.runner().world() == before);
}

void MainWindowTest::badSceneFileShowsProblemsInMessageBox()
{
    MainWindow window;
    window.setScene(test::hangingBoxWorld(), QStringLiteral("hanging box"));
    QVERIFY(showActive(window));
    const model::World before = window.runner().world();

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("negative.json"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({ "format": "impetus-scene", "version": 1,
        "bodies": [ { "name": "b", "shape": { "type": "circle", "radius": -1 }, "position": [0, 0] } ] })");
    file.close();

    // The box is modal: read and close it from the event loop it runs.
    QString shownText;
    bool boxSeen = false;
    QTimer::singleShot(0, this, [&] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (!box)
            return;
        boxSeen = true;
        shownText = box->text() + QLatin1Char('\n') + box->informativeText();
        box->button(QMessageBox::Ok)->click();
    });
    QVERIFY(!window.openSceneInteractively(path));
    QVERIFY(boxSeen);
    QVERIFY2(shownText.contains(QStringLiteral("negative.json")), qPrintable(shownText));
    QVERIFY2(shownText.contains(QStringLiteral("bodies[0].shape.radius")), qPrintable(shownText));
    QVERIFY(window.runner().world() == before);
    QCOMPARE(window.windowTitle(), QStringLiteral("hanging box[*] — Impetus"));
}

void MainWindowTest::widgetsHaveAccessibleNames()
{
    MainWindow window;
    QVERIFY(!window.canvas().accessibleName().isEmpty());
    const auto toolBars = window.findChildren<QToolBar*>();
    QCOMPARE(toolBars.size(), 2); // run controls, drawing tools
    for (const QToolBar* toolBar : toolBars) {
        QVERIFY(!toolBar->accessibleName().isEmpty());
        for (QAction* action : toolBar->actions()) {
            if (QWidget* widget = toolBar->widgetForAction(action))
                QVERIFY2(!widget->accessibleName().isEmpty(), qPrintable(action->text()));
        }
    }
    QVERIFY(toolBars.at(0)->widgetForAction(window.playAction()) != nullptr);
    for (const QLabel* label : window.statusBar()->findChildren<QLabel*>())
        QVERIFY(!label->accessibleName().isEmpty());
}

void MainWindowTest::bodyPutBackOutOfAWallIsToldInTheStatusBar()
{
    // A 3.2 kg ellipse on a rod to a chain of 82 kg and 4.9 t at 78 m/s: the solve lets its centre
    // into the left wall in the second step of 1/60 s, and the engine puts it back.
    const model::SceneLoadResult loaded = model::loadSceneFile(IMPETUS_GUARDED_SCENE);
    QVERIFY(loaded.ok());
    MainWindow window;
    window.setScene(*loaded.world, QStringLiteral("soak 2087"));
    QVERIFY(showActive(window));
    QVERIFY(window.statusBar()->currentMessage().isEmpty());
    QTest::keyClick(&window.canvas(), Qt::Key_Space);
    QTRY_VERIFY(!window.statusBar()->currentMessage().isEmpty());
    const QString text = window.statusBar()->currentMessage();
    QVERIFY2(text.contains(QStringLiteral("“body-2”")) && text.contains(QStringLiteral("“wall-left”")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("put back")), qPrintable(text));
    // When: the end of a step of 1/60 s from the second on (each batch shown tells of its own).
    const QRegularExpressionMatch when = QRegularExpression(QStringLiteral("t = ([0-9.]+) s")).match(text);
    QVERIFY2(when.hasMatch(), qPrintable(text));
    const double steps = when.captured(1).toDouble() * 60;
    QVERIFY2(steps >= 2 - 1e-4 && std::abs(steps - std::round(steps)) < 1e-4, qPrintable(text));
    // The run goes on: a word in the status bar, not a box that stops it.
    QVERIFY(window.runner().isRunning());
    QVERIFY(window.findChild<QMessageBox*>() == nullptr);
}

void MainWindowTest::runThatBlowsUpStopsWithAMessage()
{
    MainWindow window;
    window.setScene(test::explodingSpringWorld(), QStringLiteral("stiff spring"));
    QVERIFY(showActive(window));
    const model::World start = window.runner().world();

    // Play with Space on the canvas: the run soon gives not-a-number and stops by itself.
    QTest::keyClick(&window.canvas(), Qt::Key_Space);
    QTRY_VERIFY(window.findChild<QMessageBox*>(QStringLiteral("divergedBox")) != nullptr);
    auto* box = window.findChild<QMessageBox*>(QStringLiteral("divergedBox"));
    QVERIFY(!window.runner().isRunning());
    QVERIFY(!window.playAction()->isChecked());
    const QString text = box->text() + QLatin1Char('\n') + box->informativeText();
    QVERIFY2(text.contains(QStringLiteral("“bob”")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("t = ")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("Reset")) && text.contains(QStringLiteral("Undo")), qPrintable(text));
    // The window shows the last finite state: no "nan" in the readouts.
    QVERIFY2(!statusText(window).contains(QStringLiteral("nan"), Qt::CaseInsensitive), qPrintable(statusText(window)));
    QVERIFY(std::isfinite(window.runner().world().bodies[0].state.position.x()));
    box->button(QMessageBox::Ok)->click();
    QTRY_VERIFY(window.findChild<QMessageBox*>(QStringLiteral("divergedBox")) == nullptr);

    // Nothing is lost: Reset goes back to the world at Play. (The offscreen platform gives the
    // activation back to no window when the box closes; a desktop gives it to the main window.)
    window.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    window.canvas().setFocus();
    QTest::keyClick(&window.canvas(), Qt::Key_R);
    QVERIFY(window.runner().world() == start);
}

void MainWindowTest::badSceneOnTheCommandLineOpensTheDefaultSceneAndListsProblems()
{
    // `impetus bad.json`: the window shows, on the default scene, with every problem listed in the
    // box File > Open uses.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("bad.json"));
    QVERIFY(test::writeFile(path, test::kSceneWithTwoProblems));

    MainWindow window;
    QVERIFY(showActive(window));
    const QStringList problems = window.openStartupScene(path);
    QCOMPARE(problems.size(), 2);
    const model::SceneLoadResult expected = impetus::view::loadScene(QString::fromLatin1(impetus::view::kDefaultScenePath));
    QVERIFY(expected.ok());
    QVERIFY(window.runner().world() == *expected.world);
    QVERIFY(window.isVisible());

    auto* box = window.findChild<QMessageBox*>(QStringLiteral("openErrorBox"));
    QVERIFY(box);
    QTRY_VERIFY(box->isVisible());
    const QString text = box->text() + QLatin1Char('\n') + box->informativeText();
    QVERIFY2(text.contains(QStringLiteral("bad.json")) && text.contains(QStringLiteral("default scene")),
             qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("bodies[0].shape.width")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("bodies[1].name")), qPrintable(text));
    box->button(QMessageBox::Ok)->click();
    QTRY_VERIFY(window.findChild<QMessageBox*>(QStringLiteral("openErrorBox")) == nullptr);

    // A good file opens with no box.
    const QString good = dir.filePath(QStringLiteral("good.json"));
    QVERIFY(test::writeFile(good, R"({ "format": "impetus-scene", "version": 1, "bodies": [
        { "name": "only", "shape": { "type": "circle", "radius": 1 }, "position": [0, 0] } ] })"));
    QVERIFY(window.openStartupScene(good).isEmpty());
    QCOMPARE(window.runner().world().bodies.size(), std::size_t(1));
    QVERIFY(window.findChild<QMessageBox*>(QStringLiteral("openErrorBox")) == nullptr);
}

void MainWindowTest::savedWindowSizeIsKeptAndTheDefaultUsedOnlyWithout()
{
    QSettings().clear(); // this test's own settings folder: no window has been saved yet
    {
        MainWindow first;
        QCOMPARE(first.size(), QSize(impetus::view::constants::kDefaultWindowWidth,
                                     impetus::view::constants::kDefaultWindowHeight));
        first.show();
        QVERIFY(QTest::qWaitForWindowExposed(&first));
        first.resize(700, 500);
        QVERIFY(first.close());
    }
    MainWindow second;
    QCOMPARE(second.size(), QSize(700, 500));
    second.show();
    QVERIFY(QTest::qWaitForWindowExposed(&second));
    QCOMPARE(second.size(), QSize(700, 500));
}

void MainWindowTest::slowRunSaysItRunsSlowerThanRealTimeAndWhy()
{
    test::StepGate gate;
    MainWindow window;
    const auto release = qScopeGuard([&gate] { gate.openForGood(); });
    window.runner().setStepFunction(gate.function());
    window.setScene(model::makePyramid(3), QStringLiteral("pyramid"));
    QVERIFY(showActive(window));
    auto* indicator = window.statusBar()->findChild<QLabel*>(QStringLiteral("paceStatus"));
    QVERIFY(indicator != nullptr);
    QVERIFY(indicator->isHidden());

    // One step goes through, so that the window knows what a step costs.
    gate.open(1);
    QTest::keyClick(&window.canvas(), Qt::Key_Right);
    QTRY_COMPARE(window.runner().world().stepCount, std::int64_t(1));
    QVERIFY(indicator->isHidden());

    // Play; the next step does not end. Meanwhile the window keeps painting (a zoom shows) and
    // soon says that the simulation runs slower than real time, and why.
    QTest::keyClick(&window.canvas(), Qt::Key_Space);
    QVERIFY(window.runner().isRunning());
    QTRY_COMPARE(gate.started(), 2);
    const PaintCounter paints(window.canvas().viewport());
    const double zoom = window.canvas().pixelsPerMetre();
    turnWheel(window.canvas().viewport(), 1);
    QVERIFY(window.canvas().pixelsPerMetre() > zoom);
    QTRY_VERIFY(paints.count() > 0);
    QTRY_VERIFY(!indicator->isHidden());
    const QString text = indicator->text();
    QVERIFY2(text.startsWith(QStringLiteral("Running at ")) && text.endsWith(QStringLiteral("× real time")),
             qPrintable(text));
    const QString why = indicator->toolTip();
    QVERIFY2(why.contains(QStringLiteral("ms to compute; at 1× it may take at most")), qPrintable(why));
    QVERIFY2(why.contains(QStringLiteral("bodies: %1, contacts: %2")
                              .arg(window.runner().world().bodies.size())
                              .arg(window.runner().pace().profile.contacts)),
             qPrintable(why));
    QVERIFY2(why.contains(QStringLiteral("use fewer bodies")), qPrintable(why));
    QVERIFY(window.runner().pace().profile.contacts > 0); // the boxes rest on each other
    QCOMPARE(window.runner().world().stepCount, std::int64_t(1));

    // Space pauses at once, with the step still under way: the indicator goes, and the world
    // stays as it is shown when the step ends.
    QTest::keyClick(&window.canvas(), Qt::Key_Space);
    QVERIFY(!window.runner().isRunning());
    QVERIFY(indicator->isHidden());
    gate.openForGood();
    QTRY_VERIFY(!window.runner().isComputing());
    QCOMPARE(window.runner().world().stepCount, std::int64_t(1));
}

void MainWindowTest::slowStepIsComputedInTheBackground()
{
    test::StepGate gate;
    MainWindow window;
    const auto release = qScopeGuard([&gate] { gate.openForGood(); });
    window.runner().setStepFunction(gate.function());
    window.setScene(test::hangingBoxWorld(), QStringLiteral("hanging box"));
    QVERIFY(showActive(window));
    auto* indicator = window.statusBar()->findChild<QLabel*>(QStringLiteral("paceStatus"));
    QVERIFY(indicator != nullptr);
    const model::World start = window.runner().world();

    // → with a step that does not end: the key returns, the status bar says a step is being
    // computed, and Step waits for it.
    QTest::keyClick(&window.canvas(), Qt::Key_Right);
    QVERIFY(window.runner().isComputingStep());
    QVERIFY(!window.stepAction()->isEnabled());
    QVERIFY(!indicator->isHidden());
    QCOMPARE(indicator->text(), QStringLiteral("Computing a step…"));
    QVERIFY(!indicator->toolTip().isEmpty());
    // A second → meanwhile asks for nothing more.
    QTest::keyClick(&window.canvas(), Qt::Key_Right);
    gate.open(1);
    QTRY_VERIFY(!window.runner().isComputing());
    QCOMPARE(gate.started(), 1);
    QCOMPARE(window.runner().world().stepCount, std::int64_t(1));
    QVERIFY(window.stepAction()->isEnabled());
    QVERIFY(indicator->isHidden());

    // Undo while the next step is computed: the world goes back to the start, and the step, when
    // it ends, does not land on it.
    QTest::keyClick(&window.canvas(), Qt::Key_Right);
    QVERIFY(window.runner().isComputingStep());
    QTest::keyClick(&window.canvas(), Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(!window.runner().isComputingStep());
    QVERIFY(window.stepAction()->isEnabled());
    QVERIFY(window.runner().world() == start);
    gate.openForGood();
    QTRY_VERIFY(!window.runner().isComputing());
    QVERIFY(window.runner().world() == start);
}

QTEST_MAIN(MainWindowTest)
#include "main_window_test.moc"
