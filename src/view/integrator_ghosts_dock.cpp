// View › Compare Integrators, added by MainWindow with one call so that its own code stays small.

#include "view/integrator_ghosts_dock.h"

#include "controller/integrator_comparison.h"
#include "view/canvas_view.h"
#include "view/ghost_constants.h"
#include "view/integrator_ghosts.h"
#include "view/main_window.h"
#include "view/number_text.h"
#include "view/timeline.h"

#include <QAction>
#include <QChart>
#include <QChartView>
#include <QDockWidget>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QLocale>
#include <QLogValueAxis>
#include <QMenu>
#include <QPen>
#include <QSignalBlocker>
#include <QSlider>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace impetus::view {

namespace {

constexpr int kEnergyColumn = 0;
constexpr int kPositionColumn = 1;
constexpr std::size_t kIntegratorCount = controller::kComparedIntegrators.size();

/// Millimetres per metre.
constexpr double kMillimetres = 1000.0;
/// Per cent per unit.
constexpr double kPercent = 100.0;
/// Significant digits of the readout: enough to check a number against its formula by eye.
constexpr int kReadoutDigits = 4;
/// The chart's least height, px: room for its title, legend and a few labelled decades.
constexpr int kChartMinHeight = 260;
/// The most labels on the error axis: as many as its least height has room for.
constexpr double kMaxErrorLabels = 5;

/// The slider notch whose time step is nearest `h` on a log scale.
int nearestNotch(double h)
{
    int best = 0;
    for (int i = 1; i < static_cast<int>(constants::kGhostTimeSteps.size()); ++i) {
        if (std::abs(std::log(constants::kGhostTimeSteps[static_cast<std::size_t>(i)] / h)) <
            std::abs(std::log(constants::kGhostTimeSteps[static_cast<std::size_t>(best)] / h)))
            best = i;
    }
    return best;
}

/// Closes with the dock's own close button: the action that opened it goes off.
class DockCloseWatcher : public QObject {
public:
    DockCloseWatcher(QDockWidget& dock, QAction& action)
        : QObject(&dock)
        , m_action(action)
    {
        dock.installEventFilter(this);
    }

protected:
    bool eventFilter(QObject*, QEvent* event) override
    {
        if (event->type() == QEvent::Close)
            m_action.setChecked(false);
        return false;
    }

private:
    QAction& m_action;
};

} // namespace

std::optional<double> logLogSlope(const std::vector<double>& x, const std::vector<double>& y)
{
    const std::size_t n = std::min(x.size(), y.size());
    if (n < 2)
        return std::nullopt;
    double mx = 0;
    double my = 0;
    for (std::size_t i = 0; i < n; ++i) {
        mx += std::log(x[i]);
        my += std::log(y[i]);
    }
    mx /= static_cast<double>(n);
    my /= static_cast<double>(n);
    double sxy = 0;
    double sxx = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double dx = std::log(x[i]) - mx;
        sxy += dx * (std::log(y[i]) - my);
        sxx += dx * dx;
    }
    if (sxx == 0)
        return std::nullopt;
    return sxy / sxx;
}

IntegratorGhostsPanel::IntegratorGhostsPanel(IntegratorGhosts& ghosts, QWidget* parent)
    : QWidget(parent)
    , m_ghosts(ghosts)
{
    auto* layout = new QVBoxLayout(this);

    m_table = new QTableWidget(static_cast<int>(kIntegratorCount), 2, this);
    m_table->setObjectName(QStringLiteral("ghostReadout"));
    m_table->setHorizontalHeaderLabels({tr("Energy error"), tr("Position error")});
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_table->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->setToolTip(tr("Energy error: (E − E₀)/|E₀|. Position error: the largest distance of a body from "
                           "the textbook solution."));
    for (std::size_t i = 0; i < kIntegratorCount; ++i) {
        auto* name = new QTableWidgetItem(QStringLiteral("■ ") + ghostIntegratorName(i));
        name->setForeground(ghostColor(i));
        m_table->setVerticalHeaderItem(static_cast<int>(i), name);
        for (const int column : {kEnergyColumn, kPositionColumn})
            m_table->setItem(static_cast<int>(i), column, new QTableWidgetItem);
    }
    // Three rows always: the table is as tall as they are, with no scroll bar.
    m_table->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_table->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_table->resizeRowsToContents();
    int tableHeight = m_table->horizontalHeader()->sizeHint().height() + 2 * m_table->frameWidth();
    for (int row = 0; row < m_table->rowCount(); ++row)
        tableHeight += m_table->rowHeight(row);
    m_table->setFixedHeight(tableHeight);
    layout->addWidget(m_table);

    m_analytic = new QLabel(this);
    m_analytic->setObjectName(QStringLiteral("ghostAnalytic"));
    m_analytic->setWordWrap(true);
    layout->addWidget(m_analytic);
    m_clock = new QLabel(this);
    m_clock->setObjectName(QStringLiteral("ghostClock"));
    layout->addWidget(m_clock);

    auto* stepRow = new QHBoxLayout;
    auto* stepName = new QLabel(tr("Ghosts' time step h:"), this);
    stepRow->addWidget(stepName);
    m_slider = new QSlider(Qt::Horizontal, this);
    m_slider->setObjectName(QStringLiteral("ghostTimeStepSlider"));
    m_slider->setRange(0, static_cast<int>(constants::kGhostTimeSteps.size()) - 1);
    m_slider->setPageStep(1);
    m_slider->setTickPosition(QSlider::TicksBelow);
    m_slider->setAccessibleName(tr("Ghosts' time step"));
    m_slider->setToolTip(tr("The ghosts' fixed time step, from 1/1000 s (left) to 1/30 s (right)"));
    stepName->setBuddy(m_slider);
    stepRow->addWidget(m_slider, 1);
    m_stepLabel = new QLabel(this);
    m_stepLabel->setObjectName(QStringLiteral("ghostTimeStepLabel"));
    stepRow->addWidget(m_stepLabel);
    layout->addLayout(stepRow);

    m_chart = new QChart;
    m_chart->setTitle(tr("Largest position error in %1 s against the time step")
                          .arg(QLocale().toString(constants::kGhostErrorRunSeconds)));
    m_axisH = new QLogValueAxis;
    m_axisH->setTitleText(tr("time step h (s)"));
    m_axisH->setLabelFormat(QStringLiteral("%.0e"));
    // Whole decades, so that the log axis's labels fall on round numbers.
    m_axisH->setRange(std::pow(10.0, std::floor(std::log10(constants::kGhostTimeSteps.front()))),
                      std::pow(10.0, std::ceil(std::log10(constants::kGhostTimeSteps.back()))));
    m_axisError = new QLogValueAxis;
    m_axisError->setTitleText(tr("position error (m)"));
    m_axisError->setLabelFormat(QStringLiteral("%.0e"));
    m_chart->addAxis(m_axisH, Qt::AlignBottom);
    m_chart->addAxis(m_axisError, Qt::AlignLeft);
    for (std::size_t i = 0; i < kIntegratorCount; ++i) {
        m_lines[i] = new QLineSeries;
        m_lines[i]->setName(ghostIntegratorName(i));
        m_lines[i]->setColor(ghostColor(i));
        m_lines[i]->setPointsVisible(true);
        m_chart->addSeries(m_lines[i]);
        m_lines[i]->attachAxis(m_axisH);
        m_lines[i]->attachAxis(m_axisError);
    }
    m_marker = new QLineSeries;
    m_marker->setName(tr("ghosts' h"));
    QPen markerPen(Qt::gray);
    markerPen.setStyle(Qt::DashLine);
    m_marker->setPen(markerPen);
    m_chart->addSeries(m_marker);
    m_marker->attachAxis(m_axisH);
    m_marker->attachAxis(m_axisError);
    // The dashed line is explained by the slider beside it; the legend names the methods only.
    for (QLegendMarker* marker : m_chart->legend()->markers(m_marker))
        marker->setVisible(false);
    m_chartView = new QChartView(m_chart, this);
    m_chartView->setObjectName(QStringLiteral("ghostErrorChart"));
    m_chartView->setRenderHint(QPainter::Antialiasing);
    m_chartView->setMinimumHeight(kChartMinHeight);
    layout->addWidget(m_chartView, 1);
    m_slopeLabel = new QLabel(this);
    m_slopeLabel->setObjectName(QStringLiteral("ghostSlopes"));
    m_slopeLabel->setWordWrap(true);
    layout->addWidget(m_slopeLabel);

    connect(m_slider, &QSlider::valueChanged, this, [this](int notch) {
        m_ghosts.setTimeStep(constants::kGhostTimeSteps.at(static_cast<std::size_t>(notch)));
    });
    connect(&m_ghosts, &IntegratorGhosts::restarted, this, &IntegratorGhostsPanel::onRestarted);
    connect(&m_ghosts, &IntegratorGhosts::advanced, this, &IntegratorGhostsPanel::updateReadout);
    onRestarted();
}

std::vector<std::pair<double, double>> IntegratorGhostsPanel::plotted(std::size_t i) const
{
    std::vector<std::pair<double, double>> out;
    for (const QPointF& p : m_lines.at(i)->points())
        out.emplace_back(p.x(), p.y());
    return out;
}

void IntegratorGhostsPanel::onRestarted()
{
    {
        // The slider follows the ghosts' h (the scene's, at first) without setting it again.
        const QSignalBlocker quiet(m_slider);
        m_slider->setValue(nearestNotch(m_ghosts.timeStep() > 0 ? m_ghosts.timeStep() : constants::kGhostTimeSteps.front()));
    }
    m_stepLabel->setText(m_ghosts.timeStep() > 0 ? formatTimeStep(m_ghosts.timeStep()) : QString());
    if (const controller::IntegratorComparison* comparison = m_ghosts.comparison()) {
        if (!m_plottedStart || !(*m_plottedStart == comparison->start()))
            replot(comparison->start());
        switch (comparison->analytic()) {
        case controller::AnalyticKind::Projectile:
            m_analytic->setText(tr("Analytic solution: free flight, x = x₀ + v₀t + ½gt², until the first contact."));
            break;
        case controller::AnalyticKind::Spring:
            m_analytic->setText(tr("Analytic solution: a mass on a spring, x = x_eq + (x₀ − x_eq)·cos ωt + "
                                   "(v₀/ω)·sin ωt, ω = √(k/m)."));
            break;
        case controller::AnalyticKind::Pendulum:
            m_analytic->setText(tr("Analytic solution: a pendulum at any amplitude, sin(θ/2) = k·sn(ω₀t + u₀, k), "
                                   "ω₀ = √(g/L), until the first contact."));
            break;
        case controller::AnalyticKind::None:
            m_analytic->setText(tr("No analytic solution for this scene: only the energy errors can be compared."));
            break;
        }
        // The engine moves a body that a joint holds by semi-implicit Euler whatever the scene's
        // integrator (docs/physics.md, "Collisions and contacts", step 5): said here, or the ghosts lying on one another
        // would look like a fault.
        if (!comparison->start().joints.empty()) {
            m_analytic->setText(m_analytic->text() + QLatin1Char(' ') +
                                tr("Bodies held by joints move by semi-implicit Euler whichever integrator is "
                                   "chosen, so their ghosts lie on one another."));
        }
    }
    moveMarker();
    updateReadout();
}

void IntegratorGhostsPanel::updateReadout()
{
    const controller::IntegratorComparison* comparison = m_ghosts.comparison();
    // In the window's number format ("0,25" in German), as the status bar.
    const QLocale locale;
    for (std::size_t i = 0; i < kIntegratorCount; ++i) {
        QString energy;
        QString position;
        if (comparison && comparison->diverged(i)) {
            energy = tr("diverged at t = %1 s")
                         .arg(locale.toString(comparison->world(i).time - comparison->start().time, 'f', 3));
            position = tr("diverged");
        } else if (comparison) {
            energy = tr("%1 %").arg(localeNumber(kPercent * comparison->energyError(i), 'g', kReadoutDigits));
            if (comparison->energyError(i) > 0)
                energy.prepend(QLatin1Char('+'));
            if (const std::optional<Scalar> error = comparison->positionError(i))
                position = tr("%1 mm").arg(localeNumber(kMillimetres * *error, 'g', kReadoutDigits));
            else if (comparison->analytic() != controller::AnalyticKind::None)
                position = tr("no analytic solution after a contact");
            else
                position = tr("no analytic solution");
        }
        m_table->item(static_cast<int>(i), kEnergyColumn)->setText(energy);
        m_table->item(static_cast<int>(i), kPositionColumn)->setText(position);
    }
    if (comparison) {
        const double t = static_cast<double>(m_ghosts.steps()) * m_ghosts.timeStep();
        m_clock->setText(tr("Ghosts at t = %1 s after their start: n = %2 steps of h = %3%4")
                             .arg(locale.toString(t, 'f', 3), locale.toString(m_ghosts.steps()),
                                  formatTimeStep(m_ghosts.timeStep()),
                                  m_ghosts.caughtUp() ? QString() : tr(" (catching up)")));
    } else {
        m_clock->clear();
    }
}

void IntegratorGhostsPanel::replot(const model::World& start)
{
    m_plottedStart = start;
    const std::vector<Scalar> steps(constants::kGhostTimeSteps.begin(), constants::kGhostTimeSteps.end());
    const std::vector<controller::StepError> errors =
        controller::errorAgainstStep(start, steps, constants::kGhostErrorRunSeconds);
    m_errorLow = 0;
    m_errorHigh = 0;
    QStringList slopes;
    for (std::size_t i = 0; i < kIntegratorCount; ++i) {
        QList<QPointF> points;
        std::vector<double> hs;
        std::vector<double> es;
        for (const controller::StepError& e : errors) {
            // Rounding is no method's error (and a log axis has no zero): left off.
            if (e.positionError[i] < constants::kGhostRoundingFloor)
                continue;
            points << QPointF(e.timeStep, e.positionError[i]);
            hs.push_back(e.timeStep);
            es.push_back(e.positionError[i]);
            m_errorLow = m_errorLow == 0 ? es.back() : std::min(m_errorLow, es.back());
            m_errorHigh = std::max(m_errorHigh, es.back());
        }
        m_lines[i]->replace(points);
        m_slopes[i] = logLogSlope(hs, es);
        if (m_slopes[i]) {
            slopes << tr("%1 %2").arg(ghostIntegratorName(i), QLocale().toString(*m_slopes[i], 'f', 2));
        } else if (!errors.empty()) {
            slopes << tr("%1 exact to rounding").arg(ghostIntegratorName(i));
        }
    }
    if (errors.empty()) {
        m_slopeLabel->setText(tr("No analytic solution for this scene: no error to plot."));
    } else {
        m_slopeLabel->setText(tr("Fitted slopes (the method's order): %1").arg(slopes.join(tr(", "))));
    }
    if (m_errorHigh > 0) {
        // Whole decades, so that the log axis's labels fall on round numbers; and a label every
        // few decades when the errors span many (RK4's are far below the Eulers'), so that the
        // labels have room to be read.
        const double low = std::floor(std::log10(m_errorLow));
        const double decades = std::max(1.0, std::ceil(std::log10(m_errorHigh)) - low);
        const double perLabel = std::ceil(decades / kMaxErrorLabels);
        m_axisError->setBase(std::pow(10.0, perLabel));
        m_axisError->setRange(std::pow(10.0, low), std::pow(10.0, low + perLabel * std::ceil(decades / perLabel)));
    }
}

void IntegratorGhostsPanel::moveMarker()
{
    const double h = m_ghosts.timeStep();
    if (h > 0 && m_errorHigh > 0)
        m_marker->replace(QList<QPointF>{QPointF(h, m_axisError->min()), QPointF(h, m_axisError->max())});
    else
        m_marker->clear();
}

void addIntegratorGhosts(MainWindow& window)
{
    auto* ghosts = new IntegratorGhosts(window.canvas(), window.runner(), window.timeline(), &window);
    ghosts->setObjectName(QStringLiteral("integratorGhosts"));

    auto* dock = new QDockWidget(IntegratorGhostsPanel::tr("Integrator Ghosts"), &window);
    dock->setObjectName(QStringLiteral("integratorGhostsDock"));
    dock->setWidget(new IntegratorGhostsPanel(*ghosts, dock));
    window.addDockWidget(Qt::RightDockWidgetArea, dock);
    dock->hide();

    auto* action = new QAction(IntegratorGhostsPanel::tr("Compare &Integrators"), &window);
    action->setObjectName(QStringLiteral("compareIntegratorsAction"));
    action->setCheckable(true);
    action->setStatusTip(IntegratorGhostsPanel::tr("Run the scene under explicit Euler, semi-implicit Euler and RK4 "
                                                   "beside the real run, drawn as ghosts, with their errors"));
    QObject::connect(action, &QAction::toggled, ghosts, [ghosts, dock](bool on) {
        ghosts->setEnabled(on);
        dock->setVisible(on);
    });
    new DockCloseWatcher(*dock, *action);
    auto* viewMenu = window.findChild<QMenu*>(QStringLiteral("viewMenu"));
    if (viewMenu == nullptr)
        return;
    // Beside the other energy view, the ledger, rather than after the language menu.
    const QList<QAction*> entries = viewMenu->actions();
    const auto ledger = std::find_if(entries.begin(), entries.end(), [](const QAction* entry) {
        return entry->objectName() == QLatin1String("energyLedgerAction");
    });
    if (ledger != entries.end() && ledger + 1 != entries.end())
        viewMenu->insertAction(*(ledger + 1), action);
    else
        viewMenu->addAction(action);
}

} // namespace impetus::view
