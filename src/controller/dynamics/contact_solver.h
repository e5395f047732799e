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

#include "controller/collision/collision_types.h"
#include "controller/dynamics/contact_batches.h"
#include "controller/dynamics/impact_record.h"
#include "controller/integration/force_model.h"
#include "controller/dynamics/solver_body.h"
#include "controller/task_pair.h"
#include "model/scalar.h"
#include "model/world.h"

#include <Eigen/Core>
#include <Eigen/LU>

#include <array>
#include <cstdint>
#include <functional>
#include <utility>
#include <span>
#include <vector>

namespace impetus::controller {

namespace detail {

/// What the impact pass needs to rule out a contact's impact from bounds alone (staysOpen in
/// contact_impacts.cpp), kept per entry of a body's list of constraints, so that looking again at
/// a struck body's contacts reads one run of memory instead of each constraint's lines. Filled for
/// a body's entries the first time it is struck in a step.
struct ImpactReach {
    std::uint32_t bodyA = 0;
    std::uint32_t bodyB = 0;
    Vec2 normal = Vec2::Zero();
    Scalar shift = 0; ///< least (sB − sA)·n over the points, s the unturned surface arms, m
    Scalar armA = 0; ///< largest |sA|₁ over the points, m
    Scalar armB = 0; ///< largest |sB|₁ over the points, m
    Scalar acceleration = 0; ///< least relative normal acceleration over the points, m/s²
};

} // namespace detail

/// One point of a contact constraint.
struct ContactConstraintPoint {
    Vec2 point = Vec2::Zero(); ///< the contact point (for an impact, where it struck), world, m
    Vec2 rA = Vec2::Zero(); ///< from A's centre of mass to the contact point, m
    Vec2 rB = Vec2::Zero(); ///< from B's centre of mass to the contact point, m
    Vec2 localAnchorA = Vec2::Zero(); ///< A's surface point, A's frame, m (position correction)
    Vec2 localAnchorB = Vec2::Zero(); ///< B's surface point, B's frame, m
    Scalar separation = 0; ///< at the start of the step, m (negative: overlap)
    /// The gap the velocity passes let close over the whole step at the end velocities, m: the
    /// separation, or for a contact of a body struck this step the gap left at the impact spread
    /// over the rest of the step (ContactSolver::moveArmsToImpactTimes).
    Scalar closingGap = 0;
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
    /// Two points whose 2×2 effective-mass matrix is well conditioned, solved together.
    bool blockSolve = false;
    /// The radius of piece A (B) when it is a rigid circle, else 0, m. A circle's surface point
    /// facing the other piece does not turn with the circle: refresh() puts it back on the normal.
    Scalar roundA = 0;
    Scalar roundB = 0;
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
    /// One point of a contact as the velocity passes see it.
    struct VelocityPoint {
        Vec2 rA = Vec2::Zero(); ///< m
        Vec2 rB = Vec2::Zero(); ///< m
        Scalar normalMass = 0; ///< kg
        Scalar tangentMass = 0; ///< kg
        Scalar normalImpulse = 0; ///< accumulated, N·s
        Scalar tangentImpulse = 0; ///< accumulated, N·s
        Scalar gapSpeed = 0; ///< max(separation, 0)/h: how fast a speculative point may close, m/s
    };
    /// A contact as the velocity passes see it: what ContactConstraint holds for them, packed.
    struct VelocityConstraint {
        std::uint32_t bodyA = 0;
        std::uint32_t bodyB = 0;
        int pointCount = 0;
        bool blockSolve = false; ///< two points, solved together
        bool acted = false; ///< an impulse acted this step
        Vec2 normal = Vec2::Zero();
        Scalar friction = 0;
        Scalar k11 = 0, k12 = 0, k22 = 0; ///< the two-point effective-mass matrix K, 1/kg
        Scalar inverse11 = 0, inverse12 = 0, inverse22 = 0; ///< K⁻¹, kg
        std::array<VelocityPoint, 2> points{};
    };

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

    /// Creates the constraints of a step of length h (s), orders them for solving (see
    /// partition) and, in a batched step, lays them out in batches, which keep pointers into this
    /// solver's copies of the bodies (m_batchBodies). `bodies` holds every solver body at the
    /// start of the step, and `derivatives` their smooth-force derivatives, indexed alike (world
    /// bodies, then soft-grid ellipses: force_model.h, stateCount).
    void prepare(const model::World& world, std::span<const PairManifold> manifolds, std::span<SolverBody> bodies,
                 std::span<const BodyDerivative> derivatives, Scalar h);

    /// Brings this step's constraints up to date for a later substep of length h (s), without a
    /// new collision pass or a new build: `bodies` and `derivatives` are those at the start of that
    /// substep. Each point's separation is measured again at the bodies' present poses, from the
    /// surface points and the normal that prepare() fixed in the bodies' frames (a circle's
    /// surface point and normal are put back on the line of contact); its approach velocity and
    /// acceleration are taken afresh, for the impacts; and the accumulated impulses that the last
    /// substep's passes ended with are the warm start. The normal, the lever arms and the masses
    /// stay those of prepare(), as over one step of Box2D v3's substeps. See docs/physics.md,
    /// "Time step and substeps".
    void refresh(std::span<SolverBody> bodies, std::span<const BodyDerivative> derivatives, Scalar h);

    /// Resolves the impacts of this step, in order of approach speed, on `bodies` (which hold the
    /// velocities from before this step's forces). Records each body's impact data. Returns the
    /// number of impacts resolved.
    int solveImpacts(std::span<SolverBody> bodies, Scalar h);

    /// Lets the solver run the halves of a split world on `tasks` (owned by the caller, who keeps it
    /// alive); nullptr runs them one after the other on the calling thread, with the same result.
    void useTasks(TaskPair* tasks) { m_tasks = tasks; }
    /// A step with at least `count` constraints runs its velocity passes in batches
    /// (contact_batches.h); constants::kBatchMinConstraints unless set. Tests set 0 to batch every
    /// world, or SIZE_MAX to batch none.
    void setBatchMinConstraints(std::size_t count) { m_batchMinConstraints = count; }
    /// Appends a record of every impact solveImpacts() resolves to `log` (impact_record.h), or
    /// records nothing (nullptr, the default). The caller keeps `log` alive.
    void setImpactLog(std::vector<ImpactRecord>* log) { m_impactLog = log; }
    /// Whether the impact pass rules out from bounds the contacts of a struck body that cannot meet
    /// within the step (staysOpen in contact_impacts.cpp), before looking at them in full: the
    /// same impacts in the same order either way, to the bit. On unless set; tests compare.
    void setImpactReachBounds(bool on) { m_impactReachBounds = on; }
    /// The contacts the last solveImpacts looked at again after its impacts (what its budget,
    /// kMaxImpactVisitsPerContact, counts).
    std::size_t impactVisits() const { return m_impactVisits; }
    /// Those of impactVisits() it looked at in full, not ruled out by the bounds.
    std::size_t impactLooks() const { return m_impactLooks; }
    /// Whether this step's velocity passes run in batches.
    bool batched() const { return m_batched; }
    /// The lanes of this step's batches, padding included (0 when it is not batched): each colour
    /// fills whole pairs of batches, and a contact that finds no colour free in any round takes a
    /// pair alone (colourGroup).
    std::size_t batchLaneCount() const { return m_batched ? m_batchLanes.size() : 0; }
    /// Starts the velocity passes: packs the constraints for them (unless prepare() has put them
    /// in batches) and applies last step's contact-force impulses (warm starting).
    /// `sharedVelocities`: something else (the joints) changes the bodies' velocities between this
    /// solver's passes, so that each pass must start from the bodies and leave its result there.
    void warmStart(std::span<SolverBody> bodies, Scalar h, bool sharedVelocities);

    /// One sequential-impulse pass over every contact: friction, then the normal constraints.
    void solveVelocities(std::span<SolverBody> bodies);
    /// Ends the velocity passes: writes their impulses into this step's contact records (what the
    /// next step warm-starts from; see swapRecords) and marks the bodies that a contact force
    /// acted on. `writeRecords` false: a batched step's later substeps keep the impulses in their
    /// batch lanes, which refresh() reads, and only the substep that hands the records on (or a
    /// ledger, which reads them every substep) writes them; the records are then not this
    /// substep's until a later call writes them. An unbatched step always writes them.
    void finishVelocities(std::span<SolverBody> bodies, bool writeRecords = true);
    /// Drops every accumulated contact-force impulse (warm start and passes alike), so that
    /// warmStart() then starts the passes cold. The bodies' velocities are the caller's to restore.
    void forgetImpulses();

    /// Exchanges this step's contact records (begun by prepare(), with the impacts from
    /// solveImpacts() and the impulses from finishVelocities()), one per constraint in the same
    /// order, for `records`, whose old contents this solver then overwrites at the next step.
    void swapRecords(std::vector<model::ContactRecord>& records) { m_records.swap(records); }

    /// One non-linear Gauss–Seidel pass on positions. `turnedElsewhere`: bodies may have turned
    /// since this solver's last pass (the first pass of a step, or joints in between). Returns
    /// true when every penetration is within the slop.
    bool solvePositions(std::span<SolverBody> bodies, bool turnedElsewhere);
    /// Before a substep's position passes: clears what they will have pushed, when `measured`
    /// (measurePushes will read it). A large world under gravity, whose pushes nobody reads, does
    /// not go through every position batch for it.
    void beginPositions(bool measured);
    /// After them: measures, contact by contact, what their moving the bodies did to the angular
    /// momentum, P × (v_B − v_A). Contacts with a fixed body are left alone. Only after
    /// beginPositions(true).
    void measurePushes(std::span<const SolverBody> bodies);
    /// Then takes each back by turning the pushed pair's relative velocity
    /// (restoreAngularMomentum; docs/physics.md, "Conservation").
    void takeBackPushes(std::span<SolverBody> bodies) const;

    /// Props (contact_props.cpp). A light body that a fixed body holds against one at least
    /// kPropMassRatio times as heavy (a pebble under a tonne, a chip wedged in a corner by a
    /// sliding crate) is a prop: the velocity passes, which hand each contact's impulse to both
    /// of its bodies, slow the heavy body by about 1/ratio of its approach a pass and so let it
    /// crush the prop through the fixed body. findProps() finds them, after finishVelocities();
    /// it needs the records' touching. A prop holds only where the heavy body pushes it against
    /// the fixed bodies that touch it: within 45° of one's push, or into a corner of two.
    void findProps(std::span<const SolverBody> bodies);
    /// Then stops the heavy body's approach at each prop as if the prop were fixed; the prop's
    /// own velocity is left as the passes made it. Applied after the passes and not kept for the
    /// warm start.
    void solvePropVelocities(std::span<SolverBody> bodies, Scalar h);
    /// After the position passes: moves the heavy body, alone, out of each prop.
    void solvePropPositions(std::span<SolverBody> bodies);

    /// The constraints of this step, with their impact impulses. Their normal and tangent impulses
    /// are the warm start's: the passes' final ones are in the records (swapRecords).
    const std::vector<ContactConstraint>& constraints() const { return m_constraints; }

    /// This step's contact records so far (see swapRecords): after finishVelocities, the passes'
    /// final impulses, one record per constraint in the same order.
    const std::vector<model::ContactRecord>& records() const { return m_records; }

    /// Whether solveImpacts sums the work of its impulses (for the energy ledger; off unless a
    /// ledger is attached).
    void measureImpactWork(bool on) { m_measureImpactWork = on; }
    /// The work of the normal impulses of the last solveImpacts at their times of impact,
    /// Σ j·(u⁻ + u⁺)/2 with u the relative normal velocity just before and after (≤ 0: e < 1
    /// loses ½(1 − e²) of the approach energy), J; 0 when not measured.
    Scalar impactNormalWork() const { return m_impactNormalWork; }
    /// The work of friction during the last solveImpacts, Σ jₜ·(vₜ⁻ + vₜ⁺)/2 (≤ 0), J; 0 when not measured.
    Scalar impactFrictionWork() const { return m_impactFrictionWork; }

    /// Where body `index` is at τ·h of the step being solved, moving straight with its velocity and
    /// the impacts solveImpacts has given it so far, m.
    Vec2 positionAt(std::uint32_t index, const SolverBody& body, Scalar tau, Scalar h) const;
    /// How far body `index` has turned by τ·h, with its angular velocity and the impacts so far, rad.
    Scalar turnAt(std::uint32_t index, const SolverBody& body, Scalar tau, Scalar h) const;
    /// `r` turned by `turn` (turnAt) for body `index`, as rotate() gives it: the impact pass turns
    /// every contact of a struck body by its one turn at the impact's time, so the body's last
    /// sine and cosine are kept, and a turn of zero (a body that does not spin) costs none.
    Vec2 turnedWith(std::uint32_t index, const Vec2& r, Scalar turn) const;

private:
    static constexpr std::uint32_t kNoImpulse = UINT32_MAX;
    static constexpr std::uint8_t kFixedHalf = 255; ///< m_half of a body that cannot move
    /// Numbers the non-empty manifolds of [begin, end) from constraint `out` on: fills
    /// m_manifoldOf, m_previousOf (the matching record of the last step) and m_constraintBodies.
    void numberConstraints(std::span<const PairManifold> manifolds, const std::vector<model::ContactRecord>& previous,
                           std::size_t begin, std::size_t end, std::size_t out);
    /// Orders the constraints for solving. A large world (constants::kParallelMinConstraints) is
    /// cut into two halves that share no movable body, solved side by side on two threads, then
    /// the constraints that join them; a small one keeps the broad phase's order. In a batched
    /// step each of these groups is then coloured for the velocity passes: colour by colour,
    /// kBatchLanes contacts at a time. The order, and so the result, depends only on the world,
    /// not on how many threads the machine has. Reads only the constraints' bodies.
    void partition(std::span<const SolverBody> bodies);
    /// Builds the constraints `indices` (and in a batched step writes each into its lane); the
    /// approaching ones and the point count go to `part` of m_preparedCandidates and
    /// m_preparedPoints.
    void buildConstraints(const model::World& world, std::span<const PairManifold> manifolds,
                          std::span<SolverBody> bodies, std::span<const BodyDerivative> derivatives,
                          std::span<const std::uint32_t> indices, Scalar h, std::size_t part);
    /// Asks for the memory buildConstraints() reads and writes for constraint `index`: its
    /// manifold, the constraint itself, its record and the last step's matching record.
    void prefetchForBuild(std::uint32_t index, std::span<const PairManifold> manifolds,
                          const std::vector<model::ContactRecord>& previous) const;
    /// Asks for the memory refreshConstraint(index) reads: the constraint, and its record (an
    /// unbatched step) or its lane (a batched one).
    void prefetchForRefresh(std::uint32_t index) const;
    /// Whether constraint ci has touched this step: its record says so, or (a batched step whose
    /// records finishVelocities() has not written) a normal impulse of its lane did.
    bool touching(std::uint32_t ci) const;
    /// Asks for what the build and the refresh read of a constraint's two bodies: the solver
    /// bodies, their derivatives and their rotations.
    void prefetchPairBodies(std::uint32_t bodyA, std::uint32_t bodyB, std::span<const SolverBody> bodies,
                            std::span<const BodyDerivative> derivatives) const;
    /// refresh() for constraint `index` of group `part`.
    void refreshConstraint(std::uint32_t index, std::span<SolverBody> bodies,
                           std::span<const BodyDerivative> derivatives, Scalar h, std::size_t part);
    /// Fills m_rotations with every body's (cos, sin) of its angle, and m_rotationAngles with
    /// the angles they are of.
    void computeRotations(std::span<const SolverBody> bodies, bool split);
    /// Brings m_rotations up to every body's angle from the angles computeRotations (or this) last
    /// saw: a body that turned by less than detail::kSmallTurn since is turned by the Taylor
    /// polynomials (small_turn.h), as the batched position passes turn their poses; a larger turn
    /// takes std::cos and std::sin. Only after computeRotations in the same step, for the same bodies.
    void turnRotations(std::span<const SolverBody> bodies, bool split);
    /// Runs solve(group, index) over the groups of partition(): groups 0 and 1 side by side when
    /// the world is split, then group 2.
    void runGroups(const std::function<void(int)>& solve);
    void forEachGroupIndex(const std::function<void(std::span<const std::uint32_t>, int)>& solve);
    void forEachGroup(const std::function<void(std::span<VelocityConstraint>, int)>& solve);
    /// Colours the constraints of each group and lays out the batches' lanes (partition()).
    void colour(std::span<const SolverBody> bodies);
    /// Colours group g's constraints into m_groupLanes[g], and notes each one's lane there.
    void colourGroup(std::span<const SolverBody> bodies, std::size_t g);
    /// Fills lane `laneIndex` of the batches of group g from its constraint (or as padding), for
    /// this step's velocity and position passes.
    void packLane(std::span<SolverBody> bodies, Scalar h, std::size_t g, std::size_t laneIndex);
    /// Lays out the slots of a batched step (m_slotOf): the movable bodies of half 0, then those
    /// of half 1, then every other body; a world that is not split keeps the bodies' order.
    void assignSlots(std::span<const SolverBody> bodies);
    /// Runs work(begin, end) over the slots [0, count): on two threads, cut where half 1's slots
    /// begin, when the world is split.
    void inSlotHalves(std::size_t count, const std::function<void(std::size_t, std::size_t)>& work);
    /// Copies the bodies' velocities into m_batchBodies, or the batches' velocities back.
    void copyVelocitiesIn(std::span<const SolverBody> bodies);
    void copyVelocitiesOut(std::span<SolverBody> bodies);
    /// The slot of group g's scratch body and pose, which its lanes write for a fixed body and a
    /// padding lane reads.
    std::uint32_t scratchSlot(std::size_t g) const
    {
        return static_cast<std::uint32_t>(m_bodyOfSlot.size() + kScratchStride * (g + 1));
    }
    /// solvePositions() for a batched step.
    bool solvePositionsInBatches(std::span<SolverBody> bodies, bool turnedElsewhere);
    /// The batches of group g.
    std::span<ContactBatch> batchesOf(std::size_t g)
    {
        return std::span<ContactBatch>(m_batches).subspan(m_batchGroupStart[g],
                                                          m_batchGroupStart[g + 1] - m_batchGroupStart[g]);
    }

    /// A velocity change an impact gave a body at time τ·h within the step; `previous` chains the
    /// same body's earlier entries.
    struct TimedImpulse {
        std::uint32_t previous = kNoImpulse;
        Scalar tau = 0;
        Vec2 velocityChange = Vec2::Zero();
        Scalar angularVelocityChange = 0;
    };

    /// An approaching constraint waiting in the impact heap.
    struct Candidate {
        Scalar velocity;
        std::uint32_t constraint;
        std::uint32_t version;
    };

    /// After the impacts: each struck body's impulse origin (its place at its last impact), and
    /// the lever arms of every contact of a struck body taken from there (repacked into its batch
    /// lane in a batched step).
    void moveArmsToImpactTimes(std::span<SolverBody> bodies, Scalar h);
    /// The group whose batches hold lane `laneIndex`.
    std::size_t groupOfLane(std::uint32_t laneIndex) const
    {
        const std::size_t batch = laneIndex / kBatchLanes;
        std::size_t g = 0;
        while (g + 1 < m_groups.size() && batch >= m_batchGroupStart[g + 1])
            ++g;
        return g;
    }

    /// Applies an impact impulse (−impulse on A at rA, +impulse on B at rB) at time τ·h and
    /// records it for the bodies' positions at later times.
    void applyImpactImpulse(const ContactConstraint& c, const Vec2& rA, const Vec2& rB, Scalar tau,
                            const Vec2& impulse, std::span<SolverBody> bodies);

    /// A pair the position passes pushed, and the angular momentum that changed, kg·m²/s.
    struct PushedPair {
        std::uint32_t bodyA;
        std::uint32_t bodyB;
        Scalar change;
        Vec2 push; ///< the linear position impulse on B, m·kg
    };
    /// An unbatched step's linear position impulse per constraint, summed over its points and the
    /// passes, m·kg (a batched step keeps them in its position batches).
    std::vector<Vec2> m_pushes;
    std::vector<PushedPair> m_pushedPairs; ///< measurePushes's findings
    bool m_pushesMeasured = false; ///< the last beginPositions cleared the pushes

    std::vector<std::uint32_t> m_struckBodies; ///< the bodies this step's impacts struck, once each
    std::vector<ContactConstraint> m_constraints;
    /// See findProps.
    struct Prop {
        std::uint32_t constraint = 0;
        bool propIsA = false; ///< the prop is the constraint's body A (else B)
    };
    struct PropCandidate {
        std::uint32_t constraint = 0;
        std::uint32_t prop = 0; ///< the light body
    };
    struct PropSupport {
        std::uint32_t body = 0;
        Vec2 direction = Vec2::Zero(); ///< the way a touching fixed body pushes it
        std::uint32_t constraint = 0; ///< the contact with that fixed body
    };
    static constexpr int kPropPasses = 4;
    std::vector<Prop> m_props;
    std::vector<std::uint32_t> m_propFixedContacts; ///< the props' contacts with fixed bodies
    std::vector<PropCandidate> m_propCandidates;
    std::vector<PropSupport> m_propSupports;
    std::vector<std::uint32_t> m_propLight;
    std::vector<Vec2> m_propScratch;
    bool m_measureImpactWork = false; ///< see measureImpactWork
    Scalar m_impactNormalWork = 0; ///< see impactNormalWork, J
    Scalar m_impactFrictionWork = 0; ///< see impactFrictionWork, J
    /// This step's contact records (see swapRecords), begun while each constraint is built and
    /// finished from the batches, so the constraints need not be read again.
    std::vector<model::ContactRecord> m_records;
    /// Each constraint's two solver bodies, packed: partition() and colour() read only these, and
    /// a walk over the whole constraints would touch a cache line per constraint.
    std::vector<std::array<std::uint32_t, 2>> m_constraintBodies;
    std::vector<TimedImpulse> m_impulseTimeline;
    std::vector<std::uint32_t> m_lastTimedImpulse; ///< per body: its latest timeline entry
    std::vector<Candidate> m_candidates; ///< the impact heap
    /// The constraints approaching at the start of the step, and the number of contact points, as
    /// prepare() found them in each part it built (a group, or a half of the constraints).
    std::array<std::vector<Candidate>, 3> m_preparedCandidates;
    std::array<std::size_t, 3> m_preparedPoints{};
    static constexpr std::uint32_t kNoRecord = UINT32_MAX;
    std::vector<std::uint32_t> m_manifoldOf; ///< per constraint: its manifold
    std::vector<std::uint32_t> m_previousOf; ///< per constraint: the last step's record, or kNoRecord
    std::vector<std::uint32_t> m_laneOf; ///< per constraint of a batched step: its lane
    std::vector<std::uint32_t> m_versions; ///< per constraint: bumped when it is looked at again
    /// Per constraint with a fixed body: the impacts it took this step (kMaxFixedImpactsPerContact).
    std::vector<std::uint8_t> m_fixedImpacts;
    /// Per body: the first fixed body that struck it this step (kNoStriker: none), and whether a
    /// second one did, with one of the two moving: the body is pinched between them.
    std::vector<std::uint32_t> m_fixedStriker;
    std::vector<std::uint8_t> m_pinched;
    static constexpr std::uint32_t kNoStriker = UINT32_MAX;
    /// Per body, during solveImpacts: its last turn and that turn's cosine and sine (turnedWith).
    struct TurnCache {
        Scalar turn = 0;
        Scalar cosine = 1;
        Scalar sine = 0;
    };
    mutable std::vector<TurnCache> m_turnCache;
    std::vector<std::uint32_t> m_bodyConstraintStart; ///< per body: start in m_bodyConstraints
    std::vector<std::uint32_t> m_bodyConstraints; ///< constraint indices, grouped by body
    std::vector<std::uint32_t> m_bodyConstraintFill;
    /// What the impact pass needs to rule out a contact's impact from bounds alone, per entry of
    /// m_bodyConstraints and beside it (detail::ImpactReach).
    std::vector<detail::ImpactReach> m_bodyConstraintReach;
    bool m_impactReachBounds = true;
    std::size_t m_impactVisits = 0;
    std::size_t m_impactLooks = 0;
    std::vector<std::uint8_t> m_reachReady; ///< per body: its entries of m_bodyConstraintReach are filled
    /// Fills body `body`'s entries of m_bodyConstraintReach.
    void fillImpactReach(std::uint32_t body);
    /// Constraint indices in solving order: half 0, half 1, then those joining the halves.
    std::array<std::vector<std::uint32_t>, 3> m_groups;
    bool m_split = false; ///< groups 0 and 1 run on two threads
    std::vector<std::uint8_t> m_half; ///< per body: its half, or kFixedHalf
    std::vector<std::pair<Scalar, std::uint32_t>> m_sortKeys;
    std::vector<VelocityConstraint> m_velocityConstraints; ///< in solving order
    std::vector<Vec2> m_rotations; ///< per body: (cos, sin) of its angle, in the position passes
    std::vector<Scalar> m_rotationAngles; ///< per body: the angle m_rotations holds the cos and sin of, rad
    std::array<std::size_t, 4> m_groupStart{}; ///< where each group starts in m_velocityConstraints
    TaskPair* m_tasks = nullptr; ///< the second thread, if any (see useTasks)

    static constexpr std::uint32_t kNoConstraint = UINT32_MAX; ///< a padding lane
    std::size_t m_batchMinConstraints = constants::kBatchMinConstraints;
    std::vector<ImpactRecord>* m_impactLog = nullptr; ///< setImpactLog(); null: no records
    bool m_batched = false; ///< this step's velocity passes run in batches
    std::vector<ContactBatch> m_batches; ///< group 0's, then group 1's, then group 2's
    std::vector<std::uint32_t> m_batchLanes; ///< per lane of every batch: its constraint, or kNoConstraint
    std::array<std::size_t, 4> m_batchGroupStart{}; ///< where each group's batches start
    std::vector<PositionBatch> m_positionBatches; ///< the same lanes as m_batches, for the position passes
    /// Per batch, the lanes (bit `lane`) that have carried a normal impulse at the end of a
    /// substep's passes this step: what finishVelocities() ORs into the records' `touching` when
    /// it writes them.
    std::vector<std::uint8_t> m_touched;
    /// A batched step's passes do not work on the solver bodies but on copies of them, in slots
    /// laid out by half (assignSlots). The halves of a split world are cut by position, so in the
    /// bodies' own order the two threads' bodies alternate, and each thread's passes took 1.3 times
    /// as long side by side as alone, though no cache line was written by both (most likely the
    /// processor, fetching lines next to the ones a thread reads, took lines the other thread was
    /// writing; docs/physics.md, "Two threads").
    std::vector<std::uint32_t> m_slotOf; ///< per body: its slot
    std::vector<std::uint32_t> m_bodyOfSlot; ///< per slot: its body
    std::size_t m_firstHalfSlots = 0; ///< slots of half 0's movable bodies (all, if not split)
    std::size_t m_movableSlots = 0; ///< slots the passes may write to, from 0 (all, if not split)
    bool m_sharedVelocities = false; ///< see warmStart
    /// Per slot the velocities of a batched step's velocity passes, then one scratch body per
    /// group (scratchSlot).
    std::vector<BatchBody> m_batchBodies;
    /// Per slot the poses of a batched step's position passes, then one scratch pose per group.
    std::vector<BatchPose> m_poses;
    /// Slots apart between two groups' scratch bodies and poses, which the two threads write for
    /// every fixed body and padding lane, and from the last body. Both are one cache line, so any
    /// stride keeps them on lines of their own; 3 also keeps them out of one 128-byte pair of
    /// lines, which the processor's adjacent-line prefetcher fetches together.
    static constexpr std::size_t kScratchStride = 3;
    static constexpr std::size_t kScratchSlots = kScratchStride * 4; ///< after the bodies' slots
    std::vector<std::uint64_t> m_colourMasks; ///< per body: the colours its constraints have taken
    std::array<std::vector<std::uint8_t>, 3> m_colourOf; ///< per group: each constraint's colour
    std::array<std::vector<std::uint32_t>, 3> m_groupLanes; ///< per group: its lanes, from 0
    /// Per group: the constraints (places in the group) a colouring round has not coloured yet,
    /// and those it leaves to the next.
    std::array<std::vector<std::uint32_t>, 3> m_uncoloured;
    std::array<std::vector<std::uint32_t>, 3> m_uncolouredNext;
};

} // namespace impetus::controller
