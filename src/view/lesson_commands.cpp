#include "view/lesson_commands.h"

#include "view/scene_document.h"

#include <utility>

namespace impetus::view {

SetLessonCommand::SetLessonCommand(SceneDocument& document, std::optional<model::Lesson> lesson,
                                   const QString& name, LessonTyping typing)
    : QUndoCommand(name)
    , m_document(document)
    , m_before(document.world().lesson)
    , m_after(std::move(lesson))
    , m_typing(typing)
{
}

void SetLessonCommand::redo() { put(m_after); }

void SetLessonCommand::undo() { put(m_before); }

int SetLessonCommand::id() const { return m_typing == LessonTyping::None ? -1 : kLessonTypingCommandId; }

bool SetLessonCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = dynamic_cast<const SetLessonCommand*>(other);
    if (!next || next->m_typing != m_typing)
        return false;
    m_after = next->m_after;
    // Typing back to where it started leaves nothing to undo.
    setObsolete(m_after == m_before);
    return true;
}

void SetLessonCommand::put(const std::optional<model::Lesson>& lesson)
{
    m_document.applyEdit([&lesson](model::World& world) { world.lesson = lesson; });
}

} // namespace impetus::view
