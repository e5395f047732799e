#include "view/lesson_panel.h"

#include "view/lesson_session.h"
#include "view/lesson_text.h"
#include "view/scene_document.h"

#include <QAccessible>
#include <QColor>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPalette>
#include <QPushButton>
#include <QStringList>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <cmath>

namespace impetus::view {

namespace {

/// The title's size against the window's font: a heading, not a shout in a narrow dock.
constexpr double kTitleFontScale = 1.25;

/// Significant digits of the differences a verdict names: enough to tell 0.12 from 0.13.
constexpr int kVerdictDigits = 3;

/// Verdict colours, a dark green and a dark red with a contrast above 4.5:1 on a light background.
/// The words say right or wrong too, so no one depends on telling the two apart.
const QColor kRightColor{0x15, 0x80, 0x3d};
const QColor kWrongColor{0xb9, 0x1c, 0x1c};

void setTextColor(QLabel* label, const QColor& color)
{
    QPalette palette = label->palette();
    palette.setColor(QPalette::WindowText, color);
    label->setPalette(palette);
}

} // namespace

LessonPanel::LessonPanel(LessonSession& session, QWidget* parent)
    : QWidget(parent)
    , m_session(session)
{
    setAccessibleName(tr("Lesson"));
    auto* layout = new QVBoxLayout(this);

    m_title = new QLabel(this);
    m_title->setObjectName(QStringLiteral("lessonTitle"));
    m_title->setAccessibleName(tr("Lesson title"));
    m_title->setWordWrap(true);
    m_title->setTextFormat(Qt::PlainText);
    QFont titleFont = m_title->font();
    titleFont.setBold(true);
    titleFont.setPointSizeF(titleFont.pointSizeF() * kTitleFontScale);
    m_title->setFont(titleFont);
    layout->addWidget(m_title);

    m_instructions = new QTextBrowser(this);
    m_instructions->setObjectName(QStringLiteral("lessonInstructions"));
    m_instructions->setAccessibleName(tr("Instructions"));
    m_instructions->setOpenExternalLinks(true);
    layout->addWidget(m_instructions, 1);

    m_locks = new QLabel(this);
    m_locks->setObjectName(QStringLiteral("lessonLocks"));
    m_locks->setAccessibleName(tr("What you may change"));
    m_locks->setWordWrap(true);
    m_locks->setTextFormat(Qt::PlainText);
    layout->addWidget(m_locks);

    m_questions = new QWidget(this);
    m_questionsLayout = new QVBoxLayout(m_questions);
    m_questionsLayout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_questions);

    connect(&m_session, &LessonSession::locksChanged, this, &LessonPanel::update);
    // The list of what may change names bodies, which may be renamed.
    connect(&m_session.document(), &SceneDocument::worldChanged, this, &LessonPanel::updateLocks);
    update();
}

void LessonPanel::update()
{
    const std::optional<model::Lesson>& lesson = m_session.lesson();
    if (!m_built || lesson != m_shown) {
        if (lesson) {
            m_title->setText(QString::fromStdString(lesson->title));
            m_instructions->setMarkdown(QString::fromStdString(lesson->instructions));
        } else {
            m_title->setText(tr("No lesson"));
            m_instructions->setPlainText(
                tr("This scene has no lesson. A teacher can write one with Lesson › Edit."));
        }
        const std::vector<model::LessonQuestion> none;
        const std::vector<model::LessonQuestion>& questions = lesson ? lesson->questions : none;
        // Answers typed so far stay unless the questions themselves changed.
        if (!m_shown || questions != m_shown->questions || m_rows.size() != questions.size())
            rebuildQuestions(questions);
        m_shown = lesson;
        m_built = true;
    }
    updateLocks();
}

void LessonPanel::rebuildQuestions(const std::vector<model::LessonQuestion>& questions)
{
    m_rows.clear();
    while (QLayoutItem* item = m_questionsLayout->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    for (std::size_t i = 0; i < questions.size(); ++i) {
        const model::LessonQuestion& question = questions[i];
        const int index = static_cast<int>(i);
        auto* box = new QWidget(m_questions);
        auto* column = new QVBoxLayout(box);
        column->setContentsMargins(0, 0, 0, 0);
        auto* prompt = new QLabel(tr("%1. %2").arg(index + 1).arg(QString::fromStdString(question.prompt)), box);
        prompt->setWordWrap(true);
        prompt->setTextFormat(Qt::PlainText);
        column->addWidget(prompt);

        QuestionRow row;
        auto* line = new QHBoxLayout;
        row.answer = new QLineEdit(box);
        row.answer->setObjectName(QStringLiteral("lessonAnswer%1").arg(index));
        row.answer->setAccessibleName(tr("Answer to question %1").arg(index + 1));
        row.answer->setPlaceholderText(tr("your answer"));
        prompt->setBuddy(row.answer);
        line->addWidget(row.answer, 1);
        const QString unit = QString::fromStdString(question.unit);
        if (!unit.isEmpty()) {
            row.answer->setAccessibleDescription(tr("Unit: %1").arg(unit));
            line->addWidget(new QLabel(unit, box));
        }
        row.check = new QPushButton(tr("Check"), box);
        row.check->setObjectName(QStringLiteral("lessonCheck%1").arg(index));
        row.check->setAccessibleName(tr("Check answer %1").arg(index + 1));
        line->addWidget(row.check);
        column->addLayout(line);
        row.result = new QLabel(box);
        row.result->setObjectName(QStringLiteral("lessonResult%1").arg(index));
        row.result->setAccessibleName(tr("Verdict on answer %1").arg(index + 1));
        row.result->setWordWrap(true);
        row.result->hide();
        column->addWidget(row.result);
        m_questionsLayout->addWidget(box);

        connect(row.check, &QPushButton::clicked, this, [this, index] { check(index); });
        connect(row.answer, &QLineEdit::returnPressed, this, [this, index] { check(index); });
        m_rows.push_back(row);
    }
}

bool LessonPanel::check(int index)
{
    const std::optional<model::Lesson>& lesson = m_session.lesson();
    if (!lesson || index < 0 || static_cast<std::size_t>(index) >= lesson->questions.size() ||
        static_cast<std::size_t>(index) >= m_rows.size())
        return false;
    const model::LessonQuestion& question = lesson->questions[static_cast<std::size_t>(index)];
    const QuestionRow& row = m_rows[static_cast<std::size_t>(index)];
    const QString unit = QString::fromStdString(question.unit);
    const QString text = row.answer->text().trimmed();
    const std::optional<double> value = parseLessonNumber(locale(), text);
    const auto amount = [this, &unit](double x) {
        return withUnit(formatLessonNumber(locale(), x, kVerdictDigits), unit);
    };

    bool right = false;
    QString verdict;
    if (text.isEmpty()) {
        verdict = tr("Type your answer first.");
    } else if (!value) {
        verdict = tr("“%1” is not a number.").arg(text);
    } else if (question.accepts(*value)) {
        right = true;
        verdict = tr("Right! You are %1 off; up to %2 counts as right.")
                      .arg(amount(std::abs(*value - question.answer)), amount(question.tolerance));
    } else if (*value > question.answer) {
        verdict = tr("Wrong: %1 too high (up to %2 off counts as right).")
                      .arg(amount(*value - question.answer), amount(question.tolerance));
    } else {
        verdict = tr("Wrong: %1 too low (up to %2 off counts as right).")
                      .arg(amount(question.answer - *value), amount(question.tolerance));
    }
    row.result->setText(verdict);
    setTextColor(row.result, right ? kRightColor : kWrongColor);
    row.result->show();
    QAccessibleEvent event(row.result, QAccessible::Alert);
    QAccessible::updateAccessibility(&event);
    return right;
}

void LessonPanel::updateLocks()
{
    const std::optional<model::Lesson>& lesson = m_session.lesson();
    m_locks->setVisible(lesson.has_value());
    if (!lesson)
        return;
    if (m_session.isEditing()) {
        m_locks->setText(tr("Lesson › Edit is on: nothing is locked."));
        return;
    }
    const model::World& world = m_session.document().world();
    QStringList parts;
    for (const model::EditableBody& entry : lesson->editableBodies) {
        if (entry.body.index < world.bodies.size())
            parts << tr("“%1”: %2").arg(QString::fromStdString(world.body(entry.body).name),
                                       attributeList(entry.attributes));
    }
    for (const model::EditableSpring& entry : lesson->editableSprings) {
        if (entry.spring < world.springs.size())
            parts << tr("spring %1: %2").arg(entry.spring).arg(springAttributeList(entry.attributes));
    }
    for (const model::EditableJoint& entry : lesson->editableJoints) {
        if (entry.joint < world.joints.size())
            parts << tr("joint %1: %2").arg(entry.joint).arg(jointAttributeList(entry.attributes));
    }
    if (lesson->editableWorld.any())
        parts << tr("world: %1").arg(attributeList(lesson->editableWorld));
    m_locks->setText(parts.isEmpty()
                         ? tr("Everything in this scene is locked by the lesson.")
                         : tr("You may change %1. Everything else is locked by the lesson.").arg(parts.join(QStringLiteral("; "))));
}

} // namespace impetus::view
