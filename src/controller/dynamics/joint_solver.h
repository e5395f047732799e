#pragma once
/// \file joint_solver.h
/// Pin and rod joints as velocity constraints (sequential impulses with warm starting), with
/// position correction by non-linear Gauss–Seidel.
/// Each velocity constraint aims at the anchors' positions at the end of the step (SHAKE), with the
/// joint's error there what it was when its impulses begin to act; see solveVelocities.
///  - Pin: the two anchor points coincide, C = p_B − p_A = 0 (two equations).
///  - Rod: the anchors keep their distance, C = |p_B − p_A| − L = 0 (one equation, pushes or pulls).
/// A joint to the world (bodyB absent) uses a fixed point for B.

#include "controller/dynamics/contact_solver.h"
#include "controller/dynamics/unlike_masses.h"
#include "model/world.h"

#include <Eigen/Core>
#include <Eigen/QR>

#include <cstdint>
#include <span>
#include <vector>

namespace impetus::controller {

/// How much of the step a body's end velocity moves it for, as its joints see it: all of it, or
/// after a struck body's last impact the rest of the step, at least kMinStruckShare
/// (joint_solver.cpp says why).
Scalar velocityShare(const SolverBody& body);

class JointSolver {
public:
    /// Builds the constraints from the world's joints at the bodies' current poses, warm-starting
    /// from each joint's stored impulse, for a step of h seconds. Called after the impacts: a
    /// struck body's joints act from where it is after its last impact and aim at where the step
    /// will really leave it.
    void prepare(const model::World& world, std::span<const SolverBody> bodies, Scalar h);

    /// Applies the stored impulses.
    void warmStart(std::span<SolverBody> bodies);

    /// One pass over every joint's velocity constraint, for a step of h seconds.
    void solveVelocities(std::span<SolverBody> bodies, Scalar h);

    /// One position pass. Returns true when every joint is within kLinearSlop of exact.
    bool solvePositions(std::span<SolverBody> bodies);
    /// Before a substep's position passes: clears what they will have pushed. `turnRotations`:
    /// the passes carry each body's cosine and sine on by its small turns (rotated()) instead of
    /// taking them afresh at every pin; false in a world with soft bodies, whose aggregates are
    /// fitted afresh to their ellipses between the passes.
    void beginPositions(std::size_t bodyCount, bool turnRotations);
    /// After them: measures what their moving two bodies did to the angular momentum, and then
    /// takes it back, as ContactSolver::measurePushes and takeBackPushes do. Joints to the world
    /// are left alone.
    void measurePushes(std::span<const SolverBody> bodies);
    void takeBackPushes(std::span<SolverBody> bodies) const;

    /// Each joint's velocity constraints as rows (one for a rod, two for a pin), as the passes
    /// see them now: a row's value is what the pass would drive to zero, the rod's non-linear end
    /// condition taken to first order about the present velocities. For UnlikeMassIslands.
    void appendRows(std::span<const SolverBody> bodies, Scalar h, std::vector<ConstraintRow>& rows) const;
    /// The same for the position passes at the bodies' present poses: a row's offset is the
    /// joint's error along it (m), its lever arms the anchors'. Shares are 1.
    void appendPositionRows(std::span<const SolverBody> bodies, std::vector<ConstraintRow>& rows) const;

    /// Copies the accumulated impulses back into the world's joints (for warm starting).
    void storeImpulses(model::World& world) const;
    /// Clears the accumulated impulses of the joints on any of `bodies` (sorted): what the passes
    /// summed for bodies that UnlikeMassIslands then solved whole is not what acted on them.
    void forgetImpulses(std::span<const std::uint32_t> bodies);

    bool empty() const { return m_joints.empty(); }

private:
    static constexpr std::uint32_t kWorld = UINT32_MAX; ///< "body" index of the fixed world

    struct Constraint {
        model::JointType type = model::JointType::Pin;
        std::uint32_t bodyA = 0;
        std::uint32_t bodyB = kWorld;
        Vec2 localA = Vec2::Zero(); ///< anchor in A's frame
        Vec2 localB = Vec2::Zero(); ///< anchor in B's frame, or the world point
        /// The lever arms of the velocity impulses, m. A pin between two bodies takes both to one
        /// point, half-way between its anchors, each from the body's impulse origin: its impulses
        /// then keep the angular momentum exactly (docs/physics.md, "Conservation").
        Vec2 rA = Vec2::Zero();
        Vec2 rB = Vec2::Zero();
        Vec2 push = Vec2::Zero(); ///< linear position impulse of this substep's position passes, m·kg
        /// How much of each body's end velocity moves it this step: 1 − T, with T·h its last
        /// impact (Simulation::finishBodyPosition); 1 for a body without impacts.
        Scalar shareA = 1;
        Scalar shareB = 1;
        /// p_B − p_A when the joint's velocity impulses begin to act: at the start of the step,
        /// moved on by a struck body's motion up to its last impact, m. The end velocities move
        /// the anchors on from there.
        Vec2 separation = Vec2::Zero();
        /// How far the anchors' arcs over the step part from their tangents, B's less A's, over
        /// h (m/s): added to their relative velocity in the end condition (see prepare). A rod to
        /// the world that follows its arc takes it afresh in each pass (solveVelocities).
        Vec2 arc = Vec2::Zero();
        /// Rod to the world: its anchor follows its arc at the body's turn as each pass finds it
        /// (set in prepare, where the body's turn over the step is within kMaxArcTurn and the
        /// anchor on or in the body, kMaxArcFollowRatio).
        bool followsArc = false;
        Scalar length = 0; ///< rod length, m
        /// Rod: the distance the velocity passes hold, |separation|, m. Its error against `length`
        /// is the position passes' to remove (solveVelocities says why).
        Scalar heldLength = 0;
        Vec2 axis = Vec2::Zero(); ///< rod: unit vector from A's anchor to B's
        Eigen::Matrix2d pinMass = Eigen::Matrix2d::Zero(); ///< pin: K⁻¹
        Scalar rodMass = 0; ///< rod: 1/K
        Vec2 impulse = Vec2::Zero(); ///< accumulated (rod: x only)
        /// A pin solved with the others of its block (m_blocks index), or −1: alone.
        std::int32_t block = -1;
    };

    /// Pins that share moving bodies, a few of them, solved together: each velocity pass puts
    /// every anchor pair of the block together at once, with the impulses of one linear system,
    /// where a pass one pin at a time converges only slowly through a light body between heavy
    /// ones or the world (docs/physics.md, "Joints").
    struct PinBlock {
        std::vector<std::uint32_t> pins; ///< m_joints indices, in list order
        /// The system's matrix: block (k, l) is what pin l's impulse does to pin k's relative
        /// anchor velocity; factored once per substep.
        Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> system;
        Eigen::VectorXd velocity; ///< working: every pin's relative anchor velocity, m/s
    };

    /// Groups the pins that share moving bodies into blocks, and factors each block's matrix.
    void buildBlocks(std::span<const SolverBody> bodies);
    /// Takes the arcs off a block's pins when the block, nearly a mechanism, would answer them
    /// with speeds far above their own (kMaxArcAmplification).
    void keepArcsIfSound(const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>& system,
                         std::span<const std::uint32_t> pins, std::span<const SolverBody> bodies);
    /// One position pass over a block's pins, all at once. Returns its worst pin error, m.
    Scalar solveBlockPositions(const PinBlock& block, std::span<SolverBody> bodies);

    SolverBody& bodyOf(std::span<SolverBody> bodies, std::uint32_t index);

    /// `local` in the frame of body `index` (or the world) as it stands now: the body's cosine and
    /// sine are taken once per startRotations() with std::cos and std::sin (the bits of rotate()),
    /// then, where beginPositions() allows it, carried on by its small turns since
    /// (small_turn.h) as the passes move it, and otherwise taken afresh as it turns. A large
    /// world's pins took std::cos and std::sin of both bodies' angles at every pin in every pass:
    /// a fifth of v3's joint grid's time.
    Vec2 rotated(const Vec2& local, std::span<const SolverBody> bodies, std::uint32_t index);
    /// Makes rotated() take every body's cosine and sine afresh at its next use.
    void startRotations(std::size_t bodyCount);

    std::vector<Constraint> m_joints;
    std::vector<PinBlock> m_blocks;
    std::vector<Scalar> m_changes; ///< measurePushes's findings, kg·m²/s
    SolverBody m_world; ///< the fixed world: zero inverse mass, at the origin, never moves
    /// Per body, for rotated(): the angle its cosine and sine were last brought to, and them.
    std::vector<Scalar> m_rotationAngles;
    std::vector<Vec2> m_rotations;
    /// Per body, the startRotations() call that last took its rotation afresh.
    std::vector<std::uint32_t> m_rotationStamps;
    std::uint32_t m_rotationStamp = 0;
    bool m_turnRotations = false; ///< see beginPositions
};

} // namespace impetus::controller
