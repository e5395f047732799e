// The canvas instruments and graphs, driven from the window's menus as a user would: vector
// arrows found in a grab, their legend and scale, trails with dots every N steps that follow the
// timeline, and a graph of a falling body's vy exported as CSV.

#include "support/pendulum_theory.h"
#include "test_files.h"
#include "test_graphs.h"
#include "test_pixels.h"
#include "test_settings.h"
#include "test_worlds.h"
#include "view/canvas_instruments.h"
#include "view/canvas_view.h"
#include "view/graph_panel.h"
#include "view/main_window.h"
#include "view/property_pane.h"
#include "view/scene_document.h"
#include "view/simulation_runner.h"
#include "view/tools/measure_tools.h"
#include "view/tools/probe_tool.h"
#include "view/tools/trace_point_tool.h"
#include "view/timeline.h"
#include "view/view_constants.h"

#include <QAction>
#include <QCheckBox>
#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QRegularExpression>
#include <QScrollArea>
#include <QTemporaryDir>
#include <QValueAxis>
#include <QXYSeries>
#include <QToolBar>
#include <QToolButton>
#include <QUndoStack>
#include <QTest>

#include <cmath>
#include <numbers>
#include <set>

using impetus::view::CanvasInstruments;
using impetus::view::GraphPanel;
using impetus::view::GraphQuantity;
using impetus::view::MainWindow;
using impetus::view::VectorKind;
namespace model = impetus::model;
namespace constants = impetus::view::constants;
namespace test = impetus::view::test;

namespace {

/// A ball falling freely from (0, 10) m, with nothing to hit.
model::World fallingBallWorld()
{
    model::World world;
    world.bodies.push_back(test::makeBody("ball", model::Circle{0.1}, impetus::Vec2(0, 10)));
    return world;
}

/// A ball falling freely from (0, 10) m between two fixed markers, at the origin and at (2, 12) m,
/// which frame the view around the ball's first metres of fall.
model::World fallingBallOverMarkerWorld()
{
    model::World world = fallingBallWorld();
    world.bodies.push_back(test::makeBody("marker", model::Box{0.4, 0.4}, impetus::Vec2(0, 0), true));
    world.bodies.push_back(test::makeBody("top", model::Box{0.4, 0.4}, impetus::Vec2(2, 12), true));
    return world;
}

/// A block at (−2, 0) moving at `blockSpeed` m/s along x and a wheel of radius 0.5 m at (2, 0)
/// rolling up at 1 m/s and turning at 2 rad/s, in zero gravity.
model::World blockAndWheelWorld(double blockSpeed)
{
    model::World world;
    world.settings.gravity = impetus::Vec2::Zero();
    model::Body block = test::makeBody("block", model::Box{0.6, 0.6}, impetus::Vec2(-2, 0));
    block.state.velocity = impetus::Vec2(blockSpeed, 0);
    world.bodies.push_back(block);
    model::Body wheel = test::makeBody("wheel", model::Circle{0.5}, impetus::Vec2(2, 0));
    wheel.state.velocity = impetus::Vec2(0, 1);
    wheel.state.angularVelocity = 2;
    world.bodies.push_back(wheel);
    return world;
}

/// Turns the trails on, traces the wheel of blockAndWheelWorld 0.4 m below its centre with the
/// Trace Point tool, and runs 24 steps: the wheel's trail and traced point have 25 points.
void traceTheWheelFor24Steps(MainWindow& window)
{
    impetus::view::CanvasView& canvas = window.canvas();
    QWidget* viewport = canvas.viewport();
    CanvasInstruments& instruments = canvas.instruments();
    window.trailsAction()->trigger();
    QTest::keyClick(viewport, Qt::Key_X);
    QTest::mouseClick(viewport, Qt::LeftButton, {}, canvas.toView(QPointF(2, -0.4)).toPoint());
    QCOMPARE(instruments.tracedPoints().size(), std::size_t{1});
    QCOMPARE(instruments.tracedPoints().front().body, 1u);
    window.runner().stepBy(24);
    QCOMPARE(instruments.trail(1).size(), std::size_t{25});
}

/// The number after "`name` = " in `text` ("y = 9.877 m" gives 9.877); NaN when there is none.
double readoutValue(const QString& text, const QString& name)
{
    const QRegularExpression pattern(QStringLiteral("(?:^|[\\s,(])%1 = (-?[0-9]+\\.[0-9]+)")
                                         .arg(QRegularExpression::escape(name)));
    const QRegularExpressionMatch match = pattern.match(text);
    return match.hasMatch() ? match.captured(1).toDouble() : std::nan("");
}

} // namespace

class InstrumentsTest : public QObject {
    Q_OBJECT

private slots:
    void velocityVectorsAppearInTheGrab();
    void legendGivesTheScaleAndItCanBeChanged();
    void forceArrowsOfABoxOnTheFloorComeFromTheEngine();
    void trailsHaveDotsAndFollowTheTimeline();
    void graphOfAFallingBodysVyHasSlopeMinusG();
    void graphExportsAPictureAndFollowsTheTimeline();
    void pendulumPeriodReadOffTheGraphToAMillisecond();
    void twoGraphsAtOnceWithAPhasePlotOfTheSpring();
    void aFullGraphDropsItsOldestSamplesInOneGo();
    void rulerBetweenTwoClicksReadsTheDistance();
    void protractorReadsTheAngle();
    void probeFollowsAFallingBall();
    void velocityVectorsOfOneBodyFromThePane();
    void accelerationForceAndMomentumArrowsPointAlongTheirVectors();
    void tracePointDrawsACycloid();
    void pathsStayWithTheirBodiesWhenABodyIsDeletedOrBack();
    void pathsStayWithABodyRenamedInThePane();
    void aBodyDrawnInADeletedOnesPlaceGetsNoOtherPathsOnReset();
    void toolsAndRunControlsHaveIconsAndShortcutTips();

private:
    static bool showActive(MainWindow& window);
    test::TemporarySettings m_settings;
};

bool InstrumentsTest::showActive(MainWindow& window)
{
    window.resize(900, 650);
    window.show();
    window.activateWindow();
    return QTest::qWaitForWindowActive(&window);
}

void InstrumentsTest::velocityVectorsAppearInTheGrab()
{
    MainWindow window;
    window.setScene(test::movingBallWorld(), QStringLiteral("moving"));
    QVERIFY(showActive(window));
    impetus::view::CanvasView& canvas = window.canvas();
    const QImage before = canvas.viewport()->grab().toImage();
    QCOMPARE(test::pixelsNear(before, constants::kVelocityColor), 0);

    window.vectorAction(VectorKind::Velocity)->trigger();
    QVERIFY(canvas.instruments().showsVector(VectorKind::Velocity));
    const QImage after = canvas.viewport()->grab().toImage();
    // 2 m/s at 0.25 m per m/s is 0.5 m of arrow: many pixels at this zoom.
    const double expectedLengthPx = 2 * constants::kDefaultVelocityScale * canvas.pixelsPerMetre();
    const QPointF ball = canvas.toView(QPointF(0, 0));
    // Around the ball, away from the legend's sample arrow in the corner.
    const int reach = static_cast<int>(2 * expectedLengthPx);
    const QRect aroundBall(ball.toPoint() - QPoint(reach, reach), QSize(2 * reach, 2 * reach));
    QPoint centroid;
    const int arrow = test::pixelsNear(after, constants::kVelocityColor, &centroid, aroundBall);
    QVERIFY2(arrow > expectedLengthPx, qPrintable(QStringLiteral("%1 arrow pixels").arg(arrow)));
    // It points to the right of the ball, along its velocity, at its height.
    QVERIFY(centroid.x() > ball.x() + 0.25 * expectedLengthPx);
    QVERIFY(std::abs(centroid.y() - ball.y()) < 0.2 * expectedLengthPx);

    // Zoomed in, the arrow grows with the canvas but keeps its width on screen: about as many
    // pixels per pixel of length as before. Zoomed far out, it is still drawn.
    const double density = arrow / expectedLengthPx;
    canvas.zoomBy(2, ball);
    const QPointF ballIn = canvas.toView(QPointF(0, 0));
    const QRect aroundIn(ballIn.toPoint() - QPoint(2 * reach, 2 * reach), QSize(4 * reach, 4 * reach));
    const int zoomedIn = test::pixelsNear(canvas.viewport()->grab().toImage(), constants::kVelocityColor, nullptr, aroundIn);
    QVERIFY2(std::abs(zoomedIn / (2 * expectedLengthPx) - density) < 0.25 * density,
             qPrintable(QStringLiteral("%1 px along %2 px, before %3").arg(zoomedIn).arg(2 * expectedLengthPx).arg(arrow)));
    canvas.zoomBy(0.05, ballIn);
    const QPoint ballOut = canvas.toView(QPointF(0, 0)).toPoint();
    const QRect nearBall(ballOut - QPoint(40, 40), QSize(80, 80));
    QVERIFY(test::pixelsNear(canvas.viewport()->grab().toImage(), constants::kVelocityColor, nullptr, nearBall) > 0);

    window.vectorAction(VectorKind::Velocity)->trigger();
    QCOMPARE(test::pixelsNear(canvas.viewport()->grab().toImage(), constants::kVelocityColor), 0); // legend gone too
}

void InstrumentsTest::legendGivesTheScaleAndItCanBeChanged()
{
    MainWindow window;
    window.setScene(test::movingBallWorld(), QStringLiteral("moving"));
    QVERIFY(showActive(window));
    CanvasInstruments& instruments = window.canvas().instruments();
    QVERIFY(instruments.legendLines().isEmpty());
    window.vectorAction(VectorKind::Velocity)->trigger();
    window.vectorAction(VectorKind::Momentum)->trigger();
    QCOMPARE(instruments.legendLines(),
             QStringList({QStringLiteral("velocity: 1 m/s = 0.25 m"), QStringLiteral("momentum: 1 kg·m/s = 0.25 m")}));
    // "]" on the canvas doubles every arrow, "[" halves them.
    QTest::keyClick(window.canvas().viewport(), Qt::Key_BracketRight);
    QCOMPARE(instruments.legendLines().front(), QStringLiteral("velocity: 1 m/s = 0.5 m"));
    QTest::keyClick(window.canvas().viewport(), Qt::Key_BracketLeft);
    QTest::keyClick(window.canvas().viewport(), Qt::Key_BracketLeft);
    QCOMPARE(instruments.legendLines().front(), QStringLiteral("velocity: 1 m/s = 0.125 m"));
}

void InstrumentsTest::forceArrowsOfABoxOnTheFloorComeFromTheEngine()
{
    model::World world;
    world.bodies.push_back(test::makeBody("floor", model::Box{4, 0.2}, impetus::Vec2(0, -0.1), true));
    world.bodies.push_back(test::makeBody("box", model::Box{0.5, 0.4}, impetus::Vec2(0, 0.2)));
    MainWindow window;
    window.setScene(world, QStringLiteral("box"));
    QVERIFY(showActive(window));
    window.runner().stepBy(480); // 2 s: at rest on the floor
    window.vectorAction(VectorKind::ForceParts)->trigger();
    const auto& forces = window.canvas().instruments().forces();
    QCOMPARE(forces.size(), std::size_t{2});
    const double weight = window.runner().world().bodies[1].mass * 9.81;
    QVERIFY(std::abs(forces[1].gravity.y() + weight) < 1e-9);
    QVERIFY(std::abs(forces[1].contactNormal.y() - weight) < 1e-3 * weight);
    // Gravity down and the floor's push up, both drawn from the box's centre.
    const QImage image = window.canvas().viewport()->grab().toImage();
    QPoint gravity;
    QPoint normal;
    const QPointF centre = window.canvas().toView(QPointF(0, 0.2));
    const int reach = static_cast<int>(weight * constants::kDefaultForceScale * window.canvas().pixelsPerMetre()) + 20;
    const QRect aroundBox(centre.toPoint() - QPoint(reach, reach), QSize(2 * reach, 2 * reach));
    QVERIFY(test::pixelsNear(image, constants::kGravityColor, &gravity, aroundBox) > 0);
    QVERIFY(test::pixelsNear(image, constants::kContactNormalColor, &normal, aroundBox) > 0);
    QVERIFY(gravity.y() > centre.y());
    QVERIFY(normal.y() < centre.y());
}

void InstrumentsTest::trailsHaveDotsAndFollowTheTimeline()
{
    MainWindow window;
    window.setScene(test::movingBallWorld(), QStringLiteral("moving"));
    QVERIFY(showActive(window));
    window.trailsAction()->trigger();
    CanvasInstruments& instruments = window.canvas().instruments();
    QVERIFY(instruments.showsTrails());
    QVERIFY(window.runner().sampleRequest().centres);
    for (int i = 0; i < 4; ++i)
        window.runner().stepBy(12); // batches, as a run shows them
    const auto& trail = instruments.trail(0);
    QCOMPARE(trail.size(), std::size_t{49}); // the start and each of 48 steps
    for (std::size_t k = 0; k < trail.size(); ++k) {
        QCOMPARE(trail[k].step, static_cast<std::int64_t>(k));
        // x = 2 m/s · t: equal spacing, as a student reads off the dots.
        QVERIFY(std::abs(trail[k].position.x() - 2.0 * static_cast<double>(k) / 240) < 1e-12);
    }
    // A dot every 24 steps (0.1 s): at steps 0, 24 and 48.
    const QImage image = window.canvas().viewport()->grab().toImage();
    const QColor dotColour = QColor(0x3b, 0x82, 0xf6).darker();
    QVERIFY(test::pixelsNear(image, dotColour) > 0);

    // Back along the timeline, the trail ends at the ball; Play from there forgets the rest.
    window.timeline().seek(30);
    window.runner().play();
    window.runner().pause();
    QCOMPARE(instruments.trail(0).size(), std::size_t{31});
}

void InstrumentsTest::graphOfAFallingBodysVyHasSlopeMinusG()
{
    MainWindow window;
    window.setScene(fallingBallWorld(), QStringLiteral("falling"));
    QVERIFY(showActive(window));
    // Select the ball, open a graph, and choose vy in its quantity box, as a user does.
    window.document().setSelection(impetus::view::Selection{{0}, {}, {}});
    window.newGraphAction()->trigger();
    QCOMPARE(window.graphPanels().size(), std::size_t{1});
    GraphPanel* graph = window.graphPanels().front();
    auto* yBox = graph->findChild<QComboBox*>(QStringLiteral("graphY"));
    QVERIFY(yBox);
    const int vy = yBox->findText(QStringLiteral("vy (m/s)"));
    QVERIFY(vy >= 0);
    yBox->setCurrentIndex(vy);
    emit yBox->activated(vy);
    QCOMPARE(graph->yQuantity(), GraphQuantity::Vy);
    QCOMPARE(graph->bodyName(), QStringLiteral("ball"));
    QVERIFY(!window.runner().sampleRequest().bodies.empty());

    // One second of running, shown in batches: every step is recorded.
    for (int i = 0; i < 24; ++i)
        window.runner().stepBy(10);
    QCOMPARE(graph->records().size(), std::size_t{241});

    const QStringList lines = test::exportedCsvRows(*graph);
    QVERIFY(!lines.isEmpty());
    QCOMPARE(lines.front(), QStringLiteral("time,body,vy"));
    QCOMPARE(lines.size(), 242);
    // Least squares over the rows: vy = a + b·t, with b = −g.
    double n = 0, st = 0, sv = 0, stt = 0, stv = 0;
    for (qsizetype i = 1; i < lines.size(); ++i) {
        const QStringList cells = lines[i].split(QLatin1Char(','));
        QCOMPARE(cells.size(), 3);
        QCOMPARE(cells[1], QStringLiteral("ball"));
        bool okT = false;
        bool okV = false;
        const double t = cells[0].toDouble(&okT);
        const double v = cells[2].toDouble(&okV);
        QVERIFY(okT && okV);
        n += 1;
        st += t;
        sv += v;
        stt += t * t;
        stv += t * v;
    }
    const double slope = (n * stv - st * sv) / (n * stt - st * st);
    const double intercept = (sv - slope * st) / n;
    QVERIFY2(std::abs(slope + 9.81) < 1e-9, qPrintable(QString::number(slope, 'g', 17)));
    QVERIFY(std::abs(intercept) < 1e-9);
}

void InstrumentsTest::graphExportsAPictureAndFollowsTheTimeline()
{
    MainWindow window;
    window.setScene(fallingBallWorld(), QStringLiteral("falling"));
    QVERIFY(showActive(window));
    GraphPanel* graph = window.addGraph(QString(), GraphQuantity::Y);
    window.runner().stepBy(240);
    QCOMPARE(graph->records().size(), std::size_t{241});
    QTemporaryDir dir;
    const QString png = dir.filePath(QStringLiteral("y.png"));
    QVERIFY(!graph->exportPng(png));
    const QImage picture(png);
    QVERIFY(!picture.isNull());
    QCOMPARE(picture.size(), graph->chartView()->size() * graph->chartView()->devicePixelRatio());

    // A phase plot from the same records: vy against y.
    graph->setQuantities(GraphQuantity::Vy, GraphQuantity::Y);
    QCOMPARE(graph->title(), QStringLiteral("vy against y of ball"));

    // Play from t = 0.5 s forgets what the graph had after it.
    window.timeline().seek(120);
    window.runner().play();
    window.runner().pause();
    QCOMPARE(graph->records().size(), std::size_t{121});
    QCOMPARE(graph->records().back().step, 120);

    // A file that cannot be written is a message, not a crash.
    const std::optional<QString> error = graph->exportCsv(dir.filePath(QStringLiteral("no/such/folder/x.csv")));
    QVERIFY(error.has_value());
}

// Issue 13: "a student can read its period off the graph to 1 ms", as docs/app.md ("Graphs")
// tells them: a graph of the bob's x against time, eleven swings, a box dragged over the first
// upward crossing of x = 0 to zoom in, the cursor on the crossing, the readout's time; the same
// ten periods later. And from the exported CSV, interpolating between the rows on either side.
void InstrumentsTest::pendulumPeriodReadOffTheGraphToAMillisecond()
{
    MainWindow window;
    QVERIFY(window.openScene(QStringLiteral(":/examples/pendulum.json")).isEmpty());
    window.resize(1100, 750);
    QVERIFY(showActive(window));
    const model::World& world = window.runner().world();
    const std::optional<model::BodyId> bob = world.findBody("bob");
    QVERIFY(bob.has_value());
    QCOMPARE(world.joints.size(), std::size_t{1});
    const impetus::Vec2 pivot = world.joints[0].anchorB;
    const impetus::Vec2 arm = world.bodies[bob->index].state.position - pivot;
    const double expected =
        impetus::testing::pendulumPeriod(arm.norm(), -world.settings.gravity.y(), std::atan2(arm.x(), -arm.y()));
    const double h = world.settings.timeStep;
    QCOMPARE(pivot.x(), 0.0); // so that the crossings of x = 0 are the bob's passes under the pivot

    window.document().setSelection(impetus::view::Selection{{static_cast<int>(bob->index)}, {}, {}});
    window.newGraphAction()->trigger();
    QCOMPARE(window.graphPanels().size(), std::size_t{1});
    GraphPanel* graph = window.graphPanels().front();
    auto* yBox = graph->findChild<QComboBox*>(QStringLiteral("graphY"));
    QVERIFY(yBox);
    const int x = yBox->findText(QStringLiteral("x (m)"));
    QVERIFY(x >= 0);
    yBox->setCurrentIndex(x);
    emit yBox->activated(x);
    QCOMPARE(graph->bodyName(), QStringLiteral("bob"));

    const int steps = static_cast<int>(std::ceil(11.3 * expected / h));
    for (int done = 0; done < steps; done += 240)
        window.runner().stepBy(std::min(240, steps - done));
    const std::vector<impetus::view::GraphRecord>& records = graph->records();
    QCOMPARE(records.size(), static_cast<std::size_t>(steps) + 1);

    // Where the curve meets the axis going up: what the student sees on the plot.
    std::vector<double> crossings;
    for (std::size_t i = 1; i < records.size(); ++i) {
        const double before = records[i - 1].body.position.x();
        const double after = records[i].body.position.x();
        if (before < 0 && after >= 0)
            crossings.push_back(records[i - 1].time + (records[i].time - records[i - 1].time) * -before / (after - before));
    }
    QVERIFY(crossings.size() >= 11);

    QChartView* view = graph->chartView();
    QChart* chart = view->chart();
    QTRY_VERIFY(view->isVisible() && !chart->plotArea().isEmpty());
    QAbstractSeries* curve = chart->series().front();
    const auto pixelOf = [&](double t, double value) {
        return view->mapFromScene(chart->mapToPosition(QPointF(t, value), curve));
    };
    auto* readout = graph->findChild<QLabel*>(QStringLiteral("graphReadout"));
    QVERIFY(readout);
    // Zoom in on a crossing with the mouse, twice (a second around it, then 60 ms), hover over
    // it, read the time; right-click back to the whole run.
    const auto dragBox = [&](const QPoint& from, const QPoint& to) {
        QTest::mousePress(view->viewport(), Qt::LeftButton, {}, from);
        QTest::mouseMove(view->viewport(), (from + to) / 2);
        QTest::mouseMove(view->viewport(), to);
        QTest::mouseRelease(view->viewport(), Qt::LeftButton, {}, to);
    };
    const auto readCrossing = [&](double crossing) -> std::optional<double> {
        dragBox(pixelOf(crossing - 0.5, 1.2), pixelOf(crossing + 0.5, -1.2));
        if (!graph->isZoomed())
            return std::nullopt;
        dragBox(pixelOf(crossing - 0.03, 0.2), pixelOf(crossing + 0.03, -0.2));
        // 60 ms across the plot now: a pixel is far less than a step.
        if (pixelOf(crossing + h, 0).x() - pixelOf(crossing, 0).x() < 5)
            return std::nullopt;
        QTest::mouseMove(view->viewport(), pixelOf(crossing, 0));
        const double time = readoutValue(readout->text(), QStringLiteral("time"));
        QTest::mouseClick(view->viewport(), Qt::RightButton, {}, pixelOf(crossing, 0));
        if (graph->isZoomed())
            return std::nullopt;
        return time;
    };
    const std::optional<double> first = readCrossing(crossings[0]);
    const std::optional<double> eleventh = readCrossing(crossings[10]);
    QVERIFY(first && eleventh);
    // The readout gives the step nearest the crossing.
    // The readout gives the step nearest the crossing (to within the cursor's pixel, 0.08 ms).
    QVERIFY2(std::abs(*first - crossings[0]) <= h / 2 + 1e-4, qPrintable(readout->text()));
    QVERIFY2(std::abs(*eleventh - crossings[10]) <= h / 2 + 1e-4, qPrintable(readout->text()));
    const double hovered = (*eleventh - *first) / 10;
    QVERIFY2(std::abs(hovered - expected) < 1e-3,
             qPrintable(QStringLiteral("%1 against %2").arg(hovered, 0, 'g', 10).arg(expected, 0, 'g', 10)));

    // From the CSV: the rows on either side of each crossing, interpolated.
    const QStringList lines = test::exportedCsvRows(*graph);
    QVERIFY(!lines.isEmpty());
    QCOMPARE(lines.front(), QStringLiteral("time,body,x"));
    std::vector<double> fromCsv;
    double lastT = 0;
    double lastX = 0;
    for (qsizetype i = 1; i < lines.size(); ++i) {
        const QStringList cells = lines[i].split(QLatin1Char(','));
        QCOMPARE(cells.size(), 3);
        const double t = cells[0].toDouble();
        const double value = cells[2].toDouble();
        if (i > 1 && lastX < 0 && value >= 0)
            fromCsv.push_back(lastT + (t - lastT) * -lastX / (value - lastX));
        lastT = t;
        lastX = value;
    }
    QVERIFY(fromCsv.size() >= 11);
    const double interpolated = (fromCsv[10] - fromCsv[0]) / 10;
    // The engine's swing keeps the large-amplitude period to a few tens of microseconds.
    QVERIFY2(std::abs(interpolated - expected) < 1e-4,
             qPrintable(QStringLiteral("%1 against %2").arg(interpolated, 0, 'g', 10).arg(expected, 0, 'g', 10)));

    // A click that slips a pixel or two is not a zoom.
    auto* timeAxis = qobject_cast<QValueAxis*>(chart->axes(Qt::Horizontal).front());
    QVERIFY(timeAxis);
    const double wholeMax = timeAxis->max();
    dragBox(pixelOf(crossings[3], 0), pixelOf(crossings[3], 0) + QPoint(2, 1));
    QVERIFY(!graph->isZoomed());
    QCOMPARE(timeAxis->max(), wholeMax);
    // A zoom stays while the run goes on; a right click shows the whole run again.
    dragBox(pixelOf(crossings[3] - 0.5, 1.2), pixelOf(crossings[3] + 0.5, -1.2));
    QVERIFY(graph->isZoomed());
    const double zoomedMin = timeAxis->min();
    const double zoomedMax = timeAxis->max();
    QVERIFY(zoomedMax - zoomedMin < 1.5);
    window.runner().stepBy(240);
    QCOMPARE(timeAxis->min(), zoomedMin);
    QCOMPARE(timeAxis->max(), zoomedMax);
    QTest::mouseClick(view->viewport(), Qt::RightButton, {}, pixelOf(crossings[3], 0));
    QVERIFY(!graph->isZoomed());
    QVERIFY(timeAxis->min() <= 0 && timeAxis->max() >= graph->records().back().time);
}

// Two graphs at once, as a teacher sets them up for the spring example (a 1 kg puck on a spring of
// k = 10 N/m to the table's centre, released 1 m out with 1.5 m/s sideways): x against time, and
// a phase plot of vx against x chosen in the second graph's boxes. Along x the puck is a harmonic
// oscillator, x = cos ωt with ω = √(k/m): the first graph is that cosine, and the phase plot the
// ellipse x² + (vx/ω)² = 1, record by record and point by point of the plotted series.
void InstrumentsTest::twoGraphsAtOnceWithAPhasePlotOfTheSpring()
{
    MainWindow window;
    QVERIFY(window.openScene(QStringLiteral(":/examples/spring.json")).isEmpty());
    window.resize(1200, 800);
    QVERIFY(showActive(window));
    const std::optional<model::BodyId> puck = window.runner().world().findBody("puck");
    QVERIFY(puck.has_value());
    const double omega = std::sqrt(10.0 / 1.0);
    window.document().setSelection(impetus::view::Selection{{static_cast<int>(puck->index)}, {}, {}});
    window.newGraphAction()->trigger();
    window.newGraphAction()->trigger();
    QCOMPARE(window.graphPanels().size(), std::size_t{2});
    GraphPanel* overTime = window.graphPanels()[0];
    GraphPanel* phase = window.graphPanels()[1];
    const auto choose = [](GraphPanel* graph, const char* box, const QString& text) {
        auto* combo = graph->findChild<QComboBox*>(QString::fromLatin1(box));
        const int at = combo ? combo->findText(text) : -1;
        if (at < 0)
            return false;
        combo->setCurrentIndex(at);
        emit combo->activated(at);
        return true;
    };
    QVERIFY(choose(overTime, "graphY", QStringLiteral("x (m)")));
    QVERIFY(choose(phase, "graphY", QStringLiteral("vx (m/s)")));
    QVERIFY(choose(phase, "graphX", QStringLiteral("x (m)")));
    QCOMPARE(phase->title(), QStringLiteral("vx against x of puck"));
    QTRY_VERIFY(overTime->chartView()->isVisible() && phase->chartView()->isVisible());

    // Two periods, 2·2π/ω = 3.97 s.
    const double h = window.runner().world().settings.timeStep;
    const int steps = static_cast<int>(std::ceil(2 * 2 * std::numbers::pi / omega / h));
    for (int done = 0; done < steps; done += 240)
        window.runner().stepBy(std::min(240, steps - done));
    QCOMPARE(overTime->records().size(), static_cast<std::size_t>(steps) + 1);
    QCOMPARE(phase->records().size(), static_cast<std::size_t>(steps) + 1);
    for (const impetus::view::GraphRecord& r : overTime->records()) {
        QVERIFY2(std::abs(impetus::view::valueOf(GraphQuantity::X, r) - std::cos(omega * r.time)) < 1e-6,
                 qPrintable(QString::number(r.time)));
    }
    // The plotted series of the phase plot: its points are (x, vx), on the ellipse.
    auto* series = qobject_cast<QXYSeries*>(phase->chartView()->chart()->series().front());
    QVERIFY(series);
    const QList<QPointF> points = series->points();
    QCOMPARE(points.size(), static_cast<qsizetype>(steps) + 1);
    double widest = 0;
    for (const QPointF& p : points) {
        const double onEllipse = p.x() * p.x() + (p.y() / omega) * (p.y() / omega);
        QVERIFY2(std::abs(onEllipse - 1) < 1e-6, qPrintable(QStringLiteral("(%1, %2)").arg(p.x()).arg(p.y())));
        widest = std::max(widest, std::abs(p.y()));
    }
    QVERIFY(std::abs(widest - omega) < 1e-3); // the vx semi-axis: ω·A
}

// A graph keeps its last hour (kMaxGraphSamples); past that, the oldest samples go in chunks of an
// eighth of it, not a few each frame (which moved the whole hour, 170 MB, at every frame). Here
// with a limit of 80 samples for the test: it grows to 90, then drops to the last 80, and what it
// keeps are the latest steps in order.
void InstrumentsTest::aFullGraphDropsItsOldestSamplesInOneGo()
{
    MainWindow window;
    window.setScene(fallingBallWorld(), QStringLiteral("falling"));
    QVERIFY(showActive(window));
    window.document().setSelection(impetus::view::Selection{{0}, {}, {}});
    window.newGraphAction()->trigger();
    GraphPanel* graph = window.graphPanels().front();
    QCOMPARE(graph->sampleLimit(), constants::kMaxGraphSamples);
    graph->setSampleLimit(80);
    const auto steps = [&] {
        std::vector<std::int64_t> taken;
        for (const impetus::view::GraphRecord& record : graph->records())
            taken.push_back(record.step);
        return taken;
    };
    window.runner().stepBy(89); // the start and 89 steps: 90 records, 80 + an eighth of 80
    QCOMPARE(graph->records().size(), std::size_t{90});
    QCOMPARE(graph->records().front().step, std::int64_t{0});
    window.runner().stepBy(1); // 91: the last 80 stay
    QCOMPARE(graph->records().size(), std::size_t{80});
    window.runner().stepBy(1); // and grow again one a step
    std::vector<std::int64_t> kept = steps();
    QCOMPARE(kept.size(), std::size_t{81});
    QCOMPARE(kept.front(), std::int64_t{11});
    QCOMPARE(kept.back(), std::int64_t{91});
    QVERIFY(std::adjacent_find(kept.begin(), kept.end(), [](auto a, auto b) { return b != a + 1; }) == kept.end());
}

void InstrumentsTest::rulerBetweenTwoClicksReadsTheDistance()
{
    MainWindow window;
    window.setScene(test::movingBallWorld(), QStringLiteral("moving"));
    QVERIFY(showActive(window));
    impetus::view::CanvasView& canvas = window.canvas();
    QWidget* viewport = canvas.viewport();
    QTest::keyClick(viewport, Qt::Key_M);
    QCOMPARE(canvas.toolKind(), impetus::view::ToolKind::Ruler);
    auto* ruler = dynamic_cast<impetus::view::RulerTool*>(canvas.tool());
    QVERIFY(ruler);
    // Two clicks a few pixels off the ball's centre and the marker's top-right corner: the ends
    // snap to them.
    const QPoint near(3, -2);
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, canvas.toView(QPointF(0, 0)).toPoint() + near);
    QVERIFY(ruler->text().isEmpty()); // the end follows the cursor until the second click
    QTest::mouseMove(viewport, canvas.toView(QPointF(1, 0.5)).toPoint());
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, canvas.toView(QPointF(2.1, 1.1)).toPoint() - near);
    QVERIFY(ruler->distance().has_value());
    const double expected = std::hypot(2.1, 1.1);
    QVERIFY(std::abs(*ruler->distance() - expected) < 1e-12);
    QCOMPARE(ruler->text(), QStringLiteral("%1 m").arg(expected, 0, 'f', 3));
    QCOMPARE(ruler->text(), QStringLiteral("2.371 m"));
    // Measuring is not an edit.
    QCOMPARE(window.document().undoStack()->count(), 0);
    QTest::keyClick(viewport, Qt::Key_Escape);
    QVERIFY(ruler->text().isEmpty());
}

void InstrumentsTest::protractorReadsTheAngle()
{
    MainWindow window;
    window.setScene(test::movingBallWorld(), QStringLiteral("moving"));
    QVERIFY(showActive(window));
    impetus::view::CanvasView& canvas = window.canvas();
    QWidget* viewport = canvas.viewport();
    QTest::keyClick(viewport, Qt::Key_A);
    auto* protractor = dynamic_cast<impetus::view::ProtractorTool*>(canvas.tool());
    QVERIFY(protractor);
    // The vertex at the ball's centre, one arm to the marker's centre, one to a free point at
    // (−1, 0.5) m: the angle between (2, 1) and (−1, 0.5).
    const QPoint free = canvas.toView(QPointF(-1, 0.5)).toPoint();
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, canvas.toView(QPointF(0, 0)).toPoint());
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, canvas.toView(QPointF(2, 1)).toPoint());
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, free);
    QVERIFY(protractor->angleDegrees().has_value());
    const QPointF armEnd = canvas.toScene(free);
    const double cross = 2 * armEnd.y() - 1 * armEnd.x();
    const double dot = 2 * armEnd.x() + 1 * armEnd.y();
    const double expected = std::atan2(std::abs(cross), dot) * 180 / 3.14159265358979323846;
    QVERIFY(std::abs(*protractor->angleDegrees() - expected) < 1e-9);
    QVERIFY(std::abs(expected - 126.87) < 1); // about 126.9° at the pixel clicked
    QCOMPARE(protractor->text(), QStringLiteral("%1°").arg(expected, 0, 'f', 1));
}

void InstrumentsTest::probeFollowsAFallingBall()
{
    MainWindow window;
    window.setScene(fallingBallOverMarkerWorld(), QStringLiteral("falling"));
    QVERIFY(showActive(window));
    window.resize(1200, 650); // room for the label to the right of the ball
    impetus::view::CanvasView& canvas = window.canvas();
    QWidget* viewport = canvas.viewport();
    QTRY_VERIFY(viewport->width() > 600);
    QTest::keyClick(viewport, Qt::Key_I);
    QCOMPARE(canvas.toolKind(), impetus::view::ToolKind::Probe);
    auto* probe = dynamic_cast<impetus::view::ProbeTool*>(canvas.tool());
    QVERIFY(probe);
    QVERIFY(probe->text().isEmpty());
    QVERIFY(probe->labelRect().isNull());

    // A click on the ball shows its readout to its right, level with it.
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, canvas.toView(QPointF(0.02, 10.03)).toPoint());
    QVERIFY(probe->body().has_value());
    QCOMPARE(probe->body()->index, 0u);
    QCOMPARE(probe->text().split(QLatin1Char('\n')).front(), QStringLiteral("ball"));
    QCOMPARE(readoutValue(probe->text(), QStringLiteral("y")), 10.0);
    QCOMPARE(readoutValue(probe->text(), QStringLiteral("vy")), 0.0);
    const QRectF before = probe->labelRect();
    const QPointF ballBefore = canvas.toView(QPointF(0, 10));
    QVERIFY(before.left() > ballBefore.x());
    QVERIFY(before.top() < ballBefore.y() && ballBefore.y() < before.bottom());
    // The label is painted there: dark text on its paper, and nothing dark there before.
    const QImage probed = viewport->grab().toImage();
    QVERIFY(test::pixelsNear(probed, constants::kMeasureColor, nullptr, before.toRect()) > 0);

    // Half a second of fall in batches, then one Step (→) as a user presses it.
    for (int i = 0; i < 7; ++i)
        window.runner().stepBy(17);
    QTest::keyClick(viewport, Qt::Key_Right);
    QTRY_COMPARE(window.runner().world().stepCount, std::int64_t{120});
    const model::Body& ball = window.runner().world().bodies[0];
    const double t = 0.5;
    // The engine's state: v = −g·t exactly under constant gravity.
    QVERIFY(std::abs(ball.state.velocity.y() + 9.81 * t) < 1e-9);
    // The label reads the engine's state, to its last digit (three decimals).
    const QString text = probe->text();
    QVERIFY2(std::abs(readoutValue(text, QStringLiteral("y")) - ball.state.position.y()) <= 5e-4, qPrintable(text));
    QVERIFY2(std::abs(readoutValue(text, QStringLiteral("vy")) - ball.state.velocity.y()) <= 5e-4, qPrintable(text));
    QCOMPARE(readoutValue(text, QStringLiteral("vy")), -4.905);
    QCOMPARE(readoutValue(text, QStringLiteral("vx")), 0.0);
    const impetus::controller::BodyReadout readout = *probe->readout();
    QVERIFY(std::abs(readout.kinetic - 0.5 * ball.mass * 4.905 * 4.905) < 1e-9);
    QVERIFY(std::abs(readoutValue(text, QStringLiteral("K")) - readout.kinetic) <= 5e-4);
    QVERIFY(std::abs(readoutValue(text, QStringLiteral("U")) - ball.mass * 9.81 * ball.state.position.y()) <= 5e-4);

    // The label went down with the ball, by as many pixels as the ball fell.
    const QRectF after = probe->labelRect();
    const double fallPx = (10 - ball.state.position.y()) * canvas.pixelsPerMetre();
    QVERIFY2(std::abs(after.top() - before.top() - fallPx) < 1.0,
             qPrintable(QStringLiteral("%1 -> %2, %3 px").arg(before.top()).arg(after.top()).arg(fallPx)));
    QVERIFY(test::pixelsNear(viewport->grab().toImage(), constants::kMeasureColor, nullptr, after.toRect()) > 0);

    // Scrubbed back along the timeline, the label reads the state there.
    window.timeline().seek(24);
    QCOMPARE(readoutValue(probe->text(), QStringLiteral("vy")), -0.981);
    QVERIFY(std::abs(probe->labelRect().top() - before.top() - 0.5 * 9.81 * 0.01 * canvas.pixelsPerMetre()) < 1.0);

    // Esc removes it; so does a second click on the ball, or a click on empty space. A click on
    // another body reads that one instead. None of it is an edit (the Step above is one).
    const int edits = window.document().undoStack()->count();
    QTest::keyClick(viewport, Qt::Key_Escape);
    QVERIFY(probe->text().isEmpty());
    QVERIFY(probe->labelRect().isNull());
    const QPoint ballNow = canvas.toView(impetus::view::toQPointF(window.runner().world().bodies[0].state.position)).toPoint();
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, ballNow);
    QVERIFY(probe->body().has_value());
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, ballNow);
    QVERIFY(!probe->body().has_value());
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, canvas.toView(QPointF(0, 0)).toPoint());
    QCOMPARE(probe->text().split(QLatin1Char('\n')).front(), QStringLiteral("marker (fixed)"));
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, canvas.toView(QPointF(0.5, 5)).toPoint());
    QVERIFY(probe->text().isEmpty());
    QCOMPARE(window.document().undoStack()->count(), edits);
}

void InstrumentsTest::velocityVectorsOfOneBodyFromThePane()
{
    // Two balls moving alike, one above the other, no gravity.
    model::World world = test::movingBallWorld();
    model::Body upper = test::makeBody("upper", model::Circle{0.1}, impetus::Vec2(0, 1.5));
    upper.state.velocity = impetus::Vec2(2, 0);
    world.bodies.push_back(upper);
    MainWindow window;
    window.setScene(world, QStringLiteral("two balls"));
    QVERIFY(showActive(window));
    impetus::view::CanvasView& canvas = window.canvas();
    const double arrowPx = 2 * constants::kDefaultVelocityScale * canvas.pixelsPerMetre();
    const auto around = [&](const QPointF& centre) {
        const QPoint c = canvas.toView(centre).toPoint();
        const int reach = static_cast<int>(1.5 * arrowPx);
        return QRect(c - QPoint(reach / 3, reach / 3), QSize(reach, reach / 3 * 2));
    };
    QVERIFY(!around(QPointF(0, 0)).intersects(around(QPointF(0, 1.5))));

    // Click the lower ball with the select tool; the pane shows it, with no arrows ticked.
    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, Qt::NoModifier, canvas.toView(QPointF(0, 0)).toPoint());
    QCOMPARE(window.document().selection().bodies, std::vector<int>{0});
    auto* velocity = window.propertyPane()->findChild<QCheckBox*>(QStringLiteral("bodyVelocityVectors"));
    QVERIFY(velocity);
    QVERIFY(velocity->isVisible());
    QVERIFY(!velocity->isChecked());
    // Tick its velocity box, on the box itself.
    // The group is at the bottom of the body's attributes: scroll down to it, as a user does.
    auto* scroll = window.propertyPane()->findChild<QScrollArea*>();
    QVERIFY(scroll);
    QTRY_VERIFY(velocity->height() > 0); // laid out once the event loop has run
    scroll->ensureWidgetVisible(velocity);
    QTRY_VERIFY(!velocity->visibleRegion().isEmpty());
    const int half = velocity->height() / 2;
    QTest::mouseClick(velocity, Qt::LeftButton, Qt::NoModifier, QPoint(half, half));
    QVERIFY(velocity->isChecked());
    QVERIFY(canvas.instruments().showsBodyVector("ball", VectorKind::Velocity));
    QVERIFY(!canvas.instruments().showsVector(VectorKind::Velocity)); // the View menu's stays off

    // An arrow on that ball only, and the legend gives its scale.
    QImage image = canvas.viewport()->grab().toImage();
    QVERIFY2(test::pixelsNear(image, constants::kVelocityColor, nullptr, around(QPointF(0, 0))) > arrowPx / 2,
             qPrintable(QStringLiteral("%1 px").arg(arrowPx)));
    QCOMPARE(test::pixelsNear(image, constants::kVelocityColor, nullptr, around(QPointF(0, 1.5))), 0);
    QCOMPARE(canvas.instruments().legendLines(), QStringList{QStringLiteral("velocity: 1 m/s = 0.25 m")});
    // The arrow moves with the ball.
    window.runner().stepBy(24);
    image = canvas.viewport()->grab().toImage();
    QVERIFY(test::pixelsNear(image, constants::kVelocityColor, nullptr, around(QPointF(0.2, 0))) > arrowPx / 2);
    QCOMPARE(test::pixelsNear(image, constants::kVelocityColor, nullptr, around(QPointF(0.2, 1.5))), 0);

    // The other ball's box is not ticked; back on the first, it is.
    window.document().setSelection(impetus::view::Selection{{2}, {}, {}});
    QVERIFY(!velocity->isChecked());
    window.document().setSelection(impetus::view::Selection{{0}, {}, {}});
    QVERIFY(velocity->isChecked());
    // A view setting, not an edit.
    QCOMPARE(window.document().undoStack()->count(), 0);

    // Cleared, the arrow goes.
    QTest::mouseClick(velocity, Qt::LeftButton, Qt::NoModifier, QPoint(half, half));
    QVERIFY(!canvas.instruments().showsBodyVector("ball", VectorKind::Velocity));
    QCOMPARE(test::pixelsNear(canvas.viewport()->grab().toImage(), constants::kVelocityColor), 0);
}

// View › Acceleration, Net Force and Momentum, as a user toggles them: each arrow is found in a
// grab, in its own colour, below a ½ kg ball falling freely (a = g, F = m·g, p = m·v all point
// down), as long as the legend's scale makes it, and it goes when toggled off.
void InstrumentsTest::accelerationForceAndMomentumArrowsPointAlongTheirVectors()
{
    model::World world;
    world.settings.gravity = impetus::Vec2(0, -9.81);
    model::Body ball = test::makeBody("ball", model::Circle{0.1}, impetus::Vec2(0, 10));
    ball.massSpec = {model::MassMode::Mass, 0.5};
    ball.updateDerived();
    world.bodies.push_back(ball);
    // Two fixed markers that frame the view, well away from the arrows.
    world.bodies.push_back(test::makeBody("left", model::Box{0.2, 0.2}, impetus::Vec2(-3, 5), true));
    world.bodies.push_back(test::makeBody("right", model::Box{0.2, 0.2}, impetus::Vec2(3, 11), true));
    MainWindow window;
    window.setScene(world, QStringLiteral("falling"));
    QVERIFY(showActive(window));
    window.runner().stepBy(120); // half a second of fall: v = −4.905 m/s, p = −2.4525 kg·m/s
    impetus::view::CanvasView& canvas = window.canvas();
    const model::Body& now = window.runner().world().bodies[0];
    QVERIFY(std::abs(now.state.velocity.y() + 4.905) < 1e-9);

    struct Arrow {
        VectorKind kind;
        QColor colour;
        double lengthM; // the arrow's length on the canvas, m
    };
    const Arrow arrows[] = {
        {VectorKind::Acceleration, constants::kAccelerationColor, 9.81 * constants::kDefaultAccelerationScale},
        {VectorKind::NetForce, constants::kNetForceColor, 0.5 * 9.81 * constants::kDefaultForceScale},
        {VectorKind::Momentum, constants::kMomentumColor, 0.5 * 4.905 * constants::kDefaultMomentumScale},
    };
    for (const Arrow& arrow : arrows) {
        const QPointF centre = canvas.toView(QPointF(now.state.position.x(), now.state.position.y()));
        const double lengthPx = arrow.lengthM * canvas.pixelsPerMetre();
        const int reach = static_cast<int>(lengthPx) + 20;
        const QRect around(centre.toPoint() - QPoint(reach, reach), QSize(2 * reach, 2 * reach));
        QCOMPARE(test::pixelsNear(canvas.viewport()->grab().toImage(), arrow.colour, nullptr, around), 0);
        window.vectorAction(arrow.kind)->trigger();
        QVERIFY(canvas.instruments().showsVector(arrow.kind));
        QPoint centroid;
        const int pixels = test::pixelsNear(canvas.viewport()->grab().toImage(), arrow.colour, &centroid, around);
        const QString what = QStringLiteral("kind %1: %2 px, centroid (%3, %4), ball (%5, %6), length %7 px")
                                 .arg(static_cast<int>(arrow.kind))
                                 .arg(pixels)
                                 .arg(centroid.x())
                                 .arg(centroid.y())
                                 .arg(centre.x())
                                 .arg(centre.y())
                                 .arg(lengthPx);
        QVERIFY2(pixels > lengthPx, qPrintable(what));
        // Straight down from the ball (screen y grows downwards), about half its length below.
        QVERIFY2(std::abs(centroid.x() - centre.x()) < 0.15 * lengthPx, qPrintable(what));
        QVERIFY2(centroid.y() > centre.y() + 0.3 * lengthPx && centroid.y() < centre.y() + 0.8 * lengthPx,
                 qPrintable(what));
        window.vectorAction(arrow.kind)->trigger();
        QCOMPARE(test::pixelsNear(canvas.viewport()->grab().toImage(), arrow.colour, nullptr, around), 0);
    }
}

// Trace Point (X), as a user traces a wheel's rim: a ball sent along at v and spinning at
// ω = −v/r, as a wheel rolls, in zero gravity; a click on its rim fixes the point there; after a
// second of running the point's path is the cycloid x = vt − r·sin(vt/r), y = −r·cos(vt/r) about
// the starting centre (for the point at the bottom; in general c(t) + R(ωt)·p), step by step,
// drawn in its colour; a click on the point stops tracing it, and Esc stops them all.
void InstrumentsTest::tracePointDrawsACycloid()
{
    const double v = 2;   // m/s
    const double r = 0.5; // m
    model::World world;
    world.settings.gravity = impetus::Vec2::Zero();
    model::Body wheel = test::makeBody("wheel", model::Circle{r}, impetus::Vec2(0, 0));
    wheel.state.velocity = impetus::Vec2(v, 0);
    wheel.state.angularVelocity = -v / r;
    world.bodies.push_back(wheel);
    world.bodies.push_back(test::makeBody("marker", model::Box{0.2, 0.2}, impetus::Vec2(3, 1.5), true));
    MainWindow window;
    window.setScene(world, QStringLiteral("wheel"));
    QVERIFY(showActive(window));
    impetus::view::CanvasView& canvas = window.canvas();
    QWidget* viewport = canvas.viewport();
    CanvasInstruments& instruments = canvas.instruments();
    QVERIFY(!window.runner().sampleRequest().centres);

    QTest::keyClick(viewport, Qt::Key_X);
    QVERIFY(dynamic_cast<impetus::view::TracePointTool*>(canvas.tool()));
    // Just inside the rim, at the bottom.
    QTest::mouseClick(viewport, Qt::LeftButton, {}, canvas.toView(QPointF(0, -0.95 * r)).toPoint());
    QCOMPARE(instruments.tracedPoints().size(), std::size_t{1});
    const impetus::Vec2 local = instruments.tracedPoints().front().local;
    const double pixel = 1 / canvas.pixelsPerMetre();
    QVERIFY2((local - impetus::Vec2(0, -0.95 * r)).norm() < pixel,
             qPrintable(QStringLiteral("(%1, %2)").arg(local.x()).arg(local.y())));
    QVERIFY(window.runner().sampleRequest().centres); // the steps are recorded for it

    const double h = window.runner().world().settings.timeStep;
    for (int i = 0; i < 24; ++i)
        window.runner().stepBy(10);
    const std::deque<impetus::view::TrailPoint>& path = instruments.tracedPoints().front().trail;
    QCOMPARE(path.size(), std::size_t{241}); // where it was clicked, and after each of 240 steps
    for (std::size_t k = 0; k < path.size(); ++k) {
        const double t = static_cast<double>(k) * h;
        const double turn = -v / r * t;
        // c(t) + R(ωt)·p: for p = (0, −r) the cycloid (vt − r·sin(vt/r), −r·cos(vt/r)).
        const impetus::Vec2 expected = impetus::Vec2(v * t, 0) + impetus::rotate(local, turn);
        QCOMPARE(path[k].step, static_cast<std::int64_t>(k));
        QVERIFY2(std::abs(path[k].position.x() - expected.x()) < 1e-9 &&
                     std::abs(path[k].position.y() - expected.y()) < 1e-9,
                 qPrintable(QStringLiteral("step %1: (%2, %3) against (%4, %5)")
                                .arg(k)
                                .arg(path[k].position.x())
                                .arg(path[k].position.y())
                                .arg(expected.x())
                                .arg(expected.y())));
    }
    // The arch's top: half a turn in, the point is at the top of the wheel, 2·0.95·r above where it began.
    const std::size_t half = static_cast<std::size_t>(std::llround(std::numbers::pi * r / v / h));
    QVERIFY(std::abs(path[half].position.y() - 0.95 * r) < 0.01);

    // Drawn: the path in its colour, on the canvas.
    // A one-pixel antialiased line: its pixels are the colour laid over the paper at some coverage.
    const QImage drawn = viewport->grab().toImage();
    const QColor paper = drawn.pixelColor(2, drawn.height() / 2);
    const auto tinted = [&](const QImage& image) {
        int count = 0;
        const QColor ink = constants::kTracedPointColor;
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x) {
                const QColor c = image.pixelColor(x, y);
                // c = paper + a·(ink − paper) for one a in [0.3, 1], channel by channel, within 12.
                const double a = static_cast<double>(c.green() - paper.green()) / (ink.green() - paper.green());
                if (a < 0.3 || a > 1.05)
                    continue;
                const auto off = [&](int p, int i, int seen) { return std::abs(p + a * (i - p) - seen); };
                if (off(paper.red(), ink.red(), c.red()) < 12 && off(paper.blue(), ink.blue(), c.blue()) < 12)
                    ++count;
            }
        }
        return count;
    };
    QVERIFY2(tinted(drawn) > 100, qPrintable(QString::number(tinted(drawn))));

    // Back on the timeline and Play from there: the path forgets what came after.
    window.timeline().seek(120);
    window.runner().play();
    window.runner().pause();
    QCOMPARE(instruments.tracedPoints().front().trail.back().step, 120);

    // A click on the traced point stops tracing it; a new one and Esc, all.
    const impetus::Vec2 now = instruments.worldPoint(0, local);
    QTest::mouseClick(viewport, Qt::LeftButton, {}, canvas.toView(QPointF(now.x(), now.y())).toPoint());
    QVERIFY(instruments.tracedPoints().empty());
    QVERIFY(!window.runner().sampleRequest().centres);
    const impetus::Vec2 centre = window.runner().world().bodies[0].state.position;
    QTest::mouseClick(viewport, Qt::LeftButton, {}, canvas.toView(QPointF(centre.x() + 0.3, centre.y())).toPoint());
    QCOMPARE(instruments.tracedPoints().size(), std::size_t{1});
    QTest::keyClick(viewport, Qt::Key_Escape);
    QVERIFY(instruments.tracedPoints().empty());
    QCOMPARE(tinted(viewport->grab().toImage()), 0);
}

// A student traces a wheel's rim and draws trails, then deletes another body (and takes it back
// with Undo): the wheel's index changes each time, but its trail and its traced point stay its
// own; the body that comes back starts a trail where it is.
void InstrumentsTest::pathsStayWithTheirBodiesWhenABodyIsDeletedOrBack()
{
    MainWindow window;
    window.setScene(blockAndWheelWorld(1), QStringLiteral("wheel"));
    QVERIFY(showActive(window));
    impetus::view::CanvasView& canvas = window.canvas();
    QWidget* viewport = canvas.viewport();
    CanvasInstruments& instruments = canvas.instruments();
    traceTheWheelFor24Steps(window);
    if (QTest::currentTestFailed())
        return;
    const QPointF wheelStart = instruments.trail(1).front().position;
    const QPointF tracedStart = instruments.tracedPoints().front().trail.front().position;
    QCOMPARE(wheelStart, QPointF(2, 0));

    // Select the block and delete it: the wheel is body 0 now, with its paths.
    QTest::keyClick(viewport, Qt::Key_S);
    const impetus::Vec2 blockNow = window.runner().world().bodies[0].state.position;
    QTest::mouseClick(viewport, Qt::LeftButton, {}, canvas.toView(QPointF(blockNow.x(), blockNow.y())).toPoint());
    QCOMPARE(window.document().selection(), (impetus::view::Selection{{0}, {}, {}}));
    QTest::keyClick(&canvas, Qt::Key_Delete);
    QCOMPARE(window.runner().world().bodies.size(), std::size_t{1});
    QCOMPARE(instruments.trail(0).size(), std::size_t{25});
    QCOMPARE(instruments.trail(0).front().position, wheelStart);
    QCOMPARE(instruments.tracedPoints().size(), std::size_t{1});
    QCOMPARE(instruments.tracedPoints().front().body, 0u);
    QCOMPARE(instruments.tracedPoints().front().trail.size(), std::size_t{25});
    QCOMPARE(instruments.tracedPoints().front().trail.front().position, tracedStart);

    // Undo: the block is back as body 0 with a trail that starts where it is; the wheel is body 1
    // again, and both its paths go on growing with the next steps.
    QTest::keyClick(&canvas, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(window.runner().world().bodies.size(), std::size_t{2});
    QCOMPARE(instruments.trail(0).size(), std::size_t{1});
    QCOMPARE(instruments.trail(1).front().position, wheelStart);
    QCOMPARE(instruments.tracedPoints().front().body, 1u);
    window.runner().stepBy(12);
    QCOMPARE(instruments.trail(1).size(), std::size_t{37});
    QCOMPARE(instruments.tracedPoints().front().trail.size(), std::size_t{37});
    QCOMPARE(instruments.trail(0).size(), std::size_t{13});
}

void InstrumentsTest::pathsStayWithABodyRenamedInThePane()
{
    MainWindow window;
    window.setScene(blockAndWheelWorld(0), QStringLiteral("wheel"));
    QVERIFY(showActive(window));
    impetus::view::CanvasView& canvas = window.canvas();
    QWidget* viewport = canvas.viewport();
    CanvasInstruments& instruments = canvas.instruments();
    traceTheWheelFor24Steps(window);
    if (QTest::currentTestFailed())
        return;
    const QPointF tracedStart = instruments.tracedPoints().front().trail.front().position;

    // Select the wheel where it is now and rename it in the pane.
    QTest::keyClick(viewport, Qt::Key_S);
    const impetus::Vec2 wheelNow = window.runner().world().bodies[1].state.position;
    QTest::mouseClick(viewport, Qt::LeftButton, {}, canvas.toView(QPointF(wheelNow.x(), wheelNow.y())).toPoint());
    QCOMPARE(window.document().selection(), (impetus::view::Selection{{1}, {}, {}}));
    // The wheel's own velocity arrow, ticked in the pane (kept by name).
    auto* velocity = window.propertyPane()->findChild<QCheckBox*>(QStringLiteral("bodyVelocityVectors"));
    QVERIFY(velocity);
    velocity->click();
    QVERIFY(instruments.showsBodyVector("wheel", VectorKind::Velocity));
    auto* name = window.propertyPane()->findChild<QLineEdit*>(QStringLiteral("name"));
    QVERIFY(name);
    name->setFocus();
    QTest::keyClick(name, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(name, QStringLiteral("disc"));
    QTest::keyClick(name, Qt::Key_Return);
    QCOMPARE(window.runner().world().bodies[1].name, std::string("disc"));
    // Its arrow stays, under its new name, and its box in the pane stays ticked.
    QVERIFY(instruments.showsBodyVector("disc", VectorKind::Velocity));
    QVERIFY(!instruments.showsBodyVector("wheel", VectorKind::Velocity));
    QTRY_VERIFY(velocity->isChecked());

    // Its trail and traced point are still there, from the same start, and grow on; the block's
    // trail is untouched.
    QCOMPARE(instruments.trail(1).size(), std::size_t{25});
    QCOMPARE(instruments.trail(1).front().position, QPointF(2, 0));
    QCOMPARE(instruments.tracedPoints().size(), std::size_t{1});
    QCOMPARE(instruments.tracedPoints().front().body, 1u);
    QCOMPARE(instruments.tracedPoints().front().trail.front().position, tracedStart);
    window.runner().stepBy(12);
    QCOMPARE(instruments.trail(1).size(), std::size_t{37});
    QCOMPARE(instruments.tracedPoints().front().trail.size(), std::size_t{37});
    QCOMPARE(instruments.trail(0).size(), std::size_t{37});

    // Undo gives the wheel its name back, and the paths stay with it again.
    QTest::keyClick(&canvas, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(window.runner().world().bodies[1].name, std::string("wheel"));
    QCOMPARE(instruments.trail(1).size(), std::size_t{37});
    QCOMPARE(instruments.tracedPoints().size(), std::size_t{1});
}

// The wheel is deleted and a box drawn in its place (the last index), then Reset brings the wheel
// back where the box was: one name changed at one index, as in a rename, but another kind of body
// stands there. The wheel starts a fresh trail; it does not take over the box's.
void InstrumentsTest::aBodyDrawnInADeletedOnesPlaceGetsNoOtherPathsOnReset()
{
    MainWindow window;
    window.setScene(blockAndWheelWorld(0), QStringLiteral("wheel"));
    QVERIFY(showActive(window));
    impetus::view::CanvasView& canvas = window.canvas();
    QWidget* viewport = canvas.viewport();
    CanvasInstruments& instruments = canvas.instruments();
    window.trailsAction()->trigger();
    // Play and pause at once: Reset comes back to here.
    window.playAction()->trigger();
    window.playAction()->trigger();
    QVERIFY(!window.runner().isRunning());
    const std::size_t before = instruments.trail(1).size();
    window.runner().stepBy(24);
    QCOMPARE(instruments.trail(1).size(), before + 24);

    QTest::keyClick(viewport, Qt::Key_S);
    const impetus::Vec2 wheelNow = window.runner().world().bodies[1].state.position;
    QTest::mouseClick(viewport, Qt::LeftButton, {}, canvas.toView(QPointF(wheelNow.x(), wheelNow.y())).toPoint());
    QTest::keyClick(&canvas, Qt::Key_Delete);
    QCOMPARE(window.runner().world().bodies.size(), std::size_t{1});
    QTest::keyClick(&canvas, Qt::Key_B);
    const QPoint from = canvas.toView(QPointF(0.5, 2.5)).toPoint();
    const QPoint to = canvas.toView(QPointF(1.5, 1.5)).toPoint();
    QTest::mousePress(viewport, Qt::LeftButton, {}, from);
    QTest::mouseMove(viewport, (from + to) / 2);
    QTest::mouseMove(viewport, to);
    QTest::mouseRelease(viewport, Qt::LeftButton, {}, to);
    QCOMPARE(window.runner().world().bodies.size(), std::size_t{2});
    QVERIFY(window.runner().world().bodies[1].name != "wheel");
    window.runner().stepBy(12);
    QCOMPARE(instruments.trail(1).size(), std::size_t{13});

    window.resetAction()->trigger();
    QCOMPARE(window.runner().world().bodies.size(), std::size_t{2});
    QCOMPARE(window.runner().world().bodies[1].name, std::string("wheel"));
    QCOMPARE(window.runner().world().bodies[1].state.position, impetus::Vec2(2, 0));
    // A fresh trail where the wheel stands, not the box's 13 points from (1, 2).
    QCOMPARE(instruments.trail(1).size(), std::size_t{1});
    QCOMPARE(instruments.trail(1).front().position, QPointF(2, 0));
}

void InstrumentsTest::toolsAndRunControlsHaveIconsAndShortcutTips()
{
    using impetus::view::ToolKind;
    MainWindow window;
    QVERIFY(showActive(window));
    // A drawing, not an empty or missing file: some opaque pixels in a 24 px rendering.
    const auto drawn = [](const QIcon& icon) {
        if (icon.isNull())
            return QImage();
        const QImage image = icon.pixmap(QSize(24, 24)).toImage();
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x) {
                if (qAlpha(image.pixel(x, y)) > 128)
                    return image;
            }
        }
        return QImage();
    };
    std::set<QByteArray> drawings;
    const auto distinct = [&](const QImage& image) {
        const QByteArray bytes(reinterpret_cast<const char*>(image.constBits()), image.sizeInBytes());
        return drawings.insert(bytes).second;
    };
    auto* toolBar = window.findChild<QToolBar*>(QStringLiteral("drawingTools"));
    QVERIFY(toolBar);
    QCOMPARE(toolBar->toolButtonStyle(), Qt::ToolButtonIconOnly);
    const ToolKind kinds[] = {ToolKind::Select, ToolKind::Rotate, ToolKind::Polygon, ToolKind::Box,
                              ToolKind::Circle, ToolKind::Ellipse, ToolKind::Spring, ToolKind::Pin,
                              ToolKind::Rod, ToolKind::Ruler, ToolKind::Protractor, ToolKind::Probe,
                              ToolKind::TracePoint};
    for (const ToolKind kind : kinds) {
        QAction* action = window.toolAction(kind);
        const QImage image = drawn(action->icon());
        QVERIFY2(!image.isNull(), qPrintable(action->text()));
        QVERIFY2(distinct(image), qPrintable(action->text()));
        const QString key = action->shortcut().toString(QKeySequence::NativeText);
        QVERIFY(!key.isEmpty());
        QVERIFY2(action->toolTip().contains(QStringLiteral("(%1)").arg(key)), qPrintable(action->toolTip()));
        // The tool bar's button shows the icon alone, and answers to the shortcut.
        auto* button = qobject_cast<QToolButton*>(toolBar->widgetForAction(action));
        QVERIFY(button);
        QVERIFY(!button->icon().isNull());
        QCOMPARE(button->toolButtonStyle(), Qt::ToolButtonIconOnly);
        QTest::keyClick(window.canvas().viewport(), action->shortcut()[0].key());
        QCOMPARE(window.canvas().toolKind(), kind);
    }

    // The run controls: Play, Step Back, Step and Reset, and Pause while running.
    const std::pair<QAction*, QString> controls[] = {{window.playAction(), QStringLiteral("(Space)")},
                                                     {window.stepBackAction(), QStringLiteral("(←)")},
                                                     {window.stepAction(), QStringLiteral("(→)")},
                                                     {window.resetAction(), QStringLiteral("(R)")}};
    for (const auto& [action, key] : controls) {
        QVERIFY2(!drawn(action->icon()).isNull(), qPrintable(action->text()));
        QVERIFY2(distinct(drawn(action->icon())), qPrintable(action->text()));
        QVERIFY2(action->toolTip().contains(key), qPrintable(action->toolTip()));
    }
    window.playAction()->trigger();
    QCOMPARE(window.playAction()->text(), QStringLiteral("Pause"));
    QVERIFY(distinct(drawn(window.playAction()->icon())));
    QVERIFY(window.playAction()->toolTip().contains(QStringLiteral("(Space)")));
    window.playAction()->trigger();
}

QTEST_MAIN(InstrumentsTest)
#include "instruments_test.moc"
