#pragma once
/// \file lesson_panel.h
/// What students see of a lesson: its title, its instructions and its questions, each with an
/// answer field and a Check button.

#include "model/lesson.h"

#include <QWidget>

#include <optional>
#include <vector>

class QLabel;
class QLineEdit;
class QPushButton;
class QTextBrowser;
class QVBoxLayout;

namespace impetus::view {

class LessonSession;

/// The lesson panel. Shows the lesson's title (object name "lessonTitle"), its instructions as
/// Markdown ("lessonInstructions"), what students may change ("lessonLocks"), and per question i
/// the prompt, an answer field ("lessonAnswer<i>", in the user's number format, a decimal point
/// always accepted), its unit, a Check button ("lessonCheck<i>"; Enter in the field does the same)
/// and the verdict ("lessonResult<i>"): right, or wrong and by how much, in words and not by
/// colour alone. Follows the session's lesson; answers typed stay while the questions do not
/// change.
class LessonPanel : public QWidget {
    Q_OBJECT

public:
    /// A panel for `session`'s lesson; the session must outlive it.
    explicit LessonPanel(LessonSession& session, QWidget* parent = nullptr);

    /// Checks the answer typed for question `index` and shows the verdict. Returns true when it is
    /// right; false when wrong, not a number, or there is no such question.
    bool check(int index);

private:
    struct QuestionRow {
        QLineEdit* answer = nullptr;
        QPushButton* check = nullptr;
        QLabel* result = nullptr;
    };

    /// Shows the session's lesson when it differs from the one shown.
    void update();
    void rebuildQuestions(const std::vector<model::LessonQuestion>& questions);
    void updateLocks();

    LessonSession& m_session;
    std::optional<model::Lesson> m_shown; ///< the lesson the widgets show
    bool m_built = false; ///< the widgets show m_shown (false until the first update)
    QLabel* m_title = nullptr;
    QTextBrowser* m_instructions = nullptr;
    QLabel* m_locks = nullptr;
    QWidget* m_questions = nullptr;
    QVBoxLayout* m_questionsLayout = nullptr;
    std::vector<QuestionRow> m_rows;
};

} // namespace impetus::view
