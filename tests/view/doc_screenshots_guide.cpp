// The pictures of docs/user-guide.md that show the app at work, each taken from a real MainWindow
// driven as a user would: tools chosen with their keys, shapes drawn with mouse drags, values typed
// into the attribute pane, menu actions triggered. A run is a number of fixed steps, so every
// picture comes out the same on every machine (the engine is deterministic).

#include "doc_screenshots_guide.h"

#include "view/canvas_instruments.h"
#include "view/canvas_view.h"
#include "view/graph_quantity.h"
#include "view/main_window.h"
#include "view/property_pane.h"
#include "view/scene_document.h"
#include "view/simulation_runner.h"
#include "view/timeline.h"
#include "view/timeline_bar.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QPainter>
#include <QPixmap>
#include <QSlider>
#include <QTest>
#include <QTreeWidget>

#include <cstdio>
#include <functional>

namespace impetus::view::screenshots {

namespace {

/// The window's size in most pictures, px: readable on a page, small as a PNG.
constexpr int kWidth = 1100;
constexpr int kHeight = 660;
/// The window's height when a dock below or beside the canvas (a graph, the lesson editor) needs room.
constexpr int kTallHeight = 800;
/// Fixed steps per frame of a real-time run at the examples' 1/240 s step and 60 frames a second:
/// a run is shown in batches of this many steps, as Play takes them.
constexpr int kStepsPerFrame = 4;

bool save(const QPixmap& picture, const QString& folder, const char* file)
{
    const QString path = QDir(folder).filePath(QLatin1String(file));
    if (!picture.save(path, "png")) {
        std::fprintf(stderr, "doc_screenshots: cannot write %s\n", qPrintable(path));
        return false;
    }
    std::printf("%s\n", qPrintable(path));
    return true;
}

/// Opens the example `name` (or, for an empty name, starts an empty scene) in `window`, at
/// `width` × `height`, shown and ready for input.
bool open(MainWindow& window, const char* name, int width = kWidth, int height = kHeight)
{
    if (*name) {
        if (!window.openScene(QStringLiteral(":/examples/%1.json").arg(QLatin1String(name))).isEmpty())
            return false;
    } else if (!window.newScene()) {
        return false;
    }
    window.resize(width, height);
    window.show();
    window.activateWindow();
    if (!QTest::qWaitForWindowExposed(&window))
        return false;
    window.canvas().setFocus();
    return true;
}

/// Plays `seconds` of simulated time, in the batches a real-time run takes.
void play(MainWindow& window, double seconds)
{
    const double dt = window.runner().world().settings.timeStep;
    const int frames = static_cast<int>(seconds / dt / kStepsPerFrame + 0.5);
    for (int frame = 0; frame < frames; ++frame)
        window.runner().stepBy(kStepsPerFrame);
}

/// Where the scene point `at` (m) is on the canvas, px.
QPoint onCanvas(MainWindow& window, QPointF at) { return window.canvas().toView(at).toPoint(); }

/// The canvas point at the fractions (`x`, `y`) of its width and height, px.
QPoint fraction(MainWindow& window, double x, double y)
{
    const QWidget* viewport = window.canvas().viewport();
    return {static_cast<int>(x * viewport->width()), static_cast<int>(y * viewport->height())};
}

void key(MainWindow& window, Qt::Key key) { QTest::keyClick(window.canvas().viewport(), key); }

void drag(MainWindow& window, QPoint from, QPoint to)
{
    QWidget* viewport = window.canvas().viewport();
    QTest::mousePress(viewport, Qt::LeftButton, {}, from);
    QTest::mouseMove(viewport, (from + to) / 2);
    QTest::mouseMove(viewport, to);
    QTest::mouseRelease(viewport, Qt::LeftButton, {}, to);
}

void click(MainWindow& window, QPoint at) { QTest::mouseClick(window.canvas().viewport(), Qt::LeftButton, {}, at); }

/// The centre of mass of the body called `name` (m); the origin when there is none.
QPointF centreOf(MainWindow& window, const char* name)
{
    for (const model::Body& body : window.runner().world().bodies)
        if (body.name == name)
            return {body.state.position.x(), body.state.position.y()};
    return {};
}

/// The window's action whose text, without its `&`, is `text`; nullptr when there is none.
QAction* actionNamed(MainWindow& window, const QString& text)
{
    for (QAction* action : window.findChildren<QAction*>())
        if (QString(action->text()).remove(QLatin1Char('&')) == text)
            return action;
    return nullptr;
}

QPixmap settle(MainWindow& window)
{
    QTest::qWait(100);
    return window.grab();
}

/// An empty scene with the drawing tools at work: a box as the floor, a circle hung from a world
/// point on a spring, an ellipse on a rod (selected, as a new item is), and a polygon with three of
/// its corners clicked and the fourth under the mouse.
bool drawing(const QString& folder)
{
    MainWindow window;
    if (!open(window, ""))
        return false;
    key(window, Qt::Key_B);
    drag(window, fraction(window, 0.06, 0.84), fraction(window, 0.94, 0.92));
    key(window, Qt::Key_C);
    const QPoint ball = fraction(window, 0.22, 0.52);
    drag(window, ball, ball + QPoint(40, 0));
    key(window, Qt::Key_K);
    drag(window, ball, fraction(window, 0.22, 0.12));
    key(window, Qt::Key_E);
    drag(window, fraction(window, 0.38, 0.48), fraction(window, 0.50, 0.60));
    key(window, Qt::Key_L);
    drag(window, fraction(window, 0.44, 0.54), fraction(window, 0.44, 0.14));
    key(window, Qt::Key_P);
    click(window, fraction(window, 0.62, 0.74));
    click(window, fraction(window, 0.82, 0.76));
    click(window, fraction(window, 0.76, 0.46));
    QTest::mouseMove(window.canvas().viewport(), fraction(window, 0.66, 0.50));
    return save(settle(window), folder, "guide-drawing.png");
}

/// The incline's block clicked with the Select tool and its friction typed into the pane.
bool attributes(const QString& folder)
{
    MainWindow window;
    if (!open(window, "incline"))
        return false;
    key(window, Qt::Key_S);
    click(window, onCanvas(window, centreOf(window, "block")));
    auto* friction = window.propertyPane()->findChild<QLineEdit*>(QStringLiteral("friction"));
    if (!friction)
        return false;
    friction->setFocus();
    friction->selectAll();
    QTest::keyClicks(friction, QStringLiteral("0.6"));
    QTest::keyClick(friction, Qt::Key_Return);
    return save(settle(window), folder, "guide-attributes.png");
}

/// The pendulum at half speed with its trail, run for 3 s and dragged back to 1.5 s on the timeline.
bool runAndTimeline(const QString& folder)
{
    MainWindow window;
    if (!open(window, "pendulum"))
        return false;
    QComboBox* speed = window.speedBox();
    speed->setCurrentIndex(speed->findData(0.5));
    window.trailsAction()->trigger();
    play(window, 3.0);
    QSlider* slider = window.timelineBar()->slider();
    slider->setSliderPosition((slider->minimum() + slider->maximum()) / 2);
    slider->triggerAction(QAbstractSlider::SliderMove);
    return save(settle(window), folder, "guide-run-timeline.png");
}

/// The projectile after 1.1 s with trails, velocity and acceleration arrows (docs/app.md's picture).
bool vectorsAndTrails(const QString& folder)
{
    MainWindow window;
    if (!open(window, "projectile", 1280, 760))
        return false;
    window.trailsAction()->trigger();
    window.vectorAction(VectorKind::Velocity)->trigger();
    window.vectorAction(VectorKind::Acceleration)->trigger();
    play(window, 1.1);
    return save(settle(window), folder, "instruments-vectors-trails.png");
}

/// The incline's block sliding, with the force parts and the net force on it (docs/app.md's picture).
bool forces(const QString& folder)
{
    MainWindow window;
    if (!open(window, "incline", 1100, 700))
        return false;
    window.vectorAction(VectorKind::ForceParts)->trigger();
    window.vectorAction(VectorKind::NetForce)->trigger();
    key(window, Qt::Key_BracketRight); // Longer Arrows: friction and the net force are short
    play(window, 1.0);
    return save(settle(window), folder, "instruments-forces.png");
}

/// The incline's ramp measured: the protractor on its foot, or the ruler along its slope.
bool measuring(const QString& folder, bool protractor)
{
    MainWindow window;
    if (!open(window, "incline"))
        return false;
    // The ramp's corners in the scene (resources/examples/incline.json): the foot at (7, 0), the
    // top at (0, 4.04).
    const QPointF foot(7.0, 0.0);
    const QPointF top(0.0, 4.041452);
    if (protractor) {
        key(window, Qt::Key_A);
        click(window, onCanvas(window, foot));
        // The arms end on corners, which the protractor snaps to: the angle is the ramp's own.
        click(window, onCanvas(window, QPointF(0.0, 0.0)));
        click(window, onCanvas(window, top));
    } else {
        key(window, Qt::Key_M);
        click(window, onCanvas(window, top));
        click(window, onCanvas(window, foot));
    }
    QTest::mouseMove(window.canvas().viewport(), fraction(window, 0.95, 0.1));
    return save(settle(window), folder, protractor ? "guide-protractor.png" : "guide-ruler.png");
}

/// The pendulum run for 6 s with two graphs of the bob (x against time, vx against x), scrubbed
/// back to 3.75 s (docs/app.md's picture).
bool graphs(const QString& folder)
{
    MainWindow window;
    if (!open(window, "pendulum", 1326, 860))
        return false;
    key(window, Qt::Key_S);
    click(window, onCanvas(window, centreOf(window, "bob")));
    window.addGraph(QStringLiteral("bob"), GraphQuantity::X);
    window.addGraph(QStringLiteral("bob"), GraphQuantity::Vx, GraphQuantity::X);
    play(window, 6.0);
    window.timeline().seek(static_cast<std::int64_t>(3.75 / window.runner().world().settings.timeStep + 0.5));
    return save(settle(window), folder, "instruments-graphs-timeline.png");
}

/// The Examples menu open over the default scene: the menu is a window of its own, drawn onto the
/// picture where it stands.
bool examplesMenu(const QString& folder)
{
    MainWindow window;
    if (!open(window, "default"))
        return false;
    QMenu* menu = window.examplesMenu();
    const QRect title = window.menuBar()->actionGeometry(menu->menuAction());
    menu->popup(window.menuBar()->mapToGlobal(title.bottomLeft()));
    if (!QTest::qWaitForWindowExposed(menu))
        return false;
    QTest::qWait(100);
    QPixmap picture = window.grab();
    QPainter painter(&picture);
    painter.drawPixmap(window.mapFromGlobal(menu->pos()), menu->grab());
    painter.end();
    menu->hide();
    return save(picture, folder, "guide-examples-menu.png");
}

/// The soft-bodies example 1.4 s after Play, ellipses and strain shown (docs/app.md's picture).
bool softBodies(const QString& folder)
{
    MainWindow window;
    if (!open(window, "soft-bodies", 1200, 720))
        return false;
    QAction* ellipses = actionNamed(window, QStringLiteral("Show Soft-Body Ellipses"));
    QAction* strain = actionNamed(window, QStringLiteral("Show Soft-Body Strain"));
    if (!ellipses || !strain)
        return false;
    ellipses->trigger();
    strain->trigger();
    play(window, 1.4);
    return save(settle(window), folder, "soft-bodies.png");
}

/// The incline lesson with Lesson › Edit on: the editor in the lesson dock.
bool lessonEditor(const QString& folder)
{
    MainWindow window;
    if (!open(window, "lesson-incline-friction", 1280, kTallHeight))
        return false;
    auto* edit = window.findChild<QAction*>(QStringLiteral("editLessonAction"));
    if (!edit)
        return false;
    edit->trigger();
    // The block's entry opened, as a teacher would click it, to show its attributes' boxes.
    auto* locks = window.findChild<QTreeWidget*>(QStringLiteral("lessonLocksTree"));
    if (!locks || locks->topLevelItemCount() == 0)
        return false;
    locks->expandItem(locks->topLevelItem(locks->topLevelItemCount() - 1));
    return save(settle(window), folder, "guide-lesson-editor.png");
}

} // namespace

bool takeGuidePictures(const QString& folder)
{
    const std::function<bool(const QString&)> pictures[] = {
        drawing,
        attributes,
        runAndTimeline,
        vectorsAndTrails,
        forces,
        [](const QString& to) { return measuring(to, true); },
        [](const QString& to) { return measuring(to, false); },
        graphs,
        examplesMenu,
        softBodies,
        lessonEditor,
    };
    for (const auto& picture : pictures)
        if (!picture(folder))
            return false;
    return true;
}

} // namespace impetus::view::screenshots
