#pragma once
/// \file lesson_dock.h
/// The Lesson dock and the Lesson menu of the main window.

#include <QDockWidget>

class QStackedWidget;

namespace impetus::view {

class LessonEditor;
class LessonPanel;
class LessonSession;
class MainWindow;

/// The dock (object name "lessonDock") that shows a scene's lesson: the LessonPanel for students,
/// or the LessonEditor while Lesson › Edit is on.
class LessonDock : public QDockWidget {
    Q_OBJECT

public:
    /// A dock for `session`'s lesson; the session must outlive it.
    explicit LessonDock(LessonSession& session, QWidget* parent = nullptr);

    /// What students see.
    LessonPanel* panel() const { return m_panel; }
    /// What Lesson › Edit shows.
    LessonEditor* editor() const { return m_editor; }

private:
    QStackedWidget* m_pages = nullptr;
    LessonPanel* m_panel = nullptr;
    LessonEditor* m_editor = nullptr;
};

/// Gives `window` its lessons: a LessonSession on its document (a child of the window, returned),
/// whose locks the canvas and the attribute pane obey; a LessonDock on the right, shown whenever
/// the scene opened has a lesson; and a Lesson menu before Examples with Edit (object name
/// "editLessonAction", checkable: lifts the locks and shows the editor, making a lesson first
/// when the scene has none), Remove Lesson ("removeLessonAction") and the dock's own toggle. While
/// the locks are in force, the drawing tools are disabled.
LessonSession* addLessons(MainWindow& window);

} // namespace impetus::view
