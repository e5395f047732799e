#pragma once
/// \file constants.h
/// Every tuning constant of the engine, with its unit and the reason for its value.

#include "model/scalar.h"

namespace impetus::constants {

/// Default fixed time step, s. 1/240 s is four physics steps per 60 Hz frame: small enough that
/// RK4 is accurate to ~1e-9 on classroom oscillators (ω ≲ 20 rad/s) and that explicit Euler's
/// energy drift stays visible but slow, which is what a lesson on integrators wants to show.
inline constexpr Scalar kDefaultTimeStep = 1.0 / 240.0;

/// Standard gravity, m/s², used as the default gravity (0, −kStandardGravity).
inline constexpr Scalar kStandardGravity = 9.81;

/// Two polygon vertices closer than this, relative to the polygon's size (the diagonal of its
/// bounding box), are the same point. 1e-9 is far below anything a user can draw (a micrometre on
/// a kilometre-sized shape) but well above double rounding (~1e-16).
inline constexpr Scalar kRelativePointTolerance = 1e-9;

/// A polygon whose area is below this fraction of its bounding-box diagonal squared has no area.
/// Same reasoning as kRelativePointTolerance, squared because it is an area.
inline constexpr Scalar kRelativeAreaTolerance = 1e-12;

} // namespace impetus::constants
