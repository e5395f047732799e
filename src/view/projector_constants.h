#pragma once
/// \file projector_constants.h
/// The tuning constants of projector mode (View › Projector Mode, projector_mode.h), with their
/// units and reasons. Kept apart from view_constants.h, which holds the normal look.

#include <QColor>

namespace impetus::view::constants {

/// Window text (menus, tool bars, the attribute pane) in projector mode, × the normal size: a
/// 10 pt font at 1.5 × reads from the back of a classroom on a 2 m wide screen.
inline constexpr double kProjectorFontScale = 1.5;

/// The readouts in the status bar (time, energies, momentum, collisions) in projector mode, × the
/// normal size: the numbers the class is asked about, larger again than the rest. Where they do
/// not all fit across the status bar at that size, they are made smaller in steps of
/// kProjectorReadoutStep until they do (ProjectorMode).
inline constexpr double kProjectorReadoutScale = 1.8;

/// The step by which projector mode makes the readouts smaller or larger to fit them, × the normal
/// size; and the room, as a share of the status bar, that must be free before they grow back a
/// step, so that numbers whose width changes by a digit as they run do not make them flicker.
inline constexpr double kProjectorReadoutStep = 0.1;
inline constexpr double kProjectorReadoutGrowRoom = 0.02;

/// QStatusBar's layout: 6 px between its permanent widgets, and the room at its ends (2 px
/// before the first, and the size grip's), px.
inline constexpr int kStatusBarSpacingPx = 6;
inline constexpr int kStatusBarEndsPx = 24;

/// Line widths on the canvas in projector mode (outlines, springs, rods, markers), × the normal
/// widths: a 1.5 px outline thins to nothing on a projector that blurs across 2 to 3 px.
inline constexpr double kProjectorLineScale = 2.5;

/// Grid labels in projector mode, × the normal size.
inline constexpr double kProjectorGridLabelScale = 1.6;

/// Canvas colours in projector mode: white paper and grid lines two to three times darker than
/// the normal ones, since a projector washes out light greys first.
inline const QColor kProjectorBackgroundColor{0xff, 0xff, 0xff};
inline const QColor kProjectorMinorGridColor{0xc8, 0xc8, 0xc8};
inline const QColor kProjectorMajorGridColor{0x8c, 0x8c, 0x8c};
inline const QColor kProjectorAxisColor{0x30, 0x30, 0x30};
inline const QColor kProjectorGridLabelColor{0x10, 0x10, 0x10};
/// Body outlines in projector mode: near-black whatever the fill, so that a pale body still has
/// an edge on a washed-out image.
inline const QColor kProjectorOutlineColor{0x11, 0x11, 0x11};
/// The cross-hatch drawn over a colliding body in projector mode: near-black on the collision red,
/// so a student who cannot tell red from green still sees which bodies touch.
inline const QColor kProjectorCollidingHatchColor{0x11, 0x11, 0x11};

/// Window colours in projector mode (QPalette): black text on white, and a dark blue highlight
/// with white text, the contrast a washed-out projector still shows.
inline const QColor kProjectorWindowColor{0xff, 0xff, 0xff};
inline const QColor kProjectorTextColor{0x00, 0x00, 0x00};
inline const QColor kProjectorButtonColor{0xe8, 0xe8, 0xe8};
inline const QColor kProjectorHighlightColor{0x00, 0x2b, 0x80};

} // namespace impetus::view::constants
