#include "view/spring_item.h"

#include "view/view_constants.h"

#include <QLineF>
#include <QPainter>

#include <algorithm>

namespace impetus::view {

SpringItem::SpringItem(double restLength, QGraphicsItem* parent)
    : QGraphicsItem(parent)
    , m_halfWidth(std::min(constants::kSpringHalfWidth,
                           constants::kSpringMaxHalfWidthPerLength * std::max(restLength, 0.0)))
    , m_pen(constants::kSpringColor, constants::kOutlineWidthPx)
{
    m_pen.setCosmetic(true);
    m_pen.setJoinStyle(Qt::RoundJoin);
    m_pen.setCapStyle(Qt::RoundCap);
    // Springs are drawn over the bodies they join, so both anchors stay visible.
    setZValue(1);
}

void SpringItem::setEnds(const QPointF& a, const QPointF& b)
{
    prepareGeometryChange();
    m_path = QPainterPath(a);
    const QLineF line(a, b);
    const qreal length = line.length();
    if (length <= 0 || m_halfWidth <= 0) {
        m_path.lineTo(b);
        return;
    }
    const QPointF along = (b - a) / length;
    const QPointF across(-along.y(), along.x());
    const qreal lead = constants::kSpringLeadFraction * length;
    const qreal tooth = (length - 2 * lead) / (constants::kSpringZigZagCorners + 1);
    m_path.lineTo(a + along * lead);
    for (int i = 1; i <= constants::kSpringZigZagCorners; ++i) {
        const qreal side = (i % 2 == 1) ? m_halfWidth : -m_halfWidth;
        m_path.lineTo(a + along * (lead + i * tooth) + across * side);
    }
    m_path.lineTo(b - along * lead);
    m_path.lineTo(b);
}

void SpringItem::setHighlighted(bool on)
{
    if (on == m_highlighted)
        return;
    m_highlighted = on;
    m_pen.setColor(on ? constants::kSelectionColor : constants::kSpringColor);
    m_pen.setWidthF((on ? constants::kSelectionWidthPx : constants::kOutlineWidthPx) * m_lineScale);
    update();
}

void SpringItem::setLineScale(double scale)
{
    m_lineScale = scale;
    m_pen.setWidthF((m_highlighted ? constants::kSelectionWidthPx : constants::kOutlineWidthPx) * m_lineScale);
    update();
}

QRectF SpringItem::boundingRect() const
{
    return m_path.boundingRect().adjusted(-m_halfWidth, -m_halfWidth, m_halfWidth, m_halfWidth);
}

void SpringItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*)
{
    painter->setPen(m_pen);
    painter->setBrush(Qt::NoBrush);
    painter->drawPath(m_path);
}

AnchorItem::AnchorItem(const QPointF& position, QGraphicsItem* parent)
    : QGraphicsItem(parent)
{
    setFlag(ItemIgnoresTransformations);
    setPos(position);
    setZValue(2);
}

void AnchorItem::setLineScale(double scale)
{
    prepareGeometryChange();
    m_lineScale = scale;
}

QRectF AnchorItem::boundingRect() const
{
    const qreal r = (constants::kAnchorMarkerRadiusPx + constants::kOutlineWidthPx) * m_lineScale;
    return QRectF(-r, -r, 2 * r, 2 * r);
}

void AnchorItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*)
{
    QPen pen(constants::kSpringColor, constants::kOutlineWidthPx * m_lineScale);
    painter->setPen(pen);
    painter->setBrush(constants::kBackgroundColor);
    const qreal r = constants::kAnchorMarkerRadiusPx * m_lineScale;
    painter->drawEllipse(QPointF(0, 0), r, r);
    painter->setPen(Qt::NoPen);
    painter->setBrush(constants::kSpringColor);
    painter->drawEllipse(QPointF(0, 0), r / 2, r / 2);
}

} // namespace impetus::view
