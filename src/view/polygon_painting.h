#pragma once
/// \file polygon_painting.h
/// Filling, hatching and outlining a polygon body the way Qt's raster engine does it fastest.
///
/// Measured on the 2000-body frame-budget scene (docs/benchmarks.md, "The frame budget"): its
/// four turning walls, painted as paths (an antialiased fill, a pattern brush for the fixed
/// bodies' hatch, a 1.5 px cosmetic outline with round joins), took about 5 ms of a 12 ms paint,
/// more than its 2000 circles. Qt strokes a closed outline wider than one pixel through its
/// general stroker and rasteriser, which for a 600 px wall costs 0.45 ms, and fills a pattern
/// brush through a texture fetch per pixel; the same outline as square-capped lines, the same
/// hatch as one-pixel lines, and the fill as a polygon cost a fifteenth of that together.

#include <QBrush>
#include <QPen>
#include <QPolygonF>

class QPainter;

namespace impetus::view {

/// Fills the closed `polygon` (painter coordinates, odd-even rule as a QPainterPath's) with
/// `brush` and no outline.
void fillPolygon(QPainter& painter, const QPolygonF& polygon, const QBrush& brush);

/// Draws a hatch brush (Qt::BDiagPattern or Qt::DiagCrossPattern, in the brush's colour) over
/// the closed `polygon` (painter coordinates) as Qt's pattern would: one-pixel diagonal lines,
/// not antialiased, constants::kHatchSpacingPx apart on the screen's pixel grid, whatever the
/// painter's rotation and scale, anchored at the painter's origin so that the hatch moves with the
/// body. Inside by the odd-even rule. Another brush style is filled as a brush.
void hatchPolygon(QPainter& painter, const QPolygonF& polygon, const QBrush& hatch);

/// Strokes the closed `polygon`'s outline with the cosmetic `pen`. Up to
/// constants::kEdgeLinesMaxWidthPx wide, each edge is drawn as a square-capped line, which
/// covers the round join's disc at every corner (the caps stick out past it by at most
/// (√2 − 1)·w/2, under a third of a pixel); wider, as the outline with the pen's own joins.
void strokePolygon(QPainter& painter, const QPolygonF& polygon, const QPen& pen);

} // namespace impetus::view
