#pragma once
/// \file integrator_comparison.h
/// One scene run under explicit Euler, semi-implicit Euler and RK4 side by side, each a copy of
/// the world (World copies with =), with each run's energy error and, where the scene has an
/// analytic solution, its position error against it (issue 14, item 3: integrator ghosts).

#include "controller/simulation.h"
#include "model/scalar.h"
#include "model/world.h"

#include <array>
#include <optional>
#include <vector>

namespace impetus::controller {

/// The textbook motions a scene can be recognised as.
enum class AnalyticKind {
    None, ///< no analytic solution known
    /// Free flight in uniform gravity, no springs, joints or drag: x(t) = x₀ + v₀t + ½gt² for every
    /// dynamic body, until the first contact.
    Projectile,
    /// One dynamic body on one undamped zero-rest-length spring from its centre of mass to a world
    /// point, no drag or joints: x(t) = x_eq + (x₀ − x_eq)·cos ωt + (v₀/ω)·sin ωt, ω = √(k/m),
    /// x_eq = anchor + m·g/k.
    Spring,
};

/// Which analytic solution `world` (in its start state) has, by its bodies, springs and settings.
AnalyticKind analyticKind(const model::World& world);

/// Where body `body` of `start` is after t seconds by the analytic solution of `kind`, m; none
/// for AnalyticKind::None or a body that is fixed.
std::optional<Vec2> analyticPosition(const model::World& start, AnalyticKind kind, std::size_t body, Scalar t);

/// The three integrators, in the order the comparison keeps them.
inline constexpr std::array<model::IntegratorKind, 3> kComparedIntegrators = {
    model::IntegratorKind::Euler, model::IntegratorKind::SemiImplicitEuler, model::IntegratorKind::Rk4};

/// The same scene stepped under each of kComparedIntegrators, from one start state, with a
/// common time step (the scene's unless setTimeStep changes it).
class IntegratorComparison {
public:
    /// Starts the three runs from `start`.
    explicit IntegratorComparison(const model::World& start);

    /// Starts again from the start state with time step h (s, > 0).
    void setTimeStep(Scalar h);
    /// Advances each run by one fixed step.
    void step();

    /// The run of integrator i (an index into kComparedIntegrators).
    const model::World& world(std::size_t i) const { return m_worlds[i]; }
    /// The start state.
    const model::World& start() const { return m_start; }
    /// What the scene was recognised as.
    AnalyticKind analytic() const { return m_analytic; }

    /// (E − E₀)/|E₀| of run i, dimensionless (E₀ the start's energy; 0 when E₀ = 0).
    Scalar energyError(std::size_t i) const;
    /// The largest distance of a dynamic body of run i from the analytic solution, m; none when
    /// the scene has none, or (a projectile) once any body has touched another.
    std::optional<Scalar> positionError(std::size_t i) const;

private:
    model::World m_start;
    std::array<model::World, 3> m_worlds;
    Simulation m_simulation;
    AnalyticKind m_analytic = AnalyticKind::None;
    Scalar m_startEnergy = 0;
};

/// One point of an error-against-step plot: the largest position error over a run of fixed length
/// under a step h.
struct StepError {
    Scalar timeStep = 0; ///< h, s
    std::array<Scalar, 3> positionError{}; ///< per kComparedIntegrators, m (0: no analytic solution)
};

/// The largest position error of each integrator over `duration` seconds (rounded to whole steps)
/// for each of `timeSteps`, on a scene with an analytic solution (empty otherwise): the log-log plot
/// of error against h whose slope is each method's order (1 for the Eulers, 4 for RK4).
std::vector<StepError> errorAgainstStep(const model::World& start, const std::vector<Scalar>& timeSteps, Scalar duration);

} // namespace impetus::controller
