// The canvas's paint caches (CanvasView::setPaintCaches) against painting everything afresh:
// the layer of paper, grid and trails, grown while steps come and painted whole once they stop,
// shows at rest exactly what a whole paint shows, also after a zoom; stamped circles differ from
// circles drawn in place only in their edge pixels' antialiasing.

#include "test_worlds.h"
#include "view/body_item.h"
#include "view/canvas_instruments.h"
#include "view/canvas_view.h"
#include "view/simulation_runner.h"
#include "view/view_constants.h"

#include <QImage>
#include <QTest>

#include <cmath>

using impetus::Vec2;
using impetus::view::CanvasView;
using impetus::view::SimulationRunner;
namespace model = impetus::model;
namespace constants = impetus::view::constants;
namespace test = impetus::view::test;

namespace {

/// Canvas size, px.
constexpr int kWidth = 420;
constexpr int kHeight = 300;

/// Three boxes thrown apart under gravity, turning, and a fixed box that frames the view: their
/// trails are three parabolas with dots. Boxes, not circles, so that no stamp is involved and
/// only the trail layer differs between the two canvases.
model::World thrownBoxesWorld()
{
    model::World world;
    const Vec2 velocities[] = {Vec2(-1.5, 3), Vec2(0.3, 4), Vec2(2, 2.5)};
    for (int i = 0; i < 3; ++i) {
        model::Body box = test::makeBody("box" + std::to_string(i), model::Box{0.2, 0.15}, Vec2(0.4 * i, 0));
        box.state.velocity = velocities[i];
        box.state.angularVelocity = 2.0 + i;
        box.color = model::Color{static_cast<std::uint8_t>(60 * i), 0x40, static_cast<std::uint8_t>(200 - 60 * i)};
        world.bodies.push_back(box);
    }
    world.bodies.push_back(test::makeBody("frame", model::Box{5, 0.2}, Vec2(0.4, -1.5), true));
    world.bodies.push_back(test::makeBody("top", model::Box{0.2, 0.2}, Vec2(0.4, 2.5), true));
    return world;
}

/// A canvas on `runner` with the trails on, caches as `caches`.
void setUp(CanvasView& canvas, SimulationRunner& runner, bool caches)
{
    canvas.setPaintCaches(caches);
    canvas.resize(kWidth, kHeight);
    canvas.show();
    canvas.instruments().setShowTrails(true);
    impetus::view::SampleRequest request;
    request.centres = true;
    runner.setSampleRequest(request);
}

/// Pixels where `a` and `b` differ.
int differingPixels(const QImage& a, const QImage& b)
{
    int count = 0;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x)
            count += a.pixel(x, y) != b.pixel(x, y) ? 1 : 0;
    }
    return count;
}

/// The grab of `canvas`'s viewport.
QImage grabOf(CanvasView& canvas) { return canvas.viewport()->grab().toImage().convertToFormat(QImage::Format_RGB32); }

} // namespace

class PaintCacheTest : public QObject {
    Q_OBJECT

private slots:
    void trailLayerAtRestEqualsWholePaint();
    void stampedCirclesDifferOnlyAtTheirEdges();
};

void PaintCacheTest::trailLayerAtRestEqualsWholePaint()
{
    SimulationRunner runner;
    runner.setWorld(thrownBoxesWorld());
    CanvasView cached(runner);
    CanvasView whole(runner);
    setUp(cached, runner, true);
    setUp(whole, runner, false);
    QVERIFY(QTest::qWaitForWindowExposed(&cached));
    QVERIFY(QTest::qWaitForWindowExposed(&whole));
    const QImage start = grabOf(cached);

    // Steps a few at a time with a paint after each, as a run shows them: the layer grows.
    for (int batch = 0; batch < 30; ++batch) {
        runner.stepBy(6);
        cached.viewport()->repaint();
    }
    QVERIFY(cached.instruments().trail(0).size() > 100);
    const QImage grown = grabOf(cached);
    QVERIFY(differingPixels(start, grown) > 200); // the growth was drawn: three trails with dots

    // Once no state has come for a moment, the cached canvas shows exactly the whole paint.
    QTest::qWait(3 * constants::kLayerSettleMs);
    const QImage reference = grabOf(whole);
    QCOMPARE(differingPixels(grabOf(cached), reference), 0);
    QVERIFY(differingPixels(start, reference) > 200);

    // A zoom draws the layer anew at the new scale rather than showing the old picture.
    for (CanvasView* canvas : {&cached, &whole})
        canvas->zoomBy(1.5, QPointF(kWidth / 2.0, kHeight / 2.0));
    QCOMPARE(differingPixels(grabOf(cached), grabOf(whole)), 0);

    // Scrubbing back (the timeline's cut) shortens the trails in the layer too.
    for (CanvasView* canvas : {&cached, &whole})
        canvas->instruments().discardAfter(60);
    QCOMPARE(differingPixels(grabOf(cached), grabOf(whole)), 0);
}

void PaintCacheTest::stampedCirclesDifferOnlyAtTheirEdges()
{
    // Circles of two sizes at several angles and at positions that fall at different places
    // within a pixel, one of them colliding (red).
    model::World world;
    world.settings.gravity = Vec2::Zero();
    const double radii[] = {0.1, 0.23};
    for (int i = 0; i < 8; ++i) {
        model::Body ball = test::makeBody("ball" + std::to_string(i), model::Circle{radii[i % 2]},
                                          Vec2(0.55 * i + 0.0137 * i * i, 0.31 * (i % 3) + 0.0071 * i));
        ball.state.angle = 0.7 * i;
        ball.colliding = i == 3;
        world.bodies.push_back(ball);
    }
    SimulationRunner runner;
    runner.setWorld(world);
    CanvasView stamped(runner);
    CanvasView drawn(runner);
    stamped.setPaintCaches(true);
    drawn.setPaintCaches(false);
    for (CanvasView* canvas : {&stamped, &drawn}) {
        canvas->resize(kWidth, kHeight);
        canvas->show();
    }
    QVERIFY(QTest::qWaitForWindowExposed(&stamped));
    QVERIFY(QTest::qWaitForWindowExposed(&drawn));
    const QImage a = grabOf(stamped);
    const QImage b = grabOf(drawn);

    // A stamp's centre is within 1/(2·kStampSubpixelSteps) px of the true one and its curve is
    // flattened unturned, another ≤ 1/8 px: an edge pixel's coverage changes by at most a
    // quarter, so a channel by at most a quarter of 255. Pixels more than the outline's width
    // and a pixel of antialiasing from every circle's edge must be the same.
    const double ppm = stamped.pixelsPerMetre();
    const double band = constants::kOutlineWidthPx + 1.5;
    int edgeDifferences = 0;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            const QColor ca = a.pixelColor(x, y);
            const QColor cb = b.pixelColor(x, y);
            if (ca == cb)
                continue;
            bool nearEdge = false;
            for (const model::Body& body : runner.world().bodies) {
                const QPointF centre = stamped.toView(QPointF(body.state.position.x(), body.state.position.y()));
                const double radius = std::get<model::Circle>(body.shape).radius * ppm;
                const double distance = std::hypot(x + 0.5 - centre.x(), y + 0.5 - centre.y());
                nearEdge = nearEdge || std::abs(distance - radius) <= band;
            }
            QVERIFY2(nearEdge, qPrintable(QStringLiteral("pixel (%1, %2) differs away from any edge").arg(x).arg(y)));
            const int most = std::max({std::abs(ca.red() - cb.red()), std::abs(ca.green() - cb.green()),
                                       std::abs(ca.blue() - cb.blue())});
            QVERIFY2(most <= 255 / 4, qPrintable(QStringLiteral("pixel (%1, %2) differs by %3").arg(x).arg(y).arg(most)));
            ++edgeDifferences;
        }
    }
    // The stamps were used: something differs, and the red of the colliding ball is there.
    QVERIFY(edgeDifferences > 0);
    const model::Body& red = runner.world().bodies[3];
    const QPointF redCentre = stamped.toView(QPointF(red.state.position.x(), red.state.position.y()));
    const QPoint inside = (redCentre + QPointF(0, -0.5 * std::get<model::Circle>(red.shape).radius * ppm)).toPoint();
    QCOMPARE(a.pixelColor(inside), b.pixelColor(inside));
    QCOMPARE(a.pixelColor(inside), QColor(constants::kCollidingRed, constants::kCollidingGreen, constants::kCollidingBlue));
}

QTEST_MAIN(PaintCacheTest)
#include "paint_cache_test.moc"
