// View › Projector Mode, driven as a user would: F11 on the window, then what the class sees —
// larger readouts, full screen, thick lines, and colliding bodies marked by more than colour.

#include "test_pixels.h"
#include "test_settings.h"
#include "test_worlds.h"
#include "view/body_item.h"
#include "view/canvas_instruments.h"
#include "view/canvas_look.h"
#include "view/canvas_view.h"
#include "view/main_window.h"
#include "view/projector_constants.h"
#include "view/projector_mode.h"
#include "view/simulation_runner.h"
#include "view/view_constants.h"

#include <QAction>
#include <QLabel>
#include <QMenuBar>
#include <QSettings>
#include <QStatusBar>
#include <QTest>

using impetus::view::MainWindow;
namespace model = impetus::model;
namespace test = impetus::view::test;
namespace view = impetus::view;
namespace constants = impetus::view::constants;

namespace {

/// The status bar label whose accessible name is `name`, or nullptr.
QLabel* statusLabel(MainWindow& window, const QString& name)
{
    for (QLabel* label : window.statusBar()->findChildren<QLabel*>())
        if (label->accessibleName() == name)
            return label;
    return nullptr;
}

/// The width of a common classroom projector (1280 × 800), px.
constexpr int kProjectorWidthPx = 1280;

/// Whether every readout of the status bar is as wide as its text asks: none is cut off.
bool everyReadoutFits(MainWindow& window)
{
    for (QLabel* label : window.statusBar()->findChildren<QLabel*>(QString(), Qt::FindDirectChildrenOnly)) {
        if (label->isVisible() && label->width() < label->sizeHint().width())
            return false;
    }
    return true;
}

/// Under gravity: a blue box resting on a fixed floor, so both are in contact at every step.
model::World restingBoxWorld()
{
    model::World world;
    model::Body floor = test::makeBody("floor", model::Box{6, 0.5}, impetus::Vec2(0, -0.25), true);
    world.bodies.push_back(floor);
    model::Body box = test::makeBody("box", model::Box{1.5, 1.5}, impetus::Vec2(0, 0.75));
    box.color = model::Color{0x3b, 0x82, 0xf6};
    world.bodies.push_back(box);
    return world;
}

/// Of the pixels well inside body `index`'s outline on the canvas as shown: the share that is the
/// collision red, and the share that is near-black.
struct InsideColours {
    double red = 0;
    double dark = 0;
};

InsideColours coloursInside(view::CanvasView& canvas, std::size_t index)
{
    const QImage image = canvas.grab().toImage();
    const QRectF scene = canvas.bodyItems()[index]->sceneBoundingRect();
    QRectF pixels = QRectF(canvas.toView(scene.topLeft()), canvas.toView(scene.bottomRight())).normalized();
    // Away from the outline, whose thickness is not what is measured here.
    pixels = pixels.adjusted(pixels.width() / 5, pixels.height() / 5, -pixels.width() / 5, -pixels.height() / 5);
    int red = 0;
    int dark = 0;
    int all = 0;
    const qreal ratio = image.devicePixelRatio();
    for (int y = static_cast<int>(pixels.top() * ratio); y < static_cast<int>(pixels.bottom() * ratio); ++y) {
        for (int x = static_cast<int>(pixels.left() * ratio); x < static_cast<int>(pixels.right() * ratio); ++x) {
            const QColor c = image.pixelColor(x, y);
            ++all;
            if (c.red() > 180 && c.green() < 90 && c.blue() < 90)
                ++red;
            else if (c.red() < 70 && c.green() < 70 && c.blue() < 70)
                ++dark;
        }
    }
    if (all == 0)
        return {};
    return {static_cast<double>(red) / all, static_cast<double>(dark) / all};
}

} // namespace

class ProjectorModeTest : public QObject {
    Q_OBJECT

private slots:
    void f11EnlargesTheReadoutsAndGoesFullScreen();
    void projectorModeIsRememberedForTheNextWindow();
    void readoutsShrinkToFitLongNumbersAndGrowBack();
    void collidingBodyIsHatchedBesidesRed();
    void arrowsAndTrailsAreThickInProjectorMode();

private:
    static bool showActive(MainWindow& window);

    test::TemporarySettings m_settings;
};

bool ProjectorModeTest::showActive(MainWindow& window)
{
    window.resize(900, 650);
    window.show();
    window.activateWindow();
    return QTest::qWaitForWindowActive(&window);
}

void ProjectorModeTest::f11EnlargesTheReadoutsAndGoesFullScreen()
{
    MainWindow window;
    window.setScene(restingBoxWorld(), QStringLiteral("box"));
    QVERIFY(showActive(window));
    QLabel* time = statusLabel(window, QStringLiteral("Simulated time"));
    QLabel* energy = statusLabel(window, QStringLiteral("Total energy"));
    QVERIFY(time && energy);
    const double readoutBefore = time->font().pointSizeF();
    const double menuBefore = window.menuBar()->font().pointSizeF();
    const int readoutHeightBefore = time->sizeHint().height();
    QVERIFY(readoutBefore > 0);
    QVERIFY(!window.isFullScreen());
    QCOMPARE(window.canvas().look(), view::CanvasLook{});

    QTest::keyClick(&window.canvas(), Qt::Key_F11);

    auto* action = window.findChild<QAction*>(QStringLiteral("projectorModeAction"));
    QVERIFY(action && action->isChecked());
    QVERIFY(window.windowState() & Qt::WindowFullScreen);
    // The readouts are as large as lets every one of them fit across the status bar: on the test
    // platform's screen of 800 px that is barely larger than normal, so they are read on a window
    // as wide as a 1280 px projector.
    auto* projector = window.findChild<view::ProjectorMode*>();
    QVERIFY(projector);
    QTRY_VERIFY(everyReadoutFits(window));
    window.showNormal();
    window.resize(kProjectorWidthPx, 720);
    // There, larger than the rest of the window's text.
    QTRY_VERIFY(projector->readoutScale() > constants::kProjectorFontScale);
    QTRY_VERIFY(everyReadoutFits(window));
    QCOMPARE(time->font().pointSizeF(), readoutBefore * projector->readoutScale());
    QCOMPARE(energy->font().pointSizeF(), readoutBefore * projector->readoutScale());
    QVERIFY(time->sizeHint().height() > readoutHeightBefore);
    window.showFullScreen();
    QCOMPARE(window.menuBar()->font().pointSizeF(), menuBefore * constants::kProjectorFontScale);
    QVERIFY(window.windowState() & Qt::WindowFullScreen);
    QCOMPARE(window.canvas().look(), view::CanvasLook::projector());
    QVERIFY(window.canvas().look().lineScale > 1);

    // F11 again gives the window back as it was.
    QTest::keyClick(&window.canvas(), Qt::Key_F11);
    QVERIFY(!action->isChecked());
    QCOMPARE(time->font().pointSizeF(), readoutBefore);
    QCOMPARE(window.menuBar()->font().pointSizeF(), menuBefore);
    QVERIFY(!(window.windowState() & Qt::WindowFullScreen));
    QCOMPARE(window.canvas().look(), view::CanvasLook{});
}

// A fast, heavy body high up makes every readout several digits longer. At the size that suits
// the resting box they would no longer fit across the screen, and the last ones would be cut off
// (their units first): they are made smaller until they fit, and grow back with short numbers.
void ProjectorModeTest::readoutsShrinkToFitLongNumbersAndGrowBack()
{
    MainWindow window;
    window.setScene(restingBoxWorld(), QStringLiteral("box"));
    QVERIFY(showActive(window));
    QTest::keyClick(&window.canvas(), Qt::Key_F11);
    auto* projector = window.findChild<view::ProjectorMode*>();
    QVERIFY(projector && projector->isOn());
    window.showNormal();
    window.resize(kProjectorWidthPx, 720);
    QTRY_VERIFY(projector->readoutScale() > constants::kProjectorFontScale);
    QTRY_VERIFY(everyReadoutFits(window));
    const double shortScale = projector->readoutScale();

    model::World fast = restingBoxWorld();
    fast.bodies[1].massSpec = model::MassSpec{model::MassMode::Mass, 5000};
    fast.bodies[1].updateDerived();
    fast.bodies[1].state.position = impetus::Vec2(0, 3210);
    fast.bodies[1].state.velocity = impetus::Vec2(-1234.5, 987.6);
    window.setScene(fast, QStringLiteral("fast"));
    QTRY_VERIFY(projector->readoutScale() < shortScale);
    QTRY_VERIFY(everyReadoutFits(window));
    QLabel* energy = statusLabel(window, QStringLiteral("Total energy"));
    QVERIFY(energy && energy->text().contains(QStringLiteral(" J")));

    window.setScene(restingBoxWorld(), QStringLiteral("box"));
    QTRY_COMPARE(projector->readoutScale(), shortScale);
    QVERIFY(everyReadoutFits(window));
    QTest::keyClick(&window.canvas(), Qt::Key_F11);
    QVERIFY(!projector->isOn());
    QCOMPARE(projector->readoutScale(), 1.0);
}

void ProjectorModeTest::projectorModeIsRememberedForTheNextWindow()
{
    double normalReadout = 0;
    {
        MainWindow window;
        normalReadout = statusLabel(window, QStringLiteral("Simulated time"))->font().pointSizeF();
        window.findChild<QAction*>(QStringLiteral("projectorModeAction"))->trigger();
        QVERIFY(QSettings().value(QLatin1String(view::kProjectorSettingKey)).toBool());
    }
    {
        MainWindow window;
        QVERIFY(window.findChild<QAction*>(QStringLiteral("projectorModeAction"))->isChecked());
        QCOMPARE(statusLabel(window, QStringLiteral("Simulated time"))->font().pointSizeF(),
                 normalReadout * constants::kProjectorReadoutScale);
        QCOMPARE(window.canvas().look(), view::CanvasLook::projector());
        window.findChild<QAction*>(QStringLiteral("projectorModeAction"))->trigger();
    }
    QVERIFY(!QSettings().value(QLatin1String(view::kProjectorSettingKey)).toBool());
    MainWindow window;
    QVERIFY(!window.findChild<QAction*>(QStringLiteral("projectorModeAction"))->isChecked());
}

void ProjectorModeTest::collidingBodyIsHatchedBesidesRed()
{
    MainWindow window;
    window.setScene(restingBoxWorld(), QStringLiteral("box"));
    QVERIFY(showActive(window));
    window.stepAction()->trigger();
    QTRY_VERIFY(window.runner().world().stepCount == 1);
    view::CanvasView& canvas = window.canvas();
    QVERIFY(canvas.bodyItems()[1]->isColliding());

    // The normal look: the colliding box is plain red inside.
    const InsideColours normal = coloursInside(canvas, 1);
    QVERIFY2(normal.red > 0.9, qPrintable(QString::number(normal.red)));
    QVERIFY2(normal.dark < 0.01, qPrintable(QString::number(normal.dark)));

    // Projector mode: still red, with a dark cross-hatch over it.
    window.findChild<QAction*>(QStringLiteral("projectorModeAction"))->trigger();
    const InsideColours projector = coloursInside(canvas, 1);
    QVERIFY2(projector.red > 0.5, qPrintable(QString::number(projector.red)));
    QVERIFY2(projector.dark > 0.05, qPrintable(QString::number(projector.dark)));

    // A body that does not collide gets no hatch: the hatch means "colliding".
    window.setScene(restingBoxWorld(), QStringLiteral("box"));
    QVERIFY(!canvas.bodyItems()[1]->isColliding());
    QVERIFY2(coloursInside(canvas, 1).dark < 0.01, "a body at rest before any step is hatched");
    window.findChild<QAction*>(QStringLiteral("projectorModeAction"))->trigger();
}

// "Thick outlines and arrows": the velocity arrow is drawn kProjectorLineScale times as wide in
// projector mode, and the trail's dots as large (its line stays one pixel: wider, Qt strokes a
// long trail a hundred times slower), so they stay visible from the back of the room.
void ProjectorModeTest::arrowsAndTrailsAreThickInProjectorMode()
{
    MainWindow window;
    window.setScene(test::movingBallWorld(), QStringLiteral("moving"));
    QVERIFY(showActive(window));
    window.vectorAction(view::VectorKind::Velocity)->trigger();
    window.trailsAction()->trigger();
    window.runner().stepBy(120); // half a second at 2 m/s: a metre of trail
    view::CanvasView& canvas = window.canvas();
    QCOMPARE(canvas.instruments().lineScale(), 1.0);

    // Pixels of the arrow, and of the trail, per pixel of their length: their width on screen.
    struct Widths {
        double arrow = 0;
        double trail = 0;
    };
    const auto widths = [&]() -> Widths {
        const QImage image = canvas.viewport()->grab().toImage();
        const impetus::Vec2 ball = window.runner().world().bodies[0].state.position;
        const QPointF centre = canvas.toView(QPointF(ball.x(), ball.y()));
        const double perMetre = canvas.pixelsPerMetre();
        const double arrowPx = 2 * constants::kDefaultVelocityScale * perMetre; // 2 m/s
        // Right of the ball the arrow; left of it the trail, a body's own colour, half-transparent
        // over the paper (found by a band of rows around the ball's height, clear of the ball).
        const int radius = static_cast<int>(0.1 * perMetre) + 4;
        const QRect ahead(static_cast<int>(centre.x()) + radius, static_cast<int>(centre.y()) - 30,
                          static_cast<int>(arrowPx), 60);
        const int arrow = test::pixelsNear(image, constants::kVelocityColor, nullptr, ahead);
        const int trailLength = static_cast<int>(0.6 * perMetre);
        const QRect behind(static_cast<int>(centre.x()) - radius - trailLength, static_cast<int>(centre.y()) - 30,
                           trailLength, 60);
        const QColor paper = image.pixelColor(behind.topLeft());
        int trail = 0;
        for (int y = behind.top(); y <= behind.bottom(); ++y) {
            for (int x = behind.left(); x <= behind.right(); ++x) {
                const QColor c = image.pixelColor(x, y);
                if (std::abs(c.red() - paper.red()) + std::abs(c.green() - paper.green()) +
                        std::abs(c.blue() - paper.blue()) > 60)
                    ++trail;
            }
        }
        return {arrow / arrowPx, trail / static_cast<double>(trailLength)};
    };
    const Widths normal = widths();
    QVERIFY2(normal.arrow > 1 && normal.trail > 0.5, qPrintable(QStringLiteral("%1 %2").arg(normal.arrow).arg(normal.trail)));

    window.findChild<QAction*>(QStringLiteral("projectorModeAction"))->trigger();
    QCOMPARE(canvas.instruments().lineScale(), view::constants::kProjectorLineScale);
    const Widths projector = widths();
    const QString what = QStringLiteral("arrow %1 -> %2 px, trail %3 -> %4 px")
                             .arg(normal.arrow)
                             .arg(projector.arrow)
                             .arg(normal.trail)
                             .arg(projector.trail);
    qInfo("%s", qPrintable(what));
    QVERIFY2(projector.arrow > 2 * normal.arrow, qPrintable(what));
    // The trail's dots 2.5 times as large, its line the same: about twice the pixels in the band
    // (3.3 against 6.7 px here).
    QVERIFY2(projector.trail > 1.6 * normal.trail, qPrintable(what));
    window.findChild<QAction*>(QStringLiteral("projectorModeAction"))->trigger();
    QCOMPARE(canvas.instruments().lineScale(), 1.0);
}

QTEST_MAIN(ProjectorModeTest)
#include "projector_mode_test.moc"
