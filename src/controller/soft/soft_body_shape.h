#pragma once
/// \file soft_body_shape.h
/// What a soft body looks like now, for drawing and for tests: its deformed outline, its
/// ellipses, its springs with their strain, and its lattice cells' area. Qt-free; the view draws
/// what these return.

#include "model/scalar.h"
#include "model/soft_grid.h"
#include "model/world.h"

#include <vector>

namespace impetus::controller {

/// One ellipse of a soft grid in world coordinates.
struct SoftEllipseView {
    Vec2 center = Vec2::Zero(); ///< m
    Scalar radiusX = 0; ///< semi-axis along the ellipse's own x, m
    Scalar radiusY = 0; ///< semi-axis along its own y, m
    Scalar angle = 0; ///< of its x axis, rad (the grid's best fit, model::SoftGrid::fitAngle)
};

/// One spring of a soft grid in world coordinates, with its strain.
struct SoftSpringView {
    Vec2 endA = Vec2::Zero(); ///< m
    Vec2 endB = Vec2::Zero(); ///< m
    Scalar strain = 0; ///< L/L₀ − 1: positive stretched, negative compressed
    bool diagonal = false; ///< shear spring
};

/// The body's outline in world coordinates, deformed with its grid: the shape's outline in the
/// body frame (a box's or polygon's edges cut into pieces about a cell long, or
/// kSoftRoundOutlinePoints points around a circle or ellipse), each point moved by the body's
/// best-fit rigid motion plus the displacement of the grid around it, interpolated bilinearly
/// between the four ellipse centres of the lattice square around it (extrapolated linearly beyond
/// the outermost centres; when a corner is missing, outside the shape, the others' weights are
/// renormalised). Counter-clockwise, not closed (the last point is not repeated).
std::vector<Vec2> softOutline(const model::World& world, const model::SoftGrid& grid);

/// Every ellipse of the grid.
std::vector<SoftEllipseView> softEllipses(const model::World& world, const model::SoftGrid& grid);

/// Every spring of the grid with its strain.
std::vector<SoftSpringView> softSprings(const model::SoftGrid& grid);

/// Area of the grid's lattice cells, m²: each square of four neighbouring ellipse centres, as a
/// quadrilateral at the current positions. Equal to the rest lattice's when undeformed.
Scalar softLatticeArea(const model::SoftGrid& grid);

/// softLatticeArea at the rest positions, m².
Scalar softRestLatticeArea(const model::SoftGrid& grid);

/// Number of lattice cells that are turned inside out: a corner of the quadrilateral of four
/// neighbouring ellipse centres turns clockwise. 0 for a healthy grid.
int invertedSoftCells(const model::SoftGrid& grid);

} // namespace impetus::controller
