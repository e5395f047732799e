#include "view/main_window.h"

#include "controller/diagnostics.h"
#include "view/canvas_view.h"
#include "view/scene_loading.h"
#include "view/simulation_runner.h"

#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QIcon>
#include <QKeySequence>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>

#include <utility>

namespace impetus::view {

namespace {

/// Space on each side of a status bar reading, px, so "t = …" and "E = …" read as two values.
constexpr int kStatusLabelPaddingPx = 8;

/// Problems listed in the body of the "Cannot open scene" box; the rest are under Show Details, so
/// a file with hundreds of problems still gives a box that fits on the screen.
constexpr qsizetype kProblemsShown = 10;

} // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent)
    , m_runner(new SimulationRunner(this))
    , m_canvas(new CanvasView(*m_runner, this))
{
    setCentralWidget(m_canvas);
    setWindowIcon(QIcon(QStringLiteral(":/icons/impetus.svg")));
    setAccessibleName(tr("Impetus main window"));

    createActions();
    createMenus();
    createToolBar();
    createStatusBar();

    connect(m_runner, &SimulationRunner::runningChanged, this, &MainWindow::onRunningChanged);
    connect(m_runner, &SimulationRunner::stepped, this, &MainWindow::updateStatus);
    connect(m_runner, &SimulationRunner::worldChanged, this, &MainWindow::updateStatus);

    m_canvas->setFocus();
    updateTitle();
    updateStatus();
}

void MainWindow::createActions()
{
    m_openAction = new QAction(tr("&Open…"), this);
    m_openAction->setShortcut(QKeySequence::Open);
    m_openAction->setStatusTip(tr("Open a scene file"));
    connect(m_openAction, &QAction::triggered, this, &MainWindow::openSceneDialog);

    m_quitAction = new QAction(tr("&Quit"), this);
    m_quitAction->setShortcut(QKeySequence::Quit);
    m_quitAction->setMenuRole(QAction::QuitRole);
    connect(m_quitAction, &QAction::triggered, this, &QWidget::close);

    m_playAction = new QAction(style()->standardIcon(QStyle::SP_MediaPlay), tr("Play"), this);
    m_playAction->setCheckable(true);
    m_playAction->setShortcut(QKeySequence(Qt::Key_Space));
    m_playAction->setToolTip(tr("Run the simulation (Space)"));
    connect(m_playAction, &QAction::toggled, m_runner, &SimulationRunner::setRunning);

    m_stepAction = new QAction(style()->standardIcon(QStyle::SP_MediaSkipForward), tr("Step"), this);
    m_stepAction->setShortcut(QKeySequence(Qt::Key_Right));
    m_stepAction->setToolTip(tr("Advance one time step (→)"));
    connect(m_stepAction, &QAction::triggered, m_runner, &SimulationRunner::stepOnce);
}

void MainWindow::createMenus()
{
    QMenu* fileMenu = menuBar()->addMenu(tr("&File"));
    fileMenu->addAction(m_openAction);
    fileMenu->addSeparator();
    fileMenu->addAction(m_quitAction);

    QMenu* simulationMenu = menuBar()->addMenu(tr("&Simulation"));
    simulationMenu->addAction(m_playAction);
    simulationMenu->addAction(m_stepAction);
}

void MainWindow::createToolBar()
{
    QToolBar* toolBar = addToolBar(tr("Run controls"));
    toolBar->setObjectName(QStringLiteral("runControls"));
    toolBar->setAccessibleName(tr("Run controls"));
    toolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    toolBar->setMovable(false);
    toolBar->addAction(m_playAction);
    toolBar->addAction(m_stepAction);
    if (QWidget* button = toolBar->widgetForAction(m_playAction))
        button->setAccessibleName(tr("Play or pause"));
    if (QWidget* button = toolBar->widgetForAction(m_stepAction))
        button->setAccessibleName(tr("Step once"));
}

void MainWindow::createStatusBar()
{
    m_timeLabel = new QLabel(this);
    m_timeLabel->setAccessibleName(tr("Simulated time"));
    m_energyLabel = new QLabel(this);
    m_energyLabel->setAccessibleName(tr("Total energy"));
    m_collisionLabel = new QLabel(this);
    m_collisionLabel->setAccessibleName(tr("Collision count"));
    for (QLabel* label : {m_timeLabel, m_energyLabel, m_collisionLabel})
        label->setContentsMargins(kStatusLabelPaddingPx, 0, kStatusLabelPaddingPx, 0);
    statusBar()->addPermanentWidget(m_timeLabel);
    statusBar()->addPermanentWidget(m_energyLabel);
    statusBar()->addPermanentWidget(m_collisionLabel);
    statusBar()->setAccessibleName(tr("Status"));
}

QStringList MainWindow::openScene(const QString& path)
{
    model::SceneLoadResult result = loadScene(path);
    if (!result.ok())
        return problemMessages(result);
    setScene(std::move(*result.world), sceneDisplayName(path));
    return {};
}

void MainWindow::setScene(model::World world, const QString& name)
{
    m_sceneName = name;
    m_runner->setWorld(std::move(world));
    updateTitle();
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
    const QStringList problems = openScene(path);
    if (problems.isEmpty())
        return true;
    QMessageBox box(QMessageBox::Warning, tr("Cannot open scene"),
                    tr("“%1” could not be opened. The current scene is unchanged.")
                        .arg(QFileInfo(path).fileName()),
                    QMessageBox::Ok, this);
    QStringList shown = problems.mid(0, kProblemsShown);
    if (problems.size() > kProblemsShown) {
        shown << tr("…and %n more.", nullptr, static_cast<int>(problems.size() - kProblemsShown));
        box.setDetailedText(problems.join(QLatin1Char('\n')));
    }
    box.setInformativeText(shown.join(QLatin1Char('\n')));
    box.exec();
    return false;
}

void MainWindow::onRunningChanged(bool running)
{
    // Keeps the action in step when the runner is paused from elsewhere (Step, a new scene).
    const QSignalBlocker blocker(m_playAction);
    m_playAction->setChecked(running);
    m_playAction->setText(running ? tr("Pause") : tr("Play"));
    m_playAction->setIcon(style()->standardIcon(running ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    m_playAction->setToolTip(running ? tr("Pause the simulation (Space)") : tr("Run the simulation (Space)"));
    m_stepAction->setEnabled(!running);
}

void MainWindow::updateStatus()
{
    const model::World& world = m_runner->world();
    m_timeLabel->setText(tr("t = %1 s").arg(world.time, 0, 'f', 3));
    const double energy = controller::computeEnergy(world).total();
    m_energyLabel->setText(tr("E = %1 J").arg(energy, 0, 'f', 3));
    m_collisionLabel->setText(tr("Collisions: %1").arg(world.collisionCount));
}

void MainWindow::updateTitle()
{
    setWindowTitle(m_sceneName.isEmpty() ? tr("Impetus") : tr("Impetus — %1").arg(m_sceneName));
}

} // namespace impetus::view
