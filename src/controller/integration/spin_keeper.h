#pragma once
/// \file spin_keeper.h
/// The angular momentum of bodies that pull on each other, through an integrator step. Forces
/// between two bodies act along the line between their points of action (a spring), or towards a
/// best-fit rotation of a rest shape (a soft grid's shape matching), so they exert no torque on
/// the pair or the grid as a whole: a group of bodies joined by springs, and a soft grid's
/// ellipses, turn only as the forces from outside turn them. Explicit Euler and RK4 do not keep
/// that. Explicit Euler moves every body along the tangent of its orbit, which adds
/// h²·Σ m·(v − v̄) × (a − ā) to the group's angular momentum each step: a spinning soft grid spun
/// itself up, faster the faster it turned, and left at hundreds of m/s (soak seed 335); five boxes
/// on four springs, turning, gained 10 % of their angular momentum in 10 s at 1/60 s. RK4 takes a
/// little away (0.6 % of a free-spinning soft box's in 10 s at 1/60 s). The keeper measures the torque
/// from outside as the integrator samples it and gives each group the angular momentum that
/// torque leaves it, by a rigid turn of its velocities. See docs/physics.md, "Conservation".

#include "controller/integration/force_model.h"
#include "model/scalar.h"
#include "model/world.h"

#include <cstdint>
#include <span>
#include <vector>

namespace impetus::controller {

/// Keeps the angular momentum of a world's groups through one integrator step. A group is a soft
/// grid's ellipses, or dynamic rigid bodies joined by scene springs (fixed bodies and soft bodies
/// do not join rigid ones: their pull counts as from outside).
class SpinKeeper {
public:
    /// Finds the groups of `world`, whose state list (force_model.h, stateCount) the step uses,
    /// and clears the torques. Returns false when there is none (the step then needs nothing).
    bool begin(const model::World& world);

    /// Adds `weight` × the torque about each group's centre of mass of the forces in `rates`,
    /// with the bodies at `states` (N·m).
    void addTorques(std::span<const model::BodyState> states, std::span<const BodyDerivative> rates, Scalar weight);

    /// Gives every group in `end` the angular momentum about its centre of mass that it had in
    /// `start` plus h × its summed torque, by adding δω × (x − x̄) to its bodies' velocities and
    /// δω to the rigid ones' spins: the group's momentum and positions stay as they are.
    void keep(std::span<const model::BodyState> start, std::vector<model::BodyState>& end, Scalar h) const;

private:
    /// Group g's members are m_members[m_first[g] … m_first[g + 1]), state-list indices.
    std::vector<std::uint32_t> m_members;
    std::vector<std::uint32_t> m_first;
    std::vector<Scalar> m_mass; ///< per member, kg
    std::vector<Scalar> m_inertia; ///< per member, kg·m² (0 for an ellipse, which does not spin)
    std::vector<Scalar> m_torques; ///< per group, the weighted sum, N·m
    std::vector<std::uint32_t> m_parent; ///< union–find forest over the bodies, working
};

} // namespace impetus::controller
