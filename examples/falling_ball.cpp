/// \file falling_ball.cpp
/// The smallest program built on the installed engine: a ball dropped from rest falls a height h
/// onto a fixed floor. It prints the time of the first contact, as the engine reports it, next to
/// the textbook fall time t = √(2h/g), and exits 0 when the two agree to within one time step
/// (the engine reports contacts at the end of the step in which they begin), 1 otherwise.
///
///   falling_ball [HEIGHT]        HEIGHT in metres, > 0 (default 2)

#include "controller/simulation.h"
#include "model/world.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

namespace model = impetus::model;

/// Ball radius, m: a tennis ball.
constexpr double kBallRadius = 0.033;
/// Floor size, m: wide enough that the ball cannot miss it, thick enough to look like a floor.
constexpr double kFloorWidth = 4.0;
constexpr double kFloorThickness = 0.2;
/// Fall height used when none is given, m.
constexpr double kDefaultHeight = 2.0;
/// How long the program waits for the ball to land before it gives up, in multiples of the
/// textbook fall time.
constexpr double kPatience = 2.0;

/// A world whose floor's top face is at y = 0 and whose ball's lowest point starts at y = h.
model::World makeWorld(double height)
{
    model::World world; // default settings: g = 9.81 m/s² downwards, RK4, h = 1/240 s

    model::Body floor;
    floor.name = "floor";
    floor.shape = model::Box{kFloorWidth, kFloorThickness};
    floor.fixed = true;
    floor.state.position = impetus::Vec2(0, -kFloorThickness / 2);
    floor.updateDerived();
    world.bodies.push_back(floor);

    model::Body ball;
    ball.name = "ball";
    ball.shape = model::Circle{kBallRadius};
    ball.state.position = impetus::Vec2(0, height + kBallRadius);
    ball.updateDerived();
    world.bodies.push_back(ball);
    return world;
}

} // namespace

int main(int argc, char* argv[])
{
    double height = kDefaultHeight;
    if (argc > 1) {
        char* end = nullptr;
        height = std::strtod(argv[1], &end);
        if (end == argv[1] || *end != '\0' || !std::isfinite(height) || height <= 0) {
            std::fprintf(stderr, "falling_ball: HEIGHT must be a number of metres > 0, not \"%s\"\n", argv[1]);
            return 2;
        }
    }

    model::World world = makeWorld(height);
    const double g = -world.settings.gravity.y();
    const double dt = world.settings.timeStep;
    const double expected = std::sqrt(2 * height / g);

    impetus::controller::Simulation simulation;
    while (world.time < kPatience * expected) {
        simulation.step(world);
        if (!simulation.events().empty()) {
            const double landed = simulation.events().front().time;
            std::printf("height h       %.3f m\n", height);
            std::printf("engine         %.4f s (first contact, time step %.4f s)\n", landed, dt);
            std::printf("sqrt(2h/g)     %.4f s\n", expected);
            std::printf("difference     %+.4f s\n", landed - expected);
            // The contact is reported at the end of its step: up to one step after the textbook
            // time, never before it.
            return (landed >= expected && landed - expected <= dt) ? 0 : 1;
        }
    }
    std::fprintf(stderr, "falling_ball: the ball did not land within %.2f s\n", world.time);
    return 1;
}
