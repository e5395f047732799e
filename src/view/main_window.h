#pragma once
/// \file main_window.h
/// The main window: the canvas, the run controls and the status bar.

#include "model/world.h"

#include <QMainWindow>
#include <QString>
#include <QStringList>

class QAction;
class QLabel;

namespace impetus::view {

class CanvasView;
class SimulationRunner;

/// The application window. The canvas is the central widget; a tool bar holds Play/Pause (Space)
/// and Step (→); the status bar shows the simulated time and the total energy. File > Open…
/// replaces the scene, File > Quit closes the window. The title is "Impetus — <scene name>".
class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    /// A window showing an empty world. Call openScene() or setScene() to show a scene.
    explicit MainWindow(QWidget* parent = nullptr);

    /// Loads the scene at `path` (a file, or a Qt resource path such as kDefaultScenePath) and
    /// shows it, paused. On failure the current scene stays untouched and the problems are
    /// returned, one "path: reason" line each; nothing is shown to the user.
    QStringList openScene(const QString& path);

    /// openScene(), telling the user: a file that fails to load shows its problems in a modal
    /// message box, and the current scene stays. What File > Open… does with the chosen file.
    /// Returns true when the scene was opened.
    bool openSceneInteractively(const QString& path);

    /// Shows `world` (paused) under the name `name`.
    void setScene(model::World world, const QString& name);

    /// The name of the scene shown (the title says "Impetus — <name>").
    QString sceneName() const { return m_sceneName; }

    /// The runner that owns and steps the world.
    SimulationRunner& runner() { return *m_runner; }
    const SimulationRunner& runner() const { return *m_runner; }

    /// The central canvas.
    CanvasView& canvas() { return *m_canvas; }

    /// The Play/Pause action (checkable, Space).
    QAction* playAction() const { return m_playAction; }

    /// The Step action (→).
    QAction* stepAction() const { return m_stepAction; }

private:
    void createActions();
    void createMenus();
    void createToolBar();
    void createStatusBar();
    void openSceneDialog();
    void onRunningChanged(bool running);
    void updateStatus();
    void updateTitle();

    SimulationRunner* m_runner;
    CanvasView* m_canvas;
    QString m_sceneName;
    QString m_lastDirectory;
    QAction* m_openAction = nullptr;
    QAction* m_quitAction = nullptr;
    QAction* m_playAction = nullptr;
    QAction* m_stepAction = nullptr;
    QLabel* m_timeLabel = nullptr;
    QLabel* m_energyLabel = nullptr;
    QLabel* m_collisionLabel = nullptr;
};

} // namespace impetus::view
