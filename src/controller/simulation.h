#pragma once
/// \file simulation.h
/// The fixed-step driver. Simulation::step reads top to bottom as the phases it runs.

#include "controller/broad_phase.h"
#include "controller/collision_events.h"
#include "controller/colliders.h"
#include "controller/contact_solver.h"
#include "controller/integrator.h"
#include "controller/joint_solver.h"
#include "controller/task_pair.h"
#include "model/constants.h"
#include "model/world.h"

#include <memory>
#include <vector>

namespace impetus::controller {

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
    int impacts = 0; ///< impacts resolved
};

/// Iteration counts of the constraint solvers.
struct SolverSettings {
    int velocityIterations = constants::kVelocityIterations; ///< sequential-impulse passes, 8
    int positionIterations = constants::kPositionIterations; ///< position-correction passes (at most), 3
    /// Use a second thread for large worlds (docs/physics.md, "Two threads"). The result is the
    /// same bits either way; false saves the thread.
    bool secondThread = true;
};

/// Steps a world with its fixed time step. Holds only scratch state (buffers, the broad phase's
/// sort order), so one Simulation can step any world; the world itself carries everything
/// physical, including the contact impulses that warm-start the next step.
class Simulation {
public:
    explicit Simulation(SolverSettings settings = {});

    /// Advances `world` by one fixed step world.settings.timeStep with world.settings.integrator,
    /// resolving collisions, contacts and joints.
    void step(model::World& world);

    /// Timing of the last step().
    const StepProfile& profile() const { return m_profile; }

    /// The contacts that began in the last step (the collision log's new entries).
    const std::vector<CollisionEvent>& events() const { return m_events; }

private:
    Integrator& integratorFor(model::IntegratorKind kind);
    void collide(const model::World& world, Scalar h);
    void integratePositions(model::World& world, Scalar h);

    SolverSettings m_settings;
    std::vector<Manifold> m_pairManifolds; ///< one per broad-phase pair, filled by both threads
    std::unique_ptr<Integrator> m_euler;
    std::unique_ptr<Integrator> m_semiImplicitEuler;
    std::unique_ptr<Integrator> m_rk4;
    /// The second thread, shared by the narrow phase and the contact solver. Behind a pointer so
    /// that the contact solver's reference to it survives moving the Simulation.
    std::unique_ptr<TaskPair> m_tasks;
    StepProfile m_profile;

    // Scratch, reused from step to step.
    std::vector<model::BodyState> m_startStates;
    std::vector<BodyDerivative> m_startDerivatives;
    std::vector<SolverBody> m_bodies;
    std::vector<Scalar> m_margins;
    std::vector<BroadPhaseProxy> m_proxies;
    std::vector<ProxyPair> m_pairs;
    std::vector<ContactSolver::PairManifold> m_manifolds;
    ColliderSet m_colliders;
    BroadPhase m_broadPhase;
    ContactSolver m_contactSolver;
    JointSolver m_jointSolver;
    std::vector<CollisionEvent> m_events;
    std::vector<model::ContactRecord> m_previousContacts;
};

} // namespace impetus::controller
