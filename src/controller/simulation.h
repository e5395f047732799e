#pragma once
/// \file simulation.h
/// The fixed-step driver. Simulation::step reads top to bottom as the phases it runs.

#include "controller/collision/broad_phase.h"
#include "controller/collision/fixed_body_guard.h"
#include "controller/collision_events.h"
#include "controller/collision/colliders.h"
#include "controller/dynamics/contact_solver.h"
#include "controller/dynamics/island_spin.h"
#include "controller/integration/integrator.h"
#include "controller/dynamics/joint_solver.h"
#include "controller/dynamics/unlike_masses.h"
#include "controller/soft/soft_damping.h"
#include "controller/soft/soft_stability.h"
#include "controller/task_pair.h"
#include "model/constants.h"
#include "model/world.h"

#include <memory>
#include <vector>

namespace impetus::controller {

class EnergyLedger;

/// Wall-clock time spent in each phase of the last step, ms. For benchmarks and profiling only;
/// nothing physical depends on it.
struct StepProfile {
    double broadMs = 0; ///< collider placement and the broad phase
    double narrowMs = 0; ///< contact manifolds of the candidate pairs
    double integrateMs = 0; ///< smooth forces and their integration
    double solveMs = 0; ///< impacts, contact and joint velocities, position correction
    // The parts of solveMs:
    double prepareMs = 0; ///< contact and joint constraints built, warm-start impulses matched
    double impactsMs = 0; ///< the impact pass
    double velocityMs = 0; ///< warm start and the velocity passes
    double positionMs = 0; ///< positions and the position passes
    double eventsMs = 0; ///< colliding flags, contact-begin events, contact records (not in solveMs)
    double totalMs = 0; ///< the whole step
    int contacts = 0; ///< contact constraints (pairs of pieces in contact or speculative)
    /// Lanes of the batched velocity passes, padding included (ContactSolver::batchLaneCount);
    /// 0 in a step that is not batched. Summed over substeps, as contacts.
    int batchLanes = 0;
    int impacts = 0; ///< impacts resolved
    /// The contacts the impact pass looked at again after its impacts, summed over the substeps
    /// (ContactSolver::impactVisits).
    std::size_t impactVisits = 0;
    /// Those of impactVisits the impact pass looked at in full, not ruled out by its bounds.
    std::size_t impactLooks = 0;
    int substeps = 0; ///< substeps the step was split into (solverSubsteps, soft grids)
    /// Islands of unlike masses whose velocities were solved whole (UnlikeMassIslands), summed
    /// over the substeps.
    int unlikeMassIslands = 0;
    /// Collision passes (broad and narrow phase) the step ran: one for a rigid world at rest or
    /// nearly however many substeps it takes; one per substep where bodies move fast or with soft
    /// bodies (Simulation::step).
    int collisionPasses = 0;
    /// Centres of moving bodies or soft ellipses that the fixed-body guard put back where their
    /// path entered a fixed body (FixedBodyGuard), summed over the substeps: 0 wherever the contact
    /// solve holds.
    int guardedCentres = 0;
};

/// Iteration counts of the constraint solvers.
struct SolverSettings {
    int velocityIterations = constants::kVelocityIterations; ///< sequential-impulse passes, 8
    int positionIterations = constants::kPositionIterations; ///< position-correction passes (at most), 3
    /// Use a second thread for large worlds (docs/physics.md, "Two threads"). The result is the
    /// same bits either way; false saves the thread.
    bool secondThread = true;
    /// A step with at least this many contact constraints runs its velocity passes in batches of
    /// contacts of one colour (contact_batches.h). Tests set 0 to batch every world.
    std::size_t batchMinConstraints = constants::kBatchMinConstraints;
    /// The longest substep the solvers take, s: a longer world step is split into equal substeps
    /// (solverSubsteps). Tests set it to the world step to see one unsplit step.
    Scalar maxSubstep = constants::kMaxSolverStep;
    /// The impact pass rules out from bounds the contacts of a struck body that cannot meet within
    /// the step before looking at them in full (ContactSolver::setImpactReachBounds). The same
    /// bits either way; tests set false to compare.
    bool impactReachBounds = true;
};

/// The equal substeps a step of h seconds is split into so that none is longer than maxSubstep:
/// ⌈h / maxSubstep⌉, 1 for h ≤ maxSubstep (a step a hair longer by rounding, such as 4 × (1/240)
/// against 1/60, is not split again), and at most constants::kMaxSolverSubsteps.
int solverSubsteps(Scalar h, Scalar maxSubstep);

/// The equal substeps a step of h seconds needs so that Stokes drag stays stable on every dynamic
/// body: γ·(h / substeps) ≤ constants::kMaxDragRateStep with γ = drag / m the body's drag rate;
/// 1 without drag, at most constants::kMaxSolverSubsteps.
int dragSubsteps(const model::World& world, Scalar h);

/// The equal substeps a step of h seconds needs so that no body other than a circle or a soft
/// body turns by more than an eighth of a turn within one: ⌈|ω|·h / (π/4)⌉ for the fastest
/// spinning one, fixed bodies included; 1 for slower spins, at most constants::kMaxSolverSubsteps.
/// In a world whose dynamic bodies' masses lie more than UnlikeMassIslands::kMassRatio apart,
/// 0.1 rad instead of π/4 (a light body driven against a wall by a heavy one).
/// A pinned body counts whatever its shape, and a rod whose ends go round each other at Ω counts
/// as ⌈Ω·h / 0.2⌉, the turn at which the rod's pass keeps the energy to about 1 %.
int spinSubsteps(const model::World& world, Scalar h);

/// The equal substeps a step of h seconds needs so that a large world's dynamic bodies travel, on
/// average, no more than a quarter of their bounding radius within one (kMaxCrowdTravelPerSubstep):
/// each contact's margins grow with the travel, and a heap flung at 100–200 m/s (the spinner's
/// opening) made dozens of speculative contacts a body, which cost more than the substeps that
/// keep each body among its neighbours. 1 for a world of fewer than
/// constants::kLocalStrikeShareMinBodies bodies, whose step is split for its physics alone.
int crowdSubsteps(const model::World& world, Scalar h);

/// How far the fastest moving body of `world` travels in h seconds at its present speed, m: its
/// speed plus its spin times its bounding radius, times h. Fixed bodies that move count too.
Scalar fastestTravel(const model::World& world, Scalar h);

/// Whether no body of `world` moves so far in h seconds that a step's contacts, found once with
/// margins for the whole step, would cost more than finding them every substep: each body's
/// travel (as fastestTravel's) at most kReuseContactsMaxTravel, or for a dynamic body at most
/// kReuseContactsMaxTravelFraction of its bounding radius up to kReuseContactsMaxBodyTravel.
bool contactsLastTheStep(const model::World& world, Scalar h);

/// Steps a world with its fixed time step. Soft bodies (docs/physics.md, "Soft mode") are built
/// into grids on the first step that needs them (prepareSoftBodies). A step is split into equal
/// substeps when it is longer than the solver's longest step (solverSubsteps) and has contacts or
/// joints to solve, when a grid is too stiff for the integrator at the world's step
/// (softStability), or when drag would make a light body's velocity blow up (dragSubsteps),
/// whichever needs more.
/// Each substep runs every phase below. Holds only scratch state (buffers, the broad phase's
/// sort order), so one Simulation can step any world; the world itself carries everything
/// physical, including the contact impulses that warm-start the next step.
class Simulation {
public:
    /// A simulation whose solvers use `settings`; the world to step is passed to each step().
    explicit Simulation(SolverSettings settings = {});

    /// Advances `world` by one fixed step world.settings.timeStep with world.settings.integrator,
    /// resolving collisions, contacts and joints.
    void step(model::World& world);

    /// Timing of the last step() (summed over its substeps).
    const StepProfile& profile() const { return m_profile; }

    /// The contacts that began in the last step (the collision log's new entries).
    const std::vector<CollisionEvent>& events() const { return m_events; }

    /// The bodies the fixed-body guard put back in the last step (fixed_body_guard.h), once per
    /// pair of body and fixed body, in the order the substeps met them: empty wherever the contact
    /// solve held. The app tells of them, as the solve failed there.
    const std::vector<KeptOut>& keptOut() const { return m_keptOut; }

    /// Appends a record of every impact from the next step on to `log` (impact_record.h), or
    /// stops recording (nullptr, the default). The caller keeps `log` alive.
    void setImpactLog(std::vector<ImpactRecord>* log) { m_contactSolver.setImpactLog(log); }

    /// The substeps of the last step and why (one, with no message, without soft bodies).
    const SoftStability& stability() const { return m_stability; }

    /// Books every substep's energy by cause in `ledger` (energy_ledger.h), or stops booking for
    /// nullptr (the default, which costs nothing). The caller keeps the ledger alive.
    void setLedger(EnergyLedger* ledger);

private:
    /// What an entry of the world's state list is, for the solvers.
    enum class Entry : std::uint8_t { Rigid, Fixed, SoftOwner, Ellipse };

    Integrator& integratorFor(model::IntegratorKind kind);
    /// How a substep finds its contacts.
    enum class Contacts : std::uint8_t {
        Find, ///< phases 0 and 1 afresh, with margins for the substep
        FindForStep, ///< phases 0 and 1 with margins for the whole step, which later substeps reuse
        Found, ///< startAndCollide has run for this substep already (substepsFor)
        Reuse, ///< the start states afresh, and the step's constraints refreshed (ContactSolver::refresh)
    };
    /// One pass of every phase over h seconds of a step of `step` seconds, ending at simulated time
    /// endTime. `handOver`: the substep hands its contacts to the world and tells what began (a
    /// step whose substeps reuse its contacts does so once, at its last).
    void substep(model::World& world, Scalar h, Scalar step, Scalar endTime, Contacts contacts, bool handOver);
    /// Phases 0 and 1 of a step of h seconds: the start states, the solver bodies, the smooth
    /// forces' derivatives, and the contacts found with speculative margins for h.
    void startAndCollide(const model::World& world, Scalar h);
    /// Keeps every solver body's velocity (for holdContactEnergy) and returns their kinetic
    /// energy, J.
    Scalar saveVelocities();
    /// Σ ½m·v² + ½I·ω² over the solver bodies that can move, J.
    Scalar kineticEnergyOfBodies() const;
    /// After the contact velocity passes of a world without joints: when they left more kinetic
    /// energy than `kineticBefore`, runs more passes, then (if that is not enough) starts them over
    /// from the saved velocities with no impulse (constants::kMaxExtraVelocityRounds).
    void holdContactEnergy(Scalar kineticBefore, Scalar h);
    /// The substeps this step of `world` takes (docs/physics.md, "Time step and substeps"): what
    /// its soft grids need, and for a step longer than the solver's longest, solverSubsteps
    /// when the step has contacts or joints to solve (or the last step ended with contacts). A world with neither runs its integrator
    /// over the whole step, as the user chose it; `collided` tells that this function ran
    /// startAndCollide for the whole step, which the step's first substep can then use.
    int substepsFor(model::World& world, bool& collided);
    void setUpSolverBodies(const model::World& world);
    void collide(const model::World& world, Scalar h);
    /// A large world's strike shares (constants::kLocalStrikeShareMinBodies): adds to each
    /// dynamic body's margin, and to its pieces' boxes in m_colliders (built with the bodies' own
    /// margins), 2·h times the speed at which the fastest striker that can reach it approaches
    /// it: a body whose box reaches its box (at the difference of their velocities and their
    /// spins), a moving fixed body at its velocity there, or one that reaches it down a chain of
    /// such bodies (kStrikeChainLinks in simulation.cpp).
    void addStrikeShares(const model::World& world, Scalar h);
    /// A bound on how fast a point of rigid body `first` approaches a point of `second` at the
    /// step's start: the difference of their velocities plus each one's spin at its bounding
    /// radius, m/s.
    Scalar approachSpeed(const model::World& world, std::uint32_t first, std::uint32_t second) const;
    /// How far apart two bodies' pieces may be for their pair to get contact points: their
    /// margins, with the two travels replaced by the travel towards each other (rigid pairs).
    Scalar pairDistance(std::uint32_t first, std::uint32_t second, Scalar h) const;
    /// The broad phase of a world with soft bodies: fills m_pairs (piece indices, sorted).
    void findPairsWithSoftBodies(const model::World& world);
    void integratePositions(const model::World& world, Scalar h);
    /// integratePositions for state i (docs/physics.md, "Contacts").
    void finishBodyPosition(std::size_t i, Scalar h);
    /// The second thread for loops over a large world's bodies, or null for a small world.
    TaskPair* bodyTasks(const model::World& world) const;
    /// Sets each soft body's solver body (and m_softAggregates) to the aggregate of its
    /// ellipses' solver bodies: where the joints see it.
    void syncSoftAggregates(const model::World& world);
    /// Hands what joints did to a soft body's aggregate on to its ellipses, as a rigid motion:
    /// velocities (positions = false) or positions (true).
    void shareJointMotion(const model::World& world, bool positions);

    SolverSettings m_settings;
    std::unique_ptr<Integrator> m_euler;
    std::unique_ptr<Integrator> m_semiImplicitEuler;
    std::unique_ptr<Integrator> m_rk4;
    /// The second thread, shared by the narrow phase and the contact solver. Behind a pointer so
    /// that the contact solver's reference to it survives moving the Simulation.
    std::unique_ptr<TaskPair> m_tasks;
    StepProfile m_profile;

    // Scratch, reused from step to step.
    std::vector<model::BodyState> m_startStates;
    std::vector<model::BodyState> m_endStates;
    std::vector<BodyDerivative> m_startDerivatives;
    ForceScratch m_forceScratch; ///< computeDerivatives' working arrays
    std::vector<SolverBody> m_bodies; ///< one per state-list entry (bodies, then soft ellipses)
    /// A solver body's velocity before the contact velocity passes (saveVelocities).
    struct SavedVelocity {
        Vec2 velocity = Vec2::Zero(); ///< m/s
        Scalar angularVelocity = 0; ///< rad/s
    };
    std::vector<SavedVelocity> m_savedVelocities;
    std::vector<Entry> m_entries;
    /// Per soft grid: its aggregate pose and velocity as the joint solver was handed it.
    std::vector<SolverBody> m_softAggregates;
    /// By solver body, the one that moves it in UnlikeMassIslands: a soft body's ellipse, its
    /// grid's aggregate; any other, itself. Empty without soft bodies.
    std::vector<std::uint32_t> m_movedBy;
    SoftStability m_stability;
    std::vector<Vec2> m_scratchPositions;
    std::vector<Vec2> m_scratchVelocities;
    SoftDampingScratch m_dampingScratch; ///< the soft grids' damping pass's working arrays
    std::vector<Scalar> m_margins;
    /// Per body, the speed (m/s) at which it can strike another: 0 for a fixed body, a soft
    /// body's fastest ellipse's.
    std::vector<Scalar> m_strikeSpeeds;
    std::vector<Scalar> m_strikeShares; ///< per body, what addStrikeShares adds to its margin, m
    /// Per body, the fastest striker that can reach it, blows passed on included, m/s
    std::vector<Scalar> m_reachSpeeds;
    std::vector<Scalar> m_handedSpeeds; ///< the next round of m_reachSpeeds

    std::vector<BroadPhaseProxy> m_reachProxies; ///< per dynamic body, the box of its pieces
    std::vector<ProxyPair> m_reachPairs;
    BroadPhase m_reachPhase; ///< which bodies can reach which (addStrikeShares); its own cache
    std::vector<BroadPhaseProxy> m_proxies;
    std::vector<ProxyPair> m_pairs;
    std::vector<ProxyPair> m_coarsePairs; ///< with soft bodies: pairs of bodies or rigid pieces
    std::vector<std::pair<std::uint32_t, std::uint32_t>> m_proxyPieces; ///< per coarse proxy: its pieces
    std::vector<std::uint32_t> m_nearA;
    std::vector<std::uint32_t> m_nearB;
    /// One per broad-phase pair (filled by both threads), then only those with contact points.
    std::vector<ContactSolver::PairManifold> m_manifolds;
    ColliderSet m_colliders;
    BroadPhase m_broadPhase;
    ContactSolver m_contactSolver;
    JointSolver m_jointSolver;
    UnlikeMassIslands m_unlikeMasses;
    FixedBodyGuard m_fixedBodyGuard; ///< the last line against passing into a fixed body
    IslandSpin m_islandSpin; ///< closed islands' angular momentum in zero gravity (island_spin.h)
    std::vector<CollisionEvent> m_events;
    std::vector<KeptOut> m_keptOut; ///< see keptOut()
    std::vector<model::ContactRecord> m_previousContacts;
    CollisionScratch m_collisionScratch;
    EnergyLedger* m_ledger = nullptr; ///< see setLedger
};

} // namespace impetus::controller
