#pragma once
/// \file integrator_ghosts_dock.h
/// View › Compare Integrators: the ghosts on the canvas and the dock that reads them out
/// (docs/explainers.md, "Integrator ghosts").

#include "model/world.h"

#include <QString>
#include <QWidget>

#include <array>
#include <optional>
#include <utility>
#include <vector>

class QChart;
class QChartView;
class QLabel;
class QLineSeries;
class QLogValueAxis;
class QSlider;
class QTableWidget;

namespace impetus::view {

class IntegratorGhosts;
class MainWindow;

/// The slope of the least-squares line through the points (log xᵢ, log yᵢ), dimensionless: the
/// order p of an error that falls as hᵖ. None with fewer than two points or no spread in x.
std::optional<double> logLogSlope(const std::vector<double>& x, const std::vector<double>& y);

/// The dock's contents. A table (object name "ghostReadout") with a row per integrator and two
/// columns: the energy error (E − E₀)/|E₀| in %, and the largest distance of a body from the
/// analytic solution in mm, or "no analytic solution" where the scene has none (anything but a
/// projectile in flight or a mass on an undamped spring). Under it the clock of the ghosts
/// ("ghostClock": t, the steps n and h), the time-step slider ("ghostTimeStepSlider", one notch per
/// constants::kGhostTimeSteps), and a log–log chart ("ghostErrorChart") of each integrator's
/// largest position error over constants::kGhostErrorRunSeconds against h
/// (controller::errorAgainstStep), with the slope fitted to each line, the method's order, written
/// under it ("ghostSlopes").
class IntegratorGhostsPanel : public QWidget {
    Q_OBJECT

public:
    /// A panel reading out `ghosts`, which must outlive it.
    explicit IntegratorGhostsPanel(IntegratorGhosts& ghosts, QWidget* parent = nullptr);

    /// The fitted slope of each integrator's line on the chart; none where the line has fewer than
    /// two points (no analytic solution, or an error at the rounding level throughout).
    const std::array<std::optional<double>, 3>& slopes() const { return m_slopes; }
    /// The points of integrator i's line on the chart, (h in s, error in m).
    std::vector<std::pair<double, double>> plotted(std::size_t i) const;

private:
    /// Fills the table and the clock from the ghosts now.
    void updateReadout();
    /// The ghosts started again: a new start makes a new error plot; a new h moves its marker.
    void onRestarted();
    /// Makes the error plot of the start the ghosts run from.
    void replot(const model::World& start);
    void moveMarker();

    IntegratorGhosts& m_ghosts;
    QTableWidget* m_table = nullptr;
    QLabel* m_clock = nullptr;
    QLabel* m_analytic = nullptr;
    QSlider* m_slider = nullptr;
    QLabel* m_stepLabel = nullptr;
    QChart* m_chart = nullptr;
    QChartView* m_chartView = nullptr;
    QLogValueAxis* m_axisH = nullptr;
    QLogValueAxis* m_axisError = nullptr;
    std::array<QLineSeries*, 3> m_lines{};
    QLineSeries* m_marker = nullptr; ///< a vertical line at the ghosts' h
    QLabel* m_slopeLabel = nullptr;
    std::array<std::optional<double>, 3> m_slopes{};
    std::optional<model::World> m_plottedStart; ///< the start the plot was made for
    double m_errorLow = 0; ///< the plot's error range, m
    double m_errorHigh = 0;
};

/// Adds View › Compare Integrators (checkable; object name "compareIntegratorsAction") to
/// `window`: on, it shows the ghosts (an IntegratorGhosts, object name "integratorGhosts") and the
/// dock "integratorGhostsDock" holding an IntegratorGhostsPanel; off, or the dock closed, hides both
/// and stops the ghosts.
void addIntegratorGhosts(MainWindow& window);

} // namespace impetus::view
