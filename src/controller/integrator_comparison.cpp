#include "controller/integrator_comparison.h"

#include "controller/diagnostics.h"

#include <algorithm>
#include <cmath>

namespace impetus::controller {

namespace {

/// The indices of the world's dynamic bodies.
std::vector<std::size_t> dynamicBodies(const model::World& world)
{
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        if (!world.bodies[i].fixed)
            out.push_back(i);
    }
    return out;
}

} // namespace

AnalyticKind analyticKind(const model::World& world)
{
    if (!world.joints.empty() || world.settings.drag != 0)
        return AnalyticKind::None;
    for (const model::Body& body : world.bodies) {
        if (body.soft)
            return AnalyticKind::None;
    }
    const std::vector<std::size_t> dynamic = dynamicBodies(world);
    if (dynamic.empty())
        return AnalyticKind::None;
    if (world.springs.empty())
        return AnalyticKind::Projectile;
    if (world.springs.size() != 1 || dynamic.size() != 1)
        return AnalyticKind::None;
    const model::Spring& spring = world.springs.front();
    // Hooke's law is linear in x only for a zero rest length from the centre of mass; a spring to
    // another body or with damping is no longer this textbook case.
    const bool textbook = !spring.bodyB && spring.bodyA.index == dynamic.front() && spring.anchorA.isZero() &&
                          spring.restLength == 0 && spring.damping == 0 && spring.stiffness > 0;
    return textbook ? AnalyticKind::Spring : AnalyticKind::None;
}

std::optional<Vec2> analyticPosition(const model::World& start, AnalyticKind kind, std::size_t body, Scalar t)
{
    if (body >= start.bodies.size() || start.bodies[body].fixed)
        return std::nullopt;
    const model::BodyState& s = start.bodies[body].state;
    const Vec2 g = start.settings.gravity;
    switch (kind) {
    case AnalyticKind::None:
        return std::nullopt;
    case AnalyticKind::Projectile:
        return Vec2(s.position + s.velocity * t + 0.5 * g * t * t);
    case AnalyticKind::Spring: {
        const model::Spring& spring = start.springs.front();
        const Scalar m = start.bodies[body].mass;
        const Scalar omega = std::sqrt(spring.stiffness / m);
        const Vec2 equilibrium = spring.anchorB + m * g / spring.stiffness;
        return Vec2(equilibrium + (s.position - equilibrium) * std::cos(omega * t) +
                    s.velocity * (std::sin(omega * t) / omega));
    }
    }
    return std::nullopt;
}

IntegratorComparison::IntegratorComparison(const model::World& start)
    : m_start(start)
    // One thread: three small copies of a classroom scene do not pay for a second one.
    , m_simulation(SolverSettings{.secondThread = false})
    , m_analytic(analyticKind(start))
    , m_startEnergy(computeEnergy(start).total())
{
    setTimeStep(start.settings.timeStep);
}

void IntegratorComparison::setTimeStep(Scalar h)
{
    for (std::size_t i = 0; i < m_worlds.size(); ++i) {
        m_worlds[i] = m_start;
        m_worlds[i].settings.integrator = kComparedIntegrators[i];
        m_worlds[i].settings.timeStep = h;
    }
}

void IntegratorComparison::step()
{
    for (model::World& world : m_worlds)
        m_simulation.step(world);
}

Scalar IntegratorComparison::energyError(std::size_t i) const
{
    if (m_startEnergy == 0)
        return 0;
    return (computeEnergy(m_worlds[i]).total() - m_startEnergy) / std::abs(m_startEnergy);
}

std::optional<Scalar> IntegratorComparison::positionError(std::size_t i) const
{
    const model::World& world = m_worlds[i];
    if (m_analytic == AnalyticKind::None || (m_analytic == AnalyticKind::Projectile && world.collisionCount > 0))
        return std::nullopt;
    Scalar worst = 0;
    for (const std::size_t b : dynamicBodies(world)) {
        const std::optional<Vec2> exact = analyticPosition(m_start, m_analytic, b, world.time - m_start.time);
        if (exact)
            worst = std::max(worst, (world.bodies[b].state.position - *exact).norm());
    }
    return worst;
}

std::vector<StepError> errorAgainstStep(const model::World& start, const std::vector<Scalar>& timeSteps, Scalar duration)
{
    std::vector<StepError> out;
    if (analyticKind(start) == AnalyticKind::None)
        return out;
    IntegratorComparison comparison(start);
    for (const Scalar h : timeSteps) {
        if (!(h > 0))
            continue;
        comparison.setTimeStep(h);
        const auto steps = static_cast<long>(std::lround(duration / h));
        StepError e;
        e.timeStep = h;
        // The largest error over the run, not the error at its end: an oscillator's phase error
        // shows in the position only as sin ωt, which may be near zero at the end.
        for (long k = 0; k < steps; ++k) {
            comparison.step();
            for (std::size_t i = 0; i < e.positionError.size(); ++i)
                e.positionError[i] = std::max(e.positionError[i], comparison.positionError(i).value_or(0));
        }
        out.push_back(e);
    }
    return out;
}

} // namespace impetus::controller
