#pragma once
/// \file timeline.h
/// The run's past: keyframes of the world and deterministic replay, so that the window can go
/// back to any step of a run and play on from there.

#include "controller/simulation.h"
#include "model/world.h"

#include <QObject>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace impetus::view {

class SimulationRunner;

/// The approximate memory a copy of `world` takes, bytes: the World itself and what its vectors
/// hold (bodies with their outlines and pieces, springs, joints, contact records, soft grids).
std::size_t worldBytes(const model::World& world);

/// Keeps the states of the run shown by a SimulationRunner, from the scene's start (or the last
/// edit before it) to the newest step computed, and goes back to any of them.
///
/// It keeps a keyframe (a copy of the World, which copies with `=`) every keyframeInterval()
/// steps, and rebuilds the steps in between by replaying them from the keyframe before with a
/// controller::Simulation of its own: the engine gives the same bits for the same steps, so a
/// replayed state is the state the run had. Its memory is bounded: when the keyframes would take
/// more than memoryBudget() bytes, every other periodic keyframe is dropped and the interval
/// doubles (replays get longer instead).
///
/// What changes the run:
///  - an edit (the runner's worldChanged() for a world the timeline did not put in) at step s is
///    a new start: the states after s are forgotten (futureDiscarded(s)) and the edited world is
///    kept as a keyframe of its own, which thinning never drops. Undo and Reset back to a state
///    the timeline holds as a keyframe are not edits: the timeline just goes there;
///  - Play from step s < lastStep() forgets the states after s, as an edit does;
///  - a new scene starts a new timeline.
/// Step (→) from a past step moves forward along the same run and forgets nothing.
class Timeline : public QObject {
    Q_OBJECT

public:
    /// A timeline of `runner`'s runs, starting from its world now. The runner must outlive it.
    explicit Timeline(SimulationRunner& runner, QObject* parent = nullptr);

    /// The earliest step the timeline can go back to (World::stepCount).
    std::int64_t firstStep() const;
    /// The newest step of the run.
    std::int64_t lastStep() const { return m_lastStep; }
    /// The step shown now (the runner's World::stepCount).
    std::int64_t currentStep() const;

    /// Steps between periodic keyframes (constants::kKeyframeIntervalSteps, doubled by thinning).
    std::int64_t keyframeInterval() const { return m_interval; }
    /// Keyframes kept.
    std::size_t keyframeCount() const { return m_keyframes.size(); }
    /// The memory the keyframes take, bytes (worldBytes of each).
    std::size_t memoryUsed() const { return m_bytes; }
    /// The most memory the keyframes may take, bytes (constants::kTimelineMemoryBudgetBytes).
    std::size_t memoryBudget() const { return m_budget; }
    /// Changes the memory budget (tests use a small one), thinning at once if needed.
    void setMemoryBudget(std::size_t bytes);

    /// The world at `step` (clamped to firstStep() … lastStep()): a keyframe, replayed forward.
    model::World stateAt(std::int64_t step);
    /// The world the run through `step` started from: the scene's start or the last edit at or
    /// before `step` (the integrator ghosts start there).
    const model::World& runStart(std::int64_t step) const;

public slots:
    /// Pauses and shows the state at `step` (clamped), without forgetting anything.
    void seek(std::int64_t step);
    /// Pauses and goes back one fixed step; nothing at firstStep().
    void stepBack();

signals:
    /// firstStep() or lastStep() changed.
    void rangeChanged();
    /// The states after `step` were forgotten: what was recorded of them is no longer the run.
    void futureDiscarded(std::int64_t step);

private:
    struct Keyframe {
        model::World world;
        std::size_t bytes = 0;
        bool essential = false; ///< the start of the scene or an edit: never thinned
    };

    void onStepped();
    void onWorldChanged();
    void onSceneReplaced();
    void onRunningChanged(bool running);
    /// Forgets keyframes after `step` and makes `step` the last step.
    void truncateAfter(std::int64_t step);
    void addKeyframe(const model::World& world, bool essential);
    /// Drops periodic keyframes, doubling the interval, until the keyframes fit the budget.
    void thin();
    /// Index of the last keyframe at or before `step`; 0 when none is.
    std::size_t keyframeBefore(std::int64_t step) const;
    void restart();

    SimulationRunner& m_runner;
    std::vector<Keyframe> m_keyframes; ///< sorted by World::stepCount, one per step at most
    std::int64_t m_lastStep = 0;
    std::int64_t m_interval;
    std::size_t m_bytes = 0;
    std::size_t m_budget;
    bool m_showing = false; ///< seek() is putting a state in: not an edit
    controller::Simulation m_replay; ///< replays from keyframes; scratch state only
};

} // namespace impetus::view
