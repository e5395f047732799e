// Steps the same scenes in Impetus, Box2D and Chipmunk, one engine after the other in this one
// process, and prints per scene the time per step and two measures of quality of the result.
// Run: build/bench/bench/impetus-bench-compare [--steps N] [--scene NAME] [--quick]
// docs/benchmarks.md explains the scenes, what keeps the comparison fair, and every column.

#include "peer_engines.h"
#include "pose_quality.h"

#include "controller/dynamics/contact_batches.h"
#include "controller/simulation.h"
#include "model/example_scenes.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace impetus;
using namespace impetus::bench;

/// Steps per scene unless --steps says otherwise, and under --quick.
constexpr int kDefaultSteps = 500;
constexpr int kQuickSteps = 20;

/// The seed of the polygon rain: any fixed value, so every run rains the same polygons.
constexpr unsigned kRainSeed = 1;

/// One benchmark scene: the world every engine starts from, what turns, and which bodies are the
/// tops of pyramids (whose drift is the classic measure of a stacking solver's quality).
struct Scene {
    std::string name;
    std::string description;
    model::World world;
    Turning turning;
    std::vector<std::size_t> topBoxes;
};

struct SceneRecipe {
    std::string name;
    std::function<Scene(bool quick)> build;
};

Scene pyramidScene(bool quick)
{
    const int base = quick ? 20 : 100;
    Scene scene{"pyramid", "", model::makePyramid(base), {}, {}};
    scene.description = "Box2D's pyramid: base " + std::to_string(base) + ", " +
                        std::to_string(base * (base + 1) / 2) + " boxes of 1 m on a fixed ground";
    scene.topBoxes = {scene.world.bodies.size() - 1}; // makePyramid's order: the top box is last
    return scene;
}

Scene pyramidGridScene(bool quick)
{
    const int count = quick ? 3 : 20;
    const int base = 10;
    Scene scene{"pyramid-grid", "", model::makePyramidGrid(count, count, base), {}, {}};
    const std::size_t perPyramid = base * (base + 1) / 2;
    scene.description = std::to_string(count) + " x " + std::to_string(count) + " pyramids of base " +
                        std::to_string(base) + " (" + std::to_string(count * count * static_cast<int>(perPyramid)) +
                        " boxes) on " + std::to_string(count) + " grounds";
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
                 {}};
}

Scene rotatingBoxScene(bool quick)
{
    const int count = quick ? 300 : 2000;
    std::ostringstream description;
    description << count << " circles of radius 0.25 m in a closed box turning at "
                << model::kRotatingContainerAngularVelocity << " rad/s";
    return Scene{"rotating-box", description.str(), model::makeRotatingBoxWithCircles(count),
                 Turning{Vec2::Zero(), model::kRotatingContainerAngularVelocity}, {}};
}

const std::vector<SceneRecipe>& recipes()
{
    static const std::vector<SceneRecipe> all = {{"pyramid", pyramidScene},
                                                 {"pyramid-grid", pyramidGridScene},
                                                 {"polygon-rain", polygonRainScene},
                                                 {"rotating-box", rotatingBoxScene}};
    return all;
}

/// The engines in the order they run; --engines picks some of them.
const std::vector<std::string>& engineNames()
{
    static const std::vector<std::string> all = {"impetus", "box2d", "chipmunk"};
    return all;
}

struct Options {
    int steps = kDefaultSteps;
    bool stepsGiven = false;
    std::string scene; ///< empty: all
    std::vector<std::string> engines = engineNames();
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
    out << "usage: impetus-bench-compare [--steps N] [--scene NAME] [--engines LIST] [--one-thread] [--no-batches] [--quick]\n"
           "  --steps N       steps per scene (default "
        << kDefaultSteps << ", " << kQuickSteps
        << " with --quick)\n"
           "  --scene NAME    run one scene:";
    for (const SceneRecipe& recipe : recipes())
        out << ' ' << recipe.name;
    out << "\n  --engines LIST  comma-separated, from impetus,box2d,chipmunk (default: all three)\n"
           "  --one-thread    Impetus without its second thread (the same results, one core)\n"
           "  --no-batches    Impetus's velocity passes one contact at a time, not in batches\n"
           "  --quick         small scenes and few steps: a smoke test, not a measurement\n";
}

std::optional<Options> parseArguments(int argc, char** argv)
{
    Options options;
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        const bool hasValue = i + 1 < argc;
        if (argument == "--steps" && hasValue) {
            char* end = nullptr;
            const long steps = std::strtol(argv[++i], &end, 10);
            if (*end != '\0' || steps < 1 || steps > 1000000) {
                std::cerr << "impetus-bench-compare: --steps takes a whole number from 1 to 1000000\n";
                return std::nullopt;
            }
            options.steps = static_cast<int>(steps);
            options.stepsGiven = true;
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
                             "chipmunk\n";
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
    if (options.quick && !options.stepsGiven)
        options.steps = kQuickSteps;
    return options;
}

/// What one engine did with one scene.
struct Run {
    std::string engine;
    std::vector<double> stepMs; ///< wall-clock time of each step, ms
    std::vector<Pose> poses; ///< at the end
    controller::StepProfile profileSum; ///< Impetus only
};

Run run(Engine& engine, int steps)
{
    using Clock = std::chrono::steady_clock;
    Run result;
    result.engine = engine.name();
    result.stepMs.reserve(static_cast<std::size_t>(steps));
    for (int i = 0; i < steps; ++i) {
        const Clock::time_point start = Clock::now();
        engine.step();
        result.stepMs.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    }
    result.poses = engine.poses();
    return result;
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

/// The engine called `name` (one of engineNames()) holding `scene`.
std::unique_ptr<Engine> makeEngine(const std::string& name, const Scene& scene,
                                   const controller::SolverSettings& impetusSolver)
{
    if (name == "impetus")
        return std::make_unique<ImpetusEngine>(scene.world, scene.turning, impetusSolver);
    if (name == "box2d")
        return makeBox2dEngine(scene.world, scene.turning);
    return makeChipmunkEngine(scene.world, scene.turning);
}

void runScene(const Scene& scene, int steps, const std::vector<std::string>& engines,
              const controller::SolverSettings& impetusSolver)
{
    const model::World& world = scene.world;
    const auto dynamic =
        std::count_if(world.bodies.begin(), world.bodies.end(), [](const model::Body& b) { return !b.fixed; });
    std::cout << "\n## " << scene.name << "\n\n"
              << scene.description << ": " << world.bodies.size() << " bodies (" << dynamic << " dynamic), "
              << steps << " steps of " << describeTimeStep(world.settings.timeStep) << " ("
              << fixed(steps * world.settings.timeStep, 2) << " s simulated).\n\n"
              << std::flush;

    // Each engine is built just before it runs and freed after, so that only one copy of a big
    // scene is alive at a time.
    std::vector<Run> runs;
    for (const std::string& name : engines) {
        const std::unique_ptr<Engine> engine = makeEngine(name, scene, impetusSolver);
        runs.push_back(run(*engine, steps));
        if (const auto* impetus = dynamic_cast<const ImpetusEngine*>(engine.get()))
            runs.back().profileSum = impetus->profileSum();
    }

    const bool withImpetus = engines.front() == "impetus";
    const double impetusMean = withImpetus ? mean(runs.front().stepMs) : 0;
    const bool pyramids = !scene.topBoxes.empty();
    std::cout << "| engine   | ms/step mean | ms/step median | time / Impetus |"
              << (pyramids ? " top drift (m) | top drop (m) |" : "") << " deepest overlap (m) |\n"
              << "|----------|-------------:|---------------:|---------------:|"
              << (pyramids ? "--------------:|-------------:|" : "") << "--------------------:|\n";
    for (const Run& r : runs) {
        const double m = mean(r.stepMs);
        const Overlap overlap = deepestOverlap(world, r.poses);
        std::string engineCell = r.engine;
        engineCell.resize(8, ' ');
        std::cout << "| " << engineCell << " | " << fixed(m, 3) << " | " << fixed(median(r.stepMs), 3) << " | "
                  << (impetusMean > 0 ? significant(m / impetusMean, 3) : std::string("-")) << " |";
        if (pyramids) {
            const TopBoxMotion motion = topBoxMotion(scene, r.poses);
            std::cout << ' ' << fixed(motion.drift, 4) << " | " << fixed(motion.drop, 4) << " |";
        }
        std::cout << ' ' << fixed(overlap.depth, 4) << " |\n";
    }
    for (const Run& r : runs) {
        if (const std::size_t lost = countNonFinite(r.poses))
            std::cout << "\n" << r.engine << ": " << lost << " bodies ended with a non-finite pose.\n";
    }

    if (!withImpetus)
        return;
    // Where Impetus's time goes, from controller::Simulation::profile(). A new StepProfile field
    // needs a line here and one in ImpetusEngine::step.
    const controller::StepProfile& p = runs.front().profileSum;
    const double n = steps;
    std::cout << "\nImpetus phases, mean ms/step: broad " << fixed(p.broadMs / n, 3) << ", narrow "
              << fixed(p.narrowMs / n, 3) << ", integrate " << fixed(p.integrateMs / n, 3) << ", solve "
              << fixed(p.solveMs / n, 3) << " (prepare " << fixed(p.prepareMs / n, 3) << ", impacts "
              << fixed(p.impactsMs / n, 3) << ", velocities " << fixed(p.velocityMs / n, 3) << ", positions "
              << fixed(p.positionMs / n, 3) << "), events " << fixed(p.eventsMs / n, 3) << "; total "
              << fixed(p.totalMs / n, 3) << "\n"
              << std::flush;
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
    std::cout << "# Impetus vs Box2D " << box2dVersion() << " vs Chipmunk " << chipmunkVersion() << "\n\n"
              << "The engines run one after the other; " << std::thread::hardware_concurrency()
              << " hardware threads. Box2D 2.4 and Chipmunk use one thread; Impetus uses "
              << (impetusSolver.secondThread ? "two for large worlds (docs/physics.md, \"Two threads\")" : "one (--one-thread)")
              << ". Sleeping is off in every engine.\n"
              << "Impetus: " << impetusSolver.velocityIterations << " velocity / " << impetusSolver.positionIterations
              << " position iterations (controller::Simulation defaults), double; "
              << (options->noBatches ? std::string("one contact at a time (--no-batches)")
                                     : "worlds of " + std::to_string(impetusSolver.batchMinConstraints) +
                                           " contacts or more in batches of four" +
                                           (controller::fastestBatchOrder() == controller::BatchOrder::InPairs
                                                ? ", two at a time"
                                                : "") +
                                           " (" + controller::batchInstructions() + " on this processor)")
              << ".\n"
              << "Box2D: " << kBox2dVelocityIterations << " velocity / " << kBox2dPositionIterations
              << " position iterations, float.\n"
              << "Chipmunk: " << kChipmunkIterations << " iterations, collision slop " << kChipmunkCollisionSlop
              << " m, double.\n";
    if (options->quick)
        std::cout << "\n--quick: small scenes and few steps; the times below are not a measurement.\n";

    for (const SceneRecipe& recipe : recipes()) {
        if (!options->scene.empty() && recipe.name != options->scene)
            continue;
        runScene(recipe.build(options->quick), options->steps, options->engines, impetusSolver);
    }
    return 0;
}
