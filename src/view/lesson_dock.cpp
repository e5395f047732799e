#include "view/lesson_dock.h"

#include "view/canvas_view.h"
#include "view/lesson_commands.h"
#include "view/lesson_editor.h"
#include "view/lesson_panel.h"
#include "view/lesson_session.h"
#include "view/main_window.h"
#include "view/property_pane.h"
#include "view/scene_document.h"

#include <QAction>
#include <QMenu>
#include <QMenuBar>
#include <QSignalBlocker>
#include <QStackedWidget>
#include <QUndoStack>

#include <algorithm>
#include <array>

namespace impetus::view {

namespace {

/// The tools that add bodies, springs or joints: a lesson's locks disable them.
constexpr std::array<ToolKind, 7> kDrawingTools = {ToolKind::Polygon, ToolKind::Box,  ToolKind::Circle, ToolKind::Ellipse,
                                                   ToolKind::Spring,  ToolKind::Pin,  ToolKind::Rod};

/// Enables the drawing tools, or disables them while the locks are in force, and then leaves a
/// drawing tool for Select.
void applyDrawingLock(MainWindow& window, const LessonSession& session)
{
    const std::optional<QString> lock = session.drawingLock();
    for (const ToolKind kind : kDrawingTools) {
        QAction* action = window.toolAction(kind);
        action->setEnabled(!lock);
    }
    const ToolKind current = window.canvas().toolKind();
    if (lock && std::find(kDrawingTools.begin(), kDrawingTools.end(), current) != kDrawingTools.end())
        window.canvas().setTool(ToolKind::Select);
}

} // namespace

LessonDock::LessonDock(LessonSession& session, QWidget* parent)
    : QDockWidget(tr("Lesson"), parent)
{
    setObjectName(QStringLiteral("lessonDock"));
    setAccessibleName(tr("Lesson"));
    setAllowedAreas(Qt::LeftDockWidgetArea | Qt::RightDockWidgetArea);
    m_pages = new QStackedWidget(this);
    m_panel = new LessonPanel(session, m_pages);
    m_editor = new LessonEditor(session, m_pages);
    m_pages->addWidget(m_panel);
    m_pages->addWidget(m_editor);
    setWidget(m_pages);
    const auto showPage = [this](bool editing) {
        m_pages->setCurrentWidget(editing ? static_cast<QWidget*>(m_editor) : m_panel);
        setWindowTitle(editing ? tr("Lesson (editing)") : tr("Lesson"));
    };
    connect(&session, &LessonSession::editingChanged, this, showPage);
    showPage(session.isEditing());
}

LessonSession* addLessons(MainWindow& window)
{
    SceneDocument& document = window.document();
    auto* session = new LessonSession(document, &window);
    window.canvas().setLessonSession(session);
    window.propertyPane()->setLessonSession(session);

    auto* dock = new LessonDock(*session, &window);
    window.addDockWidget(Qt::RightDockWidgetArea, dock);
    dock->setVisible(session->lesson().has_value());

    auto* menu = new QMenu(LessonDock::tr("&Lesson"), &window);
    menu->setObjectName(QStringLiteral("lessonMenu"));
    window.menuBar()->insertMenu(window.examplesMenu()->menuAction(), menu);

    QAction* edit = menu->addAction(LessonDock::tr("&Edit"));
    edit->setObjectName(QStringLiteral("editLessonAction"));
    edit->setCheckable(true);
    edit->setStatusTip(LessonDock::tr("Lift the lesson's locks and write its title, instructions, locks and questions"));
    QObject::connect(edit, &QAction::toggled, session, [&window, session, dock](bool on) {
        SceneDocument& doc = window.document();
        if (on && !session->lesson()) {
            model::Lesson lesson;
            lesson.title = doc.displayName().isEmpty() ? LessonDock::tr("Lesson").toStdString()
                                                       : doc.displayName().toStdString();
            doc.undoStack()->push(new SetLessonCommand(doc, lesson, LessonDock::tr("Create lesson")));
        }
        session->setEditing(on);
        if (on) {
            dock->show();
            dock->raise();
        }
    });

    QAction* remove = menu->addAction(LessonDock::tr("&Remove Lesson"));
    remove->setObjectName(QStringLiteral("removeLessonAction"));
    remove->setStatusTip(LessonDock::tr("Take the lesson out of the scene: no locks, no questions"));
    QObject::connect(remove, &QAction::triggered, session, [&window, session] {
        SceneDocument& doc = window.document();
        session->setEditing(false);
        doc.undoStack()->push(new SetLessonCommand(doc, std::nullopt, LessonDock::tr("Remove lesson")));
    });

    menu->addSeparator();
    QAction* toggle = dock->toggleViewAction();
    toggle->setText(LessonDock::tr("Lesson &Panel"));
    toggle->setObjectName(QStringLiteral("lessonPanelAction"));
    menu->addAction(toggle);

    QObject::connect(session, &LessonSession::editingChanged, edit, [edit](bool on) {
        const QSignalBlocker blocker(edit);
        edit->setChecked(on);
    });
    const auto onLocksChanged = [&window, session, remove] {
        // Undoing the lesson's creation leaves nothing to edit.
        if (session->isEditing() && !session->lesson())
            session->setEditing(false);
        remove->setEnabled(session->lesson().has_value());
        applyDrawingLock(window, *session);
        SceneDocument& doc = window.document();
        window.propertyPane()->showSelection(doc.world(), doc.selection());
    };
    QObject::connect(session, &LessonSession::locksChanged, &window, onLocksChanged);
    // A scene that comes with a lesson shows it; one without hides the dock.
    QObject::connect(&document, &SceneDocument::sceneReplaced, dock,
                     [dock, session] { dock->setVisible(session->lesson().has_value()); });
    onLocksChanged();
    return session;
}

} // namespace impetus::view
