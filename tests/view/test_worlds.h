#pragma once
/// \file test_worlds.h
/// Small worlds built in C++ for the view tests, so that they do not depend on scene files.

#include "model/world.h"

#include <string>
#include <utility>

namespace impetus::view::test {

/// A body called `name` with `shape` at `position`, its derived data computed.
inline model::Body makeBody(std::string name, model::Shape shape, Vec2 position, bool fixed = false)
{
    model::Body body;
    body.name = std::move(name);
    body.shape = std::move(shape);
    body.state.position = position;
    body.fixed = fixed;
    body.updateDerived();
    return body;
}

/// No gravity; a ball of radius 0.1 m at the origin moving right at 2 m/s, and a fixed 0.2 m box at
/// (2, 1) m that frames the view around it and for the ruler to snap to.
inline model::World movingBallWorld()
{
    model::World world;
    world.settings.gravity = Vec2::Zero();
    model::Body ball = makeBody("ball", model::Circle{0.1}, Vec2(0, 0));
    ball.state.velocity = Vec2(2, 0);
    world.bodies.push_back(ball);
    world.bodies.push_back(makeBody("marker", model::Box{0.2, 0.2}, Vec2(2, 1), true));
    return world;
}

/// A pin hinging body `a` of `world` to body `b` at the world point `hinge`, its anchors in each
/// body's frame taken from their current poses, as the scene loader derives them.
inline model::Joint pinAt(const model::World& world, model::BodyId a, model::BodyId b, Vec2 hinge)
{
    model::Joint pin;
    pin.type = model::JointType::Pin;
    pin.bodyA = a;
    pin.bodyB = b;
    pin.worldAnchor = hinge;
    const model::BodyState& stateA = world.body(a).state;
    const model::BodyState& stateB = world.body(b).state;
    pin.anchorA = rotate(Vec2(hinge - stateA.position), -stateA.angle);
    pin.anchorB = rotate(Vec2(hinge - stateB.position), -stateB.angle);
    return pin;
}

/// No gravity; a red ball at the origin moving straight up at 1 m/s, and a fixed grey box 2 m
/// above it that widens the framed region so the ball stays in view as it rises.
inline model::World risingBallWorld()
{
    model::World world;
    world.settings.gravity = Vec2::Zero();
    model::Body ball = makeBody("ball", model::Circle{0.1}, Vec2(0, 0));
    ball.state.velocity = Vec2(0, 1);
    ball.color = model::Color{0xff, 0x00, 0x00};
    world.bodies.push_back(ball);
    model::Body marker = makeBody("marker", model::Box{0.2, 0.2}, Vec2(0, 2), true);
    marker.color = model::Color{0x80, 0x80, 0x80};
    world.bodies.push_back(marker);
    return world;
}

/// Under gravity: a box hanging from the world point (0, 2) by a spring, and a fixed floor.
inline model::World hangingBoxWorld()
{
    model::World world;
    world.bodies.push_back(makeBody("box", model::Box{0.4, 0.3}, Vec2(0.3, 1)));
    world.bodies.push_back(makeBody("floor", model::Box{4, 0.2}, Vec2(0, -0.1), true));
    model::Spring spring;
    spring.bodyA = model::BodyId{0};
    spring.anchorA = Vec2(0, 0.15);
    spring.anchorB = Vec2(0, 2);
    spring.stiffness = 50;
    spring.restLength = 0.6;
    world.springs.push_back(spring);
    return world;
}

/// No gravity; a ball called "bob" 1 m from the world origin, held there by a spring far too stiff
/// (k = 10¹⁴ N/m) for the default time step: within a few dozen steps its state is not finite.
inline model::World explodingSpringWorld()
{
    model::World world;
    world.settings.gravity = Vec2::Zero();
    world.bodies.push_back(makeBody("bob", model::Circle{0.1}, Vec2(1, 0)));
    model::Spring spring;
    spring.bodyA = model::BodyId{0};
    spring.anchorB = Vec2(0, 0);
    spring.stiffness = 1e14;
    spring.restLength = 0;
    world.springs.push_back(spring);
    return world;
}

} // namespace impetus::view::test
