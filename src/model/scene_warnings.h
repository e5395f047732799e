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
