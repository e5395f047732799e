#include "view/soft_detail_item.h"

#include "view/view_constants.h"

#include <QPainter>
#include <QPen>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace impetus::view {

SoftDetailItem::SoftDetailItem(QGraphicsItem* parent)
    : QGraphicsItem(parent)
{
    // Over the body it details, under the selection outline and the tools' overlays.
    setZValue(constants::kSoftDetailZ);
    setAcceptedMouseButtons(Qt::NoButton);
}

void SoftDetailItem::setContents(std::vector<controller::SoftEllipseView> ellipses,
                                 std::vector<controller::SoftSpringView> springs)
{
    QRectF bounds;
    for (const controller::SoftEllipseView& e : ellipses) {
        const double r = std::max(e.radiusX, e.radiusY);
        bounds = bounds.united(QRectF(e.center.x() - r, e.center.y() - r, 2 * r, 2 * r));
    }
    for (const controller::SoftSpringView& s : springs)
        bounds = bounds.united(QRectF(QPointF(s.endA.x(), s.endA.y()), QPointF(s.endB.x(), s.endB.y())).normalized());
    if (bounds != m_bounds)
        prepareGeometryChange();
    m_bounds = bounds;
    m_ellipses = std::move(ellipses);
    m_springs = std::move(springs);
    update();
}

void SoftDetailItem::setParts(bool ellipses, bool springs)
{
    m_showEllipses = ellipses;
    m_showSprings = springs;
    update();
}

QColor SoftDetailItem::strainColour(double strain)
{
    const double t = std::clamp(strain / constants::kStrainColourFullScale, -1.0, 1.0);
    const QColor rest(constants::kStrainRestGrey, constants::kStrainRestGrey, constants::kStrainRestGrey);
    const QColor end = t < 0 ? QColor(Qt::blue) : QColor(Qt::red);
    const double w = std::abs(t);
    return QColor::fromRgbF(static_cast<float>((1 - w) * rest.redF() + w * end.redF()),
                            static_cast<float>((1 - w) * rest.greenF() + w * end.greenF()),
                            static_cast<float>((1 - w) * rest.blueF() + w * end.blueF()));
}

QRectF SoftDetailItem::boundingRect() const { return m_bounds; }

void SoftDetailItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*)
{
    if (m_showSprings) {
        for (const controller::SoftSpringView& s : m_springs) {
            QPen pen(strainColour(s.strain), constants::kSoftSpringWidthPx);
            pen.setCosmetic(true);
            painter->setPen(pen);
            painter->drawLine(QPointF(s.endA.x(), s.endA.y()), QPointF(s.endB.x(), s.endB.y()));
        }
    }
    if (m_showEllipses) {
        QPen pen(QColor(constants::kSoftEllipseGrey, constants::kSoftEllipseGrey, constants::kSoftEllipseGrey),
                 constants::kSoftEllipseWidthPx);
        pen.setCosmetic(true);
        painter->setPen(pen);
        painter->setBrush(Qt::NoBrush);
        for (const controller::SoftEllipseView& e : m_ellipses) {
            painter->save();
            painter->translate(e.center.x(), e.center.y());
            painter->rotate(e.angle * 180 / std::numbers::pi);
            painter->drawEllipse(QPointF(0, 0), e.radiusX, e.radiusY);
            painter->restore();
        }
    }
}

} // namespace impetus::view
