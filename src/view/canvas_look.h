#pragma once
/// \file canvas_look.h
/// How the canvas draws: line widths, grid colours, and what marks a colliding body. A
/// default-constructed CanvasLook is the normal look; CanvasLook::projector() is projector mode's
/// (projector_mode.h).

#include "view/view_constants.h"

#include <QColor>

namespace impetus::view {

/// The canvas's drawing choices that projector mode changes. A value: the canvas hands it to
/// every item it makes.
struct CanvasLook {
    /// Line widths (body outlines, springs, rods, anchor and pin markers) × their normal widths.
    double lineScale = 1;
    /// Body outlines in `outlineColor` rather than a darker shade of each body's fill.
    bool uniformOutline = false;
    QColor outlineColor; ///< the outline colour when uniformOutline
    /// A colliding body gets a cross-hatch in `collidingHatchColor` over its red fill, so that
    /// colour is not the only sign of a collision.
    bool hatchColliding = false;
    QColor collidingHatchColor; ///< the hatch colour when hatchColliding
    QColor background = constants::kBackgroundColor; ///< the paper
    QColor minorGrid = constants::kMinorGridColor; ///< grid lines
    QColor majorGrid = constants::kMajorGridColor; ///< every tenth grid line
    QColor axis = constants::kAxisColor; ///< the lines x = 0 and y = 0
    QColor gridLabel = constants::kGridLabelColor; ///< the labels along the edges
    double gridLabelScale = 1; ///< grid label font × its normal size

    /// Projector mode's look (projector_constants.h): thick lines, dark outlines and grid on white,
    /// hatched collisions.
    static CanvasLook projector();

    bool operator==(const CanvasLook&) const = default; ///< memberwise equality
};

} // namespace impetus::view
