// The collision log and the impulse formula filled in. Every number comes from the engine: the log
// from Simulation::events(), the impact's terms from the contact solver's ImpactRecord, and the
// formula's arithmetic from controller::impactFormula; this file only lays them out.

#include "view/collision_inspector.h"

#include "model/constants.h"
#include "view/explain_constants.h"
#include "view/number_text.h"
#include "view/scene_document.h"
#include "view/simulation_runner.h"
#include "view/timeline.h"

#include <QCoreApplication>
#include <QLabel>
#include <QListWidget>
#include <QLocale>
#include <QSplitter>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace impetus::view {

namespace {

// The inspector's numbers are in the window's number format ("3,75 N·s" in German), as the status
// bar's and the probe's.

/// A number as the formula shows it: six significant digits, ∞ for a fixed body's mass.
QString num(Scalar x)
{
    if (std::isinf(x))
        return QStringLiteral("∞");
    return localeNumber(x, 'g', 6);
}

/// A time in seconds, to the tenth of a millisecond.
QString seconds(double t) { return QLocale().toString(t, 'f', 4); }

QString vec(const Vec2& v)
{
    //: A vector: its x and y. Where the decimal separator is a comma, separate them with a
    //: semicolon: (0,6; -0,8).
    return QCoreApplication::translate("impetus::view::CollisionInspector", "(%1, %2)")
        .arg(num(v.x()), num(v.y()));
}

QString bodyName(const model::World& world, std::uint32_t index)
{
    return index < world.bodies.size() ? QString::fromStdString(world.bodies[index].name).toHtmlEscaped()
                                       : QString::number(index);
}

} // namespace

CollisionInspector::CollisionInspector(SceneDocument& document, Timeline& timeline, QWidget* parent)
    : QWidget(parent)
    , m_document(document)
    , m_timeline(timeline)
    , m_status(new QLabel(this))
    , m_list(new QListWidget(this))
    , m_formula(new QTextBrowser(this))
{
    m_list->setObjectName(QStringLiteral("collisionLog"));
    m_formula->setObjectName(QStringLiteral("impactFormula"));
    m_status->setObjectName(QStringLiteral("collisionLogStatus"));
    m_status->setWordWrap(true);
    auto* splitter = new QSplitter(Qt::Vertical, this);
    splitter->addWidget(m_list);
    splitter->addWidget(m_formula);
    // The formula needs the room; a few rows of the log are enough to pick from.
    splitter->setStretchFactor(0, 1);
    splitter->setStretchFactor(1, 4);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_status);
    layout->addWidget(splitter, 1);

    connect(m_list, &QListWidget::currentRowChanged, this, [this](int row) {
        if (row >= 0)
            select(row);
    });
    SimulationRunner& runner = m_document.runner();
    const auto refreshIfShown = [this] {
        if (isVisible())
            refresh();
    };
    connect(&runner, &SimulationRunner::runningChanged, this, refreshIfShown);
    connect(&m_document, &SceneDocument::stepped, this, refreshIfShown);
    connect(&m_document, &SceneDocument::sceneReplaced, this, [this] {
        clearLog();
        if (isVisible())
            refresh();
    });
    connect(&m_timeline, &Timeline::futureDiscarded, this, &CollisionInspector::forgetAfter);
}

void CollisionInspector::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    refresh();
}

void CollisionInspector::clearLog()
{
    m_world.reset();
    m_entries.clear();
    m_selected.reset();
    rebuildList();
    m_formula->clear();
}

void CollisionInspector::forgetAfter(std::int64_t step)
{
    // The states after `step` are no longer the run, and the state at `step` itself may have been
    // edited: what was logged up to it stays, the replay starts again from it.
    std::erase_if(m_entries, [step](const CollisionLogEntry& e) { return e.step > step; });
    if (m_world && m_world->stepCount >= step)
        m_world.reset();
    if (m_selected && *m_selected >= static_cast<int>(m_entries.size())) {
        m_selected.reset();
        m_formula->clear();
    }
    rebuildList();
}

void CollisionInspector::refresh()
{
    if (m_document.runner().isRunning()) {
        m_status->setText(tr("Pause the run to bring the log up to date."));
        return;
    }
    const std::int64_t current = m_timeline.currentStep();
    const std::int64_t earliest = std::max(m_timeline.firstStep(), current - constants::kCollisionLogMaxReplaySteps);
    if (!m_world || m_world->stepCount < earliest) {
        // Start from the newest state already logged, or the earliest the log covers.
        const std::int64_t from = std::max(earliest, m_entries.empty() ? earliest : m_entries.back().step);
        std::erase_if(m_entries, [from](const CollisionLogEntry& e) { return e.step > from; });
        m_world = m_timeline.stateAt(from);
    }
    m_simulation.setImpactLog(&m_impacts);
    bool added = false;
    while (m_world->stepCount < current) {
        m_impacts.clear();
        m_simulation.step(*m_world);
        for (const controller::CollisionEvent& event : m_simulation.events()) {
            CollisionLogEntry entry{m_world->stepCount, event, {}};
            for (const controller::ImpactRecord& impact : m_impacts) {
                const bool samePair = (impact.ownerA == event.bodyA.index && impact.ownerB == event.bodyB.index) ||
                                      (impact.ownerA == event.bodyB.index && impact.ownerB == event.bodyA.index);
                if (samePair)
                    entry.impacts.push_back(impact);
            }
            m_entries.push_back(std::move(entry));
            added = true;
        }
    }
    m_simulation.setImpactLog(nullptr);
    if (m_entries.size() > static_cast<std::size_t>(constants::kCollisionLogMaxEntries)) {
        const auto excess = static_cast<std::ptrdiff_t>(m_entries.size()) - constants::kCollisionLogMaxEntries;
        m_entries.erase(m_entries.begin(), m_entries.begin() + excess);
        m_selected.reset();
        added = true;
    }
    if (added)
        rebuildList();
    m_status->setText(m_entries.empty() ? tr("No collisions yet. Run or step the scene, then pause.")
                                        : tr("%n collision(s). Click one to see its impulse.", nullptr,
                                             static_cast<int>(m_entries.size())));
}

void CollisionInspector::rebuildList()
{
    const QSignalBlocker blocker(m_list);
    m_list->clear();
    const model::World& world = m_document.world();
    for (const CollisionLogEntry& entry : m_entries) {
        const QString impulse = num(entry.event.normalImpulse);
        m_list->addItem(tr("t = %1 s: %2 and %3, impulse %4 N·s")
                            .arg(seconds(entry.event.time))
                            .arg(QString::fromStdString(entry.event.bodyA.index < world.bodies.size()
                                                            ? world.bodies[entry.event.bodyA.index].name
                                                            : std::string()))
                            .arg(QString::fromStdString(entry.event.bodyB.index < world.bodies.size()
                                                            ? world.bodies[entry.event.bodyB.index].name
                                                            : std::string()))
                            .arg(impulse));
    }
    if (m_selected)
        m_list->setCurrentRow(*m_selected);
}

void CollisionInspector::select(int index)
{
    if (index < 0 || index >= static_cast<int>(m_entries.size()))
        return;
    m_selected = index;
    if (m_list->currentRow() != index) {
        const QSignalBlocker blocker(m_list);
        m_list->setCurrentRow(index);
    }
    m_formula->setHtml(formulaHtml(m_entries[static_cast<std::size_t>(index)]));
}

std::optional<controller::ImpactFormula> CollisionInspector::selectedFormula() const
{
    if (!m_selected)
        return std::nullopt;
    const CollisionLogEntry& entry = m_entries[static_cast<std::size_t>(*m_selected)];
    if (entry.impacts.empty())
        return std::nullopt;
    return controller::impactFormula(entry.impacts.front());
}

QString CollisionInspector::formulaText() const { return m_formula->toPlainText(); }

QString CollisionInspector::formulaHtml(const CollisionLogEntry& entry) const
{
    const model::World& world = m_document.world();
    const controller::CollisionEvent& event = entry.event;
    QString html = tr("<h3>%1 and %2 at t = %3 s</h3>")
                       .arg(bodyName(world, event.bodyA.index), bodyName(world, event.bodyB.index),
                            seconds(event.time));
    html += tr("<p>Normal n = %1 (from %2 to %3). Total normal impulse this step, as logged: <b>%4 N·s</b>; "
               "relative normal speed %5 m/s before, %6 m/s after the step.</p>")
                .arg(vec(event.normal), bodyName(world, event.bodyA.index), bodyName(world, event.bodyB.index),
                     num(event.normalImpulse), num(event.normalSpeedBefore), num(event.normalSpeedAfter));
    if (entry.impacts.empty()) {
        html += tr("<p>No impact: the bodies met slower than the restitution threshold (%1 m/s), or were "
                   "already touching, so the contact forces alone stopped the approach. No bounce, e plays "
                   "no part.</p>")
                    .arg(num(impetus::constants::kRestitutionThreshold));
        return html;
    }
    int number = 0;
    for (const controller::ImpactRecord& impact : entry.impacts) {
        ++number;
        const controller::ImpactFormula f = controller::impactFormula(impact);
        if (entry.impacts.size() > 1)
            html += tr("<h4>Impact %1 of %2</h4>").arg(number).arg(entry.impacts.size());
        html += tr("<p>m<sub>A</sub> = %1 kg, 1/I<sub>A</sub> = %2 1/(kg·m²); m<sub>B</sub> = %3 kg, "
                   "1/I<sub>B</sub> = %4 1/(kg·m²); e = %5, μ = %6</p>")
                    .arg(num(f.massA), num(f.invInertiaA), num(f.massB), num(f.invInertiaB), num(f.restitution),
                         num(f.friction));
        for (int i = 0; i < f.count; ++i) {
            const controller::ImpactFormulaPoint& p = f.points[static_cast<std::size_t>(i)];
            const controller::ImpactPointRecord& r = impact.points[static_cast<std::size_t>(i)];
            if (f.count > 1)
                html += tr("<p><b>Point %1</b></p>").arg(i + 1);
            html += tr("<p>r<sub>A</sub> = %1 m, r<sub>B</sub> = %2 m; r<sub>A</sub>×n = %3 m, r<sub>B</sub>×n = %4 m<br>"
                       "relative normal speed before v<sub>n</sub> = %5 m/s</p>")
                        .arg(vec(r.rA), vec(r.rB), num(p.rnA), num(p.rnB), num(p.approachSpeed));
            const QString e = p.bounces ? num(f.restitution) : QStringLiteral("0");
            html += tr("<p>j = −(1 + e)·v<sub>n</sub> / (1/m<sub>A</sub> + 1/m<sub>B</sub> + (r<sub>A</sub>×n)²/I<sub>A</sub> "
                       "+ (r<sub>B</sub>×n)²/I<sub>B</sub>)<br>"
                       "&nbsp;&nbsp;= −(1 + %1)·(%2) / (%3 + %4 + (%5)²·%6 + (%7)²·%8)<br>"
                       "&nbsp;&nbsp;= −(1 + %1)·(%2) / %9 = <b>%10 N·s</b></p>")
                        .arg(e, num(p.approachSpeed), num(impact.beforeA.invMass), num(impact.beforeB.invMass),
                             num(p.rnA), num(f.invInertiaA), num(p.rnB), num(f.invInertiaB), num(p.denominator))
                        .arg(num(p.formulaImpulse));
            if (!p.bounces)
                html += tr("<p>|v<sub>n</sub>| is below the restitution threshold (%1 m/s): the impulse only stops "
                           "the approach, e counts as 0.</p>")
                            .arg(num(impetus::constants::kRestitutionThreshold));
            if (f.count > 1)
                html += tr("<p>Two points struck at once: the engine solves K·j = −(1 + e)·v<sub>n</sub> for both "
                           "together, K = [[%1, %2], [%3, %4]] 1/kg, and applied <b>%5 N·s</b> here (the formula "
                           "above is this point alone).</p>")
                            .arg(num(impact.k[0][0]), num(impact.k[0][1]), num(impact.k[1][0]), num(impact.k[1][1]),
                                 num(p.engineImpulse));
            else
                html += tr("<p>The engine applied %1 N·s.</p>").arg(num(p.engineImpulse));
            html += tr("<p>Normal speed after: v<sub>n</sub>′ = %1 m/s (−e·v<sub>n</sub> = %2 m/s)</p>")
                        .arg(num(p.speedAfter), num(r.targetSpeed));
            html += tr("<p>Friction: tangential speed v<sub>t</sub> = %1 m/s; stopping it needs −v<sub>t</sub>/K<sub>t</sub> "
                       "= %2 N·s with K<sub>t</sub> = %3 1/kg; the limit μ·j = %4 N·s; applied %5 N·s: <b>%6</b></p>")
                        .arg(num(p.tangentSpeed), num(p.frictionNeeded), num(p.tangentDenominator),
                             num(p.frictionLimit), num(p.frictionImpulse),
                             p.slid ? tr("it slid (friction at its limit)") : tr("it stuck (sliding stopped)"));
        }
        html += tr("<p>Momentum of the pair: %1 → %2 kg·m/s<br>Kinetic energy of the pair: %3 → %4 J (%5 J)</p>")
                    .arg(vec(f.before.momentum), vec(f.after.momentum), num(f.before.energy), num(f.after.energy),
                         num(f.after.energy - f.before.energy));
        if (std::isinf(f.massA) || std::isinf(f.massB))
            html += tr("<p>A fixed body takes any momentum: the pair's momentum changes by the impulse.</p>");
    }
    return html;
}

} // namespace impetus::view
