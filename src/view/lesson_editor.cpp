#include "view/lesson_editor.h"

#include "view/message_label.h"

#include "view/lesson_commands.h"
#include "view/lesson_session.h"
#include "view/lesson_text.h"
#include "view/scene_document.h"

#include <QAccessible>
#include <QColor>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPalette>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QTreeWidget>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>
#include <array>
#include <bitset>
#include <utility>

namespace impetus::view {

namespace {

/// Significant digits of answers and tolerances in the table: all that a teacher types survives
/// being shown again.
constexpr int kEditorDigits = 12;

/// The tolerance a new question starts with, in its unit, until the teacher sets one: one unit,
/// loose enough to be noticed and changed.
constexpr double kNewQuestionTolerance = 1.0;


/// Columns of the questions table.
enum Column { PromptColumn, AnswerColumn, UnitColumn, ToleranceColumn, ColumnCount };

/// The item data role that holds a lock tree item's body index (−1: the world) or attribute.
constexpr int kIndexRole = Qt::UserRole;

/// The lock tree's top-level item of the world settings.
constexpr int kWorldItem = -1;

/// The item data role that holds what a top-level item and its attributes are about (ItemKind);
/// kIndexRole is then the index of the body, spring or joint.
constexpr int kKindRole = Qt::UserRole + 1;

/// What a lock tree item is about.
enum class ItemKind { Body, World, Spring, Joint };

/// The attributes ticked under a top-level item of the lock tree, as a bitset of N.
template <std::size_t N>
std::bitset<N> tickedAttributes(const QTreeWidgetItem* parent)
{
    std::bitset<N> attributes;
    for (int i = 0; i < parent->childCount(); ++i)
        attributes.set(static_cast<std::size_t>(parent->child(i)->data(0, kIndexRole).toInt()),
                       parent->child(i)->checkState(0) == Qt::Checked);
    return attributes;
}

/// A top-level item of the lock tree for the `index`-th item of `kind`, with a box for each of
/// `attributes`.
template <class Attribute, std::size_t N>
void addLockItem(QTreeWidget* tree, const QString& label, ItemKind kind, int index,
                 const std::array<Attribute, N>& attributes)
{
    auto* item = new QTreeWidgetItem(tree, {label});
    item->setData(0, kIndexRole, index);
    item->setData(0, kKindRole, static_cast<int>(kind));
    for (const Attribute attribute : attributes) {
        auto* child = new QTreeWidgetItem(item, {attributeTitle(attribute)});
        child->setData(0, kIndexRole, static_cast<int>(attribute));
    }
}

ItemKind kindOf(const QTreeWidgetItem* item) { return static_cast<ItemKind>(item->data(0, kKindRole).toInt()); }

Qt::CheckState checkState(bool on) { return on ? Qt::Checked : Qt::Unchecked; }

/// The state of a top-level item from its children: all, some or none ticked.
Qt::CheckState summary(const QTreeWidgetItem* parent)
{
    int ticked = 0;
    for (int i = 0; i < parent->childCount(); ++i)
        ticked += parent->child(i)->checkState(0) == Qt::Checked ? 1 : 0;
    if (ticked == 0)
        return Qt::Unchecked;
    return ticked == parent->childCount() ? Qt::Checked : Qt::PartiallyChecked;
}

} // namespace

LessonEditor::LessonEditor(LessonSession& session, QWidget* parent)
    : QWidget(parent)
    , m_session(session)
{
    setAccessibleName(tr("Lesson editor"));
    auto* layout = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    layout->addLayout(form);

    m_title = new QLineEdit(this);
    m_title->setObjectName(QStringLiteral("lessonTitleEdit"));
    m_title->setAccessibleName(tr("Lesson title"));
    form->addRow(tr("&Title"), m_title);
    connect(m_title, &QLineEdit::textEdited, this, &LessonEditor::onTitleEdited);
    connect(m_title, &QLineEdit::editingFinished, this, &LessonEditor::onTitleFinished);

    m_instructions = new QPlainTextEdit(this);
    m_instructions->setObjectName(QStringLiteral("lessonInstructionsEdit"));
    m_instructions->setAccessibleName(tr("Instructions"));
    m_instructions->setAccessibleDescription(tr("Plain text or simple Markdown: **bold**, *italic*, lists"));
    m_instructions->setPlaceholderText(tr("What students should do; **bold**, *italic* and lists work"));
    // Tab moves on to the next field rather than typing a tab into the instructions.
    m_instructions->setTabChangesFocus(true);
    auto* instructionsLabel = new QLabel(tr("&Instructions"), this);
    instructionsLabel->setBuddy(m_instructions);
    layout->addWidget(instructionsLabel);
    layout->addWidget(m_instructions, 1);
    connect(m_instructions, &QPlainTextEdit::textChanged, this, &LessonEditor::onInstructionsChanged);

    auto* locksLabel = new QLabel(tr("Students may change (ticked; everything else is locked):"), this);
    locksLabel->setWordWrap(true);
    layout->addWidget(locksLabel);
    m_locks = new QTreeWidget(this);
    m_locks->setObjectName(QStringLiteral("lessonLocksTree"));
    m_locks->setAccessibleName(tr("What students may change"));
    m_locks->setHeaderHidden(true);
    locksLabel->setBuddy(m_locks);
    layout->addWidget(m_locks, 1);
    connect(m_locks, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item) { onLockChanged(item); });

    auto* questionsLabel = new QLabel(tr("&Questions"), this);
    layout->addWidget(questionsLabel);
    m_questions = new QTableWidget(0, ColumnCount, this);
    m_questions->setObjectName(QStringLiteral("lessonQuestionsTable"));
    m_questions->setAccessibleName(tr("Questions"));
    m_questions->setHorizontalHeaderLabels({tr("Question"), tr("Answer"), tr("Unit"), tr("Tolerance (±)")});
    m_questions->horizontalHeader()->setSectionResizeMode(PromptColumn, QHeaderView::Stretch);
    m_questions->setSelectionMode(QAbstractItemView::SingleSelection);
    m_questions->setTabKeyNavigation(false);
    questionsLabel->setBuddy(m_questions);
    layout->addWidget(m_questions, 1);
    connect(m_questions, &QTableWidget::itemChanged, this, &LessonEditor::onQuestionChanged);

    auto* buttons = new QHBoxLayout;
    m_addQuestion = new QPushButton(tr("Add Question"), this);
    m_addQuestion->setObjectName(QStringLiteral("addQuestion"));
    m_removeQuestion = new QPushButton(tr("Remove Question"), this);
    m_removeQuestion->setObjectName(QStringLiteral("removeQuestion"));
    m_removeQuestion->setToolTip(tr("Remove the current question"));
    buttons->addWidget(m_addQuestion);
    buttons->addWidget(m_removeQuestion);
    buttons->addStretch(1);
    layout->addLayout(buttons);
    connect(m_addQuestion, &QPushButton::clicked, this, &LessonEditor::addQuestion);
    connect(m_removeQuestion, &QPushButton::clicked, this, &LessonEditor::removeQuestion);

    m_message = makeMessageLabel(QStringLiteral("lessonEditorMessage"), tr("Message"), this);
    layout->addWidget(m_message);

    connect(&m_session, &LessonSession::locksChanged, this, &LessonEditor::refresh);
    // Bodies come, go and are renamed without the lesson changing; the lock tree follows them.
    connect(&m_session.document(), &SceneDocument::worldChanged, this, &LessonEditor::refreshLocks);
    refresh();
}

QString LessonEditor::message() const { return m_message->text(); }

// ---- Showing ------------------------------------------------------------------------------------

void LessonEditor::refresh()
{
    const std::optional<model::Lesson>& lesson = m_session.lesson();
    for (QWidget* widget : std::initializer_list<QWidget*>{m_title, m_instructions, m_locks, m_questions,
                                                           m_addQuestion, m_removeQuestion})
        widget->setEnabled(lesson.has_value());
    const QString title = lesson ? QString::fromStdString(lesson->title) : QString();
    // An empty title being typed over is kept: it was refused, and the old one still holds.
    if (m_title->text() != title && !(m_title->hasFocus() && m_title->text().isEmpty()))
        m_title->setText(title);
    const QString instructions = lesson ? QString::fromStdString(lesson->instructions) : QString();
    // Typing makes the lesson's text equal to the field's, so only undo and redo get here.
    if (m_instructions->toPlainText() != instructions) {
        const QSignalBlocker blocker(m_instructions);
        m_instructions->setPlainText(instructions);
    }
    refreshLocks();
    refreshQuestions();
}

void LessonEditor::refreshLocks()
{
    const model::World& world = m_session.document().world();
    const std::optional<model::Lesson>& lesson = m_session.lesson();
    // The tree's items: every body by name, then every spring and every joint by its ends.
    std::vector<std::string> names;
    names.reserve(world.bodies.size() + world.springs.size() + world.joints.size() + 1);
    for (const model::Body& body : world.bodies)
        names.push_back(body.name);
    const auto endName = [&world](std::optional<model::BodyId> body) {
        return body && body->index < world.bodies.size() ? QStringLiteral("“%1”").arg(QString::fromStdString(world.body(*body).name))
                                                          : tr("the world");
    };
    std::vector<QString> springLabels;
    for (std::size_t i = 0; i < world.springs.size(); ++i) {
        const model::Spring& spring = world.springs[i];
        springLabels.push_back(tr("Spring %1 (%2 to %3)").arg(i).arg(endName(spring.bodyA), endName(spring.bodyB)));
        names.push_back(springLabels.back().toStdString());
    }
    std::vector<QString> jointLabels;
    for (std::size_t i = 0; i < world.joints.size(); ++i) {
        const model::Joint& joint = world.joints[i];
        jointLabels.push_back(joint.type == model::JointType::Pin
                                  ? tr("Pin %1 (%2 to %3)").arg(i).arg(endName(joint.bodyA), endName(joint.bodyB))
                                  : tr("Rod %1 (%2 to %3)").arg(i).arg(endName(joint.bodyA), endName(joint.bodyB)));
        names.push_back(jointLabels.back().toStdString());
    }
    // The counts end the list too: a body named like a spring's label must not pass for it.
    names.push_back(std::to_string(world.bodies.size()) + ' ' + std::to_string(world.springs.size()));
    if (names == m_lockNames && lesson == m_lockLesson)
        return;
    const QSignalBlocker blocker(m_locks);
    // A new set of bodies, springs or joints gets a new tree; otherwise the boxes are ticked in
    // place, because this may run inside itemChanged of one of them.
    if (names != m_lockNames || m_locks->topLevelItemCount() != static_cast<int>(names.size())) {
        m_locks->clear();
        addLockItem(m_locks, tr("World settings"), ItemKind::World, kWorldItem, model::kWorldAttributes);
        for (std::size_t i = 0; i < world.bodies.size(); ++i) {
            addLockItem(m_locks, QStringLiteral("“%1”").arg(QString::fromStdString(names[i])), ItemKind::Body,
                        static_cast<int>(i), model::kBodyAttributes);
        }
        for (std::size_t i = 0; i < springLabels.size(); ++i)
            addLockItem(m_locks, springLabels[i], ItemKind::Spring, static_cast<int>(i), model::kSpringAttributes);
        for (std::size_t i = 0; i < jointLabels.size(); ++i)
            addLockItem(m_locks, jointLabels[i], ItemKind::Joint, static_cast<int>(i), model::kJointAttributes);
    }
    for (int top = 0; top < m_locks->topLevelItemCount(); ++top) {
        QTreeWidgetItem* parent = m_locks->topLevelItem(top);
        const int index = parent->data(0, kIndexRole).toInt();
        const auto item = static_cast<std::size_t>(std::max(index, 0));
        for (int i = 0; i < parent->childCount(); ++i) {
            QTreeWidgetItem* child = parent->child(i);
            const auto bit = static_cast<std::size_t>(child->data(0, kIndexRole).toInt());
            bool on = false;
            if (lesson) {
                switch (kindOf(parent)) {
                case ItemKind::Spring:
                    on = lesson->editableSpring(item).test(bit);
                    break;
                case ItemKind::Joint:
                    on = lesson->editableJoint(item).test(bit);
                    break;
                case ItemKind::World:
                    on = lesson->editableWorld.test(bit);
                    break;
                case ItemKind::Body:
                    on = lesson->editable(model::BodyId{static_cast<std::uint32_t>(item)}).test(bit);
                    break;
                }
            }
            child->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
            child->setCheckState(0, checkState(on));
        }
        parent->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
        parent->setCheckState(0, summary(parent));
    }
    m_lockNames = std::move(names);
    m_lockLesson = lesson;
}

void LessonEditor::refreshQuestions()
{
    const std::optional<model::Lesson>& lesson = m_session.lesson();
    const std::vector<model::LessonQuestion> none;
    const std::vector<model::LessonQuestion>& questions = lesson ? lesson->questions : none;
    const QSignalBlocker blocker(m_questions);
    const int rows = static_cast<int>(questions.size());
    m_questions->setRowCount(rows);
    for (int row = 0; row < rows; ++row) {
        const model::LessonQuestion& question = questions[static_cast<std::size_t>(row)];
        const QString texts[ColumnCount] = {QString::fromStdString(question.prompt), formatNumber(question.answer),
                                            QString::fromStdString(question.unit), formatNumber(question.tolerance)};
        for (int column = 0; column < ColumnCount; ++column) {
            // Items are updated in place: this may run inside itemChanged, whose item must live on.
            QTableWidgetItem* item = m_questions->item(row, column);
            if (!item) {
                item = new QTableWidgetItem;
                m_questions->setItem(row, column, item);
            }
            if (item->text() != texts[column])
                item->setText(texts[column]);
        }
    }
    m_removeQuestion->setEnabled(lesson.has_value() && rows > 0);
}

// ---- Editing ------------------------------------------------------------------------------------

void LessonEditor::commit(const model::Lesson& lesson, const QString& actionName, LessonTyping typing)
{
    if (m_session.lesson() == lesson)
        return;
    SceneDocument& document = m_session.document();
    document.undoStack()->push(new SetLessonCommand(document, lesson, actionName, typing));
}

void LessonEditor::onTitleEdited(const QString& text)
{
    const std::optional<model::Lesson>& current = m_session.lesson();
    if (!current)
        return;
    const QString title = text.trimmed();
    if (title.isEmpty()) {
        refuse(tr("A lesson needs a title."));
        return;
    }
    clearMessage();
    model::Lesson lesson = *current;
    lesson.title = title.toStdString();
    commit(lesson, tr("Change lesson title"), LessonTyping::Title);
}

void LessonEditor::onTitleFinished()
{
    // A title left empty goes back to the lesson's, which the refusal kept.
    if (m_title->text().trimmed().isEmpty() && m_session.lesson())
        m_title->setText(QString::fromStdString(m_session.lesson()->title));
}

void LessonEditor::onInstructionsChanged()
{
    const std::optional<model::Lesson>& current = m_session.lesson();
    if (!current)
        return;
    model::Lesson lesson = *current;
    lesson.instructions = m_instructions->toPlainText().toStdString();
    commit(lesson, tr("Change lesson instructions"), LessonTyping::Instructions);
}

void LessonEditor::onLockChanged(QTreeWidgetItem* item)
{
    const std::optional<model::Lesson>& current = m_session.lesson();
    if (!current)
        return;
    QTreeWidgetItem* parent = item->parent() ? item->parent() : item;
    if (!item->parent()) {
        // A body's own box ticks or clears all of its attributes at once.
        const QSignalBlocker blocker(m_locks);
        const bool on = item->checkState(0) != Qt::Unchecked;
        for (int i = 0; i < item->childCount(); ++i)
            item->child(i)->setCheckState(0, checkState(on));
    }
    const int index = parent->data(0, kIndexRole).toInt();
    model::Lesson lesson = *current;
    QString actionName;
    switch (kindOf(parent)) {
    case ItemKind::Spring:
        lesson.setEditableSpring(static_cast<std::size_t>(index), tickedAttributes<model::kSpringAttributeCount>(parent));
        actionName = tr("Change what students may change of spring %1").arg(index);
        break;
    case ItemKind::Joint:
        lesson.setEditableJoint(static_cast<std::size_t>(index), tickedAttributes<model::kJointAttributeCount>(parent));
        actionName = tr("Change what students may change of joint %1").arg(index);
        break;
    case ItemKind::World:
        lesson.editableWorld = tickedAttributes<model::kWorldAttributeCount>(parent);
        actionName = tr("Change which world settings students may change");
        break;
    case ItemKind::Body: {
        lesson.setEditable(model::BodyId{static_cast<std::uint32_t>(index)},
                           tickedAttributes<model::kBodyAttributeCount>(parent));
        const model::World& world = m_session.document().world();
        const QString name = static_cast<std::size_t>(index) < world.bodies.size()
            ? QString::fromStdString(world.bodies[static_cast<std::size_t>(index)].name)
            : QString();
        actionName = tr("Change what students may change of “%1”").arg(name);
        break;
    }
    }
    {
        const QSignalBlocker blocker(m_locks);
        parent->setCheckState(0, summary(parent));
    }
    clearMessage();
    commit(lesson, actionName, LessonTyping::None);
}

void LessonEditor::onQuestionChanged(QTableWidgetItem* item)
{
    const std::optional<model::Lesson>& current = m_session.lesson();
    if (!current || item->row() >= static_cast<int>(current->questions.size()))
        return;
    model::Lesson lesson = *current;
    model::LessonQuestion& question = lesson.questions[static_cast<std::size_t>(item->row())];
    const QString text = item->text().trimmed();
    std::optional<QString> problem;
    switch (item->column()) {
    case PromptColumn:
        if (text.isEmpty())
            problem = tr("A question needs a prompt.");
        else
            question.prompt = text.toStdString();
        break;
    case UnitColumn:
        question.unit = text.toStdString();
        break;
    case AnswerColumn:
    case ToleranceColumn: {
        const std::optional<double> value = parseLessonNumber(locale(), text);
        const bool answer = item->column() == AnswerColumn;
        const QString label = answer ? tr("Answer") : tr("Tolerance");
        if (!value)
            problem = tr("%1: “%2” is not a number.").arg(label, text);
        else if (!answer && !(*value > 0))
            problem = tr("Tolerance must be greater than 0 (got %1).").arg(text);
        else if (answer)
            question.answer = *value;
        else
            question.tolerance = *value;
        break;
    }
    default:
        return;
    }
    if (problem) {
        refuse(*problem);
        refreshQuestions();
        return;
    }
    clearMessage();
    commit(lesson, tr("Edit question %1").arg(item->row() + 1), LessonTyping::None);
    // The cell shows the value as the lesson keeps it ("0.50" becomes "0.5").
    refreshQuestions();
}

void LessonEditor::addQuestion()
{
    const std::optional<model::Lesson>& current = m_session.lesson();
    if (!current)
        return;
    model::Lesson lesson = *current;
    lesson.questions.push_back(model::LessonQuestion{tr("New question").toStdString(), 0, {}, kNewQuestionTolerance});
    clearMessage();
    commit(lesson, tr("Add question"), LessonTyping::None);
    const int row = static_cast<int>(lesson.questions.size()) - 1;
    m_questions->setCurrentCell(row, PromptColumn);
    m_questions->setFocus();
}

void LessonEditor::removeQuestion()
{
    const std::optional<model::Lesson>& current = m_session.lesson();
    const int row = m_questions->currentRow() >= 0 ? m_questions->currentRow() : m_questions->rowCount() - 1;
    if (!current || row < 0 || row >= static_cast<int>(current->questions.size()))
        return;
    model::Lesson lesson = *current;
    lesson.questions.erase(lesson.questions.begin() + row);
    clearMessage();
    commit(lesson, tr("Remove question %1").arg(row + 1), LessonTyping::None);
}

// ---- Messages -----------------------------------------------------------------------------------

void LessonEditor::refuse(const QString& message)
{
    m_message->setText(message);
    m_message->show();
    QAccessibleEvent event(m_message, QAccessible::Alert);
    QAccessible::updateAccessibility(&event);
}

void LessonEditor::clearMessage()
{
    m_message->clear();
    m_message->hide();
}

QString LessonEditor::formatNumber(double value) const { return formatLessonNumber(locale(), value, kEditorDigits); }

} // namespace impetus::view
