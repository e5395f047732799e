#pragma once
/// \file soft_grid.h
/// The runtime state of a soft body: its grid of ellipses and the springs that join them. Not part
/// of the scene file; controller::prepareSoftBodies builds it from the body's definition, and the
/// simulation moves it. A plain value, so a World that holds it still copies with `=`.

#include "model/body.h"
#include "model/scalar.h"
#include "model/shape.h"

#include <array>
#include <cstdint>
#include <vector>

namespace impetus::model {

/// A Hooke spring with damping along its length between ellipses `a` and `b` of one soft grid:
/// tension T = k·(L − L₀) + c·dL/dt.
struct SoftSpring {
    std::uint32_t a = 0; ///< ellipse index in the grid
    std::uint32_t b = 0; ///< ellipse index in the grid
    Scalar restLength = 0; ///< L₀, m
    Scalar stiffness = 0; ///< k, N/m
    Scalar damping = 0; ///< c, N·s/m
    bool diagonal = false; ///< a shear spring (to a diagonal neighbour), else structural
    bool operator==(const SoftSpring&) const = default; ///< memberwise equality
};

/// The grid springs of one lattice direction laid out over the lattice's cells, for the force
/// loop (controller/force_model): the spring that starts in cell c joins the ellipses of cells c
/// and c + step. A cell where no spring of this direction starts has all three values 0. With
/// this layout the force loop reads both ends of every spring from consecutive memory.
struct SoftSpringField {
    /// Cell index of a spring's `b` end minus that of its `a` end: 1 (right), columns (up),
    /// columns + 1 (up-right) or columns − 1 (up-left).
    std::int32_t step = 0;
    /// The cells [begin, end) hold every spring of this direction (outside it there is none).
    std::int32_t begin = 0;
    std::int32_t end = 0; ///< see begin
    std::vector<Scalar> stiffness; ///< per cell (columns × rows, row-major): k, N/m
    std::vector<Scalar> restLength; ///< per cell: L₀, m
    bool operator==(const SoftSpringField&) const = default; ///< memberwise equality
};

/// The grid of one soft body. Ellipse i sits in cell cells[i] = (column, row) of a columns × rows
/// lattice of cellSize cells; every ellipse has semi-axes cellSize/2 along the body's axes and
/// mass ellipseMass, so that they share the body's mass.
struct SoftGrid {
    BodyId body; ///< the owning body (World::bodies index)

    // What the grid was built from. When the body's definition no longer matches, it is rebuilt.
    Shape shape; ///< the body's shape the grid fills
    MassSpec massSpec; ///< the body's mass choice the ellipses share
    SoftSettings settings; ///< the body's soft-mode settings

    /// The density actually used, 1/m²: settings.ellipsesPerSquareMeter, or the value the auto
    /// measurement chose when settings.autoDensity.
    Scalar ellipsesPerSquareMeter = 0;
    int columns = 0; ///< lattice columns
    int rows = 0; ///< lattice rows
    Vec2 cellSize = Vec2::Zero(); ///< cell width and height, m
    /// Lower-left corner of the lattice in the body frame (origin at the shape's centroid), m.
    Vec2 latticeOrigin = Vec2::Zero();
    /// The grid's own centre of mass in the body frame, m: rest positions are measured from it.
    /// Differs from zero (the shape's centroid) by at most about a cell for an asymmetric shape.
    Vec2 restCentre = Vec2::Zero();
    Scalar ellipseMass = 0; ///< mass of every ellipse, kg
    /// Damping c of every grid spring, N·s/m: settings.damping, or 2ζ·√(k·m/2) from
    /// settings.dampingRatio (controller::softSpringDamping).
    Scalar springDamping = 0;
    /// Bound on ω² of the fastest grid vibration, 1/s²: max over ellipses of 2·λmax(Σ k·u·uᵀ)/m.
    Scalar maxSpringRate = 0;

    std::vector<std::int32_t> cellEllipse; ///< columns × rows, row-major: ellipse index or −1
    std::vector<std::int32_t> ellipseCell; ///< per ellipse: its cell, row·columns + column
    std::vector<Vec2> restPositions; ///< ellipse centres relative to restCentre, body frame, m
    std::vector<SoftSpring> springs; ///< every grid spring, structural and shear
    /// The same springs by direction (right, up, up-right, up-left), laid out on the lattice.
    std::array<SoftSpringField, 4> springFields;

    // Runtime state.
    std::vector<Vec2> positions; ///< ellipse centres, world, m
    std::vector<Vec2> velocities; ///< m/s
    /// The best-fit rotation of the rest lattice onto `positions`, rad, counted on continuously
    /// (controller::softAggregate). The owner's angle, the grid's frame, turns with it while the
    /// grid keeps its shape; a grid that was crushed keeps the frame where its ellipses' turn
    /// took it, and the two then differ.
    Scalar fitAngle = 0;
    /// The state last written to the owning body. A body whose state differs was moved by hand
    /// (the editor), and its grid is placed again as a rigid copy of the new state.
    BodyState ownerState;
    /// True while the grid is a rigid copy of its body's state (controller::placeSoftGrid), false
    /// once a step has moved it on its own. A saved scene keeps the grid's state only when false.
    bool rigidCopy = true;

    bool operator==(const SoftGrid&) const = default; ///< memberwise equality

    /// Number of ellipses.
    std::size_t size() const { return restPositions.size(); }

    /// The ellipse in lattice cell (column, row), or −1 when that cell is empty or outside.
    std::int32_t ellipseAt(int column, int row) const
    {
        if (column < 0 || row < 0 || column >= columns || row >= rows)
            return -1;
        return cellEllipse[static_cast<std::size_t>(row * columns + column)];
    }

    /// Semi-axes of every ellipse, along the body's x and y axes, m.
    Vec2 semiAxes() const { return 0.5 * cellSize; }
};

} // namespace impetus::model
