#pragma once
/// \file diagnostics.h
/// Conserved and monitored quantities of a world: energy, linear and angular momentum, and the
/// check for a state that is no longer a number.
/// Fixed bodies are excluded: they have infinite mass and a prescribed motion, and counting them
/// would only hide the changes a student is looking for.

#include "model/scalar.h"
#include "model/world.h"

#include <cstddef>
#include <optional>
#include <span>

namespace impetus::controller {

/// Energy of a world, J. A soft body counts as its grid: each ellipse's ½mv² and height, and
/// ½k(L − L₀)² for each grid spring.
struct Energy {
    /// Σ ½mv² + ½Iω² over dynamic bodies.
    Scalar kinetic = 0;
    /// Gravitational, from y = 0 (the origin in general): Σ −m·(g · x) over dynamic bodies, which
    /// is m·g·y for the default downward gravity.
    Scalar potential = 0;
    /// Σ ½k(L − L₀)² over springs.
    Scalar elastic = 0;
    /// kinetic + potential + elastic.
    Scalar total() const { return kinetic + potential + elastic; }
};

/// The energy of `world` in its current state.
Energy computeEnergy(const model::World& world);

/// The energy of `world` with its state list (force_model.h, stateCount: bodies, then soft-grid
/// ellipses) replaced by `states`, J: for the states between the phases of a step.
Energy computeEnergy(const model::World& world, std::span<const model::BodyState> states);

/// Total linear momentum Σ m·v of the dynamic bodies, kg·m/s.
Vec2 linearMomentum(const model::World& world);

/// Total angular momentum about the world origin, Σ (I·ω + m·(x × v)) over dynamic bodies, kg·m²/s.
Scalar angularMomentum(const model::World& world);

/// The index of the first body whose state (position, angle, velocity or angular velocity) is not
/// finite, if any: the sign that the simulation blew up (a step far too large for a stiff spring).
/// Every runner checks with this after its steps: the CLI, the screenshot mode and the window.
std::optional<std::size_t> firstNonFiniteBody(const model::World& world);

} // namespace impetus::controller
