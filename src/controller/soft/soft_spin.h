#pragma once
/// \file soft_spin.h
/// A soft grid's angular momentum through an integrator step. A grid's own forces (its springs,
/// shape matching) pull its ellipses along the lines between them or towards a best-fit rotation
/// of its rest shape, so they exert no torque about its centre of mass: the grid turns only as
/// the forces from outside turn it. Explicit Euler and RK4 do not keep that. Explicit Euler moves
/// every ellipse along the tangent of its orbit, which adds h²·Σ m·(v − v̄) × (a − ā) to the
/// grid's angular momentum each substep: a spinning grid spins itself up, faster the faster it
/// turns, and leaves at hundreds of m/s (soak seed 335). RK4 takes some of it away (0.6 % of a
/// free-spinning box's in 10 s at 1/60 s). These functions measure the torque from outside as
/// the integrator samples it and give each grid the angular momentum that torque leaves it,
/// by a rigid turn of its velocities. See docs/physics.md, "Soft mode: spin".

#include "controller/integration/force_model.h"
#include "model/scalar.h"
#include "model/world.h"

#include <span>
#include <vector>

namespace impetus::controller {

/// Adds `weight` × the torque about each grid's centre of mass of the forces in `rates` with the
/// grid's ellipses at `states` (a state list, force_model.h, stateCount), N·m, to
/// torques[g] for grid g (World::softBodies order). `torques` must have one entry per grid.
void addGridTorques(const model::World& world, std::span<const model::BodyState> states,
                    std::span<const BodyDerivative> rates, Scalar weight, std::span<Scalar> torques);

/// Gives every grid in `end` the angular momentum about its centre of mass that it had in
/// `start` plus h × torques[g] (N·m, as addGridTorques summed them with the integrator's
/// weights), by adding δω × (x − x̄) to its ellipses' velocities: the grid's momentum, its
/// positions and how it is deformed stay as they are.
void keepGridAngularMomentum(const model::World& world, std::span<const model::BodyState> start,
                             std::vector<model::BodyState>& end, Scalar h, std::span<const Scalar> torques);

} // namespace impetus::controller
