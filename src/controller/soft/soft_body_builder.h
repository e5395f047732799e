#pragma once
/// \file soft_body_builder.h
/// Soft mode: building a body's grid of ellipses and springs, keeping World::softBodies in step
/// with the bodies, and reading a grid's motion back as the body's state. See docs/physics.md,
/// "Soft mode".

#include "model/body.h"
#include "model/scalar.h"
#include "model/soft_grid.h"
#include "model/world.h"

#include <span>

namespace impetus::controller {

/// True when `body` is simulated as a grid: it has `soft` and is not fixed (a fixed body feels no
/// force, so a grid would never deform; a fixed soft body is simulated as a rigid one).
bool isSoftBody(const model::Body& body);

/// The damping c of every grid spring of a soft body whose ellipses have mass `ellipseMass` (kg),
/// N·s/m. SoftDampingMode::Coefficient: settings.damping. SoftDampingMode::Ratio: c = 2ζ·√(k·m_eff)
/// with ζ = settings.dampingRatio, k = settings.stiffness and m_eff = m/2, the reduced mass of the
/// two equal ellipses a spring joins, so that a pair of ellipses joined by one spring, alone, is
/// damped at ratio ζ (ζ = 1 critical: it returns to rest without overshoot).
Scalar softSpringDamping(const model::SoftSettings& settings, Scalar ellipseMass);

/// The grid of `body` (World::bodies[id]) at `ellipsesPerSquareMeter` = n (1/m²), placed at the
/// body's state. The lattice covers the shape's bounding box in the body frame with
/// round(W·√n) × round(H·√n) cells (at least one each way), so cells are as close to 1/√n square
/// as the box allows; a cell is kept when its centre lies inside the shape. Each kept cell holds
/// an ellipse that fills it (semi-axes = half the cell), of mass body.mass / count. Structural
/// springs join the four neighbours, shear springs the diagonals, all with the body's stiffness
/// and damping and the rest length of the lattice. Precondition: isSoftBody(body).
model::SoftGrid buildSoftGrid(const model::Body& body, model::BodyId id, Scalar ellipsesPerSquareMeter);

/// Places the grid as a rigid copy of `state`: its centre of mass at state.position, turned by
/// state.angle, every ellipse moving with v + ω × r. Records `state` as the owner's state.
void placeSoftGrid(model::SoftGrid& grid, const model::BodyState& state);

/// A grid's motion as one body: centre of mass and its velocity, the turn of its frame and the
/// angular velocity of the ellipses about the centre of mass.
struct SoftAggregate {
    Vec2 position = Vec2::Zero(); ///< centre of mass, m
    /// The turn of the grid's frame, rad: the owner's angle, where joints and scene springs hold
    /// it. It follows the best fit while the grid keeps its shape (see softAggregate).
    Scalar angle = 0;
    /// The best-fit rotation of the rest lattice onto the ellipses, rad, counted on continuously
    /// from the reference's (in the half turn nearest it): what the grid's fitAngle becomes.
    Scalar fitAngle = 0;
    /// The best-fit rotation itself, atan2(Σ r × p, Σ r · p), rad: where shape matching pulls.
    Scalar bestFit = 0;
    Vec2 velocity = Vec2::Zero(); ///< total momentum / mass, m/s
    Scalar angularVelocity = 0; ///< angular momentum about the centre / inertia, rad/s
    Scalar inertia = 0; ///< Σ m·|x − c|² of the ellipses now, kg·m²
};

/// Where a grid's frame was last taken: the ellipses then, its frame angle (the owner's) and its
/// fitAngle then.
struct SoftReference {
    std::span<const Vec2> positions; ///< the ellipses' centres then, m (empty: the same as now)
    Scalar angle = 0; ///< the frame's turn then, rad
    Scalar fitAngle = 0; ///< the best fit then, counted on, rad
};

/// The aggregate of a grid whose ellipses are at `positions` with `velocities`, its frame turned
/// on from `reference`. The best fit θ maximises Σ (x − c)·R(θ)·r (r the rest positions):
/// θ = atan2(Σ r × p, Σ r · p). While the grid keeps its shape the frame turns as the best fit
/// does; a grid crushed or turned inside out (its fit quality |Σ r·p, Σ r×p| / Σ|r|² below
/// constants::kSoftFullFitQuality, then or now) has a best fit that is a guess, which can flip by
/// half a turn within a step, and its frame turns in that proportion as its ellipses turn about
/// their centre instead (the best fit of the ellipses now onto where they were). Turns are taken
/// in the half turn nearest the reference, so that the frame turns continuously and a spinning
/// body's angle keeps counting. A grid of one ellipse keeps the reference's angle.
SoftAggregate softAggregate(const model::SoftGrid& grid, std::span<const Vec2> positions,
                            std::span<const Vec2> velocities, const SoftReference& reference);
/// The aggregate with the grid as it is stored as the reference, its frame at `referenceAngle`
/// (the owner's angle).
SoftAggregate softAggregate(const model::SoftGrid& grid, std::span<const Vec2> positions,
                            std::span<const Vec2> velocities, Scalar referenceAngle);

/// The shape-matching spring constant of each ellipse of `grid`, N/m: kSoftShapeMatching·k·m/M, so
/// that the whole body's pull back to its rest shape is kSoftShapeMatching times the grid springs'
/// stiffness k, at any density. Each ellipse feels F = −k_s·(x − g), with g where the best-fit
/// rigid motion of the rest lattice puts it (Müller et al. 2005); the forces sum to zero and have
/// zero torque about the centre of mass, and store ½k_s·|x − g|² (counted as elastic energy).
Scalar softShapeMatchingStiffness(const model::SoftGrid& grid, const model::Body& body);
/// The damping of each ellipse's pull towards its goal, N·s/m: kSoftShapeMatching·c·m/M, the same
/// ratio to softShapeMatchingStiffness as the grid springs' damping c to their stiffness k. It acts
/// on the ellipse's velocity relative to the grid's rigid motion.
Scalar softShapeMatchingDamping(const model::SoftGrid& grid, const model::Body& body);

/// Makes world.softBodies match world.bodies: builds the grid of every soft body that has none,
/// rebuilds one whose body's shape, mass or soft settings changed, drops grids of bodies that are
/// no longer soft, and places again (as a rigid copy) the grid of a body whose state was set by
/// hand. A body with `"auto"` density gets the density measured once per world by
/// chooseAutoDensity (soft_density.h); later rebuilds reuse that choice. Cheap when nothing
/// changed, so Simulation::step calls it every step; call it after loading a scene to have the
/// grids (and the auto choice) before the first step.
void prepareSoftBodies(model::World& world);

/// Sets every soft body's state to its grid's aggregate (position = centre of mass of its
/// ellipses, velocity = momentum / mass, angle = its frame's turn, angular velocity), and each
/// grid's fitAngle. `previous`, when given, is the world's states (as gatherStates lays them out)
/// from which the grids last moved, owners and ellipses: the frames turn on from there. Without
/// it each grid is taken as it is, from its owner's angle now.
void updateSoftOwners(model::World& world, std::span<const model::BodyState> previous = {});

/// The ellipses of every grid before grid g, i.e. where g's ellipses start in the world's state
/// list after the bodies (see force_model.h, stateCount).
std::size_t softEllipseOffset(const model::World& world, std::size_t g);

} // namespace impetus::controller
