#pragma once
/// \file lesson_editor.h
/// Lesson › Edit: where a teacher writes the lesson of a scene.

#include "model/lesson.h"

#include <QWidget>

#include <optional>
#include <string>
#include <vector>

class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QPushButton;
class QTableWidget;
class QTableWidgetItem;
class QTreeWidget;
class QTreeWidgetItem;

namespace impetus::view {

class LessonSession;
enum class LessonTyping;

/// The lesson editor: the title ("lessonTitleEdit"), the instructions in plain text or simple
/// Markdown ("lessonInstructionsEdit"), what students may change ("lessonLocksTree": the world
/// settings, every body and every spring, each with its attributes as check boxes; a ticked box is
/// unlocked)
/// and the questions ("lessonQuestionsTable": prompt, answer, unit, tolerance), with Add Question
/// ("addQuestion") and Remove Question ("removeQuestion").
///
/// Every change is one SetLessonCommand on the document's undo stack; typing in the title or the
/// instructions undoes as one step. A bad value (an empty title or prompt, an answer that is not
/// a number, a tolerance that is not > 0) is refused with a message ("lessonEditorMessage") and the
/// field goes back to the lesson's value. Does nothing while the scene has no lesson.
class LessonEditor : public QWidget {
    Q_OBJECT

public:
    /// An editor of `session`'s lesson; the session must outlive it.
    explicit LessonEditor(LessonSession& session, QWidget* parent = nullptr);

    /// The text of the message area: the last refusal, or empty.
    QString message() const;

private:
    /// Shows the lesson where it differs from what the widgets show, leaving the rest (and the
    /// text cursor) alone.
    void refresh();
    void refreshLocks();
    void refreshQuestions();

    /// Pushes a command that makes `lesson` the scene's lesson, when it differs.
    void commit(const model::Lesson& lesson, const QString& actionName, LessonTyping typing);

    void onTitleEdited(const QString& text);
    void onTitleFinished();
    void onInstructionsChanged();
    void onLockChanged(QTreeWidgetItem* item);
    void onQuestionChanged(QTableWidgetItem* item);
    void addQuestion();
    void removeQuestion();

    void refuse(const QString& message);
    void clearMessage();
    QString formatNumber(double value) const;

    LessonSession& m_session;
    QLineEdit* m_title = nullptr;
    QPlainTextEdit* m_instructions = nullptr;
    QTreeWidget* m_locks = nullptr;
    QTableWidget* m_questions = nullptr;
    QPushButton* m_addQuestion = nullptr;
    QPushButton* m_removeQuestion = nullptr;
    QLabel* m_message = nullptr;
    /// What the lock tree shows: the body names and spring labels, and the lesson's editable sets.
    std::vector<std::string> m_lockNames;
    std::optional<model::Lesson> m_lockLesson;
};

} // namespace impetus::view
