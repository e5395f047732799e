#include "view/scene_commands.h"

#include "view/simulation_runner.h"

#include <algorithm>
#include <functional>

namespace impetus::view {

namespace {

/// One flag per item of a list of `count`, set for the indices in `removed` (index, item) pairs.
template <class Item>
std::vector<bool> removedFlags(std::size_t count, const std::vector<std::pair<std::size_t, Item>>& removed)
{
    std::vector<bool> flags(count, false);
    for (const auto& entry : removed)
        flags[entry.first] = true;
    return flags;
}

/// Applies `map` to every body reference of the springs, joints and contacts of `world`. `map`
/// keeps the order of indices, so the contacts stay sorted.
void remapBodyIds(model::World& world, const std::function<std::uint32_t(std::uint32_t)>& map)
{
    const auto remap = [&](model::BodyId& id) { id.index = map(id.index); };
    for (model::ContactRecord& contact : world.contacts) {
        remap(contact.bodyA);
        remap(contact.bodyB);
    }
    for (model::Spring& spring : world.springs) {
        remap(spring.bodyA);
        if (spring.bodyB)
            remap(*spring.bodyB);
    }
    for (model::Joint& joint : world.joints) {
        remap(joint.bodyA);
        if (joint.bodyB)
            remap(*joint.bodyB);
    }
}

template <class T>
bool refersTo(const T& connection, const std::vector<bool>& removedBody)
{
    return removedBody[connection.bodyA.index] || (connection.bodyB && removedBody[connection.bodyB->index]);
}

/// Erases the elements at `removed` (ascending) from `elements`.
template <class T, class Stored>
void eraseAt(std::vector<T>& elements, const std::vector<Stored>& removed)
{
    for (auto it = removed.rbegin(); it != removed.rend(); ++it)
        elements.erase(elements.begin() + static_cast<std::ptrdiff_t>(it->first));
}

/// Inserts the stored elements (ascending index) back where they were.
template <class T, class Stored>
void insertAt(std::vector<T>& elements, const std::vector<Stored>& removed)
{
    for (const auto& [index, value] : removed)
        elements.insert(elements.begin() + static_cast<std::ptrdiff_t>(index), value);
}

std::vector<BodyPose> posesOf(const model::World& world, const std::vector<int>& indices)
{
    std::vector<BodyPose> poses;
    poses.reserve(indices.size());
    for (const int i : indices) {
        const model::BodyState& state = world.bodies[static_cast<std::size_t>(i)].state;
        poses.push_back({state.position, state.angle});
    }
    return poses;
}

/// Sets each body's `colliding` flag from the touching contacts of `world`, as a step does.
void markColliding(model::World& world)
{
    for (model::Body& body : world.bodies)
        body.colliding = false;
    for (const model::ContactRecord& contact : world.contacts) {
        if (contact.touching) {
            world.body(contact.bodyA).colliding = true;
            world.body(contact.bodyB).colliding = true;
        }
    }
}

} // namespace

void forgetContactsOf(model::World& world, const std::function<bool(std::uint32_t)>& affected)
{
    std::erase_if(world.contacts, [&](const model::ContactRecord& contact) {
        return affected(contact.bodyA.index) || affected(contact.bodyB.index);
    });
    markColliding(world);
}

SetWorldSettingsCommand::SetWorldSettingsCommand(SceneDocument& document, const model::WorldSettings& settings,
                                                 const QString& name)
    : QUndoCommand(name)
    , m_document(document)
    , m_before(document.world().settings)
    , m_after(settings)
{
}

void SetWorldSettingsCommand::redo()
{
    m_document.applyEdit([&](model::World& world) { world.settings = m_after; });
}

void SetWorldSettingsCommand::undo()
{
    m_document.applyEdit([&](model::World& world) { world.settings = m_before; });
}

RemoveCommand::RemoveCommand(SceneDocument& document, const Selection& selection, const QString& name)
    : QUndoCommand(name)
    , m_document(document)
{
    const model::World& world = document.world();
    m_lessonBefore = world.lesson;
    std::vector<bool> removedBody(world.bodies.size(), false);
    for (const int i : selection.bodies)
        removedBody[static_cast<std::size_t>(i)] = true;
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        if (removedBody[i])
            m_bodies.emplace_back(i, world.bodies[i]);
    }
    for (std::size_t i = 0; i < world.springs.size(); ++i) {
        const bool selected = std::ranges::find(selection.springs, static_cast<int>(i)) != selection.springs.end();
        if (selected || refersTo(world.springs[i], removedBody))
            m_springs.emplace_back(i, world.springs[i]);
    }
    for (std::size_t i = 0; i < world.joints.size(); ++i) {
        const bool selected = std::ranges::find(selection.joints, static_cast<int>(i)) != selection.joints.end();
        if (selected || refersTo(world.joints[i], removedBody))
            m_joints.emplace_back(i, world.joints[i]);
    }
}

void RemoveCommand::redo()
{
    m_document.applyEdit([&](model::World& world) {
        const auto removed = [&](std::uint32_t index) {
            return std::ranges::any_of(m_bodies, [&](const auto& body) { return body.first == index; });
        };
        forgetContactsOf(world, removed);
        if (world.lesson) {
            world.lesson->removeBodies(removedFlags(world.bodies.size(), m_bodies));
            world.lesson->removeSprings(removedFlags(world.springs.size(), m_springs));
            world.lesson->removeJoints(removedFlags(world.joints.size(), m_joints));
        }
        eraseAt(world.springs, m_springs);
        eraseAt(world.joints, m_joints);
        eraseAt(world.bodies, m_bodies);
        // A body keeps its place in the order; it moves down by the number of removed bodies
        // before it. No spring, joint or contact that stays refers to a removed body.
        remapBodyIds(world, [&](std::uint32_t index) {
            const auto below = std::ranges::count_if(m_bodies, [&](const auto& body) { return body.first < index; });
            return index - static_cast<std::uint32_t>(below);
        });
    });
}

void RemoveCommand::undo()
{
    m_document.applyEdit([&](model::World& world) {
        // The inverse of redo's renumbering: the n-th body that stayed goes back to the n-th index
        // that was not removed.
        std::vector<std::uint32_t> kept;
        const std::size_t total = world.bodies.size() + m_bodies.size();
        std::size_t next = 0;
        for (std::size_t i = 0; i < total; ++i) {
            if (next < m_bodies.size() && m_bodies[next].first == i)
                ++next;
            else
                kept.push_back(static_cast<std::uint32_t>(i));
        }
        remapBodyIds(world, [&](std::uint32_t index) { return kept[index]; });
        insertAt(world.bodies, m_bodies);
        insertAt(world.springs, m_springs);
        insertAt(world.joints, m_joints);
        world.lesson = m_lessonBefore;
        // The bodies that come back have no contacts (they may be elsewhere by the next step).
        markColliding(world);
    });
}

SetPosesCommand::SetPosesCommand(SceneDocument& document, std::vector<int> indices, std::vector<BodyPose> poses,
                                 const QString& name, int gesture)
    : QUndoCommand(name)
    , m_document(document)
    , m_indices(std::move(indices))
    , m_before(posesOf(document.world(), m_indices))
    , m_after(std::move(poses))
    , m_gesture(gesture)
{
    // A command that changes nothing (a drag given up, a snap to where the body is) is dropped
    // by the stack instead of leaving an empty "Move" to undo.
    setObsolete(m_after == m_before);
}

void SetPosesCommand::redo() { put(m_after); }

void SetPosesCommand::undo() { put(m_before); }

bool SetPosesCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const SetPosesCommand*>(other);
    if (next->m_gesture != m_gesture || next->m_indices != m_indices)
        return false;
    m_after = next->m_after;
    // A drag that came back to its start, or was given up: the stack drops the whole command.
    setObsolete(m_after == m_before);
    return true;
}

void SetPosesCommand::put(const std::vector<BodyPose>& poses)
{
    m_document.applyEdit([&](model::World& world) {
        forgetContactsOf(world, [&](std::uint32_t index) {
            const auto it = std::ranges::find(m_indices, static_cast<int>(index));
            if (it == m_indices.end())
                return false;
            const model::BodyState& state = world.bodies[index].state;
            return poses[static_cast<std::size_t>(it - m_indices.begin())] != BodyPose{state.position, state.angle};
        });
        for (std::size_t k = 0; k < m_indices.size(); ++k) {
            model::BodyState& state = world.bodies[static_cast<std::size_t>(m_indices[k])].state;
            state.position = poses[k].position;
            state.angle = poses[k].angle;
        }
    });
}

WorldSnapshotCommand::WorldSnapshotCommand(SceneDocument& document, model::World before,
                                           std::optional<model::World> after, FirstRedo firstRedo,
                                           const QString& name)
    : QUndoCommand(name)
    , m_document(document)
    , m_before(std::move(before))
    , m_after(std::move(after))
    , m_firstRedo(firstRedo)
{
}

void WorldSnapshotCommand::redo()
{
    if (m_done || m_firstRedo == FirstRedo::PutAfter) {
        put(*m_after);
    } else if (m_firstRedo == FirstRedo::Step) {
        m_document.runner().stepOnce();
    }
    m_done = true;
}

void WorldSnapshotCommand::undo()
{
    // Stop first: undoing a run while it goes on would otherwise be overwritten by its next step.
    m_document.runner().pause();
    m_after = m_document.world();
    put(m_before);
}

int WorldSnapshotCommand::id() const
{
    return m_firstRedo == FirstRedo::Step ? static_cast<int>(CommandId::Step) : -1;
}

bool WorldSnapshotCommand::mergeWith(const QUndoCommand*)
{
    // Only steps share an id; this command keeps its own "before", and the merged step has
    // already changed the world, which an undo will take as "after".
    return true;
}

void WorldSnapshotCommand::put(const model::World& world)
{
    m_document.runner().pause();
    m_document.applyEdit([&](model::World& current) { current = world; });
}

} // namespace impetus::view
