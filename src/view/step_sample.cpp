#include "view/step_sample.h"

namespace impetus::view {

StepSample takeSample(const model::World& world, const SampleRequest& request)
{
    StepSample sample;
    sample.step = world.stepCount;
    sample.time = world.time;
    if (request.centres) {
        sample.centres.reserve(world.bodies.size());
        sample.angles.reserve(world.bodies.size());
        for (const model::Body& body : world.bodies) {
            sample.centres.push_back(body.state.position);
            sample.angles.push_back(body.state.angle);
        }
    }
    sample.bodies.reserve(request.bodies.size());
    for (const std::uint32_t index : request.bodies) {
        if (index < world.bodies.size())
            sample.bodies.push_back({index, controller::readBody(world, model::BodyId{index})});
    }
    if (request.totals) {
        sample.totals.energy = controller::computeEnergy(world);
        sample.totals.momentum = controller::linearMomentum(world);
        sample.totals.angularMomentum = controller::angularMomentum(world);
        sample.totals.collisions = world.collisionCount;
    }
    return sample;
}

} // namespace impetus::view
