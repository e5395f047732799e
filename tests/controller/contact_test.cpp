// Contacts against the textbook: 1D collisions, bouncing, friction on an incline, rolling,
// Newton's cradle, tunnelling, and the conservation laws of free bodies in zero gravity.

#include "controller/dynamics/contact_solver.h"
#include "controller/diagnostics.h"
#include "controller/simulation.h"
#include "controller/solver_under_test.h"
#include "support/world_builders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace impetus::controller {
namespace {

using model::IntegratorKind;
using testing::makeBall;
using testing::makeBox;
using testing::makeEmptyWorld;
using testing::makeGround;
using testing::withMaterial;

constexpr Scalar kPi = std::numbers::pi_v<Scalar>;
constexpr Scalar kG = 9.81;

void run(model::World& world, Simulation& simulation, int steps)
{
    for (int i = 0; i < steps; ++i)
        simulation.step(world);
}

// ---- Materials -----------------------------------------------------------------------------

// Two bodies of one material behave exactly as that material: the mixing rule gives back e and μ
// bit for bit (√(μ·μ) = μ exactly in IEEE arithmetic), and mixes unlike ones as documented.
TEST(Materials, OneMaterialMixesToItselfExactly)
{
    for (const Scalar x : {0.0, 0.05, 0.3, 1.0 / 3.0, 0.61, 0.999, 1.0, 1.7}) {
        EXPECT_EQ(mixFriction(x, x), x);
        EXPECT_EQ(mixRestitution(x, x), x);
    }
    EXPECT_DOUBLE_EQ(mixFriction(0.2, 0.8), 0.4);
    EXPECT_EQ(mixRestitution(0.2, 0.8), 0.8);
}

// ---- 1D collisions -------------------------------------------------------------------------

struct Collision1d {
    Scalar m1, m2, v1, v2, e;
};

class OneDimensionalCollision : public ::testing::TestWithParam<Collision1d> {};

// Two discs meet head on in zero gravity. Momentum is conserved to rounding at every step, and the
// velocities after are v₁' = (m₁v₁ + m₂v₂ − m₂e(v₁ − v₂))/(m₁ + m₂) and
// v₂' = (m₁v₁ + m₂v₂ + m₁e(v₁ − v₂))/(m₁ + m₂).
TEST_P(OneDimensionalCollision, MatchesTheTextbook)
{
    const Collision1d c = GetParam();
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240.0);
    world.bodies.push_back(withMaterial(makeBall("a", c.m1, 0.25, Vec2(-1, 0), Vec2(c.v1, 0)), c.e, 0.3));
    world.bodies.push_back(withMaterial(makeBall("b", c.m2, 0.25, Vec2(1, 0), Vec2(c.v2, 0)), c.e, 0.3));
    const Vec2 p0 = linearMomentum(world);
    Simulation simulation(settingsUnderTest());
    for (int i = 0; i < 480; ++i) {
        simulation.step(world);
        ASSERT_NEAR((linearMomentum(world) - p0).norm(), 0.0, 1e-9 * std::max(1.0, p0.norm())) << "step " << i;
    }
    const Scalar total = c.m1 + c.m2;
    const Scalar p = c.m1 * c.v1 + c.m2 * c.v2;
    const Scalar v1 = (p - c.m2 * c.e * (c.v1 - c.v2)) / total;
    const Scalar v2 = (p + c.m1 * c.e * (c.v1 - c.v2)) / total;
    EXPECT_NEAR(world.bodies[0].state.velocity.x(), v1, 1e-6);
    EXPECT_NEAR(world.bodies[1].state.velocity.x(), v2, 1e-6);
    EXPECT_NEAR(world.bodies[0].state.velocity.y(), 0.0, 1e-12);
    EXPECT_NEAR(world.bodies[0].state.angularVelocity, 0.0, 1e-9);
    EXPECT_EQ(world.collisionCount, 1);
    EXPECT_EQ(world.bodies[0].collisionCount, 1);
}

INSTANTIATE_TEST_SUITE_P(Contacts, OneDimensionalCollision,
                         ::testing::Values(Collision1d{1, 1, 3, -1, 1.0}, Collision1d{1, 1, 3, -1, 0.0},
                                           Collision1d{1, 3, 2, 0, 0.5}, Collision1d{5, 0.5, 1, -4, 0.8},
                                           Collision1d{2, 7, 4, 1, 0.3}, Collision1d{0.2, 0.2, 5, -1, 0.9}));

// ---- Bouncing ------------------------------------------------------------------------------

// A ball dropped on the floor rises after each bounce to e² times its previous height (energy
// after an impact is e² times the energy before).
TEST(Bounce, ApexesFollowESquaredToTheN)
{
    const Scalar e = 0.8;
    const Scalar r = 0.1;
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240.0, Vec2(0, -kG));
    world.bodies.push_back(withMaterial(makeGround("floor", 10, 1), e, 0.0));
    world.bodies.push_back(withMaterial(makeBall("ball", 1.0, r, Vec2(0, 1.0 + r)), e, 0.0));
    Simulation simulation(settingsUnderTest());
    std::vector<Scalar> apexes{1.0};
    Scalar previousVy = 0;
    for (int i = 0; i < 240 * 6 && apexes.size() < 5; ++i) {
        simulation.step(world);
        const model::BodyState& s = world.bodies[1].state;
        if (previousVy > 0 && s.velocity.y() <= 0) {
            // Refine the apex between samples: y + v²/2g from the last state going up.
            apexes.push_back(s.position.y() - r + s.velocity.y() * s.velocity.y() / (2 * kG));
        }
        previousVy = s.velocity.y();
    }
    ASSERT_EQ(apexes.size(), 5u);
    for (std::size_t n = 1; n < apexes.size(); ++n) {
        const Scalar expected = std::pow(e, 2.0 * static_cast<double>(n));
        EXPECT_NEAR(apexes[n], expected, 0.005 * expected) << "bounce " << n;
    }
}

// ---- Friction --------------------------------------------------------------------------------

/// A block resting on a fixed incline of angle θ (descending to the right), both with friction μ.
model::World makeIncline(Scalar theta, Scalar mu, model::Body block)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240.0, Vec2(0, -kG));
    world.bodies.push_back(withMaterial(makeGround("ramp", 40, 1, Vec2::Zero(), -theta), 0.0, mu));
    const Vec2 normal = rotate(Vec2(0, 1), -theta);
    const Vec2 uphill = rotate(Vec2(-1, 0), -theta);
    Scalar halfHeight = 0;
    if (const auto* box = std::get_if<model::Box>(&block.shape))
        halfHeight = box->height / 2;
    else if (const auto* circle = std::get_if<model::Circle>(&block.shape))
        halfHeight = circle->radius;
    block.state.position = 2.0 * uphill + halfHeight * normal;
    block.state.angle = -theta;
    world.bodies.push_back(withMaterial(block, 0.0, mu));
    return world;
}

/// The body's velocity along the slope, downhill positive.
Scalar downhillSpeed(const model::World& world, Scalar theta)
{
    return world.bodies[1].state.velocity.dot(rotate(Vec2(1, 0), -theta));
}

// μ < tanθ: the block slides with a = g(sinθ − μcosθ).
TEST(Incline, BlockSlidesWithTheoreticalAcceleration)
{
    const Scalar theta = kPi / 6;
    const Scalar mu = 0.2;
    model::World world = makeIncline(theta, mu, makeBox("block", 1.0, 0.4, 0.2, Vec2::Zero()));
    Simulation simulation(settingsUnderTest());
    run(world, simulation, 240);
    const Scalar expected = kG * (std::sin(theta) - mu * std::cos(theta)) * 1.0;
    EXPECT_NEAR(downhillSpeed(world, theta), expected, 0.01 * expected);
}

// μ > tanθ: the block stays put; creep under 1 mm in 2 s.
TEST(Incline, BlockSticksWhenFrictionExceedsTanTheta)
{
    const Scalar theta = kPi / 6;
    model::World world = makeIncline(theta, 0.7, makeBox("block", 1.0, 0.4, 0.2, Vec2::Zero()));
    const Vec2 start = world.bodies[1].state.position;
    Simulation simulation(settingsUnderTest());
    run(world, simulation, 480);
    EXPECT_LT((world.bodies[1].state.position - start).norm(), 1e-3);
    EXPECT_TRUE(world.bodies[1].colliding);
}

// A disc rolling without slipping accelerates at a = ⅔·g·sinθ.
TEST(Incline, DiskRollsWithTwoThirdsGSinTheta)
{
    const Scalar theta = 20 * kPi / 180;
    model::World world = makeIncline(theta, 0.5, makeBall("disk", 1.0, 0.2, Vec2::Zero()));
    Simulation simulation(settingsUnderTest());
    run(world, simulation, 240);
    const Scalar expected = 2.0 / 3.0 * kG * std::sin(theta);
    EXPECT_NEAR(downhillSpeed(world, theta), expected, 0.01 * expected);
    // Rolling: ω·r equals the speed (clockwise spin for downhill motion to the right).
    EXPECT_NEAR(-world.bodies[1].state.angularVelocity * 0.2, downhillSpeed(world, theta), 0.01 * expected);
}

// A box set down on a conveyor belt (a fixed body moving at u) slides, accelerated by kinetic
// friction μ·g, until it moves with the belt: v(t) = min(μ·g·t, u). The belt is not slowed.
TEST(Friction, ConveyorBeltCarriesABoxUpToItsSpeed)
{
    const Scalar mu = 0.4;
    const Scalar u = 1.5;
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240.0, Vec2(0, -kG));
    model::Body belt = withMaterial(makeGround("belt", 60, 0.5), 0.0, mu);
    belt.state.velocity = Vec2(u, 0);
    world.bodies.push_back(belt);
    world.bodies.push_back(withMaterial(makeBox("parcel", 2.0, 0.5, 0.3, Vec2(0, 0.15)), 0.0, mu));
    Simulation simulation(settingsUnderTest());
    run(world, simulation, 48); // 0.2 s: still slipping (μ·g·t = 0.78 m/s < u)
    EXPECT_NEAR(world.bodies[1].state.velocity.x(), mu * kG * 0.2, 0.01 * mu * kG * 0.2);
    run(world, simulation, 192); // 1 s: long since carried at the belt's speed
    EXPECT_NEAR(world.bodies[1].state.velocity.x(), u, 1e-6);
    EXPECT_EQ(world.bodies[0].state.velocity, Vec2(u, 0));
    EXPECT_NEAR(world.bodies[1].state.position.y(), 0.15, constants::kLinearSlop);
}

// ---- Newton's cradle -------------------------------------------------------------------------

/// n touching balls in a row; the first `moving` of them come in at speed v from the left.
model::World makeCradle(int n, int moving, Scalar v)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240.0);
    const Scalar r = 0.1;
    for (int i = 0; i < n; ++i) {
        // The moving balls start 0.05 m to the left of the resting row, still touching each other.
        const Scalar x = 2 * r * i - (i < moving ? 0.05 : 0.0);
        world.bodies.push_back(withMaterial(makeBall("ball" + std::to_string(i), 0.5, r, Vec2(x, 0),
                                                     Vec2(i < moving ? v : 0.0, 0)),
                                            1.0, 0.0));
    }
    return world;
}

// The real toy: one ball in, one ball out at the same speed; the others stay at rest.
TEST(NewtonsCradle, OneBallInOneBallOut)
{
    model::World world = makeCradle(5, 1, 2.0);
    Simulation simulation(settingsUnderTest());
    run(world, simulation, 120);
    for (int i = 0; i < 4; ++i)
        EXPECT_NEAR(world.bodies[static_cast<std::size_t>(i)].state.velocity.norm(), 0.0, 1e-6) << "ball " << i;
    EXPECT_NEAR(world.bodies[4].state.velocity.x(), 2.0, 1e-6);
}

TEST(NewtonsCradle, TwoBallsInTwoBallsOut)
{
    model::World world = makeCradle(5, 2, 1.5);
    Simulation simulation(settingsUnderTest());
    run(world, simulation, 120);
    for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(world.bodies[static_cast<std::size_t>(i)].state.velocity.norm(), 0.0, 1e-6) << "ball " << i;
    EXPECT_NEAR(world.bodies[3].state.velocity.x(), 1.5, 1e-6);
    EXPECT_NEAR(world.bodies[4].state.velocity.x(), 1.5, 1e-6);
}

// ---- Tunnelling ------------------------------------------------------------------------------

// A 0.1 m ball at 200 m/s (0.83 m per step) against a 0.1 m wall bounces back instead of passing
// through: speculative contacts stop it at the surface in the step it would cross.
TEST(Tunnelling, FastBallBouncesOffAThinWall)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240.0);
    model::Body wall;
    wall.name = "wall";
    wall.shape = model::Box{0.1, 2.0};
    wall.fixed = true;
    wall.state.position = Vec2(5.05, 0);
    wall.updateDerived();
    world.bodies.push_back(withMaterial(wall, 1.0, 0.0));
    world.bodies.push_back(withMaterial(makeBall("bullet", 0.1, 0.05, Vec2(0, 0), Vec2(200, 0)), 1.0, 0.0));
    Simulation simulation(settingsUnderTest());
    run(world, simulation, 24); // 0.1 s
    EXPECT_NEAR(world.bodies[1].state.velocity.x(), -200.0, 1e-6);
    EXPECT_LT(world.bodies[1].state.position.x(), 5.0 - 0.05);
    EXPECT_EQ(world.collisionCount, 1);
}

// A ball struck by another flies into a wall just behind it, in the same step: the wall's contact
// was made in time (speculative margins allow for what an impact can hand on), so it rebounds
// instead of passing through.
TEST(Tunnelling, StruckBallDoesNotPassThroughTheWallBehindIt)
{
    for (const Scalar v : {10.0, 50.0, 200.0}) {
        model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240.0);
        model::Body wall;
        wall.name = "wall";
        wall.shape = model::Box{0.02, 2.0};
        wall.fixed = true;
        wall.state.position = Vec2(0.11 + 0.01, 0); // its face 10 mm behind the resting ball
        wall.updateDerived();
        world.bodies.push_back(withMaterial(wall, 1.0, 0.0));
        // The striker touches the ball as the step starts, so the ball travels a whole step.
        world.bodies.push_back(withMaterial(makeBall("striker", 1.0, 0.1, Vec2(-0.2, 0), Vec2(v, 0)), 1.0, 0.0));
        world.bodies.push_back(withMaterial(makeBall("struck", 1.0, 0.1, Vec2(0, 0)), 1.0, 0.0));
        Simulation simulation(settingsUnderTest());
        run(world, simulation, 24);
        // In front of the wall's face (x = 0.11), pressed into it by no more than the position
        // solver allows (3 slops; see ContactSolver::solvePositions). Without the margin for what
        // an impact hands on, it ends far beyond the wall.
        EXPECT_LT(world.bodies[2].state.position.x(), 0.11 - 0.1 + 3 * constants::kLinearSlop) << "v = " << v;
        // Equal masses, e = 1: the struck ball rebounds from the wall and hands its speed back
        // to the striker, which leaves at −v while the struck ball stays at rest by the wall.
        EXPECT_NEAR(world.bodies[2].state.velocity.x(), 0.0, 1e-6) << "v = " << v;
        EXPECT_NEAR(world.bodies[1].state.velocity.x(), -v, 1e-6) << "v = " << v;
    }
}

// An ellipse spinning at 2,233 rad/s thrown at 50 m/s against a thick wall (soak seed 131: an
// ellipse struck to that spin passed through the wall). Its contact is built at the start of a
// substep and followed linearly in its turn: at 1/240 s it turned 9.3 rad, a turn and a half,
// within one, and at 16 of 40 starting angles its centre ended beyond the wall's face. Split so
// that it turns at most an eighth of a turn a substep (spinSubsteps), it bounces off at every
// angle, at 1/240 s and 1/60 s, under explicit Euler and RK4, and leaves with no more kinetic
// energy than it came with.
TEST(Tunnelling, FastSpinningEllipseBouncesOffAWall)
{
    constexpr Scalar kSpin = 2233; // rad/s
    constexpr Scalar kSpeed = 50; // m/s
    constexpr Scalar kSemiMajor = 0.3; // m
    constexpr Scalar kSemiMinor = 0.1; // m
    for (const Scalar h : {1.0 / 240.0, 1.0 / 60.0}) {
        for (const IntegratorKind integrator : {IntegratorKind::Euler, IntegratorKind::Rk4}) {
            for (int k = 0; k < 40; ++k) {
                model::World world = makeEmptyWorld(integrator, h, Vec2::Zero());
                // A fixed box 2 m thick whose face is the line x = 0.
                world.bodies.push_back(withMaterial(makeGround("wall", 2, 20, Vec2(1, 10)), 0.5, 0.5));
                model::Body spinner = makeBox("spinner", 1.0, 1.0, 1.0, Vec2(-1, 0));
                spinner.shape = model::Ellipse{kSemiMajor, kSemiMinor};
                spinner.state.velocity = Vec2(kSpeed, 0);
                spinner.state.angularVelocity = kSpin;
                spinner.state.angle = 0.07 * k;
                spinner.updateDerived();
                world.bodies.push_back(withMaterial(spinner, 0.5, 0.5));
                const model::Body& body = world.bodies[1];
                // Zero gravity and a fixed wall: the world's energy is the ellipse's kinetic energy.
                const Scalar kineticBefore = computeEnergy(world).kinetic;
                Simulation simulation(settingsUnderTest());
                const int steps = static_cast<int>(std::lround(0.25 / h));
                for (int i = 0; i < steps; ++i) {
                    simulation.step(world);
                    // Its centre stays at least a semi-minor axis from the face, less what the
                    // position solver lets a contact press in.
                    ASSERT_LT(body.state.position.x(), -kSemiMinor + 3 * constants::kLinearSlop)
                        << "h = " << h << ", integrator " << static_cast<int>(integrator) << ", angle " << 0.07 * k
                        << ", step " << i;
                    ASSERT_LE(computeEnergy(world).kinetic, kineticBefore * (1 + 1e-12));
                }
                // It came back off the wall.
                EXPECT_LT(body.state.velocity.x(), 0) << "h = " << h << ", angle " << 0.07 * k;
            }
        }
    }
}

// A vertical Newton's cradle: a ball dropped onto a ball resting on the floor (all e = 1). The
// blow travels through the resting contacts, and the top ball bounces back up to near its drop
// height, while the bottom ball stays on the floor.
TEST(Bounce, BallDroppedOnARestingBallBouncesBackUp)
{
    const Scalar r = 0.1;
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240.0, Vec2(0, -kG));
    world.bodies.push_back(withMaterial(makeGround("floor", 10, 1), 1.0, 0.0));
    world.bodies.push_back(withMaterial(makeBall("bottom", 1.0, r, Vec2(0, r)), 1.0, 0.0));
    world.bodies.push_back(withMaterial(makeBall("top", 1.0, r, Vec2(0, 3 * r + 1.0)), 1.0, 0.0));
    Simulation simulation(settingsUnderTest());
    run(world, simulation, 120); // the bottom ball settles under load
    Scalar highest = 0;
    Scalar bottomHighest = 0;
    for (int i = 0; i < 240; ++i) {
        simulation.step(world);
        if (i > 120) {
            highest = std::max(highest, world.bodies[2].state.position.y());
            bottomHighest = std::max(bottomHighest, world.bodies[1].state.position.y());
        }
    }
    EXPECT_GT(highest, 3 * r + 0.9); // back up to within 10 cm of where it was dropped
    EXPECT_LT(bottomHighest, r + 0.01);
}

// ---- Moving fixed bodies ---------------------------------------------------------------------

// A box riding on a platform that moves down at 1 m/s stays on it: no gap opens, and its velocity
// is the platform's.
TEST(MovingFixedBody, BoxRidesAPlatformMovingDown)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240.0, Vec2(0, -kG));
    model::Body platform = withMaterial(makeGround("lift", 4, 0.2), 0.0, 0.5);
    platform.state.velocity = Vec2(0, -1);
    world.bodies.push_back(platform);
    world.bodies.push_back(withMaterial(makeBox("crate", 1.0, 0.5, 0.5, Vec2(0, 0.25)), 0.0, 0.5));
    Simulation simulation(settingsUnderTest());
    run(world, simulation, 240);
    const Scalar platformTop = world.bodies[0].state.position.y() + 0.1;
    EXPECT_NEAR(world.bodies[1].state.position.y() - 0.25, platformTop, constants::kLinearSlop);
    EXPECT_NEAR(world.bodies[1].state.velocity.y(), -1.0, 1e-6);
}

// A bob pinned to a moving fixed carrier keeps its hinge on the carrier.
TEST(MovingFixedBody, PinToAMovingCarrierHolds)
{
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240.0);
    model::Body carrier = makeGround("carrier", 1, 0.2);
    carrier.state.velocity = Vec2(1, 0);
    world.bodies.push_back(carrier);
    world.bodies.push_back(makeBox("bob", 1.0, 0.2, 0.2, Vec2(0, -1)));
    model::Joint pin;
    pin.type = model::JointType::Pin;
    pin.bodyA = model::BodyId{1};
    pin.bodyB = model::BodyId{0};
    pin.worldAnchor = Vec2(0, -0.1);
    pin.anchorA = Vec2(0, 0.9);
    pin.anchorB = Vec2(0, 0);
    world.joints.push_back(pin);
    Simulation simulation(settingsUnderTest());
    for (int i = 0; i < 240; ++i) {
        simulation.step(world);
        const Vec2 onBob = world.bodies[1].worldPoint(Vec2(0, 0.9));
        const Vec2 onCarrier = world.bodies[0].worldPoint(Vec2(0, 0));
        ASSERT_LT((onBob - onCarrier).norm(), 1e-3) << "step " << i;
    }
    // The hinge moves with the carrier.
    EXPECT_NEAR((world.bodies[1].velocityAt(world.bodies[1].worldPoint(Vec2(0, 0.9))) - Vec2(1, 0)).norm(), 0.0, 0.01);
}

// ---- Collision events ------------------------------------------------------------------------

// Two boxes resting on the pillars of a fixed U (a concave body of several pieces) begin their
// contacts once each, not in every step.
TEST(CollisionEvents, RestingOnAConcaveBodyBeginsOnce)
{
    // Both orders of the two boxes: the bodies' pairs then come out of the pieces' order in both
    // ways.
    for (const bool rightFirst : {true, false}) {
        model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240.0, Vec2(0, -kG));
        model::Body u;
        u.name = "u";
        u.shape = model::Polygon{{Vec2(-2, 0), Vec2(2, 0), Vec2(2, 2), Vec2(1, 2), Vec2(1, 1), Vec2(-1, 1),
                                  Vec2(-1, 2), Vec2(-2, 2)}};
        u.fixed = true;
        u.updateDerived();
        u.state.position = u.geometry.centroidOffset; // the vertices as given are world coordinates
        world.bodies.push_back(u);
        const Scalar firstX = rightFirst ? 1.5 : -1.5;
        world.bodies.push_back(makeBox("first", 1.0, 0.8, 0.4, Vec2(firstX, 2.2)));
        world.bodies.push_back(makeBox("second", 1.0, 0.8, 0.4, Vec2(-firstX, 2.2)));
        Simulation simulation(settingsUnderTest());
        run(world, simulation, 240);
        EXPECT_EQ(world.collisionCount, 2) << "right first: " << rightFirst;
        EXPECT_EQ(world.bodies[0].collisionCount, 2) << "right first: " << rightFirst;
        EXPECT_TRUE(world.bodies[1].colliding);
        EXPECT_TRUE(world.bodies[2].colliding);
    }
}

// ---- Conservation in zero gravity ------------------------------------------------------------

// Random convex polygons thrown together in zero gravity: every contact impulse is internal, so
// linear momentum is conserved to rounding and no contact ever adds kinetic energy. Angular
// momentum is conserved to rounding too, in a pile where a body takes impacts and contact forces in
// the same step (docs/physics.md, "Conservation"; it drifted by 1e-4 of L before each impulse acted
// at one point in space at each body's own time).
TEST(ZeroGravity, RandomPolygonsConserveMomentumAndNeverGainEnergy)
{
    std::mt19937 rng(12345);
    auto uniform = [&](Scalar lo, Scalar hi) {
        return lo + (hi - lo) * static_cast<Scalar>(rng() - std::mt19937::min()) /
                        static_cast<Scalar>(std::mt19937::max() - std::mt19937::min());
    };
    model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240.0);
    for (int i = 0; i < 16; ++i) {
        model::Body body;
        // Appended rather than "p" + …: GCC 12 warns falsely (-Wrestrict) on that concatenation.
        body.name = "p";
        body.name += std::to_string(i);
        std::vector<Vec2> vertices;
        const int n = 3 + i % 5;
        for (int k = 0; k < n; ++k) {
            const Scalar angle = 2 * kPi * (k + uniform(0.1, 0.9)) / n;
            const Scalar radius = uniform(0.25, 0.45);
            vertices.push_back(radius * Vec2(std::cos(angle), std::sin(angle)));
        }
        body.shape = model::Polygon{vertices};
        body.state.position = Vec2(1.2 * (i % 4) - 1.8, 1.2 * (i / 4) - 1.8);
        // Everything flies towards the middle, spinning.
        body.state.velocity = -1.5 * body.state.position.normalized() + Vec2(uniform(-0.3, 0.3), uniform(-0.3, 0.3));
        body.state.angularVelocity = uniform(-2, 2);
        body.material.restitution = uniform(0.0, 1.0);
        body.material.friction = uniform(0.0, 0.8);
        body.updateDerived();
        world.bodies.push_back(body);
    }
    const Vec2 p0 = linearMomentum(world);
    const Scalar l0 = angularMomentum(world);
    Scalar kinetic = computeEnergy(world).kinetic;
    const Scalar k0 = kinetic;
    Simulation simulation(settingsUnderTest());
    for (int i = 0; i < 240 * 3; ++i) {
        simulation.step(world);
        ASSERT_NEAR((linearMomentum(world) - p0).norm(), 0.0, 1e-9) << "step " << i;
        ASSERT_NEAR(angularMomentum(world), l0, 1e-9 * std::abs(l0)) << "step " << i;
        const Scalar k = computeEnergy(world).kinetic;
        ASSERT_LE(k, kinetic * (1 + 1e-12)) << "step " << i;
        kinetic = k;
    }
    EXPECT_GT(world.collisionCount, 10);
    EXPECT_LT(kinetic, k0); // some collisions were inelastic
}

// Two polygons meeting off-centre in zero gravity: impacts with spin and friction. Linear and
// angular momentum are conserved to rounding (every impulse acts on both bodies at one common
// point at the time of impact), and the collision changes the spins. (With e = 0 these two stay in
// contact and strike again; that is the mixed case the pile-up test above covers.)
TEST(ZeroGravity, ObliqueImpactConservesAngularMomentumExactly)
{
    for (const Scalar e : {0.3, 0.6, 1.0}) {
        model::World world = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 240.0);
        model::Body a = withMaterial(makeBox("a", 2.0, 1.0, 0.5, Vec2(-2, 0.3), 0.3), e, 0.4);
        a.state.velocity = Vec2(3, 0);
        a.state.angularVelocity = 1.0;
        model::Body b;
        b.name = "b";
        b.shape = model::Polygon{{Vec2(0, 0), Vec2(1, 0), Vec2(0.5, 0.9)}};
        b.massSpec = {model::MassMode::Mass, 1.0};
        b.state.position = Vec2(1, -0.2);
        b.state.velocity = Vec2(-2, 0.5);
        b.updateDerived();
        world.bodies.push_back(a);
        world.bodies.push_back(withMaterial(b, e, 0.4));
        const Vec2 p0 = linearMomentum(world);
        const Scalar l0 = angularMomentum(world);
        Simulation simulation(settingsUnderTest());
        for (int i = 0; i < 240; ++i) {
            simulation.step(world);
            ASSERT_NEAR((linearMomentum(world) - p0).norm(), 0.0, 1e-12) << "e = " << e;
            ASSERT_NEAR(angularMomentum(world), l0, 1e-9 * std::abs(l0)) << "e = " << e << ", step " << i;
        }
        EXPECT_GE(world.collisionCount, 1) << "e = " << e; // the spinning box may strike twice
        EXPECT_NE(world.bodies[1].state.angularVelocity, 0.0) << "e = " << e;
    }
}

} // namespace
} // namespace impetus::controller
