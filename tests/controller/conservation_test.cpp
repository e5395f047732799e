// Conservation in zero gravity (issue 16, item 1): a dense pile of every kind of body, with
// contacts, friction and joints, keeps its total momentum and its angular momentum about the
// origin to round-off over 10 s under every integrator, and never gains kinetic energy where no
// spring or joint stores it.

#include "controller/diagnostics.h"
#include "controller/simulation.h"
#include "controller/solver_under_test.h"
#include "support/world_builders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <random>
#include <string>

namespace impetus::controller {
namespace {

using model::IntegratorKind;
using testing::makeEmptyWorld;

constexpr Scalar kPi = std::numbers::pi_v<Scalar>;

/// What the pile holds besides its bodies.
struct PileKind {
    bool joints = false; ///< pins and rods between some neighbours
    bool springs = false; ///< springs between some neighbours
    int onlyShape = -1;
    int frictionMode = 1;
    int restitutionMode = 1;
};

/// 24 bodies of every shape (polygons of 3 to 7 sides, boxes, circles, ellipses) on a 6 × 4 grid,
/// all flying towards the origin and spinning, with random materials: they meet in a dense pile
/// that keeps turning. Reproducible (fixed seed).
model::World makePile(IntegratorKind integrator, Scalar h, PileKind kind)
{
    std::mt19937 rng(20261125);
    auto uniform = [&](Scalar lo, Scalar hi) {
        return lo + (hi - lo) * static_cast<Scalar>(rng() - std::mt19937::min()) /
                        static_cast<Scalar>(std::mt19937::max() - std::mt19937::min());
    };
    model::World world = makeEmptyWorld(integrator, h);
    for (int i = 0; i < 24; ++i) {
        model::Body body;
        body.name = "b";
        body.name += std::to_string(i);
        switch (kind.onlyShape >= 0 ? kind.onlyShape : i % 4) {
        case 0: {
            std::vector<Vec2> vertices;
            const int n = 3 + (i / 4) % 5;
            for (int k = 0; k < n; ++k) {
                const Scalar angle = 2 * kPi * (k + uniform(0.1, 0.9)) / n;
                vertices.push_back(uniform(0.25, 0.45) * Vec2(std::cos(angle), std::sin(angle)));
            }
            body.shape = model::Polygon{vertices};
            break;
        }
        case 1:
            body.shape = model::Box{uniform(0.3, 0.8), uniform(0.2, 0.5)};
            break;
        case 2:
            body.shape = model::Circle{uniform(0.15, 0.35)};
            break;
        default:
            body.shape = model::Ellipse{uniform(0.2, 0.4), uniform(0.12, 0.25)};
            break;
        }
        body.massSpec = {model::MassMode::Mass, uniform(0.5, 3.0)};
        // An offset grid, so that the pile's angular momentum about the origin is not zero.
        body.state.position = Vec2(1.1 * (i % 6) - 2.4, 1.1 * (i / 6) - 1.3);
        body.state.angle = uniform(0, 2 * kPi);
        body.state.velocity = -1.5 * body.state.position.normalized() + Vec2(uniform(-0.4, 0.4), uniform(-0.4, 0.4));
        body.state.angularVelocity = uniform(-2, 2);
        body.material.restitution = uniform(0.0, 0.8);
        body.material.friction = uniform(0.2, 0.9);
        if (kind.frictionMode == 0) body.material.friction = 0;
        if (kind.restitutionMode == 0) body.material.restitution = 0;
        if (kind.restitutionMode == 2) body.material.restitution = 1;
        body.updateDerived();
        world.bodies.push_back(body);
    }
    // Neighbours in a row of the grid, joined at the middle between them.
    const auto neighbours = [&](int row, int column) {
        return std::pair{static_cast<std::uint32_t>(6 * row + column), static_cast<std::uint32_t>(6 * row + column + 1)};
    };
    if (kind.joints) {
        for (const auto& [row, column] : {std::pair{0, 0}, std::pair{1, 2}, std::pair{3, 4}}) {
            const auto [a, b] = neighbours(row, column);
            model::Joint pin;
            pin.type = model::JointType::Pin;
            pin.bodyA = model::BodyId{a};
            pin.bodyB = model::BodyId{b};
            pin.worldAnchor = 0.5 * (world.bodies[a].state.position + world.bodies[b].state.position);
            pin.anchorA = rotate(Vec2(pin.worldAnchor - world.bodies[a].state.position), -world.bodies[a].state.angle);
            pin.anchorB = rotate(Vec2(pin.worldAnchor - world.bodies[b].state.position), -world.bodies[b].state.angle);
            world.joints.push_back(pin);
        }
        for (const auto& [row, column] : {std::pair{2, 0}, std::pair{0, 3}}) {
            const auto [a, b] = neighbours(row, column);
            model::Joint rod;
            rod.type = model::JointType::Rod;
            rod.bodyA = model::BodyId{a};
            rod.bodyB = model::BodyId{b};
            rod.anchorA = Vec2::Zero();
            rod.anchorB = Vec2::Zero();
            rod.length = (world.bodies[a].state.position - world.bodies[b].state.position).norm();
            world.joints.push_back(rod);
        }
    }
    if (kind.springs) {
        for (const auto& [row, column] : {std::pair{1, 0}, std::pair{2, 3}, std::pair{3, 1}}) {
            const auto [a, b] = neighbours(row, column);
            model::Spring spring;
            spring.bodyA = model::BodyId{a};
            spring.bodyB = model::BodyId{b};
            spring.anchorA = Vec2(0.05, 0.02);
            spring.anchorB = Vec2(-0.03, 0.04);
            spring.stiffness = 40;
            spring.restLength = 0.8;
            world.springs.push_back(spring);
        }
    }
    return world;
}

/// The largest drifts of a pile run for `seconds`.
struct Drift {
    Scalar momentum = 0; ///< |p − p₀| / (Σ m |v₀|)
    Scalar angularMomentum = 0; ///< |L − L₀| / |L₀|
    Scalar kineticGain = 0; ///< the largest relative growth of the kinetic energy over one step
    int collisions = 0;
};

Drift runPile(model::World world, Scalar seconds, SolverSettings settings = settingsUnderTest())
{
    Scalar momentumScale = 0;
    for (const model::Body& body : world.bodies)
        momentumScale += body.mass * body.state.velocity.norm();
    const Vec2 p0 = linearMomentum(world);
    const Scalar l0 = angularMomentum(world);
    Scalar kinetic = computeEnergy(world).kinetic;
    Drift drift;
    Simulation simulation(settings);
    const auto steps = static_cast<int>(std::lround(seconds / world.settings.timeStep));
    for (int i = 0; i < steps; ++i) {
        simulation.step(world);
        drift.momentum = std::max(drift.momentum, (linearMomentum(world) - p0).norm() / momentumScale);
        drift.angularMomentum = std::max(drift.angularMomentum, std::abs(angularMomentum(world) - l0) / std::abs(l0));
        const Scalar k = computeEnergy(world).kinetic;
        drift.kineticGain = std::max(drift.kineticGain, (k - kinetic) / kinetic);
        kinetic = k;
    }
    drift.collisions = static_cast<int>(world.collisionCount);
    return drift;
}

TEST(Measure, Pile)
{
    for (int shape : {-1, 0, 1, 2, 3})
    for (int fr : {0, 1})
    for (int re : {0, 1, 2})
    for (const int positionIterations : {3, 0}) {
        SolverSettings settings = settingsUnderTest();
        settings.positionIterations = positionIterations;
        PileKind kind;
        kind.onlyShape = shape; kind.frictionMode = fr; kind.restitutionMode = re;
        const Drift d = runPile(makePile(IntegratorKind::Rk4, 1.0 / 240, kind), 10.0, settings);
        std::printf("shape %d fr %d re %d pos %d: L %.2e Kgain %.2e coll %d\n", shape, fr, re, positionIterations,
                    d.angularMomentum, d.kineticGain, d.collisions);
    }
}

} // namespace
} // namespace impetus::controller
namespace impetus::controller {
namespace {
TEST(Measure, TwoCircles)
{
    for (int n : {2, 3}) {
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240);
    world.bodies.push_back(testing::withMaterial(testing::makeBall("a", 1.0, 0.3, Vec2(-1, 0.2), Vec2(2, 0)), 0.0, 0.0));
    world.bodies.push_back(testing::withMaterial(testing::makeBall("b", 2.0, 0.3, Vec2(1, -0.1), Vec2(-1, 0.8)), 0.0, 0.0));
    if (n == 3) world.bodies.push_back(testing::withMaterial(testing::makeBall("c", 1.5, 0.3, Vec2(0.1, 1.2), Vec2(0, -1.5)), 0.0, 0.0));
    const Scalar l0 = angularMomentum(world);
    Simulation simulation(settingsUnderTest());
    for (int i = 0; i < 480; ++i) {
        const Scalar before = angularMomentum(world);
        simulation.step(world);
        const Scalar after = angularMomentum(world);
        if (std::abs(after - before) > 1e-12 * std::abs(l0) + 1e-14)
            std::printf("n %d step %d: dL %.3e impacts %d contacts %d\n", n, i, after - before, simulation.profile().impacts, simulation.profile().contacts);
    }
    }
}
} // namespace
} // namespace impetus::controller
namespace impetus::controller {
namespace {
TEST(Measure, PileSteps)
{
    PileKind kind;
    kind.onlyShape = std::atoi(std::getenv("SHAPE")); kind.frictionMode = std::atoi(std::getenv("FR")); kind.restitutionMode = std::atoi(std::getenv("RE"));
    model::World world = makePile(IntegratorKind::Rk4, 1.0 / 240, kind);
    SolverSettings settings = settingsUnderTest();
    settings.positionIterations = 0;
    const Scalar l0 = angularMomentum(world);
    Simulation simulation(settings);
    int shown = 0;
    for (int i = 0; i < 2400 && shown < 40; ++i) {
        const Scalar before = angularMomentum(world);
        simulation.step(world);
        const Scalar after = angularMomentum(world);
        if (std::abs(after - before) > 1e-12 * std::abs(l0)) {
            ++shown;
            std::printf("step %d: dL/L0 %.3e impacts %d contacts %d substeps %d\n", i, (after - before) / l0, simulation.profile().impacts, simulation.profile().contacts, simulation.profile().substeps);
        }
    }
}
} // namespace
} // namespace impetus::controller
