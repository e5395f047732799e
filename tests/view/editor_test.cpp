// The editor, driven as a user would: tools with the mouse, shortcuts with the keyboard, the
// canvas zoomed and panned, files saved and opened, collisions seen in red.

#include "model/polygon.h"
#include "model/scene_io.h"
#include "test_files.h"
#include "test_settings.h"
#include "test_worlds.h"
#include "view/body_item.h"
#include "view/canvas_view.h"
#include "view/example_catalog.h"
#include "view/main_window.h"
#include "view/property_pane.h"
#include "view/scene_document.h"
#include "view/scene_loading.h"
#include "view/screenshot.h"
#include "view/simulation_runner.h"
#include "view/tools/polygon_tool.h"
#include "view/view_constants.h"

#include <QAbstractButton>
#include <QAction>
#include <QCheckBox>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QImage>
#include <QLabel>
#include <QLineF>
#include <QMenu>
#include <QMessageBox>
#include <QStatusBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QLineEdit>
#include <QTest>
#include <QTimer>
#include <QTranslator>
#include <QToolTip>
#include <QUndoStack>
#include <QWheelEvent>

#include <cmath>
#include <numbers>

using impetus::Vec2;
using impetus::view::CanvasView;
using impetus::view::MainWindow;
using impetus::view::Selection;
using impetus::view::ToolKind;
namespace model = impetus::model;
namespace test = impetus::view::test;

namespace {

/// No gravity and no bodies: a blank page to draw on.
model::World emptyWorld()
{
    model::World world;
    world.settings.gravity = Vec2::Zero();
    return world;
}

/// Two blue discs of radius 0.3 m, 1.2 m apart, moving toward each other at 1 m/s each, no
/// gravity, elastic: they meet, bounce and fly apart.
model::World approachingDiscs()
{
    model::World world = emptyWorld();
    for (const double x : {-0.6, 0.6}) {
        model::Body disc = test::makeBody(x < 0 ? "left" : "right", model::Circle{0.3}, Vec2(x, 0));
        disc.state.velocity = Vec2(x < 0 ? 1.0 : -1.0, 0);
        disc.material.restitution = 1;
        disc.color = model::Color{0x1d, 0x4e, 0xd8};
        world.bodies.push_back(disc);
    }
    return world;
}

/// A translator that marks every example title it translates, «like this»: a title that comes out
/// unmarked did not go through tr().
class MarkingTranslator : public QTranslator {
public:
    bool isEmpty() const override { return false; }
    QString translate(const char* context, const char* sourceText, const char* = nullptr, int = -1) const override
    {
        if (QLatin1String(context) != QLatin1String("impetus::view::Examples"))
            return {};
        return QStringLiteral("«%1»").arg(QString::fromUtf8(sourceText));
    }
};

/// An action's text without its mnemonic ampersand: what the menu shows.
QString shownText(const QAction* action) { return action->text().remove(QLatin1Char('&')); }

/// The viewport pixel of the scene point `scene`.
QPoint pixelOf(const CanvasView& canvas, const QPointF& scene) { return canvas.toView(scene).toPoint(); }

/// The scene point of the viewport pixel `pixel`: where a click there lands.
QPointF sceneOf(const CanvasView& canvas, const QPoint& pixel) { return canvas.toScene(QPointF(pixel)); }

/// Presses the left button at `from`, moves through the midpoint to `to` and releases there.
void drag(QWidget* viewport, const QPoint& from, const QPoint& to, Qt::KeyboardModifiers modifiers = {},
          Qt::MouseButton button = Qt::LeftButton)
{
    QTest::mousePress(viewport, button, modifiers, from);
    QTest::mouseMove(viewport, (from + to) / 2);
    QTest::mouseMove(viewport, to);
    QTest::mouseRelease(viewport, button, modifiers, to);
}

/// Turns a wheel by `notches` at the viewport pixel `at`.
void turnWheel(QWidget* viewport, const QPoint& at, int notches)
{
    QWheelEvent event(QPointF(at), viewport->mapToGlobal(QPointF(at)), QPoint(), QPoint(0, 120 * notches),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(viewport, &event);
}

/// How close `color` is to `target`, channel by channel.
bool near(const QColor& color, const QColor& target, int tolerance = 24)
{
    return std::abs(color.red() - target.red()) <= tolerance && std::abs(color.green() - target.green()) <= tolerance
        && std::abs(color.blue() - target.blue()) <= tolerance;
}

/// Clicks `button` of the next modal message box when it opens, keeping its object name.
void answerNextBox(QObject* context, QMessageBox::StandardButton button, QString* seenName, QString* seenText = nullptr)
{
    QTimer::singleShot(0, context, [=] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (!box)
            return;
        *seenName = box->objectName();
        if (seenText)
            *seenText = box->text() + QLatin1Char('\n') + box->informativeText();
        box->button(button)->click();
    });
}

} // namespace

class EditorTest : public QObject {
    Q_OBJECT

private slots:
    void init();
    void cleanup();

    void polygonFromThreeClicksClosedOnFirstVertex();
    void polygonClosedWithEnterOrDoubleClick();
    void invalidPolygonIsRefusedAndStaysOpen();
    void dragOutBoxOfThatSizeAtThatPlace();
    void dragOutCircleAndEllipse();
    void dragOutBoxThenTypeRestitutionInThePane();
    void undoRestoresAndRedoReappliesWithKeys();
    void deleteKeyRemovesSelection();
    void selectClickRubberBandAndMove();
    void ctrlDragRotatesAndRotateTool();
    void arrowKeysNudgeSelectionInsteadOfStepping();
    void snapPutsCornersOnTheGrid();
    void springAndRodFromBodyToBodyOrWorld();
    void pinHingesBodyToTheWorld();
    void wheelZoomKeepsPointUnderCursor();
    void middleDragAndSpaceDragPan();
    void collidingBodiesTurnRedAndBack();
    void playResetAndUndoTheRun();
    void toolShortcutsPickTools();
    void speedChoiceSetsRunnerSpeed();
    void readoutsShowEnergiesAndMomentum();
    void titleShowsModifiedAndSaveClearsIt();
    void saveAndReopenRoundTrip();
    void badFileShowsErrorAndSceneIsUnchanged();
    void askBeforeDiscardingEdits();
    void examplesMenuListsAndOpensExamples();
    void dockLayoutIsRemembered();
    void screenshotRendersRedWithoutSelection();
    void undoingAnAttributeEditKeepsTheBodyWhereItIs();
    void pinHingeFieldShowsAndEditsTheHingeWhereItIsNow();
    void spaceOnTheFixedCheckBoxTogglesItAndDoesNotPlay();
    void deleteAndArrowsInTheVertexTableStayInTheTable();
    void deletingOrMovingAPartnerEndsTheRed();
    void everyExampleHasATranslatableTitle();
    void escapeCancelsADragInProgress();
    void saveWhileRunningPausesAndSavesTheInstantShown();
    void boxPreviewIsTintedWithItsAlpha();

private:
    /// A window showing `world`, shown and active so that shortcuts work.
    void open(model::World world);

    test::TemporarySettings m_settings;
    std::unique_ptr<MainWindow> m_window;
};

void EditorTest::init() { open(emptyWorld()); }

void EditorTest::cleanup()
{
    // Nothing the tests did is worth a question on closing.
    m_window->document().undoStack()->setClean();
    m_window.reset();
}

void EditorTest::open(model::World world)
{
    if (m_window)
        m_window->document().undoStack()->setClean();
    m_window = std::make_unique<MainWindow>();
    m_window->setScene(std::move(world), QStringLiteral("test"));
    m_window->resize(900, 640);
    m_window->show();
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    m_window->canvas().setFocus();
}

void EditorTest::polygonFromThreeClicksClosedOnFirstVertex()
{
    CanvasView& canvas = m_window->canvas();
    QTest::keyClick(&canvas, Qt::Key_P);
    QCOMPARE(canvas.toolKind(), ToolKind::Polygon);

    const QPoint a(300, 400), b(500, 400), c(380, 250);
    for (const QPoint& p : {a, b, c})
        QTest::mouseClick(canvas.viewport(), Qt::LeftButton, {}, p);
    QCOMPARE(m_window->runner().world().bodies.size(), std::size_t(0));
    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, {}, a + QPoint(2, -1)); // on the first vertex

    const model::World& world = m_window->runner().world();
    QCOMPARE(world.bodies.size(), std::size_t(1));
    const model::Body& body = world.bodies[0];
    QCOMPARE(body.name, std::string("polygon 1"));
    const auto* polygon = std::get_if<model::Polygon>(&body.shape);
    QVERIFY(polygon);
    QCOMPARE(polygon->vertices.size(), std::size_t(3));
    // The corners are where the clicks were, in the scene.
    const QPoint clicks[] = {a, b, c};
    for (std::size_t i = 0; i < 3; ++i) {
        const Vec2 corner = body.worldPoint(polygon->vertices[i] - body.geometry.centroidOffset);
        const QPointF expected = sceneOf(canvas, clicks[i]);
        QVERIFY(qAbs(corner.x() - expected.x()) < 1e-9 && qAbs(corner.y() - expected.y()) < 1e-9);
    }
    // Area of the triangle from its clicked corners: ½|(b − a) × (c − a)|.
    const QPointF pa = sceneOf(canvas, a), pb = sceneOf(canvas, b), pc = sceneOf(canvas, c);
    const double area = 0.5 * std::abs((pb.x() - pa.x()) * (pc.y() - pa.y()) - (pb.y() - pa.y()) * (pc.x() - pa.x()));
    QVERIFY2(qAbs(body.area - area) < 1e-9 * area, qPrintable(QStringLiteral("%1 vs %2").arg(body.area).arg(area)));
    QVERIFY(area > 0.1);
    // The body sits at its centroid, the mean of a triangle's corners, with density 1.
    QVERIFY(qAbs(body.state.position.x() - (pa.x() + pb.x() + pc.x()) / 3) < 1e-9);
    QVERIFY(qAbs(body.state.position.y() - (pa.y() + pb.y() + pc.y()) / 3) < 1e-9);
    QCOMPARE(body.density(), 1.0);
    QCOMPARE(m_window->document().selection(), (Selection{{0}, {}, {}}));
    QCOMPARE(shownText(m_window->undoAction()), QStringLiteral("Undo Draw polygon"));
}

void EditorTest::polygonClosedWithEnterOrDoubleClick()
{
    CanvasView& canvas = m_window->canvas();
    QTest::keyClick(&canvas, Qt::Key_P);
    // A concave "L" closed with Enter.
    const QPoint corners[] = {{200, 450}, {400, 450}, {400, 380}, {280, 380}, {280, 250}, {200, 250}};
    for (const QPoint& p : corners)
        QTest::mouseClick(canvas.viewport(), Qt::LeftButton, {}, p);
    QTest::keyClick(&canvas, Qt::Key_Return);
    QCOMPARE(m_window->runner().world().bodies.size(), std::size_t(1));
    const model::Body& l = m_window->runner().world().bodies[0];
    QVERIFY(l.geometry.convexPieces.size() >= 2);
    const double pixelsPerMetre = canvas.pixelsPerMetre();
    const double expectedArea = (200.0 * 70 + 80.0 * 130) / (pixelsPerMetre * pixelsPerMetre);
    QVERIFY(qAbs(l.area - expectedArea) < 1e-9 * expectedArea);

    // A triangle closed by double-clicking its last corner.
    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, {}, QPoint(550, 450));
    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, {}, QPoint(700, 450));
    // A double click as the window system delivers it: press, release, press, double click,
    // release. (QTest::mouseDClick on a widget sends the double-click event alone.)
    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, {}, QPoint(620, 300));
    QTest::mousePress(canvas.viewport(), Qt::LeftButton, {}, QPoint(620, 300));
    QTest::mouseDClick(canvas.viewport(), Qt::LeftButton, {}, QPoint(620, 300));
    QTest::mouseRelease(canvas.viewport(), Qt::LeftButton, {}, QPoint(620, 300));
    QCOMPARE(m_window->runner().world().bodies.size(), std::size_t(2));
    const auto* triangle = std::get_if<model::Polygon>(&m_window->runner().world().bodies[1].shape);
    QVERIFY(triangle);
    QCOMPARE(triangle->vertices.size(), std::size_t(3));
}

void EditorTest::invalidPolygonIsRefusedAndStaysOpen()
{
    CanvasView& canvas = m_window->canvas();
    QTest::keyClick(&canvas, Qt::Key_P);
    auto* tool = dynamic_cast<impetus::view::PolygonTool*>(canvas.tool());
    QVERIFY(tool);

    // Two corners, then a click on the first: not a polygon yet.
    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, {}, QPoint(300, 300));
    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, {}, QPoint(500, 300));
    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, {}, QPoint(300, 300));
    QVERIFY2(canvas.lastMessage().contains(QStringLiteral("at least 3")), qPrintable(canvas.lastMessage()));
    QCOMPARE(tool->vertices().size(), std::size_t(2));
    QCOMPARE(m_window->runner().world().bodies.size(), std::size_t(0));

    // A bow tie: the edges cross. Enter is refused and the four corners stay.
    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, {}, QPoint(300, 450));
    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, {}, QPoint(500, 450));
    QTest::keyClick(&canvas, Qt::Key_Return);
    QVERIFY2(canvas.lastMessage().contains(QStringLiteral("cross")), qPrintable(canvas.lastMessage()));
    QVERIFY2(QToolTip::isVisible() && QToolTip::text() == canvas.lastMessage(), qPrintable(QToolTip::text()));
    QCOMPARE(tool->vertices().size(), std::size_t(4));
    QCOMPARE(m_window->runner().world().bodies.size(), std::size_t(0));

    // Fix it: take the last corner back and put it on the other side, then close.
    QTest::keyClick(&canvas, Qt::Key_Backspace);
    QTest::keyClick(&canvas, Qt::Key_Backspace);
    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, {}, QPoint(500, 450));
    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, {}, QPoint(300, 450));
    QTest::keyClick(&canvas, Qt::Key_Enter);
    QCOMPARE(m_window->runner().world().bodies.size(), std::size_t(1));
    QVERIFY(tool->vertices().empty());
    const double side = 200 / canvas.pixelsPerMetre();
    QVERIFY(qAbs(m_window->runner().world().bodies[0].area - 0.75 * side * side) < 1e-9);
}

void EditorTest::dragOutBoxOfThatSizeAtThatPlace()
{
    CanvasView& canvas = m_window->canvas();
    QTest::keyClick(&canvas, Qt::Key_B);
    const QPoint from(250, 420), to(430, 300);
    drag(canvas.viewport(), from, to);

    const model::World& world = m_window->runner().world();
    QCOMPARE(world.bodies.size(), std::size_t(1));
    const model::Body& box = world.bodies[0];
    const auto* shape = std::get_if<model::Box>(&box.shape);
    QVERIFY(shape);
    const QPointF a = sceneOf(canvas, from), b = sceneOf(canvas, to);
    QVERIFY(qAbs(shape->width - std::abs(b.x() - a.x())) < 1e-9);
    QVERIFY(qAbs(shape->height - std::abs(b.y() - a.y())) < 1e-9);
    QVERIFY(qAbs(box.state.position.x() - (a.x() + b.x()) / 2) < 1e-9);
    QVERIFY(qAbs(box.state.position.y() - (a.y() + b.y()) / 2) < 1e-9);
    QCOMPARE(box.name, std::string("box 1"));
    QCOMPARE(box.material, model::Material{});
    QCOMPARE(box.density(), 1.0);

    // A second box is "box 2"; a click without a drag draws nothing.
    drag(canvas.viewport(), QPoint(500, 420), QPoint(600, 380));
    QCOMPARE(m_window->runner().world().bodies[1].name, std::string("box 2"));
    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, {}, QPoint(700, 200));
    QCOMPARE(m_window->runner().world().bodies.size(), std::size_t(2));
}

void EditorTest::dragOutBoxThenTypeRestitutionInThePane()
{
    CanvasView& canvas = m_window->canvas();
    QTest::keyClick(&canvas, Qt::Key_B);
    const QPoint from(250, 420), to(430, 300);
    drag(canvas.viewport(), from, to);
    QCOMPARE(m_window->runner().world().bodies.size(), std::size_t(1));

    // Pick it with the select tool: the pane shows the box.
    QTest::keyClick(&canvas, Qt::Key_S);
    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, {}, (from + to) / 2);
    QCOMPARE(m_window->document().selection().bodies, std::vector<int>{0});
    auto* restitution = m_window->propertyPane()->findChild<QLineEdit*>(QStringLiteral("restitution"));
    QVERIFY(restitution);
    QVERIFY(restitution->isVisible());
    QCOMPARE(restitution->text().toDouble(), 0.5);

    // Type a new value and press Enter, as a user would: the model changes, and nothing else.
    const model::Body before = m_window->runner().world().bodies[0];
    QTest::mouseDClick(restitution, Qt::LeftButton);
    restitution->selectAll();
    QTest::keyClicks(restitution, QStringLiteral("0.8"));
    QTest::keyClick(restitution, Qt::Key_Return);
    const model::Body& after = m_window->runner().world().bodies[0];
    QCOMPARE(after.material.restitution, 0.8);
    model::Body expected = before;
    expected.material.restitution = 0.8;
    QCOMPARE(after, expected);
    QVERIFY(m_window->document().undoStack()->undoText().contains(QStringLiteral("estitution")));

    // A bad value is refused with a message and changes nothing.
    restitution->selectAll();
    QTest::keyClicks(restitution, QStringLiteral("1.5"));
    QTest::keyClick(restitution, Qt::Key_Return);
    QCOMPARE(m_window->runner().world().bodies[0].material.restitution, 0.8);
    QVERIFY(!m_window->propertyPane()->message().isEmpty());

    // Undo from the canvas puts the old value back in the model and in the pane.
    canvas.setFocus();
    QTest::keyClick(&canvas, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(m_window->runner().world().bodies[0].material.restitution, 0.5);
    QCOMPARE(restitution->text().toDouble(), 0.5);
}

void EditorTest::dragOutCircleAndEllipse()
{
    CanvasView& canvas = m_window->canvas();
    QTest::keyClick(&canvas, Qt::Key_C);
    drag(canvas.viewport(), QPoint(300, 300), QPoint(360, 380));
    QTest::keyClick(&canvas, Qt::Key_E);
    drag(canvas.viewport(), QPoint(500, 300), QPoint(640, 360));

    const model::World& world = m_window->runner().world();
    QCOMPARE(world.bodies.size(), std::size_t(2));
    const auto* circle = std::get_if<model::Circle>(&world.bodies[0].shape);
    QVERIFY(circle);
    QVERIFY(qAbs(circle->radius - 100 / canvas.pixelsPerMetre()) < 1e-9);
    const QPointF centre = sceneOf(canvas, QPoint(300, 300));
    QVERIFY(qAbs(world.bodies[0].state.position.x() - centre.x()) < 1e-9);
    const auto* ellipse = std::get_if<model::Ellipse>(&world.bodies[1].shape);
    QVERIFY(ellipse);
    QVERIFY(qAbs(ellipse->radiusX - 70 / canvas.pixelsPerMetre()) < 1e-9);
    QVERIFY(qAbs(ellipse->radiusY - 30 / canvas.pixelsPerMetre()) < 1e-9);
    QCOMPARE(world.bodies[1].name, std::string("ellipse 1"));
}

void EditorTest::undoRestoresAndRedoReappliesWithKeys()
{
    CanvasView& canvas = m_window->canvas();
    QTest::keyClick(&canvas, Qt::Key_B);
    drag(canvas.viewport(), QPoint(250, 420), QPoint(430, 300));
    const model::World drawn = m_window->runner().world();
    QCOMPARE(drawn.bodies.size(), std::size_t(1));
    QCOMPARE(shownText(m_window->undoAction()), QStringLiteral("Undo Draw box"));

    QTest::keyClick(&canvas, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(m_window->runner().world().bodies.size(), std::size_t(0));
    QCOMPARE(shownText(m_window->redoAction()), QStringLiteral("Redo Draw box"));
    QVERIFY(canvas.bodyItems().empty());

    QTest::keyClick(&canvas, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY(m_window->runner().world() == drawn);
    QCOMPARE(canvas.bodyItems().size(), std::size_t(1));
}

void EditorTest::deleteKeyRemovesSelection()
{
    model::World world = test::hangingBoxWorld();
    world.settings.gravity = Vec2::Zero();
    open(world);
    CanvasView& canvas = m_window->canvas();
    QVERIFY(!m_window->deleteAction()->isEnabled());
    // Click the box (body 0): selected; Del removes it and its spring.
    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, {}, pixelOf(canvas, QPointF(0.3, 1.0)));
    QCOMPARE(m_window->document().selection(), (Selection{{0}, {}, {}}));
    QVERIFY(canvas.bodyItems()[0]->isHighlighted());
    QVERIFY(m_window->deleteAction()->isEnabled());
    QTest::keyClick(&canvas, Qt::Key_Delete);
    QCOMPARE(m_window->runner().world().bodies.size(), std::size_t(1));
    QCOMPARE(m_window->runner().world().bodies[0].name, std::string("floor"));
    QVERIFY(m_window->runner().world().springs.empty());
    QVERIFY(canvas.springItems().empty());

    QTest::keyClick(&canvas, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(m_window->runner().world().bodies.size(), std::size_t(2));
    QCOMPARE(m_window->runner().world().springs.size(), std::size_t(1));

    // The Edit menu's Delete does the same.
    m_window->document().setSelection(Selection{{1}, {}, {}});
    m_window->deleteAction()->trigger();
    QCOMPARE(m_window->runner().world().bodies.size(), std::size_t(1));
    QCOMPARE(m_window->runner().world().bodies[0].name, std::string("box"));
}

void EditorTest::selectClickRubberBandAndMove()
{
    model::World world = emptyWorld();
    world.bodies.push_back(test::makeBody("a", model::Box{0.4, 0.4}, Vec2(-1, 0)));
    world.bodies.push_back(test::makeBody("b", model::Circle{0.2}, Vec2(1, 0)));
    world.bodies.push_back(test::makeBody("c", model::Box{0.4, 0.4}, Vec2(3, 0)));
    open(world);
    CanvasView& canvas = m_window->canvas();

    // A rubber band around a and b (not c).
    drag(canvas.viewport(), pixelOf(canvas, QPointF(-1.5, 0.5)), pixelOf(canvas, QPointF(1.5, -0.5)));
    QCOMPARE(m_window->document().selection(), (Selection{{0, 1}, {}, {}}));
    // Shift+click adds c; a click on empty space clears.
    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, Qt::ShiftModifier, pixelOf(canvas, QPointF(3, 0)));
    QCOMPARE(m_window->document().selection(), (Selection{{0, 1, 2}, {}, {}}));
    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, {}, pixelOf(canvas, QPointF(0, 2)));
    QVERIFY(m_window->document().selection().empty());

    // Dragging b moves it by the mouse's way in the scene, as one undo step.
    const QPoint from = pixelOf(canvas, QPointF(1, 0));
    const QPoint to = from + QPoint(90, -45);
    drag(canvas.viewport(), from, to);
    const QPointF moved = sceneOf(canvas, to) - sceneOf(canvas, from);
    const Vec2 position = m_window->runner().world().bodies[1].state.position;
    QVERIFY(qAbs(position.x() - (1 + moved.x())) < 1e-9);
    QVERIFY(qAbs(position.y() - moved.y()) < 1e-9);
    QCOMPARE(m_window->runner().world().bodies[0].state.position, Vec2(-1, 0));
    QCOMPARE(shownText(m_window->undoAction()), QStringLiteral("Undo Move"));
    QCOMPARE(m_window->document().undoStack()->count(), 1);
    m_window->undoAction()->trigger();
    QCOMPARE(m_window->runner().world().bodies[1].state.position, Vec2(1, 0));
}

void EditorTest::ctrlDragRotatesAndRotateTool()
{
    model::World world = emptyWorld();
    world.bodies.push_back(test::makeBody("bar", model::Box{2, 0.2}, Vec2(0, 0)));
    open(world);
    CanvasView& canvas = m_window->canvas();

    // Ctrl+drag from the bar's right end up to straight above its centre: a quarter turn.
    drag(canvas.viewport(), pixelOf(canvas, QPointF(0.9, 0)), pixelOf(canvas, QPointF(0, 0.9)), Qt::ControlModifier);
    QVERIFY2(qAbs(m_window->runner().world().bodies[0].state.angle - std::numbers::pi / 2) < 0.02,
             qPrintable(QString::number(m_window->runner().world().bodies[0].state.angle)));
    QCOMPARE(shownText(m_window->undoAction()), QStringLiteral("Undo Rotate"));

    // The Rotate tool with Shift snaps to 15°: from straight up to about 40° left of it gives 45°.
    QTest::keyClick(&canvas, Qt::Key_T);
    QCOMPARE(canvas.toolKind(), ToolKind::Rotate);
    const double start = m_window->runner().world().bodies[0].state.angle;
    const double a = 40 * std::numbers::pi / 180;
    drag(canvas.viewport(), pixelOf(canvas, QPointF(0, 0.9)), pixelOf(canvas, QPointF(-0.9 * std::sin(a), 0.9 * std::cos(a))),
         Qt::ShiftModifier);
    const double turned = m_window->runner().world().bodies[0].state.angle - start;
    QVERIFY2(qAbs(turned - std::numbers::pi / 4) < 1e-12, qPrintable(QString::number(turned)));
}

void EditorTest::arrowKeysNudgeSelectionInsteadOfStepping()
{
    model::World world = emptyWorld();
    world.bodies.push_back(test::makeBody("a", model::Box{0.4, 0.4}, Vec2(0, 0)));
    open(world);
    CanvasView& canvas = m_window->canvas();
    const double nudge = 0.1 * canvas.gridSpacing();

    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, {}, pixelOf(canvas, QPointF(0, 0)));
    QTest::keyClick(&canvas, Qt::Key_Right);
    QTest::keyClick(&canvas, Qt::Key_Up);
    QTest::keyClick(&canvas, Qt::Key_Up);
    const Vec2 position = m_window->runner().world().bodies[0].state.position;
    QVERIFY(qAbs(position.x() - nudge) < 1e-12);
    QVERIFY(qAbs(position.y() - 2 * nudge) < 1e-12);
    QCOMPARE(m_window->runner().world().stepCount, std::int64_t(0));

    // Escape clears the selection; then → is Step again.
    QTest::keyClick(&canvas, Qt::Key_Escape);
    QVERIFY(m_window->document().selection().empty());
    QTest::keyClick(&canvas, Qt::Key_Right);
    QCOMPARE(m_window->runner().world().stepCount, std::int64_t(1));
}

void EditorTest::snapPutsCornersOnTheGrid()
{
    CanvasView& canvas = m_window->canvas();
    QTest::keyClick(&canvas, Qt::Key_G);
    QVERIFY(m_window->snapAction()->isChecked());
    QVERIFY(canvas.snapToGrid());
    QTest::keyClick(&canvas, Qt::Key_B);
    drag(canvas.viewport(), QPoint(253, 417), QPoint(431, 298));
    const model::Body& box = m_window->runner().world().bodies.at(0);
    const auto* shape = std::get_if<model::Box>(&box.shape);
    QVERIFY(shape);
    const double spacing = canvas.gridSpacing();
    const auto onGrid = [&](double v) { return qAbs(v / spacing - std::round(v / spacing)) < 1e-9; };
    for (const double x : {box.state.position.x() - shape->width / 2, box.state.position.x() + shape->width / 2})
        QVERIFY2(onGrid(x), qPrintable(QString::number(x)));
    for (const double y : {box.state.position.y() - shape->height / 2, box.state.position.y() + shape->height / 2})
        QVERIFY2(onGrid(y), qPrintable(QString::number(y)));
}

void EditorTest::springAndRodFromBodyToBodyOrWorld()
{
    model::World world = emptyWorld();
    world.bodies.push_back(test::makeBody("a", model::Box{0.6, 0.6}, Vec2(-1.5, 0)));
    world.bodies.push_back(test::makeBody("b", model::Box{0.6, 0.6}, Vec2(1.5, 0)));
    open(world);
    CanvasView& canvas = m_window->canvas();

    QTest::keyClick(&canvas, Qt::Key_K);
    drag(canvas.viewport(), pixelOf(canvas, QPointF(-1.5, 0)), pixelOf(canvas, QPointF(1.5, 0)));
    QCOMPARE(m_window->runner().world().springs.size(), std::size_t(1));
    const model::Spring spring = m_window->runner().world().springs[0];
    QCOMPARE(spring.bodyA.index, 0u);
    QVERIFY(spring.bodyB && spring.bodyB->index == 1u);
    // At rest at its drawn length, anchored where pressed and released.
    const Vec2 endA = m_window->runner().world().bodies[0].worldPoint(spring.anchorA);
    const Vec2 endB = m_window->runner().world().bodies[1].worldPoint(spring.anchorB);
    QVERIFY(qAbs((endB - endA).norm() - spring.restLength) < 1e-9);
    QVERIFY(qAbs(spring.restLength - 3) < 2 / canvas.pixelsPerMetre());
    QCOMPARE(canvas.springItems().size(), std::size_t(1));

    // A spring from body b up to empty space hangs from a world point.
    drag(canvas.viewport(), pixelOf(canvas, QPointF(1.5, 0)), pixelOf(canvas, QPointF(1.5, 2)));
    const model::Spring hanging = m_window->runner().world().springs.at(1);
    QVERIFY(!hanging.bodyB);
    QVERIFY(qAbs(hanging.anchorB.y() - 2) < 2 / canvas.pixelsPerMetre());

    // Starting on empty space is refused with a message.
    drag(canvas.viewport(), pixelOf(canvas, QPointF(0, 2)), pixelOf(canvas, QPointF(1.5, 0)));
    QCOMPARE(m_window->runner().world().springs.size(), std::size_t(2));
    QVERIFY(canvas.lastMessage().contains(QStringLiteral("spring")));

    // A rod from a to b keeps the drawn length.
    QTest::keyClick(&canvas, Qt::Key_L);
    drag(canvas.viewport(), pixelOf(canvas, QPointF(-1.4, 0.1)), pixelOf(canvas, QPointF(1.4, 0.1)));
    QCOMPARE(m_window->runner().world().joints.size(), std::size_t(1));
    const model::Joint rod = m_window->runner().world().joints[0];
    QVERIFY(rod.type == model::JointType::Rod);
    QVERIFY(rod.bodyB && rod.bodyB->index == 1u);
    const Vec2 rodA = m_window->runner().world().bodies[0].worldPoint(rod.anchorA);
    const Vec2 rodB = m_window->runner().world().bodies[1].worldPoint(rod.anchorB);
    QVERIFY(qAbs((rodB - rodA).norm() - rod.length) < 1e-9);
    QCOMPARE(canvas.jointItems().size(), std::size_t(1));
}

void EditorTest::pinHingesBodyToTheWorld()
{
    model::World world = test::hangingBoxWorld();
    world.springs.clear();
    open(world);
    CanvasView& canvas = m_window->canvas();
    QTest::keyClick(&canvas, Qt::Key_N);
    QCOMPARE(canvas.toolKind(), ToolKind::Pin);
    const QPoint at = pixelOf(canvas, QPointF(0.3, 1.1));
    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, {}, at);
    QCOMPARE(m_window->runner().world().joints.size(), std::size_t(1));
    const model::Joint pin = m_window->runner().world().joints[0];
    QVERIFY(pin.type == model::JointType::Pin);
    QCOMPARE(pin.bodyA.index, 0u);
    QVERIFY(!pin.bodyB);
    const QPointF hinge = sceneOf(canvas, at);
    QVERIFY(qAbs(pin.worldAnchor.x() - hinge.x()) < 1e-12 && qAbs(pin.worldAnchor.y() - hinge.y()) < 1e-12);
    QVERIFY((m_window->runner().world().bodies[0].worldPoint(pin.anchorA) - pin.worldAnchor).norm() < 1e-12);

    // Run: the box swings about the hinge, which stays put.
    for (int i = 0; i < 60; ++i)
        m_window->stepAction()->trigger();
    const model::World& after = m_window->runner().world();
    QVERIFY((after.bodies[0].worldPoint(pin.anchorA) - pin.worldAnchor).norm() < 1e-3);
    QVERIFY(after.bodies[0].state.angle != 0);
}

void EditorTest::wheelZoomKeepsPointUnderCursor()
{
    CanvasView& canvas = m_window->canvas();
    const QPoint cursor(620, 170);
    const QPointF under = sceneOf(canvas, cursor);
    const double scale = canvas.pixelsPerMetre();

    turnWheel(canvas.viewport(), cursor, 2);
    QVERIFY(qAbs(canvas.pixelsPerMetre() - scale * 1.44) < 1e-9 * scale);
    QVERIFY2(QLineF(canvas.toView(under), QPointF(cursor)).length() <= 1.0,
             qPrintable(QStringLiteral("%1, %2").arg(canvas.toView(under).x()).arg(canvas.toView(under).y())));
    QVERIFY(!canvas.autoFrame());

    turnWheel(canvas.viewport(), QPoint(100, 500), -3);
    QVERIFY(canvas.pixelsPerMetre() < scale);
    QVERIFY(QLineF(canvas.toView(under), QPointF(cursor)).length() > 1.0); // the other anchor moved it
}

void EditorTest::middleDragAndSpaceDragPan()
{
    model::World world = emptyWorld();
    world.bodies.push_back(test::makeBody("a", model::Box{0.4, 0.4}, Vec2(0, 0)));
    open(world);
    CanvasView& canvas = m_window->canvas();
    const QPointF origin = canvas.toView(QPointF(0, 0));

    drag(canvas.viewport(), QPoint(400, 300), QPoint(460, 260), {}, Qt::MiddleButton);
    QVERIFY(QLineF(canvas.toView(QPointF(0, 0)), origin + QPointF(60, -40)).length() <= 1.0);

    // Space held while dragging pans (even over a body) and does not play; the body stays.
    const QPointF before = canvas.toView(QPointF(0, 0));
    QTest::keyPress(&canvas, Qt::Key_Space);
    drag(canvas.viewport(), before.toPoint(), before.toPoint() + QPoint(-80, 30));
    QTest::keyRelease(&canvas, Qt::Key_Space);
    QVERIFY(!m_window->runner().isRunning());
    QVERIFY(QLineF(canvas.toView(QPointF(0, 0)), before + QPointF(-80, 30)).length() <= 1.0);
    QCOMPARE(m_window->runner().world().bodies[0].state.position, Vec2(0, 0));
    QCOMPARE(m_window->document().undoStack()->count(), 0);

    // A plain Space tap still plays.
    QTest::keyClick(&canvas, Qt::Key_Space);
    QVERIFY(m_window->runner().isRunning());
    QTest::keyClick(&canvas, Qt::Key_Space);
    QVERIFY(!m_window->runner().isRunning());
}

void EditorTest::collidingBodiesTurnRedAndBack()
{
    open(approachingDiscs());
    CanvasView& canvas = m_window->canvas();
    const QColor blue(0x1d, 0x4e, 0xd8);
    const QColor red(0xdc, 0x26, 0x26);
    // A point inside each disc, off the radius line and the outline.
    const auto insideOf = [&](int body) {
        const Vec2 p = m_window->runner().world().bodies[static_cast<std::size_t>(body)].state.position;
        return pixelOf(canvas, QPointF(p.x(), p.y() + 0.15));
    };
    const auto colourAt = [&](int body) { return canvas.viewport()->grab().toImage().pixelColor(insideOf(body)); };
    QVERIFY(near(colourAt(0), blue));

    int steps = 0;
    while (!m_window->runner().world().bodies[0].colliding && steps < 1000) {
        QTest::keyClick(&canvas, Qt::Key_Right);
        ++steps;
    }
    QVERIFY2(m_window->runner().world().bodies[0].colliding, "the discs never met");
    QVERIFY2(near(colourAt(0), red), qPrintable(colourAt(0).name()));
    QVERIFY2(near(colourAt(1), red), qPrintable(colourAt(1).name()));
    QCOMPARE(m_window->runner().world().collisionCount, std::int64_t(1));

    while ((m_window->runner().world().bodies[0].colliding || m_window->runner().world().bodies[1].colliding)
           && steps < 2000) {
        QTest::keyClick(&canvas, Qt::Key_Right);
        ++steps;
    }
    // They bounced apart: left moves left again, and both are blue.
    QVERIFY(m_window->runner().world().bodies[0].state.velocity.x() < 0);
    QVERIFY2(near(colourAt(0), blue), qPrintable(colourAt(0).name()));
    QVERIFY2(near(colourAt(1), blue), qPrintable(colourAt(1).name()));
}

void EditorTest::playResetAndUndoTheRun()
{
    open(test::risingBallWorld());
    CanvasView& canvas = m_window->canvas();
    const model::World start = m_window->runner().world();

    QTest::keyClick(&canvas, Qt::Key_Space);
    QTRY_VERIFY(m_window->runner().world().time > 0.05);
    QTest::keyClick(&canvas, Qt::Key_Space);
    QVERIFY(!m_window->runner().isRunning());
    const model::World ran = m_window->runner().world();

    // R: back to the world at Play.
    QTest::keyClick(&canvas, Qt::Key_R);
    QVERIFY(m_window->runner().world() == start);
    // Ctrl+Z undoes the reset, then the run itself.
    QTest::keyClick(&canvas, Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(m_window->runner().world() == ran);
    QCOMPARE(shownText(m_window->undoAction()), QStringLiteral("Undo Run"));
    QTest::keyClick(&canvas, Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(m_window->runner().world() == start);
    QCOMPARE(canvas.bodyItems()[0]->scenePos(), QPointF(0, 0));
}

void EditorTest::toolShortcutsPickTools()
{
    CanvasView& canvas = m_window->canvas();
    const std::pair<Qt::Key, ToolKind> keys[] = {
        {Qt::Key_T, ToolKind::Rotate}, {Qt::Key_P, ToolKind::Polygon}, {Qt::Key_B, ToolKind::Box},
        {Qt::Key_C, ToolKind::Circle}, {Qt::Key_E, ToolKind::Ellipse}, {Qt::Key_K, ToolKind::Spring},
        {Qt::Key_N, ToolKind::Pin},    {Qt::Key_L, ToolKind::Rod},     {Qt::Key_S, ToolKind::Select},
    };
    for (const auto& [key, kind] : keys) {
        QTest::keyClick(&canvas, key);
        QCOMPARE(canvas.toolKind(), kind);
        QVERIFY(m_window->toolAction(kind)->isChecked());
    }
    // The tool bar's buttons work too.
    m_window->toolAction(ToolKind::Box)->trigger();
    QCOMPARE(canvas.toolKind(), ToolKind::Box);
}

void EditorTest::speedChoiceSetsRunnerSpeed()
{
    QComboBox* box = m_window->speedBox();
    QCOMPARE(m_window->runner().speed(), 1.0);
    QCOMPARE(box->itemData(0).toDouble(), 0.1);
    QCOMPARE(box->itemData(box->count() - 1).toDouble(), 4.0);
    box->setCurrentIndex(0);
    QCOMPARE(m_window->runner().speed(), 0.1);
    box->setCurrentIndex(box->count() - 1);
    QCOMPARE(m_window->runner().speed(), 4.0);
}

void EditorTest::readoutsShowEnergiesAndMomentum()
{
    model::World world = test::risingBallWorld();
    world.bodies[0].state.velocity = Vec2(3, 4);
    open(world);
    const double mass = world.bodies[0].mass;
    QStringList texts;
    for (const QLabel* label : m_window->statusBar()->findChildren<QLabel*>())
        texts << label->text();
    const QString all = texts.join(QLatin1Char(' '));
    QVERIFY2(all.contains(QStringLiteral("K = %1 J").arg(12.5 * mass, 0, 'f', 3)), qPrintable(all));
    QVERIFY2(all.contains(QStringLiteral("p = (%1, %2) kg·m/s").arg(3 * mass, 0, 'f', 3).arg(4 * mass, 0, 'f', 3)),
             qPrintable(all));
    QVERIFY2(all.contains(QStringLiteral("Collisions: 0")), qPrintable(all));
}

void EditorTest::titleShowsModifiedAndSaveClearsIt()
{
    QCOMPARE(m_window->windowTitle(), QStringLiteral("test[*] — Impetus"));
    QVERIFY(!m_window->isWindowModified());
    QTest::keyClick(&m_window->canvas(), Qt::Key_B);
    drag(m_window->canvas().viewport(), QPoint(250, 420), QPoint(430, 300));
    QVERIFY(m_window->isWindowModified());

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(m_window->saveTo(dir.filePath(QStringLiteral("drawn.json"))));
    QVERIFY(!m_window->isWindowModified());
    QCOMPARE(m_window->windowTitle(), QStringLiteral("drawn[*] — Impetus"));
    QCOMPARE(m_window->recentFiles().value(0), dir.filePath(QStringLiteral("drawn.json")));
    // Undoing past the save is a change again.
    QTest::keyClick(&m_window->canvas(), Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(m_window->isWindowModified());
}

void EditorTest::saveAndReopenRoundTrip()
{
    CanvasView& canvas = m_window->canvas();
    QTest::keyClick(&canvas, Qt::Key_B);
    drag(canvas.viewport(), QPoint(250, 420), QPoint(430, 300));
    QTest::keyClick(&canvas, Qt::Key_C);
    drag(canvas.viewport(), QPoint(600, 300), QPoint(640, 330));
    QTest::keyClick(&canvas, Qt::Key_K);
    drag(canvas.viewport(), QPoint(340, 360), QPoint(600, 300));
    const model::World drawn = m_window->runner().world();
    QCOMPARE(drawn.springs.size(), std::size_t(1));

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("round.json"));
    QVERIFY(m_window->saveTo(path));

    m_window->newScene();
    QVERIFY(m_window->runner().world().bodies.empty());
    QVERIFY(m_window->openSceneInteractively(path));
    QCOMPARE(model::serializeScene(m_window->runner().world()), model::serializeScene(drawn));
    QCOMPARE(m_window->sceneName(), QStringLiteral("round"));
    QCOMPARE(m_window->document().filePath(), path);
}

void EditorTest::badFileShowsErrorAndSceneIsUnchanged()
{
    open(test::hangingBoxWorld());
    const model::World before = m_window->runner().world();
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("bad.json"));
    QVERIFY(test::writeFile(path, test::kSceneWithTwoProblems));

    QString boxName, boxText;
    answerNextBox(this, QMessageBox::Ok, &boxName, &boxText);
    QVERIFY(!m_window->openSceneInteractively(path));
    QCOMPARE(boxName, QStringLiteral("openErrorBox"));
    QVERIFY2(boxText.contains(QStringLiteral("bodies[0].shape.width")), qPrintable(boxText));
    QVERIFY2(boxText.contains(QStringLiteral("bodies[1].name")), qPrintable(boxText));
    QVERIFY(m_window->runner().world() == before);
    QCOMPARE(m_window->canvas().bodyItems().size(), before.bodies.size());
    QCOMPARE(m_window->sceneName(), QStringLiteral("test"));
}

void EditorTest::askBeforeDiscardingEdits()
{
    CanvasView& canvas = m_window->canvas();
    QTest::keyClick(&canvas, Qt::Key_B);
    drag(canvas.viewport(), QPoint(250, 420), QPoint(430, 300));

    QString boxName;
    answerNextBox(this, QMessageBox::Cancel, &boxName);
    QVERIFY(!m_window->newScene());
    QCOMPARE(boxName, QStringLiteral("unsavedChangesBox"));
    QCOMPARE(m_window->runner().world().bodies.size(), std::size_t(1));

    boxName.clear();
    answerNextBox(this, QMessageBox::Cancel, &boxName);
    QVERIFY(!m_window->close());
    QCOMPARE(boxName, QStringLiteral("unsavedChangesBox"));
    QVERIFY(m_window->isVisible());

    boxName.clear();
    answerNextBox(this, QMessageBox::Discard, &boxName);
    QVERIFY(m_window->newScene());
    QCOMPARE(boxName, QStringLiteral("unsavedChangesBox"));
    QVERIFY(m_window->runner().world().bodies.empty());

    // Without edits there is no question: a run alone is not work to lose.
    open(test::risingBallWorld());
    QTest::keyClick(&m_window->canvas(), Qt::Key_Right);
    boxName.clear();
    answerNextBox(this, QMessageBox::Cancel, &boxName);
    QVERIFY(m_window->newScene());
    QVERIFY(boxName.isEmpty());
    QApplication::processEvents(); // let the unused answer run, finding no box
}

void EditorTest::examplesMenuListsAndOpensExamples()
{
    const QList<QAction*> actions = m_window->examplesMenu()->actions();
    QVERIFY(!actions.isEmpty());
    QStringList titles;
    for (const QAction* action : actions)
        titles << action->text();
    QVERIFY2(titles.contains(QStringLiteral("Default scene")), qPrintable(titles.join(QLatin1Char(','))));
    QCOMPARE(impetus::view::exampleTitle(QStringLiteral("newtons-cradle")), QStringLiteral("Newton's cradle"));
    QCOMPARE(impetus::view::exampleTitle(QStringLiteral("block-on-incline")), QStringLiteral("Block on incline"));

    for (QAction* action : actions) {
        if (action->text() == QStringLiteral("Default scene"))
            action->trigger();
    }
    const model::SceneLoadResult expected = impetus::view::loadScene(QString::fromLatin1(impetus::view::kDefaultScenePath));
    QVERIFY(expected.ok());
    QVERIFY(m_window->runner().world() == *expected.world);
    QCOMPARE(m_window->sceneName(), QStringLiteral("Default scene"));
    QVERIFY(m_window->document().filePath().isEmpty());
}

void EditorTest::dockLayoutIsRemembered()
{
    QDockWidget* dock = m_window->findChild<QDockWidget*>(QStringLiteral("attributesDock"));
    QVERIFY(dock);
    QCOMPARE(m_window->dockWidgetArea(dock), Qt::RightDockWidgetArea);
    QVERIFY(!dock->isHidden());
    m_window->addDockWidget(Qt::LeftDockWidgetArea, dock);
    QVERIFY(m_window->close());

    auto second = std::make_unique<MainWindow>();
    second->show();
    QVERIFY(QTest::qWaitForWindowExposed(second.get()));
    QDockWidget* restored = second->findChild<QDockWidget*>(QStringLiteral("attributesDock"));
    QCOMPARE(second->dockWidgetArea(restored), Qt::LeftDockWidgetArea);

    // Hidden stays hidden.
    restored->hide();
    QVERIFY(second->close());
    MainWindow third;
    third.show();
    QVERIFY(QTest::qWaitForWindowExposed(&third));
    QVERIFY(third.attributesDock()->isHidden());
    third.attributesDock()->show();
    QVERIFY(third.close());
}

void EditorTest::screenshotRendersRedWithoutSelection()
{
    // The screenshot canvas shows the runner alone: colliding bodies red, no tool, no selection.
    impetus::view::SimulationRunner runner;
    model::World world = approachingDiscs();
    runner.setWorld(world);
    CanvasView canvas(runner);
    while (!runner.world().bodies[0].colliding && runner.world().stepCount < 1000)
        runner.stepBy(1);
    const QImage image = impetus::view::renderCanvasImage(canvas, QSize(400, 300));
    const Vec2 p = runner.world().bodies[0].state.position;
    const QPoint inside = canvas.toView(QPointF(p.x(), p.y() + 0.15)).toPoint();
    QVERIFY2(near(image.pixelColor(inside), QColor(0xdc, 0x26, 0x26)), qPrintable(image.pixelColor(inside).name()));
    QCOMPARE(canvas.tool(), nullptr);
}

void EditorTest::undoingAnAttributeEditKeepsTheBodyWhereItIs()
{
    open(test::risingBallWorld());
    CanvasView& canvas = m_window->canvas();
    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, {}, pixelOf(canvas, QPointF(0, 0)));
    QCOMPARE(m_window->document().selection(), (Selection{{0}, {}, {}}));
    const model::World& world = m_window->runner().world();

    // Run, and change the ball's friction in the pane while it runs.
    QTest::keyClick(&canvas, Qt::Key_Space);
    QTRY_VERIFY(world.time > 0.05);
    auto* friction = m_window->propertyPane()->findChild<QLineEdit*>(QStringLiteral("friction"));
    QVERIFY(friction);
    friction->setFocus();
    friction->selectAll();
    QTest::keyClicks(friction, QStringLiteral("0.9"));
    QTest::keyClick(friction, Qt::Key_Return);
    QCOMPARE(world.bodies[0].material.friction, 0.9);
    QVERIFY(m_window->runner().isRunning());

    // The ball rises on; pause, then undo the friction change from the canvas.
    const double editedAt = world.time;
    QTRY_VERIFY(world.time > editedAt + 0.05);
    canvas.setFocus();
    QTest::keyClick(&canvas, Qt::Key_Space);
    QVERIFY(!m_window->runner().isRunning());
    const model::BodyState now = world.bodies[0].state;
    QVERIFY(now.position.y() > editedAt + 0.04); // 1 m/s upward since t = 0
    QCOMPARE(shownText(m_window->undoAction()), QStringLiteral("Undo Change friction"));
    QTest::keyClick(&canvas, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(world.bodies[0].material.friction, 0.5);
    QCOMPARE(world.bodies[0].state, now);
    QCOMPARE(canvas.bodyItems()[0]->scenePos(), QPointF(now.position.x(), now.position.y()));

    // Redo puts the friction back, and leaves the ball where it is too.
    QTest::keyClick(&canvas, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(world.bodies[0].material.friction, 0.9);
    QCOMPARE(world.bodies[0].state, now);
}

void EditorTest::pinHingeFieldShowsAndEditsTheHingeWhereItIsNow()
{
    // Two planks hinged end to end at the origin, no gravity.
    model::World world = emptyWorld();
    world.bodies.push_back(test::makeBody("left", model::Box{1, 0.4}, Vec2(-0.5, 0)));
    world.bodies.push_back(test::makeBody("right", model::Box{1, 0.4}, Vec2(0.5, 0)));
    world.joints.push_back(test::pinAt(world, model::BodyId{0}, model::BodyId{1}, Vec2(0, 0)));
    open(world);
    CanvasView& canvas = m_window->canvas();

    // Drag the left plank away: the hinge, a point of that plank, goes with it.
    drag(canvas.viewport(), pixelOf(canvas, QPointF(-0.5, 0)), pixelOf(canvas, QPointF(-1.5, 0.8)));
    const model::World& now = m_window->runner().world();
    const Vec2 hinge = now.bodies[0].worldPoint(now.joints[0].anchorA);
    QVERIFY((hinge - Vec2(-1, 0.8)).norm() < 0.05);

    // The pane shows the hinge where it is now, not where the pin was made.
    m_window->document().setSelection(Selection{{}, {}, {0}});
    auto* hingeX = m_window->propertyPane()->findChild<QLineEdit*>(QStringLiteral("pinAnchorX"));
    auto* hingeY = m_window->propertyPane()->findChild<QLineEdit*>(QStringLiteral("pinAnchorY"));
    QVERIFY(hingeX && hingeY && hingeX->isVisible());
    QVERIFY2(qAbs(hingeX->text().toDouble() - hinge.x()) < 1e-5, qPrintable(hingeX->text()));
    QVERIFY2(qAbs(hingeY->text().toDouble() - hinge.y()) < 1e-5, qPrintable(hingeY->text()));

    // Move the hinge 0.1 m up along the joint line by typing its y: x stays where it is now, and
    // both planks get their anchor on the new point, so nothing pulls them anywhere.
    const Vec2 moved(hinge.x(), hinge.y() + 0.1);
    hingeY->setFocus();
    hingeY->selectAll();
    QTest::keyClicks(hingeY, QString::number(moved.y(), 'g', 17));
    QTest::keyClick(hingeY, Qt::Key_Return);
    const model::Joint& edited = now.joints[0];
    const Vec2 onLeft = now.bodies[0].worldPoint(edited.anchorA);
    const Vec2 onRight = now.bodies[1].worldPoint(edited.anchorB);
    QVERIFY2((onLeft - moved).norm() < 1e-9, qPrintable(QStringLiteral("%1, %2").arg(onLeft.x()).arg(onLeft.y())));
    QVERIFY2((onRight - moved).norm() < 1e-9, qPrintable(QStringLiteral("%1, %2").arg(onRight.x()).arg(onRight.y())));
    const Vec2 leftBefore = now.bodies[0].state.position;
    const Vec2 rightBefore = now.bodies[1].state.position;
    canvas.setFocus();
    QTest::keyClick(&canvas, Qt::Key_Right);
    QCOMPARE(now.stepCount, std::int64_t(1));
    QVERIFY((now.bodies[0].state.position - leftBefore).norm() < 1e-9);
    QVERIFY((now.bodies[1].state.position - rightBefore).norm() < 1e-9);
}

void EditorTest::spaceOnTheFixedCheckBoxTogglesItAndDoesNotPlay()
{
    model::World world = emptyWorld();
    world.bodies.push_back(test::makeBody("crate", model::Box{1, 1}, Vec2(0, 0)));
    open(world);
    CanvasView& canvas = m_window->canvas();
    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, {}, pixelOf(canvas, QPointF(0, 0)));
    QCOMPARE(m_window->document().selection(), (Selection{{0}, {}, {}}));

    // A keyboard user tabs to "Fixed" and presses Space: the box is fixed, nothing plays.
    auto* fixed = m_window->propertyPane()->findChild<QCheckBox*>(QStringLiteral("fixed"));
    QVERIFY(fixed && fixed->isVisible() && !fixed->isChecked());
    fixed->setFocus(Qt::TabFocusReason);
    QVERIFY(fixed->hasFocus());
    QTest::keyClick(fixed, Qt::Key_Space);
    QVERIFY(fixed->isChecked());
    QVERIFY(m_window->runner().world().bodies[0].fixed);
    QVERIFY(!m_window->runner().isRunning());
    // The menus still show the shortcut, and on the canvas Space still plays.
    QCOMPARE(m_window->playAction()->shortcut(), QKeySequence(Qt::Key_Space));
    canvas.setFocus();
    QTest::keyClick(&canvas, Qt::Key_Space);
    QVERIFY(m_window->runner().isRunning());
    QTest::keyClick(&canvas, Qt::Key_Space);
    QVERIFY(!m_window->runner().isRunning());
}

void EditorTest::deleteAndArrowsInTheVertexTableStayInTheTable()
{
    model::World world = emptyWorld();
    world.bodies.push_back(
        test::makeBody("wedge", model::Polygon{{Vec2(0, 0), Vec2(2, 0), Vec2(2, 1)}}, Vec2(0, 0)));
    open(world);
    CanvasView& canvas = m_window->canvas();
    m_window->document().setSelection(Selection{{0}, {}, {}});
    auto* table = m_window->propertyPane()->findChild<QTableWidget*>(QStringLiteral("vertices"));
    QVERIFY(table && table->isVisible());
    table->setFocus(Qt::TabFocusReason);
    table->setCurrentCell(1, 0);

    // Delete in the table is the table's: the body stays. → moves to the next cell, not a step.
    QTest::keyClick(table, Qt::Key_Delete);
    QCOMPARE(m_window->runner().world().bodies.size(), std::size_t(1));
    QTest::keyClick(table, Qt::Key_Right);
    QCOMPARE(table->currentColumn(), 1);
    QCOMPARE(m_window->runner().world().stepCount, std::int64_t(0));
    // Tool letters and R do not act from the table either.
    QTest::keyClick(table, Qt::Key_B);
    QCOMPARE(canvas.toolKind(), ToolKind::Select);

    // On the canvas, Delete deletes.
    canvas.setFocus();
    QTest::keyClick(&canvas, Qt::Key_Delete);
    QVERIFY(m_window->runner().world().bodies.empty());
}

void EditorTest::deletingOrMovingAPartnerEndsTheRed()
{
    // Two blue discs touching at the origin, at rest, no gravity; far away a disc touching a floor.
    model::World world = emptyWorld();
    for (const double x : {-0.3, 0.3}) {
        model::Body disc = test::makeBody(x < 0 ? "left" : "right", model::Circle{0.3}, Vec2(x, 0));
        disc.color = model::Color{0x1d, 0x4e, 0xd8};
        world.bodies.push_back(disc);
    }
    world.bodies.push_back(test::makeBody("floor", model::Box{2, 0.5}, Vec2(5, -0.55), true));
    world.bodies.push_back(test::makeBody("rester", model::Circle{0.3}, Vec2(5, 0)));
    open(world);
    CanvasView& canvas = m_window->canvas();
    const QColor blue(0x1d, 0x4e, 0xd8);
    const QColor red(0xdc, 0x26, 0x26);
    const auto colourAt = [&](const QPointF& scene) {
        return canvas.viewport()->grab().toImage().pixelColor(pixelOf(canvas, scene));
    };
    const model::World& now = m_window->runner().world();

    QTest::keyClick(&canvas, Qt::Key_Right);
    QVERIFY(now.bodies[0].colliding && now.bodies[1].colliding);
    QVERIFY(now.bodies[2].colliding && now.bodies[3].colliding);
    QVERIFY2(near(colourAt(QPointF(-0.3, 0.15)), red), qPrintable(colourAt(QPointF(-0.3, 0.15)).name()));

    // Delete the right disc: the left one touches nothing any more and is blue again.
    QTest::mouseClick(canvas.viewport(), Qt::LeftButton, {}, pixelOf(canvas, QPointF(0.4, 0)));
    QCOMPARE(m_window->document().selection(), (Selection{{1}, {}, {}}));
    QTest::keyClick(&canvas, Qt::Key_Delete);
    QCOMPARE(now.bodies.size(), std::size_t(3));
    QVERIFY(!now.bodies[0].colliding);
    QVERIFY2(near(colourAt(QPointF(-0.3, 0.15)), blue), qPrintable(colourAt(QPointF(-0.3, 0.15)).name()));
    // The disc resting on the floor far away still touches it, and stays red.
    QVERIFY(now.bodies[1].colliding && now.bodies[2].colliding);
    QVERIFY2(near(colourAt(QPointF(5, 0.15)), red), qPrintable(colourAt(QPointF(5, 0.15)).name()));
    QCOMPARE(now.contacts.size(), std::size_t(1));
    QCOMPARE(now.contacts[0].bodyA.index, 1u);
    QCOMPARE(now.contacts[0].bodyB.index, 2u);

    // Undo brings it back; a step makes both red; dragging the right one away ends the contact
    // for both at once, before any step.
    QTest::keyClick(&canvas, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(now.bodies.size(), std::size_t(4));
    QVERIFY(now.bodies[3].colliding);
    QTest::keyClick(&canvas, Qt::Key_Escape);
    QTest::keyClick(&canvas, Qt::Key_Right);
    QVERIFY(now.bodies[0].colliding && now.bodies[1].colliding);
    drag(canvas.viewport(), pixelOf(canvas, QPointF(0.4, 0)), pixelOf(canvas, QPointF(1.6, 0)));
    QVERIFY(now.bodies[1].state.position.x() > 1.2);
    QVERIFY(!now.bodies[0].colliding && !now.bodies[1].colliding);
    QVERIFY(now.bodies[2].colliding && now.bodies[3].colliding);
    QVERIFY2(near(colourAt(QPointF(-0.3, 0.15)), blue), qPrintable(colourAt(QPointF(-0.3, 0.15)).name()));
    const Vec2 right = now.bodies[1].state.position;
    QVERIFY2(near(colourAt(QPointF(right.x(), right.y() + 0.15)), blue),
             qPrintable(colourAt(QPointF(right.x(), right.y() + 0.15)).name()));
}

void EditorTest::everyExampleHasATranslatableTitle()
{
    // Every scene in resources/examples gets its title from the table, through tr(): none is made
    // from its file name, which a translator could not reach.
    MarkingTranslator translator;
    QCoreApplication::installTranslator(&translator);
    const std::vector<impetus::view::ExampleScene> examples = impetus::view::exampleScenes();
    QCoreApplication::removeTranslator(&translator);
    QVERIFY(examples.size() >= 10);
    QStringList titles;
    for (const impetus::view::ExampleScene& example : examples) {
        QVERIFY2(example.title.startsWith(QStringLiteral("«")) && example.title.endsWith(QStringLiteral("»")),
                 qPrintable(example.path + QStringLiteral(": ") + example.title));
        titles << example.title;
    }
    // One title each, and the examples by the names a student looks for.
    titles.removeDuplicates();
    QCOMPARE(titles.size(), static_cast<qsizetype>(examples.size()));
    for (const char* title : {"«Newton's cradle»", "«Pendulum»", "«Billiards break»", "«Spaceship and asteroids»"})
        QVERIFY2(titles.contains(QString::fromUtf8(title)), qPrintable(titles.join(QLatin1Char(','))));
}

void EditorTest::escapeCancelsADragInProgress()
{
    model::World world = emptyWorld();
    world.bodies.push_back(test::makeBody("crate", model::Box{0.6, 0.6}, Vec2(0, 0)));
    open(world);
    CanvasView& canvas = m_window->canvas();
    const model::World before = m_window->runner().world();
    const int commands = m_window->document().undoStack()->count();
    const QPoint onCrate = pixelOf(canvas, QPointF(0, 0));
    const QPoint away = pixelOf(canvas, QPointF(2, 1));

    // Press, drag, Escape, release: nothing is drawn, with every drag tool.
    for (const Qt::Key key : {Qt::Key_B, Qt::Key_C, Qt::Key_E, Qt::Key_K, Qt::Key_L}) {
        QTest::keyClick(&canvas, key);
        QTest::mousePress(canvas.viewport(), Qt::LeftButton, {}, onCrate);
        QTest::mouseMove(canvas.viewport(), (onCrate + away) / 2);
        QTest::mouseMove(canvas.viewport(), away);
        QTest::keyClick(&canvas, Qt::Key_Escape);
        QTest::mouseRelease(canvas.viewport(), Qt::LeftButton, {}, away);
        QVERIFY2(m_window->runner().world() == before, qPrintable(QKeySequence(key).toString()));
        QCOMPARE(m_window->document().undoStack()->count(), commands);
    }

    // A move with the select tool, and a turn with the rotate tool: the crate goes back where it
    // was, and there is nothing to undo.
    for (const Qt::Key key : {Qt::Key_S, Qt::Key_T}) {
        QTest::keyClick(&canvas, key);
        QTest::mousePress(canvas.viewport(), Qt::LeftButton, {}, onCrate + QPoint(5, 5));
        QTest::mouseMove(canvas.viewport(), onCrate + QPoint(40, 60));
        QTest::mouseMove(canvas.viewport(), away);
        QVERIFY(m_window->runner().world().bodies[0].state != before.bodies[0].state);
        QTest::keyClick(&canvas, Qt::Key_Escape);
        QCOMPARE(m_window->runner().world().bodies[0].state, before.bodies[0].state);
        QTest::mouseMove(canvas.viewport(), away + QPoint(10, 0));
        QTest::mouseRelease(canvas.viewport(), Qt::LeftButton, {}, away + QPoint(10, 0));
        QCOMPARE(m_window->runner().world().bodies[0].state, before.bodies[0].state);
        QCOMPARE(m_window->document().undoStack()->count(), commands);
        QCOMPARE(canvas.bodyItems()[0]->scenePos(), QPointF(0, 0));
    }

    // The tools work as before afterwards.
    QTest::keyClick(&canvas, Qt::Key_B);
    drag(canvas.viewport(), away, away + QPoint(40, 40));
    QCOMPARE(m_window->runner().world().bodies.size(), std::size_t(2));
}

void EditorTest::saveWhileRunningPausesAndSavesTheInstantShown()
{
    open(test::risingBallWorld());
    CanvasView& canvas = m_window->canvas();
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("rising.json"));
    QVERIFY(m_window->saveTo(path));

    QTest::keyClick(&canvas, Qt::Key_Space);
    QTRY_VERIFY(m_window->runner().world().time > 0.05);
    QTest::keyClick(&canvas, Qt::Key_S, Qt::ControlModifier);
    // Saving stopped the run, so the file holds the instant on the canvas, and it stays there.
    QVERIFY(!m_window->runner().isRunning());
    QVERIFY(!m_window->playAction()->isChecked());
    const model::SceneLoadResult saved = impetus::view::loadScene(path);
    QVERIFY(saved.ok());
    const Vec2 inFile = saved.world->bodies[0].state.position;
    QVERIFY(inFile.y() > 0.04);
    QCOMPARE(m_window->runner().world().bodies[0].state.position, inFile);
    QCOMPARE(canvas.bodyItems()[0]->scenePos(), QPointF(inFile.x(), inFile.y()));
    QTest::qWait(50);
    QCOMPARE(m_window->runner().world().bodies[0].state.position, inFile);
    QVERIFY(!m_window->isWindowModified());
}

void EditorTest::boxPreviewIsTintedWithItsAlpha()
{
    // The box being dragged out is the preview colour at kPreviewFillAlpha over the canvas.
    CanvasView& canvas = m_window->canvas();
    QTest::keyClick(&canvas, Qt::Key_B);
    const QPoint from(250, 420), to(430, 300), inside(340, 360);
    const QColor paper = canvas.viewport()->grab().toImage().pixelColor(inside);
    QTest::mousePress(canvas.viewport(), Qt::LeftButton, {}, from);
    QTest::mouseMove(canvas.viewport(), to);
    const QColor tinted = canvas.viewport()->grab().toImage().pixelColor(inside);
    const double alpha = impetus::view::constants::kPreviewFillAlpha;
    const QColor preview = impetus::view::constants::kPreviewColor;
    const auto blend = [&](int under, int over) { return static_cast<int>(std::lround(under * (1 - alpha) + over * alpha)); };
    const QColor expected(blend(paper.red(), preview.red()), blend(paper.green(), preview.green()),
                          blend(paper.blue(), preview.blue()));
    QVERIFY2(near(tinted, expected, 3), qPrintable(tinted.name() + QStringLiteral(" vs ") + expected.name()));
    QTest::mouseRelease(canvas.viewport(), Qt::LeftButton, {}, to);
}

QTEST_MAIN(EditorTest)
#include "editor_test.moc"
