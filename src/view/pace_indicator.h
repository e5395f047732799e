#pragma once
/// \file pace_indicator.h
/// The status-bar reading that appears when the simulation runs slower than real time, and says
/// why.

#include <QLabel>
#include <QString>

namespace impetus::view {

class SimulationRunner;
struct RunPace;

/// A status-bar label that follows a SimulationRunner's pace(). It is hidden while the run keeps
/// up with the wall clock and while paused. It shows "Running at 0.05× real time" (with the speed
/// asked for when that is not 1×) while a run falls behind, and "Computing a step…" while a Step
/// is computed in the background. Its tool tip gives the reason: the wall time one step takes
/// against the time real time allows it (time step ÷ speed), what the engine says that step cost
/// (contacts, impacts, solver time, soft-body substeps), and what to change to keep up.
class PaceIndicator : public QLabel {
    Q_OBJECT

public:
    /// A hidden indicator following `runner`, which must outlive it.
    explicit PaceIndicator(const SimulationRunner& runner, QWidget* parent = nullptr);

private:
    void refresh();
    /// The tool tip: why the run is behind (or the Step slow) and what to do about it.
    QString reason(const RunPace& pace, bool running) const;

    const SimulationRunner& m_runner;
};

} // namespace impetus::view
