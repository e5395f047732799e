#include "controller/integrator_comparison.h"

#include "controller/diagnostics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

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

/// Relative accuracy the elliptic functions below are computed to: far below anything a position
/// error in a classroom scene can show, far above rounding (so that the loops end).
constexpr Scalar kEllipticTolerance = 1e-13;
/// The most halvings (Landen) or duplications (Carlson) those loops take: each squares the
/// remaining error or divides it by four, so a few dozen reach rounding from any start.
constexpr int kEllipticIterations = 64;
/// A pendulum whose modulus k comes this close to 1 goes over the top, or nearly: its swing has no
/// period to speak of, and it is left out.
constexpr Scalar kLibrationLimit = 1 - 1e-9;

/// Carlson's symmetric integral R_F(x, y, z) = ½∫₀^∞ dt / √((t + x)(t + y)(t + z)), x, y, z ≥ 0
/// with at most one zero, by the duplication theorem: each pass moves the three arguments four
/// times closer together, and the fifth-order series finishes once they nearly agree.
Scalar carlsonRF(Scalar x, Scalar y, Scalar z)
{
    Scalar mean = (x + y + z) / 3;
    for (int i = 0; i < kEllipticIterations; ++i) {
        const Scalar spread = std::max({std::abs(x - mean), std::abs(y - mean), std::abs(z - mean)});
        if (spread < kEllipticTolerance * mean)
            break;
        const Scalar sx = std::sqrt(x);
        const Scalar sy = std::sqrt(y);
        const Scalar sz = std::sqrt(z);
        const Scalar lambda = sx * sy + sy * sz + sz * sx;
        x = (x + lambda) / 4;
        y = (y + lambda) / 4;
        z = (z + lambda) / 4;
        mean = (x + y + z) / 3;
    }
    const Scalar dx = 1 - x / mean;
    const Scalar dy = 1 - y / mean;
    const Scalar dz = -dx - dy;
    const Scalar e2 = dx * dy - dz * dz;
    const Scalar e3 = dx * dy * dz;
    return (1 - e2 / 10 + e3 / 14 + e2 * e2 / 24 - 3 * e2 * e3 / 44) / std::sqrt(mean);
}

/// The incomplete elliptic integral of the first kind F(φ | k) = ∫₀^φ dψ / √(1 − k² sin²ψ), for
/// −π ≤ φ ≤ π and 0 ≤ k < 1: the u whose amplitude am(u) is φ.
Scalar ellipticF(Scalar phi, Scalar k)
{
    const Scalar sign = phi < 0 ? -1 : 1;
    phi = std::abs(phi);
    const Scalar m = k * k;
    // Carlson's form holds up to φ = π/2; past it the integrand is symmetric about π/2, so
    // F(φ) = 2K − F(π − φ), with K = F(π/2).
    const bool pastQuarter = phi > std::numbers::pi_v<Scalar> / 2;
    const Scalar psi = pastQuarter ? std::numbers::pi_v<Scalar> - phi : phi;
    const Scalar s = std::sin(psi);
    const Scalar c = std::cos(psi);
    Scalar f = s * carlsonRF(c * c, 1 - m * s * s, 1);
    if (pastQuarter)
        f = 2 * carlsonRF(0, 1 - m, 1) - f;
    return sign * f;
}

/// Jacobi's sn(u, k) and cn(u, k) for 0 ≤ k < 1, by the descending Landen transformation: the
/// arithmetic-geometric mean of 1 and √(1 − k²) takes the modulus to 0, where sn is the sine,
/// and the amplitude is carried back up one level at a time.
std::pair<Scalar, Scalar> jacobiSnCn(Scalar u, Scalar k)
{
    std::array<Scalar, kEllipticIterations + 1> a{};
    std::array<Scalar, kEllipticIterations + 1> c{};
    a[0] = 1;
    c[0] = k;
    Scalar b = std::sqrt(1 - k * k);
    int n = 0;
    while (n < kEllipticIterations && std::abs(c[n]) > kEllipticTolerance) {
        a[n + 1] = (a[n] + b) / 2;
        c[n + 1] = (a[n] - b) / 2;
        b = std::sqrt(a[n] * b);
        ++n;
    }
    Scalar phi = std::ldexp(a[static_cast<std::size_t>(n)] * u, n);
    for (int level = n; level > 0; --level) {
        const auto l = static_cast<std::size_t>(level);
        phi = (phi + std::asin(c[l] / a[l] * std::sin(phi))) / 2;
    }
    return {std::sin(phi), std::cos(phi)};
}

/// The pendulum of a world AnalyticKind::Pendulum describes, from its start state.
struct PendulumStart {
    Vec2 pivot = Vec2::Zero(); ///< the rod's fixed end, m
    Vec2 down = Vec2::Zero(); ///< unit vector along gravity
    Vec2 side = Vec2::Zero(); ///< `down` turned a quarter turn counter-clockwise: θ grows towards it
    Scalar length = 0; ///< L, m
    Scalar omega0 = 0; ///< √(g/L), rad/s
    Scalar k = 0; ///< the modulus: sin of half the largest angle
    Scalar u0 = 0; ///< where in sn's cycle the swing starts
};

/// The pendulum `world` holds: its single rod from the centre of mass of its single dynamic body to
/// a fixed point, swinging; none when it is anything else.
std::optional<PendulumStart> pendulumOf(const model::World& world)
{
    const std::vector<std::size_t> dynamic = dynamicBodies(world);
    if (world.joints.size() != 1 || !world.springs.empty() || dynamic.size() != 1)
        return std::nullopt;
    const model::Joint& rod = world.joints.front();
    // Hung by its centre of mass, the body's turning and its swing are apart (the rod pulls through
    // the centre and makes no torque); hung off it, they are coupled. A rod to a fixed body that
    // moves (a conveyor) has no fixed pivot.
    if (rod.type != model::JointType::Rod || rod.bodyA.index != dynamic.front() || !rod.anchorA.isZero())
        return std::nullopt;
    PendulumStart p;
    if (rod.bodyB) {
        const model::Body& holder = world.bodies[rod.bodyB->index];
        if (!holder.fixed || !holder.state.velocity.isZero() || holder.state.angularVelocity != 0)
            return std::nullopt;
        p.pivot = holder.worldPoint(rod.anchorB);
    } else {
        p.pivot = rod.anchorB;
    }
    const Scalar g = world.settings.gravity.norm();
    const model::BodyState& s = world.bodies[dynamic.front()].state;
    const Vec2 r = s.position - p.pivot;
    p.length = r.norm();
    if (!(g > 0) || !(p.length > 0))
        return std::nullopt;
    p.down = world.settings.gravity / g;
    p.side = Vec2(-p.down.y(), p.down.x());
    p.omega0 = std::sqrt(g / p.length);
    const Scalar theta0 = std::atan2(r.dot(p.side), r.dot(p.down));
    // Only the velocity across the rod swings the bob; the rod takes any along it in the first step.
    const Scalar thetaDot0 = (r.x() * s.velocity.y() - r.y() * s.velocity.x()) / (p.length * p.length);
    const Scalar halfSine = std::sin(theta0 / 2);
    const Scalar scaledRate = thetaDot0 / (2 * p.omega0);
    p.k = std::hypot(halfSine, scaledRate);
    if (!(p.k < kLibrationLimit))
        return std::nullopt;
    // sn(u₀) = sin(θ₀/2)/k and cn(u₀) = θ̇₀/(2kω₀): the amplitude am(u₀) is the angle of that pair.
    p.u0 = ellipticF(std::atan2(halfSine, scaledRate), p.k);
    return p;
}

} // namespace

AnalyticKind analyticKind(const model::World& world)
{
    if (world.settings.drag != 0)
        return AnalyticKind::None;
    for (const model::Body& body : world.bodies) {
        if (body.soft)
            return AnalyticKind::None;
    }
    const std::vector<std::size_t> dynamic = dynamicBodies(world);
    if (dynamic.empty())
        return AnalyticKind::None;
    if (!world.joints.empty())
        return pendulumOf(world) ? AnalyticKind::Pendulum : AnalyticKind::None;
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
    case AnalyticKind::Pendulum: {
        const std::optional<PendulumStart> p = pendulumOf(start);
        if (!p)
            return std::nullopt;
        const Scalar sn = jacobiSnCn(p->omega0 * t + p->u0, p->k).first;
        const Scalar theta = 2 * std::asin(std::clamp(p->k * sn, Scalar(-1), Scalar(1)));
        return Vec2(p->pivot + p->length * (std::cos(theta) * p->down + std::sin(theta) * p->side));
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
    m_diverged = {};
}

void IntegratorComparison::step()
{
    for (std::size_t i = 0; i < m_worlds.size(); ++i) {
        // Stepping infinities and NaNs again would only spread them (and a broad phase fed with
        // them has nothing sensible to sort).
        if (m_diverged[i])
            continue;
        m_simulation.step(m_worlds[i]);
        m_diverged[i] = firstNonFiniteBody(m_worlds[i]).has_value();
    }
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
    // A projectile or a pendulum that touched something is off the textbook's path for good.
    if (m_analytic == AnalyticKind::None || (m_analytic != AnalyticKind::Spring && world.collisionCount > 0))
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
            bool compared = false;
            for (std::size_t i = 0; i < e.positionError.size(); ++i) {
                if (const std::optional<Scalar> error = comparison.positionError(i)) {
                    e.positionError[i] = std::max(e.positionError[i], *error);
                    compared = true;
                }
            }
            // A projectile that touched something has left the textbook for good in every run:
            // the rest of the run adds nothing (and a resting pile would cost the whole run).
            if (!compared)
                break;
        }
        out.push_back(e);
    }
    return out;
}

} // namespace impetus::controller
