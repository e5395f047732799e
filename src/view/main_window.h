#pragma once
/// \file main_window.h
/// The main window: the canvas, the tools, the run controls, the menus, the readouts and the
/// attributes dock.

#include "controller/soft/soft_comparison.h"
#include "model/world.h"
#include "view/canvas_instruments.h"
#include "view/graph_quantity.h"
#include "view/tools/tool.h"

#include <QMainWindow>
#include <QString>
#include <QStringList>

#include <array>
#include <map>
#include <optional>
#include <vector>

class QAction;
class QActionGroup;
class QComboBox;
class QDockWidget;
class QLabel;
class QMenu;
class QMessageBox;

namespace impetus::view {

class CanvasView;
class GraphPanel;
class LessonSession;
class PaceIndicator;
class PropertyPane;
class SceneDocument;
class SimulationRunner;
class Timeline;
class TimelineBar;

/// The application window. The canvas is the central widget; a tool bar on the left holds the
/// drawing tools, one at the top the run controls (Play/Pause Space, Step →, Reset R, speed). The
/// one-key shortcuts (those, Del, G, Home and the tool letters) act while the canvas or a tool bar
/// has the focus, so that the attribute pane keeps its keys; the Ctrl shortcuts act anywhere. The
/// status bar shows the simulated time, the energies, the momentum and the collision count, and,
/// while the simulation runs slower than real time, a PaceIndicator (object name "paceStatus")
/// that says how much slower and why. Step is disabled while a step is computed in the
/// background. The attributes dock (object name "attributesDock") sits on the right. Menus: File
/// (New, Open, Open Recent, Save, Save As, Quit), Edit (Undo, Redo, Delete, Select All), View,
/// Tools, Simulation and Examples. The title is "<scene name>[*] — Impetus", with the marker while modified.
///
/// Before discarding edits that are not saved (New, Open, an example, closing) the window asks
/// with a QMessageBox whose object name is "unsavedChangesBox". The dock layout and the window
/// geometry are kept in QSettings; a window with no saved geometry starts at
/// constants::kDefaultWindowWidth × kDefaultWindowHeight.
///
/// When a run produces a state that is not a finite number (SimulationRunner::diverged()), the
/// run stops on the last finite state and a window-modal message box (object name "divergedBox")
/// names the body and the time and suggests Reset or Undo.
class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    /// A window showing an empty world. Call openScene() or setScene() to show a scene.
    explicit MainWindow(QWidget* parent = nullptr);

    /// Loads the scene at `path` (a file, or a Qt resource path such as kDefaultScenePath) and
    /// shows it, paused, without asking about unsaved work. On failure the current scene stays
    /// untouched and the problems are returned, one "path: reason" line each; nothing is shown.
    QStringList openScene(const QString& path);

    /// What File > Open… does with the chosen file: loads it; a file that fails to load shows its
    /// problems in a modal message box (object name "openErrorBox") and the current scene stays.
    /// A file that loads replaces the scene once the user agreed to discard unsaved edits.
    /// Returns true when the scene was opened.
    bool openSceneInteractively(const QString& path);

    /// What `impetus SCENE.json` does: opens the scene at `path` like openScene(). When it fails to
    /// load, the default example scene is opened instead and the problems are listed in the same
    /// box as File > Open's (object name "openErrorBox"), window-modal, without waiting for it to
    /// be closed. Returns the problems, one "path: reason" line each; empty when `path` opened.
    QStringList openStartupScene(const QString& path);

    /// Shows `world` (paused) under the name `name`, with no file.
    void setScene(model::World world, const QString& name);

    /// File > New: an empty scene, after asking about unsaved edits. True when done.
    bool newScene();

    /// Pauses a run, then saves to `path` (the instant on the canvas) and makes it the scene's
    /// file; a failure shows a message box (object name "saveErrorBox"). True when saved.
    bool saveTo(const QString& path);

    /// File > Save: pauses a run, then saves to the scene's file, or asks for one (Save As) when it
    /// has none.
    bool save();

    /// Asks whether to save unsaved edits (Save, Discard, Cancel) if there are any. True when the
    /// caller may go on and discard the scene.
    bool maybeDiscardChanges();

    /// The name of the scene shown (the title says "<name>[*] — Impetus").
    QString sceneName() const;

    /// The scene document: world, selection, undo stack, file.
    SceneDocument& document() { return *m_document; }

    /// The runner that owns and steps the world.
    SimulationRunner& runner();
    const SimulationRunner& runner() const;

    /// The central canvas.
    CanvasView& canvas() { return *m_canvas; }

    /// The right-hand dock for the attribute pane; its widget is a placeholder until replaced.
    QDockWidget* attributesDock() const { return m_attributesDock; }
    /// The result of the last Simulation › Compare Soft with Rigid, if any.
    const std::optional<controller::RigidSoftComparison>& lastComparison() const { return m_lastComparison; }
    /// The attribute pane inside attributesDock().
    PropertyPane* propertyPane() const { return m_pane; }

    /// The files opened or saved last, most recent first (kept in QSettings).
    QStringList recentFiles() const;

    /// The Play/Pause action (checkable, Space).
    QAction* playAction() const { return m_playAction; }
    /// The Step action (→).
    QAction* stepAction() const { return m_stepAction; }
    /// The Step Back action (←): back one fixed step along the timeline.
    QAction* stepBackAction() const { return m_stepBackAction; }
    /// The run's timeline, and the bar under the canvas that moves along it.
    Timeline& timeline() { return *m_timeline; }
    TimelineBar* timelineBar() const { return m_timelineBar; }
    /// The Reset action (R): back to the world at the last Play.
    QAction* resetAction() const { return m_resetAction; }
    /// Edit > Undo (Ctrl+Z), named after the command it undoes.
    QAction* undoAction() const { return m_undoAction; }
    /// Edit > Redo (Ctrl+Shift+Z), named after the command it redoes.
    QAction* redoAction() const { return m_redoAction; }
    /// Edit > Delete (Del).
    QAction* deleteAction() const { return m_deleteAction; }
    /// View › Vectors: the checkable action that shows arrows of `kind`.
    QAction* vectorAction(VectorKind kind) const { return m_vectorActions.at(static_cast<std::size_t>(kind)); }
    /// Opens a graph of `y` against `x` for the body called `bodyName` (the first moving body when
    /// empty) in a dock of its own (object name "graphDock"), and returns it.
    GraphPanel* addGraph(const QString& bodyName, GraphQuantity y, GraphQuantity x = GraphQuantity::Time);
    /// View › Energy Ledger: opens the ledger chart in a dock (or raises it), which asks the runner
    /// to book every step's energy by cause while it is open.
    void showEnergyLedger();
    /// The graphs open, oldest first.
    std::vector<GraphPanel*> graphPanels() const;
    /// View › New Graph: a graph of the selected body (or the first moving one).
    QAction* newGraphAction() const { return m_newGraphAction; }
    /// View › Trails (checkable).
    QAction* trailsAction() const { return m_trailsAction; }
    /// View > Snap to Grid (checkable).
    QAction* snapAction() const { return m_snapAction; }
    /// The action that makes `kind` the current tool.
    QAction* toolAction(ToolKind kind) const { return m_toolActions.at(kind); }
    /// The speed chooser of the run controls (0.1× … 4×).
    QComboBox* speedBox() const { return m_speedBox; }
    /// The Examples menu.
    QMenu* examplesMenu() const { return m_examplesMenu; }
    /// The scene's lesson and its locks (Lesson menu, lesson dock).
    LessonSession& lesson() const { return *m_lesson; }

protected:
    /// Asks about unsaved edits, then keeps the dock layout in QSettings.
    void closeEvent(QCloseEvent* event) override;

private:
    void createActions();
    void createToolActions();
    void createMenus();
    void createToolBars();
    void createDock();
    void createStatusBar();
    /// Shows the soft bodies' ellipse density (and whether "auto" chose it) and the substeps the
    /// step is split into, with the reason; hides the label when the world has no soft body.
    void updateSoftStatus();
    /// Simulation › Compare Soft with Rigid: runs copies of the scene with the selected soft body
    /// rigid and soft (controller::compareRigidSoft) and shows how far apart their centres of mass
    /// drift.
    void compareSelectedWithRigid();
    void addCanvasShortcut(QAction* action);
    /// View › Vectors and View › Trails: the canvas instruments' menu.
    void createInstrumentMenus(QMenu* viewMenu);
    /// Tells the runner what the instruments need recorded after each step.
    void updateSampling();
    void openSceneDialog();
    bool saveAsDialog();
    void openExample(const QString& path, const QString& title);
    void addRecentFile(const QString& path);
    void fillRecentMenu();
    void onRunningChanged(bool running);
    /// Step is enabled while paused and no Step is being computed.
    void updateStepAction();
    void updateStatus();
    void updateTitle();
    void showProblems(const QString& path, const QStringList& problems);
    QMessageBox* makeProblemsBox(const QString& path, const QStringList& problems, const QString& outcome);
    void showDivergence(const QString& bodyName, double time);
    /// Tells in the status bar that the engine put a body back out of a fixed body: the solve failed
    /// to hold it there (SimulationRunner::keptOut).
    void showKeptOut(const QString& bodyName, const QString& fixedName, double time, int others);

    SceneDocument* m_document;
    CanvasView* m_canvas;
    QDockWidget* m_attributesDock = nullptr;
    PropertyPane* m_pane = nullptr; ///< the attributes dock's widget
    std::optional<controller::RigidSoftComparison> m_lastComparison;
    QString m_lastDirectory;
    QAction* m_newAction = nullptr;
    QAction* m_openAction = nullptr;
    QAction* m_saveAction = nullptr;
    QAction* m_saveAsAction = nullptr;
    QAction* m_quitAction = nullptr;
    QAction* m_undoAction = nullptr;
    QAction* m_redoAction = nullptr;
    QAction* m_deleteAction = nullptr;
    QAction* m_selectAllAction = nullptr;
    QAction* m_snapAction = nullptr;
    QAction* m_frameAction = nullptr;
    QAction* m_playAction = nullptr;
    QAction* m_stepAction = nullptr;
    QAction* m_resetAction = nullptr;
    QAction* m_stepBackAction = nullptr;
    std::array<QAction*, kVectorKindCount> m_vectorActions{};
    QAction* m_trailsAction = nullptr;
    QAction* m_newGraphAction = nullptr;
    Timeline* m_timeline = nullptr;
    TimelineBar* m_timelineBar = nullptr;
    QActionGroup* m_toolGroup = nullptr;
    std::map<ToolKind, QAction*> m_toolActions;
    QComboBox* m_speedBox = nullptr;
    QMenu* m_recentMenu = nullptr;
    QMenu* m_examplesMenu = nullptr;
    QLabel* m_timeLabel = nullptr;
    QLabel* m_energyLabel = nullptr;
    QLabel* m_energyPartsLabel = nullptr;
    QLabel* m_momentumLabel = nullptr;
    QLabel* m_collisionLabel = nullptr;
    QLabel* m_softLabel = nullptr; ///< soft bodies' density and substeps; hidden without any
    PaceIndicator* m_paceIndicator = nullptr; ///< "Running at 0.2× real time"; hidden while keeping up
    QAction* m_softEllipsesAction = nullptr;
    QAction* m_compareRigidAction = nullptr;
    QAction* m_softStrainAction = nullptr;
    LessonSession* m_lesson = nullptr;
};

} // namespace impetus::view
