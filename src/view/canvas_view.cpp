#include "view/canvas_view.h"

#include "controller/soft/soft_body_shape.h"

#include "view/body_item.h"
#include "view/body_stamps.h"
#include "view/canvas_instruments.h"
#include "view/soft_detail_item.h"
#include "view/joint_item.h"
#include "view/scene_document.h"
#include "view/simulation_runner.h"
#include "view/spring_item.h"
#include "view/tools/drag_shape_tools.h"
#include "view/tools/joint_tool.h"
#include "view/tools/measure_tools.h"
#include "view/tools/polygon_tool.h"
#include "view/tools/probe_tool.h"
#include "view/tools/trace_point_tool.h"
#include "view/tools/rotate_tool.h"
#include "view/tools/select_tool.h"
#include "view/tools/spring_tool.h"
#include "view/view_constants.h"

#include <QGraphicsScene>
#include <QImage>
#include <QKeyEvent>
#include <QLineF>
#include <QMouseEvent>
#include <QPainter>
#include <QResizeEvent>
#include <QScrollBar>
#include <QToolTip>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace impetus::view {

namespace {

/// World positions of a spring's two ends.
std::pair<QPointF, QPointF> springEnds(const model::World& world, const model::Spring& spring)
{
    const QPointF a = toQPointF(world.body(spring.bodyA).worldPoint(spring.anchorA));
    const QPointF b = spring.bodyB ? toQPointF(world.body(*spring.bodyB).worldPoint(spring.anchorB))
                                   : toQPointF(spring.anchorB);
    return {a, b};
}

/// World positions of a joint's two ends: for a pin both are the hinge as body A carries it.
std::pair<QPointF, QPointF> jointEnds(const model::World& world, const model::Joint& joint)
{
    const QPointF a = toQPointF(world.body(joint.bodyA).worldPoint(joint.anchorA));
    if (joint.type == model::JointType::Pin)
        return {a, a};
    const QPointF b = joint.bodyB ? toQPointF(world.body(*joint.bodyB).worldPoint(joint.anchorB))
                                  : toQPointF(joint.anchorB);
    return {a, b};
}

/// Grid spacing, m: the first of 1, 2, 5 × 10ⁿ that is at least `minimum` metres.
struct GridSpacing {
    double spacing = 1; ///< m between neighbouring lines
    int linesPerMajor = 5; ///< every this many lines falls on a whole decade
};

GridSpacing gridSpacingFor(double minimum)
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

/// Distance from `p` to the segment a–b.
double distanceToSegment(const QPointF& p, const QPointF& a, const QPointF& b)
{
    const QPointF ab = b - a;
    const double lengthSquared = QPointF::dotProduct(ab, ab);
    const double t = lengthSquared > 0 ? std::clamp(QPointF::dotProduct(p - a, ab) / lengthSquared, 0.0, 1.0) : 0.0;
    return QLineF(p, a + t * ab).length();
}

/// A grid value as a label: "0", "2 m", "0.5 m", "−1e+03 m" for extreme zooms.
QString gridLabel(double value, double spacing)
{
    if (std::abs(value) < spacing / 2)
        return QStringLiteral("0");
    // As many decimals as the spacing needs, and no more: 0.05 m spacing shows "0.15 m".
    const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(spacing) - 1e-9)), 0, 6);
    return CanvasView::tr("%L1 m").arg(value, 0, 'f', decimals);
}

} // namespace

CanvasView::CanvasView(const SimulationRunner& runner, QWidget* parent)
    : QGraphicsView(parent)
    , m_runner(runner)
    , m_scene(new QGraphicsScene(this))
    , m_instruments(new CanvasInstruments(runner, this))
    , m_stamps(std::make_unique<BodyStamps>())
{
    // Every item moves every frame, so a BSP index would be rebuilt constantly for nothing.
    m_scene->setItemIndexMethod(QGraphicsScene::NoIndex);
    setScene(m_scene);
    setRenderHint(QPainter::Antialiasing);
    setFrameShape(QFrame::NoFrame);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    // Zoom keeps its own anchor (the cursor); a resize keeps the centre.
    setTransformationAnchor(QGraphicsView::NoAnchor);
    setResizeAnchor(QGraphicsView::AnchorViewCenter);
    // The overlay of a tool (rubber band, shape being drawn) moves with the mouse anywhere.
    setViewportUpdateMode(QGraphicsView::FullViewportUpdate);
    setMouseTracking(true);
    setFocusPolicy(Qt::StrongFocus);
    setAccessibleName(tr("Simulation canvas"));
    setAccessibleDescription(tr("The bodies, springs and joints of the scene, in metres, y up"));

    connect(&m_runner, &SimulationRunner::worldChanged, this, &CanvasView::rebuildItems);
    connect(&m_runner, &SimulationRunner::sceneReplaced, this, &CanvasView::frameScene);
    connect(&m_runner, &SimulationRunner::stepped, this, &CanvasView::syncItems);
    connect(&m_runner, &SimulationRunner::sampled, m_instruments, &CanvasInstruments::addSamples);
    connect(&m_runner, &SimulationRunner::stepped, m_instruments, &CanvasInstruments::refresh);
    connect(&m_runner, &SimulationRunner::worldChanged, m_instruments, &CanvasInstruments::refresh);
    connect(&m_runner, &SimulationRunner::sceneReplaced, m_instruments, &CanvasInstruments::clear);
    connect(m_instruments, &CanvasInstruments::changed, viewport(), [this] { viewport()->update(); });
    // The background layer holds the trails in the bodies' colours as they were drawn: an edit or
    // a state shown from the timeline paints it whole; steps only add the trails' growth
    // (updateBackgroundLayer()), and once no new state came for a moment it is painted whole, so
    // that the canvas at rest shows exactly what a whole paint shows.
    connect(&m_runner, &SimulationRunner::worldChanged, this, [this] { m_layerDirty = true; });
    m_layerSettle.setSingleShot(true);
    m_layerSettle.setInterval(constants::kLayerSettleMs);
    connect(&m_layerSettle, &QTimer::timeout, this, [this] {
        // A run slower than the settling time (a heavy scene, a busy machine) would otherwise
        // paint the layer whole between every two states: wait for it to stop.
        if (m_runner.isRunning()) {
            m_layerSettle.start();
            return;
        }
        if (m_layerGrown) {
            m_layerDirty = true;
            viewport()->update();
        }
    });
    rebuildItems();
    frameScene();
}

CanvasView::~CanvasView() = default;

void CanvasView::setDocument(SceneDocument& document)
{
    m_document = &document;
    m_tools.clear();
    m_tools.push_back(std::make_unique<SelectTool>(document, *this));
    m_tools.push_back(std::make_unique<RotateTool>(document, *this));
    m_tools.push_back(std::make_unique<PolygonTool>(document, *this));
    m_tools.push_back(std::make_unique<BoxTool>(document, *this));
    m_tools.push_back(std::make_unique<CircleTool>(document, *this));
    m_tools.push_back(std::make_unique<EllipseTool>(document, *this));
    m_tools.push_back(std::make_unique<SpringTool>(document, *this));
    m_tools.push_back(std::make_unique<JointTool>(document, *this, model::JointType::Pin));
    m_tools.push_back(std::make_unique<JointTool>(document, *this, model::JointType::Rod));
    m_tools.push_back(std::make_unique<RulerTool>(document, *this));
    m_tools.push_back(std::make_unique<ProtractorTool>(document, *this));
    m_tools.push_back(std::make_unique<ProbeTool>(document, *this));
    m_tools.push_back(std::make_unique<TracePointTool>(document, *this));
    m_tool = m_tools.front().get();
    viewport()->setCursor(m_tool->cursorShape());
    connect(m_document, &SceneDocument::selectionChanged, this, &CanvasView::showSelection);
    connect(m_document, &SceneDocument::selectionChanged, m_instruments,
            [this] { m_instruments->setSelection(m_document->selection()); });
    connect(m_document, &SceneDocument::sceneReplaced, this, [this] {
        if (m_tool)
            m_tool->cancel();
    });
    showSelection();
}

BodyItem* CanvasView::bodyItem(model::BodyId id) const
{
    return id.index < m_bodyItems.size() ? m_bodyItems[id.index] : nullptr;
}

double CanvasView::pixelsPerMetre() const { return std::abs(transform().m11()); }

void CanvasView::rebuildItems()
{
    // Only the canvas's own items go: the explainers' and the integrator ghosts' items stay on the
    // scene with their owners, who still point at them (clearing the whole scene left the Separating
    // Axes explainer drawing into a deleted item after any edit, and the window crashed).
    for (QGraphicsItem* item : m_bodyItems)
        delete item;
    for (QGraphicsItem* item : m_softItems)
        delete item;
    for (QGraphicsItem* item : m_springItems)
        delete item;
    for (QGraphicsItem* item : m_jointItems)
        delete item;
    for (QGraphicsItem* item : m_anchorItems)
        delete item;
    m_bodyItems.clear();
    m_springItems.clear();
    m_jointItems.clear();
    m_softItems.clear();
    m_anchorItems.clear();

    const model::World& world = m_runner.world();
    m_bodyItems.reserve(world.bodies.size());
    m_softItems.assign(world.bodies.size(), nullptr);
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        const model::BodyId id{static_cast<std::uint32_t>(i)};
        auto* item = new BodyItem(id, world.bodies[i]);
        item->setStamps(m_paintCaches ? m_stamps.get() : nullptr);
        m_scene->addItem(item);
        m_bodyItems.push_back(item);
        if (world.softGrid(id)) {
            m_softItems[i] = new SoftDetailItem;
            m_softItems[i]->setParts(m_showSoftEllipses, m_showSoftStrain);
            m_scene->addItem(m_softItems[i]);
        }
        syncSoftBody(i);
    }
    m_springItems.reserve(world.springs.size());
    for (const model::Spring& spring : world.springs) {
        auto* item = new SpringItem(spring.restLength);
        const auto [a, b] = springEnds(world, spring);
        item->setEnds(a, b);
        m_scene->addItem(item);
        m_springItems.push_back(item);
        if (!spring.bodyB) {
            m_anchorItems.push_back(new AnchorItem(b));
            m_scene->addItem(m_anchorItems.back());
        }
    }
    m_jointItems.reserve(world.joints.size());
    for (const model::Joint& joint : world.joints) {
        auto* item = new JointItem(joint.type);
        const auto [a, b] = jointEnds(world, joint);
        item->setEnds(a, b);
        m_scene->addItem(item);
        m_jointItems.push_back(item);
        if (joint.type == model::JointType::Rod && !joint.bodyB) {
            m_anchorItems.push_back(new AnchorItem(b));
            m_scene->addItem(m_anchorItems.back());
        }
    }
    applyLookToItems();
    showSelection();
}

void CanvasView::setPaintCaches(bool on)
{
    m_paintCaches = on;
    m_layerDirty = true;
    m_backgroundLayer = QImage();
    for (BodyItem* item : m_bodyItems)
        item->setStamps(on ? m_stamps.get() : nullptr);
    viewport()->update();
}

void CanvasView::setLook(const CanvasLook& look)
{
    m_look = look;
    m_layerDirty = true;
    m_instruments->setLineScale(look.lineScale);
    applyLookToItems();
    resetCachedContent();
    viewport()->update();
}

void CanvasView::applyLookToItems()
{
    for (QGraphicsItem* item : m_scene->items()) {
        if (auto* body = qgraphicsitem_cast<BodyItem*>(item))
            body->setLook(m_look);
        else if (auto* spring = qgraphicsitem_cast<SpringItem*>(item))
            spring->setLineScale(m_look.lineScale);
        else if (auto* anchor = qgraphicsitem_cast<AnchorItem*>(item))
            anchor->setLineScale(m_look.lineScale);
        else if (auto* joint = qgraphicsitem_cast<JointItem*>(item))
            joint->setLineScale(m_look.lineScale);
    }
}

void CanvasView::frameScene()
{
    m_frameRect = computeFrameRect();
    // Generous room beyond the framed region: QGraphicsView only centres on points inside the
    // scene rectangle, and without one it would grow with every body that flies away.
    const double padW = constants::kSceneRectPaddingFactor * m_frameRect.width();
    const double padH = constants::kSceneRectPaddingFactor * m_frameRect.height();
    m_scene->setSceneRect(m_frameRect.adjusted(-padW, -padH, padW, padH));
    m_autoFrame = true;
    frameWorld();
}

void CanvasView::syncItems()
{
    const model::World& world = m_runner.world();
    const std::size_t bodies = std::min(world.bodies.size(), m_bodyItems.size());
    for (std::size_t i = 0; i < bodies; ++i) {
        m_bodyItems[i]->setPose(world.bodies[i].state);
        m_bodyItems[i]->setColliding(world.bodies[i].colliding);
        syncSoftBody(i);
    }
    const std::size_t springs = std::min(world.springs.size(), m_springItems.size());
    for (std::size_t i = 0; i < springs; ++i) {
        const auto [a, b] = springEnds(world, world.springs[i]);
        m_springItems[i]->setEnds(a, b);
    }
    const std::size_t joints = std::min(world.joints.size(), m_jointItems.size());
    for (std::size_t i = 0; i < joints; ++i) {
        const auto [a, b] = jointEnds(world, world.joints[i]);
        m_jointItems[i]->setEnds(a, b);
    }
}

void CanvasView::syncSoftBody(std::size_t i)
{
    const model::World& world = m_runner.world();
    const model::BodyId id{static_cast<std::uint32_t>(i)};
    const model::SoftGrid* grid = world.softGrid(id);
    if (!grid || grid->size() == 0 || i >= m_bodyItems.size())
        return;
    // The outline comes in world coordinates; the item draws in the body's frame.
    const model::BodyState& state = world.bodies[i].state;
    const double c = std::cos(state.angle);
    const double s = std::sin(state.angle);
    std::vector<Vec2> outline = controller::softOutline(world, *grid);
    for (Vec2& p : outline) {
        const Vec2 d = p - state.position;
        p = Vec2(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
    }
    m_bodyItems[i]->setDeformedOutline(outline);
    if (SoftDetailItem* detail = i < m_softItems.size() ? m_softItems[i] : nullptr) {
        if (m_showSoftEllipses || m_showSoftStrain)
            detail->setContents(controller::softEllipses(world, *grid), controller::softSprings(*grid));
    }
}

void CanvasView::setShowSoftEllipses(bool on)
{
    m_showSoftEllipses = on;
    for (SoftDetailItem* item : m_softItems) {
        if (item)
            item->setParts(m_showSoftEllipses, m_showSoftStrain);
    }
    for (std::size_t i = 0; i < m_softItems.size(); ++i)
        syncSoftBody(i);
}

void CanvasView::setShowSoftStrain(bool on)
{
    m_showSoftStrain = on;
    for (SoftDetailItem* item : m_softItems) {
        if (item)
            item->setParts(m_showSoftEllipses, m_showSoftStrain);
    }
    for (std::size_t i = 0; i < m_softItems.size(); ++i)
        syncSoftBody(i);
}

void CanvasView::showSelection()
{
    const Selection selection = m_document ? m_document->selection() : Selection{};
    const auto mark = [](const auto& items, const std::vector<int>& selected) {
        for (std::size_t i = 0; i < items.size(); ++i)
            items[i]->setHighlighted(std::ranges::find(selected, static_cast<int>(i)) != selected.end());
    };
    mark(m_bodyItems, selection.bodies);
    mark(m_springItems, selection.springs);
    mark(m_jointItems, selection.joints);
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

QPointF CanvasView::toScene(const QPointF& viewPos) const { return viewportTransform().inverted().map(viewPos); }

QPointF CanvasView::toView(const QPointF& scenePos) const { return viewportTransform().map(scenePos); }

void CanvasView::zoomBy(double factor, const QPointF& viewAnchor)
{
    const double current = pixelsPerMetre();
    if (!(factor > 0) || !std::isfinite(factor) || !(current > 0))
        return;
    const QPointF anchor = toScene(viewAnchor);
    const double scale = std::clamp(current * factor, constants::kMinPixelsPerMetre, constants::kMaxPixelsPerMetre);
    setTransform(QTransform::fromScale(scale, -scale));
    // Scroll so that the anchor is back under the cursor; scroll bars move by whole pixels, so it
    // lands within half a pixel.
    panBy(viewAnchor - toView(anchor));
    m_autoFrame = false;
}

void CanvasView::panBy(const QPointF& pixels)
{
    horizontalScrollBar()->setValue(horizontalScrollBar()->value() - qRound(pixels.x()));
    verticalScrollBar()->setValue(verticalScrollBar()->value() - qRound(pixels.y()));
    m_autoFrame = false;
}

double CanvasView::gridSpacing() const
{
    const double scale = pixelsPerMetre();
    if (!(scale > 0) || !std::isfinite(scale))
        return 1;
    return gridSpacingFor(constants::kMinimumGridSpacingPx / scale).spacing;
}

QPointF CanvasView::snapped(const QPointF& scenePos) const
{
    if (!m_snapToGrid)
        return scenePos;
    const double spacing = gridSpacing();
    return QPointF(std::round(scenePos.x() / spacing) * spacing, std::round(scenePos.y() / spacing) * spacing);
}

std::vector<int> CanvasView::bodiesAt(const QPointF& scenePos) const
{
    std::vector<int> hits;
    for (std::size_t i = m_bodyItems.size(); i-- > 0;) {
        const BodyItem* item = m_bodyItems[i];
        if (item->shape().contains(item->mapFromScene(scenePos)))
            hits.push_back(static_cast<int>(i));
    }
    return hits;
}

std::optional<int> CanvasView::bodyAt(const QPointF& scenePos) const
{
    const std::vector<int> hits = bodiesAt(scenePos);
    if (hits.empty())
        return std::nullopt;
    return hits.front();
}

std::optional<int> CanvasView::springAt(const QPointF& scenePos) const
{
    const double tolerance = constants::kPickTolerancePx / std::max(pixelsPerMetre(), 1e-12);
    const model::World& world = m_runner.world();
    for (std::size_t i = world.springs.size(); i-- > 0;) {
        const auto [a, b] = springEnds(world, world.springs[i]);
        if (distanceToSegment(scenePos, a, b) <= tolerance)
            return static_cast<int>(i);
    }
    return std::nullopt;
}

std::optional<int> CanvasView::jointAt(const QPointF& scenePos) const
{
    const double tolerance = constants::kPickTolerancePx / std::max(pixelsPerMetre(), 1e-12);
    const model::World& world = m_runner.world();
    for (std::size_t i = world.joints.size(); i-- > 0;) {
        const auto [a, b] = jointEnds(world, world.joints[i]);
        if (distanceToSegment(scenePos, a, b) <= tolerance)
            return static_cast<int>(i);
    }
    return std::nullopt;
}

Selection CanvasView::itemsInside(const QRectF& rect) const
{
    Selection selection;
    const QRectF box = rect.normalized();
    for (std::size_t i = 0; i < m_bodyItems.size(); ++i) {
        if (box.contains(m_bodyItems[i]->sceneBoundingRect()))
            selection.bodies.push_back(static_cast<int>(i));
    }
    const model::World& world = m_runner.world();
    for (std::size_t i = 0; i < world.springs.size(); ++i) {
        const auto [a, b] = springEnds(world, world.springs[i]);
        if (box.contains(a) && box.contains(b))
            selection.springs.push_back(static_cast<int>(i));
    }
    for (std::size_t i = 0; i < world.joints.size(); ++i) {
        const auto [a, b] = jointEnds(world, world.joints[i]);
        if (box.contains(a) && box.contains(b))
            selection.joints.push_back(static_cast<int>(i));
    }
    return selection;
}

void CanvasView::showMessage(const QPointF& scenePos, const QString& message)
{
    m_lastMessage = message;
    const QPoint at = viewport()->mapToGlobal(toView(scenePos).toPoint());
    QToolTip::showText(at, message, viewport());
}

void CanvasView::setTool(ToolKind kind)
{
    const auto it = std::ranges::find_if(m_tools, [&](const auto& tool) { return tool->kind() == kind; });
    if (it == m_tools.end() || it->get() == m_tool)
        return;
    if (m_tool)
        m_tool->cancel();
    m_tool = it->get();
    viewport()->setCursor(m_tool->cursorShape());
    viewport()->update();
    emit toolChanged(kind);
}

void CanvasView::resizeEvent(QResizeEvent* event)
{
    QGraphicsView::resizeEvent(event);
    if (m_autoFrame)
        frameWorld();
}

bool CanvasView::event(QEvent* event)
{
    if (event->type() == QEvent::ShortcutOverride) {
        auto* key = static_cast<QKeyEvent*>(event);
        // Space is Play/Pause, but Space held while dragging pans: the canvas decides on release.
        const bool space = key->key() == Qt::Key_Space && key->modifiers() == Qt::NoModifier;
        if (space || (m_tool && m_tool->wantsKey(key->key(), key->modifiers()))) {
            event->accept();
            return true;
        }
    }
    return QGraphicsView::event(event);
}

void CanvasView::keyPressEvent(QKeyEvent* event)
{
    if (event->key() == Qt::Key_Space && event->modifiers() == Qt::NoModifier) {
        if (!event->isAutoRepeat()) {
            m_spaceHeld = true;
            m_spaceUsedForPan = false;
        }
        event->accept();
        return;
    }
    if (m_tool && m_tool->keyPress(event)) {
        viewport()->update();
        event->accept();
        return;
    }
    // QAbstractScrollArea would scroll on arrows and Page Up/Down. The arrows belong to Step and
    // the nudge, and panning has its own gestures, so the canvas leaves them to the window.
    switch (event->key()) {
    case Qt::Key_Left:
    case Qt::Key_Right:
    case Qt::Key_Up:
    case Qt::Key_Down:
    case Qt::Key_PageUp:
    case Qt::Key_PageDown:
        event->ignore();
        return;
    default:
        QGraphicsView::keyPressEvent(event);
    }
}

void CanvasView::keyReleaseEvent(QKeyEvent* event)
{
    if (event->key() == Qt::Key_Space && !event->isAutoRepeat() && m_spaceHeld) {
        m_spaceHeld = false;
        if (!m_spaceUsedForPan)
            emit spaceTapped();
        event->accept();
        return;
    }
    QGraphicsView::keyReleaseEvent(event);
}

void CanvasView::focusOutEvent(QFocusEvent* event)
{
    m_spaceHeld = false;
    m_panning = false;
    QGraphicsView::focusOutEvent(event);
}

ToolEvent CanvasView::toolEvent(const QMouseEvent* event) const
{
    return ToolEvent{toScene(event->position()), event->position(), event->button(), event->buttons(),
                     event->modifiers()};
}

void CanvasView::mousePressEvent(QMouseEvent* event)
{
    setFocus(Qt::MouseFocusReason);
    if (event->button() == Qt::MiddleButton || (event->button() == Qt::LeftButton && m_spaceHeld)) {
        m_panning = true;
        m_spaceUsedForPan = m_spaceHeld;
        m_lastPanPos = event->position();
        viewport()->setCursor(Qt::ClosedHandCursor);
        event->accept();
        return;
    }
    if (m_tool)
        m_tool->mousePress(toolEvent(event));
    viewport()->update();
    event->accept();
}

void CanvasView::mouseMoveEvent(QMouseEvent* event)
{
    if (m_panning) {
        panBy(event->position() - m_lastPanPos);
        m_lastPanPos = event->position();
        event->accept();
        return;
    }
    if (m_tool) {
        m_tool->mouseMove(toolEvent(event));
        viewport()->update();
    }
    event->accept();
}

void CanvasView::mouseReleaseEvent(QMouseEvent* event)
{
    if (m_panning) {
        if (event->button() == Qt::MiddleButton || event->button() == Qt::LeftButton) {
            m_panning = false;
            viewport()->setCursor(m_tool ? m_tool->cursorShape() : Qt::ArrowCursor);
        }
        event->accept();
        return;
    }
    if (m_tool)
        m_tool->mouseRelease(toolEvent(event));
    viewport()->update();
    event->accept();
}

void CanvasView::mouseDoubleClickEvent(QMouseEvent* event)
{
    if (m_tool && event->button() == Qt::LeftButton && !m_spaceHeld)
        m_tool->mouseDoubleClick(toolEvent(event));
    viewport()->update();
    event->accept();
}

void CanvasView::wheelEvent(QWheelEvent* event)
{
    // One notch of a wheel is 120 eighths of a degree; a touchpad sends smaller steps.
    const double notches = event->angleDelta().y() / 120.0;
    if (notches != 0)
        zoomBy(std::pow(constants::kZoomPerWheelNotch, notches), event->position());
    event->accept();
}

void CanvasView::drawForeground(QPainter* painter, const QRectF&)
{
    // Traced points' paths and arrows over the bodies, the tool's overlay over them, and the
    // legend over everything.
    m_instruments->paintTracedPoints(*painter);
    m_instruments->paintVectors(*painter);
    if (m_tool) {
        painter->save();
        m_tool->paintOverlay(*painter, pixelsPerMetre());
        painter->restore();
    }
    m_instruments->paintLegend(*painter, QRectF(viewport()->rect()));
}

void CanvasView::drawBackground(QPainter* painter, const QRectF& rect)
{
    // The cached layer is made for the viewport; another device (render() into a picture) or a
    // paint with caches off draws everything afresh.
    if (!m_paintCaches || painter->device() != viewport()) {
        drawPaper(painter, rect);
        // Trails lie on the paper, under the bodies that left them.
        m_instruments->paintTrails(*painter);
        if (m_paintCaches)
            m_layerDirty = true; // the trails' cursors now describe that other picture
        return;
    }
    updateBackgroundLayer(*painter);
    painter->save();
    painter->resetTransform();
    painter->drawImage(QPointF(0, 0), m_backgroundLayer);
    painter->restore();
}

void CanvasView::updateBackgroundLayer(QPainter& viewportPainter)
{
    const QTransform toPixels = viewportPainter.worldTransform();
    const qreal ratio = viewport()->devicePixelRatioF();
    const QSize size = viewport()->size() * ratio;
    // Whole again when the picture no longer matches: zoom, pan, size, look, the trails' revision,
    // an edit, or settled after growth (m_layerSettle).
    const bool whole = m_layerDirty || m_backgroundLayer.size() != size || m_layerTransform != toPixels ||
                       m_layerRevision != m_instruments->trailRevision();
    if (whole) {
        if (m_backgroundLayer.size() != size) {
            m_backgroundLayer = QImage(size, QImage::Format_ARGB32_Premultiplied);
            m_backgroundLayer.setDevicePixelRatio(ratio);
        }
        // Paper under every pixel first: the scene rectangle of the viewport's pixel rectangle
        // may stop short of its last row and column.
        m_backgroundLayer.fill(m_look.background);
        QPainter layer(&m_backgroundLayer);
        layer.setRenderHints(viewportPainter.renderHints());
        layer.setFont(viewportPainter.font());
        layer.setWorldTransform(toPixels);
        drawPaper(&layer, mapToScene(viewport()->rect().adjusted(-1, -1, 1, 1)).boundingRect());
        m_instruments->paintTrails(layer);
        m_layerTransform = toPixels;
        m_layerRevision = m_instruments->trailRevision();
        m_layerDirty = false;
        m_layerGrown = false;
    } else if (m_instruments->showsTrails() && m_layerStep != m_runner.world().stepCount) {
        QPainter layer(&m_backgroundLayer);
        layer.setRenderHints(viewportPainter.renderHints());
        layer.setWorldTransform(toPixels);
        m_instruments->paintTrailGrowth(layer);
        m_layerGrown = true;
        m_layerSettle.start();
    }
    m_layerStep = m_runner.world().stepCount;
}

void CanvasView::drawPaper(QPainter* painter, const QRectF& rect) const
{
    painter->save();
    painter->fillRect(rect, m_look.background);

    const double scale = pixelsPerMetre();
    if (scale > 0 && std::isfinite(scale)) {
        const GridSpacing grid = gridSpacingFor(constants::kMinimumGridSpacingPx / scale);
        // Crisp one-pixel lines: antialiasing would smear them over two pixel rows.
        painter->setRenderHint(QPainter::Antialiasing, false);
        QPen minorPen(m_look.minorGrid, 0);
        QPen majorPen(m_look.majorGrid, 0);
        QPen axisPen(m_look.axis, 0);
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
        drawGridLabels(painter, rect, grid.spacing, grid.linesPerMajor);
    }
    painter->restore();
}

void CanvasView::drawGridLabels(QPainter* painter, const QRectF& rect, double spacing, int linesPerMajor) const
{
    // Labels go along the left and bottom edges of what is visible, in pixels, so that they keep
    // their size at every zoom and stay on screen however the view is panned.
    const QRectF visible = mapToScene(viewport()->rect()).boundingRect();
    const double majorSpacing = spacing * linesPerMajor;
    const QTransform toPixels = painter->worldTransform();
    painter->save();
    painter->resetTransform();
    QFont font = painter->font();
    font.setPointSizeF(constants::kGridLabelPointSize * m_look.gridLabelScale);
    painter->setFont(font);
    painter->setPen(m_look.gridLabel);
    const QRectF pixelRect = toPixels.mapRect(rect);
    const QRectF visiblePixels = toPixels.mapRect(visible);
    const double pad = constants::kGridLabelPaddingPx;
    for (auto i = static_cast<long long>(std::ceil(visible.left() / majorSpacing));
         i <= static_cast<long long>(std::floor(visible.right() / majorSpacing)); ++i) {
        const double x = static_cast<double>(i) * majorSpacing;
        const QPointF at = toPixels.map(QPointF(x, visible.bottom()));
        const QPointF bottom(at.x() + pad, visiblePixels.bottom() - pad);
        if (pixelRect.contains(bottom))
            painter->drawText(bottom, gridLabel(x, majorSpacing));
    }
    for (auto i = static_cast<long long>(std::ceil(visible.top() / majorSpacing));
         i <= static_cast<long long>(std::floor(visible.bottom() / majorSpacing)); ++i) {
        const double y = static_cast<double>(i) * majorSpacing;
        const QPointF at = toPixels.map(QPointF(visible.left(), y));
        const QPointF left(visiblePixels.left() + pad, at.y() - pad);
        if (pixelRect.adjusted(0, -pad, 0, pad).contains(left))
            painter->drawText(left, gridLabel(y, majorSpacing));
    }
    painter->restore();
}

} // namespace impetus::view
