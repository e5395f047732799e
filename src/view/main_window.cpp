#include "view/main_window.h"

#include "controller/diagnostics.h"
#include "controller/soft/soft_stability.h"
#include "controller/soft/soft_comparison.h"
#include "view/canvas_view.h"
#include "view/example_catalog.h"
#include "view/explain_menu.h"
#include "view/energy_ledger_chart.h"
#include "view/graph_panel.h"
#include "view/integrator_ghosts_dock.h"
#include "view/language.h"
#include "view/lesson_dock.h"
#include "view/lesson_session.h"
#include "view/number_text.h"
#include "view/pace_indicator.h"
#include "view/projector_mode.h"
#include "view/property_pane.h"
#include "view/scene_document.h"
#include "view/scene_loading.h"
#include "view/simulation_runner.h"
#include "view/timeline.h"
#include "view/timeline_bar.h"
#include "view/view_constants.h"

#include <QAction>
#include <QApplication>
#include <QActionGroup>
#include <QCloseEvent>
#include <QComboBox>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QIcon>
#include <QKeySequence>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>
#include <QUndoStack>
#include <QVBoxLayout>

#include <array>
#include <memory>
#include <utility>

namespace impetus::view {

namespace {

/// Space on each side of a status bar reading, px, so "t = …" and "E = …" read as two values.
constexpr int kStatusLabelPaddingPx = 8;

/// Problems listed in the body of the "Cannot open scene" box; the rest are under Show Details, so
/// a file with hundreds of problems still gives a box that fits on the screen.
constexpr qsizetype kProblemsShown = 10;

/// Entries of File > Open Recent: enough for a lesson's scenes, few enough to scan.
constexpr qsizetype kMaxRecentFiles = 8;

/// How long the status bar tells that the engine put a body back out of a wall, ms: long enough to
/// read; a scene where it goes on happening renews it every frame.
constexpr int kKeptOutMessageMs = 10000;

/// The speeds of the run controls, simulated seconds per wall second.
constexpr std::array<double, 7> kSpeeds = {0.1, 0.25, 0.5, 1.0, 1.5, 2.0, 4.0};
constexpr int kRealTimeSpeedIndex = 3;

/// The choices of View › Trail Dots Every, steps: from every step to one a second at 240 Hz.
constexpr std::array<int, 6> kTrailDotChoices = {1, 6, 12, 24, 60, 240};

/// QSettings keys.
const QString kRecentFilesKey = QStringLiteral("recentFiles");
const QString kGeometryKey = QStringLiteral("window/geometry");
const QString kWindowStateKey = QStringLiteral("window/state");
const QString kSnapKey = QStringLiteral("view/snapToGrid");

/// The icon `name` drawn for Impetus (resources/icons/tools/NAME.svg).
QIcon impetusIcon(const QString& name) { return QIcon(QStringLiteral(":/icons/tools/%1.svg").arg(name)); }

} // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent)
    , m_document(new SceneDocument(this))
    , m_canvas(new CanvasView(m_document->runner(), this))
{
    m_canvas->setDocument(*m_document);
    m_timeline = new Timeline(m_document->runner(), this);
    // The canvas with the timeline under it, as the central widget.
    auto* centre = new QWidget(this);
    auto* centreLayout = new QVBoxLayout(centre);
    centreLayout->setContentsMargins(0, 0, 0, 0);
    centreLayout->setSpacing(0);
    centreLayout->addWidget(m_canvas, 1);
    m_timelineBar = new TimelineBar(*m_timeline, m_document->runner(), centre);
    centreLayout->addWidget(m_timelineBar);
    setCentralWidget(centre);
    setWindowIcon(QIcon(QStringLiteral(":/icons/impetus.svg")));
    setAccessibleName(tr("Impetus main window"));

    createActions();
    m_timelineBar->setStepBackAction(m_stepBackAction);
    createToolActions();
    createMenus();
    createToolBars();
    createDock();
    createStatusBar();

    SimulationRunner& runner = m_document->runner();
    connect(&runner, &SimulationRunner::runningChanged, this, &MainWindow::onRunningChanged);
    connect(&runner, &SimulationRunner::diverged, this, &MainWindow::showDivergence);
    connect(&runner, &SimulationRunner::keptOut, this, &MainWindow::showKeptOut);
    connect(&runner, &SimulationRunner::computingStepChanged, this, &MainWindow::updateStepAction);
    connect(m_timeline, &Timeline::rangeChanged, this, &MainWindow::updateStepAction);
    connect(m_document, &SceneDocument::worldChanged, this, &MainWindow::updateStepAction);
    connect(m_document, &SceneDocument::stepped, this, &MainWindow::updateStatus);
    connect(m_document, &SceneDocument::worldChanged, this, &MainWindow::updateStatus);
    connect(m_document, &SceneDocument::worldChanged, this, &MainWindow::updateSoftStatus);
    connect(m_document, &SceneDocument::fileChanged, this, &MainWindow::updateTitle);
    connect(m_document, &SceneDocument::modifiedChanged, this, &QWidget::setWindowModified);
    connect(m_canvas, &CanvasView::spaceTapped, m_playAction, &QAction::toggle);

    const QSettings settings;
    // The size the user left the window at wins; the default is for the first start only.
    if (!restoreGeometry(settings.value(kGeometryKey).toByteArray()))
        resize(constants::kDefaultWindowWidth, constants::kDefaultWindowHeight);
    restoreState(settings.value(kWindowStateKey).toByteArray());
    m_snapAction->setChecked(settings.value(kSnapKey, false).toBool());
    // View › Projector Mode (F11) and View › Language, after the geometry: projector mode, when
    // it was left on, goes full screen again.
    new ProjectorMode(*this, *m_canvas);
    addLanguageMenu(*this);
    // The Lesson menu and dock; the canvas, the pane and Delete obey the lesson's locks.
    m_lesson = addLessons(*this);
    // The Explain menu: Separating Axes and the Collision Inspector.
    addExplainers(*this);
    // View › Compare Integrators: the integrator ghosts and their dock.
    addIntegratorGhosts(*this);

    m_canvas->setFocus();
    updateTitle();
    updateStatus();
    updateSoftStatus();
}

SimulationRunner& MainWindow::runner() { return m_document->runner(); }

const SimulationRunner& MainWindow::runner() const { return m_document->runner(); }

QString MainWindow::sceneName() const { return m_document->displayName(); }

void MainWindow::createActions()
{
    m_newAction = new QAction(QIcon::fromTheme(QStringLiteral("document-new")), tr("&New"), this);
    m_newAction->setShortcut(QKeySequence::New);
    m_newAction->setStatusTip(tr("Start an empty scene"));
    connect(m_newAction, &QAction::triggered, this, &MainWindow::newScene);

    m_openAction = new QAction(QIcon::fromTheme(QStringLiteral("document-open")), tr("&Open…"), this);
    m_openAction->setShortcut(QKeySequence::Open);
    m_openAction->setStatusTip(tr("Open a scene file"));
    connect(m_openAction, &QAction::triggered, this, &MainWindow::openSceneDialog);

    m_saveAction = new QAction(QIcon::fromTheme(QStringLiteral("document-save")), tr("&Save"), this);
    m_saveAction->setShortcut(QKeySequence::Save);
    m_saveAction->setStatusTip(tr("Save the scene to its file"));
    connect(m_saveAction, &QAction::triggered, this, &MainWindow::save);

    m_saveAsAction = new QAction(tr("Save &As…"), this);
    m_saveAsAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S));
    m_saveAsAction->setStatusTip(tr("Save the scene to a new file"));
    connect(m_saveAsAction, &QAction::triggered, this, &MainWindow::saveAsDialog);

    m_quitAction = new QAction(tr("&Quit"), this);
    m_quitAction->setShortcut(QKeySequence::Quit);
    m_quitAction->setMenuRole(QAction::QuitRole);
    connect(m_quitAction, &QAction::triggered, this, &QWidget::close);

    QUndoStack* stack = m_document->undoStack();
    m_undoAction = stack->createUndoAction(this, tr("&Undo"));
    m_undoAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Z));
    m_redoAction = stack->createRedoAction(this, tr("&Redo"));
    m_redoAction->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});

    m_deleteAction = new QAction(QIcon::fromTheme(QStringLiteral("edit-delete")), tr("&Delete"), this);
    m_deleteAction->setShortcut(QKeySequence::Delete);
    m_deleteAction->setStatusTip(tr("Delete the selection, and the springs and joints on deleted bodies"));
    connect(m_deleteAction, &QAction::triggered, this, [this] {
        if (const std::optional<QString> lock = m_lesson->removalLock(m_document->selection())) {
            statusBar()->showMessage(*lock);
            return;
        }
        m_document->remove(m_document->selection(), tr("Delete"));
    });
    const auto updateDelete = [this] { m_deleteAction->setEnabled(!m_document->selection().empty()); };
    connect(m_document, &SceneDocument::selectionChanged, this, updateDelete);
    updateDelete();

    m_selectAllAction = new QAction(tr("Select &All"), this);
    m_selectAllAction->setShortcut(QKeySequence::SelectAll);
    connect(m_selectAllAction, &QAction::triggered, this, [this] {
        Selection all;
        const model::World& world = m_document->world();
        for (std::size_t i = 0; i < world.bodies.size(); ++i)
            all.bodies.push_back(static_cast<int>(i));
        for (std::size_t i = 0; i < world.springs.size(); ++i)
            all.springs.push_back(static_cast<int>(i));
        for (std::size_t i = 0; i < world.joints.size(); ++i)
            all.joints.push_back(static_cast<int>(i));
        m_document->setSelection(all);
    });

    m_snapAction = new QAction(tr("&Snap to Grid"), this);
    m_snapAction->setCheckable(true);
    m_snapAction->setShortcut(QKeySequence(Qt::Key_G));
    m_snapAction->setStatusTip(tr("Place and move points on the grid lines' crossings"));
    connect(m_snapAction, &QAction::toggled, m_canvas, &CanvasView::setSnapToGrid);

    m_softEllipsesAction = new QAction(tr("Show Soft-Body &Ellipses"), this);
    m_softEllipsesAction->setCheckable(true);
    m_softEllipsesAction->setStatusTip(tr("Draw the small ellipses a soft body is made of"));
    connect(m_softEllipsesAction, &QAction::toggled, m_canvas, &CanvasView::setShowSoftEllipses);
    m_softStrainAction = new QAction(tr("Show Soft-Body S&train"), this);
    m_softStrainAction->setCheckable(true);
    m_softStrainAction->setStatusTip(
        tr("Draw a soft body's springs coloured by strain: blue compressed, grey at rest, red stretched"));
    connect(m_softStrainAction, &QAction::toggled, m_canvas, &CanvasView::setShowSoftStrain);

    m_frameAction = new QAction(tr("&Frame Scene"), this);
    m_frameAction->setShortcut(QKeySequence(Qt::Key_Home));
    m_frameAction->setStatusTip(tr("Zoom to show every body"));
    connect(m_frameAction, &QAction::triggered, m_canvas, &CanvasView::frameScene);

    m_playAction = new QAction(impetusIcon(QStringLiteral("play")), tr("Play"), this);
    m_playAction->setCheckable(true);
    m_playAction->setShortcut(QKeySequence(Qt::Key_Space));
    m_playAction->setToolTip(tr("Run the simulation (Space)"));
    connect(m_playAction, &QAction::toggled, &m_document->runner(), &SimulationRunner::setRunning);

    m_stepAction = new QAction(impetusIcon(QStringLiteral("step")), tr("Step"), this);
    m_stepAction->setShortcut(QKeySequence(Qt::Key_Right));
    m_stepAction->setToolTip(tr("Advance one time step (→)"));
    connect(m_stepAction, &QAction::triggered, m_document, &SceneDocument::stepOnce);

    m_stepBackAction = new QAction(impetusIcon(QStringLiteral("step-back")), tr("Step Back"), this);
    m_stepBackAction->setShortcut(QKeySequence(Qt::Key_Left));
    m_stepBackAction->setToolTip(tr("Go back one time step along the timeline (←)"));
    connect(m_stepBackAction, &QAction::triggered, this, [this] { m_timeline->stepBack(); });

    m_resetAction = new QAction(impetusIcon(QStringLiteral("reset")), tr("Reset"), this);
    m_resetAction->setShortcut(QKeySequence(Qt::Key_R));
    m_resetAction->setToolTip(tr("Go back to the state at the last Play (R)"));
    connect(m_resetAction, &QAction::triggered, m_document, &SceneDocument::resetToLastPlay);

    // Shortcuts with Ctrl work wherever the focus is in the window.
    for (QAction* action : {m_newAction, m_openAction, m_saveAction, m_saveAsAction, m_quitAction, m_undoAction,
                            m_redoAction, m_selectAllAction})
        addAction(action);
    for (QAction* action : {m_deleteAction, m_snapAction, m_frameAction, m_playAction, m_stepAction, m_stepBackAction,
                            m_resetAction})
        addCanvasShortcut(action);
}

void MainWindow::addCanvasShortcut(QAction* action)
{
    // A single key (or Del) belongs to the widget that has the focus when that is a field of the
    // pane: Space ticks a check box, Del and the arrows edit the vertex table. So these shortcuts
    // act only while the canvas, or a tool bar that shows the action, has the focus; the menus
    // still show them.
    action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    m_canvas->addAction(action);
}

void MainWindow::createToolActions()
{
    struct ToolEntry {
        ToolKind kind;
        QString text;
        Qt::Key key;
        QString tip;
        QString icon; ///< resources/icons/tools/ICON.svg
    };
    const ToolEntry entries[] = {
        {ToolKind::Select, tr("Select"), Qt::Key_S, tr("Select, move (drag) and nudge (arrow keys); Ctrl+drag turns"),
         QStringLiteral("select")},
        {ToolKind::Rotate, tr("Rotate"), Qt::Key_T, tr("Drag to turn a body or the selection about its centre"),
         QStringLiteral("rotate")},
        {ToolKind::Polygon, tr("Polygon"), Qt::Key_P,
         tr("Click the corners; click the first one, press Enter or double-click to close"), QStringLiteral("polygon")},
        {ToolKind::Box, tr("Box"), Qt::Key_B, tr("Drag from corner to corner"), QStringLiteral("box")},
        {ToolKind::Circle, tr("Circle"), Qt::Key_C, tr("Drag from the centre out"), QStringLiteral("circle")},
        {ToolKind::Ellipse, tr("Ellipse"), Qt::Key_E, tr("Drag out its bounding box"), QStringLiteral("ellipse")},
        {ToolKind::Spring, tr("Spring"), Qt::Key_K, tr("Drag from a body to another body or to a point"),
         QStringLiteral("spring")},
        {ToolKind::Pin, tr("Pin"), Qt::Key_N, tr("Click on a body to hinge it to the body below or the world"),
         QStringLiteral("pin")},
        {ToolKind::Rod, tr("Rod"), Qt::Key_L, tr("Drag from a body to another body or to a point"),
         QStringLiteral("rod")},
        {ToolKind::Ruler, tr("Ruler"), Qt::Key_M,
         tr("Click two points, or drag: the distance in metres; snaps to body centres and corners"),
         QStringLiteral("ruler")},
        {ToolKind::Protractor, tr("Protractor"), Qt::Key_A,
         tr("Click the vertex, then a point on each arm: the angle in degrees"), QStringLiteral("protractor")},
        {ToolKind::Probe, tr("Probe"), Qt::Key_I,
         tr("Click a body to read its position, velocity, energies and collisions as it moves"),
         QStringLiteral("probe")},
        {ToolKind::TracePoint, tr("Trace Point"), Qt::Key_X,
         tr("Click a point on a body to draw the path it takes (a wheel's rim: a cycloid); click it again, or "
            "Esc, to stop"),
         QStringLiteral("trace-point")},
    };
    m_toolGroup = new QActionGroup(this);
    m_toolGroup->setExclusive(true);
    for (const ToolEntry& entry : entries) {
        auto* action = new QAction(impetusIcon(entry.icon), entry.text, m_toolGroup);
        action->setCheckable(true);
        action->setShortcut(QKeySequence(entry.key));
        action->setToolTip(tr("%1 (%2): %3").arg(entry.text, QKeySequence(entry.key).toString(QKeySequence::NativeText),
                                                 entry.tip));
        action->setStatusTip(entry.tip);
        const ToolKind kind = entry.kind;
        connect(action, &QAction::triggered, this, [this, kind] { m_canvas->setTool(kind); });
        m_toolActions[kind] = action;
        addCanvasShortcut(action);
    }
    m_toolActions.at(ToolKind::Select)->setChecked(true);
    connect(m_canvas, &CanvasView::toolChanged, this, [this](ToolKind kind) { m_toolActions.at(kind)->setChecked(true); });
}

void MainWindow::createMenus()
{
    QMenu* fileMenu = menuBar()->addMenu(tr("&File"));
    fileMenu->addAction(m_newAction);
    fileMenu->addAction(m_openAction);
    m_recentMenu = fileMenu->addMenu(tr("Open &Recent"));
    connect(m_recentMenu, &QMenu::aboutToShow, this, &MainWindow::fillRecentMenu);
    fillRecentMenu();
    fileMenu->addSeparator();
    fileMenu->addAction(m_saveAction);
    fileMenu->addAction(m_saveAsAction);
    fileMenu->addSeparator();
    fileMenu->addAction(m_quitAction);

    QMenu* editMenu = menuBar()->addMenu(tr("&Edit"));
    editMenu->addAction(m_undoAction);
    editMenu->addAction(m_redoAction);
    editMenu->addSeparator();
    editMenu->addAction(m_deleteAction);
    editMenu->addAction(m_selectAllAction);

    QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
    viewMenu->addAction(m_snapAction);
    viewMenu->addAction(m_frameAction);
    viewMenu->addSeparator();
    viewMenu->addAction(m_softEllipsesAction);
    viewMenu->addAction(m_softStrainAction);
    viewMenu->setObjectName(QStringLiteral("viewMenu"));
    createInstrumentMenus(viewMenu);

    QMenu* toolsMenu = menuBar()->addMenu(tr("&Tools"));
    toolsMenu->addActions(m_toolGroup->actions());

    QMenu* simulationMenu = menuBar()->addMenu(tr("&Simulation"));
    simulationMenu->addAction(m_playAction);
    simulationMenu->addAction(m_stepBackAction);
    simulationMenu->addAction(m_stepAction);
    simulationMenu->addAction(m_resetAction);
    simulationMenu->addSeparator();
    m_compareRigidAction = simulationMenu->addAction(tr("&Compare Soft with Rigid…"), this,
                                                     &MainWindow::compareSelectedWithRigid);
    m_compareRigidAction->setStatusTip(
        tr("Run the selected soft body rigid and soft for a few seconds and show how far apart they drift"));
    const auto updateCompare = [this] {
        const std::vector<int>& bodies = m_document->selection().bodies;
        const model::World& world = m_document->world();
        m_compareRigidAction->setEnabled(bodies.size() == 1 && static_cast<std::size_t>(bodies[0]) < world.bodies.size() &&
                                         world.bodies[static_cast<std::size_t>(bodies[0])].soft.has_value() &&
                                         !world.bodies[static_cast<std::size_t>(bodies[0])].fixed);
    };
    connect(m_document, &SceneDocument::selectionChanged, this, updateCompare);
    connect(m_document, &SceneDocument::worldChanged, this, updateCompare);
    updateCompare();

    m_examplesMenu = menuBar()->addMenu(tr("E&xamples"));
    for (const ExampleScene& example : exampleScenes()) {
        QAction* action = m_examplesMenu->addAction(example.title);
        const QString path = example.path;
        const QString title = example.title;
        connect(action, &QAction::triggered, this, [this, path, title] { openExample(path, title); });
    }
}

void MainWindow::createInstrumentMenus(QMenu* viewMenu)
{
    CanvasInstruments& instruments = m_canvas->instruments();
    QMenu* vectors = viewMenu->addMenu(tr("&Vectors"));
    vectors->setObjectName(QStringLiteral("vectorsMenu"));
    struct VectorEntry {
        VectorKind kind;
        QString text;
        QString tip;
    };
    const VectorEntry entries[] = {
        {VectorKind::Velocity, tr("&Velocity"), tr("Arrows of each body's velocity")},
        {VectorKind::Acceleration, tr("&Acceleration"), tr("Arrows of each body's acceleration, net force / mass")},
        {VectorKind::NetForce, tr("&Net Force"), tr("Arrows of the net force on each body")},
        {VectorKind::ForceParts, tr("&Force Parts"),
         tr("Arrows of gravity, springs, drag, contact normal and friction forces and joint forces")},
        {VectorKind::Momentum, tr("&Momentum"), tr("Arrows of each body's momentum")},
    };
    for (const VectorEntry& entry : entries) {
        QAction* action = vectors->addAction(entry.text);
        action->setCheckable(true);
        action->setStatusTip(entry.tip);
        const VectorKind kind = entry.kind;
        connect(action, &QAction::toggled, this, [&instruments, kind](bool on) { instruments.setShowVector(kind, on); });
        m_vectorActions[static_cast<std::size_t>(kind)] = action;
    }
    vectors->addSeparator();
    QAction* longer = vectors->addAction(tr("&Longer Arrows"), this, [&instruments] {
        instruments.scaleArrows(constants::kVectorScaleStep);
    });
    longer->setShortcut(QKeySequence(Qt::Key_BracketRight));
    longer->setStatusTip(tr("Double the length of every arrow (the legend gives the scale)"));
    QAction* shorter = vectors->addAction(tr("&Shorter Arrows"), this, [&instruments] {
        instruments.scaleArrows(1 / constants::kVectorScaleStep);
    });
    shorter->setShortcut(QKeySequence(Qt::Key_BracketLeft));
    shorter->setStatusTip(tr("Halve the length of every arrow (the legend gives the scale)"));
    addCanvasShortcut(longer);
    addCanvasShortcut(shorter);

    m_trailsAction = viewMenu->addAction(tr("&Trails"));
    m_trailsAction->setCheckable(true);
    m_trailsAction->setStatusTip(tr("Draw the path of each body's centre of mass, with a dot every few steps"));
    connect(m_trailsAction, &QAction::toggled, &instruments, &CanvasInstruments::setShowTrails);
    QMenu* dots = viewMenu->addMenu(tr("Trail &Dots Every"));
    dots->setObjectName(QStringLiteral("trailDotsMenu"));
    auto* dotGroup = new QActionGroup(dots);
    for (const int steps : kTrailDotChoices) {
        QAction* action = dots->addAction(tr("%n step(s)", nullptr, steps));
        action->setCheckable(true);
        action->setChecked(steps == constants::kDefaultTrailDotSteps);
        action->setData(steps);
        dotGroup->addAction(action);
        connect(action, &QAction::triggered, &instruments, [&instruments, steps] { instruments.setTrailDotSteps(steps); });
    }

    QAction* selectedOnly = viewMenu->addAction(tr("Vectors and Trails for &Selected Bodies Only"));
    selectedOnly->setCheckable(true);
    selectedOnly->setStatusTip(tr("Draw arrows and trails only for the bodies selected"));
    connect(selectedOnly, &QAction::toggled, &instruments, &CanvasInstruments::setSelectedOnly);

    viewMenu->addSeparator();
    m_newGraphAction = viewMenu->addAction(tr("New &Graph"), this, [this] {
        const std::vector<int>& selected = m_document->selection().bodies;
        const model::World& world = m_document->world();
        const QString name = selected.empty() ? QString()
                                              : QString::fromStdString(world.bodies[static_cast<std::size_t>(selected.front())].name);
        addGraph(name, GraphQuantity::Y);
    });
    m_newGraphAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_G));
    m_newGraphAction->setStatusTip(tr("Plot a quantity of the selected body against time, or against another quantity"));
    addAction(m_newGraphAction);

    QAction* ledgerAction = viewMenu->addAction(tr("Energy &Ledger"), this, &MainWindow::showEnergyLedger);
    ledgerAction->setObjectName(QStringLiteral("energyLedgerAction"));
    ledgerAction->setStatusTip(tr("Chart where the energy goes: what each cause has taken out, stacked over time"));

    connect(&instruments, &CanvasInstruments::samplingChanged, this, &MainWindow::updateSampling);
    connect(m_timeline, &Timeline::futureDiscarded, &instruments, &CanvasInstruments::discardAfter);
}

void MainWindow::showEnergyLedger()
{
    if (auto* open = findChild<QDockWidget*>(QStringLiteral("energyLedgerDock"))) {
        open->raise();
        return;
    }
    auto* dock = new QDockWidget(tr("Energy Ledger"), this);
    dock->setObjectName(QStringLiteral("energyLedgerDock"));
    // A closed chart is gone, and with it the ledger's booking in the steps.
    dock->setAttribute(Qt::WA_DeleteOnClose);
    auto* chart = new EnergyLedgerChart(dock);
    dock->setWidget(chart);
    connect(&m_document->runner(), &SimulationRunner::sampled, chart, &EnergyLedgerChart::addSamples);
    connect(m_document, &SceneDocument::sceneReplaced, chart, &EnergyLedgerChart::clear);
    connect(m_timeline, &Timeline::futureDiscarded, chart, &EnergyLedgerChart::discardAfter);
    connect(dock, &QObject::destroyed, this, [this] { QTimer::singleShot(0, this, &MainWindow::updateSampling); });
    addDockWidget(Qt::BottomDockWidgetArea, dock);
    updateSampling();
}

GraphPanel* MainWindow::addGraph(const QString& bodyName, GraphQuantity y, GraphQuantity x)
{
    SimulationRunner& runner = m_document->runner();
    auto* dock = new QDockWidget(this);
    dock->setObjectName(QStringLiteral("graphDock"));
    // A closed graph is gone, and with it what the runner records for it.
    dock->setAttribute(Qt::WA_DeleteOnClose);
    auto* panel = new GraphPanel(runner, bodyName, y, x, dock);
    dock->setWidget(panel);
    dock->setWindowTitle(panel->title());
    connect(panel, &GraphPanel::titleChanged, dock, &QDockWidget::setWindowTitle);
    connect(&runner, &SimulationRunner::sampled, panel, &GraphPanel::addSamples);
    connect(m_document, &SceneDocument::worldChanged, panel, &GraphPanel::onWorldChanged);
    connect(m_document, &SceneDocument::stepped, panel, &GraphPanel::onWorldChanged);
    connect(m_document, &SceneDocument::sceneReplaced, panel, &GraphPanel::onSceneReplaced);
    connect(m_timeline, &Timeline::futureDiscarded, panel, &GraphPanel::discardAfter);
    connect(panel, &GraphPanel::bodyChanged, this, &MainWindow::updateSampling);
    connect(dock, &QObject::destroyed, this, [this] { QTimer::singleShot(0, this, &MainWindow::updateSampling); });
    addDockWidget(Qt::BottomDockWidgetArea, dock);
    updateSampling();
    return panel;
}

std::vector<GraphPanel*> MainWindow::graphPanels() const
{
    std::vector<GraphPanel*> panels;
    for (QDockWidget* dock : findChildren<QDockWidget*>(QStringLiteral("graphDock"))) {
        if (auto* panel = qobject_cast<GraphPanel*>(dock->widget()))
            panels.push_back(panel);
    }
    return panels;
}

void MainWindow::updateSampling()
{
    SampleRequest request;
    request.centres = m_canvas->instruments().needsCentres();
    for (const GraphPanel* panel : graphPanels()) {
        if (panel->body() && std::ranges::find(request.bodies, *panel->body()) == request.bodies.end())
            request.bodies.push_back(*panel->body());
        request.totals = true;
    }
    request.ledger = findChild<QDockWidget*>(QStringLiteral("energyLedgerDock")) != nullptr;
    m_document->runner().setSampleRequest(std::move(request));
}

void MainWindow::createToolBars()
{
    QToolBar* runBar = addToolBar(tr("Run controls"));
    runBar->setObjectName(QStringLiteral("runControls"));
    runBar->setAccessibleName(tr("Run controls"));
    runBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    runBar->addAction(m_playAction);
    runBar->addAction(m_stepBackAction);
    runBar->addAction(m_stepAction);
    runBar->addAction(m_resetAction);
    if (QWidget* button = runBar->widgetForAction(m_playAction))
        button->setAccessibleName(tr("Play or pause"));
    if (QWidget* button = runBar->widgetForAction(m_stepAction))
        button->setAccessibleName(tr("Step once"));
    if (QWidget* button = runBar->widgetForAction(m_stepBackAction))
        button->setAccessibleName(tr("Step back once"));
    if (QWidget* button = runBar->widgetForAction(m_resetAction))
        button->setAccessibleName(tr("Reset to the last Play"));

    auto* speedLabel = new QLabel(tr("Speed:"), runBar);
    speedLabel->setAccessibleName(tr("Speed"));
    speedLabel->setContentsMargins(kStatusLabelPaddingPx, 0, kStatusLabelPaddingPx / 2, 0);
    runBar->addWidget(speedLabel);
    m_speedBox = new QComboBox(runBar);
    m_speedBox->setAccessibleName(tr("Simulation speed"));
    m_speedBox->setToolTip(tr("Simulated seconds per real second"));
    m_speedBox->setFocusPolicy(Qt::ClickFocus);
    for (const double speed : kSpeeds)
        m_speedBox->addItem(tr("%1×").arg(QLocale().toString(speed)), speed);
    m_speedBox->setCurrentIndex(kRealTimeSpeedIndex);
    speedLabel->setBuddy(m_speedBox);
    connect(m_speedBox, &QComboBox::currentIndexChanged, this,
            [this](int index) { m_document->runner().setSpeed(m_speedBox->itemData(index).toDouble()); });
    // Back to the canvas once a speed is chosen, so that Space plays again instead of opening
    // the list.
    connect(m_speedBox, &QComboBox::activated, m_canvas, [this] { m_canvas->setFocus(); });
    runBar->addWidget(m_speedBox);

    QToolBar* toolBar = new QToolBar(tr("Tools"), this);
    toolBar->setObjectName(QStringLiteral("drawingTools"));
    toolBar->setAccessibleName(tr("Drawing tools"));
    // Icons only, each naming its tool and shortcut in its tooltip: a column of words was long and
    // hard to scan.
    toolBar->setToolButtonStyle(Qt::ToolButtonIconOnly);
    toolBar->addActions(m_toolGroup->actions());
    for (QAction* action : m_toolGroup->actions()) {
        if (QWidget* button = toolBar->widgetForAction(action))
            button->setAccessibleName(tr("%1 tool").arg(action->text()));
    }
    addToolBar(Qt::LeftToolBarArea, toolBar);
}

void MainWindow::createDock()
{
    m_attributesDock = new QDockWidget(tr("Attributes"), this);
    m_attributesDock->setObjectName(QStringLiteral("attributesDock"));
    m_attributesDock->setAccessibleName(tr("Attributes"));
    m_attributesDock->setAllowedAreas(Qt::LeftDockWidgetArea | Qt::RightDockWidgetArea);
    // The pane shows the selection (or the world settings) and turns each edit into one undoable
    // command on the document; it follows every change, and the live values follow each step.
    m_pane = new PropertyPane(m_attributesDock);
    m_pane->setObjectName(QStringLiteral("propertyPane"));
    m_attributesDock->setWidget(m_pane);
    connect(m_pane, &PropertyPane::bodyEdited, m_document, &SceneDocument::setBody);
    connect(m_pane, &PropertyPane::springEdited, m_document, &SceneDocument::setSpring);
    connect(m_pane, &PropertyPane::jointEdited, m_document, &SceneDocument::setJoint);
    connect(m_pane, &PropertyPane::worldSettingsEdited, m_document, &SceneDocument::setWorldSettings);
    // A body's own arrows are the canvas's business: the pane reads and sets them there.
    CanvasInstruments& instruments = m_canvas->instruments();
    m_pane->setBodyVectorsShown([&instruments](const std::string& name, VectorKind kind) {
        return instruments.showsBodyVector(name, kind);
    });
    connect(m_pane, &PropertyPane::bodyVectorToggled, &instruments,
            [&instruments](const QString& name, VectorKind kind, bool on) {
                instruments.setBodyVector(name.toStdString(), kind, on);
            });
    const auto showSelection = [this] { m_pane->showSelection(m_document->world(), m_document->selection()); };
    connect(m_document, &SceneDocument::selectionChanged, this, showSelection);
    connect(m_document, &SceneDocument::worldChanged, this, showSelection);
    connect(m_document, &SceneDocument::stepped, this, [this] { m_pane->refresh(m_document->world()); });
    showSelection();
    addDockWidget(Qt::RightDockWidgetArea, m_attributesDock);
    QMenu* viewMenu = findChild<QMenu*>(QStringLiteral("viewMenu"));
    if (viewMenu) {
        viewMenu->addSeparator();
        viewMenu->addAction(m_attributesDock->toggleViewAction());
    }
}

void MainWindow::createStatusBar()
{
    m_timeLabel = new QLabel(this);
    m_timeLabel->setAccessibleName(tr("Simulated time"));
    m_energyPartsLabel = new QLabel(this);
    m_energyPartsLabel->setAccessibleName(tr("Kinetic, potential and elastic energy"));
    m_energyPartsLabel->setToolTip(
        tr("Kinetic energy K, gravitational potential energy U (from y = 0) and elastic energy of the springs"));
    m_energyLabel = new QLabel(this);
    m_energyLabel->setAccessibleName(tr("Total energy"));
    m_momentumLabel = new QLabel(this);
    m_momentumLabel->setAccessibleName(tr("Total momentum"));
    m_collisionLabel = new QLabel(this);
    m_collisionLabel->setAccessibleName(tr("Collision count"));
    m_softLabel = new QLabel(this);
    m_softLabel->setObjectName(QStringLiteral("softStatus"));
    m_softLabel->setAccessibleName(tr("Soft bodies"));
    m_softLabel->hide();
    m_paceIndicator = new PaceIndicator(m_document->runner(), this);
    for (QLabel* label : {static_cast<QLabel*>(m_paceIndicator), m_softLabel, m_timeLabel, m_energyPartsLabel,
                          m_energyLabel, m_momentumLabel, m_collisionLabel}) {
        label->setContentsMargins(kStatusLabelPaddingPx, 0, kStatusLabelPaddingPx, 0);
        statusBar()->addPermanentWidget(label);
    }
    statusBar()->setAccessibleName(tr("Status"));
}

QStringList MainWindow::openScene(const QString& path)
{
    model::SceneLoadResult result = loadScene(path);
    if (!result.ok())
        return problemMessages(result);
    // A resource (an example) has no file to save back to.
    const QString file = path.startsWith(QLatin1Char(':')) ? QString() : QFileInfo(path).absoluteFilePath();
    m_document->setScene(std::move(*result.world), file, sceneDisplayName(path));
    if (!file.isEmpty())
        addRecentFile(file);
    return {};
}

void MainWindow::setScene(model::World world, const QString& name)
{
    m_document->setScene(std::move(world), QString(), name);
}

bool MainWindow::newScene()
{
    if (!maybeDiscardChanges())
        return false;
    m_document->setScene(model::World{}, QString(), tr("untitled"));
    return true;
}

void MainWindow::openSceneDialog()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Scene"), m_lastDirectory,
                                                      tr("Impetus scenes (*.json);;All files (*)"));
    if (path.isEmpty())
        return;
    m_lastDirectory = QFileInfo(path).absolutePath();
    openSceneInteractively(path);
}

bool MainWindow::openSceneInteractively(const QString& path)
{
    // Load first: a file that fails changes nothing, so there is nothing to ask about.
    model::SceneLoadResult result = loadScene(path);
    if (!result.ok()) {
        showProblems(path, problemMessages(result));
        return false;
    }
    if (!maybeDiscardChanges())
        return false;
    const QString file = path.startsWith(QLatin1Char(':')) ? QString() : QFileInfo(path).absoluteFilePath();
    m_document->setScene(std::move(*result.world), file, sceneDisplayName(path));
    if (!file.isEmpty())
        addRecentFile(file);
    return true;
}

void MainWindow::openExample(const QString& path, const QString& title)
{
    model::SceneLoadResult result = loadScene(path);
    if (!result.ok()) {
        showProblems(path, problemMessages(result));
        return;
    }
    if (!maybeDiscardChanges())
        return;
    m_document->setScene(std::move(*result.world), QString(), title);
}

QStringList MainWindow::openStartupScene(const QString& path)
{
    const QStringList problems = openScene(path);
    if (problems.isEmpty())
        return problems;
    // A window with a scene to press Play on, and the problems in front of it, serve a user who
    // double-clicked a file better than no window at all.
    const bool defaultOpened = openScene(QString::fromLatin1(kDefaultScenePath)).isEmpty();
    QMessageBox* box = makeProblemsBox(path, problems,
                                       defaultOpened ? tr("The default scene is shown instead.")
                                                     : tr("An empty scene is shown instead."));
    // Not exec(): the caller is main(), which still has to start the application's event loop.
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setWindowModality(Qt::WindowModal);
    box->open();
    return problems;
}

void MainWindow::showProblems(const QString& path, const QStringList& problems)
{
    std::unique_ptr<QMessageBox> box(makeProblemsBox(path, problems, tr("The current scene is unchanged.")));
    box->exec();
}

QMessageBox* MainWindow::makeProblemsBox(const QString& path, const QStringList& problems, const QString& outcome)
{
    auto* box = new QMessageBox(QMessageBox::Warning, tr("Cannot open scene"),
                                tr("“%1” could not be opened. %2").arg(QFileInfo(path).fileName(), outcome),
                                QMessageBox::Ok, this);
    box->setObjectName(QStringLiteral("openErrorBox"));
    QStringList shown = problems.mid(0, kProblemsShown);
    if (problems.size() > kProblemsShown) {
        shown << tr("…and %n more.", nullptr, static_cast<int>(problems.size() - kProblemsShown));
        box->setDetailedText(problems.join(QLatin1Char('\n')));
    }
    box->setInformativeText(shown.join(QLatin1Char('\n')));
    return box;
}

void MainWindow::showDivergence(const QString& bodyName, double time)
{
    // Window-modal and not waiting for an answer: the report comes from inside a timer tick, and
    // a nested event loop there would only invite more ticks.
    auto* box = new QMessageBox(QMessageBox::Warning, tr("The simulation blew up"),
                                tr("Body “%1” got a position or velocity that is not a finite number by t = %2 s.")
                                    .arg(bodyName, localeNumber(time, 'g', 6)),
                                QMessageBox::Ok, this);
    box->setObjectName(QStringLiteral("divergedBox"));
    box->setInformativeText(tr("The run stopped at the last finite state. The time step is too large for the "
                               "stiffest spring or the fastest motion in the scene. Press Reset (R) to go back to "
                               "where you pressed Play, or Undo (Ctrl+Z); then try a smaller time step or a softer "
                               "spring."));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setWindowModality(Qt::WindowModal);
    box->open();
}

void MainWindow::showKeptOut(const QString& bodyName, const QString& fixedName, double time, int others)
{
    // The run goes on, so a line in the status bar, not a box: a scene where it happens at every
    // step (a soft body crushed into a wall) must not bury the window under boxes.
    QString text = tr("At t = %1 s the solver let the centre of “%2” into “%3”; it was put back at the surface.")
                       .arg(localeNumber(time, 'g', 6), bodyName, fixedName);
    if (others > 0)
        text += QLatin1Char(' ') + tr("%n more such body pair(s) in the same steps.", "", others);
    statusBar()->showMessage(text, kKeptOutMessageMs);
}

bool MainWindow::saveTo(const QString& path)
{
    // A file holds one instant: the one on the canvas. Saving while the run goes on would write
    // the world at some step after the one the user chose to keep, and go on changing it.
    m_document->runner().pause();
    if (const std::optional<QString> error = m_document->saveAs(path)) {
        QMessageBox box(QMessageBox::Warning, tr("Cannot save scene"),
                        tr("The scene could not be saved to “%1”. Nothing was overwritten.").arg(path), QMessageBox::Ok,
                        this);
        box.setObjectName(QStringLiteral("saveErrorBox"));
        box.setInformativeText(*error);
        box.exec();
        return false;
    }
    addRecentFile(m_document->filePath());
    return true;
}

bool MainWindow::save()
{
    m_document->runner().pause();
    if (m_document->filePath().isEmpty())
        return saveAsDialog();
    return saveTo(m_document->filePath());
}

bool MainWindow::saveAsDialog()
{
    // Paused before the file dialog, so the instant saved is the one on screen when asked.
    m_document->runner().pause();
    QString path = QFileDialog::getSaveFileName(this, tr("Save Scene"), m_lastDirectory,
                                                tr("Impetus scenes (*.json);;All files (*)"));
    if (path.isEmpty())
        return false;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".json");
    m_lastDirectory = QFileInfo(path).absolutePath();
    return saveTo(path);
}

bool MainWindow::maybeDiscardChanges()
{
    if (!m_document->hasUnsavedEdits())
        return true;
    QMessageBox box(QMessageBox::Question, tr("Unsaved changes"),
                    tr("“%1” has changes that are not saved.").arg(m_document->displayName()),
                    QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, this);
    box.setObjectName(QStringLiteral("unsavedChangesBox"));
    box.setInformativeText(tr("Save them before going on?"));
    box.setDefaultButton(QMessageBox::Save);
    switch (box.exec()) {
    case QMessageBox::Save:
        return save();
    case QMessageBox::Discard:
        return true;
    default:
        return false;
    }
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (!maybeDiscardChanges()) {
        event->ignore();
        return;
    }
    QSettings settings;
    settings.setValue(kGeometryKey, saveGeometry());
    settings.setValue(kWindowStateKey, saveState());
    settings.setValue(kSnapKey, m_snapAction->isChecked());
    m_document->runner().pause();
    event->accept();
}

QStringList MainWindow::recentFiles() const { return QSettings().value(kRecentFilesKey).toStringList(); }

void MainWindow::addRecentFile(const QString& path)
{
    QStringList files = recentFiles();
    files.removeAll(path);
    files.prepend(path);
    while (files.size() > kMaxRecentFiles)
        files.removeLast();
    QSettings().setValue(kRecentFilesKey, files);
    fillRecentMenu();
}

void MainWindow::fillRecentMenu()
{
    m_recentMenu->clear();
    const QStringList files = recentFiles();
    for (const QString& file : files) {
        QAction* action = m_recentMenu->addAction(QFileInfo(file).fileName());
        action->setToolTip(file);
        action->setStatusTip(file);
        connect(action, &QAction::triggered, this, [this, file] { openSceneInteractively(file); });
    }
    m_recentMenu->setEnabled(!files.isEmpty());
}

void MainWindow::onRunningChanged(bool running)
{
    // Keeps the action in step when the runner is paused from elsewhere (Step, a new scene).
    const QSignalBlocker blocker(m_playAction);
    m_playAction->setChecked(running);
    m_playAction->setText(running ? tr("Pause") : tr("Play"));
    m_playAction->setIcon(impetusIcon(running ? QStringLiteral("pause") : QStringLiteral("play")));
    m_playAction->setToolTip(running ? tr("Pause the simulation (Space)") : tr("Run the simulation (Space)"));
    updateStepAction();
}

void MainWindow::updateStepAction()
{
    // Step waits for the step it asked for: presses while it is computed would pile up steps.
    const SimulationRunner& runner = m_document->runner();
    m_stepAction->setEnabled(!runner.isRunning() && !runner.isComputingStep());
    m_stepBackAction->setEnabled(!runner.isComputingStep() && m_timeline->currentStep() > m_timeline->firstStep());
}

void MainWindow::updateStatus()
{
    const model::World& world = m_document->world();
    m_timeLabel->setText(tr("t = %L1 s").arg(world.time, 0, 'f', 3));
    const controller::Energy energy = controller::computeEnergy(world);
    m_energyPartsLabel->setText(tr("K = %L1 J  U = %L2 J  elastic = %L3 J")
                                    .arg(energy.kinetic, 0, 'f', 3)
                                    .arg(energy.potential, 0, 'f', 3)
                                    .arg(energy.elastic, 0, 'f', 3));
    m_energyLabel->setText(tr("E = %L1 J").arg(energy.total(), 0, 'f', 3));
    const Vec2 momentum = controller::linearMomentum(world);
    m_momentumLabel->setText(tr("p = (%L1, %L2) kg·m/s").arg(momentum.x(), 0, 'f', 3).arg(momentum.y(), 0, 'f', 3));
    m_collisionLabel->setText(tr("Collisions: %L1").arg(world.collisionCount));
}

void MainWindow::compareSelectedWithRigid()
{
    const std::vector<int>& selected = m_document->selection().bodies;
    if (selected.size() != 1)
        return;
    m_document->runner().pause();
    const model::World& world = m_document->world();
    const model::BodyId id{static_cast<std::uint32_t>(selected[0])};
    const auto steps = static_cast<std::int64_t>(std::llround(constants::kCompareRigidSeconds / world.settings.timeStep));
    const std::int64_t sampleEvery = std::max<std::int64_t>(1, steps / constants::kCompareRigidRows);
    // Both runs are copies: the scene itself does not move. They take a moment, so say so.
    statusBar()->showMessage(tr("Running %1 rigid and soft…").arg(QString::fromStdString(world.body(id).name)));
    QApplication::setOverrideCursor(Qt::WaitCursor);
    const controller::RigidSoftComparison result = controller::compareRigidSoft(world, id, steps, sampleEvery);
    QApplication::restoreOverrideCursor();
    statusBar()->clearMessage();

    // In the window's number format ("0,25" in German), as the status bar.
    const QLocale locale;
    QString table = tr("<table><tr><th align=right>t (s)</th><th align=right>distance (m)</th></tr>");
    for (const controller::RigidSoftSample& sample : result.samples)
        table += QStringLiteral("<tr><td align=right>%1</td><td align=right>%2</td></tr>")
                     .arg(locale.toString(sample.time - world.time, 'f', 2), locale.toString(sample.distance, 'f', 4));
    table += QStringLiteral("</table>");
    QMessageBox box(QMessageBox::Information, tr("Soft against rigid"), QString(), QMessageBox::Ok, this);
    box.setObjectName(QStringLiteral("compareRigidBox"));
    box.setTextFormat(Qt::RichText);
    box.setText(tr("<p>How far the centre of mass of <b>%1</b> run soft (%2 ellipses, %3 per m²) drifts from "
                   "the same body run rigid, over the next %4 s:</p><p>RMS %5 m, largest %6 m at t = %7 s.</p>%8")
                    .arg(QString::fromStdString(world.body(id).name).toHtmlEscaped(), locale.toString(result.ellipses),
                         localeNumber(result.ellipsesPerSquareMeter, 'g', 4),
                         localeNumber(constants::kCompareRigidSeconds, 'g', 3),
                         locale.toString(result.rmsDistance, 'f', 4), locale.toString(result.maxDistance, 'f', 4),
                         locale.toString(result.maxDistanceTime - world.time, 'f', 2), table));
    m_lastComparison = result;
    box.exec();
}

void MainWindow::updateSoftStatus()
{
    const model::World& world = m_document->world();
    if (world.softBodies.empty()) {
        m_softLabel->hide();
        return;
    }
    QStringList densities;
    for (const model::SoftGrid& grid : world.softBodies) {
        const model::Body& body = world.body(grid.body);
        const bool automatic = body.soft && body.soft->autoDensity;
        densities << (automatic ? tr("%1: %L2/m² (auto)") : tr("%1: %L2/m²"))
                         .arg(QString::fromStdString(body.name))
                         .arg(grid.ellipsesPerSquareMeter, 0, 'g', 4);
    }
    const controller::SoftStability stability = controller::softStability(world);
    QString text = densities.join(QStringLiteral(", "));
    if (stability.substeps > 1)
        text = tr("%1 — %2 substeps per step").arg(text).arg(stability.substeps);
    m_softLabel->setText(text);
    m_softLabel->setToolTip(stability.message.empty() ? tr("One step per step: the grids are stable at this time step.")
                                                      : QString::fromStdString(stability.message));
    m_softLabel->show();
}

void MainWindow::updateTitle()
{
    const QString name = m_document->displayName().isEmpty() ? tr("untitled") : m_document->displayName();
    setWindowTitle(tr("%1[*] — Impetus").arg(name));
    setWindowModified(m_document->isModified());
}

} // namespace impetus::view
