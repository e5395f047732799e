#include "view/graph_panel.h"

#include "controller/diagnostics.h"
#include "view/number_text.h"
#include "view/simulation_runner.h"
#include "view/view_constants.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineSeries>
#include <QLocale>
#include <QMessageBox>
#include <QMouseEvent>
#include <QPixmap>
#include <QPushButton>
#include <QRubberBand>
#include <QSaveFile>
#include <QScatterSeries>
#include <QSignalBlocker>
#include <QTimer>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <limits>

namespace impetus::view {

namespace {

/// The smallest chart that still reads, px.
constexpr int kMinChartWidthPx = 240;
constexpr int kMinChartHeightPx = 160;
/// The marker of the state shown, px.
constexpr double kMarkerSizePx = 9;
/// Space around the chart and the panel's controls, px.
constexpr int kMarginPx = 4;
/// The axes reach this fraction of the data's span beyond it, so no point sits on the frame.
constexpr double kRangeMarginFraction = 0.05;
/// A box dragged over the plot narrower or shorter than this is a click, not a zoom, px.
constexpr int kMinZoomBoxPx = 4;
/// A constant quantity (a body at rest) gets an axis at least this far each side of its value,
/// in its own unit.
constexpr double kFlatRangeMargin = 0.5;
/// Significant digits of the value under the cursor: enough to tell two steps of a long run apart
/// (t = 12.345678 s at 1/240 s a step).
constexpr int kReadoutDigits = 8;

/// A number as impetus-cli writes it: the shortest text that reads back to the same double.
QString csvNumber(double value) { return QString::number(value, 'g', QLocale::FloatingPointShortest); }

/// Quotes a CSV field when it holds a comma, a quote or a line break (RFC 4180), as impetus-cli.
QString csvField(const QString& text)
{
    if (!text.contains(QLatin1Char(',')) && !text.contains(QLatin1Char('"')) && !text.contains(QLatin1Char('\n')) &&
        !text.contains(QLatin1Char('\r')))
        return text;
    QString quoted = text;
    quoted.replace(QLatin1Char('"'), QStringLiteral("\"\""));
    return QLatin1Char('"') + quoted + QLatin1Char('"');
}

/// The plotted range of `values` with a margin, never empty.
std::pair<double, double> paddedRange(double low, double high)
{
    if (!(low <= high))
        return {0, 1};
    // A constant (a body at rest) still gets an axis a unit wide around its value.
    const double span = high - low;
    const double margin = span > 0 ? kRangeMarginFraction * span
                                    : std::max(kFlatRangeMargin, kRangeMarginFraction * std::abs(low));
    return {low - margin, high + margin};
}

} // namespace

GraphPanel::GraphPanel(const SimulationRunner& runner, const QString& bodyName, GraphQuantity y, GraphQuantity x,
                       QWidget* parent)
    : QWidget(parent)
    , m_runner(runner)
    , m_bodyName(bodyName)
    , m_y(y)
    , m_x(x)
    , m_bodyBox(new QComboBox(this))
    , m_yBox(new QComboBox(this))
    , m_xBox(new QComboBox(this))
    , m_readout(new QLabel(this))
    , m_chart(new QChart)
    , m_chartView(new QChartView(m_chart, this))
    , m_series(new QLineSeries)
    , m_marker(new QScatterSeries)
    , m_axisX(new QValueAxis)
    , m_axisY(new QValueAxis)
    , m_redrawTimer(new QTimer(this))
{
    setAccessibleName(tr("Graph"));
    m_bodyBox->setObjectName(QStringLiteral("graphBody"));
    m_bodyBox->setAccessibleName(tr("Body plotted"));
    m_yBox->setObjectName(QStringLiteral("graphY"));
    m_yBox->setAccessibleName(tr("Quantity on the vertical axis"));
    m_xBox->setObjectName(QStringLiteral("graphX"));
    m_xBox->setAccessibleName(tr("Quantity on the horizontal axis"));
    m_readout->setObjectName(QStringLiteral("graphReadout"));
    m_readout->setAccessibleName(tr("Value under the cursor"));
    m_chartView->setObjectName(QStringLiteral("graphChartView"));
    m_chartView->setRenderHint(QPainter::Antialiasing);
    m_chartView->setMinimumSize(kMinChartWidthPx, kMinChartHeightPx);
    m_chartView->viewport()->installEventFilter(this);
    m_chartView->viewport()->setMouseTracking(true);
    // A box dragged over the plot zooms in on it (to read a time to a step off a long run); a
    // right click shows the whole record again.
    m_chartView->setRubberBand(QChartView::RectangleRubberBand);
    m_chartView->setToolTip(tr("Drag a box over the plot to zoom in on it; right-click to see everything again"));
    for (const GraphQuantity q : graphQuantities()) {
        if (q != GraphQuantity::Time)
            m_yBox->addItem(quantityLabel(q), static_cast<int>(q));
        m_xBox->addItem(quantityLabel(q), static_cast<int>(q));
    }
    m_yBox->setCurrentIndex(m_yBox->findData(static_cast<int>(m_y)));
    m_xBox->setCurrentIndex(m_xBox->findData(static_cast<int>(m_x)));

    m_chart->legend()->hide();
    // The axes' numbers in the window's format too ("0,5" in German), as the readout under them.
    m_chart->setLocalizeNumbers(true);
    m_chart->addSeries(m_series);
    m_chart->addSeries(m_marker);
    m_chart->addAxis(m_axisX, Qt::AlignBottom);
    m_chart->addAxis(m_axisY, Qt::AlignLeft);
    for (QAbstractSeries* series : {static_cast<QAbstractSeries*>(m_series), static_cast<QAbstractSeries*>(m_marker)}) {
        series->attachAxis(m_axisX);
        series->attachAxis(m_axisY);
    }
    m_marker->setMarkerSize(kMarkerSizePx);
    m_marker->setColor(constants::kSelectionColor);
    m_chart->setMargins(QMargins(kMarginPx, kMarginPx, kMarginPx, kMarginPx));
    // A range the graph did not set itself is the user's zoom: kept until a right click, or a
    // new body or quantity, as new records come in.
    for (QValueAxis* axis : {m_axisX, m_axisY}) {
        connect(axis, &QValueAxis::rangeChanged, this, [this] {
            if (!m_settingRange)
                m_zoomed = true;
        });
    }

    auto* exportCsv = new QPushButton(tr("Export CSV…"), this);
    exportCsv->setObjectName(QStringLiteral("graphExportCsv"));
    exportCsv->setToolTip(tr("Save every recorded step as a table (time, body and the plotted quantities)"));
    auto* exportPng = new QPushButton(tr("Export PNG…"), this);
    exportPng->setObjectName(QStringLiteral("graphExportPng"));
    exportPng->setToolTip(tr("Save the graph as a picture"));
    connect(exportCsv, &QPushButton::clicked, this, &GraphPanel::exportCsvInteractively);
    connect(exportPng, &QPushButton::clicked, this, &GraphPanel::exportPngInteractively);

    auto* choices = new QHBoxLayout;
    choices->addWidget(m_bodyBox, 1);
    choices->addWidget(m_yBox, 1);
    choices->addWidget(new QLabel(tr("against"), this));
    choices->addWidget(m_xBox, 1);
    auto* bottom = new QHBoxLayout;
    bottom->addWidget(m_readout, 1);
    bottom->addWidget(exportCsv);
    bottom->addWidget(exportPng);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(kMarginPx, kMarginPx, kMarginPx, kMarginPx);
    layout->addLayout(choices);
    layout->addWidget(m_chartView, 1);
    layout->addLayout(bottom);

    connect(m_bodyBox, &QComboBox::activated, this, [this] { setBody(m_bodyBox->currentText()); });
    connect(m_yBox, &QComboBox::activated, this, [this] {
        setQuantities(static_cast<GraphQuantity>(m_yBox->currentData().toInt()), m_x);
    });
    connect(m_xBox, &QComboBox::activated, this, [this] {
        setQuantities(m_y, static_cast<GraphQuantity>(m_xBox->currentData().toInt()));
    });
    m_redrawTimer->setSingleShot(true);
    m_redrawTimer->setInterval(constants::kGraphRefreshMs);
    connect(m_redrawTimer, &QTimer::timeout, this, &GraphPanel::redraw);

    fillBodies();
    restart();
}

QString GraphPanel::title() const
{
    const QString y = quantityLabel(m_y).section(QLatin1Char(' '), 0, -2);
    if (isWorldQuantity(m_y) && m_x == GraphQuantity::Time)
        return y;
    if (m_x == GraphQuantity::Time)
        return tr("%1 of %2").arg(y, m_bodyName);
    return tr("%1 against %2 of %3").arg(y, quantityLabel(m_x).section(QLatin1Char(' '), 0, -2), m_bodyName);
}

void GraphPanel::fillBodies()
{
    const model::World& world = m_runner.world();
    const QSignalBlocker blocker(m_bodyBox);
    m_bodyBox->clear();
    for (const model::Body& body : world.bodies)
        m_bodyBox->addItem(QString::fromStdString(body.name));
    m_body.reset();
    const std::optional<model::BodyId> found = world.findBody(m_bodyName.toStdString());
    if (found) {
        m_body = found->index;
    } else {
        // The first body that moves: what a student means by "the body" in a one-body scene.
        const auto dynamic = std::ranges::find_if(world.bodies, [](const model::Body& b) { return !b.fixed; });
        if (dynamic != world.bodies.end())
            m_body = static_cast<std::uint32_t>(dynamic - world.bodies.begin());
        else if (!world.bodies.empty())
            m_body = 0;
        m_bodyName = m_body ? QString::fromStdString(world.bodies[*m_body].name) : QString();
    }
    if (m_body)
        m_bodyBox->setCurrentIndex(static_cast<int>(*m_body));
}

void GraphPanel::setBody(const QString& name)
{
    m_bodyName = name;
    fillBodies();
    restart();
    emit bodyChanged();
    emit titleChanged(title());
}

void GraphPanel::setQuantities(GraphQuantity y, GraphQuantity x)
{
    m_y = y;
    m_x = x;
    {
        const QSignalBlocker blockY(m_yBox);
        const QSignalBlocker blockX(m_xBox);
        m_yBox->setCurrentIndex(m_yBox->findData(static_cast<int>(m_y)));
        m_xBox->setCurrentIndex(m_xBox->findData(static_cast<int>(m_x)));
    }
    // The records hold every quantity: a new choice is plotted from them at once, all of it.
    m_zoomed = false;
    redraw();
    emit titleChanged(title());
}

GraphRecord GraphPanel::currentRecord() const
{
    const model::World& world = m_runner.world();
    GraphRecord record;
    record.step = world.stepCount;
    record.time = world.time;
    if (m_body && *m_body < world.bodies.size())
        record.body = controller::readBody(world, model::BodyId{*m_body});
    record.totals.energy = controller::computeEnergy(world);
    record.totals.momentum = controller::linearMomentum(world);
    record.totals.angularMomentum = controller::angularMomentum(world);
    record.totals.collisions = world.collisionCount;
    return record;
}

void GraphPanel::restart()
{
    m_zoomed = false;
    m_records.clear();
    if (m_body)
        m_records.push_back(currentRecord());
    redraw();
}

void GraphPanel::addSamples(const std::vector<StepSample>& samples)
{
    if (!m_body)
        return;
    for (const StepSample& sample : samples) {
        const auto it = std::ranges::find_if(sample.bodies, [&](const BodySample& b) { return b.body == *m_body; });
        if (it == sample.bodies.end())
            continue;
        // Steps along a run already recorded (Step after scrubbing back) add nothing.
        if (!m_records.empty() && m_records.back().step >= sample.step)
            continue;
        m_records.push_back(GraphRecord{sample.step, sample.time, it->readout, sample.totals});
    }
    trimRecords();
    scheduleRedraw();
}

void GraphPanel::setSampleLimit(std::size_t most)
{
    m_sampleLimit = std::max<std::size_t>(1, most);
    trimRecords();
    scheduleRedraw();
}

void GraphPanel::trimRecords()
{
    // In one go once well past the limit: erasing from the front moves every record kept.
    const auto slack = static_cast<std::size_t>(constants::kGraphTrimShare * static_cast<double>(m_sampleLimit));
    if (m_records.size() <= m_sampleLimit + slack)
        return;
    m_records.erase(m_records.begin(),
                    m_records.begin() + static_cast<std::ptrdiff_t>(m_records.size() - m_sampleLimit));
}

void GraphPanel::discardAfter(std::int64_t step)
{
    while (!m_records.empty() && m_records.back().step > step)
        m_records.pop_back();
    scheduleRedraw();
}

void GraphPanel::onWorldChanged()
{
    const model::World& world = m_runner.world();
    const bool same = m_body && *m_body < world.bodies.size() && world.bodies[*m_body].name == m_bodyName.toStdString();
    if (!same) {
        // Renamed, deleted or re-indexed: find it again; a body of another name starts afresh.
        const std::optional<std::uint32_t> before = m_body;
        fillBodies();
        if (m_body != before) {
            restart();
            emit bodyChanged();
            emit titleChanged(title());
            return;
        }
    } else if (m_bodyBox->count() != static_cast<int>(world.bodies.size())) {
        fillBodies();
    }
    if (m_records.empty() && m_body)
        m_records.push_back(currentRecord());
    scheduleRedraw();
}

void GraphPanel::onSceneReplaced()
{
    m_bodyName.clear();
    fillBodies();
    restart();
    emit bodyChanged();
    emit titleChanged(title());
}

void GraphPanel::scheduleRedraw()
{
    // While running, the series is redrawn a few times a second: Qt Charts redraws a long series
    // slower than the steps come. Paused, at once, so a scrub shows at once.
    if (m_runner.isRunning()) {
        if (!m_redrawTimer->isActive())
            m_redrawTimer->start();
    } else {
        redraw();
    }
}

void GraphPanel::redraw()
{
    QList<QPointF> points;
    points.reserve(static_cast<qsizetype>(m_records.size()));
    double xLow = std::numeric_limits<double>::infinity();
    double xHigh = -xLow;
    double yLow = xLow;
    double yHigh = -xLow;
    for (const GraphRecord& r : m_records) {
        const double x = valueOf(m_x, r);
        const double y = valueOf(m_y, r);
        points.append(QPointF(x, y));
        xLow = std::min(xLow, x);
        xHigh = std::max(xHigh, x);
        yLow = std::min(yLow, y);
        yHigh = std::max(yHigh, y);
    }
    m_series->replace(points);
    // The marker is the state on the canvas: where the timeline is.
    m_marker->clear();
    if (m_body) {
        const GraphRecord now = currentRecord();
        m_marker->append(valueOf(m_x, now), valueOf(m_y, now));
    }
    if (!m_zoomed) {
        const auto [x0, x1] = paddedRange(xLow, xHigh);
        const auto [y0, y1] = paddedRange(yLow, yHigh);
        m_settingRange = true;
        m_axisX->setRange(x0, x1);
        m_axisY->setRange(y0, y1);
        m_settingRange = false;
    }
    m_axisX->setTitleText(quantityLabel(m_x));
    m_axisY->setTitleText(quantityLabel(m_y));
}

bool GraphPanel::eventFilter(QObject* watched, QEvent* event)
{
    // A right click ends the zoom: the whole record again (QChartView's own right click would
    // only undo one zoom, and only within its own history).
    if (watched == m_chartView->viewport() &&
        (event->type() == QEvent::MouseButtonPress || event->type() == QEvent::MouseButtonRelease) &&
        static_cast<QMouseEvent*>(event)->button() == Qt::RightButton) {
        if (event->type() == QEvent::MouseButtonRelease)
            showAll();
        return true;
    }
    // A click that moved a pixel or two is a click, not a box to zoom into: QChartView would zoom
    // into a sliver of the plot. Its rubber band is put away and the release goes no further.
    if (watched == m_chartView->viewport() &&
        (event->type() == QEvent::MouseButtonPress || event->type() == QEvent::MouseButtonRelease) &&
        static_cast<QMouseEvent*>(event)->button() == Qt::LeftButton) {
        const QPoint at = static_cast<QMouseEvent*>(event)->position().toPoint();
        if (event->type() == QEvent::MouseButtonPress) {
            m_pressAt = at;
        } else if (std::abs(at.x() - m_pressAt.x()) < kMinZoomBoxPx || std::abs(at.y() - m_pressAt.y()) < kMinZoomBoxPx) {
            if (auto* band = m_chartView->findChild<QRubberBand*>())
                band->hide();
            return true;
        }
    }
    if (watched == m_chartView->viewport() && event->type() == QEvent::MouseMove && !m_records.empty()) {
        const auto* mouse = static_cast<QMouseEvent*>(event);
        const QPointF value = m_chart->mapToValue(m_chartView->mapToScene(mouse->position().toPoint()), m_series);
        // The record whose x is nearest to the cursor's: on a graph against time, the step under it.
        const auto nearest = std::ranges::min_element(m_records, {}, [&](const GraphRecord& r) {
            return std::abs(valueOf(m_x, r) - value.x());
        });
        // In the window's number format ("0,25" in German); the CSV keeps the decimal point.
        m_readout->setText(tr("%1 = %2, %3 = %4")
                               .arg(csvColumn(m_x), localeNumber(valueOf(m_x, *nearest), 'g', kReadoutDigits),
                                    csvColumn(m_y), localeNumber(valueOf(m_y, *nearest), 'g', kReadoutDigits)));
    }
    return QWidget::eventFilter(watched, event);
}

void GraphPanel::showAll()
{
    m_zoomed = false;
    redraw();
}

std::optional<QString> GraphPanel::exportCsv(const QString& path) const
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text))
        return tr("Cannot write “%1”: %2").arg(path, file.errorString());
    QStringList columns{QStringLiteral("time"), QStringLiteral("body")};
    std::vector<GraphQuantity> quantities;
    for (const GraphQuantity q : {m_x, m_y}) {
        if (q != GraphQuantity::Time && std::ranges::find(quantities, q) == quantities.end()) {
            quantities.push_back(q);
            columns << csvColumn(q);
        }
    }
    QByteArray text = columns.join(QLatin1Char(',')).toUtf8() + '\n';
    const QString body = csvField(m_bodyName);
    for (const GraphRecord& r : m_records) {
        QStringList row{csvNumber(r.time), body};
        for (const GraphQuantity q : quantities)
            row << csvNumber(valueOf(q, r));
        text += row.join(QLatin1Char(',')).toUtf8() + '\n';
    }
    if (file.write(text) != text.size() || !file.commit())
        return tr("Cannot write “%1”: %2").arg(path, file.errorString());
    return std::nullopt;
}

std::optional<QString> GraphPanel::exportPng(const QString& path) const
{
    const QPixmap picture = m_chartView->grab();
    if (picture.isNull() || !picture.save(path, "PNG"))
        return tr("Cannot write the picture “%1”.").arg(path);
    return std::nullopt;
}

void GraphPanel::exportCsvInteractively()
{
    QString path = QFileDialog::getSaveFileName(this, tr("Export Graph Data"), QString(),
                                                tr("CSV tables (*.csv);;All files (*)"));
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".csv");
    if (const std::optional<QString> error = exportCsv(path))
        QMessageBox::warning(this, tr("Cannot export"), *error);
}

void GraphPanel::exportPngInteractively()
{
    QString path = QFileDialog::getSaveFileName(this, tr("Export Graph Picture"), QString(),
                                                tr("PNG pictures (*.png);;All files (*)"));
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".png");
    if (const std::optional<QString> error = exportPng(path))
        QMessageBox::warning(this, tr("Cannot export"), *error);
}

} // namespace impetus::view
