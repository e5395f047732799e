#pragma once
/// \file energy_ledger_chart.h
/// The energy ledger as a stacked chart over time (docs/app.md, "Energy ledger"): the world's
/// kinetic, potential and elastic energy, then what each cause has taken out since the ledger
/// started, stacked one on another. When the ledger closes, the top edge is the starting energy:
/// a flat line. The numbers are the engine's (controller::EnergyLedger); the chart only draws.

#include "view/step_sample.h"

#include <QString>
#include <QWidget>

#include <array>
#include <cstdint>
#include <vector>

class QAreaSeries;
class QChart;
class QChartView;
class QLabel;
class QLineSeries;
class QValueAxis;

namespace impetus::view {

class EnergyLedgerChart : public QWidget {
    Q_OBJECT

public:
    /// The bands, bottom to top.
    enum Band : int {
        Kinetic,
        Potential,
        Elastic,
        Impacts,
        Friction,
        Drag,
        SpringDamping,
        SoftDamping,
        Joints,
        Correction,
        Drift,
        BandCount
    };

    explicit EnergyLedgerChart(QWidget* parent = nullptr);

    /// The band's name, as the legend shows it.
    static QString bandName(Band band);
    /// The points the chart holds.
    std::size_t pointCount() const { return m_points.size(); }
    /// The readout under the chart: the starting and current energy and how well the ledger closes.
    QString readout() const;

public slots:
    /// Appends the ledger rows of a batch's samples. A ledger that started again (the world was
    /// edited, reset or replaced) clears the chart first.
    void addSamples(const std::vector<StepSample>& samples);
    /// Forgets every point.
    void clear();
    /// Drops the points after `step` (the timeline discarded that future).
    void discardAfter(std::int64_t step);

private:
    struct Point {
        std::int64_t step = 0;
        double time = 0; ///< s
        std::array<double, BandCount> values{}; ///< J, per band
    };
    void redraw();

    QChart* m_chart = nullptr;
    QChartView* m_view = nullptr;
    QLabel* m_readout = nullptr;
    QValueAxis* m_timeAxis = nullptr;
    QValueAxis* m_energyAxis = nullptr;
    std::array<QLineSeries*, BandCount> m_lower{}; ///< each band's lower edge
    std::array<QLineSeries*, BandCount> m_upper{}; ///< each band's upper edge
    std::array<QAreaSeries*, BandCount> m_bands{};
    std::vector<Point> m_points;
    double m_startTime = -1; ///< the ledger start the points belong to, s
    controller::LedgerSample m_last; ///< the latest row, for the readout
    bool m_hasLast = false;
};

} // namespace impetus::view
