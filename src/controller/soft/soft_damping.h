#pragma once
/// \file soft_damping.h
/// A soft grid's damping as a pass of its own: once per substep, before the smooth forces are
/// integrated, the grid's dampers act on its velocities implicitly or exactly. The pass is stable
/// at any step, so the grid's damping, however strong, never makes its integration unstable (only
/// its stiffness does, see soft_stability.h). See docs/physics.md, "Soft mode: the damping pass".

#include "model/body.h"
#include "model/scalar.h"
#include "model/soft_grid.h"
#include "model/world.h"

#include <vector>

namespace impetus::controller {

/// Working arrays of the damping pass, kept by a caller that runs it often so that a pass
/// allocates nothing once they have grown to the largest grid.
struct SoftDampingScratch {
    std::vector<Vec2> axis; ///< per grid spring: its unit direction from a to b
    std::vector<Scalar> weight; ///< per grid spring: h·c/m, dimensionless
    std::vector<Vec2> residual; ///< per ellipse: the conjugate gradients' residual, m/s
    std::vector<Vec2> direction; ///< per ellipse: their search direction, m/s
    std::vector<Vec2> product; ///< per ellipse: the system applied to the direction, m/s
};

/// Damps one grid's velocities over a substep of h seconds, in two stages:
///  - the grid springs' dampers, by implicit Euler: (M + h·C)·v' = M·v, with C = Σ c·u·uᵀ over
///    the springs (u along each, c its damping, acting on the relative velocity of its two ends)
///    and M the ellipses' equal masses. Solved by conjugate gradients to a relative residual of
///    kSoftDampingSolveTolerance. It never adds kinetic energy, is stable at any step, treats
///    every spring alike whatever the order of the list, and keeps momentum and angular momentum
///    (C has the rigid motions in its null space);
///  - the pull towards the grid's rigid motion (internal damping β and shape matching's damping
///    c_s): every ellipse's v − v_rigid decays exactly as exp(−(β + c_s/m)·h), with v_rigid =
///    v_c + ω × p the grid's centre-of-mass velocity and angular velocity L/I. This keeps momentum
///    and angular momentum exactly.
/// Positions are not touched. Returns the kinetic energy taken out, J (≥ 0).
Scalar dampSoftGrid(model::SoftGrid& grid, const model::Body& body, Scalar h, SoftDampingScratch& scratch);

/// dampSoftGrid on every grid of `world`; returns the kinetic energy taken out in all, J.
Scalar dampSoftGrids(model::World& world, Scalar h, SoftDampingScratch& scratch);

} // namespace impetus::controller
