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
/// - a spring so stiff for the bodies it joins that the world's integrator is unstable at the
///   time step: ω·h above 2 (semi-implicit Euler) or 2√2 (RK4), with ω = √(k/m) and m the ends'
///   effective mass along the spring, turns included; for explicit Euler, above the ω·h at which
///   the energy doubles within one period (about 0.11).
std::vector<SceneProblem> sceneWarnings(const World& world);

/// The fastest oscillation a spring drives in the bodies it joins, at their present poses.
struct SpringMode {
    Scalar omega = 0; ///< ω = √(k/m), rad/s
    Scalar zeta = 0; ///< damping ratio c/(2mω) of the mode (0 across the spring, where no dashpot acts)
    Scalar stiffness = 0; ///< k along the spring, or k·(1 − L₀/L) across it, N/m
    Scalar inverseMass = 0; ///< 1/m, the ends' effective inverse mass in that direction, turns included, 1/kg
    Scalar length = 0; ///< the spring's present length L, m
    bool across = false; ///< true when the mode across the stretched spring is the faster one
};

/// The spring's fastest mode: along it with k, or across it with the tension's k·(1 − L₀/L)
/// when stretched, each body's turn about its centre counted at its anchor's lever arm.
SpringMode springMode(const World& world, const Spring& spring);

/// The largest ω·h at which `integrator` keeps an oscillator of angular frequency ω and damping
/// ratio ζ from growing at a step h: 2 for semi-implicit Euler and 2√2 for RK4 (undamped); for
/// explicit Euler, which grows wherever ω·h > 2ζ, the ω·h at which the energy doubles within one
/// period (about 0.11 undamped), and nothing for ζ ≥ 1 (no oscillation).
std::optional<Scalar> stableOmegaStep(IntegratorKind integrator, Scalar zeta);

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
