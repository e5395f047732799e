#include "view/canvas_view.h"

#include "view/body_item.h"
#include "view/simulation_runner.h"
#include "view/spring_item.h"
#include "view/view_constants.h"

#include <QGraphicsScene>
#include <QPainter>
#include <QResizeEvent>

#include <algorithm>
#include <cmath>

namespace impetus::view {

namespace {

QPointF toQPointF(const Vec2& v) { return QPointF(v.x(), v.y()); }

/// World positions of a spring's two ends.
std::pair<QPointF, QPointF> springEnds(const model::World& world, const model::Spring& spring)
{
    const QPointF a = toQPointF(world.body(spring.bodyA).worldPoint(spring.anchorA));
    const QPointF b = spring.bodyB ? toQPointF(world.body(*spring.bodyB).worldPoint(spring.anchorB))
                                   : toQPointF(spring.anchorB);
    return {a, b};
}

/// Grid spacing, m: the first of 1, 2, 5 × 10ⁿ that is at least `minimum` metres.
struct GridSpacing {
    double spacing = 1; ///< m between neighbouring lines
    int linesPerMajor = 5; ///< every this many lines falls on a whole decade
};

GridSpacing gridSpacing(double minimum)
{
    const double decade = std::pow(10.0, std::floor(std::log10(minimum)));
    // 1 → lines every 10ⁿ, a darker one every 5 (graph paper); 2 → every 5th line is 10ⁿ⁺¹;
    // 5 → every 2nd line is 10ⁿ⁺¹.
    if (decade >= minimum)
        return {decade, 5};
    if (2 * decade >= minimum)
        return {2 * decade, 5};
    if (5 * decade >= minimum)
        return {5 * decade, 2};
    return {10 * decade, 5};
}

} // namespace

CanvasView::CanvasView(const SimulationRunner& runner, QWidget* parent)
    : QGraphicsView(parent)
    , m_runner(runner)
    , m_scene(new QGraphicsScene(this))
{
    // Every item moves every frame, so a BSP index would be rebuilt constantly for nothing.
    m_scene->setItemIndexMethod(QGraphicsScene::NoIndex);
    setScene(m_scene);
    setRenderHint(QPainter::Antialiasing);
    setFrameShape(QFrame::NoFrame);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    setTransformationAnchor(QGraphicsView::AnchorViewCenter);
    setResizeAnchor(QGraphicsView::AnchorViewCenter);
    setAccessibleName(tr("Simulation canvas"));
    setAccessibleDescription(tr("The bodies and springs of the scene, in metres, y up"));

    connect(&m_runner, &SimulationRunner::worldChanged, this, &CanvasView::rebuildItems);
    connect(&m_runner, &SimulationRunner::stepped, this, &CanvasView::syncItems);
    rebuildItems();
}

BodyItem* CanvasView::bodyItem(model::BodyId id) const
{
    return id.index < m_bodyItems.size() ? m_bodyItems[id.index] : nullptr;
}

double CanvasView::pixelsPerMetre() const { return std::abs(transform().m11()); }

void CanvasView::rebuildItems()
{
    m_scene->clear();
    m_bodyItems.clear();
    m_springItems.clear();

    const model::World& world = m_runner.world();
    m_bodyItems.reserve(world.bodies.size());
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        const model::BodyId id{static_cast<std::uint32_t>(i)};
        auto* item = new BodyItem(id, world.bodies[i]);
        m_scene->addItem(item);
        m_bodyItems.push_back(item);
    }
    m_springItems.reserve(world.springs.size());
    for (const model::Spring& spring : world.springs) {
        auto* item = new SpringItem(spring.restLength);
        const auto [a, b] = springEnds(world, spring);
        item->setEnds(a, b);
        m_scene->addItem(item);
        m_springItems.push_back(item);
        if (!spring.bodyB)
            m_scene->addItem(new AnchorItem(b));
    }

    m_frameRect = computeFrameRect();
    // Generous room beyond the framed region: QGraphicsView only centres on points inside the
    // scene rectangle, and without one it would grow with every body that flies away.
    const double padW = constants::kSceneRectPaddingFactor * m_frameRect.width();
    const double padH = constants::kSceneRectPaddingFactor * m_frameRect.height();
    m_scene->setSceneRect(m_frameRect.adjusted(-padW, -padH, padW, padH));
    frameWorld();
}

void CanvasView::syncItems()
{
    const model::World& world = m_runner.world();
    const std::size_t bodies = std::min(world.bodies.size(), m_bodyItems.size());
    for (std::size_t i = 0; i < bodies; ++i) {
        m_bodyItems[i]->setPose(world.bodies[i].state);
        m_bodyItems[i]->setColliding(world.bodies[i].colliding);
    }
    const std::size_t springs = std::min(world.springs.size(), m_springItems.size());
    for (std::size_t i = 0; i < springs; ++i) {
        const auto [a, b] = springEnds(world, world.springs[i]);
        m_springItems[i]->setEnds(a, b);
    }
}

QRectF CanvasView::computeFrameRect() const
{
    QRectF bounds;
    for (const BodyItem* item : m_bodyItems)
        bounds = bounds.united(item->mapToScene(item->shape()).boundingRect());
    for (const SpringItem* item : m_springItems)
        bounds = bounds.united(item->mapToScene(item->boundingRect()).boundingRect());
    if (bounds.isNull()) {
        return QRectF(-constants::kEmptyWorldWidth / 2, -constants::kEmptyWorldHeight / 2,
                      constants::kEmptyWorldWidth, constants::kEmptyWorldHeight);
    }
    const double side = std::max(bounds.width(), bounds.height());
    const double margin = std::max(constants::kMinimumFrameMargin, constants::kFrameMarginFraction * side);
    QRectF framed = bounds.adjusted(-margin, -margin, margin, margin);
    if (framed.width() < constants::kMinimumFrameExtent || framed.height() < constants::kMinimumFrameExtent) {
        const QPointF centre = framed.center();
        framed.setWidth(std::max(framed.width(), constants::kMinimumFrameExtent));
        framed.setHeight(std::max(framed.height(), constants::kMinimumFrameExtent));
        framed.moveCenter(centre);
    }
    return framed;
}

void CanvasView::frameWorld()
{
    const QSize viewportSize = viewport()->size();
    if (viewportSize.isEmpty() || m_frameRect.isEmpty())
        return;
    const double s = std::min(viewportSize.width() / m_frameRect.width(),
                              viewportSize.height() / m_frameRect.height());
    setTransform(QTransform::fromScale(s, -s));
    centerOn(m_frameRect.center());
}

void CanvasView::resizeEvent(QResizeEvent* event)
{
    QGraphicsView::resizeEvent(event);
    if (m_autoFrame)
        frameWorld();
}

void CanvasView::drawBackground(QPainter* painter, const QRectF& rect)
{
    painter->save();
    painter->fillRect(rect, constants::kBackgroundColor);

    const double scale = pixelsPerMetre();
    if (scale > 0 && std::isfinite(scale)) {
        const GridSpacing grid = gridSpacing(constants::kMinimumGridSpacingPx / scale);
        // Crisp one-pixel lines: antialiasing would smear them over two pixel rows.
        painter->setRenderHint(QPainter::Antialiasing, false);
        QPen minorPen(constants::kMinorGridColor, 0);
        QPen majorPen(constants::kMajorGridColor, 0);
        QPen axisPen(constants::kAxisColor, 0);
        const auto penFor = [&](long long index) -> const QPen& {
            if (index == 0)
                return axisPen;
            return index % grid.linesPerMajor == 0 ? majorPen : minorPen;
        };
        const auto first = [&](double from) { return static_cast<long long>(std::ceil(from / grid.spacing)); };
        const auto last = [&](double to) { return static_cast<long long>(std::floor(to / grid.spacing)); };
        // Minor lines first, so that the major lines and axes are drawn over them.
        for (int pass = 0; pass < 2; ++pass) {
            const bool major = pass == 1;
            for (long long i = first(rect.left()); i <= last(rect.right()); ++i) {
                if ((i % grid.linesPerMajor == 0) != major)
                    continue;
                const double x = static_cast<double>(i) * grid.spacing;
                painter->setPen(penFor(i));
                painter->drawLine(QPointF(x, rect.top()), QPointF(x, rect.bottom()));
            }
            for (long long i = first(rect.top()); i <= last(rect.bottom()); ++i) {
                if ((i % grid.linesPerMajor == 0) != major)
                    continue;
                const double y = static_cast<double>(i) * grid.spacing;
                painter->setPen(penFor(i));
                painter->drawLine(QPointF(rect.left(), y), QPointF(rect.right(), y));
            }
        }
    }
    painter->restore();
}

} // namespace impetus::view
