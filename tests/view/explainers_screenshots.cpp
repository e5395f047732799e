// Not a test: the pictures of docs/explainers.md, taken from the real window driven as a user
// would (clicks, the Explain menu's actions, keys). scripts/screenshots-explainers runs it under
// Xvfb. Usage: explainers_screenshots OUTPUT_DIRECTORY

#include "screenshot_files.h"
#include "test_settings.h"
#include "test_worlds.h"
#include "view/canvas_view.h"
#include "view/collision_inspector.h"
#include "view/main_window.h"
#include "view/sat_explainer.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QListWidget>
#include <QTest>
#include <QtMath>

#include <cmath>
#include <cstdio>

using namespace impetus;
using impetus::view::MainWindow;

namespace {

/// The window's size in the pictures, px: small enough to read on a page.
constexpr int kWidth = 1100;
constexpr int kHeight = 640;
/// The collision inspector's width in its picture, px: wide enough for a line of the formula.
constexpr int kInspectorWidth = 560;

void click(MainWindow& window, Vec2 at, Qt::KeyboardModifiers modifiers)
{
    view::CanvasView& canvas = window.canvas();
    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, modifiers, canvas.toView(QPointF(at.x(), at.y())).toPoint());
}

/// A box tipped by 20° with its corner pressed 6 cm into a crate: SAT on a rotated pair.
bool separatingAxes(const QDir& directory)
{
    model::World world;
    world.settings.gravity = Vec2::Zero();
    model::Body crate = view::test::makeBody("crate", model::Box{1.6, 1.0}, Vec2(0, 0.5));
    crate.color = model::Color{0x9e, 0xc5, 0xe8};
    model::Body tipped = view::test::makeBody("tipped box", model::Box{1.0, 0.6}, Vec2(0.55, 1.40));
    tipped.state.angle = qDegreesToRadians(20.0);
    tipped.color = model::Color{0xf5, 0xc1, 0x8c};
    tipped.updateDerived();
    world.bodies.push_back(crate);
    world.bodies.push_back(tipped);
    MainWindow window;
    window.setScene(world, QStringLiteral("Separating axes"));
    if (!view::test::showWindowAt(window, kWidth, kHeight))
        return false;
    click(window, Vec2(-0.5, 0.3), Qt::NoModifier);
    click(window, Vec2(0.7, 1.5), Qt::ShiftModifier);
    window.findChild<QAction*>(QStringLiteral("separatingAxesAction"))->trigger();
    auto* explainer = window.findChild<view::SatExplainer*>(QStringLiteral("satExplainer"));
    if (explainer == nullptr || !explainer->isOpen())
        return false;
    // To the axis of least overlap, then to the summary.
    const controller::PiecePairTrace* pair = explainer->current();
    const std::size_t least = pair->trace.contactAxis.value_or(0);
    while (explainer->currentAxis() < least)
        QTest::keyClick(&window.canvas(), Qt::Key_N);
    QTest::qWait(50);
    if (!view::test::saveGrab(window, directory, QStringLiteral("explain-sat-axis.png")))
        return false;
    while (explainer->currentAxis() < pair->trace.axes.size())
        QTest::keyClick(&window.canvas(), Qt::Key_N);
    QTest::qWait(50);
    return view::test::saveGrab(window, directory, QStringLiteral("explain-sat-summary.png"));
}

/// The impact of tests/controller/impact_formula_test.cpp, inspected.
bool collisionInspector(const QDir& directory)
{
    model::World world;
    world.settings.gravity = Vec2::Zero();
    model::Body slab = view::test::makeBody("slab", model::Box{6, 0.5}, Vec2(0, -0.25), true);
    slab.material.friction = 0.2;
    model::Body box = view::test::makeBody("box", model::Box{2, 1}, Vec2(0.5, 1.0));
    box.massSpec = {model::MassMode::Mass, 2.0};
    box.state.angle = std::atan2(0.6, 0.8);
    box.state.velocity = Vec2(0, -2);
    box.material.restitution = 0.5;
    box.material.friction = 0.2;
    box.updateDerived();
    world.bodies.push_back(slab);
    world.bodies.push_back(box);
    MainWindow window;
    window.setScene(world, QStringLiteral("Collision inspector"));
    if (!view::test::showWindowAt(window, kWidth, kHeight))
        return false;
    window.findChild<QAction*>(QStringLiteral("collisionInspectorAction"))->trigger();
    // The attribute pane makes room for the formula.
    window.attributesDock()->hide();
    auto* dock = window.findChild<QDockWidget*>(QStringLiteral("collisionInspectorDock"));
    window.resizeDocks({dock}, {kInspectorWidth}, Qt::Horizontal);
    window.canvas().setFocus();
    QTest::keyClick(&window.canvas(), Qt::Key_Right);
    auto* inspector = window.findChild<view::CollisionInspector*>(QStringLiteral("collisionInspector"));
    if (inspector == nullptr || !QTest::qWaitFor([&] { return inspector->list()->count() > 0; }))
        return false;
    QListWidget* list = inspector->list();
    QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::NoModifier, list->visualItemRect(list->item(0)).center());
    QTest::qWait(50);
    return view::test::saveGrab(window, directory, QStringLiteral("explain-collision-inspector.png"));
}

} // namespace

int main(int argc, char** argv)
{
    QApplication app(argc, argv);
    if (argc != 2) {
        std::fprintf(stderr, "usage: explainers_screenshots OUTPUT_DIRECTORY\n");
        return 2;
    }
    const impetus::view::test::TemporarySettings settings;
    const QDir directory(QString::fromLocal8Bit(argv[1]));
    return separatingAxes(directory) && collisionInspector(directory) ? 0 : 1;
}
