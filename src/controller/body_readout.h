#pragma once
/// \file body_readout.h
/// What an instrument reads off one body: its state and the quantities that follow from it.

#include "model/scalar.h"
#include "model/world.h"

#include <cstdint>

namespace impetus::controller {

/// One body's readout in a world's current state. Energies follow diagnostics.h: a fixed body has
/// none, potential energy is measured from y = 0 (the origin in general).
struct BodyReadout {
    Vec2 position = Vec2::Zero(); ///< centre of mass, m
    Scalar angle = 0; ///< rad, counter-clockwise
    Vec2 velocity = Vec2::Zero(); ///< of the centre of mass, m/s
    Scalar angularVelocity = 0; ///< ω, rad/s
    Scalar speed = 0; ///< |v|, m/s
    Vec2 momentum = Vec2::Zero(); ///< m·v, kg·m/s (0 for a fixed body)
    Scalar kinetic = 0; ///< ½mv² + ½Iω², J
    Scalar potential = 0; ///< −m·(g · x), J: m·g·y under the default gravity
    bool colliding = false; ///< touching another body at the end of the last step
    std::int64_t collisions = 0; ///< contact-begin events the body took part in
};

/// The readout of body `id` of `world`. Precondition: id.index < world.bodies.size().
BodyReadout readBody(const model::World& world, model::BodyId id);

} // namespace impetus::controller
