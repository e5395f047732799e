#include "model/scene_warnings.h"

#include "model/constants.h"

#include <algorithm>
#include <Eigen/Dense>

#include <cmath>
#include <limits>
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

/// `value` and `bound` to kShownDigits significant digits, or to as many more as it takes for the
/// two to read differently (a value just past its bound must not read as equal to it).
std::pair<std::string, std::string> shownApart(Scalar value, Scalar bound)
{
    for (int digits = kShownDigits; digits < std::numeric_limits<Scalar>::max_digits10; ++digits) {
        std::ostringstream a;
        std::ostringstream b;
        a << std::setprecision(digits) << value;
        b << std::setprecision(digits) << bound;
        if (a.str() != b.str())
            return {a.str(), b.str()};
    }
    return {shown(value), shown(bound)};
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

/// Dynamic bodies so fast that they cross the whole scene (the box around every body) in one
/// solver step: such a body may meet the same bodies many times within a step, more often than
/// the impact pass resolves (kMaxImpactsPerPoint per contact point), and what is left goes to the
/// contact forces, which do not keep restitution. A scene of one body has nothing to meet.
void checkSpeeds(const World& world, std::vector<SceneProblem>& out)
{
    if (world.bodies.size() < 2)
        return;
    Vec2 lowest = Vec2::Constant(std::numeric_limits<Scalar>::infinity());
    Vec2 highest = -lowest;
    for (const Body& body : world.bodies) {
        const Vec2 reach = Vec2::Constant(body.geometry.boundingRadius);
        lowest = lowest.cwiseMin(Vec2(body.state.position - reach));
        highest = highest.cwiseMax(Vec2(body.state.position + reach));
    }
    const Scalar across = (highest - lowest).maxCoeff();
    if (!(across > 0) || !std::isfinite(across))
        return;
    const Scalar h = solverStep(world.settings.timeStep);
    const Scalar fastest = across / h;
    int reported = 0;
    int more = 0;
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        const Body& body = world.bodies[i];
        const Scalar speed = body.state.velocity.norm();
        if (body.fixed || !(speed > fastest))
            continue;
        if (reported == constants::kMaxSpeedWarnings) {
            ++more;
            continue;
        }
        ++reported;
        const auto [speedText, fastestText] = shownApart(speed, fastest);
        const auto [travelText, acrossText] = shownApart(speed * h, across);
        out.push_back({"bodies[" + std::to_string(i) + "]",
                       "'" + body.name + "' moves at " + speedText + " m/s, " + travelText + " m in one solver step of " +
                           shown(h * kMillisecondsPerSecond) + " ms, more than the " + acrossText +
                           " m across the whole scene: it may meet the same bodies more often in one step than the " +
                           std::to_string(constants::kMaxImpactsPerPoint) +
                           " impacts per contact point the solver resolves, and the contact forces that take the "
                           "rest do not keep restitution (it loses energy); keep its speed at most " +
                           fastestText + " m/s at this step, or make the step smaller"});
    }
    if (more > 0) {
        out.push_back({"bodies", "and " + std::to_string(more) + " more bodies that cross the whole scene in one "
                                     "solver step"});
    }
}

/// What goes wrong past the integrator's limit, for a motion that oscillates or one that is only
/// damped.
std::string integratorWords(IntegratorKind integrator, bool oscillates)
{
    switch (integrator) {
    case IntegratorKind::SemiImplicitEuler:
        return "semi-implicit Euler stays stable: the bodies on it will swing ever wider and fly apart";
    case IntegratorKind::Rk4:
        return "RK4 stays stable: the bodies on it will swing ever wider and fly apart";
    case IntegratorKind::Euler:
        break;
    }
    if (!oscillates)
        return "explicit Euler stays stable: the bodies on it will shake ever harder and fly apart";
    return "explicit Euler's energy doubles within one period (each step multiplies it by 1 − 2ζωh + ω²h², ζ the "
           "damping ratio)";
}

/// A spring too stiff, or too strongly damped, for the step: the spring and the bodies it joins
/// move in modes (springMode), and an integrator that takes steps longer than
/// longestStableStep() makes the fastest of them grow. A world with no joint, soft body or
/// contact is not split for a spring: a lesson on integrators shows each one's error at the step
/// the user chose.
void checkSpringSteps(const World& world, std::vector<SceneProblem>& out)
{
    for (std::size_t i = 0; i < world.springs.size(); ++i) {
        if (std::optional<SceneProblem> warning = springWarning(world, i))
            out.push_back(std::move(*warning));
    }
}

/// One step of `integrator` on ẍ = −ω²x − r·ẋ: the matrix that takes (x, v) to the next (x, v).
/// Semi-implicit Euler as the engine does it: the force from the state at the start of the step,
/// then the velocity, then the position with the new velocity.
Eigen::Matrix2d stepMatrix(IntegratorKind integrator, Scalar omega, Scalar rate, Scalar h)
{
    Eigen::Matrix2d a;
    a << 0, 1, -omega * omega, -rate;
    const Eigen::Matrix2d ha = h * a;
    const Eigen::Matrix2d identity = Eigen::Matrix2d::Identity();
    switch (integrator) {
    case IntegratorKind::Euler:
        return identity + ha;
    case IntegratorKind::SemiImplicitEuler: {
        Eigen::Matrix2d m;
        m << 1 - h * h * omega * omega, h * (1 - h * rate), -h * omega * omega, 1 - h * rate;
        return m;
    }
    case IntegratorKind::Rk4:
        break;
    }
    const Eigen::Matrix2d ha2 = ha * ha;
    return identity + ha + ha2 / 2 + ha2 * ha / 6 + ha2 * ha2 / 24;
}

/// The largest |λ| of a real 2×2 matrix.
Scalar spectralRadius(const Eigen::Matrix2d& m)
{
    const Scalar half = 0.5 * m.trace();
    const Scalar discriminant = half * half - m.determinant();
    if (discriminant < 0)
        return std::sqrt(m.determinant()); // a complex pair: |λ|² = λ·λ̄ = det
    const Scalar root = std::sqrt(discriminant);
    return std::max(std::abs(half + root), std::abs(half - root));
}

/// The ω·h at which explicit Euler's energy doubles within one period of an oscillator of damping
/// ratio ζ < 1: each step multiplies the energy by |1 + hλ|² = 1 − 2ζωh + ω²h², a period is
/// 2π/(ωh) steps. Bisection between where it starts to grow (2ζ) and one further, where for every
/// ζ < 1 it grows by more than twice a period (by 2π·ln(1 + x)/x at least, with x ≥ 1).
Scalar eulerDoublingOmegaStep(Scalar zeta)
{
    const auto growthPerPeriod = [zeta](Scalar x) {
        return 2 * std::numbers::pi / x * std::log1p(x * x - 2 * zeta * x);
    };
    const Scalar doubling = std::log(Scalar(2));
    Scalar low = std::max(Scalar(2) * zeta, Scalar(1e-6));
    Scalar high = low + 1;
    for (int i = 0; i < 60; ++i) {
        const Scalar x = 0.5 * (low + high);
        (growthPerPeriod(x) > doubling ? high : low) = x;
    }
    return low;
}

} // namespace

std::optional<Scalar> longestStableStep(IntegratorKind integrator, Scalar omega, Scalar rate)
{
    if (!(omega > 0) && !(rate > 0))
        return std::nullopt;
    if (!std::isfinite(omega) || !std::isfinite(rate))
        return Scalar(0);
    if (integrator == IntegratorKind::Euler && omega > 0 && rate < 2 * omega)
        return eulerDoublingOmegaStep(rate / (2 * omega)) / omega;
    // The first step, in units of the motion's own time 1/max(ω, r), at which one step grows the
    // state: scanned in small steps (each integrator's region is found within the first few), then
    // bisected.
    const Scalar scale = std::max(omega, rate);
    const auto grows = [&](Scalar s) {
        return spectralRadius(stepMatrix(integrator, omega, rate, s / scale)) > 1 + 1e-12;
    };
    constexpr Scalar kScanStep = 0.01;
    constexpr Scalar kScanEnd = 20;
    Scalar low = 0;
    Scalar high = 0;
    for (Scalar s = kScanStep; s <= kScanEnd; s += kScanStep) {
        if (grows(s)) {
            high = s;
            break;
        }
        low = s;
    }
    if (!(high > 0))
        return std::nullopt;
    for (int i = 0; i < 50; ++i) {
        const Scalar s = 0.5 * (low + high);
        (grows(s) ? high : low) = s;
    }
    return low / scale;
}

std::optional<Scalar> stableOmegaStep(IntegratorKind integrator, Scalar zeta)
{
    return longestStableStep(integrator, 1, 2 * zeta);
}

SpringMode springMode(const World& world, const Spring& spring)
{
    // The generalised coordinates are x, y and θ of each dynamic body the spring joins; J takes
    // their velocities to the rate of change of d = end B − end A.
    const auto dynamic = [&](std::optional<BodyId> id) -> const Body* {
        if (!id || id->index >= world.bodies.size())
            return nullptr;
        const Body& body = world.body(*id);
        return body.fixed || !(body.invMass > 0) ? nullptr : &body;
    };
    const Body* a = dynamic(spring.bodyA);
    const Body* b = dynamic(spring.bodyB);
    const auto endOf = [&](std::optional<BodyId> id, const Vec2& anchor) -> Vec2 {
        if (!id)
            return anchor;
        if (id->index >= world.bodies.size())
            return Vec2::Zero();
        return world.body(*id).worldPoint(anchor);
    };
    const Vec2 endA = endOf(spring.bodyA, spring.anchorA);
    const Vec2 endB = endOf(spring.bodyB, spring.anchorB);
    const int n = 3 * ((a ? 1 : 0) + (b ? 1 : 0));
    SpringMode mode;
    if (n == 0)
        return mode;
    Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(2, n);
    Eigen::VectorXd rootInverseMass(n);
    std::vector<std::pair<int, Scalar>> turnTerms; // (column of θ, T·(u·arm) with its sign)
    const Vec2 along = endB - endA;
    const Scalar length = along.norm();
    const Vec2 u = length > 0 ? Vec2(along / length) : Vec2::Zero();
    const Scalar tension = length > 0 ? spring.stiffness * (length - spring.restLength) : Scalar(0);
    int column = 0;
    const auto addBody = [&](const Body& body, const Vec2& end, Scalar sign) {
        const Vec2 arm = end - body.state.position;
        jacobian(0, column) = sign;
        jacobian(1, column + 1) = sign;
        jacobian(0, column + 2) = -sign * arm.y(); // d(end)/dθ = the arm turned a quarter turn
        jacobian(1, column + 2) = sign * arm.x();
        rootInverseMass(column) = std::sqrt(body.invMass);
        rootInverseMass(column + 1) = std::sqrt(body.invMass);
        rootInverseMass(column + 2) = std::sqrt(body.invInertia);
        // The end's second derivative in θ is −arm: the tension's pull along u stiffens a turn by
        // T·(u·arm) at end B's side and the opposite at end A's (an anchor on the far side tips).
        turnTerms.emplace_back(column + 2, -sign * tension * u.dot(arm));
        column += 3;
    };
    if (a)
        addBody(*a, endA, -1);
    if (b)
        addBody(*b, endB, 1);
    // The energy's Hessian in d: k along the spring, T/L across it (zero length: k every way); the
    // dashpot acts along it.
    Eigen::Matrix2d hessian = spring.stiffness * Eigen::Matrix2d::Identity();
    Eigen::Matrix2d dashpot = Eigen::Matrix2d::Identity();
    if (length > 0) {
        const Eigen::Matrix2d alongU = u * u.transpose();
        hessian = spring.stiffness * alongU + tension / length * (Eigen::Matrix2d::Identity() - alongU);
        dashpot = alongU;
    }
    Eigen::MatrixXd stiffness = jacobian.transpose() * hessian * jacobian;
    for (const auto& [at, term] : turnTerms)
        stiffness(at, at) += term;
    const Eigen::MatrixXd damping = spring.damping * (jacobian.transpose() * dashpot * jacobian);
    const auto scaled = [&](const Eigen::MatrixXd& m) {
        return Eigen::MatrixXd(rootInverseMass.asDiagonal() * m * rootInverseMass.asDiagonal());
    };
    const Eigen::MatrixXd massStiffness = scaled(stiffness);
    const Eigen::MatrixXd massDamping = scaled(damping);
    if (!massStiffness.allFinite() || !massDamping.allFinite()) {
        mode.omega = std::numeric_limits<Scalar>::infinity();
        return mode;
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> modes(massStiffness);
    const Eigen::Index fastest = n - 1; // eigenvalues in increasing order
    const Scalar omegaSquared = modes.eigenvalues()(fastest);
    if (omegaSquared > 0) {
        mode.omega = std::sqrt(omegaSquared);
        const Eigen::VectorXd shape = modes.eigenvectors().col(fastest);
        mode.rate = std::max(Scalar(0), shape.dot(massDamping * shape));
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> damped(massDamping, Eigen::EigenvaluesOnly);
    mode.dampingRate = std::max(Scalar(0), damped.eigenvalues()(n - 1));
    return mode;
}

Scalar springIntegratorStep(const World& world)
{
    // A world with joints or soft bodies is always split; one with contacts only while they last,
    // so its full step is the one judged.
    const Scalar h = world.settings.timeStep;
    return world.joints.empty() && world.softBodies.empty() ? h : solverStep(h);
}

namespace {

/// The longest stable steps of a spring's fastest mode and of its dashpot alone, infinite for no
/// limit (plain numbers: GCC's flow analysis takes optionals read under a condition for
/// uninitialised).
struct SpringLimits {
    Scalar swinging = std::numeric_limits<Scalar>::infinity();
    Scalar damped = std::numeric_limits<Scalar>::infinity();
};

SpringLimits springLimits(IntegratorKind integrator, const SpringMode& mode)
{
    constexpr Scalar kNoLimit = std::numeric_limits<Scalar>::infinity();
    SpringLimits limits;
    if (mode.omega > 0)
        limits.swinging = longestStableStep(integrator, mode.omega, mode.rate).value_or(kNoLimit);
    if (mode.dampingRate > 0)
        limits.damped = longestStableStep(integrator, 0, mode.dampingRate).value_or(kNoLimit);
    return limits;
}

} // namespace

std::optional<Scalar> longestStableSpringStep(const World& world, const Spring& spring)
{
    const SpringLimits limits = springLimits(world.settings.integrator, springMode(world, spring));
    const Scalar longest = std::min(limits.swinging, limits.damped);
    return std::isinf(longest) ? std::nullopt : std::optional<Scalar>(longest);
}

std::optional<SceneProblem> springWarning(const World& world, std::size_t index)
{
    if (index >= world.springs.size())
        return std::nullopt;
    const Spring& spring = world.springs[index];
    const Scalar h = springIntegratorStep(world);
    if (!(h > 0) || (!(spring.stiffness > 0) && !(spring.damping > 0)))
        return std::nullopt;
    const IntegratorKind integrator = world.settings.integrator;
    const SpringMode mode = springMode(world, spring);
    const SpringLimits limits = springLimits(integrator, mode);
    const std::string path = "springs[" + std::to_string(index) + "]";
    const std::string step = shown(h * kMillisecondsPerSecond) + " ms";
    if (h > limits.swinging && limits.swinging <= limits.damped) {
        const bool oscillates = mode.rate < 2 * mode.omega;
        return SceneProblem{path, "k = " + shown(spring.stiffness) + " N/m swings the bodies on it at ω = " +
                                      shown(mode.omega) + " rad/s (its fastest motion, the bodies' turns included; "
                                      "damping ratio " + shown(mode.rate / (2 * mode.omega)) + "): ω·h = " +
                                      shown(mode.omega * h) + " at the integrators' step of " + step + ", past the " +
                                      shown(mode.omega * limits.swinging) + " at which " +
                                      integratorWords(integrator, oscillates) + "; make the step at most " +
                                      shown(limits.swinging * kMillisecondsPerSecond) + " ms, or the spring softer"};
    }
    if (h > limits.damped) {
        return SceneProblem{path, "c = " + shown(spring.damping) + " N·s/m slows the bodies on it at " +
                                      shown(mode.dampingRate) + " /s: at the integrators' step of " + step +
                                      " that is " + shown(mode.dampingRate * h) + " a step, past the " +
                                      shown(mode.dampingRate * limits.damped) + " at which " +
                                      integratorWords(integrator, false) + "; make the step at most " +
                                      shown(limits.damped * kMillisecondsPerSecond) + " ms, or the damping smaller"};
    }
    return std::nullopt;
}

std::vector<SceneProblem> sceneWarnings(const World& world)
{
    std::vector<SceneProblem> warnings;
    checkTimeStep(world.settings, warnings);
    checkGravity(world.settings, warnings);
    checkMassRatios(world, warnings);
    checkSpeeds(world, warnings);
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
