#include "controller/soft/soft_stability.h"

#include "model/constants.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace impetus::controller {

namespace {

/// The largest substep at which semi-implicit Euler is stable on the grid, s: the positive root
/// of ω²x² + 2γx − L = 0.
Scalar semiImplicitEulerStep(Scalar omegaSq, Scalar gamma)
{
    const Scalar limit = constants::kSemiImplicitEulerSoftStabilityLimit;
    if (omegaSq > 0)
        return (-gamma + std::sqrt(gamma * gamma + limit * omegaSq)) / omegaSq;
    return gamma > 0 ? limit / (2 * gamma) : std::numeric_limits<Scalar>::infinity();
}

/// The largest stable substep of a grid under the integrator alone, s; 0 when no substep is
/// stable (explicit Euler, no damping).
Scalar integratorStep(const model::SoftGrid& grid, model::IntegratorKind integrator)
{
    const Scalar omegaSq = grid.maxSpringRate;
    const Scalar omega = std::sqrt(omegaSq);
    const Scalar gamma = grid.maxDampingRate;
    const Scalar unlimited = std::numeric_limits<Scalar>::infinity();
    switch (integrator) {
    case model::IntegratorKind::Rk4: {
        const Scalar rate = std::max(omega, gamma);
        return rate > 0 ? constants::kRk4SoftStabilityLimit / rate : unlimited;
    }
    case model::IntegratorKind::SemiImplicitEuler:
        return semiImplicitEulerStep(omegaSq, gamma);
    case model::IntegratorKind::Euler: {
        if (omegaSq == 0)
            return gamma > 0 ? constants::kExplicitEulerSoftSafety * 2 / gamma : unlimited;
        const Scalar stiffness = grid.settings.stiffness;
        const Scalar damping = grid.springDamping;
        if (!(damping > 0))
            return 0;
        // Shape matching's pull (rate λ² = k_s/m) is damped only by the internal damping β:
        // h ≤ 2ζ/ω becomes h ≤ β/λ² there.
        const Scalar matchingRate =
            constants::kSoftShapeMatching * stiffness / (grid.ellipseMass * static_cast<Scalar>(grid.size()));
        return constants::kExplicitEulerSoftSafety *
               std::min({damping / stiffness, 2 / gamma, constants::kSoftInternalDampingRate / matchingRate});
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
/// integrator and the contact gave it; for its springs that is semi-implicit Euler's position
/// update, stable while ω·h < 2. (Its velocity, damping included, is still the integrator's.)
Scalar largestStableStep(const model::SoftGrid& grid, model::IntegratorKind integrator)
{
    const Scalar omega = std::sqrt(grid.maxSpringRate);
    const Scalar contactStep =
        omega > 0 ? constants::kSoftContactStabilityLimit / omega : std::numeric_limits<Scalar>::infinity();
    return std::min(integratorStep(grid, integrator), contactStep);
}

} // namespace

int requiredSoftSubsteps(const model::SoftGrid& grid, model::IntegratorKind integrator, Scalar h, bool& stable)
{
    const Scalar largest = largestStableStep(grid, integrator);
    const Scalar needed = largest > 0 ? std::ceil(h / largest) : INFINITY;
    stable = needed <= constants::kMaxSoftSubsteps;
    if (!stable)
        return constants::kMaxSoftSubsteps;
    return std::max(1, static_cast<int>(needed));
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
    } else if (integrator == model::IntegratorKind::Euler && !(world.softGrid(result.body)->springDamping > 0)) {
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
