#pragma once
/// \file soft_detail_item.h
/// What a soft body is made of, drawn over it on request: its ellipses and its springs coloured by
/// strain (docs/app.md, "Soft bodies").

#include "controller/soft/soft_body_shape.h"

#include <QGraphicsItem>
#include <QPainterPath>

#include <vector>

namespace impetus::view {

/// Draws one soft body's ellipses (thin outlines) and grid springs (blue when compressed, grey at
/// rest length, red when stretched), in scene coordinates (metres, y up). Either part can be
/// hidden; with both hidden the item draws nothing. It keeps a copy of what it draws and never
/// reads the world itself.
class SoftDetailItem : public QGraphicsItem {
public:
    /// QGraphicsItem::type() of soft-detail items.
    enum { Type = UserType + 5 };

    explicit SoftDetailItem(QGraphicsItem* parent = nullptr);

    /// Replaces what is drawn.
    void setContents(std::vector<controller::SoftEllipseView> ellipses,
                     std::vector<controller::SoftSpringView> springs);
    /// Which parts are drawn.
    void setParts(bool ellipses, bool springs);
    bool showsEllipses() const { return m_showEllipses; }
    bool showsSprings() const { return m_showSprings; }
    /// The springs, as last set (for tests and the legend).
    const std::vector<controller::SoftSpringView>& springs() const { return m_springs; }

    /// The colour of a spring at `strain` (L/L₀ − 1): blue compressed, grey at rest, red
    /// stretched, saturating at ±constants::kStrainColourFullScale.
    static QColor strainColour(double strain);

    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;
    int type() const override { return Type; }

private:
    std::vector<controller::SoftEllipseView> m_ellipses;
    std::vector<controller::SoftSpringView> m_springs;
    QRectF m_bounds;
    bool m_showEllipses = false;
    bool m_showSprings = false;
};

} // namespace impetus::view
