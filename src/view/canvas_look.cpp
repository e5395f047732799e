#include "view/canvas_look.h"

#include "view/projector_constants.h"

namespace impetus::view {

CanvasLook CanvasLook::projector()
{
    CanvasLook look;
    look.lineScale = constants::kProjectorLineScale;
    look.uniformOutline = true;
    look.outlineColor = constants::kProjectorOutlineColor;
    look.hatchColliding = true;
    look.collidingHatchColor = constants::kProjectorCollidingHatchColor;
    look.background = constants::kProjectorBackgroundColor;
    look.minorGrid = constants::kProjectorMinorGridColor;
    look.majorGrid = constants::kProjectorMajorGridColor;
    look.axis = constants::kProjectorAxisColor;
    look.gridLabel = constants::kProjectorGridLabelColor;
    look.gridLabelScale = constants::kProjectorGridLabelScale;
    return look;
}

} // namespace impetus::view
