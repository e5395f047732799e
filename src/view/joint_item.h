#pragma once
/// \file joint_item.h
/// The picture of a pin or rod joint.

#include "model/joint.h"

#include <QGraphicsItem>
#include <QPointF>

namespace impetus::view {

/// Draws a joint in scene coordinates (metres, y up). A pin is a ring with a dot at the hinge, the
/// same size in pixels at every zoom; a rod is a thick line between its two anchors with a dot at
/// each end.
class JointItem : public QGraphicsItem {
public:
    /// QGraphicsItem::type() of joint items.
    enum { Type = UserType + 4 };

    /// An item for a joint of type `type`.
    explicit JointItem(model::JointType type, QGraphicsItem* parent = nullptr);

    /// Moves the joint's ends to the scene points `a` and `b`, m (a pin uses only `a`).
    void setEnds(const QPointF& a, const QPointF& b);

    /// Draws the joint in the selection colour while `on`.
    void setHighlighted(bool on);

    /// Whether the joint is drawn as selected.
    bool isHighlighted() const { return m_highlighted; }

    /// Draws lines and the pin's marker `scale` times their normal size (CanvasLook::lineScale,
    /// projector mode).
    void setLineScale(double scale);

    /// Pin: the marker's box in pixels around the hinge. Rod: the line's box in the scene, m.
    QRectF boundingRect() const override;
    /// The ring (pin) or the line (rod).
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;
    /// JointItem::Type, for qgraphicsitem_cast.
    int type() const override { return Type; }

private:
    model::JointType m_type;
    QPointF m_a; ///< rod: first end, scene m
    QPointF m_b; ///< rod: second end, scene m
    bool m_highlighted = false;
    double m_lineScale = 1;
};

} // namespace impetus::view
