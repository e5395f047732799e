#pragma once
/// \file example_scenes.h
/// Scenes built in code: the standard rigid-body stress tests (Box2D's pyramid and "many
/// pyramids", a polygon rain, a turning box full of circles, and Box2D v3's smash, spinner,
/// tumbler and joint grid) and two small textbook set-ups. The tests, the engine comparison in
/// bench/ and the example files all start from these.
///
/// Every builder returns a fully built World: updateDerived() has been called on every body, and
/// the world runs the semi-implicit Euler integrator, which is what real-time engines (Box2D,
/// Chipmunk) use and all a stack of boxes under constant gravity needs (RK4's accuracy buys
/// nothing once contacts dominate, at four force evaluations a step). Gravity is the world default
/// (0, −9.81) m/s² except where a builder says otherwise. Lengths are in metres; every body has
/// the default density of 1 kg/m². The body order of each scene is part of its contract (the
/// benchmark finds the top box of a pyramid by it) and is given with each builder.

#include "model/constants.h"
#include "model/scalar.h"
#include "model/world.h"

#include <numbers>

namespace impetus::model {

/// What the scene builders share: the surface of every body and the world's fixed step.
struct SceneOptions {
    /// Coulomb friction coefficient μ of every body. 0.6 is Box2D's default, used by its
    /// benchmarks, and is what lets a pyramid stand.
    Scalar friction = 0.6;
    /// Coefficient of restitution e of every body. 0: stacks should settle, not bounce.
    Scalar restitution = 0;
    /// The world's fixed step h, s (1/240 s, the Impetus default).
    Scalar timeStep = constants::kDefaultTimeStep;
};

/// Angular velocity at which the benchmark turns the container of makeRotatingBoxWithCircles,
/// rad/s, counter-clockwise. 0.25 rad/s is a slow tumble (one turn in 25 s) that keeps the
/// circles rolling over each other rather than flung against the walls.
inline constexpr Scalar kRotatingContainerAngularVelocity = 0.25;

/// Box2D's pyramid: 1 m × 1 m boxes, `base` in the bottom row and one fewer in each row above
/// (base·(base+1)/2 boxes, 5050 for base 100), each row centred on the one below so that every
/// box rests exactly (gap 0) on two below it, and the bottom row exactly on a fixed ground box
/// 2·base m × 1 m whose top is at y = 0. The pyramid is centred on x = 0.
/// Body order: the ground, then the rows from the bottom up, each from left to right; the last
/// body is the top box. Precondition: base ≥ 1.
World makePyramid(int base, const SceneOptions& options = {});

/// Box2D's "many pyramids": countY rows of countX pyramids of makePyramid(base) shape. Each row
/// stands on its own fixed ground box; pyramids in a row are base + 2 m apart (a 2 m gap), rows
/// are base + 3 m apart (2 m clear above the top box), so that no two pyramids touch. Row 0's
/// ground has its top at y = 0, and the scene is centred on x = 0.
/// Body order: the countY grounds from the bottom up, then the pyramids row by row from the bottom
/// and left to right within a row, each pyramid in makePyramid's order (rows bottom up, left to
/// right). So pyramid p (0-based in that order) ends with its top box at index
/// countY + (p + 1)·base·(base + 1)/2 − 1. Preconditions: countX, countY, base ≥ 1.
World makePyramidGrid(int countX, int countY, int base, const SceneOptions& options = {});

/// `count` random convex polygons (3–8 vertices on a circle of radius 0.15–0.4 m, so 0.3–0.8 m
/// across) at rest in a grid of 1 m cells, 40 columns wide (fewer when count < 40), the lowest row
/// 1 m above the floor of an open-topped container. The container is three fixed boxes: a floor
/// whose top is at y = 0 and two walls 1 m thick, standing on the floor 1 m clear of the grid on
/// each side and rising 1 m above its top row. The same seed gives the same scene on every
/// platform (the random numbers come straight from std::mt19937, not from a standard-library
/// distribution).
/// Body order: floor, left wall, right wall, then the polygons row by row from the bottom, left to
/// right. Precondition: count ≥ 0.
World makePolygonRain(int count, unsigned seed, const SceneOptions& options = {});

/// `circles` discs of radius 0.25 m at rest in a square grid (0.6 m pitch) centred on the origin,
/// inside a closed square container of four fixed walls 1 m thick, also centred on the origin,
/// whose inside is about 1.5 times the grid's side.
/// Box2D and Chipmunk make such a container a kinematic body turning at a constant angular
/// velocity. In Impetus the walls are fixed bodies (which move with the velocity they are given),
/// and a caller that wants the tumble calls spinFixedBodies(world, origin,
/// kRotatingContainerAngularVelocity) before each step.
/// Body order: bottom, right, top and left walls, then the circles row by row from the bottom,
/// left to right. Precondition: circles ≥ 0.
World makeRotatingBoxWithCircles(int circles = 2000, const SceneOptions& options = {});

/// Gives every fixed body of `world` the velocity of a rigid rotation at `angularVelocity`
/// (rad/s, counter-clockwise) about `pivot` (m): v = ω × (x − pivot), angular velocity ω. A fixed
/// body keeps its velocity through a step, so it moves along the tangent; calling this before
/// every step turns the velocity with it and keeps the bodies on their circles (to ½ω²r·h² per
/// step).
void spinFixedBodies(World& world, const Vec2& pivot, Scalar angularVelocity);

/// Box2D v3's "smash" (its shared/benchmarks.c), in zero gravity: a block 8 m × 8 m of 8 kg/m²
/// centred at (−20, 0) m flies at 40 m/s along +x into a wall of `columns` × `rows` boxes of
/// 0.4 m × 0.4 m at rest, laid side by side on a 0.4 m grid (touching, up to the rounding of
/// 0.4 m in binary): box (i, j) is centred at (30 + 0.4·i, 0.4·(j − rows/2)) m. The block's front
/// face reaches the wall after about 1.15 s. v3 starts the wall asleep; sleeping is left to the
/// caller (the benchmark keeps it off).
/// Body order: the block, then the wall column by column from the left, each from the bottom up.
/// Preconditions: columns, rows ≥ 0.
World makeSmash(int columns = 120, int rows = 80, const SceneOptions& options = {});

/// The surface of the spinner's bodies and walls, as in Box2D v3's spinner: μ = 0.1, e = 0.1.
inline constexpr SceneOptions kSpinnerSurface{.friction = 0.1, .restitution = 0.1};

/// Angular velocity of the spinner's arm, rad/s, counter-clockwise (v3's motor speed).
inline constexpr Scalar kSpinnerAngularVelocity = 5.0;

/// Box2D v3's "spinner": `count` bodies of 0.25 kg/m² (in turn a capsule 1 m × 0.5 m, a circle of
/// radius 0.35 m and a square of 0.7 m) on a 0.5 m grid 92 wide, starting at (−23, 2) m row by
/// row upwards (so neighbours start overlapping, as in v3, and are pushed apart in the first
/// steps), inside a closed ring of radius 40 m centred at (0, 32) m, stirred by an arm 1.2 m ×
/// 40.4 m centred at (0, 12) m that turns at kSpinnerAngularVelocity about its centre.
/// Impetus has neither capsules nor chains nor motors, so: each capsule is the convex octagon
/// inscribed in it (its caps are half hexagons); the ring, one chain of 360 segments in v3, is
/// 360 fixed blocks 1 m thick whose inner faces are the chain's segments; and the arm, a
/// motorised body in v3 (its motor has unbounded torque), is a fixed body with angular velocity
/// kSpinnerAngularVelocity, which makes it a kinematic body (it keeps that velocity; its centre
/// stays put). The arm is frictionless whatever the options say, as in v3; `options` give the
/// bodies' and the ring's surface. The arm and the ring take options.restitution too: v3 gives
/// them 0, but with e = max(e₁, e₂) a contact with them bounces the same either way.
/// Body order: the 360 ring blocks clockwise from (40, 32) m, the arm, then the bodies in grid
/// order (capsule, circle, square, capsule, …). Precondition: count ≥ 0.
World makeSpinner(int count = 6076, const SceneOptions& options = kSpinnerSurface);

/// Angular velocity of the tumbler's container, rad/s, counter-clockwise: 25°/s, v3's motor speed.
inline constexpr Scalar kTumblerAngularVelocity = 25.0 * std::numbers::pi / 180.0;

/// Height of the point the tumbler's container turns about, (0, kTumblerPivotHeight), m.
inline constexpr Scalar kTumblerPivotHeight = 10.0;

/// Box2D v3's "tumbler": a closed square container, 19 m × 19 m inside with walls 1 m thick,
/// centred on its pivot (0, kTumblerPivotHeight), holding `gridCount` × `gridCount` boxes of
/// 0.25 m × 0.25 m at rest on a 0.4 m grid whose first box is centred at (−0.2·gridCount,
/// kTumblerPivotHeight − 0.2·gridCount) m. In v3 the container is a body turned by a motor of
/// 1e8 N·m; here its four walls are fixed bodies, and a caller that wants the tumble calls
/// spinFixedBodies(world, (0, kTumblerPivotHeight), kTumblerAngularVelocity) before each step.
/// (v3's four wall boxes overlap near the corners; here the bottom and top walls run the full
/// outside width, 21 m, and the side walls fit between them: the same inside, with no overlap.)
/// Body order: bottom, right, top and left walls, then the boxes row by row from the bottom, left
/// to right. Precondition: gridCount ≥ 0.
World makeTumbler(int gridCount = 45, const SceneOptions& options = {});

/// Box2D v3's "joint grid": `size` × `size` discs of radius 0.4 m, disc (k, i) centred at
/// (k, −i) m, each pinned to its neighbour above and its neighbour on the left by pin joints
/// halfway between their centres, so that the grid hangs from the 7 discs of the top row nearest
/// its middle (k from size/2 − 3 to size/2 + 3), which are fixed. Unlike v3, whose discs never
/// collide (a collision filter), these discs collide with each other: Impetus has no collision
/// filter, so the benchmark has every engine collide them.
/// Body order: column by column from the left (k), each from the top down (i). Joint order: for
/// each disc in body order, the pin to the disc above (i > 0), then the pin to the disc on the
/// left (k > 0). Precondition: size ≥ 0.
World makeJointGrid(int size = 100, const SceneOptions& options = {});

/// A Newton's cradle without strings: `balls` discs of radius 0.5 m touching in a row along the x
/// axis (centres at x = 0, 1, 2, … m; y = 0), in zero gravity. Ball 0 (the leftmost) moves towards
/// the others at `speed` (m/s); the rest are at rest. Elastic and frictionless by default.
/// Body order: left to right. Precondition: balls ≥ 1.
World makeNewtonsCradle(int balls = 5, Scalar speed = 1.0,
                        const SceneOptions& options = {.friction = 0, .restitution = 1});

/// `count` 1 m × 1 m boxes stacked in a column at x = 0, each resting exactly on the one below
/// (the box i has its centre at y = i + 0.5 m), on a fixed ground box 10 m × 1 m whose top is at
/// y = 0. Body order: the ground, then the boxes from the bottom up. Precondition: count ≥ 0.
World makeBoxStack(int count = 10, const SceneOptions& options = {});

} // namespace impetus::model
