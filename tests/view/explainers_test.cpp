// The Explain menu driven as a user would: select two bodies with the mouse, open Explain ›
// Separating Axes, step through the axes with N and P, close with Esc; open the Collision
// Inspector, step into an impact and click its entry. Every number checked is the narrow phase's
// or the contact solver's own, and the hand-worked ones are worked in the comments.

#include "test_settings.h"
#include "test_worlds.h"
#include "controller/collision/narrow_phase.h"
#include "view/canvas_view.h"
#include "view/collision_inspector.h"
#include "view/main_window.h"
#include "view/sat_explainer.h"
#include "view/scene_document.h"
#include "view/simulation_runner.h"

#include <QAction>
#include <QDockWidget>
#include <QListWidget>
#include <QTest>

#include <cmath>
#include <numbers>
#include <vector>

using namespace impetus;
using namespace impetus::view;

namespace {

constexpr double kExact = 1e-12;

/// Two bodies in zero gravity, for the explainer (nothing moves unless stepped).
model::World pairWorld(model::Body a, model::Body b)
{
    model::World world;
    world.settings.gravity = Vec2::Zero();
    world.bodies.push_back(std::move(a));
    world.bodies.push_back(std::move(b));
    return world;
}

/// The outward unit normals of a counter-clockwise polygon, as the narrow phase takes them.
std::vector<Vec2> normalsOf(const std::vector<Vec2>& vertices)
{
    std::vector<Vec2> normals;
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const Vec2 e = vertices[(i + 1) % vertices.size()] - vertices[i];
        normals.push_back(Vec2(e.y(), -e.x()).normalized());
    }
    return normals;
}

} // namespace

class ExplainersTest : public QObject {
    Q_OBJECT

private slots:
    void boxesOverlappingAlongX();
    void rotatedCornerIntoAFace();
    void separatedPairShowsItsSeparatingAxis();
    void circleAndBoxUseTheClosestFeature();
    void ellipseOnABoxSaysItUsesGjkWithTheDepth();
    void concavePolygonShowsEachPairOfPieces();
    void explainerFollowsStepAndStepBack();
    void editsWithTheExplainerAndTheGhostsOpen();
    void inspectorReproducesTheLoggedImpulse();

private:
    /// Shows `world`, clicks `first` and Shift-clicks `second` (scene points, m) and opens Explain ›
    /// Separating Axes. Returns the explainer, open.
    SatExplainer* openOn(MainWindow& window, const model::World& world, Vec2 first, Vec2 second);
    /// Checks that every axis the explainer shows carries the number the narrow phase gives for the
    /// same two pieces when asked directly.
    static void checkAgainstNarrowPhase(const controller::PiecePairTrace& shown);
    static bool showActive(MainWindow& window);

    test::TemporarySettings m_settings;
};

bool ExplainersTest::showActive(MainWindow& window)
{
    window.resize(900, 650);
    window.show();
    window.activateWindow();
    return QTest::qWaitForWindowActive(&window);
}

SatExplainer* ExplainersTest::openOn(MainWindow& window, const model::World& world, Vec2 first, Vec2 second)
{
    window.setScene(world, QStringLiteral("pair"));
    if (!showActive(window))
        return nullptr;
    CanvasView& canvas = window.canvas();
    QWidget* viewport = canvas.viewport();
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, canvas.toView(QPointF(first.x(), first.y())).toPoint());
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::ShiftModifier,
                      canvas.toView(QPointF(second.x(), second.y())).toPoint());
    auto* action = window.findChild<QAction*>(QStringLiteral("separatingAxesAction"));
    if (action == nullptr || !action->isEnabled())
        return nullptr;
    action->trigger();
    auto* explainer = window.findChild<SatExplainer*>(QStringLiteral("satExplainer"));
    return explainer != nullptr && explainer->isOpen() ? explainer : nullptr;
}

void ExplainersTest::checkAgainstNarrowPhase(const controller::PiecePairTrace& shown)
{
    controller::CollisionTrace direct;
    const auto shapeOf = [](const controller::TracedPiece& piece, std::vector<Vec2>& normals) -> controller::ConvexShape {
        if (piece.kind == controller::ColliderPiece::Kind::Circle)
            return controller::CircleShape{piece.center, piece.radiusX};
        normals = normalsOf(piece.vertices);
        return controller::PolygonShape{piece.vertices, normals, piece.center};
    };
    std::vector<Vec2> normalsA;
    std::vector<Vec2> normalsB;
    const controller::Manifold m =
        controller::collide(shapeOf(shown.a, normalsA), shapeOf(shown.b, normalsB), 0.0, &direct);
    QCOMPARE(shown.trace.axes.size(), direct.axes.size());
    for (std::size_t k = 0; k < direct.axes.size(); ++k) {
        QVERIFY(std::abs(shown.trace.axes[k].separation - direct.axes[k].separation) < kExact);
        QVERIFY((shown.trace.axes[k].normal - direct.axes[k].normal).norm() < kExact);
    }
    QCOMPARE(shown.trace.separatingAxis, direct.separatingAxis);
    QCOMPARE(shown.trace.contactAxis, direct.contactAxis);
    QCOMPARE(shown.trace.result.count, m.count);
}

void ExplainersTest::boxesOverlappingAlongX()
{
    // A = [0, 2]×[0, 1], B = [1.5, 3.5]×[0.2, 1.2]: they overlap 0.5 m along x and 0.8 m along y,
    // so the axis of least overlap is x (A's right face, tied with B's left face; A's is kept),
    // and the minimum translation vector is 500 mm along (1, 0).
    MainWindow window;
    SatExplainer* explainer = openOn(window,
                                     pairWorld(test::makeBody("A", model::Box{2, 1}, Vec2(1, 0.5)),
                                               test::makeBody("B", model::Box{2, 1}, Vec2(2.5, 0.7))),
                                     Vec2(0.4, 0.5), Vec2(3.2, 0.7));
    QVERIFY(explainer != nullptr);
    QCOMPARE(explainer->traces().size(), std::size_t{1});
    const controller::PiecePairTrace& pair = *explainer->current();
    QCOMPARE(pair.trace.method, controller::TraceMethod::Sat);
    QCOMPARE(pair.trace.axes.size(), std::size_t{8}); // every face normal of both boxes
    checkAgainstNarrowPhase(pair);
    QVERIFY(explainer->panelText().contains(QStringLiteral("Axis 1 of 8")));

    // N steps to the axis of least overlap; the panel shows its overlap in mm.
    const std::size_t least = *pair.trace.contactAxis;
    QVERIFY(std::abs(pair.trace.axes[least].separation + 0.5) < kExact);
    QVERIFY((pair.trace.axes[least].normal - Vec2(1, 0)).norm() < kExact);
    CanvasView& canvas = window.canvas();
    for (std::size_t k = 0; k < least; ++k)
        QTest::keyClick(&canvas, Qt::Key_N);
    QCOMPARE(explainer->currentAxis(), least);
    QVERIFY2(explainer->panelText().contains(QStringLiteral("Overlap on this axis: 500.000 mm")),
             qPrintable(explainer->panelText()));
    QVERIFY(explainer->panelText().contains(QStringLiteral("axis of least overlap")));
    // N did not switch to the Pin tool while the explainer had it.
    QCOMPARE(canvas.toolKind(), ToolKind::Select);

    // Past the last axis: the summary with the MTV, the faces and the two clipped contact points.
    while (explainer->currentAxis() < pair.trace.axes.size())
        QTest::keyClick(&canvas, Qt::Key_N);
    const QString summary = explainer->panelText();
    QVERIFY2(summary.contains(QStringLiteral("Minimum translation vector: 500.000 mm along (1.000, 0.000)")),
             qPrintable(summary));
    QVERIFY(summary.contains(QStringLiteral("kept (touching): 2")));
    QCOMPARE(pair.trace.result.count, 2);
    QTest::keyClick(&canvas, Qt::Key_P);
    QCOMPARE(explainer->currentAxis(), pair.trace.axes.size() - 1);
    QTest::keyClick(&canvas, Qt::Key_Escape);
    QVERIFY(!explainer->isOpen());
    QVERIFY(window.canvas().viewport()->findChild<QWidget*>(QStringLiteral("satExplainerPanel")) == nullptr);
}

void ExplainersTest::rotatedCornerIntoAFace()
{
    // A unit square turned 45° whose lowest corner is 0.1 m into a fixed slab's top face (y = 0):
    // the least overlap is 100 mm along (0, 1), at one point.
    const Scalar h = std::sqrt(0.5);
    model::World world = pairWorld(test::makeBody("ground", model::Box{4, 1}, Vec2(0, -0.5), true),
                                   test::makeBody("diamond", model::Box{1, 1}, Vec2(0, h - 0.1)));
    world.bodies[1].state.angle = std::numbers::pi / 4;
    MainWindow window;
    SatExplainer* explainer = openOn(window, world, Vec2(-1.5, -0.5), Vec2(0, h));
    QVERIFY(explainer != nullptr);
    const controller::PiecePairTrace& pair = *explainer->current();
    checkAgainstNarrowPhase(pair);
    const controller::TracedAxis& least = pair.trace.axes[*pair.trace.contactAxis];
    QVERIFY(std::abs(least.separation + 0.1) < kExact);
    QVERIFY((pair.trace.result.normal - Vec2(0, 1)).norm() < kExact);
    QCOMPARE(pair.trace.result.count, 1);
    while (explainer->currentAxis() < pair.trace.axes.size())
        QTest::keyClick(&window.canvas(), Qt::Key_N);
    QVERIFY2(explainer->panelText().contains(QStringLiteral("Minimum translation vector: 100.000 mm")),
             qPrintable(explainer->panelText()));
}

void ExplainersTest::separatedPairShowsItsSeparatingAxis()
{
    // Unit boxes 0.2 m apart along x: A's bottom face (−1 m) does not separate them, its right
    // face does (+200 mm), and the narrow phase stops there after two axes.
    MainWindow window;
    SatExplainer* explainer = openOn(window,
                                     pairWorld(test::makeBody("left", model::Box{1, 1}, Vec2(0.5, 0.5)),
                                               test::makeBody("right", model::Box{1, 1}, Vec2(1.7, 0.5))),
                                     Vec2(0.5, 0.5), Vec2(1.7, 0.5));
    QVERIFY(explainer != nullptr);
    const controller::PiecePairTrace& pair = *explainer->current();
    checkAgainstNarrowPhase(pair);
    QVERIFY(pair.trace.separatingAxis.has_value());
    QCOMPARE(pair.trace.axes.size(), *pair.trace.separatingAxis + 1);
    QVERIFY(std::abs(pair.trace.axes[*pair.trace.separatingAxis].separation - 0.2) < kExact);
    QCOMPARE(pair.trace.result.count, 0);
    while (explainer->currentAxis() < *pair.trace.separatingAxis)
        QTest::keyClick(&window.canvas(), Qt::Key_N);
    QVERIFY2(explainer->panelText().contains(QStringLiteral("Gap on this axis: 200.000 mm")),
             qPrintable(explainer->panelText()));
    QVERIFY(explainer->panelText().contains(QStringLiteral("This axis separates the shapes")));
}

void ExplainersTest::circleAndBoxUseTheClosestFeature()
{
    // A ball of radius 0.5 whose centre is 0.4 m above a slab's top face, in its face region: the
    // face normal (0, 1) is the closest-feature axis, overlap 100 mm. The ball is body 0, so it is
    // A and the normal points from it down into the slab.
    model::World world = pairWorld(test::makeBody("ball", model::Circle{0.5}, Vec2(0.3, 0.4)),
                                   test::makeBody("slab", model::Box{4, 1}, Vec2(0, -0.5), true));
    MainWindow window;
    SatExplainer* explainer = openOn(window, world, Vec2(0.3, 0.6), Vec2(-1.5, -0.5));
    QVERIFY(explainer != nullptr);
    const controller::PiecePairTrace& pair = *explainer->current();
    QCOMPARE(pair.trace.method, controller::TraceMethod::PolygonCircle);
    checkAgainstNarrowPhase(pair);
    const controller::TracedAxis& closest = pair.trace.axes[*pair.trace.contactAxis];
    QCOMPARE(closest.owner, 1); // the slab's face
    QVERIFY(std::abs(closest.separation + 0.1) < kExact);
    QVERIFY((pair.trace.result.normal - Vec2(0, -1)).norm() < kExact);
    QVERIFY(explainer->panelText().contains(QStringLiteral("closest to the circle's centre")));
    while (explainer->currentAxis() < pair.trace.axes.size())
        QTest::keyClick(&window.canvas(), Qt::Key_N);
    QVERIFY2(explainer->panelText().contains(QStringLiteral("Least overlap")) &&
                 explainer->panelText().contains(QStringLiteral("100.000 mm")),
             qPrintable(explainer->panelText()));
}

// An ellipse has no faces: the panel says that GJK and EPA found the contact, and gives EPA's
// depth and normal, which are the narrow phase's. An ellipse of semi-axes 0.6 × 0.3 m whose centre
// is 0.25 m above a slab's top face overlaps it by 50 mm, straight down.
void ExplainersTest::ellipseOnABoxSaysItUsesGjkWithTheDepth()
{
    model::World world = pairWorld(test::makeBody("egg", model::Ellipse{0.6, 0.3}, Vec2(0, 0.25)),
                                   test::makeBody("slab", model::Box{4, 1}, Vec2(0, -0.5), true));
    MainWindow window;
    SatExplainer* explainer = openOn(window, world, Vec2(0, 0.3), Vec2(-1.5, -0.5));
    QVERIFY(explainer != nullptr);
    const controller::PiecePairTrace& pair = *explainer->current();
    QCOMPARE(pair.trace.method, controller::TraceMethod::Gjk);
    QVERIFY(pair.trace.result.count > 0);
    const double depth = -pair.trace.result.points[0].separation;
    QVERIFY2(std::abs(depth - 0.05) < 1e-5, qPrintable(QString::number(depth, 'g', 12))); // EPA to 0.001 mm
    QVERIFY((pair.trace.result.normal - Vec2(0, -1)).norm() < 1e-5); // from the ellipse (A) into the slab
    const QString text = explainer->panelText();
    QVERIFY2(text.contains(QStringLiteral("GJK and EPA")) && text.contains(QStringLiteral("no axes to test")),
             qPrintable(text));
    // The panel's depth is the trace's, in mm to three decimals.
    QVERIFY2(text.contains(QStringLiteral("depth %1 mm").arg(depth * 1000, 0, 'f', 3)), qPrintable(text));
}

// A concave polygon is its convex pieces: an L of two pieces across a box gives one pair per
// pair of pieces, "pair 1 of 2" then "pair 2 of 2", and N steps through the first pair's axes
// into the second's; each pair's numbers are the narrow phase's for those two pieces.
void ExplainersTest::concavePolygonShowsEachPairOfPieces()
{
    // An L, 2 m wide and 2 m tall, its arms 0.6 m thick, standing on a slab it sinks 0.1 m into.
    model::Polygon ell;
    ell.vertices = {Vec2(0, 0), Vec2(2, 0), Vec2(2, 0.6), Vec2(0.6, 0.6), Vec2(0.6, 2), Vec2(0, 2)};
    model::World world = pairWorld(test::makeBody("L", ell, Vec2(0, 0)),
                                   test::makeBody("slab", model::Box{6, 1}, Vec2(0, -0.5), true));
    // The body's frame has its origin at the L's centre of mass, geometry.centroidOffset from the
    // corner the vertices start at: place the corner at (−1, −0.1), the foot 0.1 m in the slab.
    const Vec2 offset = world.bodies[0].geometry.centroidOffset;
    world.bodies[0].state.position = Vec2(-1, -0.1) + offset;
    const Vec2 foot = Vec2(-1, -0.1) + Vec2(1, 0.3); // the middle of the foot
    MainWindow window;
    SatExplainer* explainer = openOn(window, world, foot, Vec2(2.5, -0.5));
    QVERIFY(explainer != nullptr);
    QCOMPARE(explainer->traces().size(), std::size_t{2});
    QVERIFY2(explainer->panelText().contains(QStringLiteral("(pair 1 of 2)")), qPrintable(explainer->panelText()));
    for (const controller::PiecePairTrace& pair : explainer->traces())
        checkAgainstNarrowPhase(pair);
    // Through the first pair's axes and its summary: the second pair.
    const std::size_t firstAxes = explainer->traces()[0].trace.axes.size();
    for (std::size_t k = 0; k <= firstAxes; ++k)
        QTest::keyClick(&window.canvas(), Qt::Key_N);
    QVERIFY2(explainer->panelText().contains(QStringLiteral("(pair 2 of 2)")), qPrintable(explainer->panelText()));
    QTest::keyClick(&window.canvas(), Qt::Key_P);
    QVERIFY2(explainer->panelText().contains(QStringLiteral("(pair 1 of 2)")), qPrintable(explainer->panelText()));
}

// The explainer follows the run: Step (→) moves the pair on, and the axes are traced again on the
// state shown; Step Back (←) brings the first state's numbers back, bit for bit. Two unit boxes
// 0.2 m apart along x, the right one moving away at 1 m/s in zero gravity: 12 steps of 1/240 s
// later the gap on the separating axis is 250 mm.
void ExplainersTest::explainerFollowsStepAndStepBack()
{
    model::Body right = test::makeBody("right", model::Box{1, 1}, Vec2(1.7, 0.5));
    right.state.velocity = Vec2(1, 0);
    MainWindow window;
    SatExplainer* explainer =
        openOn(window, pairWorld(test::makeBody("left", model::Box{1, 1}, Vec2(0.5, 0.5)), right), Vec2(0.5, 0.5),
               Vec2(1.7, 0.5));
    QVERIFY(explainer != nullptr);
    const controller::PiecePairTrace first = *explainer->current();
    QVERIFY(first.trace.separatingAxis.has_value());
    QVERIFY(std::abs(first.trace.axes[*first.trace.separatingAxis].separation - 0.2) < kExact);

    // Step and Step Back from the tool bar: with both bodies selected, the arrow keys nudge them.
    CanvasView& canvas = window.canvas();
    for (int i = 0; i < 12; ++i) {
        window.stepAction()->trigger();
        QTRY_COMPARE(window.runner().world().stepCount, i + 1);
    }
    QVERIFY(explainer->isOpen());
    const controller::PiecePairTrace& moved = *explainer->current();
    checkAgainstNarrowPhase(moved);
    QVERIFY(moved.trace.separatingAxis.has_value());
    QVERIFY(std::abs(moved.trace.axes[*moved.trace.separatingAxis].separation - 0.25) < 1e-9);
    while (explainer->currentAxis() < *moved.trace.separatingAxis)
        QTest::keyClick(&canvas, Qt::Key_N);
    QVERIFY2(explainer->panelText().contains(QStringLiteral("Gap on this axis: 250.000 mm")),
             qPrintable(explainer->panelText()));

    for (int i = 0; i < 12; ++i)
        window.stepBackAction()->trigger();
    QTRY_COMPARE(window.runner().world().stepCount, 0);
    const controller::PiecePairTrace& back = *explainer->current();
    QCOMPARE(back.trace.axes.size(), first.trace.axes.size());
    for (std::size_t k = 0; k < back.trace.axes.size(); ++k)
        QCOMPARE(back.trace.axes[k].separation, first.trace.axes[k].separation);
    QVERIFY2(explainer->panelText().contains(QStringLiteral("Gap on this axis: 200.000 mm")),
             qPrintable(explainer->panelText()));
}

// An edit rebuilds the canvas's items; the explainer's and the integrator ghosts' own items stay
// (the canvas once cleared the whole scene, and the next trace drew into the explainer's deleted
// item: the window crashed on any edit with Separating Axes open). Arrow keys nudge the two
// selected boxes, Undo puts them back, and the explainer follows both.
void ExplainersTest::editsWithTheExplainerAndTheGhostsOpen()
{
    MainWindow window;
    SatExplainer* explainer =
        openOn(window,
               pairWorld(test::makeBody("left", model::Box{1, 1}, Vec2(0.5, 0.5)),
                         test::makeBody("right", model::Box{1, 1}, Vec2(1.7, 0.5))),
               Vec2(0.5, 0.5), Vec2(1.7, 0.5));
    QVERIFY(explainer != nullptr);
    auto* ghosts = window.findChild<QAction*>(QStringLiteral("compareIntegratorsAction"));
    QVERIFY(ghosts != nullptr);
    ghosts->trigger();
    const Vec2 before = explainer->current()->a.center;
    CanvasView& canvas = window.canvas();
    canvas.setFocus();
    QTest::keyClick(&canvas, Qt::Key_Right); // nudges both selected boxes: an edit
    QVERIFY(explainer->isOpen());
    const Vec2 nudged = explainer->current()->a.center;
    QVERIFY2(nudged.x() > before.x() && nudged.y() == before.y(),
             qPrintable(QStringLiteral("%1 -> %2").arg(before.x()).arg(nudged.x())));
    checkAgainstNarrowPhase(*explainer->current());
    QVERIFY(!canvas.viewport()->grab().isNull()); // paints every item, the explainer's too
    window.undoAction()->trigger();
    QVERIFY(explainer->isOpen());
    QCOMPARE(explainer->current()->a.center, before);
    QVERIFY(!canvas.viewport()->grab().isNull());
    ghosts->trigger();
}

void ExplainersTest::inspectorReproducesTheLoggedImpulse()
{
    // The impact worked by hand in tests/controller/impact_formula_test.cpp: a 2 m × 1 m box of
    // 2 kg turned by θ (cos θ = 0.8, sin θ = 0.6), its lowest corner touching a fixed slab, falling
    // at 2 m/s; e = 0.5, μ = 0.2. r_B×n = −0.5, K = 0.5 + 0.25·1.2 = 0.8 1/kg,
    // j = −(1 + 0.5)(−2)/0.8 = 3.75 N·s; friction needs 2.25/1.7 N·s but μj = 0.75: it slides.
    model::World world;
    world.settings.gravity = Vec2::Zero();
    model::Body slab = test::makeBody("slab", model::Box{10, 1}, Vec2(0, -0.5), true);
    slab.material.restitution = 0;
    slab.material.friction = 0.2;
    model::Body box = test::makeBody("box", model::Box{2, 1}, Vec2(0.5, 1.0));
    box.massSpec = {model::MassMode::Mass, 2.0};
    box.state.angle = std::atan2(0.6, 0.8);
    box.state.velocity = Vec2(0, -2);
    box.material.restitution = 0.5;
    box.material.friction = 0.2;
    box.updateDerived();
    world.bodies.push_back(slab);
    world.bodies.push_back(box);

    MainWindow window;
    window.setScene(world, QStringLiteral("impact"));
    QVERIFY(showActive(window));
    auto* action = window.findChild<QAction*>(QStringLiteral("collisionInspectorAction"));
    QVERIFY(action != nullptr);
    action->trigger();
    auto* inspector = window.findChild<CollisionInspector*>(QStringLiteral("collisionInspector"));
    QVERIFY(inspector != nullptr);
    QTRY_VERIFY(inspector->isVisible());
    QVERIFY(inspector->entries().empty());

    // Step once (→ on the canvas): the box strikes the slab; the log gets the entry.
    window.canvas().setFocus();
    QTest::keyClick(&window.canvas(), Qt::Key_Right);
    QTRY_COMPARE(inspector->entries().size(), std::size_t{1});
    QListWidget* list = inspector->list();
    QCOMPARE(list->count(), 1);
    QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::NoModifier,
                      list->visualItemRect(list->item(0)).center());
    QCOMPARE(inspector->selected(), std::optional<int>(0));

    const CollisionLogEntry& entry = inspector->entries()[0];
    const std::optional<controller::ImpactFormula> formula = inspector->selectedFormula();
    QVERIFY(formula.has_value());
    QCOMPARE(formula->count, 1);
    const controller::ImpactFormulaPoint& p = formula->points[0];
    // The formula on the recorded pre-impact state reproduces the logged impulse.
    QVERIFY(std::abs(p.formulaImpulse - entry.event.normalImpulse) < kExact);
    QVERIFY(std::abs(p.formulaImpulse - 3.75) < kExact);
    QVERIFY(std::abs(p.rnB + 0.5) < kExact);
    QVERIFY(std::abs(p.denominator - 0.8) < kExact);
    QVERIFY(std::abs(p.approachSpeed + 2) < kExact);
    QVERIFY(std::abs(p.speedAfter - 1) < kExact);
    QVERIFY(p.slid);
    QVERIFY(std::abs(p.frictionImpulse - 0.75) < kExact);
    QVERIFY(std::abs(formula->before.energy - 4) < kExact);
    QVERIFY(std::abs(formula->after.energy - 0.915625) < kExact);
    const QString text = inspector->formulaText();
    QVERIFY2(text.contains(QStringLiteral("= 3.75 N·s")), qPrintable(text));
    QVERIFY(text.contains(QStringLiteral("/ 0.8 =")));
    QVERIFY(text.contains(QStringLiteral("it slid")));
    QVERIFY(text.contains(QStringLiteral("4 → 0.915625 J")));
}

QTEST_MAIN(ExplainersTest)
#include "explainers_test.moc"
