#pragma once
/// \file soak_run.h
/// Runs one scene of the soak in the closed box and checks it as it goes (docs/testing.md): every
/// state stays finite, no body leaves the box, and the energy stays within the bound derived in
/// docs/physics.md, "Energy in a closed box".

#include "model/world.h"

#include <optional>
#include <string>

namespace impetus::soak {

/// What a soak run found wrong, first thing only.
struct SoakFinding {
    std::string check; ///< "non-finite", "escaped" or "energy"
    std::string detail; ///< what, which body, by how much
    Scalar time = 0; ///< simulated time at which it was seen, s
};

/// The outcome of one run.
struct SoakResult {
    std::optional<SoakFinding> finding; ///< empty when every check held
    std::int64_t steps = 0; ///< steps taken
    /// Largest (E(t) − E(0)) / (E(0) − E_floor) seen: the growth the energy bound limits to
    /// kEnergyGrowthBound. Not measured (0) under explicit Euler, which is not held to it.
    Scalar largestEnergyGrowth = 0;
};

/// The lowest energy the box allows the dynamic bodies of `world`, J: each at rest with its centre
/// at the box corner lowest in the world's gravity, springs relaxed. Every state of the world
/// inside the box has at least this energy, since kinetic and elastic energy are never negative.
Scalar energyFloor(const model::World& world);

/// Steps `world` (a scene of the soak's box: four walls and dynamic bodies inside) for `seconds`
/// of simulated time, checking after every step. Stops at the first finding.
SoakResult runSoakScene(model::World world, Scalar seconds);

} // namespace impetus::soak
