// Steps the same scenes in Impetus, Box2D 2.4, Chipmunk and Box2D v3, one engine after the other
// (each in a child process of this one, see runEngine), and prints per scene the time per step and per simulated second and
// measures of the quality of the result: once with each engine at the settings it recommends,
// once with every engine at one common step.
// Run: build/bench/bench/impetus-bench-compare [--scene NAME] [--step S] [--seconds S] [--quick] ...
// docs/benchmarks.md explains the scenes, what keeps the comparison fair, and every column.

#include "box2d_v3_engine.h"
#include "peer_engines.h"
#include "pose_quality.h"

#include "controller/dynamics/contact_batches.h"
#include "controller/simulation.h"
#include "model/example_scenes.h"

#include <poll.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <new>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace {

using namespace impetus;
using namespace impetus::bench;

/// The common step of the second table unless --step says otherwise, s: the step the peers
/// recommend.
constexpr Scalar kDefaultCommonStep = kPeerRecommendedStep;

/// Simulated time is given in frames of 1/60 s, so that each of v3's scenes runs as long as v3's
/// own benchmark runs it (its step counts at 1/60 s).
constexpr Scalar kFrame = 1.0 / 60.0;

/// Simulated time per scene under --quick, in frames: a smoke test, not a measurement.
constexpr int kQuickFrames = 15;

/// Wall-clock time one engine may take to run one scene, s, unless --time-limit says otherwise:
/// an engine that takes longer is stopped and reported with the steps it did. The longest run
/// that finishes, on the 2-core development machine, takes about 30 s (Box2D 2.4 on the
/// tumbler); twice that leaves room for a busy machine.
constexpr double kDefaultTimeLimit = 60;
/// The same under --quick, s.
constexpr double kQuickTimeLimit = 10;

/// Address space one engine may take for one scene, bytes: the largest scene needs well under
/// 1 GiB in every engine, so a run that wants more has run away (Impetus's contacts did, on the
/// joint grid), and stopping it at 8 GiB keeps it from taking the memory of the machine's other
/// work. Set on the child process (RLIMIT_AS).
constexpr rlim_t kMemoryLimit = rlim_t{8} << 30;

/// How often a run's deepest overlap is looked at, in simulated time (s): every frame of a 60 Hz
/// display, so that what a viewer could see is counted, and at the same times for every engine.
constexpr Scalar kOverlapSampleTime = 1.0 / 60;

/// The seed of the polygon rain: any fixed value, so every run rains the same polygons.
constexpr unsigned kRainSeed = 1;

/// One benchmark scene: the world every engine starts from, what turns, which bodies are the tops
/// of pyramids (whose drift is the classic measure of a stacking solver's quality), and how long
/// to simulate it.
struct Scene {
    std::string name;
    std::string description;
    model::World world;
    Turning turning;
    std::vector<std::size_t> topBoxes;
    Scalar seconds = 0; ///< simulated time every engine runs, s
};

struct SceneRecipe {
    std::string name;
    /// Simulated time, frames of kFrame: v3's own step count for its scenes.
    int frames;
    std::function<Scene(bool quick)> build;
};

Scene pyramidScene(bool quick)
{
    const int base = quick ? 20 : 100;
    Scene scene{"pyramid", "", model::makePyramid(base), {}, {}, 0};
    scene.description = "Box2D's pyramid (v3: large_pyramid): base " + std::to_string(base) + ", " +
                        std::to_string(base * (base + 1) / 2) + " boxes of 1 m on a fixed ground";
    scene.topBoxes = {scene.world.bodies.size() - 1}; // makePyramid's order: the top box is last
    return scene;
}

Scene pyramidGridScene(bool quick)
{
    const int count = quick ? 3 : 20;
    const int base = 10;
    Scene scene{"pyramid-grid", "", model::makePyramidGrid(count, count, base), {}, {}, 0};
    const std::size_t perPyramid = base * (base + 1) / 2;
    scene.description = "v3's many_pyramids: " + std::to_string(count) + " x " + std::to_string(count) +
                        " pyramids of base " + std::to_string(base) + " (" +
                        std::to_string(count * count * static_cast<int>(perPyramid)) + " boxes) on " +
                        std::to_string(count) + " grounds";
    // makePyramidGrid's order: the grounds, then each pyramid with its top box last.
    for (std::size_t p = 0; p < static_cast<std::size_t>(count * count); ++p)
        scene.topBoxes.push_back(static_cast<std::size_t>(count) + (p + 1) * perPyramid - 1);
    return scene;
}

Scene polygonRainScene(bool quick)
{
    const int count = quick ? 200 : 1000;
    return Scene{"polygon-rain",
                 std::to_string(count) + " random convex polygons (3-8 vertices, 0.3-0.8 m) falling into an open box",
                 model::makePolygonRain(count, kRainSeed),
                 {},
                 {},
                 0};
}

Scene rotatingBoxScene(bool quick)
{
    const int count = quick ? 300 : 2000;
    std::ostringstream description;
    description << count << " circles of radius 0.25 m in a closed box turning at "
                << model::kRotatingContainerAngularVelocity << " rad/s";
    return Scene{"rotating-box", description.str(), model::makeRotatingBoxWithCircles(count),
                 Turning{Vec2::Zero(), model::kRotatingContainerAngularVelocity}, {}, 0};
}

Scene smashScene(bool quick)
{
    // v3's sizes, and those of its debug build for --quick.
    const int columns = quick ? 20 : 120;
    const int rows = quick ? 10 : 80;
    return Scene{"smash",
                 "v3's smash: a block of 8 m x 8 m at 40 m/s into a wall of " + std::to_string(columns * rows) +
                     " boxes of 0.4 m, no gravity",
                 model::makeSmash(columns, rows),
                 {},
                 {},
                 0};
}

Scene spinnerScene(bool quick)
{
    const int count = quick ? 499 : 6076;
    return Scene{"spinner",
                 "v3's spinner: " + std::to_string(count) +
                     " capsules, circles and squares stirred by an arm turning at 5 rad/s in a ring of 40 m",
                 model::makeSpinner(count),
                 {},
                 {},
                 0};
}

Scene tumblerScene(bool quick)
{
    const int gridCount = quick ? 20 : 45;
    std::ostringstream description;
    description << "v3's tumbler: " << gridCount * gridCount
                << " boxes of 0.25 m in a closed box of 19 m turning at 25 deg/s";
    return Scene{"tumbler", description.str(), model::makeTumbler(gridCount),
                 Turning{Vec2(0, model::kTumblerPivotHeight), model::kTumblerAngularVelocity}, {}, 0};
}

Scene jointGridScene(bool quick)
{
    const int size = quick ? 20 : 100;
    model::World world = model::makeJointGrid(size);
    const std::string description = "v3's joint_grid: " + std::to_string(size) + " x " + std::to_string(size) +
                                    " discs and " + std::to_string(world.joints.size()) +
                                    " pin joints hanging from 7 fixed discs (the discs collide)";
    return Scene{"joint-grid", description, std::move(world), {}, {}, 0};
}

const std::vector<SceneRecipe>& recipes()
{
    static const std::vector<SceneRecipe> all = {
        {"pyramid", 500, pyramidScene},     {"pyramid-grid", 200, pyramidGridScene},
        {"polygon-rain", 300, polygonRainScene}, {"rotating-box", 300, rotatingBoxScene},
        {"smash", 300, smashScene},         {"spinner", 500, spinnerScene},
        {"tumbler", 750, tumblerScene},     {"joint-grid", 500, jointGridScene},
    };
    return all;
}

/// The engines in the order they run; --engines picks some of them.
const std::vector<std::string>& engineNames()
{
    static const std::vector<std::string> all = {"impetus", "box2d", "chipmunk", "box2d3"};
    return all;
}

struct Options {
    std::optional<Scalar> seconds; ///< simulated time per scene, s; empty: each scene's own
    std::optional<Scalar> commonStep; ///< --step: only the common-step table, at this step (s)
    std::string scene; ///< empty: all
    std::vector<std::string> engines = engineNames();
    std::optional<double> timeLimit; ///< wall-clock seconds per engine and scene; empty: the default
    bool quick = false;
    bool oneThread = false; ///< Impetus without its second thread
    bool noBatches = false; ///< Impetus's velocity passes one contact at a time
};

/// "box2d,chipmunk" → {"box2d", "chipmunk"}, in the canonical order; nullopt for an unknown name.
std::optional<std::vector<std::string>> parseEngineList(const std::string& list)
{
    std::vector<std::string> named;
    std::stringstream stream(list);
    std::string item;
    while (std::getline(stream, item, ','))
        named.push_back(item);
    for (const std::string& name : named) {
        if (std::find(engineNames().begin(), engineNames().end(), name) == engineNames().end())
            return std::nullopt;
    }
    std::vector<std::string> chosen;
    for (const std::string& name : engineNames()) {
        if (std::find(named.begin(), named.end(), name) != named.end())
            chosen.push_back(name);
    }
    if (chosen.empty())
        return std::nullopt;
    return chosen;
}

void printUsage(std::ostream& out)
{
    out << "usage: impetus-bench-compare [--scene NAME] [--engines LIST] [--step S] [--seconds S]\n"
           "                             [--time-limit S] [--one-thread] [--no-batches] [--quick]\n"
           "  --scene NAME    run one scene:";
    for (const SceneRecipe& recipe : recipes())
        out << ' ' << recipe.name;
    out << "\n  --engines LIST  comma-separated, from impetus,box2d,chipmunk,box2d3 (default: all four)\n"
           "  --step S        every engine at one step of S seconds (e.g. 1/120), one table (default: each engine at its\n"
           "                  recommended settings, then all at a common step of 1/60 s)\n"
           "  --seconds S     simulated seconds per scene (default: each scene's own, v3's for its scenes)\n"
           "  --time-limit S  wall-clock seconds an engine may take for one scene before it is stopped\n"
           "                  (default "
        << kDefaultTimeLimit << ", " << kQuickTimeLimit
        << " with --quick)\n"
           "  --one-thread    Impetus without its second thread (the same results, one core)\n"
           "  --no-batches    Impetus's velocity passes one contact at a time, not in batches\n"
           "  --quick         small scenes, "
        << kQuickFrames << " frames of 1/60 s: a smoke test, not a measurement\n";
}

/// A positive number of seconds, at most `limit`, from a command-line value: a decimal number or
/// a fraction such as "1/60"; nullopt otherwise.
std::optional<Scalar> parseSeconds(const char* text, Scalar limit)
{
    char* end = nullptr;
    Scalar value = std::strtod(text, &end);
    if (end != text && *end == '/') {
        const char* denominator = end + 1;
        value /= std::strtod(denominator, &end);
        if (end == denominator)
            return std::nullopt;
    }
    if (end == text || *end != '\0' || !(value > 0) || !(value <= limit))
        return std::nullopt;
    return value;
}

std::optional<Options> parseArguments(int argc, char** argv)
{
    /// Bounds on --step and --seconds, s: a step longer than a second or a run longer than an hour
    /// of simulated time is a typo.
    constexpr Scalar kLongestStep = 1;
    constexpr Scalar kLongestRun = 3600;
    Options options;
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        const bool hasValue = i + 1 < argc;
        if (argument == "--seconds" && hasValue) {
            options.seconds = parseSeconds(argv[++i], kLongestRun);
            if (!options.seconds) {
                std::cerr << "impetus-bench-compare: --seconds takes a number of seconds above 0, at most "
                          << kLongestRun << "\n";
                return std::nullopt;
            }
        } else if (argument == "--time-limit" && hasValue) {
            options.timeLimit = parseSeconds(argv[++i], kLongestRun);
            if (!options.timeLimit) {
                std::cerr << "impetus-bench-compare: --time-limit takes a number of seconds above 0, at most "
                          << kLongestRun << "\n";
                return std::nullopt;
            }
        } else if (argument == "--step" && hasValue) {
            options.commonStep = parseSeconds(argv[++i], kLongestStep);
            if (!options.commonStep) {
                std::cerr << "impetus-bench-compare: --step takes a step in seconds above 0, at most " << kLongestStep
                          << " (e.g. 0.005 or 1/120)\n";
                return std::nullopt;
            }
        } else if (argument == "--scene" && hasValue) {
            options.scene = argv[++i];
            const auto& all = recipes();
            if (std::none_of(all.begin(), all.end(), [&](const SceneRecipe& r) { return r.name == options.scene; })) {
                std::cerr << "impetus-bench-compare: no scene called \"" << options.scene << "\"\n";
                printUsage(std::cerr);
                return std::nullopt;
            }
        } else if (argument == "--engines" && hasValue) {
            const std::optional<std::vector<std::string>> engines = parseEngineList(argv[++i]);
            if (!engines) {
                std::cerr << "impetus-bench-compare: --engines takes a comma-separated list of impetus, box2d, "
                             "chipmunk, box2d3\n";
                return std::nullopt;
            }
            options.engines = *engines;
        } else if (argument == "--one-thread") {
            options.oneThread = true;
        } else if (argument == "--no-batches") {
            options.noBatches = true;
        } else if (argument == "--quick") {
            options.quick = true;
        } else if (argument == "--help" || argument == "-h") {
            printUsage(std::cout);
            std::exit(0);
        } else {
            std::cerr << "impetus-bench-compare: unknown or incomplete argument \"" << argument << "\"\n";
            printUsage(std::cerr);
            return std::nullopt;
        }
    }
    return options;
}

/// What one engine did with one scene at one step.
struct Run {
    std::string id; ///< the engine's name in engineNames()
    std::string engine; ///< the engine's display name
    Scalar timeStep = 0; ///< s
    int plannedSteps = 0; ///< the steps that make up the scene's simulated time
    std::vector<double> stepMs; ///< wall-clock time of each step done, ms
    std::vector<Pose> poses; ///< at the end; empty when the run did not finish
    /// The deepest overlap of any two bodies over the run, looked at every kOverlapSampleTime of
    /// simulated time (m); empty when the scene's shapes cannot be measured (an ellipse).
    std::optional<Scalar> peakOverlap;
    std::optional<controller::StepProfile> impetusProfile; ///< Impetus only: summed over the steps done
    std::optional<Box2dV3Profile> v3Profile; ///< Box2D v3 only: summed over the steps done
    std::string failure; ///< why the engine could not take the scene; empty when it ran
    bool stopped = false; ///< stopped at the time limit before the last step
};

/// The steps of `timeStep` that make up `seconds` of simulated time (at least one).
int stepsFor(Scalar seconds, Scalar timeStep)
{
    return std::max(1, static_cast<int>(std::lround(seconds / timeStep)));
}

/// The display name of the engine called `name` (one of engineNames()), for a run that never
/// built it.
std::string displayName(const std::string& name)
{
    if (name == "impetus")
        return "Impetus";
    if (name == "box2d")
        return "Box2D 2.4";
    if (name == "chipmunk")
        return "Chipmunk";
    return "Box2D v3";
}

/// What a run's child process hands back to the parent, in memory they share. The child writes
/// it as it goes; the parent reads it once the child has ended (or has been stopped), so the two
/// never touch it at the same time. The step times and the poses follow it in the same mapping.
struct SharedRun {
    int stepsDone = 0;
    bool finished = false; ///< every step done and the poses written
    bool overlapMeasured = false; ///< peakOverlap holds: the shapes can be measured
    Scalar peakOverlap = 0; ///< m, over the steps done (Run::peakOverlap)
    bool hasImpetusProfile = false;
    controller::StepProfile impetusProfile; ///< summed over the steps done
    bool hasV3Profile = false;
    Box2dV3Profile v3Profile; ///< summed over the steps done
    char failure[256] = {}; ///< the engine refused the scene: why (empty otherwise)
};

/// Memory shared with a child process: one SharedRun, then `steps` step times (ms), then three
/// doubles (x, y, angle) per body. Unmapped when it goes.
class SharedMemory {
public:
    SharedMemory(int steps, std::size_t bodies)
        : m_steps(static_cast<std::size_t>(steps))
        , m_size(sizeof(SharedRun) + (m_steps + 3 * bodies) * sizeof(double))
    {
        m_memory = mmap(nullptr, m_size, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
        if (m_memory == MAP_FAILED)
            throw std::runtime_error("impetus-bench-compare: cannot map memory for a run");
        new (m_memory) SharedRun;
    }
    ~SharedMemory() { munmap(m_memory, m_size); }
    SharedMemory(const SharedMemory&) = delete;
    SharedMemory& operator=(const SharedMemory&) = delete;

    SharedRun& run() { return *static_cast<SharedRun*>(m_memory); }
    double* stepMs() { return reinterpret_cast<double*>(static_cast<char*>(m_memory) + sizeof(SharedRun)); }
    double* poses() { return stepMs() + m_steps; }

private:
    std::size_t m_steps;
    std::size_t m_size;
    void* m_memory = nullptr;
};

/// Builds the engine called `name` (one of engineNames()) with `scene` at `timeStep`, steps it
/// `steps` times, timing each step call alone, and writes what it did into `shared` as it goes.
/// Runs in the child process.
void runInChild(const std::string& name, const Scene& scene, Scalar timeStep, int steps,
                const controller::SolverSettings& impetusSolver, SharedMemory& shared)
{
    using Clock = std::chrono::steady_clock;
    SharedRun& out = shared.run();
    std::unique_ptr<Engine> engine;
    try {
        if (name == "impetus")
            engine = std::make_unique<ImpetusEngine>(scene.world, scene.turning, impetusSolver, timeStep);
        else if (name == "box2d3")
            engine = std::make_unique<Box2dV3Engine>(scene.world, scene.turning, timeStep, kBox2dV3Substeps);
        else if (name == "box2d")
            engine = makeBox2dEngine(scene.world, scene.turning, timeStep);
        else
            engine = makeChipmunkEngine(scene.world, scene.turning, timeStep);
    } catch (const std::invalid_argument& error) {
        std::snprintf(out.failure, sizeof out.failure, "%s", error.what());
        return;
    }
    const auto* impetus = dynamic_cast<const ImpetusEngine*>(engine.get());
    const auto* v3 = dynamic_cast<const Box2dV3Engine*>(engine.get());
    out.hasImpetusProfile = impetus != nullptr;
    out.hasV3Profile = v3 != nullptr;
    double* stepMs = shared.stepMs();
    // The overlap is looked at between the timed calls, at the same simulated times whatever the
    // engine's step, so that a short step is not looked at more often.
    const int sampleEvery = std::max(1, static_cast<int>(std::lround(kOverlapSampleTime / timeStep)));
    out.overlapMeasured = std::none_of(scene.world.bodies.begin(), scene.world.bodies.end(), [](const model::Body& body) {
        return std::holds_alternative<model::Ellipse>(body.shape);
    });
    for (int i = 0; i < steps; ++i) {
        const Clock::time_point start = Clock::now();
        engine->step();
        stepMs[i] = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        if (out.overlapMeasured && ((i + 1) % sampleEvery == 0 || i + 1 == steps))
            out.peakOverlap = std::max(out.peakOverlap, deepestOverlap(scene.world, engine->poses()).depth);
        if (impetus)
            out.impetusProfile = impetus->profileSum();
        if (v3)
            out.v3Profile = v3->profileSum();
        out.stepsDone = i + 1;
    }
    double* poses = shared.poses();
    for (const Pose& pose : engine->poses()) {
        *poses++ = pose.position.x();
        *poses++ = pose.position.y();
        *poses++ = pose.angle;
    }
    out.finished = true;
}

/// Runs the engine called `name` with `scene` at `timeStep` for the scene's simulated time, in a
/// child process: an engine that takes longer than `timeLimit` seconds of wall-clock time is
/// stopped, one that wants more than kMemoryLimit fails, and one that aborts (Chipmunk does on
/// what it cannot solve) takes only its own run down. The child is a copy of this process, so the engine sees the same scene and the timing
/// is the same as in-process; the parent sleeps in poll() meanwhile.
Run runEngine(const std::string& name, const Scene& scene, Scalar timeStep,
              const controller::SolverSettings& impetusSolver, double timeLimit)
{
    Run run;
    run.id = name;
    run.engine = displayName(name);
    run.timeStep = timeStep;
    run.plannedSteps = stepsFor(scene.seconds, timeStep);
    SharedMemory shared(run.plannedSteps, scene.world.bodies.size());

    // The child holds the pipe's write end and never writes: the read end reports a hang-up
    // when the child ends, however it ends.
    int ends[2];
    if (pipe(ends) != 0)
        throw std::runtime_error("impetus-bench-compare: cannot make a pipe");
    std::cout << std::flush;
    std::cerr << std::flush;
    const pid_t child = fork();
    if (child < 0)
        throw std::runtime_error("impetus-bench-compare: cannot start a process");
    if (child == 0) {
        close(ends[0]);
        const rlimit memory{kMemoryLimit, kMemoryLimit};
        setrlimit(RLIMIT_AS, &memory);
        try {
            runInChild(name, scene, timeStep, run.plannedSteps, impetusSolver, shared);
        } catch (const std::bad_alloc&) {
            std::snprintf(shared.run().failure, sizeof shared.run().failure, "out of memory (limit %llu GiB)",
                          static_cast<unsigned long long>(kMemoryLimit >> 30));
        } catch (const std::exception& error) {
            std::snprintf(shared.run().failure, sizeof shared.run().failure, "%s", error.what());
        }
        std::cout << std::flush;
        _exit(0);
    }
    close(ends[1]);
    using Clock = std::chrono::steady_clock;
    const Clock::time_point deadline =
        Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeLimit));
    pollfd hangUp{ends[0], POLLIN, 0};
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
        if (left <= 0) {
            kill(child, SIGKILL);
            run.stopped = true;
            break;
        }
        // Interrupted by a signal (-1) or not yet over (0): wait again for what is left.
        const int ready = poll(&hangUp, 1, static_cast<int>(std::min<long long>(left, std::numeric_limits<int>::max())));
        if (ready > 0)
            break;
    }
    close(ends[0]);
    int status = 0;
    waitpid(child, &status, 0);

    const SharedRun& result = shared.run();
    // A child that finished just as the time ran out was not stopped.
    run.stopped = run.stopped && !result.finished;
    run.stepMs.assign(shared.stepMs(), shared.stepMs() + result.stepsDone);
    if (result.overlapMeasured && result.stepsDone > 0)
        run.peakOverlap = result.peakOverlap;
    if (result.hasImpetusProfile && result.stepsDone > 0)
        run.impetusProfile = result.impetusProfile;
    if (result.hasV3Profile && result.stepsDone > 0)
        run.v3Profile = result.v3Profile;
    if (result.failure[0] != '\0') {
        run.failure = result.failure;
    } else if (result.finished) {
        const double* poses = shared.poses();
        for (std::size_t i = 0; i < scene.world.bodies.size(); ++i, poses += 3)
            run.poses.push_back(Pose{Vec2(poses[0], poses[1]), poses[2]});
    } else if (!run.stopped) {
        run.failure = WIFSIGNALED(status) ? "crashed (" + std::string(strsignal(WTERMSIG(status))) + ")"
                                          : "ended without finishing";
    }
    return run;
}

double mean(const std::vector<double>& values)
{
    double sum = 0;
    for (const double v : values)
        sum += v;
    return values.empty() ? 0 : sum / static_cast<double>(values.size());
}

double median(std::vector<double> values)
{
    if (values.empty())
        return 0;
    const std::size_t middle = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(middle), values.end());
    if (values.size() % 2 == 1)
        return values[middle];
    const double upper = values[middle];
    const double lower = *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(middle));
    return (lower + upper) / 2;
}

std::string fixed(double value, int decimals)
{
    if (!std::isfinite(value))
        return "nan";
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

/// `value` with `digits` significant digits: ratios span orders of magnitude.
std::string significant(double value, int digits)
{
    if (!std::isfinite(value))
        return "nan";
    char text[64];
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    return text;
}

/// "1/240 s" when the step is the reciprocal of a whole number of hertz, else seconds.
std::string describeTimeStep(Scalar h)
{
    const Scalar hertz = 1 / h;
    if (std::abs(hertz - std::round(hertz)) < 1e-9 * hertz)
        return "1/" + fixed(std::round(hertz), 0) + " s";
    return fixed(h, 6) + " s";
}

/// Sideways drift (|Δx|) and drop (−Δy) of the pyramids' top boxes: the largest over all pyramids.
struct TopBoxMotion {
    Scalar drift = 0; ///< m
    Scalar drop = 0; ///< m
};

TopBoxMotion topBoxMotion(const Scene& scene, const std::vector<Pose>& poses)
{
    TopBoxMotion motion;
    for (const std::size_t i : scene.topBoxes) {
        const Vec2 start = scene.world.bodies[i].state.position;
        motion.drift = std::max(motion.drift, std::abs(poses[i].position.x() - start.x()));
        motion.drop = std::max(motion.drop, start.y() - poses[i].position.y());
    }
    return motion;
}

std::size_t countNonFinite(const std::vector<Pose>& poses)
{
    return static_cast<std::size_t>(std::count_if(poses.begin(), poses.end(), [](const Pose& pose) {
        return !isFinite(pose.position) || !std::isfinite(pose.angle);
    }));
}

/// The step `engine` (one of engineNames()) recommends, s: Impetus its world's step (the scene
/// builders give every world Impetus's default step), the peers 1/60 s.
Scalar recommendedStep(const std::string& engine, const Scene& scene)
{
    return engine == "impetus" ? scene.world.settings.timeStep : kPeerRecommendedStep;
}

/// "1/60 s x 4 substeps" for v3, Impetus's own substeps when it took more than one a step.
std::string describeSettings(const Run& run)
{
    std::string text = describeTimeStep(run.timeStep);
    if (run.id == "box2d3")
        text += " x " + std::to_string(kBox2dV3Substeps) + " substeps";
    if (run.impetusProfile && !run.stepMs.empty()) {
        const double substeps = run.impetusProfile->substeps / static_cast<double>(run.stepMs.size());
        if (substeps > 1)
            text += " (" + significant(substeps, 3) + " substeps)";
    }
    return text;
}

/// Whether a run has times to show: it ran at least one step.
bool timed(const Run& run) { return run.failure.empty() && !run.stepMs.empty(); }

/// ms of wall-clock time per second of simulated time: the mean step over the step.
double msPerSimulatedSecond(const Run& run) { return mean(run.stepMs) / run.timeStep; }

/// One table: a row per run, with each engine's time per simulated second against Impetus's and
/// v3's in the same table. A run stopped at the time limit shows its times over the steps it did
/// and no quality (its bodies never got to the end).
void printTable(const Scene& scene, const std::vector<const Run*>& rows)
{
    const bool pyramids = !scene.topBoxes.empty();
    const bool joints = !scene.world.joints.empty();
    double impetusCost = 0;
    double v3Cost = 0;
    for (const Run* r : rows) {
        if (!timed(*r))
            continue;
        if (r->id == "impetus")
            impetusCost = msPerSimulatedSecond(*r);
        if (r->id == "box2d3")
            v3Cost = msPerSimulatedSecond(*r);
    }
    std::cout << "| engine    | step | steps | ms/step mean | ms/step median | slowest ÷ median | ms per simulated s | x Impetus | x v3 |"
              << (pyramids ? " top drift (m) | top drop (m) |" : "") << " deepest overlap, end (m) | deepest overlap, run (m) |"
              << (joints ? " worst joint gap (m) |" : "") << "\n"
              << "|-----------|------|------:|-------------:|---------------:|-----------------:|-------------------:|----------:|-----:|"
              << (pyramids ? "--------------:|-------------:|" : "") << "-------------------------:|-------------------------:|"
              << (joints ? "--------------------:|" : "") << "\n";
    const std::string noValue = "-";
    for (const Run* r : rows) {
        std::string engineCell = r->engine;
        engineCell.resize(9, ' ');
        if (!r->failure.empty()) {
            std::cout << "| " << engineCell << " | " << describeTimeStep(r->timeStep) << " | not run: " << r->failure
                      << " (after " << r->stepMs.size() << " of " << r->plannedSteps << " steps) |\n";
            continue;
        }
        std::string stepsCell = std::to_string(r->stepMs.size());
        if (r->stopped)
            stepsCell += " of " + std::to_string(r->plannedSteps) + ", stopped at the time limit";
        std::cout << "| " << engineCell << " | " << describeSettings(*r) << " | " << stepsCell << " | ";
        if (!timed(*r)) {
            std::cout << noValue << " | " << noValue << " | " << noValue << " | " << noValue << " | " << noValue
                      << " | " << noValue << " |";
        } else {
            const double cost = msPerSimulatedSecond(*r);
            const double middle = median(r->stepMs);
            const double slowest = *std::max_element(r->stepMs.begin(), r->stepMs.end());
            std::cout << fixed(mean(r->stepMs), 3) << " | " << fixed(middle, 3) << " | "
                      << (middle > 0 ? fixed(slowest / middle, 1) : noValue) << " | " << fixed(cost, 1)
                      << " | " << (impetusCost > 0 ? significant(cost / impetusCost, 3) : noValue) << " | "
                      << (v3Cost > 0 ? significant(cost / v3Cost, 3) : noValue) << " |";
        }
        const bool finished = !r->poses.empty();
        if (pyramids) {
            const TopBoxMotion motion = finished ? topBoxMotion(scene, r->poses) : TopBoxMotion{};
            std::cout << ' ' << (finished ? fixed(motion.drift, 4) : noValue) << " | "
                      << (finished ? fixed(motion.drop, 4) : noValue) << " |";
        }
        std::cout << ' ' << (finished ? fixed(deepestOverlap(scene.world, r->poses).depth, 4) : noValue) << " | "
                  << (finished && r->peakOverlap ? fixed(*r->peakOverlap, 4) : noValue) << " |";
        if (joints)
            std::cout << ' ' << (finished ? fixed(worstJointError(scene.world, r->poses), 4) : noValue) << " |";
        std::cout << "\n";
    }
    for (const Run* r : rows) {
        if (const std::size_t lost = countNonFinite(r->poses))
            std::cout << "\n" << r->engine << ": " << lost << " bodies ended with a non-finite pose.\n";
    }
}

/// Impetus's own time per phase (controller::Simulation::profile()), averaged over the steps.
void printImpetusPhases(const Run& run)
{
    // A new StepProfile field needs a line here and one in ImpetusEngine::step.
    const controller::StepProfile& p = *run.impetusProfile;
    const double n = static_cast<double>(run.stepMs.size());
    std::cout << "Impetus phases at " << describeTimeStep(run.timeStep) << ", mean ms/step: broad "
              << fixed(p.broadMs / n, 3) << ", narrow " << fixed(p.narrowMs / n, 3) << ", integrate "
              << fixed(p.integrateMs / n, 3) << ", solve " << fixed(p.solveMs / n, 3) << " (prepare "
              << fixed(p.prepareMs / n, 3) << ", impacts " << fixed(p.impactsMs / n, 3) << ", velocities "
              << fixed(p.velocityMs / n, 3) << ", positions " << fixed(p.positionMs / n, 3) << "), events "
              << fixed(p.eventsMs / n, 3) << "; total " << fixed(p.totalMs / n, 3) << " ("
              << fixed(p.totalMs / n / run.timeStep, 1) << " per simulated s); " << fixed(p.substeps / n, 2)
              << " substeps, " << fixed(p.collisionPasses / n, 2) << " collision passes, " << fixed(p.contacts / n, 0) << " contacts ("
              << fixed(p.batchLanes / n, 0) << " batch lanes), " << fixed(p.impacts / n, 1)
              << " impacts per step\n";
}

/// v3's own time per phase (b2Profile), averaged over the steps.
void printV3Phases(const Run& run)
{
    const Box2dV3Profile& p = *run.v3Profile;
    const double n = static_cast<double>(run.stepMs.size());
    std::cout << "Box2D v3 phases at " << describeSettings(run) << ", mean ms/step (b2Profile): pairs "
              << fixed(p.pairs / n, 3) << ", collide " << fixed(p.collide / n, 3) << ", solve "
              << fixed(p.solve / n, 3) << " (setup " << fixed(p.solverSetup / n, 3) << ", constraints "
              << fixed(p.constraints / n, 3) << " [prepare " << fixed(p.prepareConstraints / n, 3)
              << ", integrate velocities " << fixed(p.integrateVelocities / n, 3) << ", warm start "
              << fixed(p.warmStart / n, 3) << ", solve " << fixed(p.solveImpulses / n, 3) << ", integrate positions "
              << fixed(p.integratePositions / n, 3) << ", relax " << fixed(p.relaxImpulses / n, 3) << ", restitution "
              << fixed(p.applyRestitution / n, 3) << ", store " << fixed(p.storeImpulses / n, 3) << "], transforms "
              << fixed(p.transforms / n, 3) << ", refit " << fixed(p.refit / n, 3) << ", continuous "
              << fixed(p.bullets / n, 3) << "); step " << fixed(p.step / n, 3) << " ("
              << fixed(p.step / n / run.timeStep, 1) << " per simulated s)\n";
}

void runScene(const Scene& scene, const Options& options, const controller::SolverSettings& impetusSolver,
              double timeLimit)
{
    const model::World& world = scene.world;
    const auto dynamic =
        std::count_if(world.bodies.begin(), world.bodies.end(), [](const model::Body& b) { return !b.fixed; });
    std::cout << "\n## " << scene.name << "\n\n"
              << scene.description << ": " << world.bodies.size() << " bodies (" << dynamic << " dynamic), "
              << fixed(scene.seconds, 2) << " s simulated.\n"
              << std::flush;

    // The tables to print, each a list of (engine, step); a run shared by both tables (a peer
    // whose recommended step is the common step) is run once.
    const Scalar commonStep = options.commonStep.value_or(kDefaultCommonStep);
    using Table = std::pair<std::string, std::vector<std::pair<std::string, Scalar>>>;
    std::vector<Table> tables;
    if (!options.commonStep) {
        Table& recommended = tables.emplace_back("Each engine at its recommended settings", Table::second_type{});
        for (const std::string& engine : options.engines)
            recommended.second.emplace_back(engine, recommendedStep(engine, scene));
    }
    Table& common = tables.emplace_back("Every engine at one step of " + describeTimeStep(commonStep), Table::second_type{});
    for (const std::string& engine : options.engines)
        common.second.emplace_back(engine, commonStep);

    std::map<std::pair<std::string, Scalar>, Run> runs;
    std::vector<const Run*> ranInOrder;
    for (const auto& table : tables) {
        for (const auto& key : table.second) {
            if (runs.count(key) != 0)
                continue;
            const Run& run = runs.emplace(key, runEngine(key.first, scene, key.second, impetusSolver, timeLimit)).first->second;
            ranInOrder.push_back(&run);
        }
    }

    for (const auto& table : tables) {
        std::cout << "\n" << table.first << ":\n\n";
        std::vector<const Run*> rows;
        for (const auto& key : table.second)
            rows.push_back(&runs.at(key));
        printTable(scene, rows);
    }

    std::cout << "\n";
    for (const Run* run : ranInOrder) {
        if (timed(*run) && run->impetusProfile)
            printImpetusPhases(*run);
    }
    for (const Run* run : ranInOrder) {
        if (timed(*run) && run->v3Profile)
            printV3Phases(*run);
    }
    std::cout << std::flush;
}

} // namespace

int main(int argc, char** argv)
{
    const std::optional<Options> options = parseArguments(argc, argv);
    if (!options)
        return 2;

    announceChipmunk();
    controller::SolverSettings impetusSolver;
    impetusSolver.secondThread = !options->oneThread;
    if (options->noBatches)
        impetusSolver.batchMinConstraints = std::numeric_limits<std::size_t>::max();
    const Scalar impetusStep = model::SceneOptions{}.timeStep;
    std::cout << "# Impetus vs Box2D " << box2dVersion() << " vs Chipmunk " << chipmunkVersion() << " vs Box2D v3 "
              << box2dV3Version() << "\n\n"
              << "The engines run one after the other; " << std::thread::hardware_concurrency()
              << " hardware threads. Box2D 2.4, Chipmunk and Box2D v3 (workerCount 1) use one thread; Impetus uses "
              << (impetusSolver.secondThread ? "two for large worlds (docs/physics.md, \"Two threads\")"
                                             : "one (--one-thread)")
              << ". Sleeping is off in every engine.\n"
              << "Impetus: recommended step " << describeTimeStep(impetusStep)
              << " (the scenes' world step, Impetus's default), " << impetusSolver.velocityIterations << " velocity / "
              << impetusSolver.positionIterations << " position iterations (controller::Simulation defaults), double; "
              << (options->noBatches ? std::string("one contact at a time (--no-batches)")
                                     : "worlds of " + std::to_string(impetusSolver.batchMinConstraints) +
                                           " contacts or more in batches of four" +
                                           (controller::fastestBatchOrder() == controller::BatchOrder::InPairs
                                                ? ", two at a time"
                                                : "") +
                                           " (" + controller::batchInstructions() + " on this processor)")
              << ".\n"
              << "Box2D 2.4: recommended step " << describeTimeStep(kPeerRecommendedStep) << ", "
              << kBox2dVelocityIterations << " velocity / " << kBox2dPositionIterations
              << " position iterations, float.\n"
              << "Chipmunk: recommended step " << describeTimeStep(kPeerRecommendedStep) << ", " << kChipmunkIterations
              << " iterations, collision slop " << kChipmunkCollisionSlop << " m, double.\n"
              << "Box2D v3: recommended step " << describeTimeStep(kPeerRecommendedStep) << " in " << kBox2dV3Substeps
              << " substeps, float, " << box2dV3Instructions() << ", continuous collision on (its defaults).\n";
    const double timeLimit = options->timeLimit.value_or(options->quick ? kQuickTimeLimit : kDefaultTimeLimit);
    std::cout << "Each engine runs each scene in a process of its own, stopped after " << timeLimit
              << " s of wall-clock time (--time-limit).\n";
    if (options->quick)
        std::cout << "\n--quick: small scenes and a short run; the times below are not a measurement.\n";

    for (const SceneRecipe& recipe : recipes()) {
        if (!options->scene.empty() && recipe.name != options->scene)
            continue;
        Scene scene = recipe.build(options->quick);
        scene.seconds = options->seconds.value_or((options->quick ? kQuickFrames : recipe.frames) * kFrame);
        runScene(scene, *options, impetusSolver, timeLimit);
    }
    return 0;
}
