#pragma once
/// \file soak_constants.h
/// The random-scene soak's settings (scripts/soak, docs/testing.md): the closed box every scene
/// is built in, the ranges its bodies are drawn from and the bounds its checks hold the engine to.
/// The ranges are the "extreme but legal" ones; the bounds are derived in docs/physics.md,
/// "Energy in a closed box".

#include "model/scalar.h"

namespace impetus::soak {

/// Inside of the closed box, m: x in [−kBoxHalfWidth, kBoxHalfWidth], y in [0, kBoxHeight].
inline constexpr Scalar kBoxHalfWidth = 5.0;
inline constexpr Scalar kBoxHeight = 10.0; ///< see kBoxHalfWidth
/// Thickness of the four fixed walls, m. At 100 m/s a body moves 0.42 m in a 1/240 s step; a wall
/// several steps' travel thick makes "escaped" mean "passed through", not "was inside for a step".
inline constexpr Scalar kWallThickness = 2.0;
/// Side of the square cells bodies are placed in, one body a cell, so that no two overlap at the
/// start (their bounding circles are at most kMaxBodyRadius). m.
inline constexpr Scalar kCellSize = 2.0;
/// Bounding radii of the bodies drawn, m: from a pebble to most of a cell.
inline constexpr Scalar kMinBodyRadius = 0.1;
inline constexpr Scalar kMaxBodyRadius = 0.8; ///< see kMinBodyRadius

/// Masses drawn (log-uniform), kg: the 1 g to 10 t.
inline constexpr Scalar kMinMass = 1e-3;
inline constexpr Scalar kMaxMass = 1e4; ///< see kMinMass
/// Fastest initial speed of a body, m/s.
inline constexpr Scalar kMaxSpeed = 100.0;
/// Fastest initial spin, rad/s (a body of 0.8 m spinning at this has a rim speed of 24 m/s).
inline constexpr Scalar kMaxSpin = 30.0;
/// Fastest natural angular frequency √(k/μ) of a spring drawn, rad/s (μ the reduced mass). At the
/// default step ωh = 0.17, inside every integrator's stable range; stiffer is legal but then an
/// explicit integrator's blow-up is the expected outcome, not a finding.
inline constexpr Scalar kMaxSpringOmega = 40.0;
/// Largest damping ratio ζ of a spring drawn, c = 2ζ√(kμ).
inline constexpr Scalar kMaxSpringDampingRatio = 0.5;
/// A spring too stiff or too damped for its integrator at the scene's step is softened until the
/// step is this share of its longest stable step (random_scene.cpp, keepSpringStable).
inline constexpr Scalar kSpringStableShare = 0.9;
/// Soft-mode settings drawn: grid density (ellipses per m²), grid stiffness (N/m) and damping
/// (N·s/m). Kept to the lower densities so that a scene with a soft body stays cheap under the
/// sanitizers.
inline constexpr Scalar kMinSoftDensity = 16;
inline constexpr Scalar kMaxSoftDensity = 64; ///< see kMinSoftDensity
inline constexpr Scalar kMinSoftStiffness = 200; ///< see kMinSoftDensity
inline constexpr Scalar kMaxSoftStiffness = 5000; ///< see kMinSoftDensity
inline constexpr Scalar kMaxSoftDamping = 2; ///< see kMinSoftDensity
/// Damping ratios ζ of the grid springs drawn when the damping is given as a ratio (half the soft
/// bodies): from lightly damped to twice critical, the default (constants::kDefaultSoftDampingRatio).
inline constexpr Scalar kMinSoftDampingRatio = 0.1;
inline constexpr Scalar kMaxSoftDampingRatio = 2.0; ///< see kMinSoftDampingRatio
/// Strongest random gravity drawn, m/s² (two g), besides the standard one and zero.
inline constexpr Scalar kMaxGravity = 20.0;
/// Largest Stokes drag drawn, N·s/m.
inline constexpr Scalar kMaxDrag = 1.0;

/// Simulated time each scene runs, s.
inline constexpr Scalar kSoakTime = 10.0;

/// A body (or a soft body's ellipse) whose centre lies deeper than this inside a wall has escaped
/// the box, m. Resting contact allows kLinearSlop (0.5 mm) of overlap; 10 cm of a centre inside a
/// wall is a body that went through it or is on its way.
inline constexpr Scalar kEscapeDepth = 0.1;

/// The energy bound (docs/physics.md, "Energy in a closed box"): with E_floor the lowest energy
/// the box allows (every body at rest at its lowest corner), E(t) − E_floor may exceed
/// E(0) − E_floor by at most this fraction, in a scene where nothing does work. The same 10 % as
/// the growth warning (kEnergyGrowthWarning), on the energy the scene can actually spend.
inline constexpr Scalar kEnergyGrowthBound = 0.1;
/// Absolute allowance of the energy bound, J: rounding on a scene that starts at its floor.
inline constexpr Scalar kEnergyRoundingAllowance = 1e-9;

} // namespace impetus::soak
