// A perfectly elastic ball keeps bouncing (issue 17, item 1, F1): the probe's scenes, in which a
// step ends with the ball touching the floor while it still falls, stopped it dead.

#include "controller/simulation.h"
#include "model/scene_io.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace impetus::controller {
namespace {

/// bad-cases/F1_elastic_ball_stops_dead_*.json: e = 1, μ = 0, a ball 4.3 mm above the floor
/// falling at 1 m/s, so that the first step ends with it on the floor still falling.
std::string fallingBallScene(const std::string& integrator)
{
    return R"({"format": "impetus-scene", "version": 1, "world": {"gravity": [0, -9.81], "integrator": ")" +
           integrator +
           R"("}, "bodies": [{"name": "floor", "shape": {"type": "box", "width": 12, "height": 1}, "position": [0, -0.5],
           "fixed": true, "restitution": 1, "friction": 0}, {"name": "ball", "shape": {"type": "circle", "radius": 0.3},
           "position": [0, 0.30429666666666666], "velocity": [0, -1.0], "restitution": 1, "friction": 0}]})";
}

/// The heights (m) of the ball's centre at each apex, over `seconds` of simulated time.
std::vector<Scalar> apexes(model::World world, Scalar seconds)
{
    Simulation simulation;
    std::vector<Scalar> out;
    Scalar previousVy = world.bodies[1].state.velocity.y();
    const auto steps = static_cast<int>(seconds / world.settings.timeStep);
    for (int k = 0; k < steps; ++k) {
        simulation.step(world);
        const Scalar vy = world.bodies[1].state.velocity.y();
        if (previousVy > 0 && vy <= 0)
            out.push_back(world.bodies[1].state.position.y());
        previousVy = vy;
    }
    return out;
}

class ElasticBounce : public ::testing::TestWithParam<std::string> {};

// Before the fix the ball stopped on the first step it ended on the floor while still falling:
// no bounce at all, with every integrator.
TEST_P(ElasticBounce, TheBallKeepsBouncing)
{
    const model::SceneLoadResult loaded = model::parseScene(fallingBallScene(GetParam()));
    ASSERT_TRUE(loaded.ok());
    // A bounce 5.5 cm high takes 2·√(2·0.055/g) ≈ 0.21 s. Semi-implicit Euler loses and explicit
    // Euler gains about 2gh/v of the energy per bounce (docs/physics.md, "Energy over long runs"),
    // so only the count is common to all three: at least ten in three seconds.
    EXPECT_GE(apexes(*loaded.world, 3).size(), 10u);
}

// RK4 is exact in free fall, so with e = 1 every apex is the same: e²ⁿ·h₀ = h₀. The first landing
// ends a step on the floor, where the speculative contact stops the ball at the surface with
// 1.031 m/s instead of 1.041 m/s at 45 µm above it; that costs 2.2 % of the bounce once, and
// nothing afterwards.
TEST(ElasticBounceRk4, EveryApexIsTheSame)
{
    const model::SceneLoadResult loaded = model::parseScene(fallingBallScene("rk4"));
    ASSERT_TRUE(loaded.ok());
    const model::World& world = *loaded.world;
    const Scalar g = 9.81;
    const Scalar radius = 0.3;
    const Scalar y0 = world.bodies[1].state.position.y();
    const Scalar v0 = world.bodies[1].state.velocity.y();
    const Scalar bounce = y0 + v0 * v0 / (2 * g) - radius; // m above the resting height

    const std::vector<Scalar> found = apexes(world, 3);
    ASSERT_GE(found.size(), 13u);
    // The one speculative landing: m(1.0409² − 1.0312²)/2 of ½m·1.0409², 1.9 %, and the 45 µm.
    constexpr Scalar kFirstLandingLoss = 0.023;
    EXPECT_GT(found.front() - radius, (1 - kFirstLandingLoss) * bounce);
    EXPECT_LT(found.front() - radius, bounce);
    // Sampled at the step where the velocity turns, an apex is seen up to ½·g·h² ≈ 85 µm low.
    const Scalar sampling = 0.5 * g * world.settings.timeStep * world.settings.timeStep;
    for (const Scalar y : found)
        EXPECT_NEAR(y, found.front(), sampling);
}

// bad-cases/F1b: a ball bouncing in a closed box under explicit Euler struck the floor at
// −12.4 m/s at t = 153.658 s and stayed there. It is still bouncing at 165 s.
TEST(ElasticBounceInABox, StillBouncingAfter153Seconds)
{
    const model::SceneLoadResult loaded = model::parseScene(R"({"format": "impetus-scene", "version": 1,
        "world": {"gravity": [0, -9.81], "integrator": "euler"}, "bodies": [
        {"name": "floor", "shape": {"type": "box", "width": 12, "height": 1}, "position": [0, -0.5], "fixed": true, "restitution": 1, "friction": 0},
        {"name": "ceil", "shape": {"type": "box", "width": 12, "height": 1}, "position": [0, 10.5], "fixed": true, "restitution": 1, "friction": 0},
        {"name": "left", "shape": {"type": "box", "width": 1, "height": 10}, "position": [-5.5, 5.0], "fixed": true, "restitution": 1, "friction": 0},
        {"name": "right", "shape": {"type": "box", "width": 1, "height": 10}, "position": [5.5, 5.0], "fixed": true, "restitution": 1, "friction": 0},
        {"name": "ball", "shape": {"type": "circle", "radius": 0.3}, "position": [0, 5], "restitution": 1, "friction": 0}]})");
    ASSERT_TRUE(loaded.ok());
    model::World world = *loaded.world;
    Simulation simulation;
    const auto stepsTo = [&](Scalar t) { return static_cast<int>(t / world.settings.timeStep); };
    for (int k = 0; k < stepsTo(155); ++k)
        simulation.step(world);
    Scalar fastest = 0;
    for (int k = 0; k < stepsTo(10); ++k) {
        simulation.step(world);
        fastest = std::max(fastest, std::abs(world.bodies[4].state.velocity.y()));
    }
    // Dropped from 4.7 m above the floor it lands at √(2·g·4.7) ≈ 9.6 m/s, more with Euler's gain.
    EXPECT_GT(fastest, 9.0);
}

INSTANTIATE_TEST_SUITE_P(EveryIntegrator, ElasticBounce, ::testing::Values("euler", "semi-implicit-euler", "rk4"),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                             std::string name = param.param;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

} // namespace
} // namespace impetus::controller
