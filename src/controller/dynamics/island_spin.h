#pragma once
/// \file island_spin.h
/// The angular momentum of a closed island through a step's contact solve. Every impulse of the
/// solve acts on both its bodies at one point in space, each body at its own time in the step,
/// which keeps the angular momentum of bodies that only collide, touch and are pinned exactly
/// (docs/physics.md, "Conservation"). The smooth forces are another matter: a spring's pull is
/// computed where its ends were at the step's start, but a body whose contact forces act after
/// its last impact, at T·h, takes the pull from there, and its partner from its own T. The two
/// halves of the pull then act along parallel lines a little apart, and turn the pair by
/// h²·(T_A·v_A − T_B·v_B) × F a step: a zero-g pile with four springs drifted by 4e-5 to 2e-4
/// of its angular momentum in 10 s. An island that nothing outside it touches (no fixed body, no
/// pin to the world, no spring to a world point) in a world with no gravity and no drag has no
/// torque on it at all, so its angular momentum about any point must come out of the step as it
/// went in; IslandSpin gives it that by a rigid turn of the island's velocities, which keeps its
/// momentum and positions.

#include "controller/dynamics/contact_solver.h"
#include "controller/dynamics/solver_body.h"
#include "model/scalar.h"
#include "model/world.h"

#include <cstdint>
#include <span>
#include <vector>

namespace impetus::controller {

class IslandSpin {
public:
    /// True when nothing acts on `world` from outside but its fixed bodies: no gravity, no drag.
    /// Then every island that touches no fixed body keeps its angular momentum exactly.
    static bool applies(const model::World& world);

    /// Gives each closed island of `bodies` (joined by `contacts`, the world's joints and
    /// springs, and each soft grid's ellipses) the angular momentum about the origin that it had
    /// in `start`, by adding δω × (x − x̄) to its members' velocities and δω to its rigid bodies'
    /// spins. `bodies` and `start` follow the world's state list (force_model.h, stateCount);
    /// a soft body's own entry is its grid's aggregate, left to follow its ellipses.
    void keep(const model::World& world, std::span<const model::BodyState> start, std::span<SolverBody> bodies,
              std::span<const ContactConstraint> contacts);

private:
    std::vector<std::uint32_t> m_parent; ///< union–find forest over the state list
    std::vector<std::uint8_t> m_open; ///< per root after the links: touched from outside
    /// Per state-list entry, kg and kg·m²; 0 mass for entries that are not members (fixed
    /// bodies, soft bodies' aggregates).
    std::vector<Scalar> m_mass;
    std::vector<Scalar> m_inertia;
    /// Per root: total mass, Σ m·x at the end, the angular momentum about the origin lost in the
    /// step (start − end), and the moment of inertia about the centre of mass at the end.
    std::vector<Scalar> m_islandMass;
    std::vector<Vec2> m_islandMoment;
    std::vector<Scalar> m_lost;
    std::vector<Scalar> m_islandInertia;
    /// Per root: the angular momentum about the centre of mass at the end, and ½Σ(m·v² + I·ω²).
    std::vector<Scalar> m_islandSpin;
    std::vector<Scalar> m_islandKinetic;
    std::vector<Scalar> m_turn; ///< per root: δω, rad/s
};

} // namespace impetus::controller
