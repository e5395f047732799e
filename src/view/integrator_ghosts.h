#pragma once
/// \file integrator_ghosts.h
/// View › Compare Integrators, on the canvas: the open scene run under explicit Euler,
/// semi-implicit Euler and RK4 beside the real run (controller::IntegratorComparison), drawn as
/// faint ghosts over it, one colour each, with a legend (docs/explainers.md, "Integrator ghosts").

#include "controller/integrator_comparison.h"

#include <QColor>
#include <QObject>
#include <QPointer>
#include <QString>

#include <cstddef>
#include <cstdint>
#include <optional>

class QLabel;

namespace impetus::view {

class CanvasView;
class GhostItem;
class SimulationRunner;
class Timeline;

/// The name of integrator i of controller::kComparedIntegrators, as the legend and the readout
/// give it ("Explicit Euler", "Semi-implicit Euler", "RK4").
QString ghostIntegratorName(std::size_t i);
/// The colour of integrator i's ghost (constants::kGhostColors).
QColor ghostColor(std::size_t i);
/// `h` (s) as the panel writes it: "1/240 s" when 1/h is a whole number, else in milliseconds.
QString formatTimeStep(double h);

/// Three runs that follow the real one. They start where the run shown started: the scene as
/// loaded, or the last edit before the step shown (Timeline::runStart), and they step with their
/// own time step h (the scene's by default) as far as the real run's clock has gone:
/// round((t − t₀)/h) steps. So they move on while the scene plays, and when the timeline goes back
/// (Step Back, a scrub, Reset) they start again from t₀ and catch up to the time shown. An edit, a
/// new scene or a new h starts them again. Their steps are the engine's; this class only says
/// how many to take and draws the result.
///
/// While enabled, the canvas shows the ghosts (an item over the bodies, object name
/// "integratorGhostsItem") and a legend in its top-right corner (a QLabel on the viewport, object
/// name "integratorGhostsLegend").
class IntegratorGhosts : public QObject {
    Q_OBJECT

public:
    /// Ghosts of `runner`'s run on `canvas`, started as `timeline` says; all three must outlive it.
    IntegratorGhosts(CanvasView& canvas, const SimulationRunner& runner, Timeline& timeline, QObject* parent = nullptr);
    ~IntegratorGhosts() override;

    bool isEnabled() const { return m_comparison.has_value(); }
    /// The three runs, or nullptr while off.
    const controller::IntegratorComparison* comparison() const { return m_comparison ? &*m_comparison : nullptr; }
    /// The ghosts' time step, s.
    double timeStep() const { return m_timeStep; }
    /// Steps each ghost has taken since the start.
    std::int64_t steps() const { return m_steps; }
    /// Whether the ghosts are at the real run's time (false while they catch up in slices).
    bool caughtUp() const { return !m_behind; }

public slots:
    /// Shows the ghosts (from the run's start, caught up to the time shown) or hides them.
    void setEnabled(bool on);
    /// Runs the ghosts with time step `h` (s, > 0) from the start again, caught up to now.
    void setTimeStep(double h);

signals:
    /// The ghosts started again: from a new start state, or with a new time step.
    void restarted();
    /// The ghosts moved (a step, a catch-up, a restart).
    void advanced();

private:
    /// Starts again when the run's start changed, then steps the ghosts to the real run's time.
    void follow();
    /// Takes up to constants::kGhostCatchUpSlice steps towards the real run's time, and asks for
    /// another slice when that was not enough.
    void catchUp();
    void restart();
    /// Puts the item back on the canvas (a rebuild of the canvas's items deletes it) and the
    /// legend in its corner.
    void showOnCanvas();
    void updateLegend();

    CanvasView& m_canvas;
    const SimulationRunner& m_runner;
    Timeline& m_timeline;
    std::optional<controller::IntegratorComparison> m_comparison;
    double m_timeStep = 0; ///< s; 0 until the first start (then the scene's)
    bool m_userTimeStep = false; ///< set by setTimeStep: a new scene keeps it
    std::int64_t m_steps = 0;
    bool m_behind = false;
    bool m_sliceQueued = false;
    QPointer<GhostItem> m_item;
    QPointer<QLabel> m_legend;
};

} // namespace impetus::view
