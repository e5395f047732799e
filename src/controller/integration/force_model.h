#pragma once
/// \file force_model.h
/// The smooth forces of a world: gravity, Hooke springs with damping, and Stokes drag.
/// Fixed bodies feel nothing.

#include "controller/task_pair.h"
#include "model/scalar.h"
#include "model/world.h"

#include <array>
#include <span>
#include <utility>
#include <vector>

namespace impetus::controller {

/// The time derivative of one body's state: (ẋ, θ̇, v̇, ω̇).
struct BodyDerivative {
    Vec2 velocity = Vec2::Zero(); ///< ẋ, m/s
    Scalar angularVelocity = 0; ///< θ̇, rad/s
    Vec2 acceleration = Vec2::Zero(); ///< v̇ = F/m, m/s²
    Scalar angularAcceleration = 0; ///< ω̇ = τ/I, rad/s²
};

/// Working arrays of computeDerivatives for one soft grid at a time: its positions, one array
/// per component laid out on the grid's lattice (with empty slots around it), the accelerations of
/// its springs of each direction, and their sum per cell. A caller that evaluates many times keeps
/// one, so that an evaluation allocates nothing.
struct ForceScratch {
    std::vector<Scalar> x; ///< per lattice slot: position x, m
    std::vector<Scalar> y; ///< per lattice slot: position y, m
    std::array<std::vector<Scalar>, 4> fx; ///< per direction and slot: a spring's pull along x, m/s²
    std::array<std::vector<Scalar>, 4> fy; ///< per direction and slot: a spring's pull along y, m/s²
    std::vector<Scalar> ax; ///< per cell: the springs' acceleration along x, m/s²
    std::vector<Scalar> ay; ///< per cell: the springs' acceleration along y, m/s²
    /// Makes every array at least `slots` long (never shrinks).
    void resize(std::size_t slots);
};

/// The length of the world's state list: one entry per body (World::bodies order), then one per
/// soft-grid ellipse (World::softBodies order, each grid's ellipses in order). An ellipse's entry
/// uses position and velocity only; its angle and angular velocity stay zero.
std::size_t stateCount(const model::World& world);

/// Copies the world's state list into `out` (resized to stateCount(world)). With `tasks`, the
/// bodies' states are copied in two halves on two threads.
void gatherStates(const model::World& world, std::vector<model::BodyState>& out, TaskPair* tasks = nullptr);

/// Writes a state list back into the world: bodies' states and the grids' ellipses. With `tasks`,
/// the bodies' states are written in two halves on two threads.
void scatterStates(model::World& world, std::span<const model::BodyState> states, TaskPair* tasks = nullptr);

/// World positions of a spring's two ends when the bodies are in `states` (states[i] belongs to
/// world.bodies[i]), m.
std::pair<Vec2, Vec2> springEnds(const model::Spring& spring, std::span<const model::BodyState> states);

/// The derivative of every entry of the state list (see stateCount), all as one coupled system:
///  - gravity F = m·g on every dynamic body and every soft-grid ellipse;
///  - Stokes drag F = −b·v (b = world.settings.drag) on every dynamic body; a soft body's share
///    of b goes to each ellipse in proportion to its mass (F = −b·(m/M)·v), so that the body as
///    a whole feels the same drag as when rigid;
///  - each spring pulls its ends together with tension T = k·(L − L₀) + c·dL/dt along the line
///    between the anchors, applying the torque r × F about each centre of mass;
///  - each soft-grid spring pulls its two ellipses with T = k·(L − L₀), and every ellipse feels
///    shape matching's pull towards its goal. A grid's damping (its springs' c, shape matching's
///    and the internal damping) is no force here: it is a pass of its own, dampSoftGrids
///    (soft/soft_damping.h), which Simulation runs before every substep.
/// A scene spring attached to a soft body acts on the body's aggregate (centre of mass, the turn
/// of its frame, see softAggregate); its force and torque are shared out over the ellipses as a rigid
/// body would feel them (a = F/M + (τ/I) × r), which keeps momentum and angular momentum.
/// Fixed bodies get no acceleration: they keep the velocity they are given. A soft body's own
/// entry gets a zero derivative: its state follows its grid (updateSoftOwners).
/// `states` must have stateCount(world) entries; `out` is resized to the same.
void computeDerivatives(const model::World& world, std::span<const model::BodyState> states,
                        std::vector<BodyDerivative>& out);

/// The same, with the caller's working arrays: allocates nothing once `scratch` has grown to the
/// world's largest grid.
void computeDerivatives(const model::World& world, std::span<const model::BodyState> states,
                        std::vector<BodyDerivative>& out, ForceScratch& scratch);

} // namespace impetus::controller
