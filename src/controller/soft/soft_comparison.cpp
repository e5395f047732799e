#include "controller/soft/soft_comparison.h"

#include "controller/simulation.h"
#include "controller/soft/soft_body_builder.h"

#include <algorithm>
#include <cmath>

namespace impetus::controller {

RigidSoftComparison compareRigidSoft(const model::World& world, model::BodyId body, std::int64_t steps,
                                     std::int64_t sampleEvery, std::optional<model::SoftSettings> softSettings)
{
    model::World rigid = world;
    rigid.softBodies.clear();
    rigid.body(body).soft.reset();
    model::World soft = world;
    soft.softBodies.clear();
    model::Body& softBody = soft.body(body);
    if (softSettings)
        softBody.soft = *softSettings;
    else if (!softBody.soft)
        softBody.soft = model::SoftSettings{};
    // The soft run starts from the scene's state, not from a grid left over from running.
    rigid.body(body).state = world.body(body).state;
    softBody.state = world.body(body).state;

    prepareSoftBodies(soft);

    Simulation rigidSimulation;
    Simulation softSimulation;
    RigidSoftComparison result;
    Scalar sumSquares = 0;
    const auto sample = [&]() {
        RigidSoftSample s;
        s.time = soft.time;
        s.rigid = rigid.body(body).state.position;
        s.soft = soft.body(body).state.position;
        s.distance = (s.soft - s.rigid).norm();
        sumSquares += s.distance * s.distance;
        if (s.distance > result.maxDistance) {
            result.maxDistance = s.distance;
            result.maxDistanceTime = s.time;
        }
        result.samples.push_back(s);
    };
    sample();
    const std::int64_t every = std::max<std::int64_t>(1, sampleEvery);
    for (std::int64_t step = 1; step <= steps; ++step) {
        rigidSimulation.step(rigid);
        softSimulation.step(soft);
        if (step % every == 0)
            sample();
    }
    result.rmsDistance = std::sqrt(sumSquares / static_cast<Scalar>(result.samples.size()));
    if (const model::SoftGrid* grid = soft.softGrid(body)) {
        result.ellipsesPerSquareMeter = grid->ellipsesPerSquareMeter;
        result.ellipses = grid->size();
    }
    return result;
}

} // namespace impetus::controller
