#pragma once
/// \file lesson_commands.h
/// The undo command of every lesson edit (Lesson › Edit): the scene's lesson is part of its world,
/// so each change is one command on the scene document's QUndoStack.

#include "model/lesson.h"

#include <QUndoCommand>

#include <optional>

namespace impetus::view {

class SceneDocument;

/// Which typing a SetLessonCommand belongs to: commands of the same typing merge, so that typing a
/// title or instructions undoes as one step and not letter by letter.
enum class LessonTyping {
    None, ///< a single edit (a lock, a question): never merges
    Title, ///< typing in the title field
    Instructions, ///< typing in the instructions field
};

/// Replaces the world's lesson (World::lesson) with another one, or removes it (nullopt); undo
/// puts back the one before. Consecutive commands of the same LessonTyping other than None merge.
class SetLessonCommand : public QUndoCommand {
public:
    /// Replaces `document`'s lesson with `lesson`.
    SetLessonCommand(SceneDocument& document, std::optional<model::Lesson> lesson, const QString& name,
                     LessonTyping typing = LessonTyping::None);
    void redo() override;
    void undo() override;
    /// kLessonTypingCommandId for typing, −1 (no merging) otherwise.
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    void put(const std::optional<model::Lesson>& lesson);

    SceneDocument& m_document;
    std::optional<model::Lesson> m_before;
    std::optional<model::Lesson> m_after;
    LessonTyping m_typing;
};

/// QUndoCommand::id() of a SetLessonCommand that merges: apart from scene_commands.h's CommandId.
inline constexpr int kLessonTypingCommandId = 100;

} // namespace impetus::view
