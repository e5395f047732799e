#include "view/scene_document.h"

#include "model/scene_io.h"
#include "view/scene_commands.h"
#include "view/scene_loading.h"
#include "view/simulation_runner.h"
#include "view/view_constants.h"

#include <QFile>
#include <QUndoStack>

#include <algorithm>
#include <filesystem>
#include <set>
#include <utility>

namespace impetus::view {

namespace {

/// `indices` sorted, without repeats and without those ≥ `size`.
std::vector<int> cleaned(std::vector<int> indices, std::size_t size)
{
    std::erase_if(indices, [&](int i) { return i < 0 || static_cast<std::size_t>(i) >= size; });
    std::ranges::sort(indices);
    indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
    return indices;
}

bool validConnection(const model::World& world, model::BodyId a, const std::optional<model::BodyId>& b)
{
    return a.index < world.bodies.size() && (!b || b->index < world.bodies.size());
}

bool inRange(int index, std::size_t size) { return index >= 0 && static_cast<std::size_t>(index) < size; }

} // namespace

SceneDocument::SceneDocument(QObject* parent)
    : QObject(parent)
    , m_runner(new SimulationRunner(this))
    , m_undoStack(new QUndoStack(this))
{
    m_undoStack->setUndoLimit(constants::kUndoLimit);
    connect(m_runner, &SimulationRunner::worldChanged, this, [this] {
        dropInvalidSelection();
        emit worldChanged();
    });
    connect(m_runner, &SimulationRunner::stepped, this, &SceneDocument::stepped);
    connect(m_runner, &SimulationRunner::sceneReplaced, this, &SceneDocument::sceneReplaced);
    connect(m_runner, &SimulationRunner::runningChanged, this, &SceneDocument::onRunningChanged);
    connect(m_undoStack, &QUndoStack::cleanChanged, this, [this](bool clean) { emit modifiedChanged(!clean); });
}

const model::World& SceneDocument::world() const { return m_runner->world(); }

bool SceneDocument::isModified() const { return !m_undoStack->isClean(); }

bool SceneDocument::hasUnsavedEdits() const
{
    if (m_undoStack->isClean())
        return false;
    const int clean = m_undoStack->cleanIndex();
    if (clean < 0)
        return true;
    // The commands between the saved state and now, whichever way the user went.
    const int from = std::min(clean, m_undoStack->index());
    const int to = std::max(clean, m_undoStack->index());
    for (int i = from; i < to; ++i) {
        if (!dynamic_cast<const WorldSnapshotCommand*>(m_undoStack->command(i)))
            return true;
    }
    return false;
}

void SceneDocument::setSelection(const Selection& selection)
{
    const model::World& w = world();
    Selection next{cleaned(selection.bodies, w.bodies.size()), cleaned(selection.springs, w.springs.size()),
                   cleaned(selection.joints, w.joints.size())};
    if (next == m_selection)
        return;
    m_selection = std::move(next);
    emit selectionChanged();
}

void SceneDocument::dropInvalidSelection() { setSelection(m_selection); }

void SceneDocument::setScene(model::World world, const QString& filePath, const QString& displayName)
{
    m_undoStack->clear();
    m_selection = {};
    m_filePath = filePath;
    m_displayName = displayName;
    m_runner->setWorld(std::move(world));
    m_undoStack->setClean();
    emit selectionChanged();
    emit fileChanged();
    emit modifiedChanged(false);
}

model::World SceneDocument::worldToSave() const
{
    // A pin is saved by its world point, from which loading derives the body-frame anchors. Bodies
    // may have been moved or run since the pin was made, so the point written is where the hinge
    // is now: on body A, or the fixed world point of a pin to the world.
    model::World toSave = world();
    for (model::Joint& joint : toSave.joints) {
        if (joint.type == model::JointType::Pin)
            joint.worldAnchor = joint.bodyB ? toSave.body(joint.bodyA).worldPoint(joint.anchorA) : joint.anchorB;
    }
    return toSave;
}

std::optional<QString> SceneDocument::saveAs(const QString& path)
{
    const QByteArray native = QFile::encodeName(path);
    if (const std::optional<std::string> error =
            model::saveSceneFile(std::filesystem::path(native.toStdString()), worldToSave()))
        return QString::fromStdString(*error);
    m_filePath = path;
    m_displayName = sceneDisplayName(path);
    m_undoStack->setClean();
    emit fileChanged();
    return std::nullopt;
}

void SceneDocument::setBody(int index, const model::Body& body, const QString& actionName)
{
    if (!inRange(index, world().bodies.size()))
        return;
    model::Body updated = body;
    updated.updateDerived();
    m_undoStack->push(new SetElementCommand<model::Body>(*this, index, std::move(updated), actionName));
}

void SceneDocument::setSpring(int index, const model::Spring& spring, const QString& actionName)
{
    if (!inRange(index, world().springs.size()) || !validConnection(world(), spring.bodyA, spring.bodyB))
        return;
    m_undoStack->push(new SetElementCommand<model::Spring>(*this, index, spring, actionName));
}

void SceneDocument::setJoint(int index, const model::Joint& joint, const QString& actionName)
{
    if (!inRange(index, world().joints.size()) || !validConnection(world(), joint.bodyA, joint.bodyB))
        return;
    m_undoStack->push(new SetElementCommand<model::Joint>(*this, index, joint, actionName));
}

void SceneDocument::setWorldSettings(const model::WorldSettings& settings, const QString& actionName)
{
    m_undoStack->push(new SetWorldSettingsCommand(*this, settings, actionName));
}

int SceneDocument::addBody(model::Body body, const QString& actionName)
{
    body.updateDerived();
    m_undoStack->push(new AddElementCommand<model::Body>(*this, std::move(body), actionName));
    const int index = static_cast<int>(world().bodies.size()) - 1;
    setSelection(Selection{{index}, {}, {}});
    return index;
}

int SceneDocument::addSpring(const model::Spring& spring, const QString& actionName)
{
    if (!validConnection(world(), spring.bodyA, spring.bodyB))
        return -1;
    m_undoStack->push(new AddElementCommand<model::Spring>(*this, spring, actionName));
    const int index = static_cast<int>(world().springs.size()) - 1;
    setSelection(Selection{{}, {index}, {}});
    return index;
}

int SceneDocument::addJoint(const model::Joint& joint, const QString& actionName)
{
    if (!validConnection(world(), joint.bodyA, joint.bodyB))
        return -1;
    m_undoStack->push(new AddElementCommand<model::Joint>(*this, joint, actionName));
    const int index = static_cast<int>(world().joints.size()) - 1;
    setSelection(Selection{{}, {}, {index}});
    return index;
}

void SceneDocument::remove(const Selection& selection, const QString& actionName)
{
    const model::World& w = world();
    const Selection valid{cleaned(selection.bodies, w.bodies.size()), cleaned(selection.springs, w.springs.size()),
                          cleaned(selection.joints, w.joints.size())};
    auto command = std::make_unique<RemoveCommand>(*this, valid, actionName);
    if (command->isEmpty())
        return;
    setSelection({});
    m_undoStack->push(command.release());
}

void SceneDocument::setPoses(const std::vector<int>& indices, const std::vector<BodyPose>& poses,
                             const QString& actionName, int gesture)
{
    if (indices.empty() || indices.size() != poses.size())
        return;
    for (const int i : indices) {
        if (!inRange(i, world().bodies.size()))
            return;
    }
    m_undoStack->push(new SetPosesCommand(*this, indices, poses, actionName, gesture));
}

void SceneDocument::stepOnce()
{
    m_undoStack->push(new WorldSnapshotCommand(*this, world(), std::nullopt, WorldSnapshotCommand::FirstRedo::Step,
                                               tr("Step")));
}

void SceneDocument::resetToLastPlay()
{
    const std::optional<model::World>& start = m_runner->worldAtLastPlay();
    if (!start)
        return;
    m_runner->pause();
    m_undoStack->push(
        new WorldSnapshotCommand(*this, world(), *start, WorldSnapshotCommand::FirstRedo::PutAfter, tr("Reset")));
}

QString SceneDocument::uniqueBodyName(const QString& base) const
{
    std::set<std::string> taken;
    for (const model::Body& body : world().bodies)
        taken.insert(body.name);
    for (int n = 1;; ++n) {
        const QString name = QStringLiteral("%1 %2").arg(base).arg(n);
        if (!taken.contains(name.toStdString()))
            return name;
    }
}

void SceneDocument::applyEdit(const std::function<void(model::World&)>& edit) { m_runner->editWorld(edit); }

void SceneDocument::onRunningChanged(bool running)
{
    // The run is the command, pushed as it starts: its undo goes back to the world at Play.
    if (running && m_runner->worldAtLastPlay()) {
        m_undoStack->push(new WorldSnapshotCommand(*this, *m_runner->worldAtLastPlay(), std::nullopt,
                                                   WorldSnapshotCommand::FirstRedo::AlreadyDone, tr("Run")));
    }
}

} // namespace impetus::view
