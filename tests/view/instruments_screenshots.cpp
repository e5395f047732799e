// Not a test: the pictures of docs/app.md's probe, Trace Point and tool icons, taken from the real window driven
// as a user would (keys and clicks). scripts/screenshots runs it under Xvfb.
// Usage: instruments_screenshots OUTPUT_DIRECTORY

#include "screenshot_files.h"
#include "test_settings.h"
#include "view/canvas_instruments.h"
#include "view/canvas_view.h"
#include "view/main_window.h"
#include "view/simulation_runner.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QIcon>
#include <QImage>
#include <QPainter>
#include <QPixmap>
#include <QTest>

#include <cstdio>
#include <vector>

using impetus::view::MainWindow;

namespace {

/// The window's size in the pictures, px: small enough to read on a page.
constexpr int kWidth = 1100;
constexpr int kHeight = 640;

/// The projectile example in flight, with its trail, its velocity arrow, and the probe on the ball.
bool probePicture(const QDir& directory)
{
    MainWindow window;
    if (!window.openScene(QStringLiteral(":/examples/projectile.json")).isEmpty() ||
        !impetus::view::test::showWindowAt(window, kWidth, kHeight))
        return false;
    impetus::view::CanvasView& canvas = window.canvas();
    window.trailsAction()->trigger();
    window.vectorAction(impetus::view::VectorKind::Velocity)->trigger();
    // 0.45 s of flight, in frames as a run shows it.
    for (int frame = 0; frame < 27; ++frame)
        window.runner().stepBy(4);
    QTest::keyClick(canvas.viewport(), Qt::Key_I);
    const impetus::model::World& world = window.runner().world();
    for (const impetus::model::Body& body : world.bodies) {
        if (!body.fixed) {
            const QPointF at(body.state.position.x(), body.state.position.y());
            QTest::mouseClick(canvas.viewport(), Qt::LeftButton, Qt::NoModifier, canvas.toView(at).toPoint());
            break;
        }
    }
    QTest::mouseMove(canvas.viewport(), QPoint(canvas.viewport()->width() - 10, canvas.viewport()->height() - 10));
    QApplication::processEvents();
    return impetus::view::test::saveGrab(window, directory, QStringLiteral("instruments-probe.png"));
}

/// A wheel rolling along the floor with Trace Point on its rim: its centre's trail is a straight
/// line, the rim point's path a cycloid, with the dots of both.
bool tracePointPicture(const QDir& directory)
{
    namespace model = impetus::model;
    model::World world;
    model::Body floor;
    floor.name = "floor";
    floor.shape = model::Box{12, 0.4};
    floor.state.position = impetus::Vec2(0, -0.2);
    floor.fixed = true;
    floor.updateDerived();
    model::Body wheel;
    wheel.name = "wheel";
    wheel.shape = model::Circle{0.6};
    wheel.state.position = impetus::Vec2(-4.5, 0.6);
    wheel.state.velocity = impetus::Vec2(1.5, 0);
    wheel.state.angularVelocity = -1.5 / 0.6; // rolling: v = −ω·r
    wheel.updateDerived();
    world.bodies = {floor, wheel};
    MainWindow window;
    window.setScene(world, QStringLiteral("rolling wheel"));
    if (!impetus::view::test::showWindowAt(window, kWidth, kHeight))
        return false;
    impetus::view::CanvasView& canvas = window.canvas();
    window.trailsAction()->trigger();
    QTest::keyClick(canvas.viewport(), Qt::Key_X);
    // The bottom of the rim, where it touches the floor.
    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, Qt::NoModifier, canvas.toView(QPointF(-4.5, 0.03)).toPoint());
    // 5 s of rolling, in frames as a run shows it: two turns and a bit.
    for (int frame = 0; frame < 300; ++frame)
        window.runner().stepBy(4);
    QTest::keyClick(canvas.viewport(), Qt::Key_S);
    QTest::mouseMove(canvas.viewport(), QPoint(canvas.viewport()->width() - 10, canvas.viewport()->height() - 10));
    QApplication::processEvents();
    return impetus::view::test::saveGrab(window, directory, QStringLiteral("instruments-trace-point.png"));
}

/// A sheet of every tool's and run control's icon, large, each with its name and shortcut as the
/// window's actions give them.
bool iconsPicture(const QDir& directory)
{
    MainWindow window;
    using impetus::view::ToolKind;
    std::vector<QAction*> actions;
    for (const ToolKind kind : {ToolKind::Select, ToolKind::Rotate, ToolKind::Polygon, ToolKind::Box, ToolKind::Circle,
                                ToolKind::Ellipse, ToolKind::Spring, ToolKind::Pin, ToolKind::Rod, ToolKind::Ruler,
                                ToolKind::Protractor, ToolKind::Probe})
        actions.push_back(window.toolAction(kind));
    for (QAction* action : {window.playAction(), window.stepBackAction(), window.stepAction(), window.resetAction()})
        actions.push_back(action);
    constexpr int kIcon = 48;
    constexpr int kCellWidth = 170;
    constexpr int kCellHeight = 64;
    constexpr int kColumns = 4;
    const int rows = static_cast<int>((actions.size() + 1 + kColumns - 1) / kColumns);
    QImage sheet(kColumns * kCellWidth, rows * kCellHeight, QImage::Format_ARGB32);
    sheet.fill(Qt::white);
    QPainter painter(&sheet);
    painter.setRenderHint(QPainter::Antialiasing);
    const auto cell = [&](int index, const QIcon& icon, const QString& text) {
        const QPoint at((index % kColumns) * kCellWidth + 8, (index / kColumns) * kCellHeight + 8);
        painter.drawPixmap(at, icon.pixmap(QSize(kIcon, kIcon)));
        painter.setPen(Qt::black);
        painter.drawText(QRect(at + QPoint(kIcon + 8, 0), QSize(kCellWidth - kIcon - 20, kIcon)),
                         Qt::AlignVCenter | Qt::TextWordWrap, text);
    };
    int index = 0;
    for (QAction* action : actions) {
        const QString key = action->shortcut().toString(QKeySequence::NativeText);
        cell(index++, action->icon(), QStringLiteral("%1 (%2)").arg(action->text(), key));
    }
    cell(index, QIcon(QStringLiteral(":/icons/tools/pause.svg")), QStringLiteral("Pause (Space)"));
    painter.end();
    const QString path = directory.filePath(QStringLiteral("tool-icons.png"));
    if (!sheet.save(path)) {
        std::fprintf(stderr, "cannot write %s\n", qPrintable(path));
        return false;
    }
    std::printf("%s\n", qPrintable(path));
    return true;
}

} // namespace

int main(int argc, char** argv)
{
    QApplication app(argc, argv);
    impetus::view::test::TemporarySettings settings; // the user's own settings stay untouched
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s OUTPUT_DIRECTORY\n", argv[0]);
        return 2;
    }
    const QDir directory(QString::fromLocal8Bit(argv[1]));
    if (!directory.exists()) {
        std::fprintf(stderr, "no directory %s\n", argv[1]);
        return 2;
    }
    return probePicture(directory) && tracePointPicture(directory) && iconsPicture(directory) ? 0 : 1;
}
