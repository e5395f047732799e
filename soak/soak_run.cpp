#include "soak/soak_run.h"

#include "controller/diagnostics.h"
#include "controller/soft/soft_body_builder.h"
#include "controller/simulation.h"
#include "soak/soak_constants.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace impetus::soak {

namespace {

/// How far `p` lies outside the inside of the box, m (0 inside).
Scalar depthOutside(const Vec2& p)
{
    const Scalar dx = std::abs(p.x()) - kBoxHalfWidth;
    const Scalar dy = std::max(-p.y(), p.y() - kBoxHeight);
    return std::max({Scalar(0), dx, dy});
}

std::string describe(const Vec2& p)
{
    std::ostringstream text;
    text << '(' << p.x() << ", " << p.y() << ')';
    return text.str();
}

/// The first body, or soft-body ellipse, whose centre is deeper than kEscapeDepth in a wall (or
/// past it); nothing when all are inside. A NaN position counts as escaped too, but the
/// finite check runs first.
std::optional<std::string> findEscape(const model::World& world)
{
    for (const model::Body& body : world.bodies) {
        if (body.fixed)
            continue;
        if (!(depthOutside(body.state.position) <= kEscapeDepth))
            return "body '" + body.name + "' has its centre at " + describe(body.state.position) + ", outside the box";
    }
    for (const model::SoftGrid& grid : world.softBodies) {
        for (std::size_t i = 0; i < grid.positions.size(); ++i) {
            if (!(depthOutside(grid.positions[i]) <= kEscapeDepth))
                return "soft body '" + world.body(grid.body).name + "': ellipse " + std::to_string(i) + " is at " +
                       describe(grid.positions[i]) + ", outside the box";
        }
    }
    return std::nullopt;
}

} // namespace

Scalar energyFloor(const model::World& world)
{
    const std::array<Vec2, 4> corners = {Vec2(-kBoxHalfWidth, 0), Vec2(kBoxHalfWidth, 0),
                                         Vec2(-kBoxHalfWidth, kBoxHeight), Vec2(kBoxHalfWidth, kBoxHeight)};
    // Potential energy −m·g·x is linear in x, so over the box it is least at a corner.
    Scalar lowest = -corners[0].dot(world.settings.gravity);
    for (const Vec2& corner : corners)
        lowest = std::min(lowest, -corner.dot(world.settings.gravity));
    Scalar floor = 0;
    for (const model::Body& body : world.bodies) {
        if (!body.fixed)
            floor += body.mass * lowest;
    }
    return floor;
}

SoakResult runSoakScene(model::World world, Scalar seconds)
{
    SoakResult result;
    const auto steps = static_cast<std::int64_t>(std::llround(seconds / world.settings.timeStep));
    // The start's energy as the app and impetus-cli report it: a soft body's is its grid's, built
    // before the first readout. A spinning body's grid has its own moment of inertia (equal
    // masses at the cell centres, not the shape's), so measured on the rigid body the energy
    // seemed to jump at the first step: 18 % for a 3 × 3 grid in a circle (seed 3503).
    controller::prepareSoftBodies(world);
    const Scalar start = controller::computeEnergy(world).total();
    const Scalar available = start - energyFloor(world);
    // Explicit Euler adds energy by design (docs/physics.md, "Integrators"): it is checked for
    // finite states and for staying in the box, not against the energy bound.
    const bool energyBounded = world.settings.integrator != model::IntegratorKind::Euler;
    const Scalar bound = start + kEnergyGrowthBound * available + kEnergyRoundingAllowance;

    controller::Simulation simulation;
    for (std::int64_t step = 1; step <= steps; ++step) {
        simulation.step(world);
        result.steps = step;
        const Scalar time = static_cast<Scalar>(step) * world.settings.timeStep;
        if (const std::optional<std::size_t> bad = controller::firstNonFiniteBody(world)) {
            result.finding = SoakFinding{"non-finite", "body '" + world.bodies[*bad].name + "' has a non-finite state",
                                         time};
            return result;
        }
        if (std::optional<std::string> escape = findEscape(world)) {
            result.finding = SoakFinding{"escaped", std::move(*escape), time};
            return result;
        }
        const Scalar energy = controller::computeEnergy(world).total();
        if (!std::isfinite(energy)) {
            result.finding = SoakFinding{"non-finite", "the total energy is not finite", time};
            return result;
        }
        if (!energyBounded)
            continue;
        if (available > 0)
            result.largestEnergyGrowth = std::max(result.largestEnergyGrowth, (energy - start) / available);
        if (energy > bound) {
            std::ostringstream detail;
            detail << "the energy grew from " << start << " J to " << energy << " J, past the bound " << bound
                   << " J (start + " << kEnergyGrowthBound << " x " << available << " J above the box's floor)";
            result.finding = SoakFinding{"energy", detail.str(), time};
            return result;
        }
    }
    return result;
}

} // namespace impetus::soak
