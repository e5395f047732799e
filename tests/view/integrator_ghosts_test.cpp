// View › Compare Integrators driven as a user would: the View menu's entry toggled, the time-step
// slider moved with the keyboard, the run stepped, Reset pressed and the timeline scrubbed. What
// is checked is what the window shows (the canvas's pixels, the readout's text, the chart's
// points and slopes) against the textbook: explicit Euler's energy on a spring grows by exactly
// (1 + ω²h²) a step, on a projectile the two Eulers miss the parabola by ½·g·h·t either way, and
// the position errors fall as h¹ and h⁴.

#include "test_settings.h"
#include "test_worlds.h"
#include "view/canvas_view.h"
#include "view/ghost_constants.h"
#include "view/integrator_ghosts.h"
#include "view/integrator_ghosts_dock.h"
#include "view/main_window.h"
#include "view/scene_document.h"
#include "view/simulation_runner.h"
#include "view/timeline.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QRegularExpression>
#include <QSlider>
#include <QTableWidget>
#include <QTest>

#include <array>
#include <cmath>
#include <numbers>

using namespace impetus;
using namespace impetus::view;

namespace {

constexpr std::size_t kEuler = 0;
constexpr std::size_t kSemiImplicit = 1;
constexpr std::size_t kRk4 = 2;

/// How far a pixel's hue may be from a ghost's, degrees: the outline is nearly opaque, so its
/// colour survives blending with the paper or a body under it within a few degrees.
constexpr int kHueSlack = 14;
/// The least saturation and value (of 255) of a ghost's outline pixel: the paper, the grid and the
/// grey bodies have far less saturation.
constexpr int kMinSaturation = 90;
constexpr int kMinValue = 80;

/// The number in a readout cell such as "+4.25 %" or "0.0123 mm".
double numberIn(const QString& text)
{
    static const QRegularExpression number(QStringLiteral("[-+]?[0-9.]+(e[-+]?[0-9]+)?"));
    const QRegularExpressionMatch match = number.match(text);
    return match.hasMatch() ? match.captured(0).toDouble() : std::nan("");
}

/// Pixels of `image` within `radius` px of `centre` whose colour is `color`'s hue, strongly.
int pixelsOfHue(const QImage& image, QPointF centre, double radius, const QColor& color)
{
    int count = 0;
    for (int y = static_cast<int>(centre.y() - radius); y <= static_cast<int>(centre.y() + radius); ++y) {
        for (int x = static_cast<int>(centre.x() - radius); x <= static_cast<int>(centre.x() + radius); ++x) {
            if (!image.rect().contains(x, y) || std::hypot(x - centre.x(), y - centre.y()) > radius)
                continue;
            const QColor c = image.pixelColor(x, y).toHsv();
            const int gap = std::abs(c.hue() - color.hsvHue());
            if (c.saturation() >= kMinSaturation && c.value() >= kMinValue && std::min(gap, 360 - gap) <= kHueSlack)
                ++count;
        }
    }
    return count;
}

} // namespace

class IntegratorGhostsTest : public QObject {
    Q_OBJECT

private slots:
    void compareIntegratorsDrawsAGhostOfEachColour();
    void springReadoutShowsEulersEnergyGrowth();
    void sliderSetsTheStepAndThePlotShowsTheOrders();
    void sceneWithoutAnAnalyticSolutionSaysSo();
    void pendulumGhostsCoincideAndTrackTheExactSwing();
    void aGhostThatDivergesIsSaidSoAndTheOthersGoOn();

private:
    /// Opens the example `name`, shows the window and switches View › Compare Integrators on as the
    /// menu holds it. Returns the action (nullptr when anything failed).
    static QAction* openWithGhosts(MainWindow& window, const QString& name);

    test::TemporarySettings m_settings;
};

QAction* IntegratorGhostsTest::openWithGhosts(MainWindow& window, const QString& name)
{
    if (!window.openScene(QStringLiteral(":/examples/%1.json").arg(name)).isEmpty())
        return nullptr;
    window.resize(1100, 750);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window))
        return nullptr;
    // The View menu holds it, as a user finds it.
    auto* viewMenu = window.findChild<QMenu*>(QStringLiteral("viewMenu"));
    if (viewMenu == nullptr || !window.menuBar()->actions().contains(viewMenu->menuAction()))
        return nullptr;
    QAction* action = nullptr;
    for (QAction* item : viewMenu->actions()) {
        if (item->objectName() == QStringLiteral("compareIntegratorsAction"))
            action = item;
    }
    if (action == nullptr || !action->isCheckable() || action->isChecked())
        return nullptr;
    action->trigger();
    return action;
}

void IntegratorGhostsTest::compareIntegratorsDrawsAGhostOfEachColour()
{
    MainWindow window;
    QAction* action = openWithGhosts(window, QStringLiteral("projectile"));
    QVERIFY(action);
    QVERIFY(action->isChecked());
    auto* dock = window.findChild<QDockWidget*>(QStringLiteral("integratorGhostsDock"));
    QVERIFY(dock && dock->isVisible());
    auto* legend = window.canvas().viewport()->findChild<QLabel*>(QStringLiteral("integratorGhostsLegend"));
    QVERIFY(legend && legend->isVisible());
    for (std::size_t i = 0; i < 3; ++i)
        QVERIFY(legend->text().contains(ghostIntegratorName(i)));

    // The coarsest step, so that the Eulers stray far enough to be seen apart: End on the slider.
    auto* slider = dock->findChild<QSlider*>(QStringLiteral("ghostTimeStepSlider"));
    QVERIFY(slider);
    slider->setFocus();
    QTest::keyClick(slider, Qt::Key_End);
    auto* ghosts = window.findChild<IntegratorGhosts*>(QStringLiteral("integratorGhosts"));
    QVERIFY(ghosts);
    QCOMPARE(ghosts->timeStep(), 1.0 / 30);

    // One second of flight (the ball lands after 1.25 s): 240 real steps, 30 ghost steps.
    window.runner().stepBy(240);
    QCOMPARE(ghosts->steps(), std::int64_t{30});
    const controller::IntegratorComparison* comparison = ghosts->comparison();
    QVERIFY(comparison);
    // Free flight at h (g pointing down): x_n = x₀ + v₀t + ½gt² ∓ ½ght, explicit Euler (moving with
    // the velocity at the step's start, which gravity has not yet slowed) above the parabola and
    // semi-implicit below, by 0.5 · 9.81 · (1/30) · 1 = 0.1635 m; RK4 exactly on it. The launch is
    // a little closer: while the ball is within the contact margin of the launcher the engine
    // splits the step (tests/controller/integrator_comparison_test.cpp has the exact offset).
    const double offset = 0.5 * 9.81 * (1.0 / 30) * 1.0;
    for (const std::size_t i : {kEuler, kSemiImplicit}) {
        QVERIFY(*comparison->positionError(i) < offset);
        QVERIFY(*comparison->positionError(i) > 0.8 * offset);
    }
    QVERIFY(*comparison->positionError(kRk4) < 1e-9);

    CanvasView& canvas = window.canvas();
    QApplication::processEvents();
    const QImage on = canvas.viewport()->grab().toImage();
    const std::size_t ball = comparison->start().bodies.size() - 1;
    const double radiusPx = 0.15 * canvas.pixelsPerMetre() + 3;
    std::array<QPointF, 3> centres;
    for (std::size_t i = 0; i < 3; ++i) {
        const Vec2 p = comparison->world(i).bodies[ball].state.position;
        centres[i] = canvas.toView(QPointF(p.x(), p.y()));
        const int count = pixelsOfHue(on, centres[i], radiusPx, ghostColor(i));
        // A ghost's outline is 2 px round a circle of radius r: about 4πr px; half of it showing
        // (the others cross it) is still over πr.
        QVERIFY2(count > std::numbers::pi * (radiusPx - 3), qPrintable(QStringLiteral("%1: %2 px").arg(ghostIntegratorName(i)).arg(count)));
    }
    // The Eulers' ghosts are apart, either side of RK4's (screen y points down).
    QVERIFY(centres[kEuler].y() < centres[kRk4].y() - 5);
    QVERIFY(centres[kSemiImplicit].y() > centres[kRk4].y() + 5);

    // Off again: no ghost is drawn, the legend and the dock are gone.
    action->trigger();
    QVERIFY(!ghosts->isEnabled());
    QVERIFY(!dock->isVisible());
    QVERIFY(window.canvas().viewport()->findChild<QLabel*>(QStringLiteral("integratorGhostsLegend")) == nullptr);
    QApplication::processEvents();
    const QImage off = canvas.viewport()->grab().toImage();
    for (std::size_t i = 0; i < 3; ++i)
        QCOMPARE(pixelsOfHue(off, centres[i], radiusPx, ghostColor(i)), 0);

    // On again, then closed with the dock's own button: the action follows.
    action->trigger();
    QVERIFY(ghosts->isEnabled());
    dock->close();
    QVERIFY(!action->isChecked());
    QVERIFY(!ghosts->isEnabled());
}

void IntegratorGhostsTest::springReadoutShowsEulersEnergyGrowth()
{
    MainWindow window;
    QVERIFY(openWithGhosts(window, QStringLiteral("spring")));
    auto* ghosts = window.findChild<IntegratorGhosts*>(QStringLiteral("integratorGhosts"));
    auto* table = window.findChild<QTableWidget*>(QStringLiteral("ghostReadout"));
    auto* clock = window.findChild<QLabel*>(QStringLiteral("ghostClock"));
    QVERIFY(ghosts && table && clock);
    const model::World& start = window.document().world();
    QCOMPARE(start.springs.size(), std::size_t{1});
    const double h = start.settings.timeStep;
    // The ghosts step as the scene does until the slider is moved.
    QCOMPARE(ghosts->timeStep(), h);
    const double k = start.springs[0].stiffness;
    const double m = start.bodies.back().mass;
    const double omegaH2 = k / m * h * h;

    // x' = x + h·v, v' = v − h·ω²·x multiplies ½kx² + ½mv² by 1 + ω²h² exactly; in zero gravity
    // that is all the energy there is, so the error after n steps is (1 + ω²h²)ⁿ − 1.
    double percent = 0; // the energy error checkAt read, %
    const auto checkAt = [&](int n) {
        QCOMPARE(ghosts->steps(), std::int64_t{n});
        QVERIFY2(clock->text().contains(QStringLiteral("n = %1 ").arg(n)), qPrintable(clock->text()));
        const QString shown = table->item(static_cast<int>(kEuler), 0)->text();
        percent = numberIn(shown);
        const double expected = 100 * (std::pow(1 + omegaH2, n) - 1);
        // The readout has four significant digits.
        QVERIFY2(std::abs(percent - expected) < 1e-3 * expected,
                 qPrintable(QStringLiteral("n = %1: shown %2, formula %3 %").arg(n).arg(shown).arg(expected)));
        // Semi-implicit Euler keeps a modified energy within ω·h; RK4 loses next to nothing.
        QVERIFY(std::abs(numberIn(table->item(static_cast<int>(kSemiImplicit), 0)->text())) < 100 * std::sqrt(omegaH2));
        QVERIFY(std::abs(numberIn(table->item(static_cast<int>(kRk4), 0)->text())) < 1e-4);
    };

    // The ghosts follow the run: one second, then two.
    window.runner().stepBy(240);
    checkAt(240);
    const double first = percent;
    window.runner().stepBy(240);
    checkAt(480);
    QVERIFY(percent > 2 * first);
    // Against the textbook orbit: RK4 within a micrometre, explicit Euler visibly off.
    QVERIFY(numberIn(table->item(static_cast<int>(kRk4), 1)->text()) < 1e-3);
    QVERIFY(numberIn(table->item(static_cast<int>(kEuler), 1)->text()) > 1);
    QVERIFY(table->item(static_cast<int>(kEuler), 1)->text().endsWith(QStringLiteral("mm")));

    // A scrub back along the timeline takes the ghosts back with it.
    window.timeline().seek(120);
    checkAt(120);
    // Step → moves them on by one.
    window.canvas().setFocus();
    QTest::keyClick(window.canvas().viewport(), Qt::Key_Right);
    QTRY_COMPARE(ghosts->steps(), std::int64_t{121});
    checkAt(121);
    // Play (Space) from here, pause (Space), then Reset (R): back to the state at the Play, and the
    // ghosts with it.
    QTest::keyClick(window.canvas().viewport(), Qt::Key_Space);
    QTRY_VERIFY(ghosts->steps() > 140);
    QTest::keyClick(window.canvas().viewport(), Qt::Key_Space);
    QTRY_VERIFY(!window.runner().isRunning());
    QTest::keyClick(window.canvas().viewport(), Qt::Key_R);
    QTRY_COMPARE(window.runner().world().stepCount, std::int64_t{121});
    checkAt(121);
}

void IntegratorGhostsTest::sliderSetsTheStepAndThePlotShowsTheOrders()
{
    MainWindow window;
    QVERIFY(openWithGhosts(window, QStringLiteral("spring")));
    auto* panel = window.findChild<IntegratorGhostsPanel*>();
    auto* ghosts = window.findChild<IntegratorGhosts*>(QStringLiteral("integratorGhosts"));
    auto* slider = window.findChild<QSlider*>(QStringLiteral("ghostTimeStepSlider"));
    auto* stepLabel = window.findChild<QLabel*>(QStringLiteral("ghostTimeStepLabel"));
    auto* slopeLabel = window.findChild<QLabel*>(QStringLiteral("ghostSlopes"));
    QVERIFY(panel && ghosts && slider && stepLabel && slopeLabel);
    QCOMPARE(stepLabel->text(), formatTimeStep(1.0 / 240));

    // Every notch of the slider is a point of each line, and the fitted slopes are the orders.
    for (std::size_t i = 0; i < 3; ++i)
        QCOMPARE(panel->plotted(i).size(), view::constants::kGhostTimeSteps.size());
    const std::array<double, 3> orders = {1, 1, 4};
    for (std::size_t i = 0; i < 3; ++i) {
        QVERIFY(panel->slopes()[i].has_value());
        QVERIFY2(std::abs(*panel->slopes()[i] - orders[i]) < 0.15,
                 qPrintable(QStringLiteral("%1: slope %2").arg(ghostIntegratorName(i)).arg(*panel->slopes()[i])));
        // And the label prints them.
        QVERIFY2(slopeLabel->text().contains(
                     QStringLiteral("%1 %2").arg(ghostIntegratorName(i)).arg(*panel->slopes()[i], 0, 'f', 2)),
                 qPrintable(slopeLabel->text()));
    }
    // Each point is the error the engine gives for that h, and halving h halves the Eulers' error
    // and divides RK4's by about 16 (neighbouring notches are about 1.4 apart: 1.4 and 1.4⁴).
    const auto euler = panel->plotted(kEuler);
    const auto rk4 = panel->plotted(kRk4);
    for (std::size_t p = 0; p + 1 < euler.size(); ++p) {
        QVERIFY(euler[p].first < euler[p + 1].first);
        QVERIFY(euler[p].second < euler[p + 1].second);
        QVERIFY(rk4[p].second < rk4[p + 1].second);
    }

    // Keys on the slider change h: Home is 1/1000 s, one notch right 1/720 s, End 1/30 s; the
    // ghosts start again and step with it.
    slider->setFocus();
    QTest::keyClick(slider, Qt::Key_Home);
    QCOMPARE(ghosts->timeStep(), 1.0 / 1000);
    QCOMPARE(stepLabel->text(), QStringLiteral("1/1000 s"));
    window.runner().stepBy(240);
    QCOMPARE(ghosts->steps(), std::int64_t{1000});
    QTest::keyClick(slider, Qt::Key_Right);
    QCOMPARE(ghosts->timeStep(), 1.0 / 720);
    QCOMPARE(ghosts->steps(), std::int64_t{720});
    QTest::keyClick(slider, Qt::Key_End);
    QCOMPARE(ghosts->timeStep(), 1.0 / 30);
    QCOMPARE(ghosts->steps(), std::int64_t{30});
    // The coarser the step, the larger Euler's energy error after the same second: (1 + ω²h²)ⁿ
    // with n = 1/h grows with h.
    auto* table = window.findChild<QTableWidget*>(QStringLiteral("ghostReadout"));
    const model::World& start = window.document().world();
    const double omega2 = start.springs[0].stiffness / start.bodies.back().mass;
    const double h = 1.0 / 30;
    QVERIFY(std::abs(numberIn(table->item(0, 0)->text()) - 100 * (std::pow(1 + omega2 * h * h, 30) - 1)) <
            1e-3 * 100 * (std::pow(1 + omega2 * h * h, 30) - 1));
}

void IntegratorGhostsTest::sceneWithoutAnAnalyticSolutionSaysSo()
{
    // The chain of springs: damped springs between bodies, no textbook solution.
    MainWindow window;
    QVERIFY(openWithGhosts(window, QStringLiteral("spring-chain")));
    auto* table = window.findChild<QTableWidget*>(QStringLiteral("ghostReadout"));
    auto* slopeLabel = window.findChild<QLabel*>(QStringLiteral("ghostSlopes"));
    auto* panel = window.findChild<IntegratorGhostsPanel*>();
    QVERIFY(table && slopeLabel && panel);
    window.runner().stepBy(24);
    for (int i = 0; i < 3; ++i) {
        QCOMPARE(table->item(i, 1)->text(), IntegratorGhostsPanel::tr("no analytic solution"));
        // The energy error is still measured.
        QVERIFY(!std::isnan(numberIn(table->item(i, 0)->text())));
        QVERIFY(panel->plotted(static_cast<std::size_t>(i)).empty());
    }
    QCOMPARE(slopeLabel->text(), IntegratorGhostsPanel::tr("No analytic solution for this scene: no error to plot."));
}

void IntegratorGhostsTest::pendulumGhostsCoincideAndTrackTheExactSwing()
{
    MainWindow window;
    QVERIFY(openWithGhosts(window, QStringLiteral("pendulum")));
    auto* table = window.findChild<QTableWidget*>(QStringLiteral("ghostReadout"));
    auto* ghosts = window.findChild<IntegratorGhosts*>(QStringLiteral("integratorGhosts"));
    auto* analytic = window.findChild<QLabel*>(QStringLiteral("ghostAnalytic"));
    QVERIFY(table && ghosts && analytic);
    // Two seconds of the swing.
    for (int i = 0; i < 8; ++i)
        window.runner().stepBy(60);
    // The bob hangs on a rod: the engine moves a jointed body by semi-implicit Euler whatever the
    // integrator, so the three ghosts are one, and the dock says why.
    const std::size_t bob = ghosts->comparison()->start().bodies.size() - 1;
    const Vec2 euler = ghosts->comparison()->world(kEuler).bodies[bob].state.position;
    QVERIFY(euler != ghosts->comparison()->start().bodies[bob].state.position);
    QCOMPARE(ghosts->comparison()->world(kRk4).bodies[bob].state.position, euler);
    QVERIFY(analytic->text().contains(QStringLiteral("pendulum")));
    QVERIFY(analytic->text().contains(QStringLiteral("joints")));
    // Against the exact swing at any amplitude: a few millimetres off, the same for all three.
    const QString shown = table->item(static_cast<int>(kEuler), 1)->text();
    QVERIFY2(shown.endsWith(QStringLiteral("mm")) && numberIn(shown) > 0 && numberIn(shown) < 10, qPrintable(shown));
    QCOMPARE(table->item(static_cast<int>(kRk4), 1)->text(), shown);
}

void IntegratorGhostsTest::aGhostThatDivergesIsSaidSoAndTheOthersGoOn()
{
    // A ball on a spring with ω = 100 rad/s, and the ghosts at h = 1/90 s: ω·h = 1.11, past what
    // explicit Euler survives (its energy grows by 1 + ω²h² = 2.2 a step, and is not a finite number
    // after some 900 steps) but within what semi-implicit Euler (ω·h < 2) and RK4 (< 2.8) do. The
    // real run, RK4 at 1/240 s, is fine.
    constexpr double kOmega = 100;
    model::World world = test::explodingSpringWorld();
    world.springs[0].stiffness = kOmega * kOmega * world.bodies[0].mass;
    MainWindow window;
    window.setScene(world, QStringLiteral("stiff spring"));
    window.resize(1100, 750);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    auto* action = window.findChild<QAction*>(QStringLiteral("compareIntegratorsAction"));
    QVERIFY(action);
    action->trigger();
    auto* slider = window.findChild<QSlider*>(QStringLiteral("ghostTimeStepSlider"));
    auto* ghosts = window.findChild<IntegratorGhosts*>(QStringLiteral("integratorGhosts"));
    auto* table = window.findChild<QTableWidget*>(QStringLiteral("ghostReadout"));
    QVERIFY(slider && ghosts && table);
    slider->setFocus();
    QTest::keyClick(slider, Qt::Key_End);
    for (int i = 0; i < 3; ++i)
        QTest::keyClick(slider, Qt::Key_Left);
    QCOMPARE(ghosts->timeStep(), 1.0 / 90);

    // Fifteen seconds, in batches as a run shows them.
    for (int i = 0; i < 15; ++i)
        window.runner().stepBy(240);
    QVERIFY(ghosts->comparison()->diverged(kEuler));
    QVERIFY2(table->item(static_cast<int>(kEuler), 0)->text().startsWith(IntegratorGhostsPanel::tr("diverged at t = %1 s").left(12)),
             qPrintable(table->item(static_cast<int>(kEuler), 0)->text()));
    QCOMPARE(table->item(static_cast<int>(kEuler), 1)->text(), IntegratorGhostsPanel::tr("diverged"));
    for (const std::size_t i : {kSemiImplicit, kRk4}) {
        QVERIFY(!ghosts->comparison()->diverged(i));
        QVERIFY(std::isfinite(numberIn(table->item(static_cast<int>(i), 0)->text())));
        QVERIFY(std::isfinite(numberIn(table->item(static_cast<int>(i), 1)->text())));
    }
    QCOMPARE(ghosts->steps(), std::int64_t{15 * 90});
    // The canvas still draws (the diverged ghost is left out).
    QApplication::processEvents();
    QVERIFY(!window.canvas().viewport()->grab().isNull());
}

QTEST_MAIN(IntegratorGhostsTest)
#include "integrator_ghosts_test.moc"
