#pragma once
/// \file scene_warnings.h
/// Settings that are legal but outside what the engine is tested for: a scene with them loads and
/// runs, but its results may be wrong (a stack explodes, a heavy body pushes a light one through
/// the ground). The CLI prints them on stderr, the attribute pane shows them on its world page.
/// docs/scene-format.md, "Ranges the engine is tested for".

#include "model/scene_io.h"
#include "model/world.h"

#include <optional>
#include <vector>

namespace impetus::model {

/// Every warning for `world`, each as a path and a reason like a scene problem:
/// - `world.timeStep` longer than the solver's substeps can split (kMaxSolverSubsteps ×
///   kMaxSolverStep, 1 s);
/// - `world.gravity` so strong that a body falls further than the speculative contact margin in
///   one solver step: |g|·h² > kSpeculativeMargin, with h the solver step (the time step, split
///   into substeps of at most kMaxSolverStep);
/// - two dynamic bodies whose masses differ more than kMaxContactMassRatio times and that are
///   joined by a spring or joint, or touch at load time (their bounding circles overlap);
/// - a dynamic body so fast that it crosses the whole scene (the box around every body's bounding
///   circle) in one solver step, in a scene of two bodies or more: it may meet the same bodies
///   more often in a step than the kMaxImpactsPerPoint impacts per contact point the impact pass
///   resolves;
/// - a spring so stiff, or so strongly damped, for the bodies it joins that the world's
///   integrator makes its fastest motion grow at the step it takes (the time step, or its
///   substep of at most kMaxSolverStep in a world with joints or soft bodies): longestStableStep
///   of springMode.
std::vector<SceneProblem> sceneWarnings(const World& world);

/// How a spring moves the bodies it joins, at their present poses: its fastest mode (the largest
/// ω of K·q = ω²·M·q over the x, y and θ of each dynamic body, with K the Hessian of the spring's
/// energy: k along it, its tension's T/L across it, and T·(u·arm) on each body's turn) and that
/// mode's damping, and the fastest rate at which its dashpot alone slows them.
struct SpringMode {
    Scalar omega = 0; ///< ω of the fastest mode, rad/s (0 when nothing swings, e.g. k = 0)
    Scalar rate = 0; ///< that mode's damping rate 2ζω, 1/s
    Scalar dampingRate = 0; ///< the largest rate of the dashpot alone, c/m along the spring, 1/s
};

/// The modes of `spring` in `world` (SpringMode); all zero when it joins no dynamic body.
SpringMode springMode(const World& world, const Spring& spring);

/// The longest step at which `integrator` keeps the motion ẍ = −ω²x − r·ẋ from growing: where
/// one step's matrix has a spectral radius above 1 (2/ω undamped for semi-implicit Euler, 2√2/ω
/// for RK4, less for both with damping; 2/r for a dashpot alone under either Euler). Explicit
/// Euler grows on every oscillating motion: its limit there (r < 2ω) is the step at which the
/// energy doubles within one period, about 0.11/ω undamped. nullopt when nothing moves (ω = r = 0)
/// or every step holds.
std::optional<Scalar> longestStableStep(IntegratorKind integrator, Scalar omega, Scalar rate);

/// longestStableStep of an oscillator of ω = 1 and damping ratio ζ: the largest stable ω·h.
std::optional<Scalar> stableOmegaStep(IntegratorKind integrator, Scalar zeta);

/// The step the integrators take spring forces with in `world`: its time step, or the substep of
/// at most kMaxSolverStep that a world with joints or soft bodies is always split into.
Scalar springIntegratorStep(const World& world);

/// The longest step at which `world`'s integrator keeps the motions of `spring` from growing (the
/// shorter of its fastest mode's and its dashpot's), or nullopt when every step holds.
std::optional<Scalar> longestStableSpringStep(const World& world, const Spring& spring);

/// The warning for spring `index` of `world` when springIntegratorStep() is longer than
/// longestStableSpringStep() (path "springs[index]"), or nothing.
std::optional<SceneProblem> springWarning(const World& world, std::size_t index);

/// A run's starting energy, to judge its growth against (issue 17, F2).
struct EnergyBaseline {
    bool active = false; ///< false when something in the world does work (a fixed body moves)
    Scalar start = 0; ///< total energy at the start, J
    Scalar bound = 0; ///< growth past this is warned about, J: kEnergyGrowthWarning × max(|E₀|, K₀ + |P₀|)
};

/// The baseline of `world`, whose energies (J) are `total`, `kinetic` and `potential` now.
EnergyBaseline energyBaseline(const World& world, Scalar total, Scalar kinetic, Scalar potential);

/// The warning for a run whose total energy is `now` (J) at `time` (s), when it has grown past the
/// baseline's bound; nothing otherwise (also when `now` is not finite, which is a failure of its
/// own). The reason says what adds energy under `integrator`. Path "world.energy".
std::optional<SceneProblem> energyGrowthWarning(const EnergyBaseline& baseline, Scalar now, Scalar time,
                                                IntegratorKind integrator);

} // namespace impetus::model
