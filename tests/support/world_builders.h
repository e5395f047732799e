#pragma once
/// \file world_builders.h
/// Small worlds built in code for the engine tests: each sets up one textbook situation.

#include "model/world.h"

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

} // namespace impetus::testing
