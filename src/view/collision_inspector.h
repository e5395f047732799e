#pragma once
/// \file collision_inspector.h
/// Explain › Collision Inspector: the run's collision log, and for the entry clicked the impulse
/// formula with that impact's numbers (docs/explainers.md, "The collision inspector").

#include "controller/collision_events.h"
#include "controller/dynamics/impact_record.h"
#include "controller/impact_formula.h"
#include "controller/simulation.h"
#include "model/world.h"

#include <QWidget>

#include <cstdint>
#include <optional>
#include <vector>

class QLabel;
class QListWidget;
class QTextBrowser;

namespace impetus::view {

class SceneDocument;
class Timeline;

/// One entry of the collision log: a contact that began in a step, with the impacts the contact
/// solver resolved between the same two bodies in that step.
struct CollisionLogEntry {
    std::int64_t step = 0; ///< World::stepCount after the step
    controller::CollisionEvent event; ///< the engine's log entry
    std::vector<controller::ImpactRecord> impacts; ///< the engine's records, in the order resolved
};

/// The collision log of the run shown, and the impulse formula of the entry selected.
///
/// The engine logs collisions per step (controller::Simulation::events()); the window's run keeps
/// no log of its own, so the inspector takes the states from the timeline and replays the steps
/// with a Simulation of its own, recording each impact (Simulation::setImpactLog). The engine is
/// deterministic, so these are the run's own collisions, to the bit. It replays while the run is
/// paused and the inspector is shown, at most constants::kCollisionLogMaxReplaySteps steps back.
class CollisionInspector : public QWidget {
    Q_OBJECT

public:
    /// An inspector of `document`'s run along `timeline`; both must outlive it.
    CollisionInspector(SceneDocument& document, Timeline& timeline, QWidget* parent = nullptr);

    /// The log, oldest first.
    const std::vector<CollisionLogEntry>& entries() const { return m_entries; }
    /// Brings the log up to the step shown (replaying the steps not yet seen), unless running.
    void refresh();
    /// Shows entry `index` (of entries()) and its formula.
    void select(int index);
    /// The entry shown, if any.
    std::optional<int> selected() const { return m_selected; }
    /// The formula of the first impact of the entry shown, if it had one.
    std::optional<controller::ImpactFormula> selectedFormula() const;
    /// The text shown for the entry (plain text of the formula panel).
    QString formulaText() const;
    /// The log's list widget (one row per entry).
    QListWidget* list() const { return m_list; }

protected:
    void showEvent(QShowEvent* event) override;

private:
    void forgetAfter(std::int64_t step);
    void clearLog();
    void rebuildList();
    QString formulaHtml(const CollisionLogEntry& entry) const;

    SceneDocument& m_document;
    Timeline& m_timeline;
    controller::Simulation m_simulation;
    std::optional<model::World> m_world; ///< the replay's world, at the last step replayed
    std::vector<controller::ImpactRecord> m_impacts; ///< the replayed step's impact records
    std::vector<CollisionLogEntry> m_entries;
    std::optional<int> m_selected;
    QLabel* m_status = nullptr;
    QListWidget* m_list = nullptr;
    QTextBrowser* m_formula = nullptr;
};

} // namespace impetus::view
