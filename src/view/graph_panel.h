#pragma once
/// \file graph_panel.h
/// A live graph of one body's quantity (or a world total) against time or against another
/// quantity, with CSV and PNG export. Meant for a dock of its own; several can be open at once.

#include "view/graph_quantity.h"
#include "view/view_constants.h"
#include "view/step_sample.h"

#include <QPoint>
#include <QString>
#include <QWidget>

#include <cstdint>
#include <optional>
#include <vector>

class QChart;
class QChartView;
class QComboBox;
class QLabel;
class QLineSeries;
class QScatterSeries;
class QTimer;
class QValueAxis;

namespace impetus::view {

class SimulationRunner;

/// Plots y against x for the body chosen in its body box: y any GraphQuantity, x time (a graph
/// against time) or another quantity (a phase plot, such as vx against x). It keeps one record
/// per fixed step (GraphRecord) from the moment it is opened, or its body or the scene changes,
/// taken by the runner after every step (SimulationRunner::sampled()), so it has every step even
/// though the canvas shows one state a frame. A marker shows the state on the canvas, so the graph
/// follows the timeline when it is scrubbed; Play from a past step (or an edit) forgets the
/// records after it (discardAfter()).
///
/// A box dragged over the plot zooms in on it, and the zoom stays while records come in; a right
/// click shows every record again. Hovering over the plot shows the record nearest to the
/// cursor's x ("t = 1.2375 s, vy = −12.14 m/s") in the readout label under it. Export CSV writes every record kept: "time,body"
/// and then the plotted columns (csvColumn(), impetus-cli's names and SI units), numbers in the
/// shortest form that reads back to the same double. Export PNG writes the chart as shown.
/// Object names: "graphBody", "graphY", "graphX", "graphReadout", "graphChartView".
class GraphPanel : public QWidget {
    Q_OBJECT

public:
    /// A graph of `runner`'s world (the runner outlives it), of the body called `bodyName` (the
    /// first dynamic body when empty or not found), plotting `y` against `x`.
    GraphPanel(const SimulationRunner& runner, const QString& bodyName, GraphQuantity y,
               GraphQuantity x = GraphQuantity::Time, QWidget* parent = nullptr);

    /// The body plotted, by index into World::bodies; none when the world has no body.
    std::optional<std::uint32_t> body() const { return m_body; }
    QString bodyName() const { return m_bodyName; }
    GraphQuantity yQuantity() const { return m_y; }
    GraphQuantity xQuantity() const { return m_x; }
    /// Plots the body called `name`: the records start again from the state shown.
    void setBody(const QString& name);
    void setQuantities(GraphQuantity y, GraphQuantity x);

    /// The records kept, oldest first.
    const std::vector<GraphRecord>& records() const { return m_records; }
    /// Keeps at least the last `most` records (kMaxGraphSamples unless set): once there are
    /// kGraphTrimShare × `most` more, the oldest are dropped down to `most`, all at once.
    void setSampleLimit(std::size_t most);
    std::size_t sampleLimit() const { return m_sampleLimit; }
    /// A title for the dock: "vy of ball", "vx against x of ball".
    QString title() const;

    /// Writes the records to `path` as CSV. Returns the problem when the file cannot be written.
    std::optional<QString> exportCsv(const QString& path) const;
    /// Writes the chart, as shown, to `path` as PNG. Returns the problem when it cannot.
    std::optional<QString> exportPng(const QString& path) const;

    /// Whether the plot shows a part the user zoomed in on (a box dragged over it) rather than
    /// every record.
    bool isZoomed() const { return m_zoomed; }
    /// Ends the zoom: every record is shown again (a right click on the plot does it).
    void showAll();

    /// The chart view (for tests and the screenshot).
    QChartView* chartView() const { return m_chartView; }

public slots:
    /// Takes the records of `samples` for its body.
    void addSamples(const std::vector<StepSample>& samples);
    /// Forgets the records after `step`.
    void discardAfter(std::int64_t step);
    /// Follows an edit or a new state shown: finds its body again by name, moves the marker.
    void onWorldChanged();
    /// A new scene: chooses its body again and starts afresh.
    void onSceneReplaced();

signals:
    /// The body plotted changed: the runner's sampling must follow.
    void bodyChanged();
    /// The title changed.
    void titleChanged(const QString& title);

private:
    /// Starts the records again from the state shown.
    void restart();
    /// The record of the state shown.
    GraphRecord currentRecord() const;
    /// Fills the body box with the world's bodies.
    void fillBodies();
    /// Redraws the series now.
    void redraw();
    /// Drops the oldest records once there are well more than m_sampleLimit (setSampleLimit).
    void trimRecords();
    /// Redraws soon (at most every constants::kGraphRefreshMs while running).
    void scheduleRedraw();
    void exportCsvInteractively();
    void exportPngInteractively();
    bool eventFilter(QObject* watched, QEvent* event) override;

    const SimulationRunner& m_runner;
    QString m_bodyName;
    std::optional<std::uint32_t> m_body;
    GraphQuantity m_y;
    GraphQuantity m_x;
    std::vector<GraphRecord> m_records;
    std::size_t m_sampleLimit = constants::kMaxGraphSamples;
    QComboBox* m_bodyBox;
    QComboBox* m_yBox;
    QComboBox* m_xBox;
    QLabel* m_readout;
    QChart* m_chart;
    QChartView* m_chartView;
    QLineSeries* m_series;
    QScatterSeries* m_marker;
    QValueAxis* m_axisX;
    QValueAxis* m_axisY;
    QTimer* m_redrawTimer;
    bool m_zoomed = false; ///< the axes show the user's zoom, not the records' range
    bool m_settingRange = false; ///< redraw() is setting the axes' range
    QPoint m_pressAt; ///< where the left button went down on the plot, viewport px
};

} // namespace impetus::view
