#include "model/scene_warnings.h"

#include "model/constants.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <numbers>
#include <set>
#include <utility>
#include <optional>
#include <sstream>
#include <string>

namespace impetus::model {

namespace {

/// Significant digits of numbers in warnings: enough to recognise a value, short enough to read.
constexpr int kShownDigits = 3;

/// Milliseconds per second (and millimetres per metre), for steps and lengths shown in ms and mm.
constexpr Scalar kMillisecondsPerSecond = 1000;

std::string shown(Scalar value)
{
    std::ostringstream out;
    out << std::setprecision(kShownDigits) << value;
    return out.str();
}

/// The step the contact solver takes: the time step, split into equal substeps of at most
/// kMaxSolverStep, and at most kMaxSolverSubsteps of them (controller::Simulation does the same).
Scalar solverStep(Scalar timeStep)
{
    const Scalar wanted = std::ceil(timeStep / constants::kMaxSolverStep);
    const Scalar substeps = std::clamp(wanted, Scalar(1), Scalar(constants::kMaxSolverSubsteps));
    return timeStep / substeps;
}

/// A length as a person reads it: in mm below a metre, in m from a metre up.
std::string shownLength(Scalar metres)
{
    return metres < 1 ? shown(metres * kMillisecondsPerSecond) + " mm" : shown(metres) + " m";
}

void checkTimeStep(const WorldSettings& settings, std::vector<SceneProblem>& out)
{
    const Scalar longest = constants::kMaxSolverSubsteps * constants::kMaxSolverStep;
    if (!(settings.timeStep > longest))
        return;
    out.push_back({"world.timeStep", "a step of " + shown(settings.timeStep) + " s is longer than " + shown(longest) +
                                         " s: it is split into " + std::to_string(constants::kMaxSolverSubsteps) +
                                         " substeps of " +
                                         shown(solverStep(settings.timeStep) * kMillisecondsPerSecond) +
                                         " ms, longer than the " +
                                         shown(constants::kMaxSolverStep * kMillisecondsPerSecond) +
                                         " ms the contact solver is made for; bodies may sink into or fall "
                                         "through each other"});
}

void checkGravity(const WorldSettings& settings, std::vector<SceneProblem>& out)
{
    const Scalar h = solverStep(settings.timeStep);
    const Scalar g = std::hypot(settings.gravity.x(), settings.gravity.y());
    // How far gravity moves a body in one solver step beyond where its velocity takes it. Once it
    // is more than the margin at which contacts are made ahead of time, resting bodies start each
    // step already deep in each other, and a stack is pushed apart violently.
    const Scalar drop = g * h * h;
    if (!(drop > constants::kSpeculativeMargin))
        return;
    const Scalar largest = constants::kSpeculativeMargin / (h * h);
    out.push_back({"world.gravity", "|g| = " + shown(g) + " m/s² moves a body " + shownLength(drop) + " in one solver step of " + shown(h * kMillisecondsPerSecond) +
                                        " ms (|g|·h²), more than the " +
                                        shown(constants::kSpeculativeMargin * kMillisecondsPerSecond) +
                                        " mm contact margin: resting contacts and stacks may explode; keep |g| "
                                        "at most " +
                                        shown(largest) + " m/s² at this step, or make the step smaller"});
}

/// A pair of dynamic bodies that touch or are joined, and where the pair comes from.
struct MassPair {
    std::uint32_t a;
    std::uint32_t b;
    std::string path; ///< the spring or joint, or the lighter body for a touching pair
    bool joined;
};

/// Pairs of dynamic bodies whose bounding circles overlap (or come within the speculative
/// margin): a sweep along x over the circles' extents, so a large world costs n·log n plus the
/// pairs found.
std::vector<MassPair> touchingPairs(const World& world)
{
    std::vector<std::uint32_t> dynamic;
    for (std::uint32_t i = 0; i < world.bodies.size(); ++i) {
        if (!world.bodies[i].fixed)
            dynamic.push_back(i);
    }
    const auto minX = [&world](std::uint32_t i) {
        return world.bodies[i].state.position.x() - world.bodies[i].geometry.boundingRadius;
    };
    std::sort(dynamic.begin(), dynamic.end(), [&](std::uint32_t l, std::uint32_t r) { return minX(l) < minX(r); });
    std::vector<MassPair> pairs;
    for (std::size_t k = 0; k < dynamic.size(); ++k) {
        const Body& first = world.bodies[dynamic[k]];
        const Scalar reach = first.state.position.x() + first.geometry.boundingRadius + constants::kSpeculativeMargin;
        for (std::size_t m = k + 1; m < dynamic.size() && minX(dynamic[m]) <= reach; ++m) {
            const Body& second = world.bodies[dynamic[m]];
            const Vec2 gap = second.state.position - first.state.position;
            const Scalar distance = std::hypot(gap.x(), gap.y());
            if (distance <= first.geometry.boundingRadius + second.geometry.boundingRadius + constants::kSpeculativeMargin) {
                const std::uint32_t lighter = first.mass <= second.mass ? dynamic[k] : dynamic[m];
                pairs.push_back({dynamic[k], dynamic[m], "bodies[" + std::to_string(lighter) + "]", false});
            }
        }
    }
    return pairs;
}

std::vector<MassPair> joinedPairs(const World& world)
{
    std::vector<MassPair> pairs;
    const auto add = [&](BodyId a, const std::optional<BodyId>& b, const std::string& path) {
        if (b && a.index < world.bodies.size() && b->index < world.bodies.size() && !world.body(a).fixed &&
            !world.body(*b).fixed)
            pairs.push_back({a.index, b->index, path, true});
    };
    for (std::size_t i = 0; i < world.springs.size(); ++i)
        add(world.springs[i].bodyA, world.springs[i].bodyB, "springs[" + std::to_string(i) + "]");
    for (std::size_t i = 0; i < world.joints.size(); ++i)
        add(world.joints[i].bodyA, world.joints[i].bodyB, "joints[" + std::to_string(i) + "]");
    return pairs;
}

void checkMassRatios(const World& world, std::vector<SceneProblem>& out)
{
    std::vector<MassPair> pairs = joinedPairs(world);
    // A joined pair that also touches is named once, by its link.
    std::set<std::pair<std::uint32_t, std::uint32_t>> joined;
    for (const MassPair& pair : pairs)
        joined.insert(std::minmax(pair.a, pair.b));
    for (const MassPair& pair : touchingPairs(world)) {
        if (!joined.contains(std::minmax(pair.a, pair.b)))
            pairs.push_back(pair);
    }
    int reported = 0;
    int more = 0;
    for (const MassPair& pair : pairs) {
        const Body& a = world.bodies[pair.a];
        const Body& b = world.bodies[pair.b];
        const Body& heavy = a.mass >= b.mass ? a : b;
        const Body& light = a.mass >= b.mass ? b : a;
        const Scalar ratio = heavy.mass / light.mass;
        if (!(ratio > constants::kMaxContactMassRatio))
            continue;
        if (reported == constants::kMaxMassRatioWarnings) {
            ++more;
            continue;
        }
        ++reported;
        const std::string ratioText = ", a mass ratio of " + shown(ratio) + ", above the " +
                                      shown(constants::kMaxContactMassRatio) + " the solver is tested for: ";
        if (pair.joined) {
            out.push_back({pair.path, "joins '" + heavy.name + "' (" + shown(heavy.mass) + " kg) to '" + light.name +
                                          "' (" + shown(light.mass) + " kg)" + ratioText +
                                          "the light body may jitter and the link stretch"});
        } else {
            out.push_back({pair.path, "'" + light.name + "' (" + shown(light.mass) + " kg) touches '" + heavy.name +
                                          "' (" + shown(heavy.mass) + " kg)" + ratioText +
                                          "the heavy body can push the light one into or through what it rests on"});
        }
    }
    if (more > 0) {
        out.push_back({"bodies", "and " + std::to_string(more) + " more pairs of bodies with a mass ratio above " +
                                     shown(constants::kMaxContactMassRatio)});
    }
}

const char* integratorWords(IntegratorKind integrator)
{
    switch (integrator) {
    case IntegratorKind::SemiImplicitEuler:
        return "semi-implicit Euler stays stable: the bodies on it will swing ever wider and fly apart";
    case IntegratorKind::Rk4:
        return "RK4 stays stable: the bodies on it will swing ever wider and fly apart";
    case IntegratorKind::Euler:
        break;
    }
    return "explicit Euler's energy doubles within one period (each step multiplies it by 1 − 2ζωh + ω²h², ζ the "
           "damping ratio)";
}

/// A spring too stiff for the step: the spring and the bodies it joins oscillate at ω = √(k/m),
/// m the effective mass of the two ends along the spring (with the turn of each body about its
/// centre, so that an anchor far off a body's centre counts), and an integrator that takes steps
/// of h is unstable once ω·h passes its limit (stableOmegaStep). The integrators are not split
/// for a spring: a lesson on integrators shows each one's error at the step the user chose.
void checkSpringSteps(const World& world, std::vector<SceneProblem>& out)
{
    const Scalar h = world.settings.timeStep;
    if (!(h > 0))
        return;
    for (std::size_t i = 0; i < world.springs.size(); ++i) {
        const Spring& spring = world.springs[i];
        if (!(spring.stiffness > 0))
            continue;
        const SpringMode mode = springMode(world, spring);
        const std::optional<Scalar> stable = stableOmegaStep(world.settings.integrator, mode.zeta);
        const Scalar omega = mode.omega;
        if (!stable || !(omega * h > *stable) || !std::isfinite(omega))
            continue;
        const Scalar limit = *stable;
        out.push_back({"springs[" + std::to_string(i) + "]",
                       "k = " + shown(spring.stiffness) + " N/m" +
                           (mode.across ? ", stretched to " + shown(mode.length) + " m (rest length " +
                                              shown(spring.restLength) + " m), pulls its ends across its line with " +
                                              shown(mode.stiffness) + " N/m; on "
                                        : " on ") +
                           shown(1 / mode.inverseMass) + " kg (the ends' effective mass " +
                           (mode.across ? "across" : "along") + " it) it oscillates at ω = √(k/m) = " + shown(omega) +
                           " rad/s: ω·h = " + shown(omega * h) + " at the step of " +
                           shown(h * kMillisecondsPerSecond) + " ms, above the " + shown(limit) + " at which " +
                           integratorWords(world.settings.integrator) + "; make the step at most " +
                           shown(limit / omega * kMillisecondsPerSecond) + " ms, or the spring softer"});
    }
}

} // namespace

/// The largest ω·h at which `integrator` keeps an oscillator of angular frequency ω from growing,
/// at a step h: semi-implicit Euler 2, RK4 2√2 (where its stability region crosses the imaginary
/// axis), undamped. Explicit Euler grows wherever ω·h > 2ζ (ζ the damping ratio): each step
/// multiplies the energy by |1 + hλ|² = 1 − 2ζωh + ω²h²; its limit here is the ω·h at which the
/// energy doubles within one period of 2π/(ωh) steps, about 0.11 undamped. Nothing for explicit
/// Euler with ζ ≥ 1, which does not oscillate.
std::optional<Scalar> stableOmegaStep(IntegratorKind integrator, Scalar zeta)
{
    switch (integrator) {
    case IntegratorKind::SemiImplicitEuler:
        return Scalar(2);
    case IntegratorKind::Rk4:
        return 2 * std::sqrt(Scalar(2));
    case IntegratorKind::Euler:
        break;
    }
    if (!(zeta < 1))
        return std::nullopt;
    const auto growthPerPeriod = [zeta](Scalar x) {
        return 2 * std::numbers::pi / x * std::log1p(x * x - 2 * zeta * x);
    };
    // Bisection between where it starts to grow (2ζ) and one further, where for every ζ < 1 it
    // grows by more than twice a period (by 2π·ln(1 + x)/x at least, with x ≥ 1): the growth
    // rises with x between them.
    const Scalar doubling = std::log(Scalar(2));
    Scalar low = std::max(Scalar(2) * zeta, Scalar(1e-6));
    Scalar high = low + 1;
    for (int i = 0; i < 60; ++i) {
        const Scalar x = 0.5 * (low + high);
        (growthPerPeriod(x) > doubling ? high : low) = x;
    }
    return low;
}

SpringMode springMode(const World& world, const Spring& spring)
{
    const Body& a = world.body(spring.bodyA);
    const Body* b = spring.bodyB ? &world.body(*spring.bodyB) : nullptr;
    const Vec2 endA = a.worldPoint(spring.anchorA);
    const Vec2 endB = b ? b->worldPoint(spring.anchorB) : spring.anchorB;
    const Vec2 armA = endA - a.state.position;
    const Vec2 armB = b ? Vec2(endB - b->state.position) : Vec2::Zero();
    // Along the spring it pulls with k. Stretched past its rest length, its tension T also pulls
    // its ends back onto its line when they move across it, with a stiffness T/L = k·(1 − L₀/L):
    // a body whose anchor is far off its centre along the spring swings about it fastest across.
    // A spring of zero length pulls whichever way its ends part, and each turn is counted with the
    // whole arm.
    SpringMode mode;
    const Vec2 along = endB - endA;
    mode.length = along.norm();
    const auto inverseMassAcross = [&](const Vec2& direction) {
        const auto turn = [&](const Vec2& arm) {
            if (!(mode.length > 0))
                return arm.squaredNorm();
            const Scalar lever = arm.x() * direction.y() - arm.y() * direction.x();
            return lever * lever;
        };
        return a.invMass + turn(armA) * a.invInertia + (b ? b->invMass + turn(armB) * b->invInertia : Scalar(0));
    };
    const Vec2 u = mode.length > 0 ? Vec2(along / mode.length) : Vec2(1, 0);
    const Scalar axialInverse = inverseMassAcross(u);
    const Scalar acrossStiffness =
        mode.length > spring.restLength ? spring.stiffness * (1 - spring.restLength / mode.length) : Scalar(0);
    const Scalar acrossInverse = inverseMassAcross(Vec2(-u.y(), u.x()));
    mode.across = acrossStiffness * acrossInverse > spring.stiffness * axialInverse;
    mode.stiffness = mode.across ? acrossStiffness : spring.stiffness;
    mode.inverseMass = mode.across ? acrossInverse : axialInverse;
    mode.omega = std::sqrt(mode.stiffness * mode.inverseMass);
    // The dashpot acts along the spring: c/(2mω) there, and nothing across it.
    mode.zeta = !mode.across && mode.omega > 0 ? spring.damping * axialInverse / (2 * mode.omega) : Scalar(0);
    return mode;
}

std::vector<SceneProblem> sceneWarnings(const World& world)
{
    std::vector<SceneProblem> warnings;
    checkTimeStep(world.settings, warnings);
    checkGravity(world.settings, warnings);
    checkMassRatios(world, warnings);
    checkSpringSteps(world, warnings);
    return warnings;
}

EnergyBaseline energyBaseline(const World& world, Scalar total, Scalar kinetic, Scalar potential)
{
    EnergyBaseline baseline;
    for (const Body& body : world.bodies) {
        if (body.fixed && (body.state.velocity != Vec2::Zero() || body.state.angularVelocity != 0))
            return baseline; // a moving fixed body does work: growth is then physics
    }
    const Scalar scale = std::max(std::abs(total), kinetic + std::abs(potential));
    baseline.active = scale > 0 && std::isfinite(scale);
    baseline.start = total;
    baseline.bound = constants::kEnergyGrowthWarning * scale;
    return baseline;
}

std::optional<SceneProblem> energyGrowthWarning(const EnergyBaseline& baseline, Scalar now, Scalar time,
                                                IntegratorKind integrator)
{
    if (!baseline.active || !std::isfinite(now) || !(now - baseline.start > baseline.bound))
        return std::nullopt;
    const std::string cause =
        integrator == IntegratorKind::Euler
            ? "explicit Euler adds energy at every bounce and oscillation; rk4 or a smaller step keeps it"
            : "the step may be too long for the fastest motion, or impacts of fast-spinning bodies add it; a "
              "smaller step helps";
    return SceneProblem{"world.energy", "the energy grew from " + shown(baseline.start) + " J to " + shown(now) +
                                            " J by t = " + shown(time) + " s, more than " +
                                            shown(100 * constants::kEnergyGrowthWarning) +
                                            " % of its start, though nothing in the scene does work: " + cause +
                                            " (docs/physics.md, \"Energy over long runs\")"};
}

} // namespace impetus::model
