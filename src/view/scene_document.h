#pragma once
/// \file scene_document.h
/// The scene being edited: its world (through the SimulationRunner), its file, its selection and
/// the one undo stack every edit goes through.

#include "model/world.h"
#include "view/selection.h"

#include <QObject>
#include <QString>

#include <functional>
#include <optional>
#include <vector>

class QUndoStack;

namespace impetus::view {

class SimulationRunner;

/// Where a body is and how it is turned: the part of its state a drag, a rotation or a nudge
/// changes.
struct BodyPose {
    Vec2 position = Vec2::Zero(); ///< centre of mass, m
    Scalar angle = 0; ///< rad, counter-clockwise
    bool operator==(const BodyPose&) const = default;
};

/// The editable scene. Owns the SimulationRunner (and so the world), the path of the file it came
/// from, the selection, and one QUndoStack. Every change a user makes — drawing, moving, rotating,
/// deleting, an attribute, the world settings, a run — is a QUndoCommand pushed here, so each one
/// can be undone. Edits apply to the world as it is, also while the simulation runs.
///
/// The document is modified while its undo stack is not at its clean index: saving or loading
/// marks it clean, any later command (or undoing past the save) marks it modified.
class SceneDocument : public QObject {
    Q_OBJECT

public:
    /// An empty, unnamed, unmodified scene, paused.
    explicit SceneDocument(QObject* parent = nullptr);

    /// The world in its current state.
    const model::World& world() const;

    /// The runner that owns and steps the world.
    SimulationRunner& runner() { return *m_runner; }
    const SimulationRunner& runner() const { return *m_runner; }

    /// The one undo stack of the scene.
    QUndoStack* undoStack() const { return m_undoStack; }

    /// The path of the scene's file, empty for a new scene or an example (those have no file to
    /// save back to).
    QString filePath() const { return m_filePath; }

    /// The name shown in the title: the file's name without folder and extension, or the name
    /// given to setScene().
    QString displayName() const { return m_displayName; }

    /// True when there are changes since the scene was loaded or saved (runs included: the
    /// bodies are elsewhere than in the file).
    bool isModified() const;

    /// True when, since the scene was loaded or saved, there are edits other than running,
    /// stepping and resetting: work that would be lost. A run alone changes nothing the file does
    /// not already hold, so the window does not ask about it before discarding.
    bool hasUnsavedEdits() const;

    /// What is selected. Indices are always valid for world().
    Selection selection() const { return m_selection; }

    /// Selects `selection`, dropping indices that are out of range and sorting the rest. Emits
    /// selectionChanged() when it differs from the current selection. Not an undoable edit.
    void setSelection(const Selection& selection);

    /// Replaces the scene with `world`, paused. `filePath` is the file to save back to (empty for a
    /// new scene or an example); `displayName` is what the title shows. Clears the undo stack and
    /// the selection; the document is unmodified. Emits worldChanged() and sceneReplaced().
    void setScene(model::World world, const QString& filePath, const QString& displayName);

    /// The world as a file should hold it: every pin's world anchor moved to where its hinge is
    /// now (bodies may have moved or run since the pin was made).
    model::World worldToSave() const;

    /// Saves the world to `path` atomically (model::saveSceneFile). On success the document takes
    /// that path and name and is unmodified; on failure it returns the message and nothing changes.
    std::optional<QString> saveAs(const QString& path);

    /// Replaces body `index` with `body` (its derived fields recomputed with updateDerived()), as
    /// one command named `actionName`. Ignored for an index out of range.
    void setBody(int index, const model::Body& body, const QString& actionName);
    /// Replaces spring `index` with `spring`, as one command. Ignored for an index out of range.
    void setSpring(int index, const model::Spring& spring, const QString& actionName);
    /// Replaces joint `index` with `joint`, as one command. Ignored for an index out of range.
    void setJoint(int index, const model::Joint& joint, const QString& actionName);
    /// Replaces the world settings (gravity, integrator, time step, drag), as one command.
    void setWorldSettings(const model::WorldSettings& settings, const QString& actionName);

    /// Appends `body` (derived fields recomputed) and selects it. Returns its index.
    int addBody(model::Body body, const QString& actionName);
    /// Appends `spring` and selects it. Returns its index. Its body ids must be valid.
    int addSpring(const model::Spring& spring, const QString& actionName);
    /// Appends `joint` and selects it. Returns its index. Its body ids must be valid.
    int addJoint(const model::Joint& joint, const QString& actionName);

    /// Removes the bodies, springs and joints of `selection`, and with each body every spring and
    /// joint attached to it; the others are re-indexed. One command; nothing for an empty
    /// selection. Clears the selection.
    void remove(const Selection& selection, const QString& actionName);

    /// Sets the poses of bodies `indices` to `poses` (same length), as one command. Consecutive
    /// calls with the same `gesture` (from newGesture()) and the same bodies merge into one
    /// command, so a whole drag undoes at once.
    void setPoses(const std::vector<int>& indices, const std::vector<BodyPose>& poses,
                  const QString& actionName, int gesture);

    /// A number no earlier gesture had: a tool takes one when a drag begins.
    int newGesture() { return ++m_lastGesture; }

    /// Pauses and takes one fixed step (SimulationRunner::stepOnce(): a slow one is shown when it
    /// ends), as a command ("Step") whose undo puts back the world before it and drops a step
    /// still being computed. Consecutive steps merge into one command.
    void stepOnce();

    /// Puts back the world as it was at the last Play, paused, as one command ("Reset"). Does
    /// nothing when Play was not pressed since the scene was loaded.
    void resetToLastPlay();

    /// "box 1", "box 2", …: `base` followed by the smallest number ≥ 1 that no body's name has.
    QString uniqueBodyName(const QString& base) const;

    /// Applies `edit` to the world through the runner. For the undo commands of this document
    /// only: anything else goes through the methods above, so that it can be undone.
    void applyEdit(const std::function<void(model::World&)>& edit);

signals:
    /// The world was edited, replaced, reset or restored by undo: items may have come or gone.
    void worldChanged();
    /// The simulation advanced by one or more steps; the bodies are the same ones.
    void stepped();
    /// A different scene was put in (new, open, example): views frame it anew.
    void sceneReplaced();
    /// The selection changed.
    void selectionChanged();
    /// The document became modified (true) or unmodified (false).
    void modifiedChanged(bool modified);
    /// The file path or display name changed.
    void fileChanged();

private:
    void onRunningChanged(bool running);
    void dropInvalidSelection();

    SimulationRunner* m_runner;
    QUndoStack* m_undoStack;
    Selection m_selection;
    QString m_filePath;
    QString m_displayName;
    int m_lastGesture = 0;
};

} // namespace impetus::view
