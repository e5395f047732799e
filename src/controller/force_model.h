#pragma once
/// \file force_model.h
/// The smooth forces of a world: gravity, Hooke springs with damping, and Stokes drag.
/// Fixed bodies feel nothing.

#include "model/scalar.h"
#include "model/world.h"

#include <span>
#include <utility>
#include <vector>

namespace impetus::controller {

/// The time derivative of one body's state: (ẋ, θ̇, v̇, ω̇).
struct BodyDerivative {
    Vec2 velocity = Vec2::Zero(); ///< ẋ, m/s
    Scalar angularVelocity = 0; ///< θ̇, rad/s
    Vec2 acceleration = Vec2::Zero(); ///< v̇ = F/m, m/s²
    Scalar angularAcceleration = 0; ///< ω̇ = τ/I, rad/s²
};

/// World positions of a spring's two ends when the bodies are in `states` (states[i] belongs to
/// world.bodies[i]), m.
std::pair<Vec2, Vec2> springEnds(const model::Spring& spring, std::span<const model::BodyState> states);

/// The derivative of every body's state, all bodies as one coupled system:
///  - gravity F = m·g on every dynamic body;
///  - Stokes drag F = −b·v (b = world.settings.drag) on every dynamic body;
///  - each spring pulls its ends together with tension T = k·(L − L₀) + c·dL/dt along the line
///    between the anchors, applying the torque r × F about each centre of mass.
/// Fixed bodies get no acceleration: they keep the velocity they are given.
/// `out` is resized to world.bodies.size().
void computeDerivatives(const model::World& world, std::span<const model::BodyState> states,
                        std::vector<BodyDerivative>& out);

} // namespace impetus::controller
