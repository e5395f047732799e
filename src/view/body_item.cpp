#include "view/body_item.h"

#include "view/body_stamps.h"
#include "view/polygon_painting.h"
#include "view/view_constants.h"

#include <QColor>
#include <QPainter>
#include <QPolygonF>
#include <QTransform>

#include <cmath>
#include <variant>

namespace impetus::view {

namespace {

QColor toQColor(const model::Color& color) { return QColor(color.r, color.g, color.b); }

QPolygonF polygonOf(const std::vector<Vec2>& points)
{
    QPolygonF polygon;
    polygon.reserve(static_cast<qsizetype>(points.size()));
    for (const Vec2& v : points)
        polygon << QPointF(v.x(), v.y());
    return polygon;
}

} // namespace

QPolygonF bodyOutlinePolygon(const model::Body& body)
{
    if (std::holds_alternative<model::Circle>(body.shape) || std::holds_alternative<model::Ellipse>(body.shape))
        return {};
    // Boxes and polygons: the outline the model derived, already centred on the centre of mass.
    // For a concave polygon this is the true outline, not the convex pieces.
    return polygonOf(body.geometry.outline);
}

QPainterPath bodyOutlinePath(const model::Body& body)
{
    QPainterPath path;
    if (const auto* circle = std::get_if<model::Circle>(&body.shape)) {
        path.addEllipse(QPointF(0, 0), circle->radius, circle->radius);
    } else if (const auto* ellipse = std::get_if<model::Ellipse>(&body.shape)) {
        path.addEllipse(QPointF(0, 0), ellipse->radiusX, ellipse->radiusY);
    } else {
        path.addPolygon(bodyOutlinePolygon(body));
        path.closeSubpath();
    }
    return path;
}

BodyItem::BodyItem(model::BodyId id, const model::Body& body, QGraphicsItem* parent)
    : QGraphicsItem(parent)
    , m_id(id)
    , m_outline(bodyOutlinePath(body))
    , m_rigidOutline(m_outline)
    , m_polygon(bodyOutlinePolygon(body))
    , m_rigidPolygon(m_polygon)
{
    if (const auto* circle = std::get_if<model::Circle>(&body.shape)) {
        m_radiusLine = QLineF(0, 0, circle->radius, 0);
        m_rigidCircleRadius = circle->radius;
        m_circleRadius = m_rigidCircleRadius;
    } else if (const auto* ellipse = std::get_if<model::Ellipse>(&body.shape))
        m_radiusLine = QLineF(0, 0, ellipse->radiusX, 0);

    m_color = toQColor(body.color);
    m_fixed = body.fixed;
    setLook(CanvasLook{});
    setPose(body.state);
    setColliding(body.colliding);
}

void BodyItem::setLook(const CanvasLook& look)
{
    m_lineScale = look.lineScale;
    m_own = lookFor(m_color, m_fixed, look);
    m_red = lookFor(QColor(constants::kCollidingRed, constants::kCollidingGreen, constants::kCollidingBlue), m_fixed,
                    look);
    // Red against green alone is lost on a colour-blind student: the hatch says "colliding" too.
    if (look.hatchColliding)
        m_red.hatch = QBrush(look.collidingHatchColor, Qt::DiagCrossPattern);
    update();
}

BodyItem::Look BodyItem::lookFor(const QColor& color, bool fixed, const CanvasLook& canvasLook)
{
    Look look;
    look.fill = QBrush(fixed ? color.darker(constants::kFixedFillDarkerFactor) : color);
    if (fixed)
        look.hatch = QBrush(color.darker(constants::kFixedHatchDarkerFactor), Qt::BDiagPattern);
    look.pen = QPen(canvasLook.uniformOutline ? canvasLook.outlineColor : color.darker(constants::kOutlineDarkerFactor),
                    constants::kOutlineWidthPx * canvasLook.lineScale);
    look.pen.setCosmetic(true);
    look.pen.setJoinStyle(Qt::RoundJoin);
    return look;
}

void BodyItem::setColliding(bool colliding)
{
    if (colliding == m_colliding)
        return;
    m_colliding = colliding;
    update();
}

void BodyItem::setHighlighted(bool on)
{
    if (on == m_highlighted)
        return;
    m_highlighted = on;
    update();
}

void BodyItem::setPose(const model::BodyState& state)
{
    // Built from cos and sin directly: in the y-up scene, (x, y) ↦ (c·x − s·y, s·x + c·y) is the
    // counter-clockwise rotation of the model, and the view's y flip then shows it
    // counter-clockwise on screen too. QTransform's (m11, m12, m21, m22) are (c, s, −s, c).
    const qreal c = std::cos(state.angle);
    const qreal s = std::sin(state.angle);
    setTransform(QTransform(c, s, -s, c, 0, 0));
    setPos(state.position.x(), state.position.y());
}

void BodyItem::setDeformedOutline(const std::vector<Vec2>& outline)
{
    QPainterPath path;
    QPolygonF polygon;
    if (outline.size() >= 3) {
        polygon = polygonOf(outline);
        path.addPolygon(polygon);
        path.closeSubpath();
    } else {
        path = m_rigidOutline;
        polygon = m_rigidPolygon;
    }
    if (path == m_outline)
        return;
    prepareGeometryChange();
    m_outline = path;
    m_polygon = polygon;
    // Deformed, a soft circle is no longer the circle of a stamp.
    m_circleRadius = m_outline == m_rigidOutline ? m_rigidCircleRadius : 0;
}

QPainterPath BodyItem::shape() const { return m_outline; }

QRectF BodyItem::boundingRect() const { return m_outline.boundingRect(); }

void BodyItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*)
{
    // Fill, then the hatch of a fixed body, then the outline on top of both.
    const Look& look = m_colliding ? m_red : m_own;
    // A hatch lies on the screen's pixel grid, not the body's: no stamp for it.
    const bool stamped = m_stamps && m_circleRadius > 0 && look.hatch.style() == Qt::NoBrush &&
                         m_stamps->drawCircle(*painter, m_outline, m_circleRadius, look.fill, look.pen);
    if (!stamped && !m_polygon.isEmpty()) {
        // A polygon (a box, a polygon, a deformed soft body) the quick way (polygon_painting.h).
        fillPolygon(*painter, m_polygon, look.fill);
        if (look.hatch.style() != Qt::NoBrush)
            hatchPolygon(*painter, m_polygon, look.hatch);
        strokePolygon(*painter, m_polygon, look.pen);
    } else if (!stamped) {
        painter->setPen(Qt::NoPen);
        painter->setBrush(look.fill);
        painter->drawPath(m_outline);
        if (look.hatch.style() != Qt::NoBrush) {
            painter->setBrush(look.hatch);
            painter->drawPath(m_outline);
        }
    }
    painter->setPen(look.pen);
    painter->setBrush(Qt::NoBrush);
    if (!stamped && m_polygon.isEmpty())
        painter->drawPath(m_outline);
    if (!m_radiusLine.isNull())
        painter->drawLine(m_radiusLine);
    if (m_highlighted) {
        QPen selection(constants::kSelectionColor, constants::kSelectionWidthPx * m_lineScale, Qt::DashLine);
        selection.setCosmetic(true);
        painter->setPen(selection);
        painter->drawPath(m_outline);
    }
}

} // namespace impetus::view
