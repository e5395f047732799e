#include "controller/soft/soft_density.h"

#include "controller/simulation.h"
#include "model/constants.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace impetus::controller {

double measureSoftFrameCost(const model::World& world, Scalar ellipsesPerSquareMeter)
{
    model::World trial = world;
    trial.softBodies.clear();
    for (model::Body& body : trial.bodies) {
        if (body.soft && body.soft->autoDensity) {
            body.soft->autoDensity = false;
            body.soft->ellipsesPerSquareMeter = ellipsesPerSquareMeter;
        }
    }
    Simulation simulation;
    const auto stepsPerFrame =
        std::max(1, static_cast<int>(std::ceil(constants::kSoftFrameTime / trial.settings.timeStep)));
    double fastest = INFINITY;
    for (int frame = 0; frame < constants::kSoftAutoTrialFrames; ++frame) {
        const auto start = std::chrono::steady_clock::now();
        for (int i = 0; i < stepsPerFrame; ++i)
            simulation.step(trial);
        fastest = std::min(fastest, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    return fastest;
}

Scalar chooseAutoDensity(const model::World& world)
{
    const double budgetMs = 1000.0 * constants::kSoftFrameTime * constants::kSoftFrameBudgetFraction;
    Scalar chosen = constants::kSoftAutoDensities[0];
    for (const Scalar density : constants::kSoftAutoDensities) {
        if (measureSoftFrameCost(world, density) >= budgetMs)
            break;
        chosen = density;
    }
    return chosen;
}

} // namespace impetus::controller
