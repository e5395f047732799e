// The Explain menu, added by MainWindow with one call so that its own code stays small.

#include "view/explain_menu.h"

#include "view/collision_inspector.h"
#include "view/main_window.h"
#include "view/sat_explainer.h"
#include "view/scene_document.h"

#include <QAction>
#include <QDockWidget>
#include <QMenu>
#include <QMenuBar>

namespace impetus::view {

void addExplainers(MainWindow& window)
{
    QMenu* menu = window.menuBar()->addMenu(MainWindow::tr("E&xplain"));
    menu->setObjectName(QStringLiteral("explainMenu"));

    auto* explainer = new SatExplainer(window.canvas(), window.document(), &window);
    explainer->setObjectName(QStringLiteral("satExplainer"));
    QAction* axes = menu->addAction(MainWindow::tr("&Separating Axes"));
    axes->setObjectName(QStringLiteral("separatingAxesAction"));
    axes->setStatusTip(MainWindow::tr("Show how the collision test treats the two selected bodies, axis by axis "
                                      "(N: next, P: previous, Esc: close)"));
    QObject::connect(axes, &QAction::triggered, explainer, [explainer] { explainer->open(); });
    SceneDocument& document = window.document();
    const auto updateAxes = [axes, &document] { axes->setEnabled(document.selection().bodies.size() == 2); };
    QObject::connect(&document, &SceneDocument::selectionChanged, axes, updateAxes);
    updateAxes();

    auto* dock = new QDockWidget(MainWindow::tr("Collision Inspector"), &window);
    dock->setObjectName(QStringLiteral("collisionInspectorDock"));
    auto* inspector = new CollisionInspector(document, window.timeline(), dock);
    inspector->setObjectName(QStringLiteral("collisionInspector"));
    dock->setWidget(inspector);
    window.addDockWidget(Qt::RightDockWidgetArea, dock);
    dock->hide();
    QAction* inspect = dock->toggleViewAction();
    inspect->setText(MainWindow::tr("&Collision Inspector"));
    inspect->setObjectName(QStringLiteral("collisionInspectorAction"));
    inspect->setStatusTip(MainWindow::tr("List the collisions of the run; click one to see its impulse worked out"));
    menu->addAction(inspect);
}

} // namespace impetus::view
