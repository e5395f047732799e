#include "controller/soft/soft_stability.h"

#include "model/constants.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace impetus::controller {

namespace {

/// The largest substep at which the integrator, with the damping pass before it (soft_damping.h),
/// is stable on the grid, s; 0 when no substep is stable (explicit Euler, no spring damping). The
/// pass takes the damping out of the integrator, so only the stiffness ω² = maxSpringRate counts:
///  - RK4, then the pass, is stable on a mode while ω·h ≤ 2.83 whatever share of its velocity the
///    pass keeps (2.83 undamped, 3.46 when the pass stops it);
///  - semi-implicit Euler while ω²h² ≤ 2·(1 + e), e the share of the mode's velocity the pass
///    keeps: 4 undamped, but only 2 for the fastest modes of a strongly damped grid, whose velocity
///    the pass all but stops (e → 0). The limit takes e = 0;
///  - explicit Euler grows an undamped mode by √(1 + ω²h²) a step, so the pass must take out
///    enough: e·(1 + ω²h²) ≤ 1. The springs' damping (and shape matching's, in the same
///    proportion) is stiffness-proportional, e = exp(−(c/k)·ω²·h) for a mode of frequency ω, and
///    that holds for every mode while h ≤ c/k. Its ellipses held by contacts finish as
///    semi-implicit Euler does (largestStableStep), which bounds it too.
Scalar integratorStep(const model::SoftGrid& grid, model::IntegratorKind integrator)
{
    const Scalar omegaSq = grid.maxSpringRate;
    const Scalar unlimited = std::numeric_limits<Scalar>::infinity();
    if (!(omegaSq > 0))
        return unlimited;
    const Scalar omega = std::sqrt(omegaSq);
    const Scalar semiImplicit = std::sqrt(constants::kSemiImplicitEulerSoftStabilityLimit) / omega;
    switch (integrator) {
    case model::IntegratorKind::Rk4:
        return constants::kRk4SoftStabilityLimit / omega;
    case model::IntegratorKind::SemiImplicitEuler:
        return semiImplicit;
    case model::IntegratorKind::Euler: {
        const Scalar damping = grid.springDamping;
        if (!(damping > 0))
            return 0;
        return std::min(constants::kExplicitEulerSoftSafety * damping / grid.settings.stiffness, semiImplicit);
    }
    }
    return unlimited;
}

std::string formatted(Scalar value)
{
    std::ostringstream out;
    out.precision(3);
    out << value;
    return out.str();
}

/// The largest stable substep of a grid, s. Whatever the integrator, an ellipse held by a contact
/// force finishes its step as x = x₀ + h·v (as a resting rigid body does) with the velocity the
/// integrator and the contact gave it. With RK4's velocity that is stable while ω·h < 2.45,
/// whatever the damping pass keeps; semi-implicit and explicit Euler's velocities make it
/// semi-implicit Euler, which integratorStep already bounds.
Scalar largestStableStep(const model::SoftGrid& grid, model::IntegratorKind integrator)
{
    const Scalar omega = std::sqrt(grid.maxSpringRate);
    const Scalar contactStep =
        omega > 0 ? constants::kSoftContactStabilityLimit / omega : std::numeric_limits<Scalar>::infinity();
    return std::min(integratorStep(grid, integrator), contactStep);
}

/// The substeps that keep the damping pass accurate at step h (s): 2c·(h/s)/m ≤
/// kSoftDampingPassLimit for the grid springs' pair rate 2c/m. Not a matter of stability: the
/// pass is stable at any step, and beyond kMaxSoftSubsteps the grid runs stable, only less
/// accurately.
int dampingSubsteps(const model::SoftGrid& grid, Scalar h)
{
    if (!(grid.ellipseMass > 0))
        return 1;
    const Scalar pairRate = 2 * grid.springDamping / grid.ellipseMass;
    const Scalar needed = std::ceil(pairRate * h / constants::kSoftDampingPassLimit);
    return static_cast<int>(std::clamp(needed, 1.0, static_cast<Scalar>(constants::kMaxSoftSubsteps)));
}

} // namespace

int requiredSoftSubsteps(const model::SoftGrid& grid, model::IntegratorKind integrator, Scalar h, bool& stable)
{
    const Scalar largest = largestStableStep(grid, integrator);
    const Scalar needed = largest > 0 ? std::ceil(h / largest) : INFINITY;
    stable = needed <= constants::kMaxSoftSubsteps;
    if (!stable)
        return constants::kMaxSoftSubsteps;
    return std::max({1, static_cast<int>(needed), dampingSubsteps(grid, h)});
}

SoftStability softStability(const model::World& world)
{
    SoftStability result;
    const Scalar h = world.settings.timeStep;
    const model::IntegratorKind integrator = world.settings.integrator;
    bool first = true;
    for (const model::SoftGrid& grid : world.softBodies) {
        bool stable = true;
        const int substeps = requiredSoftSubsteps(grid, integrator, h, stable);
        // The grid that needs the most substeps (or is unstable) speaks for the world.
        if (first || substeps > result.substeps || (!stable && result.stable)) {
            result.substeps = std::max(result.substeps, substeps);
            result.stable = result.stable && stable;
            result.body = grid.body;
            result.omegaH = std::sqrt(grid.maxSpringRate) * h;
            first = false;
        }
    }
    if (result.substeps == 1 && result.stable)
        return result;

    const std::string name = world.bodies[result.body.index].name;
    const std::string method(model::integratorName(integrator));
    std::string text = "soft body '";
    text += name;
    const model::SoftGrid& grid = *world.softGrid(result.body);
    if (result.stable && dampingSubsteps(grid, h) == result.substeps) {
        // The damping, not the stiffness, sets the count.
        text += "': its springs' damping, 2c·h/m = ";
        text += formatted(2 * grid.springDamping / grid.ellipseMass * h);
        text += " at h = ";
        text += formatted(h * 1000);
        text += " ms, is too strong for one damping pass; each step is split into ";
        text += std::to_string(result.substeps);
        text += " substeps to keep the damping accurate";
        result.message = text;
        return result;
    }
    text += "': its fastest grid vibration has ω·h = ";
    text += formatted(result.omegaH);
    text += " at h = ";
    text += formatted(h * 1000);
    text += " ms, too fast for ";
    text += method;
    if (result.stable) {
        text += "; each step is split into ";
        text += std::to_string(result.substeps);
        text += " substeps";
    } else if (integrator == model::IntegratorKind::Euler && !(grid.springDamping > 0)) {
        text += ": explicit Euler gains energy on undamped springs at any step. Give the body some damping, "
                "or use semi-implicit-euler or rk4";
    } else {
        text += ": even ";
        text += std::to_string(constants::kMaxSoftSubsteps);
        text += " substeps are not enough. Lower its stiffness or density, or the time step";
    }
    result.message = text;
    return result;
}

} // namespace impetus::controller
