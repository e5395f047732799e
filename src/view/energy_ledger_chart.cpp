#include "view/energy_ledger_chart.h"

#include "view/number_text.h"
#include "view/view_constants.h"

#include <QAreaSeries>
#include <QChart>
#include <QChartView>
#include <QLabel>
#include <QLineSeries>
#include <QLocale>
#include <QPainter>
#include <QValueAxis>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace impetus::view {

namespace {

/// One colour per band: the three stored energies in blues, the losses in warm colours, position
/// correction in grey and the drift in black, so that the one line that is not a cause stands out.
QColor bandColor(EnergyLedgerChart::Band band)
{
    static const std::array<QColor, EnergyLedgerChart::BandCount> colors = {
        QColor(0x25, 0x63, 0xeb), QColor(0x60, 0xa5, 0xfa), QColor(0x93, 0xc5, 0xfd), QColor(0xdc, 0x26, 0x26),
        QColor(0xea, 0x58, 0x0c), QColor(0xd9, 0x77, 0x06), QColor(0x16, 0xa3, 0x4a), QColor(0x84, 0xcc, 0x16),
        QColor(0x7c, 0x3a, 0xed), QColor(0x9c, 0xa3, 0xaf), QColor(0x1f, 0x29, 0x37)};
    return colors[static_cast<std::size_t>(band)];
}

} // namespace

EnergyLedgerChart::EnergyLedgerChart(QWidget* parent)
    : QWidget(parent)
{
    setObjectName(QStringLiteral("energyLedgerChart"));
    m_chart = new QChart;
    m_chart->legend()->setAlignment(Qt::AlignRight);
    // The axes' numbers in the window's format ("0,5" in German), as the readout below them.
    m_chart->setLocalizeNumbers(true);
    m_timeAxis = new QValueAxis(m_chart);
    m_timeAxis->setTitleText(tr("time (s)"));
    m_energyAxis = new QValueAxis(m_chart);
    m_energyAxis->setTitleText(tr("energy (J)"));
    m_chart->addAxis(m_timeAxis, Qt::AlignBottom);
    m_chart->addAxis(m_energyAxis, Qt::AlignLeft);
    for (int b = 0; b < BandCount; ++b) {
        const auto band = static_cast<Band>(b);
        const auto i = static_cast<std::size_t>(b);
        m_lower[i] = new QLineSeries(m_chart);
        m_upper[i] = new QLineSeries(m_chart);
        m_bands[i] = new QAreaSeries(m_upper[i], m_lower[i]);
        m_bands[i]->setName(bandName(band));
        QColor fill = bandColor(band);
        fill.setAlpha(constants::kLedgerBandAlpha);
        m_bands[i]->setBrush(fill);
        m_bands[i]->setPen(QPen(bandColor(band).darker(), 1));
        m_chart->addSeries(m_bands[i]);
        m_bands[i]->attachAxis(m_timeAxis);
        m_bands[i]->attachAxis(m_energyAxis);
    }
    m_view = new QChartView(m_chart, this);
    m_view->setRenderHint(QPainter::Antialiasing);
    m_readout = new QLabel(this);
    m_readout->setObjectName(QStringLiteral("energyLedgerReadout"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_view, 1);
    layout->addWidget(m_readout);
    clear();
}

QString EnergyLedgerChart::bandName(Band band)
{
    switch (band) {
    case Kinetic:
        return tr("Kinetic");
    case Potential:
        return tr("Potential");
    case Elastic:
        return tr("Elastic");
    case Impacts:
        return tr("Impacts");
    case Friction:
        return tr("Friction");
    case Drag:
        return tr("Drag");
    case SpringDamping:
        return tr("Spring damping");
    case SoftDamping:
        return tr("Soft damping");
    case Joints:
        return tr("Joints");
    case Correction:
        return tr("Position correction");
    case Drift:
        return tr("Drift");
    case BandCount:
        break;
    }
    return {};
}

QString EnergyLedgerChart::readout() const
{
    return m_readout->text();
}

void EnergyLedgerChart::clear()
{
    m_points.clear();
    m_startTime = -1;
    m_hasLast = false;
    redraw();
}

void EnergyLedgerChart::discardAfter(std::int64_t step)
{
    std::erase_if(m_points, [step](const Point& p) { return p.step > step; });
    redraw();
}

void EnergyLedgerChart::addSamples(const std::vector<StepSample>& samples)
{
    bool added = false;
    for (const StepSample& sample : samples) {
        if (!sample.ledger)
            continue;
        const controller::LedgerSample& l = *sample.ledger;
        if (l.startTime != m_startTime) {
            m_points.clear();
            m_startTime = l.startTime;
        }
        const controller::EnergyLosses& x = l.losses;
        m_points.push_back(Point{sample.step, sample.time,
                                 {l.current.kinetic, l.current.potential, l.current.elastic, x.impacts, x.friction,
                                  x.drag, x.springDamping, x.softDamping, x.joints, x.correction, x.drift}});
        m_last = l;
        m_hasLast = true;
        added = true;
    }
    if (!added)
        return;
    // A long run keeps every other point, over and over: the chart's cost stays bounded and its
    // shape stays that of the whole run.
    if (m_points.size() > constants::kMaxLedgerPoints) {
        std::vector<Point> kept;
        kept.reserve(m_points.size() / 2 + 1);
        for (std::size_t i = 0; i < m_points.size(); i += 2)
            kept.push_back(m_points[i]);
        if (kept.back().step != m_points.back().step)
            kept.push_back(m_points.back());
        m_points = std::move(kept);
    }
    redraw();
}

void EnergyLedgerChart::redraw()
{
    std::array<QList<QPointF>, BandCount> lower;
    std::array<QList<QPointF>, BandCount> upper;
    double low = 0;
    double high = 0;
    for (const Point& p : m_points) {
        double sum = 0;
        for (std::size_t b = 0; b < BandCount; ++b) {
            lower[b].append(QPointF(p.time, sum));
            sum += p.values[b];
            upper[b].append(QPointF(p.time, sum));
            low = std::min(low, sum);
            high = std::max(high, sum);
        }
    }
    for (std::size_t b = 0; b < BandCount; ++b) {
        m_lower[b]->replace(lower[b]);
        m_upper[b]->replace(upper[b]);
    }
    const double first = m_points.empty() ? 0.0 : m_points.front().time;
    const double last = m_points.empty() ? 1.0 : m_points.back().time;
    m_timeAxis->setRange(first, std::max(last, first + 1e-3));
    // A little room above the top edge, which a closed ledger keeps flat at the starting energy.
    const double span = std::max(high - low, 1e-9);
    m_energyAxis->setRange(low - 0.05 * span, high + 0.05 * span);

    if (!m_hasLast) {
        m_readout->setText(tr("Run the simulation to fill the energy ledger."));
        return;
    }
    const double initial = m_last.initial.total();
    const double current = m_last.current.total();
    const double gap = std::abs(initial - current - m_last.losses.total());
    m_readout->setText(tr("Start %1 J = now %2 J + losses %3 J (off by %4 J); drift %5 J")
                           .arg(localeNumber(initial, 'g', 6), localeNumber(current, 'g', 6),
                                localeNumber(m_last.losses.total(), 'g', 6), localeNumber(gap, 'g', 2),
                                localeNumber(m_last.losses.drift, 'g', 3)));
}

} // namespace impetus::view
