#pragma once
/// \file spring_item.h
/// The picture of a spring, and the marker of a fixed world anchor.

#include <QGraphicsItem>
#include <QPainterPath>
#include <QPen>

namespace impetus::view {

/// Draws a spring as a zig-zag between its two ends, in scene coordinates (metres, y up). The
/// zig-zag has a fixed number of corners, so a stretched spring shows longer teeth and a
/// compressed one shorter teeth.
class SpringItem : public QGraphicsItem {
public:
    /// QGraphicsItem::type() of spring items.
    enum { Type = UserType + 2 };

    /// A spring item with rest length `restLength` (m), which sets the width of its zig-zag.
    explicit SpringItem(double restLength, QGraphicsItem* parent = nullptr);

    /// Moves the spring's ends to the scene points `a` and `b`, m.
    void setEnds(const QPointF& a, const QPointF& b);

    /// Draws the spring in the selection colour while `on`.
    void setHighlighted(bool on);

    /// Whether the spring is drawn as selected.
    bool isHighlighted() const { return m_highlighted; }

    /// Draws the line `scale` times its normal width (CanvasLook::lineScale, projector mode).
    void setLineScale(double scale);

    /// The zig-zag's bounding box in scene coordinates, m.
    QRectF boundingRect() const override;
    /// The zig-zag, with a cosmetic pen.
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;
    /// SpringItem::Type, for qgraphicsitem_cast.
    int type() const override { return Type; }

private:
    double m_halfWidth; ///< m
    QPainterPath m_path;
    QPen m_pen;
    bool m_highlighted = false;
    double m_lineScale = 1;
};

/// A small ring-and-dot marker at a fixed world point (a spring's world anchor). It ignores the
/// view transform, so it keeps its size in pixels at every zoom.
class AnchorItem : public QGraphicsItem {
public:
    /// QGraphicsItem::type() of anchor items.
    enum { Type = UserType + 3 };

    /// A marker at the scene point `position`, m.
    explicit AnchorItem(const QPointF& position, QGraphicsItem* parent = nullptr);

    /// Draws the marker `scale` times its normal size (CanvasLook::lineScale, projector mode).
    void setLineScale(double scale);

    /// The marker's box, px around its position.
    QRectF boundingRect() const override;
    /// A ring with a dot in its centre.
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;
    /// AnchorItem::Type, for qgraphicsitem_cast.
    int type() const override { return Type; }

private:
    double m_lineScale = 1;
};

} // namespace impetus::view
