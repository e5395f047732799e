#include "controller/soft/soft_spin.h"

#include "model/scalar.h"

namespace impetus::controller {

namespace {

/// Centre of mass and mean velocity of one grid's ellipses (all of one mass) in a state list.
std::pair<Vec2, Vec2> gridMeans(std::span<const model::BodyState> ellipses)
{
    Vec2 position = Vec2::Zero();
    Vec2 velocity = Vec2::Zero();
    for (const model::BodyState& s : ellipses) {
        position += s.position;
        velocity += s.velocity;
    }
    const auto n = static_cast<Scalar>(ellipses.size());
    return {position / n, velocity / n};
}

/// Calls work(g, first) for every grid g with at least two ellipses, `first` the index of its
/// first ellipse in the state list.
template <typename Work>
void forEachGrid(const model::World& world, Work&& work)
{
    std::size_t first = world.bodies.size();
    for (std::size_t g = 0; g < world.softBodies.size(); ++g) {
        const std::size_t count = world.softBodies[g].size();
        if (count > 1 && !world.bodies[world.softBodies[g].body.index].fixed)
            work(g, first, count);
        first += count;
    }
}

} // namespace

void addGridTorques(const model::World& world, std::span<const model::BodyState> states,
                    std::span<const BodyDerivative> rates, Scalar weight, std::span<Scalar> torques)
{
    forEachGrid(world, [&](std::size_t g, std::size_t first, std::size_t count) {
        const Vec2 centre = gridMeans(states.subspan(first, count)).first;
        Scalar torque = 0;
        for (std::size_t i = first; i < first + count; ++i)
            torque += cross(states[i].position - centre, rates[i].acceleration);
        torques[g] += weight * world.softBodies[g].ellipseMass * torque;
    });
}

void keepGridAngularMomentum(const model::World& world, std::span<const model::BodyState> start,
                             std::vector<model::BodyState>& end, Scalar h, std::span<const Scalar> torques)
{
    forEachGrid(world, [&](std::size_t g, std::size_t first, std::size_t count) {
        const auto spin = [&](std::span<const model::BodyState> ellipses, Scalar& inertia) {
            const auto [centre, velocity] = gridMeans(ellipses);
            Scalar momentum = 0;
            inertia = 0;
            for (const model::BodyState& s : ellipses) {
                momentum += cross(s.position - centre, s.velocity - velocity);
                inertia += (s.position - centre).squaredNorm();
            }
            return momentum;
        };
        const Scalar m = world.softBodies[g].ellipseMass;
        Scalar inertia = 0;
        const Scalar before = spin(start.subspan(first, count), inertia);
        const std::span<model::BodyState> ellipses(end.data() + first, count);
        const Scalar after = spin(ellipses, inertia);
        if (!(inertia > 0))
            return;
        // Per unit of the ellipses' common mass: the turn δω that gives the grid L₀ + h·τ.
        const Scalar turn = (before + h * torques[g] / m - after) / inertia;
        const Vec2 centre = gridMeans(ellipses).first;
        for (model::BodyState& s : ellipses)
            s.velocity += cross(turn, s.position - centre);
    });
}

} // namespace impetus::controller
