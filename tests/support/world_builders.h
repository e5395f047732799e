#pragma once
/// \file world_builders.h
/// Small worlds built in code for the engine tests: each sets up one textbook situation.

#include "model/pin_anchors.h"
#include "model/world.h"

#include <optional>
#include <string>

namespace impetus::testing {

/// A dynamic circle of radius r and mass m at `position`, velocity `velocity`.
inline model::Body makeBall(std::string name, Scalar mass, Scalar radius, Vec2 position,
                            Vec2 velocity = Vec2::Zero())
{
    model::Body body;
    body.name = std::move(name);
    body.shape = model::Circle{radius};
    body.massSpec = {model::MassMode::Mass, mass};
    body.state.position = position;
    body.state.velocity = velocity;
    body.updateDerived();
    return body;
}

/// A dynamic box of width × height and mass m at `position`, turned by `angle`.
inline model::Body makeBox(std::string name, Scalar mass, Scalar width, Scalar height, Vec2 position,
                           Scalar angle = 0)
{
    model::Body body;
    body.name = std::move(name);
    body.shape = model::Box{width, height};
    body.massSpec = {model::MassMode::Mass, mass};
    body.state.position = position;
    body.state.angle = angle;
    body.updateDerived();
    return body;
}

/// A fixed box whose top face is centred at `topCentre`, turned by `angle` about that point.
inline model::Body makeGround(std::string name, Scalar width, Scalar thickness, Vec2 topCentre = Vec2::Zero(),
                              Scalar angle = 0)
{
    model::Body body;
    body.name = std::move(name);
    body.shape = model::Box{width, thickness};
    body.fixed = true;
    body.state.position = topCentre + rotate(Vec2(0, -thickness / 2), angle);
    body.state.angle = angle;
    body.updateDerived();
    return body;
}

/// Sets a body's material.
inline model::Body withMaterial(model::Body body, Scalar restitution, Scalar friction)
{
    body.material.restitution = restitution;
    body.material.friction = friction;
    return body;
}

/// A pin joint of body a to body b (to the world when b is nullopt) at the world point `anchor`,
/// its anchors in the bodies' frames derived as the scene loader derives them.
inline model::Joint pinAt(const model::World& world, model::BodyId a, std::optional<model::BodyId> b, Vec2 anchor)
{
    model::Joint pin;
    pin.type = model::JointType::Pin;
    pin.bodyA = a;
    pin.bodyB = b;
    pin.worldAnchor = anchor;
    model::derivePinAnchors(world, pin);
    return pin;
}

/// A world with no gravity and the given integrator and step.
inline model::World makeEmptyWorld(model::IntegratorKind integrator, Scalar timeStep, Vec2 gravity = Vec2::Zero())
{
    model::World world;
    world.settings.gravity = gravity;
    world.settings.integrator = integrator;
    world.settings.timeStep = timeStep;
    return world;
}

/// A harmonic oscillator: one ball of mass m on a zero-rest-length spring of stiffness k to the
/// world origin, released from rest at (amplitude, 0). The force is exactly −k·x, so the motion is
/// x(t) = A·cos(ωt) with ω = √(k/m).
inline model::World makeOscillator(model::IntegratorKind integrator, Scalar timeStep, Scalar mass,
                                   Scalar stiffness, Scalar amplitude)
{
    model::World world = makeEmptyWorld(integrator, timeStep);
    world.bodies.push_back(makeBall("bob", mass, 0.1, Vec2(amplitude, 0)));
    model::Spring spring;
    spring.bodyA = model::BodyId{0};
    spring.bodyB = std::nullopt;
    spring.anchorB = Vec2::Zero();
    spring.stiffness = stiffness;
    spring.restLength = 0;
    world.springs.push_back(spring);
    return world;
}

/// `planks` planks on the ground, each carrying `balls` balls: a plank touches more bodies than
/// there are colours (64), so some of its contacts are solved in batches of their own.
inline model::World makeLoadedPlanks(int planks, int balls)
{
    constexpr Scalar kRadius = 0.1;
    constexpr Scalar kSpacing = 0.25;
    const Scalar plankWidth = balls * kSpacing;
    model::World world = makeEmptyWorld(model::IntegratorKind::Rk4, 1.0 / 240.0, Vec2(0, -9.81));
    // The ground lies under the middle of the row of planks, so that every plank rests on it.
    const Vec2 middle((planks - 1) * (plankWidth + 1) / 2, 0);
    world.bodies.push_back(withMaterial(makeGround("ground", planks * (plankWidth + 1) + 10, 1, middle), 0.0, 0.5));
    for (int p = 0; p < planks; ++p) {
        const Scalar centre = p * (plankWidth + 1);
        world.bodies.push_back(withMaterial(
            makeBox("plank" + std::to_string(p), 50.0, plankWidth, 0.2, Vec2(centre, 0.1)), 0.0, 0.5));
        for (int b = 0; b < balls; ++b) {
            const Vec2 at(centre - plankWidth / 2 + kSpacing * (b + 0.5), 0.2 + kRadius + 0.002 * (b % 7));
            world.bodies.push_back(withMaterial(
                makeBall("ball" + std::to_string(p) + "_" + std::to_string(b), 0.5, kRadius, at), 0.0, 0.5));
        }
    }
    return world;
}

} // namespace impetus::testing
