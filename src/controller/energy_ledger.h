#pragma once
/// \file energy_ledger.h
/// Where every joule goes: the energy ledger (docs/physics.md, "The energy ledger"). Simulation
/// reports each phase of each substep to an attached ledger, which books the change of mechanical
/// energy E = kinetic + gravitational + elastic between the phases by cause. The ledger closes by
/// construction: initial energy = current energy + the sum of the losses, and the integrator's
/// drift is the one line that is a remainder rather than a measured cause.

#include "controller/dynamics/contact_solver.h"
#include "controller/dynamics/solver_body.h"
#include "controller/diagnostics.h"
#include "model/scalar.h"
#include "model/world.h"

#include <span>
#include <vector>

namespace impetus::controller {

/// Energy removed from the world by each cause since the ledger started, J. Positive: taken out
/// of the world (dissipated); negative: put in. Gravity and springs are not losses: their work is
/// stored as potential and elastic energy, which are part of the current energy.
struct EnergyLosses {
    /// Impacts: −½·Σ j·(u⁻ + u⁺) of the normal impact impulses, u the relative normal velocity
    /// just before and after at the time of impact (restitution e < 1), J.
    Scalar impacts = 0;
    /// Coulomb friction, at impacts and in resting or sliding contact: −½·Σ jₜ·(uₜ⁻ + uₜ⁺), J.
    Scalar friction = 0;
    /// Stokes drag, ∫ b·|v|² dt (trapezoidal rule over each substep), J.
    Scalar drag = 0;
    /// Damping of scene springs, ∫ c·(dL/dt)² dt (trapezoidal rule), J.
    Scalar springDamping = 0;
    /// A soft body's grid-spring damping and internal damping, ∫ Σ m·β·(v − v_rigid)·v + c·(dL/dt)² dt, J.
    Scalar softDamping = 0;
    /// The joints' position correction: moving bodies back onto their rods and pins changes their
    /// height and their springs' stretch, J.
    Scalar joints = 0;
    /// The contacts' position correction: moving bodies out of overlap does the same, J.
    Scalar correction = 0;
    /// The remainder: what the integrator and the discrete step make of the smooth forces beyond
    /// the causes above (RK4's error on a spring, explicit Euler's growth, the energy the
    /// integrator puts into an approach that a contact or a joint then takes out again), J.
    Scalar drift = 0;

    /// The sum of every line, J.
    Scalar total() const
    {
        return impacts + friction + drag + springDamping + softDamping + joints + correction + drift;
    }
};

/// What a ledger holds at one moment, for a history of it (the app's ledger chart).
struct LedgerSample {
    Scalar startTime = 0; ///< simulated time at which the ledger started, s
    Energy initial; ///< the world's energy then, J
    Energy current; ///< the world's energy now, J
    EnergyLosses losses; ///< cumulative since the ledger started, J
};

/// The bookkeeping. Attach one to a Simulation (Simulation::setLedger) and it is told of every
/// substep's phases; read it between steps. It starts at the first substep it sees, and starts
/// again whenever the world it is shown was changed from outside between two substeps (an edit,
/// a reset, a jump on the timeline), since energy put in by a hand is no cause it can name.
class EnergyLedger {
public:
    /// Forgets everything: the next substep starts the ledger afresh.
    void reset();

    /// Whether it has seen a substep since it was made or reset.
    bool started() const { return m_started; }
    /// The world's energy when the ledger started, J.
    const Energy& initialEnergy() const { return m_initial; }
    /// The world's energy at the end of the last substep, J.
    const Energy& currentEnergy() const { return m_current; }
    /// The losses since the ledger started, J.
    const EnergyLosses& losses() const { return m_losses; }
    /// Simulated time at which the ledger started, s.
    Scalar startTime() const { return m_startTime; }

    /// How well the ledger closes: |E₀ − E − Σ losses| / max(|E₀|, |E|, Σ |loss|), dimensionless;
    /// 0 before the first substep. Round-off alone keeps it near 1e-15.
    Scalar closure() const;

    // Called by Simulation::substep, in this order, only when a ledger is attached. Spans of solver
    // bodies and states are indexed as the world's state list (force_model.h, stateCount).

    /// The start of a substep: the world before it.
    void beginSubstep(const model::World& world);
    /// Before the impacts, after the constraints are prepared.
    void beforeImpacts(std::span<const SolverBody> bodies);
    /// After the impacts: `normalWork` is the work of their normal impulses at the times of
    /// impact, `frictionWork` that of friction during them, J (≤ 0 each).
    void afterImpacts(std::span<const SolverBody> bodies, Scalar normalWork, Scalar frictionWork);
    /// After the integrator: the smooth forces' dissipation over [start, end], h seconds long.
    void afterIntegration(const model::World& world, std::span<const model::BodyState> start,
                          std::span<const model::BodyState> end, Scalar h);
    /// Before the velocity passes (the integrator's velocity change already added to `bodies`).
    void beforeVelocities(std::span<const SolverBody> bodies, const std::vector<ContactConstraint>& constraints);
    /// After the velocity passes: `records` hold the passes' final accumulated impulses, one per
    /// constraint in the same order.
    void afterVelocities(std::span<const SolverBody> bodies, const std::vector<ContactConstraint>& constraints,
                         const std::vector<model::ContactRecord>& records);
    /// Around each pass of the joints' position correction: `bodies` hold the poses.
    void beforeJointCorrection(const model::World& world, std::span<const SolverBody> bodies);
    void afterJointCorrection(const model::World& world, std::span<const SolverBody> bodies); ///< see beforeJointCorrection
    /// After the positions are integrated, before position correction: `states` is the state list then.
    void beforeCorrection(const model::World& world, std::span<const model::BodyState> states);
    /// The end of the substep: the world after it.
    void endSubstep(const model::World& world);

private:
    /// Σ ½m|v|² + ½Iω² of the solver bodies that carry kinetic energy, J.
    Scalar kinetic(std::span<const SolverBody> bodies) const;
    /// Gravitational plus elastic energy of the world with the solver bodies' poses, J.
    Scalar storedEnergy(const model::World& world, std::span<const SolverBody> bodies);

    bool m_started = false;
    Energy m_initial;
    Energy m_current;
    EnergyLosses m_losses;
    Scalar m_startTime = 0;

    // This substep.
    Scalar m_substepStart = 0; ///< E at its start, J
    Scalar m_kineticBeforeImpacts = 0; ///< J
    Scalar m_afterImpacts = 0; ///< E after the impacts, J
    Scalar m_smoothLoss = 0; ///< drag, damping and the velocity passes' causes booked this substep, J
    Scalar m_storedBeforeJoints = 0; ///< stored energy before a joint correction pass, J
    Scalar m_jointCorrection = 0; ///< what the joints' correction took out this substep, J
    std::vector<model::BodyState> m_poses; ///< the solver bodies' poses as a state list
    Scalar m_beforeCorrection = 0; ///< E before position correction, J
    std::vector<Scalar> m_mass; ///< per state-list entry: its mass, 0 for one that carries no energy, kg
    std::vector<Scalar> m_inertia; ///< per entry: its moment of inertia, kg·m²
    std::vector<Scalar> m_tangentBefore; ///< per contact point: relative tangential velocity, m/s
};

} // namespace impetus::controller
