#include "app/cli.h"

#include "controller/diagnostics.h"
#include "controller/energy_ledger.h"
#include "controller/simulation.h"
#include "controller/soft/soft_body_builder.h"
#include "controller/soft/soft_comparison.h"
#include "controller/soft/soft_stability.h"
#include "model/constants.h"
#include "model/scene_io.h"
#include "model/scene_warnings.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <new>
#include <optional>
#include <set>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

namespace impetus::app {

namespace {

namespace fs = std::filesystem;

/// Simulated time run when neither --time nor --steps is given, s.
constexpr double kDefaultRunTime = 10.0;

/// The most steps one run takes, whether given by --steps or by --time. A billion steps is 48
/// days of simulated time at the default step and hours of wall time even for a one-body scene;
/// more is a typo, not a lesson (docs/cli.md).
constexpr std::int64_t kMaxRunSteps = 1'000'000'000;

/// Wall time between two updates of the progress line, s.
constexpr double kProgressInterval = 0.5;

constexpr std::string_view kUsage =
    "usage:\n"
    "  impetus-cli run SCENE.json [--time SECONDS | --steps N] [--dt SECONDS]\n"
    "                             [--integrator euler|semi-implicit-euler|rk4]\n"
    "                             [--csv FILE|-] [--sample-every N] [--summary FILE|-]\n"
    "                             [--collision-log FILE|-] [--compare-rigid BODY]\n"
    "                             [--auto-density cost|measure|N]\n"
    "  impetus-cli validate SCENE.json\n"
    "\n"
    "run       steps the scene headless with its fixed time step (default: 10 s of simulated time)\n"
    "validate  prints 'ok', or every problem in the scene\n"
    "--compare-rigid BODY  also runs the scene with BODY rigid and soft and prints, as CSV on\n"
    "          stdout, how far apart its two centre-of-mass paths are over time\n"
    "--auto-density  how soft bodies' \"auto\" density is chosen: cost (the default, the same on\n"
    "          every machine), measure (timed on this machine, as the app does), or N per m²\n"
    "exit codes: 0 success, 1 failure at run time, 2 bad usage or a bad scene\n";

/// The output name that means stdout, for --csv, --summary and --collision-log.
constexpr std::string_view kStdoutPath = "-";

/// How a headless run resolves a soft body's `"auto"` density.
enum class AutoDensityRule {
    CostModel, ///< the default: the same on every machine (kSoftAutoHeadlessBudget)
    Measure, ///< timed on this machine, as the app does
    Given, ///< the number given with --auto-density
};

/// What `run` was asked to do.
struct RunOptions {
    std::string scenePath;
    std::optional<double> time;
    std::optional<std::int64_t> steps;
    std::optional<double> dt;
    std::optional<model::IntegratorKind> integrator;
    std::optional<std::string> csvPath;
    std::int64_t sampleEvery = 1;
    std::optional<std::string> summaryPath;
    std::optional<std::string> collisionLogPath;
    std::optional<std::string> compareRigid; ///< body name: run it rigid and soft and compare
    /// How "auto" soft density is chosen (--auto-density): by the cost model, by timing this
    /// machine, or as the number given.
    AutoDensityRule autoDensityRule = AutoDensityRule::CostModel;
    Scalar autoDensity = 0; ///< ellipses per m², for AutoDensityRule::Given
};

/// Thrown inside argument parsing only; caught in runCli and turned into exit code 2.
struct UsageError {
    std::string message;
};

/// Shortest text that reads back as the same double (std::to_chars round-trip guarantee).
std::string formatNumber(double value)
{
    std::array<char, 32> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    return std::string(buffer.data(), result.ptr);
}

double parsePositiveSeconds(std::string_view flag, const std::string& text, bool allowZero)
{
    double value = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc{} || ptr != end || !std::isfinite(value))
        throw UsageError{std::string(flag) + ": expected a number of seconds, got '" + text + "'"};
    if (value < 0 || (!allowZero && value == 0))
        throw UsageError{std::string(flag) + ": must be " + (allowZero ? "zero or more" : "greater than zero") +
                         ", got " + text};
    return value;
}

std::int64_t parseCount(std::string_view flag, const std::string& text, std::int64_t minimum, std::int64_t maximum)
{
    const auto tooLarge = [&] {
        return UsageError{std::string(flag) + ": " + text + " is too large (at most " + std::to_string(maximum) + ")"};
    };
    std::int64_t value = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec == std::errc::result_out_of_range && ptr == end && text.front() != '-')
        throw tooLarge();
    if (ec != std::errc{} || ptr != end) {
        // "1e20" is a whole number written as a double: say what is wrong with it, and take
        // "1e3" as the 1000 it means.
        double real = 0;
        const auto [realEnd, realError] = std::from_chars(text.data(), end, real);
        const bool whole = realError == std::errc{} && realEnd == end && std::isfinite(real) && std::floor(real) == real;
        if (!whole)
            throw UsageError{std::string(flag) + ": expected a whole number, got '" + text + "'"};
        if (real > static_cast<double>(maximum))
            throw tooLarge();
        value = static_cast<std::int64_t>(real);
    }
    if (value < minimum)
        throw UsageError{std::string(flag) + ": must be at least " + std::to_string(minimum) + ", got " + text};
    if (value > maximum)
        throw tooLarge();
    return value;
}

/// True when `path` names the file at `other` (through links, or the same name when neither
/// exists yet).
bool sameFile(const std::string& path, const std::string& other)
{
    std::error_code ec;
    if (fs::equivalent(path, other, ec) && !ec)
        return true;
    const fs::path a = fs::weakly_canonical(path, ec);
    if (ec)
        return false;
    const fs::path b = fs::weakly_canonical(other, ec);
    return !ec && a == b;
}

/// Refuses outputs that would clash, before anything is read or written: two outputs on stdout
/// ("-"), two on one file, or one on the scene file itself (writing the CSV there would destroy
/// the scene being run).
void checkOutputs(const RunOptions& options)
{
    std::vector<std::pair<std::string_view, const std::optional<std::string>*>> outputs = {
        {"--csv", &options.csvPath}, {"--summary", &options.summaryPath}, {"--collision-log", &options.collisionLogPath}};
    std::optional<std::string> onStdout;
    if (options.compareRigid)
        onStdout = "--compare-rigid";
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const auto& [flag, path] = outputs[i];
        if (!*path)
            continue;
        if (**path == kStdoutPath) {
            const std::string named = std::string(flag) + " -";
            if (onStdout)
                throw UsageError{*onStdout + " and " + named + " both write to stdout: give one of them a file"};
            onStdout = named;
            continue;
        }
        if (sameFile(**path, options.scenePath))
            throw UsageError{std::string(flag) + ": '" + **path +
                             "' is the scene file being run; writing there would overwrite it"};
        for (std::size_t j = 0; j < i; ++j) {
            const auto& [otherFlag, otherPath] = outputs[j];
            if (*otherPath && **otherPath != kStdoutPath && sameFile(**path, **otherPath))
                throw UsageError{std::string(otherFlag) + " and " + std::string(flag) + " both write '" + **path +
                                 "': give each its own file"};
        }
    }
}

/// Parses the arguments after `run`. Accepts both "--flag value" and "--flag=value".
RunOptions parseRunOptions(std::span<const std::string> args)
{
    RunOptions options;
    bool haveScene = false;
    std::set<std::string> seenFlags;
    for (std::size_t i = 0; i < args.size(); ++i) {
        std::string arg = args[i];
        std::optional<std::string> inlineValue;
        if (arg.rfind("--", 0) == 0) {
            if (const auto eq = arg.find('='); eq != std::string::npos) {
                inlineValue = arg.substr(eq + 1);
                arg.resize(eq);
            }
        }
        auto value = [&]() -> std::string {
            if (inlineValue)
                return *inlineValue;
            if (i + 1 >= args.size())
                throw UsageError{arg + ": needs a value"};
            return args[++i];
        };

        if (arg.rfind("--", 0) == 0 && !seenFlags.insert(arg).second)
            throw UsageError{arg + ": given twice (give each option once)"};
        if (arg == "--time") {
            options.time = parsePositiveSeconds(arg, value(), true);
        } else if (arg == "--steps") {
            options.steps = parseCount(arg, value(), 0, kMaxRunSteps);
        } else if (arg == "--dt") {
            options.dt = parsePositiveSeconds(arg, value(), false);
        } else if (arg == "--integrator") {
            const std::string name = value();
            options.integrator = model::integratorFromName(name);
            if (!options.integrator)
                throw UsageError{"--integrator: unknown integrator '" + name +
                                 "' (expected euler, semi-implicit-euler or rk4)"};
        } else if (arg == "--csv") {
            options.csvPath = value();
        } else if (arg == "--sample-every") {
            options.sampleEvery = parseCount(arg, value(), 1, std::numeric_limits<std::int64_t>::max());
        } else if (arg == "--summary") {
            options.summaryPath = value();
        } else if (arg == "--collision-log") {
            options.collisionLogPath = value();
        } else if (arg == "--compare-rigid") {
            options.compareRigid = value();
        } else if (arg == "--auto-density") {
            const std::string text = value();
            if (text == "cost") {
                options.autoDensityRule = AutoDensityRule::CostModel;
            } else if (text == "measure") {
                options.autoDensityRule = AutoDensityRule::Measure;
            } else {
                double density = 0;
                const char* end = text.data() + text.size();
                const auto [ptr, ec] = std::from_chars(text.data(), end, density);
                if (ec != std::errc{} || ptr != end || !std::isfinite(density) || !(density > 0))
                    throw UsageError{"--auto-density: expected 'cost', 'measure' or a number of ellipses per m² "
                                     "greater than 0, got '" + text + "'"};
                options.autoDensityRule = AutoDensityRule::Given;
                options.autoDensity = density;
            }
        } else if (arg.rfind("--", 0) == 0 || (arg.size() > 1 && arg[0] == '-')) {
            throw UsageError{"unknown option '" + arg + "'"};
        } else if (!haveScene) {
            options.scenePath = arg;
            haveScene = true;
        } else {
            throw UsageError{"unexpected argument '" + arg + "' (only one scene file is run)"};
        }
    }
    if (!haveScene)
        throw UsageError{"run: no scene file given"};
    if (options.time && options.steps)
        throw UsageError{"--time and --steps cannot be used together"};
    checkOutputs(options);
    return options;
}

/// Loads a scene, printing every problem as "FILE: path: reason" on `err`.
std::optional<model::World> loadScene(const std::string& path, std::ostream& err)
{
    model::SceneLoadResult result = model::loadSceneFile(path);
    if (!result.ok()) {
        for (const model::SceneProblem& problem : result.problems)
            err << path << ": " << problem.toString() << '\n';
        return std::nullopt;
    }
    return std::move(*result.world);
}

/// Quotes a CSV field when it holds a comma, a quote or a line break (RFC 4180).
std::string csvField(const std::string& text)
{
    if (text.find_first_of(",\"\r\n") == std::string::npos)
        return text;
    std::string quoted = "\"";
    for (const char c : text) {
        if (c == '"')
            quoted += '"';
        quoted += c;
    }
    return quoted + '"';
}

/// One CSV row per body at simulated time `time`.
void writeCsvRows(std::ostream& csv, const model::World& world, double time)
{
    const std::string t = formatNumber(time);
    for (const model::Body& body : world.bodies) {
        const model::BodyState& s = body.state;
        const int colliding = body.colliding ? 1 : 0;
        csv << t << ',' << csvField(body.name) << ',' << formatNumber(s.position.x()) << ','
            << formatNumber(s.position.y()) << ',' << formatNumber(s.angle) << ','
            << formatNumber(s.velocity.x()) << ',' << formatNumber(s.velocity.y()) << ','
            << formatNumber(s.angularVelocity) << ',' << colliding << '\n';
    }
}

/// One CSV row per contact that began in the last step.
void writeCollisionLogRows(std::ostream& log, const model::World& world,
                           const std::vector<controller::CollisionEvent>& events, double time)
{
    for (const controller::CollisionEvent& e : events) {
        log << formatNumber(time) << ',' << csvField(world.body(e.bodyA).name) << ','
            << csvField(world.body(e.bodyB).name) << ',' << formatNumber(e.point.x()) << ','
            << formatNumber(e.point.y()) << ',' << formatNumber(e.normal.x()) << ',' << formatNumber(e.normal.y())
            << ',' << formatNumber(e.normalImpulse) << ',' << formatNumber(e.normalSpeedBefore) << ','
            << formatNumber(e.normalSpeedAfter) << '\n';
    }
}

/// Opens an output file for writing, reporting failure and its reason on `err`.
bool openOutput(std::ofstream& file, const std::string& path, std::string_view what, std::ostream& err)
{
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
        err << "impetus-cli run: cannot write the " << what << " file '" << path << "': it is a directory\n";
        return false;
    }
    errno = 0;
    file.open(path, std::ios::out | std::ios::trunc);
    if (!file) {
        err << "impetus-cli run: cannot write the " << what << " file '" << path << "'";
        if (errno != 0)
            err << ": " << std::error_code(errno, std::generic_category()).message();
        err << '\n';
    }
    return static_cast<bool>(file);
}

/// Where one output goes: stdout for "-", else a file opened before the run.
class Output {
public:
    /// Opens `path` (nothing when absent); false, with the reason on `err`, when it cannot be written.
    bool open(const std::optional<std::string>& path, std::string_view what, std::ostream& out, std::ostream& err)
    {
        if (!path)
            return true;
        m_path = *path;
        if (*path == kStdoutPath) {
            m_stream = &out;
            return true;
        }
        m_stream = &m_file;
        return openOutput(m_file, *path, what, err);
    }

    bool isOpen() const { return m_stream != nullptr; }
    std::ostream& stream() { return *m_stream; }
    const std::string& path() const { return m_path; }

private:
    std::ofstream m_file;
    std::ostream* m_stream = nullptr;
    std::string m_path;
};

nlohmann::ordered_json vectorJson(const Vec2& v) { return nlohmann::ordered_json::array({v.x(), v.y()}); }

/// What chose each soft body's density, for the notes and the summary.
std::string_view densityChooser(bool automatic, AutoDensityRule rule)
{
    if (!automatic)
        return "scene";
    switch (rule) {
    case AutoDensityRule::CostModel:
        return "cost model";
    case AutoDensityRule::Measure:
        return "measured";
    case AutoDensityRule::Given:
        return "--auto-density";
    }
    return "scene";
}

/// The energy ledger of a run (docs/physics.md, "The energy ledger"): the energies at its start and
/// end, and what each cause took out, J. A run of no steps has nothing booked: both energies
/// are the world's.
nlohmann::ordered_json ledgerJson(const model::World& world, const controller::EnergyLedger& ledger)
{
    const auto energyJson = [](const controller::Energy& e) {
        return nlohmann::ordered_json{
            {"kinetic", e.kinetic}, {"potential", e.potential}, {"elastic", e.elastic}, {"total", e.total()}};
    };
    const controller::EnergyLosses& l = ledger.losses();
    nlohmann::ordered_json json;
    const controller::Energy now = controller::computeEnergy(world);
    json["initial"] = energyJson(ledger.started() ? ledger.initialEnergy() : now);
    json["current"] = energyJson(ledger.started() ? ledger.currentEnergy() : now);
    json["losses"] = {{"impacts", l.impacts},
                      {"friction", l.friction},
                      {"drag", l.drag},
                      {"springDamping", l.springDamping},
                      {"softDamping", l.softDamping},
                      {"joints", l.joints},
                      {"correction", l.correction},
                      {"drift", l.drift},
                      {"total", l.total()}};
    json["closure"] = ledger.closure();
    return json;
}

/// The end-of-run summary in the contract's layout and key order.
nlohmann::ordered_json makeSummary(const model::World& world, double time, std::int64_t steps,
                                   const std::vector<bool>& automatic, AutoDensityRule rule,
                                   const controller::EnergyLedger& ledger)
{
    const controller::Energy energy = controller::computeEnergy(world);
    nlohmann::ordered_json summary;
    summary["time"] = time;
    summary["steps"] = steps;
    summary["collisions"] = world.collisionCount;
    summary["energy"] = {{"kinetic", energy.kinetic},
                         {"potential", energy.potential},
                         {"elastic", energy.elastic},
                         {"total", energy.total()}};
    summary["momentum"] = vectorJson(controller::linearMomentum(world));
    summary["angularMomentum"] = controller::angularMomentum(world);
    nlohmann::ordered_json bodies = nlohmann::ordered_json::array();
    for (const model::Body& body : world.bodies) {
        nlohmann::ordered_json b;
        b["name"] = body.name;
        b["position"] = vectorJson(body.state.position);
        b["angle"] = body.state.angle;
        b["velocity"] = vectorJson(body.state.velocity);
        b["angularVelocity"] = body.state.angularVelocity;
        b["mass"] = body.mass;
        b["inertia"] = body.inertia;
        b["collisions"] = body.collisionCount;
        b["colliding"] = body.colliding;
        const model::SoftGrid* grid = world.softGrid(model::BodyId{static_cast<std::uint32_t>(bodies.size())});
        b["ellipses"] = grid ? grid->size() : 0;
        if (grid) { // an extension: the density the grid was built at, and what chose it
            b["ellipsesPerSquareMeter"] = grid->ellipsesPerSquareMeter;
            b["densityChosenBy"] = densityChooser(automatic[bodies.size()], rule);
        }
        bodies.push_back(std::move(b));
    }
    summary["bodies"] = std::move(bodies);
    summary["energyLedger"] = ledgerJson(world, ledger); // an addition to the contract (docs/cli.md)
    return summary;
}

/// What makes one of the summary's energies or momenta non-finite: `what` completes
/// "… at t = T s (step k)" after the subject, e.g. "body 'b' has a non-finite kinetic energy".
struct NonFiniteDiagnostic {
    std::string subject; ///< "body 'b' has a non-finite kinetic energy"
    std::string reason; ///< "½mv² + ½Iω² overflows a double (mass 1e+200 kg, speed 1e+200 m/s)"
};

/// One of the summary's sums over the dynamic bodies, with each body's share of it.
struct DiagnosticSum {
    std::string_view name; ///< "kinetic energy"
    double total;
    std::string_view formula; ///< the body's share, for the message
    double (*share)(const model::Body&, const model::WorldSettings&);
};

double kineticShare(const model::Body& b, const model::WorldSettings&)
{
    const model::BodyState& s = b.state;
    return 0.5 * b.mass * s.velocity.squaredNorm() + 0.5 * b.inertia * s.angularVelocity * s.angularVelocity;
}
double potentialShare(const model::Body& b, const model::WorldSettings& w) { return -b.mass * w.gravity.dot(b.state.position); }
double momentumXShare(const model::Body& b, const model::WorldSettings&) { return b.mass * b.state.velocity.x(); }
double momentumYShare(const model::Body& b, const model::WorldSettings&) { return b.mass * b.state.velocity.y(); }
double angularShare(const model::Body& b, const model::WorldSettings&)
{
    return b.inertia * b.state.angularVelocity + b.mass * cross(b.state.position, b.state.velocity);
}

/// The first of the summary's energies and momenta that is not a finite number, and which body
/// makes it so; nullopt when they are all finite. A finite state can still overflow them (a mass
/// of 1e200 kg at 1e200 m/s): the summary would then hold null, so the run fails instead.
std::optional<NonFiniteDiagnostic> findNonFiniteDiagnostic(const model::World& world)
{
    const controller::Energy energy = controller::computeEnergy(world);
    const Vec2 momentum = controller::linearMomentum(world);
    const std::array<DiagnosticSum, 5> sums = {{
        {"kinetic energy", energy.kinetic, "½mv² + ½Iω²", kineticShare},
        {"potential energy", energy.potential, "−m·g·x", potentialShare},
        {"momentum (x)", momentum.x(), "m·vx", momentumXShare},
        {"momentum (y)", momentum.y(), "m·vy", momentumYShare},
        {"angular momentum", controller::angularMomentum(world), "I·ω + m·(x × v)", angularShare},
    }};
    for (const DiagnosticSum& sum : sums) {
        if (std::isfinite(sum.total))
            continue;
        // The body whose own share overflows, or else the largest share of a sum that overflows.
        const model::Body* largest = nullptr;
        double largestShare = 0;
        for (const model::Body& body : world.bodies) {
            if (body.fixed)
                continue;
            const double share = sum.share(body, world.settings);
            if (!std::isfinite(share)) {
                return NonFiniteDiagnostic{
                    "body '" + body.name + "' has a non-finite " + std::string(sum.name),
                    std::string(sum.formula) + " overflows a double (mass " + formatNumber(body.mass) +
                        " kg, speed " + formatNumber(std::hypot(body.state.velocity.x(), body.state.velocity.y())) +
                        " m/s, position (" + formatNumber(body.state.position.x()) + ", " +
                        formatNumber(body.state.position.y()) + ") m)"};
            }
            if (!largest || std::abs(share) > std::abs(largestShare)) {
                largest = &body;
                largestShare = share;
            }
        }
        if (largest) {
            return NonFiniteDiagnostic{"the total " + std::string(sum.name) + " is not finite",
                                       "the bodies' shares add up past the largest double; the largest share is body '" +
                                           largest->name + "''s (" + formatNumber(largestShare) + ")"};
        }
        return NonFiniteDiagnostic{"the total " + std::string(sum.name) + " is not finite",
                                   "a soft body's grid overflows a double"};
    }
    if (!std::isfinite(energy.elastic))
        return NonFiniteDiagnostic{"the elastic energy is not finite",
                                   "a spring's ½k(L − L₀)² overflows a double"};
    if (!std::isfinite(energy.total()))
        return NonFiniteDiagnostic{"the total energy is not finite",
                                   "kinetic, potential and elastic energy add up past the largest double"};
    return std::nullopt;
}

/// Checks the summary's diagnostics after `step` steps; reports on `err` and returns false when
/// one is not finite.
bool diagnosticsFinite(const model::World& world, std::int64_t step, double dt, std::ostream& err)
{
    const std::optional<NonFiniteDiagnostic> bad = findNonFiniteDiagnostic(world);
    if (!bad)
        return true;
    err << "impetus-cli run: " << bad->subject << " at t = " << formatNumber(static_cast<double>(step) * dt)
        << " s (step " << step << "): " << bad->reason << '\n';
    return false;
}

/// Watches a run's total energy and warns once when it grows past the bound of
/// model::energyGrowthWarning.
class EnergyWatch {
public:
    explicit EnergyWatch(const model::World& world)
    {
        const controller::Energy energy = controller::computeEnergy(world);
        m_baseline = model::energyBaseline(world, energy.total(), energy.kinetic, energy.potential);
    }

    /// Compares the energy at `step` with the start; the first time it is past the bound, says so.
    void check(const model::World& world, std::int64_t step, double dt, std::ostream& err)
    {
        if (!m_baseline.active)
            return;
        const double now = controller::computeEnergy(world).total();
        const double time = static_cast<double>(step) * dt;
        if (const std::optional<model::SceneProblem> warning =
                model::energyGrowthWarning(m_baseline, now, time, world.settings.integrator)) {
            err << "impetus-cli run: warning: " << warning->toString() << '\n';
            m_baseline.active = false;
        }
    }

private:
    model::EnergyBaseline m_baseline;
};

/// Prints "step k of n (p%)" on one rewritten terminal line, at most every kProgressInterval.
class ProgressLine {
public:
    ProgressLine(std::ostream& err, bool enabled, std::int64_t total)
        : m_err(err), m_enabled(enabled && total > 0), m_total(total), m_last(Clock::now())
    {
    }

    void update(std::int64_t done)
    {
        if (!m_enabled)
            return;
        const Clock::time_point now = Clock::now();
        if (std::chrono::duration<double>(now - m_last).count() < kProgressInterval)
            return;
        m_last = now;
        m_shown = true;
        m_err << "\rstep " << done << " of " << m_total << " ("
              << (100 * done) / m_total << "%)" << std::flush;
    }

    ~ProgressLine()
    {
        if (m_shown)
            m_err << "\r\033[K" << std::flush;
    }

    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

private:
    using Clock = std::chrono::steady_clock;
    std::ostream& m_err;
    bool m_enabled;
    bool m_shown = false;
    std::int64_t m_total;
    Clock::time_point m_last;
};

/// The soft bodies whose density is `"auto"`, by index.
std::vector<bool> autoDensityBodies(const model::World& world)
{
    std::vector<bool> automatic;
    for (const model::Body& body : world.bodies)
        automatic.push_back(body.soft && body.soft->autoDensity);
    return automatic;
}

/// `world` with every `"auto"` soft body fixed at `density`.
void fixAutoDensity(model::World& world, Scalar density)
{
    for (model::Body& body : world.bodies) {
        if (body.soft && body.soft->autoDensity) {
            body.soft->autoDensity = false;
            body.soft->ellipsesPerSquareMeter = density;
        }
    }
}

/// The cost model for `"auto"`: the highest of kSoftAutoDensities at which the world's ellipses
/// times its soft substeps per step stay within kSoftAutoHeadlessBudget (the lowest when none
/// does). It builds the grids at each candidate and counts; it times nothing, so every machine
/// picks the same.
Scalar costModelDensity(const model::World& world)
{
    Scalar chosen = constants::kSoftAutoDensities[0];
    for (const Scalar density : constants::kSoftAutoDensities) {
        model::World trial = world;
        fixAutoDensity(trial, density);
        controller::prepareSoftBodies(trial);
        std::size_t ellipses = 0;
        for (const model::SoftGrid& grid : trial.softBodies)
            ellipses += grid.size();
        const auto substeps = static_cast<std::size_t>(controller::softStability(trial).substeps);
        if (ellipses * substeps > constants::kSoftAutoHeadlessBudget)
            break;
        chosen = density;
    }
    return chosen;
}

/// Resolves `"auto"` in `world` as `options` say (measuring is left to prepareSoftBodies).
void resolveAutoDensity(model::World& world, const RunOptions& options)
{
    if (options.autoDensityRule == AutoDensityRule::CostModel)
        fixAutoDensity(world, costModelDensity(world));
    else if (options.autoDensityRule == AutoDensityRule::Given)
        fixAutoDensity(world, options.autoDensity);
}

/// Notes on stderr for the soft bodies: the density "auto" chose and how, and the substeps their
/// stiffness needs (with the reason).
void reportSoftBodies(const model::World& world, const std::vector<bool>& automatic, AutoDensityRule rule,
                      std::ostream& err)
{
    for (const model::SoftGrid& grid : world.softBodies) {
        if (automatic[grid.body.index]) {
            const std::string_view how = rule == AutoDensityRule::CostModel ? "by the cost model"
                                         : rule == AutoDensityRule::Measure ? "by timing this machine"
                                                                            : "as --auto-density says";
            err << "impetus-cli run: note: soft body '" << world.body(grid.body).name << "': \"auto\" chose "
                << formatNumber(grid.ellipsesPerSquareMeter) << " ellipses per m² " << how << " ("
                << grid.size() << " ellipses)\n";
        }
    }
    const controller::SoftStability stability = controller::softStability(world);
    if (!stability.message.empty())
        err << "impetus-cli run: note: " << stability.message << '\n';
}

/// --compare-rigid: the body's centre-of-mass paths, rigid and soft, and how far apart they are.
void writeComparison(std::ostream& out, const model::World& initial, model::BodyId body, std::int64_t steps,
                     std::int64_t sampleEvery)
{
    const controller::RigidSoftComparison c = controller::compareRigidSoft(initial, body, steps, sampleEvery);
    out << "time,rigidX,rigidY,softX,softY,distance\n";
    for (const controller::RigidSoftSample& s : c.samples) {
        out << formatNumber(s.time) << ',' << formatNumber(s.rigid.x()) << ',' << formatNumber(s.rigid.y()) << ','
            << formatNumber(s.soft.x()) << ',' << formatNumber(s.soft.y()) << ',' << formatNumber(s.distance) << '\n';
    }
    out << "# '" << initial.body(body).name << "' soft (" << c.ellipses << " ellipses, "
        << formatNumber(c.ellipsesPerSquareMeter) << " per m²) against rigid: rms distance "
        << formatNumber(c.rmsDistance) << " m, largest " << formatNumber(c.maxDistance) << " m at t = "
        << formatNumber(c.maxDistanceTime) << " s\n";
}

int commandValidate(std::span<const std::string> args, std::ostream& out, std::ostream& err)
{
    if (args.size() != 1) {
        err << "impetus-cli validate: expected exactly one scene file\n\n" << kUsage;
        return kExitBadInput;
    }
    const std::optional<model::World> world = loadScene(args[0], err);
    if (!world)
        return kExitBadInput;
    // Legal but outside the tested ranges: still "ok" and exit 0, with the reason on stderr.
    for (const model::SceneProblem& warning : model::sceneWarnings(*world))
        err << args[0] << ": warning: " << warning.toString() << '\n';
    out << "ok\n";
    return kExitOk;
}

int commandRun(std::span<const std::string> args, std::ostream& out, std::ostream& err, bool errIsTerminal)
{
    RunOptions options;
    try {
        options = parseRunOptions(args);
    } catch (const UsageError& e) {
        err << "impetus-cli run: " << e.message << "\n\n" << kUsage;
        return kExitBadInput;
    }

    std::optional<model::World> loaded = loadScene(options.scenePath, err);
    if (!loaded)
        return kExitBadInput;
    model::World world = std::move(*loaded);
    if (options.dt)
        world.settings.timeStep = *options.dt;
    if (options.integrator)
        world.settings.integrator = *options.integrator;
    const double dt = world.settings.timeStep;
    // After the flags, which may be what takes the settings out of range (--dt 5).
    for (const model::SceneProblem& warning : model::sceneWarnings(world))
        err << "impetus-cli run: warning: " << warning.toString() << '\n';

    // --time is rounded to the nearest whole number of fixed steps; the summary reports the time
    // actually simulated, steps × dt. It has the same limit as --steps.
    std::int64_t totalSteps = 0;
    if (options.steps) {
        totalSteps = *options.steps;
    } else {
        const double requested = options.time.value_or(kDefaultRunTime);
        const double count = std::round(requested / dt);
        if (!(count <= static_cast<double>(kMaxRunSteps))) {
            err << "impetus-cli run: --time: " << formatNumber(requested) << " s at dt = " << formatNumber(dt)
                << " s is " << formatNumber(count) << " steps, too large (at most " << kMaxRunSteps << " steps)\n";
            return kExitBadInput;
        }
        totalSteps = static_cast<std::int64_t>(count);
    }

    // Every output is opened before the first step, so that one that cannot be written fails at
    // once rather than after a long run.
    Output csv;
    Output collisionLog;
    Output summaryOutput;
    if (!csv.open(options.csvPath, "CSV", out, err) ||
        !collisionLog.open(options.collisionLogPath, "collision log", out, err) ||
        !summaryOutput.open(options.summaryPath, "summary", out, err))
        return kExitRuntimeFailure;
    if (csv.isOpen()) {
        csv.stream() << "time,body,x,y,angle,vx,vy,angularVelocity,colliding\n";
        writeCsvRows(csv.stream(), world, 0.0);
    }
    if (collisionLog.isOpen())
        collisionLog.stream() << "time,bodyA,bodyB,x,y,nx,ny,normalImpulse,normalSpeedBefore,normalSpeedAfter\n";

    std::optional<model::BodyId> compared;
    if (options.compareRigid) {
        compared = world.findBody(*options.compareRigid);
        if (!compared) {
            err << "impetus-cli run: --compare-rigid: no body called '" << *options.compareRigid << "' in "
                << options.scenePath << "\n";
            return kExitBadInput;
        }
    }

    // Soft bodies get their grids now, so that "auto" measures before the run and both notes
    // below come first.
    // "auto" is resolved first, so that --compare-rigid runs at the same density as the run.
    const std::vector<bool> automatic = autoDensityBodies(world);
    resolveAutoDensity(world, options);
    const model::World initial = world;
    controller::prepareSoftBodies(world);
    reportSoftBodies(world, automatic, options.autoDensityRule, err);

    // A state that starts finite can still overflow the summary's sums; failing now saves the run.
    if (!diagnosticsFinite(world, 0, dt, err))
        return kExitRuntimeFailure;

    controller::Simulation simulation;
    // The ledger costs a few energy sums a substep: kept only when a summary will show it.
    controller::EnergyLedger ledger;
    if (summaryOutput.isOpen())
        simulation.setLedger(&ledger);
    EnergyWatch energyWatch(world);
    {
        ProgressLine progress(err, errIsTerminal, totalSteps);
        for (std::int64_t step = 1; step <= totalSteps; ++step) {
            simulation.step(world);
            const double time = static_cast<double>(step) * dt;
            if (const std::optional<std::size_t> bad = controller::firstNonFiniteBody(world)) {
                err << "impetus-cli run: body '" << world.bodies[*bad].name << "' has a non-finite state at t = "
                    << formatNumber(time) << " s (step " << step << ")\n";
                return kExitRuntimeFailure;
            }
            if (csv.isOpen() && step % options.sampleEvery == 0)
                writeCsvRows(csv.stream(), world, time);
            if (collisionLog.isOpen())
                writeCollisionLogRows(collisionLog.stream(), world, simulation.events(), time);
            if (step % constants::kEnergyCheckSteps == 0 || step == totalSteps)
                energyWatch.check(world, step, dt, err);
            progress.update(step);
        }
    }

    for (Output* output : {&csv, &collisionLog}) {
        if (!output->isOpen())
            continue;
        output->stream().flush();
        if (!output->stream()) {
            err << "impetus-cli run: writing '" << output->path() << "' failed\n";
            return kExitRuntimeFailure;
        }
    }

    // The summary must never write null: a non-finite energy or momentum is a failure at run
    // time, like a non-finite state.
    if (!diagnosticsFinite(world, totalSteps, dt, err))
        return kExitRuntimeFailure;
    const double simulatedTime = static_cast<double>(totalSteps) * dt;
    const nlohmann::ordered_json summary =
        makeSummary(world, simulatedTime, totalSteps, automatic, options.autoDensityRule, ledger);
    if (summaryOutput.isOpen()) {
        summaryOutput.stream() << summary.dump(2) << '\n';
        summaryOutput.stream().flush();
        if (!summaryOutput.stream()) {
            err << "impetus-cli run: writing the summary file '" << summaryOutput.path() << "' failed\n";
            return kExitRuntimeFailure;
        }
    }
    // The closing line only when stdout carries nothing else, so that `--csv -` or `--summary -`
    // stays a clean CSV or JSON.
    const bool stdoutTaken = options.csvPath == kStdoutPath || options.summaryPath == kStdoutPath ||
                             options.collisionLogPath == kStdoutPath;
    if (!stdoutTaken) {
        out << "ran " << totalSteps << " steps (" << formatNumber(simulatedTime) << " s) with "
            << model::integratorName(world.settings.integrator) << ", dt = " << formatNumber(dt) << " s\n";
    }
    if (compared)
        writeComparison(out, initial, *compared, totalSteps, options.sampleEvery);
    return kExitOk;
}

} // namespace

int runCli(std::span<const std::string> args, std::ostream& out, std::ostream& err, bool errIsTerminal)
{
    try {
        if (args.empty()) {
            err << kUsage;
            return kExitBadInput;
        }
        const std::string& command = args[0];
        if (command == "--help" || command == "-h" || command == "help") {
            out << kUsage;
            return kExitOk;
        }
        if (command == "run")
            return commandRun(args.subspan(1), out, err, errIsTerminal);
        if (command == "validate")
            return commandValidate(args.subspan(1), out, err);
        err << "impetus-cli: unknown command '" << command << "'\n\n" << kUsage;
        return kExitBadInput;
    } catch (const std::bad_alloc&) {
        // Reading a scene reports this itself (exit 2); here it struck while building or running
        // the world. The stack is unwound, so the world's memory is free again for the message.
        err << "impetus-cli: out of memory: the scene is too large to simulate with the memory available\n";
        return kExitRuntimeFailure;
    } catch (const std::exception& e) {
        // Nothing above should throw; if something does, fail cleanly.
        err << "impetus-cli: " << e.what() << '\n';
        return kExitRuntimeFailure;
    }
}

} // namespace impetus::app
