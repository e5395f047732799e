#include "view/integrator_ghosts.h"

#include "view/body_item.h"
#include "view/canvas_view.h"
#include "view/ghost_constants.h"
#include "view/number_text.h"
#include "view/simulation_runner.h"
#include "view/timeline.h"
#include "view/view_constants.h"

#include <QCoreApplication>
#include <QEvent>
#include <QGraphicsObject>
#include <QGraphicsScene>
#include <QLabel>
#include <QLocale>
#include <QPainter>
#include <QPainterPath>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace impetus::view {

/// The three ghosts, drawn in scene coordinates (m, y up) over the real bodies. A QGraphicsObject so
/// that IntegratorGhosts can hold it by QPointer, should anything else delete it (the canvas, when
/// it rebuilds, deletes only its own items).
class GhostItem : public QGraphicsObject {
public:
    explicit GhostItem(const IntegratorGhosts& ghosts)
        : m_ghosts(ghosts)
    {
        setObjectName(QStringLiteral("integratorGhostsItem"));
        setZValue(constants::kGhostZ);
        // The ghosts are a picture, not something to click: the tools see the real bodies.
        setAcceptedMouseButtons(Qt::NoButton);
        setAcceptHoverEvents(false);
    }

    /// The ghosts moved or started again: new bounds, new drawing.
    void refresh()
    {
        const controller::IntegratorComparison* comparison = m_ghosts.comparison();
        if (comparison && m_outlines.size() != comparison->start().bodies.size()) {
            m_outlines.clear();
            for (const model::Body& body : comparison->start().bodies)
                m_outlines.push_back(bodyOutlinePath(body));
        }
        prepareGeometryChange();
        m_bounds = QRectF();
        if (comparison) {
            for (std::size_t i = 0; i < controller::kComparedIntegrators.size(); ++i) {
                // A run that diverged has no place to be drawn at: the readout says so instead.
                if (comparison->diverged(i))
                    continue;
                const model::World& world = comparison->world(i);
                for (const model::Body& body : world.bodies) {
                    if (body.fixed)
                        continue;
                    const Scalar r = body.geometry.boundingRadius;
                    const Vec2 p = body.state.position;
                    m_bounds |= QRectF(p.x() - r, p.y() - r, 2 * r, 2 * r);
                }
                for (const model::Spring& spring : world.springs) {
                    const auto [a, b] = ends(world, spring);
                    m_bounds |= QRectF(QPointF(a.x(), a.y()), QPointF(b.x(), b.y())).normalized();
                }
            }
        }
        // Room for the outline's width, which is in pixels: a few centimetres at any usual zoom.
        const double pad = 0.05 * std::max(1.0, m_bounds.width());
        m_bounds.adjust(-pad, -pad, pad, pad);
        update();
    }

    /// Forgets the outlines: a new start may have other bodies.
    void forgetOutlines() { m_outlines.clear(); }

    QRectF boundingRect() const override { return m_bounds; }

    void paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) override
    {
        const controller::IntegratorComparison* comparison = m_ghosts.comparison();
        if (comparison == nullptr)
            return;
        painter->setRenderHint(QPainter::Antialiasing);
        // RK4 first and explicit Euler last: the ghost nearest the real run lies underneath, the one
        // that strays most on top, where it is seen leaving the others.
        for (std::size_t k = controller::kComparedIntegrators.size(); k-- > 0;) {
            if (comparison->diverged(k))
                continue;
            const model::World& world = comparison->world(k);
            QColor line = ghostColor(k);
            line.setAlpha(constants::kGhostOutlineAlpha);
            QColor fill = ghostColor(k);
            fill.setAlpha(constants::kGhostFillAlpha);
            QPen pen(line, constants::kGhostOutlinePx);
            pen.setCosmetic(true);
            painter->setPen(pen);
            for (const model::Spring& spring : world.springs) {
                const auto [a, b] = ends(world, spring);
                painter->drawLine(QPointF(a.x(), a.y()), QPointF(b.x(), b.y()));
            }
            painter->setBrush(fill);
            for (std::size_t b = 0; b < world.bodies.size() && b < m_outlines.size(); ++b) {
                const model::Body& body = world.bodies[b];
                if (body.fixed)
                    continue;
                QTransform pose;
                pose.translate(body.state.position.x(), body.state.position.y());
                pose.rotateRadians(body.state.angle);
                painter->drawPath(pose.map(m_outlines[b]));
            }
        }
    }

private:
    /// A spring's two ends in the world, m.
    static std::pair<Vec2, Vec2> ends(const model::World& world, const model::Spring& spring)
    {
        const Vec2 a = world.bodies[spring.bodyA.index].worldPoint(spring.anchorA);
        const Vec2 b = spring.bodyB ? world.bodies[spring.bodyB->index].worldPoint(spring.anchorB) : spring.anchorB;
        return {a, b};
    }

    const IntegratorGhosts& m_ghosts;
    std::vector<QPainterPath> m_outlines; ///< per body of the start, body frame
    QRectF m_bounds;
};

namespace {

/// Puts `label` in the top-right corner of `viewport`, at its size for its text.
void placeInCorner(QLabel& label, const QWidget& viewport)
{
    const int margin = static_cast<int>(constants::kLegendMarginPx);
    label.adjustSize();
    label.move(viewport.width() - label.width() - margin, margin);
}

/// Keeps the legend in the viewport's top-right corner as the canvas is resized.
class CornerKeeper : public QObject {
public:
    CornerKeeper(QLabel& label, QWidget& viewport)
        : QObject(&label)
        , m_label(label)
        , m_viewport(viewport)
    {
        viewport.installEventFilter(this);
    }

protected:
    bool eventFilter(QObject*, QEvent* event) override
    {
        if (event->type() == QEvent::Resize)
            placeInCorner(m_label, m_viewport);
        return false;
    }

private:
    QLabel& m_label;
    QWidget& m_viewport;
};

} // namespace

QString ghostIntegratorName(std::size_t i)
{
    switch (i) {
    case 0:
        return QCoreApplication::translate("impetus::view::IntegratorGhosts", "Explicit Euler");
    case 1:
        return QCoreApplication::translate("impetus::view::IntegratorGhosts", "Semi-implicit Euler");
    default:
        return QCoreApplication::translate("impetus::view::IntegratorGhosts", "RK4");
    }
}

QColor ghostColor(std::size_t i) { return constants::kGhostColors.at(i); }

QString formatTimeStep(double h)
{
    const double perSecond = 1.0 / h;
    // A step the slider offers (1/240 s) reads best as a fraction; anything else in milliseconds.
    if (std::abs(perSecond - std::round(perSecond)) < 1e-6 * perSecond)
        return QCoreApplication::translate("impetus::view::IntegratorGhosts", "1/%1 s").arg(std::lround(perSecond));
    return QCoreApplication::translate("impetus::view::IntegratorGhosts", "%1 ms")
        .arg(localeNumber(h * 1000, 'g', 4));
}

IntegratorGhosts::IntegratorGhosts(CanvasView& canvas, const SimulationRunner& runner, Timeline& timeline,
                                   QObject* parent)
    : QObject(parent)
    , m_canvas(canvas)
    , m_runner(runner)
    , m_timeline(timeline)
{
    // Connected after the canvas and the timeline (made before this): the canvas has rebuilt its
    // items and the timeline has booked an edit by the time the ghosts look.
    connect(&m_runner, &SimulationRunner::stepped, this, &IntegratorGhosts::follow);
    connect(&m_runner, &SimulationRunner::worldChanged, this, &IntegratorGhosts::follow);
}

IntegratorGhosts::~IntegratorGhosts()
{
    delete m_item;
    delete m_legend;
}

void IntegratorGhosts::setEnabled(bool on)
{
    if (on == isEnabled())
        return;
    if (!on) {
        m_comparison.reset();
        delete m_item;
        delete m_legend;
        emit restarted();
        return;
    }
    restart();
}

void IntegratorGhosts::setTimeStep(double h)
{
    if (!(h > 0) || h == m_timeStep)
        return;
    m_timeStep = h;
    m_userTimeStep = true;
    if (isEnabled())
        restart();
}

void IntegratorGhosts::restart()
{
    const model::World& start = m_timeline.runStart(m_runner.world().stepCount);
    if (!m_userTimeStep)
        m_timeStep = start.settings.timeStep;
    m_comparison.emplace(start);
    m_comparison->setTimeStep(m_timeStep);
    m_steps = 0;
    if (m_item)
        m_item->forgetOutlines();
    showOnCanvas();
    emit restarted();
    catchUp();
}

void IntegratorGhosts::follow()
{
    if (!isEnabled())
        return;
    showOnCanvas();
    const model::World& start = m_timeline.runStart(m_runner.world().stepCount);
    // A new scene, an edit or a Play from the past with the world changed: a new start.
    if (start.stepCount != m_comparison->start().stepCount || !(start == m_comparison->start())) {
        restart();
        return;
    }
    catchUp();
}

void IntegratorGhosts::catchUp()
{
    m_sliceQueued = false;
    if (!isEnabled())
        return;
    const double elapsed = m_runner.world().time - m_comparison->start().time;
    const auto target = std::max<std::int64_t>(0, std::llround(elapsed / m_timeStep));
    if (target < m_steps) {
        // Back along the timeline: the ghosts have no past, so they run again from the start.
        m_comparison->setTimeStep(m_timeStep);
        m_steps = 0;
    }
    const std::int64_t until = std::min<std::int64_t>(target, m_steps + constants::kGhostCatchUpSlice);
    for (; m_steps < until; ++m_steps)
        m_comparison->step();
    m_behind = m_steps < target;
    if (m_behind && !m_sliceQueued) {
        m_sliceQueued = true;
        QTimer::singleShot(0, this, &IntegratorGhosts::catchUp);
    }
    if (m_item)
        m_item->refresh();
    emit advanced();
}

void IntegratorGhosts::showOnCanvas()
{
    if (!m_item) {
        m_item = new GhostItem(*this);
        m_canvas.scene()->addItem(m_item);
        m_item->refresh();
    }
    if (!m_legend) {
        m_legend = new QLabel(m_canvas.viewport());
        m_legend->setObjectName(QStringLiteral("integratorGhostsLegend"));
        m_legend->setTextFormat(Qt::RichText);
        m_legend->setMargin(static_cast<int>(constants::kLegendPaddingPx));
        m_legend->setAutoFillBackground(true);
        m_legend->setAttribute(Qt::WA_TransparentForMouseEvents);
        new CornerKeeper(*m_legend, *m_canvas.viewport());
        m_legend->show();
    }
    updateLegend();
}

void IntegratorGhosts::updateLegend()
{
    if (!m_legend)
        return;
    QString rows;
    for (std::size_t i = 0; i < controller::kComparedIntegrators.size(); ++i) {
        rows += QStringLiteral("<br><span style=\"color:%1\">■</span> %2")
                    .arg(ghostColor(i).name(), ghostIntegratorName(i).toHtmlEscaped());
    }
    const QString text = tr("Ghosts, h = %1").arg(formatTimeStep(m_timeStep)).toHtmlEscaped() + rows;
    if (text != m_legend->text()) {
        m_legend->setText(text);
        placeInCorner(*m_legend, *m_canvas.viewport());
    }
}

} // namespace impetus::view
