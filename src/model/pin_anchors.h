#pragma once
/// \file pin_anchors.h
/// A pin joint's anchors in its bodies' frames, from its hinge point in the world.

#include "model/joint.h"
#include "model/world.h"

namespace impetus::model {

/// Sets `pin`'s anchorA and anchorB from its worldAnchor and its bodies' present poses: each body
/// keeps the hinge in its own frame, local = R(−θ)·(world − x), so that the solver can follow it
/// as the body turns; a pin to the world keeps the world point itself.
inline void derivePinAnchors(const World& world, Joint& pin)
{
    const auto local = [&](BodyId id) {
        const BodyState& state = world.body(id).state;
        return rotate(Vec2(pin.worldAnchor - state.position), -state.angle);
    };
    pin.anchorA = local(pin.bodyA);
    pin.anchorB = pin.bodyB ? local(*pin.bodyB) : pin.worldAnchor;
}

} // namespace impetus::model
