#pragma once
/// \file contact_solver.h
/// Contacts as constraints. Two kinds of impulse act at a contact, and they are kept apart:
///
///  - **Impacts** are instantaneous collisions with restitution. They are resolved first, on the
///    velocities from before this step's forces, at their time of impact inside the step. Several
///    bodies in mutual contact (Newton's cradle) are resolved one collision at a time, in order of
///    approach speed, so each pair collides with its own coefficient of restitution.
///  - **Contact forces** keep resting and sliding bodies apart: sequential impulses with
///    accumulated-impulse clamping, warm starting, a 2×2 block solve for two-point manifolds and
///    Coulomb friction |jt| ≤ μ·jn. They never bounce.
///
/// Penetration is removed at the position level (non-linear Gauss–Seidel), which moves bodies and
/// never changes a velocity, so it cannot add kinetic energy. See docs/physics.md, "Contacts".

#include "controller/collision_types.h"
#include "controller/force_model.h"
#include "controller/solver_body.h"
#include "model/scalar.h"
#include "model/world.h"

#include <Eigen/Core>
#include <Eigen/LU>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace impetus::controller {

/// One point of a contact constraint.
struct ContactConstraintPoint {
    Vec2 point = Vec2::Zero(); ///< the contact point (for an impact, where it struck), world, m
    Vec2 rA = Vec2::Zero(); ///< from A's centre of mass to the contact point, m
    Vec2 rB = Vec2::Zero(); ///< from B's centre of mass to the contact point, m
    Vec2 localAnchorA = Vec2::Zero(); ///< A's surface point, A's frame, m (position correction)
    Vec2 localAnchorB = Vec2::Zero(); ///< B's surface point, B's frame, m
    Scalar separation = 0; ///< at the start of the step, m (negative: overlap)
    Scalar normalMass = 0; ///< 1 / (effective mass along the normal), kg
    Scalar tangentMass = 0; ///< 1 / (effective mass along the tangent), kg
    Scalar normalImpulse = 0; ///< accumulated contact-force impulse, N·s (warm-started)
    Scalar tangentImpulse = 0; ///< accumulated friction impulse, N·s (warm-started)
    Scalar impactImpulse = 0; ///< total normal impulse of impacts this step, N·s
    Scalar normalAcceleration = 0; ///< relative normal acceleration from smooth forces, m/s²
    Scalar startNormalVelocity = 0; ///< relative normal velocity at the start of the step, m/s
    Scalar approachVelocity = 0; ///< impacts: relative normal velocity just before, m/s (< 0: approaching)
    bool impacted = false; ///< an impact was resolved at this point this step
    bool carriesLoad = false; ///< it had a contact-force impulse in the last step: resting, not struck
    FeatureId id = 0;
};

/// A contact between two convex pieces, with up to two points sharing a normal.
struct ContactConstraint {
    std::uint32_t bodyA = 0; ///< solver body (index into the solver's body span)
    std::uint32_t pieceA = 0;
    std::uint32_t bodyB = 0; ///< solver body
    std::uint32_t pieceB = 0;
    /// The World::bodies index that owns each piece: the body itself, or a soft body for one of
    /// its ellipses (whose solver body is the ellipse). Materials, records and events use it.
    std::uint32_t ownerA = 0;
    std::uint32_t ownerB = 0;
    Vec2 normal = Vec2::Zero(); ///< unit, from A to B
    Vec2 localNormalA = Vec2::Zero(); ///< the normal in A's frame (position correction)
    Scalar friction = 0; ///< mixed μ
    Scalar restitution = 0; ///< mixed e
    int pointCount = 0;
    std::array<ContactConstraintPoint, 2> points{};
    Eigen::Matrix2d k = Eigen::Matrix2d::Zero(); ///< two-point effective-mass matrix
    Eigen::Matrix2d normalMassBlock = Eigen::Matrix2d::Zero(); ///< its inverse
    bool blockSolve = false; ///< the 2×2 block solve is well conditioned
};

/// Mixing rule for two materials in contact: e = max(eA, eB), the bouncier surface wins, as when
/// a rubber ball bounces on a hard floor; μ = √(μA·μB), which gives exactly μ when both are μ.
Scalar mixRestitution(Scalar a, Scalar b);
Scalar mixFriction(Scalar a, Scalar b);

/// Builds the contact constraints of one step from its manifolds, taking the warm-start impulses
/// from `previous` (the world's contacts from the last step, matched by pieces and feature ids).
/// `derivatives` are the smooth forces' state derivatives at the start of the step, used for the
/// time of impact. Poses and velocities are those at the start of the step.
class ContactSolver {
public:
    /// One pair of pieces and its manifold, in broad-phase order: sorted by (ownerA, pieceA,
    /// ownerB, pieceB), as the world's contact records are.
    struct PairManifold {
        std::uint32_t bodyA = 0; ///< solver body of piece A
        std::uint32_t pieceA = 0;
        std::uint32_t bodyB = 0; ///< solver body of piece B
        std::uint32_t pieceB = 0;
        Manifold manifold;
        std::uint32_t ownerA = 0; ///< World::bodies index owning piece A (see ContactConstraint)
        std::uint32_t ownerB = 0;
    };

    /// Creates the constraints. `bodies` holds every solver body at the start of the step, and
    /// `derivatives` their smooth-force derivatives, indexed alike (world bodies, then soft-grid
    /// ellipses: force_model.h, stateCount).
    void prepare(const model::World& world, std::span<const PairManifold> manifolds,
                 std::span<const SolverBody> bodies, std::span<const BodyDerivative> derivatives);

    /// Resolves the impacts of this step, in order of approach speed, on `bodies` (which hold the
    /// velocities from before this step's forces). Records each body's impact data. Returns the
    /// number of impacts resolved.
    int solveImpacts(std::span<SolverBody> bodies, Scalar h);

    /// Applies last step's contact-force impulses (warm starting).
    void warmStart(std::span<SolverBody> bodies);

    /// One sequential-impulse pass over every contact: friction, then the normal constraints.
    void solveVelocities(std::span<SolverBody> bodies, Scalar h);

    /// One non-linear Gauss–Seidel pass on positions. Returns true when every penetration is
    /// within the slop.
    bool solvePositions(std::span<SolverBody> bodies);

    /// The constraints of this step, with their impulses.
    const std::vector<ContactConstraint>& constraints() const { return m_constraints; }

    /// The contact records to keep in the world for the next step (warm starting, begin events).
    /// `touching` must hold one flag per constraint.
    std::vector<model::ContactRecord> records(const std::vector<bool>& touching) const;

private:
    static constexpr std::uint32_t kNoImpulse = UINT32_MAX;

    /// A velocity change an impact gave a body at time τ·h within the step; `previous` chains the
    /// same body's earlier entries.
    struct TimedImpulse {
        std::uint32_t previous = kNoImpulse;
        Scalar tau = 0;
        Vec2 velocityChange = Vec2::Zero();
    };

    /// An approaching constraint waiting in the impact heap.
    struct Candidate {
        Scalar velocity;
        std::uint32_t constraint;
        std::uint32_t version;
    };

    /// Where body `index` is at τ·h, moving straight with its velocity and the impacts so far.
    Vec2 positionAt(std::uint32_t index, const SolverBody& body, Scalar tau, Scalar h) const;

    /// Applies an impact impulse (−impulse on A at rA, +impulse on B at rB) at time τ·h and
    /// records it for the bodies' positions at later times.
    void applyImpactImpulse(const ContactConstraint& c, const Vec2& rA, const Vec2& rB, Scalar tau,
                            const Vec2& impulse, std::span<SolverBody> bodies);

    std::vector<ContactConstraint> m_constraints;
    std::vector<TimedImpulse> m_impulseTimeline;
    std::vector<std::uint32_t> m_lastTimedImpulse; ///< per body: its latest timeline entry
    std::vector<Candidate> m_candidates; ///< the impact heap
    std::vector<std::uint32_t> m_versions; ///< per constraint: bumped when it is looked at again
    std::vector<std::uint32_t> m_bodyConstraintStart; ///< per body: start in m_bodyConstraints
    std::vector<std::uint32_t> m_bodyConstraints; ///< constraint indices, grouped by body
    std::vector<std::uint32_t> m_bodyConstraintFill;
};

} // namespace impetus::controller
