#pragma once
/// \file soft_stability.h
/// Whether the integrator can step a soft grid's stiff springs at the world's time step, and how
/// many substeps make it do so. See docs/physics.md, "Soft mode: stability".

#include "model/body.h"
#include "model/scalar.h"
#include "model/soft_grid.h"
#include "model/world.h"

#include <string>

namespace impetus::controller {

/// How a world's steps are split for its soft grids.
struct SoftStability {
    int substeps = 1; ///< equal substeps per step, 1 … kMaxSoftSubsteps
    /// ω·h of the fastest grid vibration at the world's step h (before substepping), with
    /// ω = √(maxSpringRate) of the grid that needs the most substeps; 0 without soft bodies.
    Scalar omegaH = 0;
    bool stable = true; ///< false: even kMaxSoftSubsteps substeps are not enough
    model::BodyId body; ///< the soft body that sets the count (meaningful when omegaH > 0)
    /// For the user: empty when one substep is enough, otherwise why the step is split (and, when
    /// not stable, what to change).
    std::string message;
};

/// The substeps one grid needs under `integrator` at step h (s). The grid's damping is a pass of
/// its own, stable at any step (soft_damping.h), so only its stiffness counts:
///  - RK4: ω·(h/s) ≤ kRk4SoftStabilityLimit;
///  - semi-implicit Euler: ω²(h/s)² ≤ kSemiImplicitEulerSoftStabilityLimit;
///  - explicit Euler: h/s ≤ kExplicitEulerSoftSafety·c/k and the semi-implicit Euler bound; with
///    no spring damping it is unstable at any step, and gets kMaxSoftSubsteps (stable = false);
/// and whatever the integrator, also ω·(h/s) ≤ kSoftContactStabilityLimit: an ellipse held by a
/// contact force finishes its step as x = x₀ + h·v. ω² = grid.maxSpringRate. Returns at most
/// kMaxSoftSubsteps; `stable` tells whether that was enough.
int requiredSoftSubsteps(const model::SoftGrid& grid, model::IntegratorKind integrator, Scalar h, bool& stable);

/// The substeps `world` needs (the most any of its grids needs) and the message to show.
/// Call prepareSoftBodies first: a body without a grid is not looked at.
SoftStability softStability(const model::World& world);

} // namespace impetus::controller
