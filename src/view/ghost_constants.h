#pragma once
/// \file ghost_constants.h
/// How View › Compare Integrators draws and what it offers (docs/explainers.md, "Integrator
/// ghosts"): the ghosts' colours, the time steps of the slider and the error plot's run.

#include <QColor>

#include <array>

namespace impetus::view::constants {

/// One colour per integrator, in the order of controller::kComparedIntegrators: explicit Euler
/// orange, semi-implicit Euler teal, RK4 violet. Far apart in hue from each other and from the red
/// of a collision, so that a ghost is told apart from the others and from a colliding body.
inline const std::array<QColor, 3> kGhostColors = {QColor(0xea, 0x58, 0x0c), QColor(0x0d, 0x94, 0x88),
                                                   QColor(0x93, 0x33, 0xea)};
/// Opacity of a ghost's fill, of 255: faint, so the real body shows through.
inline constexpr int kGhostFillAlpha = 40;
/// Opacity of a ghost's outline, of 255: nearly opaque, so that its colour reads at a glance.
inline constexpr int kGhostOutlineAlpha = 220;
/// A ghost's outline width on screen, px.
inline constexpr double kGhostOutlinePx = 2.0;
/// Ghosts lie over the bodies, springs and joints (z 0 … 5) and under the explainers (1e6).
inline constexpr double kGhostZ = 10.0;

/// The time steps the slider offers, s: from 1/1000 s, where every method is close to the
/// textbook, to 1/30 s, one step per frame of a slow film, where explicit Euler visibly fails.
/// Nearly even on a log scale (a factor of about 1.4 apart), so that the error plot's points are
/// evenly spread along its axis; and they include the scenes' usual 1/240 s.
inline constexpr std::array<double, 11> kGhostTimeSteps = {1.0 / 1000, 1.0 / 720, 1.0 / 480, 1.0 / 360,
                                                           1.0 / 240,  1.0 / 180, 1.0 / 120, 1.0 / 90,
                                                           1.0 / 60,   1.0 / 45,  1.0 / 30};
/// The simulated time each point of the error plot runs for, s: long enough for a spring of a
/// second's period to swing through, short enough that the plot is made in a blink.
inline constexpr double kGhostErrorRunSeconds = 1.0;
/// Position errors below this are rounding, not the method's error, m: they are left off the
/// plot and out of the fitted slope (RK4 follows a parabola exactly).
inline constexpr double kGhostRoundingFloor = 1e-12;
/// The most steps the ghosts take to catch up in one go, per integrator: a scrub far along a big
/// scene is taken in slices, so that the window keeps answering while the ghosts catch up.
inline constexpr int kGhostCatchUpSlice = 2000;

} // namespace impetus::view::constants
