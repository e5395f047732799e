#pragma once
/// \file force_report.h
/// The forces on each body in a world's current state, part by part, for instruments that show
/// them (the app's force vectors). The smooth forces come from the force model itself
/// (computeDerivatives); the contact and joint forces are the impulses the solvers recorded in
/// the last step divided by the time they acted over.

#include "model/scalar.h"
#include "model/world.h"

#include <vector>

namespace impetus::controller {

/// The forces acting on one body, N, each reduced to its centre of mass (torques are left out).
/// A fixed body reports zeros: it has a prescribed motion, so forces do not move it.
struct BodyForces {
    Vec2 gravity = Vec2::Zero(); ///< m·g
    Vec2 springs = Vec2::Zero(); ///< Σ of the scene springs' pulls, k·(L − L₀) + c·dL/dt along each
    Vec2 drag = Vec2::Zero(); ///< Stokes drag −b·v
    /// Σ of the normal contact impulses of the last step over the substep they acted in, N.
    Vec2 contactNormal = Vec2::Zero();
    /// Σ of the friction impulses of the last step over the substep they acted in, N.
    Vec2 contactFriction = Vec2::Zero();
    /// Σ of the pin and rod impulses of the last step over the substep they acted in, N.
    Vec2 joints = Vec2::Zero();
    /// The net force: the sum of the parts, N. Over a step, m·Δv/Δt approaches it.
    Vec2 net() const { return gravity + springs + drag + contactNormal + contactFriction + joints; }
    /// The acceleration of the centre of mass, net() / m, m/s²; zero for a fixed body.
    Vec2 acceleration = Vec2::Zero();
};

/// One BodyForces per body (World::bodies order) in the world's current state.
///  - gravity, springs and drag are the force model's (computeDerivatives) with the other parts
///    switched off, times the body's mass; a soft body reports the sum over its grid's ellipses,
///    in which the grid's own springs and damping cancel;
///  - a contact of the last step (World::contacts) gives body B the impulse Σλₙ·n + Σλₜ·t and
///    body A its opposite, where n is the normal from A to B of the pair's manifold in the current
///    state and t its tangent (n.y, −n.x), divided by the length of the step's substeps;
///  - a joint gives body B its recorded impulse (a pin's 2D impulse, a rod's along the line from
///    A's anchor to B's) and body A the opposite, divided the same way.
/// The substep length is h / max(solverSubsteps(h, kMaxSolverStep), softStability(world).substeps):
/// the split Simulation::step makes when the step has contacts or joints to solve.
std::vector<BodyForces> reportForces(const model::World& world);

} // namespace impetus::controller
