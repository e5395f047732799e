// Soft bodies in the window: drawn as their deformed outline, their ellipses and strain on
// request (View menu), and the density and substeps shown in the status bar.

#include "controller/soft/soft_body_shape.h"
#include "test_settings.h"
#include "test_worlds.h"
#include "view/body_item.h"
#include "view/canvas_view.h"
#include "view/main_window.h"
#include "view/property_pane.h"
#include "view/scene_document.h"
#include "view/simulation_runner.h"
#include "view/soft_detail_item.h"

#include <QAction>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QTimer>
#include <QTest>

#include <cmath>

using namespace impetus;
using view::MainWindow;

namespace {

/// A 1 m soft box (64 ellipses per m²) just above a fixed floor, a rigid ball beside it, gravity.
model::World softBoxWorld(bool autoDensity = false)
{
    model::World world;
    world.bodies.push_back(view::test::makeBody("floor", model::Box{6, 0.4}, Vec2(0, -0.2), true));
    model::Body jelly = view::test::makeBody("jelly", model::Box{1, 1}, Vec2(0, 0.6));
    model::SoftSettings soft;
    soft.ellipsesPerSquareMeter = 64;
    soft.stiffness = 2000;
    soft.dampingMode = model::SoftDampingMode::Coefficient;
    soft.damping = 5;
    soft.autoDensity = autoDensity;
    jelly.soft = soft;
    jelly.massSpec = model::MassSpec{model::MassMode::Mass, 10};
    jelly.updateDerived();
    world.bodies.push_back(jelly);
    world.bodies.push_back(view::test::makeBody("ball", model::Circle{0.3}, Vec2(2, 0.3)));
    return world;
}

QAction* viewAction(MainWindow& window, const QString& text)
{
    for (QAction* menuAction : window.menuBar()->actions()) {
        if (!menuAction->menu())
            continue;
        for (QAction* action : menuAction->menu()->actions()) {
            if (action->text().remove(QLatin1Char('&')) == text)
                return action;
        }
    }
    return nullptr;
}

} // namespace

class SoftViewTest : public QObject {
    Q_OBJECT

private slots:
    void softBodyIsDrawnAsItsDeformedOutline();
    void viewMenuShowsEllipsesAndStrain();
    void statusBarShowsDensityAndAutoChoice();
    void strainColoursRunBlueGreyRed();
    void compareSoftWithRigidFromTheMenu();

private:
    view::test::TemporarySettings m_settings;
};

void SoftViewTest::softBodyIsDrawnAsItsDeformedOutline()
{
    MainWindow window;
    window.setScene(softBoxWorld(), QStringLiteral("soft"));
    const model::World& world = window.runner().world();
    // The grid exists as soon as the scene is shown, before any step.
    const model::SoftGrid* grid = world.softGrid(model::BodyId{1});
    QVERIFY(grid);
    QCOMPARE(grid->size(), std::size_t(64));
    view::CanvasView& canvas = window.canvas();
    QVERIFY(canvas.softItems()[1] != nullptr);
    QVERIFY(canvas.softItems()[0] == nullptr && canvas.softItems()[2] == nullptr);

    // Let it land and squash: the item's outline is the grid's outline, mapped into the body frame.
    window.runner().stepBy(150);
    const model::Body& jelly = world.bodies[1];
    const std::vector<Vec2> outline = controller::softOutline(world, *world.softGrid(model::BodyId{1}));
    const QPainterPath drawn = canvas.bodyItems()[1]->mapToScene(canvas.bodyItems()[1]->shape());
    QVERIFY(outline.size() >= 4);
    for (const Vec2& p : outline)
        QVERIFY2(drawn.boundingRect().adjusted(-1e-6, -1e-6, 1e-6, 1e-6).contains(QPointF(p.x(), p.y())),
                 "the drawn outline holds every point of the grid's outline");
    // A rigid 1 m box would span exactly 1 m; the landed soft one is squashed or spread a little.
    const QRectF box = drawn.boundingRect();
    QVERIFY(std::abs(box.height() - 1.0) > 1e-4 || std::abs(box.width() - 1.0) > 1e-4);
    QVERIFY(std::abs(box.center().y() - jelly.state.position.y()) < 0.1);
}

void SoftViewTest::viewMenuShowsEllipsesAndStrain()
{
    MainWindow window;
    window.setScene(softBoxWorld(), QStringLiteral("soft"));
    QAction* ellipses = viewAction(window, QStringLiteral("Show Soft-Body Ellipses"));
    QAction* strain = viewAction(window, QStringLiteral("Show Soft-Body Strain"));
    QVERIFY(ellipses && strain);
    view::SoftDetailItem* detail = window.canvas().softItems()[1];
    QVERIFY(!detail->showsEllipses() && !detail->showsSprings());

    ellipses->trigger();
    QVERIFY(detail->showsEllipses());
    strain->trigger();
    QVERIFY(detail->showsSprings());
    // One spring view per grid spring, structural and shear: 2·7·8 + 2·7·7 for an 8 × 8 grid.
    QCOMPARE(detail->springs().size(), std::size_t(2 * 7 * 8 + 2 * 7 * 7));

    // Drawn: the ellipse outlines darken the body's fill inside its outline.
    window.resize(800, 600);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    const QImage withDetail = window.canvas().grab().toImage();
    ellipses->trigger();
    strain->trigger();
    QVERIFY(!detail->showsEllipses() && !detail->showsSprings());
    const QImage without = window.canvas().grab().toImage();
    QVERIFY(withDetail != without);
}

void SoftViewTest::statusBarShowsDensityAndAutoChoice()
{
    MainWindow window;
    window.setScene(softBoxWorld(), QStringLiteral("soft"));
    auto* label = window.findChild<QLabel*>(QStringLiteral("softStatus"));
    QVERIFY(label);
    QVERIFY(!label->isHidden());
    QVERIFY(label->text().contains(QStringLiteral("jelly: 64/m²")));
    QVERIFY(!label->text().contains(QStringLiteral("auto")));

    // "auto" is measured when the scene is put in, and the choice is shown.
    window.setScene(softBoxWorld(true), QStringLiteral("soft auto"));
    const model::SoftGrid* grid = window.runner().world().softGrid(model::BodyId{1});
    QVERIFY(grid);
    QVERIFY(grid->ellipsesPerSquareMeter >= 64 && grid->ellipsesPerSquareMeter <= 1024);
    QVERIFY(label->text().contains(QStringLiteral("(auto)")));
    // In the locale's number format, as every readout (1,024 in English, 1.024 in German).
    QVERIFY(label->text().contains(QLocale().toString(grid->ellipsesPerSquareMeter, 'g', 4)));
    // The pane says it too, once the body is selected.
    window.document().setSelection(view::Selection{{1}, {}, {}});
    auto* paneGrid = window.propertyPane()->findChild<QLabel*>(QStringLiteral("softGrid"));
    QVERIFY(paneGrid);
    QVERIFY(paneGrid->isVisible() || !window.isVisible());
    QVERIFY(paneGrid->text().contains(QStringLiteral("auto")));
    QVERIFY(paneGrid->text().contains(QLocale().toString(static_cast<qulonglong>(grid->size()))));

    // A world without soft bodies hides it.
    model::World rigid = softBoxWorld();
    rigid.bodies[1].soft.reset();
    rigid.bodies[1].updateDerived();
    window.setScene(rigid, QStringLiteral("rigid"));
    QVERIFY(label->isHidden());
}

void SoftViewTest::strainColoursRunBlueGreyRed()
{
    const QColor rest = view::SoftDetailItem::strainColour(0);
    QCOMPARE(rest.red(), rest.blue());
    const QColor squashed = view::SoftDetailItem::strainColour(-0.2);
    QVERIFY(squashed.blue() > 200 && squashed.red() < 40);
    const QColor stretched = view::SoftDetailItem::strainColour(0.2);
    QVERIFY(stretched.red() > 200 && stretched.blue() < 40);
    const QColor slight = view::SoftDetailItem::strainColour(0.05);
    QVERIFY(slight.red() > rest.red() && slight.red() < stretched.red());
}

void SoftViewTest::compareSoftWithRigidFromTheMenu()
{
    MainWindow window;
    window.setScene(softBoxWorld(), QStringLiteral("soft"));
    QAction* compare = viewAction(window, QStringLiteral("Compare Soft with Rigid…"));
    QVERIFY(compare);
    // Only for one soft body.
    window.document().setSelection(view::Selection{{2}, {}, {}});
    QVERIFY(!compare->isEnabled());
    window.document().setSelection(view::Selection{{1}, {}, {}});
    QVERIFY(compare->isEnabled());

    const model::World before = window.runner().world();
    QString seenTitle;
    QTimer::singleShot(0, &window, [&] {
        auto* box = window.findChild<QMessageBox*>(QStringLiteral("compareRigidBox"));
        if (box) {
            seenTitle = box->windowTitle();
            box->accept();
        }
    });
    compare->trigger();
    QCOMPARE(seenTitle, QStringLiteral("Soft against rigid"));
    QVERIFY(window.lastComparison().has_value());
    const controller::RigidSoftComparison& result = *window.lastComparison();
    QVERIFY(result.samples.size() >= 20);
    QCOMPARE(result.ellipses, std::size_t(64));
    // Both start at the same centre of mass; the soft one lands softer, so they drift apart.
    QVERIFY(result.samples.front().distance < 1e-9);
    QVERIFY(result.maxDistance > 1e-4);
    QVERIFY(result.rmsDistance <= result.maxDistance);
    // The comparison ran on copies: the scene has not moved.
    QCOMPARE(window.runner().world(), before);
}

QTEST_MAIN(SoftViewTest)
#include "soft_view_test.moc"
