#pragma once
/// \file lesson_session.h
/// The scene's lesson as the window enforces it: its locks, whether Lesson › Edit has lifted them,
/// and why an edit is refused.

#include "model/lesson.h"
#include "model/world.h"
#include "view/selection.h"

#include <QObject>
#include <QString>

#include <optional>
#include <vector>

namespace impetus::view {

class SceneDocument;

/// The locks of the lesson of a SceneDocument's world (model::Lesson). While the scene has a
/// lesson and Lesson › Edit is off, the locks are in force: students may change only what the
/// lesson lists as editable. The attribute pane, the canvas tools and Edit › Delete ask this object
/// before they edit, and say why when it refuses ("Locked by the lesson: …"). With Lesson › Edit
/// on (setEditing(true)), a teacher may change anything, the lesson included. Opening another
/// scene turns Lesson › Edit off again, so a student who opens a lesson file gets its locks. The
/// locks guard against accidents, not against a determined student: anyone can turn Lesson › Edit
/// on, and the scene file is plain JSON.
class LessonSession : public QObject {
    Q_OBJECT

public:
    /// The lesson of `document`'s world; `document` must outlive the session.
    explicit LessonSession(SceneDocument& document, QObject* parent = nullptr);

    /// The document whose lesson this is.
    SceneDocument& document() const { return m_document; }

    /// The lesson of the scene shown, if it has one.
    const std::optional<model::Lesson>& lesson() const;

    /// True while Lesson › Edit is on: the locks are lifted and the lesson can be authored.
    bool isEditing() const { return m_editing; }
    /// Turns Lesson › Edit on or off; emits editingChanged() and locksChanged() when it changes.
    void setEditing(bool on);

    /// True when the scene has a lesson and Lesson › Edit is off.
    bool locksInForce() const;

    /// Why students may not change `attribute` of body `body` now, or nullopt when they may.
    std::optional<QString> bodyLock(int body, model::BodyAttribute attribute) const;
    /// Why students may not change the world setting `attribute` now, or nullopt when they may.
    std::optional<QString> worldLock(model::WorldAttribute attribute) const;
    /// Why the edit of body `body` from `before` to `after` is refused, or nullopt when allowed.
    std::optional<QString> refusal(int body, const model::Body& before, const model::Body& after) const;
    /// Why the edit of the world settings from `before` to `after` is refused, or nullopt.
    std::optional<QString> refusal(const model::WorldSettings& before, const model::WorldSettings& after) const;
    /// Why students may not change `attribute` of joint `joint` now, or nullopt when they may.
    std::optional<QString> jointLock(int joint, model::JointAttribute attribute) const;
    /// Why the edit of joint `joint` from `before` to `after` is refused, or nullopt when allowed.
    std::optional<QString> refusal(int joint, const model::Joint& before, const model::Joint& after) const;
    /// Why students may not change `attribute` of spring `spring` now, or nullopt when they may.
    std::optional<QString> springLock(int spring, model::SpringAttribute attribute) const;
    /// Why the edit of spring `spring` from `before` to `after` is refused, or nullopt when allowed.
    std::optional<QString> refusal(int spring, const model::Spring& before, const model::Spring& after) const;
    /// Why `bodies` cannot be moved (`moves`) or turned (`turns`) on the canvas now, or nullopt.
    /// Turning several bodies turns them about their common centre, so it moves them as well.
    std::optional<QString> poseLock(const std::vector<int>& bodies, bool moves, bool turns) const;
    /// Why `selection` cannot be deleted now (a lesson's bodies, springs and joints stay), or nullopt.
    std::optional<QString> removalLock(const Selection& selection) const;
    /// Why new bodies, springs and joints cannot be drawn now, or nullopt.
    std::optional<QString> drawingLock() const;

    /// What the attribute pane says about body `body`: "Locked by the lesson. You may change: …",
    /// or nullopt when the locks are not in force.
    std::optional<QString> bodyNote(int body) const;
    /// What the attribute pane says about the world settings, or nullopt.
    std::optional<QString> worldNote() const;
    /// What the attribute pane says about spring `spring`, or nullopt.
    std::optional<QString> springNote(int spring) const;
    /// What the attribute pane says about joint `joint`, or nullopt.
    std::optional<QString> jointNote(int joint) const;

signals:
    /// Lesson › Edit was turned on or off.
    void editingChanged(bool editing);
    /// What is locked may have changed: Lesson › Edit, or a lesson that came, went or changed.
    void locksChanged();

private:
    void onWorldChanged();
    QString bodyName(int body) const;
    /// True when joint `joint` of the document's world is a pin (its anchors are its hinge).
    bool isPin(int joint) const;

    SceneDocument& m_document;
    bool m_editing = false;
    std::optional<model::Lesson> m_lastLesson; ///< the lesson when locksChanged() was last emitted
};

/// `session`'s poseLock(), or nullopt when there is no session (a canvas without lessons).
std::optional<QString> poseLockOf(const LessonSession* session, const std::vector<int>& bodies, bool moves, bool turns);

} // namespace impetus::view
