#pragma once
/// \file scene_commands.h
/// The undo commands of a SceneDocument. Each changes the world through
/// SceneDocument::applyEdit() and can put it back. Only SceneDocument creates them.

#include "model/world.h"
#include "view/scene_document.h"
#include "view/selection.h"

#include <QUndoCommand>

#include <cstdint>
#include <functional>

#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace impetus::view {

/// Forgets the contacts of the bodies for which `affected(index)` is true (removed, moved or
/// reshaped: what the records say of them is no longer so, and their warm-start impulses belong to
/// old pieces), and sets every body's `colliding` flag from the contacts that stay, so that a body
/// whose only partner went away is drawn in its own colour at once. The contacts of other bodies
/// stay, so a stack at rest elsewhere neither flickers nor counts its contacts again.
void forgetContactsOf(model::World& world, const std::function<bool(std::uint32_t)>& affected);

/// Ids for QUndoCommand::id(): commands with the same id may merge.
enum class CommandId { SetPoses = 1, Step = 2 };

/// The vector of `world` (a World or a const World) that holds elements of type T: Body, Spring
/// or Joint.
template <class T, class W>
auto& elementsOf(W& world)
{
    if constexpr (std::is_same_v<T, model::Body>)
        return world.bodies;
    else if constexpr (std::is_same_v<T, model::Spring>)
        return world.springs;
    else
        return world.joints;
}

/// Replaces one body, spring or joint; undo puts the previous value back.
///
/// A body edit whose new value has the same state as the body had (an attribute edit: friction,
/// colour, size, … but not position, angle or velocities) changes the attributes alone, on redo and
/// undo alike: the body keeps the state it has by then, and its collision flag and count, so that
/// undoing a change made during a run does not send the body back to where it was at the edit.
/// A body edit that changes the shape or the pose forgets that body's contacts (forgetContactsOf).
template <class T>
class SetElementCommand : public QUndoCommand {
public:
    /// Replaces element `index` (valid) of `document`'s world with `value`.
    SetElementCommand(SceneDocument& document, int index, T value, const QString& name)
        : QUndoCommand(name)
        , m_document(document)
        , m_index(static_cast<std::size_t>(index))
        , m_before(elementsOf<T>(document.world())[m_index])
        , m_after(std::move(value))
    {
        if constexpr (std::is_same_v<T, model::Body>)
            m_attributesOnly = m_before.state == m_after.state;
    }
    /// Puts in the new value.
    void redo() override { put(m_after); }
    /// Puts back the value from before.
    void undo() override { put(m_before); }

private:
    void put(const T& value)
    {
        m_document.applyEdit([&](model::World& world) {
            T& element = elementsOf<T>(world)[m_index];
            if constexpr (std::is_same_v<T, model::Body>) {
                const bool moved = !m_attributesOnly
                    && (value.state.position != element.state.position || value.state.angle != element.state.angle);
                if (moved || value.shape != element.shape) {
                    const auto index = static_cast<std::uint32_t>(m_index);
                    forgetContactsOf(world, [index](std::uint32_t i) { return i == index; });
                }
                if (m_attributesOnly) {
                    model::Body body = value;
                    body.state = element.state;
                    body.colliding = element.colliding;
                    body.collisionCount = element.collisionCount;
                    element = std::move(body);
                    return;
                }
            }
            element = value;
        });
    }

    SceneDocument& m_document;
    std::size_t m_index;
    T m_before;
    T m_after;
    bool m_attributesOnly = false; ///< a body edit that leaves the state alone
};

/// Appends a body, spring or joint; undo removes it again.
template <class T>
class AddElementCommand : public QUndoCommand {
public:
    /// Appends `value` to `document`'s world.
    AddElementCommand(SceneDocument& document, T value, const QString& name)
        : QUndoCommand(name)
        , m_document(document)
        , m_value(std::move(value))
    {
    }
    /// Appends the element. (A new body is at the end, so no contact record changes meaning.)
    void redo() override
    {
        m_document.applyEdit([&](model::World& world) { elementsOf<T>(world).push_back(m_value); });
    }
    /// Removes the last element, which is the one appended, with the contacts of a body.
    void undo() override
    {
        m_document.applyEdit([&](model::World& world) {
            auto& elements = elementsOf<T>(world);
            if constexpr (std::is_same_v<T, model::Body>) {
                const auto last = static_cast<std::uint32_t>(elements.size() - 1);
                forgetContactsOf(world, [last](std::uint32_t i) { return i == last; });
            }
            elements.pop_back();
        });
    }

private:
    SceneDocument& m_document;
    T m_value;
};

/// Replaces the world settings; undo puts back the previous ones.
class SetWorldSettingsCommand : public QUndoCommand {
public:
    /// Replaces `document`'s world settings with `settings`.
    SetWorldSettingsCommand(SceneDocument& document, const model::WorldSettings& settings, const QString& name);
    void redo() override;
    void undo() override;

private:
    SceneDocument& m_document;
    model::WorldSettings m_before;
    model::WorldSettings m_after;
};

/// Removes bodies, springs and joints, with every spring and joint attached to a removed body,
/// re-indexing the references of those that stay. Undo puts everything back at its old index.
class RemoveCommand : public QUndoCommand {
public:
    /// Removes `selection` (valid indices) and its dependants from `document`'s world.
    RemoveCommand(SceneDocument& document, const Selection& selection, const QString& name);
    void redo() override;
    void undo() override;

    /// True when there is nothing to remove.
    bool isEmpty() const { return m_bodies.empty() && m_springs.empty() && m_joints.empty(); }

private:
    SceneDocument& m_document;
    std::vector<std::pair<std::size_t, model::Body>> m_bodies; ///< ascending index
    std::vector<std::pair<std::size_t, model::Spring>> m_springs; ///< ascending index
    std::vector<std::pair<std::size_t, model::Joint>> m_joints; ///< ascending index
    std::optional<model::Lesson> m_lessonBefore; ///< the lesson, whose entries of removed bodies go
};

/// Sets the position and angle of some bodies. Merges with the next SetPosesCommand of the same
/// gesture and bodies, so a drag is one undo step; a command that ends up changing nothing is
/// obsolete, and the stack drops it.
class SetPosesCommand : public QUndoCommand {
public:
    /// Sets bodies `indices` (valid) of `document` to `poses`, as part of `gesture`.
    SetPosesCommand(SceneDocument& document, std::vector<int> indices, std::vector<BodyPose> poses,
                    const QString& name, int gesture);
    void redo() override;
    void undo() override;
    int id() const override { return static_cast<int>(CommandId::SetPoses); }
    bool mergeWith(const QUndoCommand* other) override;

private:
    void put(const std::vector<BodyPose>& poses);

    SceneDocument& m_document;
    std::vector<int> m_indices;
    std::vector<BodyPose> m_before;
    std::vector<BodyPose> m_after;
    int m_gesture;
};

/// A change of the whole world by the simulation: a run, steps, a reset. Undo puts back the world
/// from before; redo puts back the world as it was when undone.
class WorldSnapshotCommand : public QUndoCommand {
public:
    /// How the command's first redo() behaves.
    enum class FirstRedo {
        AlreadyDone, ///< the change is happening already (a run that started): do nothing
        Step, ///< take one fixed step
        PutAfter, ///< put in `after`
    };
    /// A command whose undo restores `before`. With FirstRedo::PutAfter, `after` is put in by the
    /// first redo; otherwise it is taken from the world when the command is undone.
    WorldSnapshotCommand(SceneDocument& document, model::World before, std::optional<model::World> after,
                         FirstRedo firstRedo, const QString& name);
    void redo() override;
    void undo() override;
    /// CommandId::Step for steps, so that consecutive steps merge; −1 (no merging) otherwise.
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    void put(const model::World& world);

    SceneDocument& m_document;
    model::World m_before;
    std::optional<model::World> m_after;
    FirstRedo m_firstRedo;
    bool m_done = false;
};

} // namespace impetus::view
