#include "view/joint_item.h"

#include "view/view_constants.h"

#include <QPainter>

namespace impetus::view {

JointItem::JointItem(model::JointType type, QGraphicsItem* parent)
    : QGraphicsItem(parent)
    , m_type(type)
{
    // A pin's marker keeps its size in pixels; the item is then placed at the hinge and draws in
    // pixels around it.
    if (m_type == model::JointType::Pin)
        setFlag(ItemIgnoresTransformations);
    // Over bodies and springs, so that what holds a body is always visible.
    setZValue(3);
}

void JointItem::setEnds(const QPointF& a, const QPointF& b)
{
    if (m_type == model::JointType::Pin) {
        setPos(a);
        return;
    }
    prepareGeometryChange();
    m_a = a;
    m_b = b;
}

void JointItem::setHighlighted(bool on)
{
    if (on == m_highlighted)
        return;
    m_highlighted = on;
    update();
}

void JointItem::setLineScale(double scale)
{
    prepareGeometryChange();
    m_lineScale = scale;
}

QRectF JointItem::boundingRect() const
{
    if (m_type == model::JointType::Pin) {
        const qreal r = (constants::kPinMarkerRadiusPx + constants::kSelectionWidthPx) * m_lineScale;
        return QRectF(-r, -r, 2 * r, 2 * r);
    }
    return QRectF(m_a, m_b).normalized();
}

void JointItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*)
{
    const QColor color = m_highlighted ? constants::kSelectionColor : constants::kJointColor;
    if (m_type == model::JointType::Pin) {
        painter->setPen(
            QPen(color, (m_highlighted ? constants::kSelectionWidthPx : constants::kOutlineWidthPx) * m_lineScale));
        painter->setBrush(constants::kBackgroundColor);
        const qreal r = constants::kPinMarkerRadiusPx * m_lineScale;
        painter->drawEllipse(QPointF(0, 0), r, r);
        painter->setPen(Qt::NoPen);
        painter->setBrush(color);
        painter->drawEllipse(QPointF(0, 0), r * constants::kPinDotFraction, r * constants::kPinDotFraction);
        return;
    }
    QPen pen(color, constants::kRodWidthPx * m_lineScale);
    pen.setCosmetic(true);
    pen.setCapStyle(Qt::RoundCap);
    painter->setPen(pen);
    painter->drawLine(m_a, m_b);
}

} // namespace impetus::view
