#pragma once
/// \file explain_constants.h
/// How the explainers (Explain menu; docs/explainers.md) draw: colours and sizes.

#include <QColor>

#include <cstdint>

namespace impetus::view::constants {

inline const QColor kExplainPieceA{0x1f, 0x6f, 0xb4}; ///< piece A and its projection (blue)
inline const QColor kExplainPieceB{0xd9, 0x6c, 0x06}; ///< piece B and its projection (orange)
inline const QColor kExplainOverlap{0xc6, 0x28, 0x28}; ///< the overlap on an axis, and the MTV (red)
inline const QColor kExplainSeparating{0x2e, 0x7d, 0x32}; ///< a separating axis's gap (green)
inline const QColor kExplainReference{0x2e, 0x7d, 0x32}; ///< the reference face (green)
inline const QColor kExplainIncident{0x8e, 0x24, 0xaa}; ///< the incident face and clipped points (purple)
inline const QColor kExplainFaint{0x90, 0x90, 0x90}; ///< the axes not being looked at (grey)
inline const QColor kExplainPanelBackground{0xff, 0xff, 0xff, 0xe6}; ///< the text panel, nearly opaque

/// Opacity of the pieces' fill, of 255: faint, so the faces and points drawn over it stand out.
inline constexpr int kExplainFillAlpha = 30;
/// Line widths on screen, px: the highlighted faces and intervals, and everything else.
inline constexpr double kExplainBoldPx = 4.0;
inline constexpr double kExplainThinPx = 1.5;
/// Radius of a drawn contact or clip point, px.
inline constexpr double kExplainPointPx = 5.0;
/// Length of a face's normal arrow, px: long enough to read its direction at any zoom.
inline constexpr double kExplainNormalPx = 28.0;
/// Arrow head size, px.
inline constexpr double kExplainArrowHeadPx = 8.0;
/// How far beside the pair the projection line is drawn, px: clear of both pieces' outlines.
inline constexpr double kExplainAxisClearancePx = 40.0;
/// Gap between the two intervals drawn on the projection line, px (A on one side, B on the other).
inline constexpr double kExplainIntervalGapPx = 6.0;
/// Millimetres per metre: the explainers give lengths in mm, the scale of a contact's overlap.
inline constexpr double kMillimetresPerMetre = 1000.0;
/// Rows of the collision inspector's log at most; older entries are dropped first.
inline constexpr int kCollisionLogMaxEntries = 2000;
/// Steps the collision inspector replays at most to fill its log (the steps before the one shown):
/// a minute at the default 240 Hz.
inline constexpr std::int64_t kCollisionLogMaxReplaySteps = 14400;

} // namespace impetus::view::constants
