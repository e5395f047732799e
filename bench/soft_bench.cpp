// Soft mode's speed goal (issue 5): 10 soft bodies of 1 m², at 256 ellipses per m², falling into a
// box. Prints the wall time of each 1/60 s frame of simulated time, averaged over the fall, the
// landing and the settled pile, against the goal of 8 ms per frame.
// Run: build/bench/bench/impetus-bench-soft [--density N] [--integrator NAME] [--seconds S] [--one-thread] [--no-batches]

#include "controller/simulation.h"
#include "controller/soft/soft_body_builder.h"
#include "model/world.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace {

using namespace impetus;

/// A fixed box (a wall or the floor) of the container.
model::Body wall(std::string name, Scalar width, Scalar height, Vec2 centre)
{
    model::Body body;
    body.name = std::move(name);
    body.shape = model::Box{width, height};
    body.fixed = true;
    body.state.position = centre;
    body.updateDerived();
    return body;
}

/// An open box 4 m wide and 6 m high, and ten 1 m × 1 m soft boxes above it in two staggered
/// columns, each at `density` ellipses per m².
model::World fallingSoftBoxes(Scalar density, model::IntegratorKind integrator)
{
    model::World world;
    world.settings.integrator = integrator;
    world.bodies.push_back(wall("floor", 5, 0.5, Vec2(0, -0.25)));
    world.bodies.push_back(wall("left", 0.5, 7, Vec2(-2.25, 3.5)));
    world.bodies.push_back(wall("right", 0.5, 7, Vec2(2.25, 3.5)));
    for (int i = 0; i < 10; ++i) {
        model::Body body;
        body.name = "soft" + std::to_string(i);
        body.shape = model::Box{1, 1};
        body.state.position = Vec2(i % 2 == 0 ? -0.7 : 0.6, 1.0 + 1.2 * i);
        body.state.angle = 0.1 * (i % 3);
        body.soft = model::SoftSettings{};
        body.soft->ellipsesPerSquareMeter = density;
        body.updateDerived();
        world.bodies.push_back(body);
    }
    return world;
}

} // namespace

int main(int argc, char** argv)
{
    Scalar density = 256;
    model::IntegratorKind integrator = model::IntegratorKind::Rk4;
    double seconds = 6;
    controller::SolverSettings settings;
    const auto usage = [&] {
        std::fprintf(stderr, "usage: %s [--density N] [--integrator NAME] [--seconds S] [--one-thread] [--no-batches]\n", argv[0]);
        return 2;
    };
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if (flag == "--one-thread") {
            settings.secondThread = false;
            continue;
        }
        if (flag == "--no-batches") {
            settings.batchMinConstraints = std::numeric_limits<std::size_t>::max();
            continue;
        }
        // Every other flag takes a value.
        if (i + 1 >= argc)
            return usage();
        const char* value = argv[++i];
        if (flag == "--density") {
            density = std::atof(value);
        } else if (flag == "--seconds") {
            seconds = std::atof(value);
        } else if (flag == "--integrator") {
            const std::optional<model::IntegratorKind> kind = model::integratorFromName(value);
            if (!kind) {
                std::fprintf(stderr, "unknown integrator %s\n", value);
                return 2;
            }
            integrator = *kind;
        } else {
            return usage();
        }
    }

    model::World world = fallingSoftBoxes(density, integrator);
    controller::prepareSoftBodies(world);
    std::size_t ellipses = 0;
    for (const model::SoftGrid& grid : world.softBodies)
        ellipses += grid.size();
    controller::Simulation simulation(settings);
    const int stepsPerFrame = static_cast<int>(std::lround(1.0 / 60.0 / world.settings.timeStep));
    const int frames = static_cast<int>(std::lround(seconds * 60));
    std::vector<double> frameMs;
    for (int frame = 0; frame < frames; ++frame) {
        const auto start = std::chrono::steady_clock::now();
        for (int i = 0; i < stepsPerFrame; ++i)
            simulation.step(world);
        frameMs.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }

    double sum = 0;
    for (const double ms : frameMs)
        sum += ms;
    std::vector<double> sorted = frameMs;
    std::sort(sorted.begin(), sorted.end());
    std::printf("10 soft boxes of 1 m² at %g ellipses/m² (%zu ellipses), %s, h = %.4g s, %d substeps\n", density,
                ellipses, std::string(model::integratorName(integrator)).c_str(), world.settings.timeStep,
                simulation.stability().substeps);
    std::printf("%d frames of 1/60 s: mean %.2f ms per frame, median %.2f, slowest %.2f (goal < 8 ms)\n", frames,
                sum / frames, sorted[sorted.size() / 2], sorted.back());
    const controller::StepProfile& p = simulation.profile();
    std::printf("last step: broad %.3f ms, narrow %.3f, integrate %.3f, solve %.3f, total %.3f; %d contacts\n",
                p.broadMs, p.narrowMs, p.integrateMs, p.solveMs, p.totalMs, p.contacts);
    Scalar lowest = INFINITY;
    for (const model::SoftGrid& grid : world.softBodies)
        lowest = std::min(lowest, world.bodies[grid.body.index].state.position.y());
    std::printf("lowest soft body's centre at y = %.3f m after %.1f s\n", lowest, world.time);
    return 0;
}
