// CanvasView: one item per body and spring, y up on screen, counter-clockwise angles, framing.

#include "test_worlds.h"
#include "view/body_item.h"
#include "view/canvas_view.h"
#include "view/screenshot.h"
#include "view/simulation_runner.h"
#include "view/spring_item.h"
#include "view/view_constants.h"

#include <QImage>
#include <QTest>

#include <cmath>
#include <numbers>
#include <optional>
#include <type_traits>

using impetus::view::BodyItem;
using impetus::view::CanvasView;
using impetus::view::SimulationRunner;
namespace model = impetus::model;
namespace test = impetus::view::test;

namespace {

// One precision (DESIGN.md): the view's tuning constants are doubles too, no `f` literals.
static_assert(std::is_same_v<decltype(impetus::view::constants::kPreviewFillAlpha), const double>);
static_assert(std::is_same_v<decltype(impetus::view::constants::kRubberBandFillAlpha), const double>);

/// Mean row of the pixels that are clearly pure red (the rising ball's fill), if any.
std::optional<double> meanRedRow(const QImage& image)
{
    double sum = 0;
    int count = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (c.red() > 220 && c.green() < 40 && c.blue() < 40) {
                sum += y;
                ++count;
            }
        }
    }
    if (count == 0)
        return std::nullopt;
    return sum / count;
}

} // namespace

class CanvasViewTest : public QObject {
    Q_OBJECT

private slots:
    void makesOneItemPerBodyAndSpring();
    void higherBodyIsHigherOnScreen();
    void bodyMovingUpGoesUpOnScreen();
    void counterClockwiseAngleShowsCounterClockwise();
    void framesAllBodiesKeepingAspect();
    void concavePolygonIsDrawnAsItsOutline();
    void screenshotHasExactSizeAndYUp();
};

void CanvasViewTest::makesOneItemPerBodyAndSpring()
{
    SimulationRunner runner;
    CanvasView canvas(runner);
    QCOMPARE(canvas.bodyItems().size(), std::size_t(0));
    runner.setWorld(test::hangingBoxWorld());
    QCOMPARE(canvas.bodyItems().size(), std::size_t(2));
    QCOMPARE(canvas.springItems().size(), std::size_t(1));
    QCOMPARE(canvas.bodyItem(model::BodyId{1})->bodyId().index, 1u);
    QCOMPARE(canvas.bodyItem(model::BodyId{2}), nullptr);
    // Items sit at the centres of mass.
    QCOMPARE(canvas.bodyItems()[0]->scenePos(), QPointF(0.3, 1.0));
}

void CanvasViewTest::higherBodyIsHigherOnScreen()
{
    SimulationRunner runner;
    runner.setWorld(test::risingBallWorld());
    CanvasView canvas(runner);
    canvas.resize(400, 300);
    canvas.show();
    QVERIFY(QTest::qWaitForWindowExposed(&canvas));

    const QPoint ball = canvas.mapFromScene(canvas.bodyItems()[0]->scenePos());
    const QPoint marker = canvas.mapFromScene(canvas.bodyItems()[1]->scenePos());
    // The marker is 2 m above the ball in the world, so it is drawn above it (smaller y).
    QVERIFY2(marker.y() < ball.y(), qPrintable(QStringLiteral("marker %1, ball %2").arg(marker.y()).arg(ball.y())));
    QCOMPARE(marker.x(), ball.x());
}

void CanvasViewTest::bodyMovingUpGoesUpOnScreen()
{
    SimulationRunner runner;
    runner.setWorld(test::risingBallWorld());
    CanvasView canvas(runner);
    canvas.resize(400, 300);
    canvas.show();
    QVERIFY(QTest::qWaitForWindowExposed(&canvas));

    BodyItem* ball = canvas.bodyItems()[0];
    const QPoint before = canvas.mapFromScene(ball->scenePos());
    const std::optional<double> rowBefore = meanRedRow(canvas.grab().toImage());
    QVERIFY(rowBefore.has_value());

    runner.stepBy(120); // 0.5 s at 1 m/s upwards
    QVERIFY(qAbs(runner.world().bodies[0].state.position.y() - 0.5) < 1e-9);

    const QPoint after = canvas.mapFromScene(ball->scenePos());
    QVERIFY2(after.y() < before.y(), qPrintable(QStringLiteral("%1 -> %2").arg(before.y()).arg(after.y())));
    QCOMPARE(after.x(), before.x());

    // What the user sees: the red ball's pixels moved up by 0.5 m worth of pixels.
    const std::optional<double> rowAfter = meanRedRow(canvas.grab().toImage());
    QVERIFY(rowAfter.has_value());
    const double expectedShift = 0.5 * canvas.pixelsPerMetre();
    QVERIFY2(qAbs((*rowBefore - *rowAfter) - expectedShift) < 1.5,
             qPrintable(QStringLiteral("moved %1 px up, expected %2").arg(*rowBefore - *rowAfter).arg(expectedShift)));
}

void CanvasViewTest::counterClockwiseAngleShowsCounterClockwise()
{
    model::World world = test::risingBallWorld();
    world.bodies[1].state.angle = std::numbers::pi / 2;
    SimulationRunner runner;
    runner.setWorld(world);
    CanvasView canvas(runner);
    canvas.resize(400, 300);
    canvas.show();
    QVERIFY(QTest::qWaitForWindowExposed(&canvas));

    // Turned a quarter turn counter-clockwise, the body's +x axis points along world +y...
    const BodyItem* box = canvas.bodyItems()[1];
    const QPointF tip = box->mapToScene(QPointF(0.1, 0));
    QVERIFY(qAbs(tip.x() - 0.0) < 1e-12);
    QVERIFY(qAbs(tip.y() - 2.1) < 1e-12);
    // ...which is straight up on screen: counter-clockwise from +x (right) as the user sees it.
    const QPointF centreOnScreen = canvas.mapFromScene(box->scenePos());
    const QPointF tipOnScreen = canvas.mapFromScene(tip);
    QVERIFY(tipOnScreen.y() < centreOnScreen.y());
    QCOMPARE(tipOnScreen.x(), centreOnScreen.x());
    // And the item follows the model's own worldPoint().
    const impetus::Vec2 modelTip = runner.world().bodies[1].worldPoint(impetus::Vec2(0.1, 0));
    QVERIFY(qAbs(modelTip.y() - tip.y()) < 1e-12);
}

void CanvasViewTest::framesAllBodiesKeepingAspect()
{
    SimulationRunner runner;
    runner.setWorld(test::hangingBoxWorld());
    CanvasView canvas(runner);
    canvas.resize(640, 200); // much wider than the scene
    canvas.show();
    QVERIFY(QTest::qWaitForWindowExposed(&canvas));

    const QTransform t = canvas.transform();
    QCOMPARE(t.m22(), -t.m11()); // same scale both ways, y flipped
    QVERIFY(t.m11() > 0);
    const QRectF visible = canvas.mapToScene(canvas.viewport()->rect()).boundingRect();
    for (const BodyItem* item : canvas.bodyItems())
        QVERIFY(visible.contains(item->sceneBoundingRect()));
    QVERIFY(visible.contains(QPointF(0, 2))); // the spring's world anchor
    // The tight direction (height) is filled: the frame is not needlessly small.
    QVERIFY(canvas.frameRect().height() * canvas.pixelsPerMetre() > 0.95 * 200);
}

void CanvasViewTest::concavePolygonIsDrawnAsItsOutline()
{
    model::World world;
    // An L: the notch at the top right is outside the body.
    world.bodies.push_back(test::makeBody(
        "L",
        model::Polygon{{impetus::Vec2(0, 0), impetus::Vec2(2, 0), impetus::Vec2(2, 1), impetus::Vec2(1, 1),
                        impetus::Vec2(1, 2), impetus::Vec2(0, 2)}},
        impetus::Vec2(0, 0)));
    QVERIFY(world.bodies[0].geometry.convexPieces.size() >= 2);
    SimulationRunner runner;
    runner.setWorld(world);
    CanvasView canvas(runner);

    const BodyItem* item = canvas.bodyItems()[0];
    const impetus::Vec2 offset = world.bodies[0].geometry.centroidOffset;
    const auto local = [&](double x, double y) { return QPointF(x - offset.x(), y - offset.y()); };
    QVERIFY(item->shape().contains(local(0.5, 1.5)));
    QVERIFY(item->shape().contains(local(1.5, 0.5)));
    QVERIFY(!item->shape().contains(local(1.5, 1.5)));
    // One closed outline (6 corners + back to the start), not one path per convex piece.
    QCOMPARE(item->shape().toSubpathPolygons().size(), 1);
    QCOMPARE(item->shape().toSubpathPolygons().at(0).size(), 7);
}

void CanvasViewTest::screenshotHasExactSizeAndYUp()
{
    SimulationRunner runner;
    runner.setWorld(test::risingBallWorld());
    CanvasView canvas(runner);
    const QImage before = impetus::view::renderCanvasImage(canvas, QSize(320, 240));
    QCOMPARE(before.size(), QSize(320, 240));
    const QRectF framed = canvas.frameRect();
    runner.stepBy(120);
    const QImage after = impetus::view::renderCanvasImage(canvas, QSize(320, 240));
    QCOMPARE(after.size(), QSize(320, 240));
    // Still the load-time framing, as in the window.
    QCOMPARE(canvas.frameRect(), framed);
    const std::optional<double> rowBefore = meanRedRow(before);
    const std::optional<double> rowAfter = meanRedRow(after);
    QVERIFY(rowBefore && rowAfter);
    const double expectedShift = 0.5 * canvas.pixelsPerMetre();
    QVERIFY2(qAbs((*rowBefore - *rowAfter) - expectedShift) < 1.5,
             qPrintable(QStringLiteral("moved %1 px up, expected %2").arg(*rowBefore - *rowAfter).arg(expectedShift)));
}

QTEST_MAIN(CanvasViewTest)
#include "canvas_view_test.moc"
