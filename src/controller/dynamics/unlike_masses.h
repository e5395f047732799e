#pragma once
/// \file unlike_masses.h
/// Small jointed islands of bodies whose masses differ many times over, solved whole after the
/// velocity passes and after the position passes.
///
/// A pass solves one constraint at a time and hands each impulse to both of its bodies by their
/// inverse masses. Through a light body between heavy ones (a 14 kg polygon on a rod to a 1.2 t
/// one, pressed into the ceiling by a 9 t circle; a 49 g polygon on a rod to a body pinned to an
/// 11 kg one, on the floor) each pass takes only about the mass ratio's inverse out of the heavy
/// bodies' approach, or of their pull on the joint, and the passes of a step leave the light body
/// driven through the wall: soak findings of issue 16. Such an island is small, so this solves
/// all of its joints and contacts at once instead:
///  - velocities: the impulses that bring every joint to what its pass asks for and stop every
///    contact's approach, with the least change of kinetic energy that does (a projection in the
///    mass metric, which can only take kinetic energy out; its impulses, equal and opposite at one
///    point, keep the momentum and the angular momentum);
///  - positions: the least mass-weighted move that closes every joint and takes every contact out
///    of its overlap past the slop, in a few linearised rounds.
/// Contacts between two bodies a joint holds together are left out (a pin and a rod weld them,
/// and their overlap may be what the weld holds).
/// A soft body takes part in the velocity solve as its grid's aggregate, as it does in the joint
/// passes: its ellipses' contacts act on the aggregate at their points, as if the grid were rigid
/// for the solve, and the caller hands the aggregate's change on to the ellipses
/// (Simulation::shareJointMotion). A contact's row keeps what the ellipse's own velocity adds to
/// the grid's rigid motion there, so that the ellipse, moved by the aggregate's change, meets the
/// row. An island with a soft body is left to the position passes (solvePositions says why).
/// The joints of a solved island start the next step cold: their passes' sums are not what acted.

#include "controller/dynamics/solver_body.h"
#include "model/scalar.h"

#include <Eigen/Core>

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace impetus::controller {

class ContactSolver;
class JointSolver;

/// One scalar constraint on two bodies: its value is
/// direction · (s_B·(v_B + ω_B × r_B) − s_A·(v_A + ω_A × r_A)) + offset, with s a body's share
/// of the step (velocityShare: a struck body's velocity moves it only after its last impact); for
/// the position passes, offset alone is the error and s = 1. An impulse λ acts as +λ·direction on
/// B at r_B and −λ·direction on A at r_A.
struct ConstraintRow {
    static constexpr std::uint32_t kNoBody = UINT32_MAX; ///< the fixed world

    std::uint32_t bodyA = kNoBody;
    std::uint32_t bodyB = kNoBody;
    Vec2 direction = Vec2::Zero();
    Vec2 rA = Vec2::Zero(); ///< m
    Vec2 rB = Vec2::Zero(); ///< m
    Scalar shareA = 1;
    Scalar shareB = 1;
    Scalar offset = 0; ///< m/s, or m for a position row
    /// A contact may only push (its value kept ≥ 0, its impulse ≥ 0); a joint row is held at 0
    /// and its impulse has either sign.
    bool contact = false;
};

/// The row's value for the bodies' present velocities, m/s.
Scalar rowValue(const ConstraintRow& row, std::span<const SolverBody> bodies);

/// Minimises ½·xᵀ·A·x + bᵀ·x over x with x_i ≥ 0 where `bounded` is set and x_i free elsewhere
/// (A symmetric positive semi-definite): an active-set method (Lawson–Hanson's, for bounds on
/// some variables only), exact in a finite number of exchanges for a positive-definite A. A tiny
/// multiple of A's diagonal is added to it so that redundant rows have an answer.
Eigen::VectorXd solveBoundedQuadratic(const Eigen::MatrixXd& a, const Eigen::VectorXd& b,
                                      const std::vector<bool>& bounded);

/// Finds the islands that need it and solves each whole. Keeps its scratch between steps.
class UnlikeMassIslands {
public:
    /// After the velocity passes. Bodies joined by joints or by contacts form an island; one with
    /// a joint, bodies whose masses differ more than kMassRatio times, and at most kMaxRows rows
    /// is solved here, and remembered for solvePositions. `movedBy` gives, by body, the body that
    /// moves it here: a soft body's ellipse, its grid's aggregate; empty when each moves itself.
    void solveVelocities(std::span<SolverBody> bodies, const JointSolver& joints, const ContactSolver& contacts,
                         Scalar h, std::span<const std::uint32_t> movedBy = {});
    /// After the position passes, the same islands but those with a soft body, where a joint is
    /// still open or a contact overlaps past the slop.
    void solvePositions(std::span<SolverBody> bodies, const JointSolver& joints, const ContactSolver& contacts,
                        std::span<const std::uint32_t> movedBy = {});
    /// What solvePositions's moves did to the angular momentum, and its take-back, as
    /// ContactSolver::measurePushes and takeBackPushes do.
    void measurePushes(std::span<const SolverBody> bodies);
    void takeBackPushes(std::span<SolverBody> bodies) const;

    /// Islands whose velocities the last call solved (StepProfile::unlikeMassIslands).
    int solvedVelocityIslands() const { return m_solvedVelocities; }
    /// Their bodies, sorted.
    std::span<const std::uint32_t> solvedBodies() const { return m_solvedBodies; }

    static constexpr Scalar kMassRatio = 10;
    static constexpr std::size_t kMaxRows = 96;

private:
    /// Joins bodies into islands and keeps in m_islands those to solve.
    void findIslands(std::span<const SolverBody> bodies, const ContactSolver& contacts);
    /// The rows of island `root`: its joints' (from `jointRows`) and its contacts', at the
    /// velocity passes' arms and normals (h > 0) or at the present poses (positions).
    void gatherRows(std::uint32_t root, std::span<const SolverBody> bodies, const std::vector<ConstraintRow>& jointRows,
                    const ContactSolver& contacts, Scalar h, bool positions);
    /// m_system from m_rows.
    void buildSystem(std::span<const SolverBody> bodies);
    bool moves(std::span<const SolverBody> bodies, std::uint32_t index) const;
    /// The body that moves `index` in the solve (m_movedBy), or the world.
    std::uint32_t mover(std::uint32_t index) const
    {
        return index < m_movedBy.size() ? m_movedBy[index] : index;
    }

    std::span<const std::uint32_t> m_movedBy; ///< the present call's
    std::vector<ConstraintRow> m_jointRows;
    std::vector<ConstraintRow> m_rows;
    Eigen::MatrixXd m_system;
    std::vector<std::uint32_t> m_parent;
    std::vector<std::uint32_t> m_islands; ///< roots of the islands solved whole
    std::vector<std::uint32_t> m_softIslands; ///< those of them that hold a soft body, sorted
    std::vector<std::pair<std::uint32_t, std::uint32_t>> m_jointedPairs; ///< sorted, smaller index first
    struct SavedBody {
        std::uint32_t index;
        Vec2 velocity;
        Scalar angularVelocity;
        Vec2 position;
        Scalar angle;
    };
    std::vector<SavedBody> m_saved;
    /// solvePositions's position impulses between two moving bodies, for the take-back.
    struct Push {
        std::uint32_t bodyA;
        std::uint32_t bodyB;
        Vec2 push; ///< m·kg
        Scalar change = 0; ///< measurePushes's finding, kg·m²/s
    };
    std::vector<Push> m_pushes;
    int m_solvedVelocities = 0;
    std::vector<std::uint32_t> m_solvedBodies;
};

} // namespace impetus::controller
