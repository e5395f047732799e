#pragma once
/// \file body_item.h
/// The picture of one body on the canvas.

#include "model/body.h"
#include "view/canvas_look.h"

#include <QBrush>
#include <QGraphicsItem>
#include <QLineF>
#include <QPainterPath>
#include <QPolygonF>
#include <QPen>

#include <vector>

namespace impetus::view {

/// The outline of `body`'s rigid shape in its own frame (m, origin at the centre of mass): a circle
/// or ellipse, or the true outline of a box or polygon (not its convex pieces).
QPainterPath bodyOutlinePath(const model::Body& body);

/// The outline of a box or polygon body in its own frame as a polygon, m, the vertices of
/// bodyOutlinePath; empty for a circle or an ellipse.
QPolygonF bodyOutlinePolygon(const model::Body& body);

/// Draws one body in its own frame (metres, origin at the centre of mass, y up): a circle or an
/// ellipse with a radius line that shows the rotation, or the outline of a box or polygon. A
/// concave polygon is drawn as its outline, not as the convex pieces the engine splits it into.
/// The fill is the body's colour; a fixed body is darker and hatched. Outlines are cosmetic (the
/// same width in pixels at every zoom).
///
/// The item keeps a copy of what it draws; setPose() moves it. It never reads the world itself.
class BodyStamps;

class BodyItem : public QGraphicsItem {
public:
    /// QGraphicsItem::type() of body items.
    enum { Type = UserType + 1 };

    /// An item for `body`, which is world.bodies[id.index]; placed at the body's current pose.
    BodyItem(model::BodyId id, const model::Body& body, QGraphicsItem* parent = nullptr);

    /// The id of the body this item draws.
    model::BodyId bodyId() const { return m_id; }

    /// Places the item at the body's pose: item → scene is the rotation by state.angle
    /// (counter-clockwise) followed by the translation to state.position.
    void setPose(const model::BodyState& state);

    /// Draws the body red (fill and outline) while it collides, in its own colour otherwise.
    void setColliding(bool colliding);

    /// Whether the item is drawn as colliding.
    bool isColliding() const { return m_colliding; }

    /// Draws a soft body deformed: `outline` is its current outline in the body frame (m), as
    /// controller::softOutline gives it after mapping into the body's frame. An empty
    /// outline goes back to the rigid shape.
    void setDeformedOutline(const std::vector<Vec2>& outline);
    /// Draws a selection outline over the body while `on`.
    void setHighlighted(bool on);

    /// Draws with `look`'s line widths and outlines, and hatches the collision red when it says so
    /// (projector mode).
    void setLook(const CanvasLook& look);

    /// Draws a round body's fill and outline from `stamps` (shared by the canvas's items; nullptr:
    /// draws them in place), where a stamp can stand in (BodyStamps::drawCircle).
    void setStamps(BodyStamps* stamps) { m_stamps = stamps; }

    /// Whether the selection outline is drawn.
    bool isHighlighted() const { return m_highlighted; }

    /// The outline of the body in its own frame, m.
    QPainterPath shape() const override;

    /// The outline's bounding box in the body frame, m.
    QRectF boundingRect() const override;
    /// Fill, hatch (fixed bodies), outline and, for round shapes, the radius line.
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;
    /// BodyItem::Type, for qgraphicsitem_cast.
    int type() const override { return Type; }

private:
    model::BodyId m_id;
    QPainterPath m_outline; ///< what is drawn: the rigid outline, or the deformed one
    QPainterPath m_rigidOutline;
    QPolygonF m_polygon; ///< m_outline as a polygon, drawn quicker (polygon_painting.h); empty for round shapes
    QPolygonF m_rigidPolygon;
    QLineF m_radiusLine; ///< drawn for round shapes; null for polygons
    double m_rigidCircleRadius = 0; ///< m, for a circle; 0 for other shapes
    double m_circleRadius = 0; ///< m_rigidCircleRadius while drawn rigid, 0 deformed (no stamp)
    BodyStamps* m_stamps = nullptr;
    /// The brushes and pen of one colour scheme.
    struct Look {
        QBrush fill;
        QBrush hatch; ///< Qt::NoBrush unless the body is fixed
        QPen pen;
    };
    static Look lookFor(const QColor& color, bool fixed, const CanvasLook& canvasLook);

    QColor m_color; ///< the body's own colour
    bool m_fixed = false;
    double m_lineScale = 1; ///< CanvasLook::lineScale

    Look m_own; ///< in the body's colour
    Look m_red; ///< while colliding
    bool m_colliding = false;
    bool m_highlighted = false;
};

} // namespace impetus::view
