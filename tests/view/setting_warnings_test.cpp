// The attribute pane's world page warns about settings outside the ranges the engine is tested
// for (issue 17, item 6): opened from a file and typed by hand, in the real window.

#include "test_settings.h"
#include "model/scene_warnings.h"
#include "view/main_window.h"
#include "view/property_pane.h"
#include "view/scene_document.h"
#include "view/simulation_runner.h"

#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>

using impetus::view::MainWindow;
using impetus::view::PropertyPane;

namespace {

/// bad-cases/F9_mass_ratio_1e12.json: a 1e6 kg box resting on a 1e-6 kg box on the floor.
constexpr const char* kMassRatioScene =
    R"({"format": "impetus-scene", "version": 1, "bodies": [)"
    R"({"name": "floor", "shape": {"type": "box", "width": 20, "height": 1}, "position": [0, -0.5], "fixed": true},)"
    R"({"name": "light", "shape": {"type": "box", "width": 1, "height": 1}, "position": [-3, 0.5], "mass": 1e-06},)"
    R"({"name": "heavy", "shape": {"type": "box", "width": 1, "height": 1}, "position": [-3, 1.5], "mass": 1000000.0}]})";

/// A box on the floor under the default settings: nothing to warn about.
constexpr const char* kPlainScene =
    R"({"format": "impetus-scene", "version": 1, "bodies": [)"
    R"({"name": "floor", "shape": {"type": "box", "width": 20, "height": 1}, "position": [0, -0.5], "fixed": true},)"
    R"({"name": "box", "shape": {"type": "box", "width": 1, "height": 1}, "position": [0, 0.5]}]})";

/// An elastic ball dropped 1 m onto the floor under explicit Euler at a 1/60 s step, which gains
/// about 7 % of its energy at each bounce (2·g·h/v; docs/physics.md, "Energy over long runs").
constexpr const char* kEulerBallScene =
    R"({"format": "impetus-scene", "version": 1, "world": {"gravity": [0, -9.81], "integrator": "euler",)"
    R"( "timeStep": 0.016666666666666666}, "bodies": [)"
    R"({"name": "floor", "shape": {"type": "box", "width": 12, "height": 1}, "position": [0, -0.5], "fixed": true,)"
    R"( "restitution": 1, "friction": 0},)"
    R"({"name": "ball", "shape": {"type": "circle", "radius": 0.3}, "position": [0, 1.3],)"
    R"( "restitution": 1, "friction": 0}]})";

/// A 1 kg box hanging from a world point by a spring of 100 N/m, under RK4 at the default step.
constexpr const char* kSpringScene =
    R"({"format": "impetus-scene", "version": 1, "bodies": [)"
    R"({"name": "box", "shape": {"type": "box", "width": 0.5, "height": 0.5}, "position": [0, 1], "mass": 1}],)"
    R"( "springs": [{"bodyA": "box", "anchorA": [0, 0], "anchorB": [0, 2], "stiffness": 100, "restLength": 0.5}]})";

/// A thin bar spinning at 10 rad/s in zero gravity on a stiff spring from its end to a world point,
/// under semi-implicit Euler at 1/60 s: as the bar turns, the spring's fastest motion (its pull
/// across the bar turns it) passes the integrator's limit and falls back below it, step by step.
constexpr const char* kSpinningBarScene =
    R"({"format": "impetus-scene", "version": 1, "world": {"gravity": [0, 0], "timeStep": 0.016666666666666666,)"
    R"( "integrator": "semi-implicit-euler"}, "bodies": [)"
    R"({"name": "bar", "shape": {"type": "box", "width": 1, "height": 0.05}, "position": [0, 0], "mass": 1,)"
    R"( "angularVelocity": 10}],)"
    R"( "springs": [{"bodyA": "bar", "anchorA": [-0.5, 0], "anchorB": [-1.5, 0], "stiffness": 6000, "restLength": 1}]})";

void typeAndEnter(QLineEdit* edit, const QString& text)
{
    edit->setFocus();
    QTest::keyClick(edit, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClick(edit, Qt::Key_Backspace);
    QTest::keyClicks(edit, text);
    QTest::keyClick(edit, Qt::Key_Return);
}

} // namespace

class SettingWarningsTest : public QObject {
    Q_OBJECT

private slots:
    void massRatioOfTouchingBodiesIsWarnedOnTheWorldPage();
    void gravityTypedOutOfRangeShowsAWarningUntilItIsBack();
    void energyGrowingUnderExplicitEulerIsWarned();
    void springTooStiffForTheStepIsWarnedOnItsPage();
    void springWarningHoldsStillWhileTheRunGoesOn();

private:
    /// Writes `text` to a file in m_dir and opens it in `window`; false when it did not open.
    bool open(MainWindow& window, const char* text)
    {
        const QString path = m_dir.filePath(QStringLiteral("scene.json"));
        QFile file(path);
        if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(text) < 0)
            return false;
        file.close();
        return window.openScene(path).isEmpty();
    }

    impetus::view::test::TemporarySettings m_settings;
    QTemporaryDir m_dir;
};

void SettingWarningsTest::massRatioOfTouchingBodiesIsWarnedOnTheWorldPage()
{
    MainWindow window;
    QVERIFY(open(window, kMassRatioScene));
    window.show();
    auto* pane = window.findChild<PropertyPane*>();
    QVERIFY(pane);
    auto* warnings = pane->findChild<QLabel*>(QStringLiteral("worldWarnings"));
    QVERIFY(warnings);
    QVERIFY(warnings->isVisible());
    QVERIFY2(warnings->text().startsWith(QStringLiteral("Warning: bodies[1]: 'light' (1e-06 kg) touches 'heavy' "
                                                        "(1e+06 kg), a mass ratio of 1e+12")),
             qPrintable(warnings->text()));
}

void SettingWarningsTest::gravityTypedOutOfRangeShowsAWarningUntilItIsBack()
{
    MainWindow window;
    QVERIFY(open(window, kPlainScene));
    window.show();
    auto* pane = window.findChild<PropertyPane*>();
    QVERIFY(pane);
    auto* warnings = pane->findChild<QLabel*>(QStringLiteral("worldWarnings"));
    QVERIFY(warnings);
    QVERIFY(!warnings->isVisible());

    // bad-cases/F8: g = 1e6 m/s² sent a stack of boxes 1e14 m away, with no word of why.
    auto* gravityY = pane->findChild<QLineEdit*>(QStringLiteral("gravityY"));
    QVERIFY(gravityY);
    typeAndEnter(gravityY, QStringLiteral("-1000000"));
    QTRY_VERIFY(warnings->isVisible());
    QVERIFY2(warnings->text().startsWith(QStringLiteral("Warning: world.gravity: |g| = 1e+06 m/s² moves a body")),
             qPrintable(warnings->text()));
    QVERIFY2(warnings->text().contains(QStringLiteral("keep |g| at most 115 m/s² at this step")),
             qPrintable(warnings->text()));

    typeAndEnter(gravityY, QStringLiteral("-9.81"));
    QTRY_VERIFY(!warnings->isVisible());
}

// bad-cases/F2: a closed elastic scene gaining energy under explicit Euler, with no word. Played as
// a user would, the world page says so once the gain passes 10 %.
void SettingWarningsTest::energyGrowingUnderExplicitEulerIsWarned()
{
    MainWindow window;
    QVERIFY(open(window, kEulerBallScene));
    window.resize(800, 600);
    window.show();
    window.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    auto* warnings = window.findChild<PropertyPane*>()->findChild<QLabel*>(QStringLiteral("worldWarnings"));
    QVERIFY(warnings);
    QVERIFY(!warnings->isVisible());
    // Play and watch: past 10 % after two bounces, about 2 s of simulated time.
    QTest::keyClick(&window, Qt::Key_Space);
    constexpr int kPatienceMs = 30000;
    QTRY_VERIFY_WITH_TIMEOUT(warnings->isVisible(), kPatienceMs);
    QTest::keyClick(&window, Qt::Key_Space);
    QVERIFY2(warnings->text().startsWith(QStringLiteral("Warning: world.energy: the energy grew from")),
             qPrintable(warnings->text()));
    QVERIFY2(warnings->text().contains(QStringLiteral("explicit Euler adds energy")), qPrintable(warnings->text()));
}

QTEST_MAIN(SettingWarningsTest)
// A teacher types a stiffness of 10⁶ N/m for a 1 kg box: ω = 1000 rad/s, ω·h = 4.17 at 1/240 s,
// past RK4's 2√2. The spring's own page says so under the field, and names the longest step that
// holds; a stiffness back in range takes the warning away.
void SettingWarningsTest::springTooStiffForTheStepIsWarnedOnItsPage()
{
    MainWindow window;
    QVERIFY(open(window, kSpringScene));
    window.show();
    window.document().setSelection(impetus::view::Selection{{}, {0}, {}});
    auto* pane = window.findChild<PropertyPane*>();
    QVERIFY(pane);
    auto* warnings = pane->findChild<QLabel*>(QStringLiteral("springWarnings"));
    auto* stiffness = pane->findChild<QLineEdit*>(QStringLiteral("springStiffness"));
    QVERIFY(warnings && stiffness);
    QVERIFY(stiffness->isVisible());
    QVERIFY(!warnings->isVisible());

    typeAndEnter(stiffness, QStringLiteral("1000000"));
    QTRY_VERIFY(warnings->isVisible());
    QCOMPARE(window.runner().world().springs[0].stiffness, 1e6);
    QVERIFY2(warnings->text().startsWith(QStringLiteral("Warning: k = 1e+06 N/m swings the bodies on it at ω = 1e+03 "
                                                        "rad/s (its fastest motion, the bodies' turns included; "
                                                        "damping ratio 0): ω·h = 4.17 at the integrators' step of "
                                                        "4.17 ms, past the 2.83 at which RK4 stays stable")),
             qPrintable(warnings->text()));
    QVERIFY2(warnings->text().contains(QStringLiteral("make the step at most 2.83 ms")), qPrintable(warnings->text()));

    typeAndEnter(stiffness, QStringLiteral("1000"));
    QTRY_VERIFY(!warnings->isVisible());

    // Back at 10⁶ N/m, the page offers the step that holds it, a little under the limit: one
    // click sets it (one undo step), and the warning goes.
    typeAndEnter(stiffness, QStringLiteral("1000000"));
    QTRY_VERIFY(warnings->isVisible());
    auto* useStep = pane->findChild<QPushButton*>(QStringLiteral("springUseStableStep"));
    QVERIFY(useStep && useStep->isVisible() && useStep->isEnabled());
    QCOMPARE(useStep->text(), QStringLiteral("Use a time step of 2.68 ms"));
    QTest::mouseClick(useStep, Qt::LeftButton);
    QCOMPARE(window.runner().world().settings.timeStep, 2.68e-3);
    QTRY_VERIFY(!warnings->isVisible());
    QVERIFY(!useStep->isVisible());
    window.undoAction()->trigger();
    QCOMPARE(window.runner().world().settings.timeStep, 1.0 / 240);
    QTRY_VERIFY(warnings->isVisible());
}

// The spring's page judges the spring when it is shown or edited, not at every step of a run: the
// spinning bar's spring is within the limit at the start and past it at some poses of the run, and
// the warning must not come and go with them (it did, every few steps). An edit judges it again,
// at the pose of the moment.
void SettingWarningsTest::springWarningHoldsStillWhileTheRunGoesOn()
{
    MainWindow window;
    QVERIFY(open(window, kSpinningBarScene));
    window.show();
    window.document().setSelection(impetus::view::Selection{{}, {0}, {}});
    auto* pane = window.findChild<PropertyPane*>();
    QVERIFY(pane);
    auto* warnings = pane->findChild<QLabel*>(QStringLiteral("springWarnings"));
    auto* damping = pane->findChild<QLineEdit*>(QStringLiteral("springDamping"));
    QVERIFY(warnings && damping);
    QVERIFY(!warnings->isVisible());
    QVERIFY(!impetus::model::springWarning(window.runner().world(), 0).has_value());

    int posesPastTheLimit = 0;
    for (int step = 0; step < 12; ++step) {
        window.runner().stepBy(1);
        posesPastTheLimit += impetus::model::springWarning(window.runner().world(), 0).has_value() ? 1 : 0;
        QVERIFY2(!warnings->isVisible(), qPrintable(QStringLiteral("the warning came at step %1").arg(step + 1)));
    }
    // The run did pass through poses at which the spring is past the limit.
    QVERIFY(posesPastTheLimit > 0);

    // An edit judges the spring again, where the bar is now.
    typeAndEnter(damping, QStringLiteral("0.001"));
    QCOMPARE(window.runner().world().springs[0].damping, 0.001);
    QCOMPARE(warnings->isVisible(), impetus::model::springWarning(window.runner().world(), 0).has_value());

    // The world page, which lists the spring's warning too, holds still in the same way: judged
    // when it is shown, here at the bar's present pose.
    window.document().setSelection(impetus::view::Selection{});
    auto* worldWarnings = pane->findChild<QLabel*>(QStringLiteral("worldWarnings"));
    QVERIFY(worldWarnings);
    // (Its line on the spring, "springs[0]: …"; a line on the run's energy may come and go.)
    const auto springLine = [worldWarnings] {
        return worldWarnings->isVisible() && worldWarnings->text().contains(QStringLiteral("springs[0]: "));
    };
    const bool shown = springLine();
    QCOMPARE(shown, impetus::model::springWarning(window.runner().world(), 0).has_value());
    int changes = 0;
    for (int step = 0; step < 12; ++step) {
        const bool before = impetus::model::springWarning(window.runner().world(), 0).has_value();
        window.runner().stepBy(1);
        changes += impetus::model::springWarning(window.runner().world(), 0).has_value() != before ? 1 : 0;
        QCOMPARE(springLine(), shown);
    }
    QVERIFY(changes > 0);
}

#include "setting_warnings_test.moc"
