// The fixed-body guard (collision/fixed_body_guard.h): where a centre's path enters a fixed body,
// and what the guard does, and does not do, to a substep's end states.

#include "controller/collision/fixed_body_guard.h"
#include "controller/integration/force_model.h"
#include "controller/simulation.h"
#include "controller/soft/soft_body_builder.h"
#include "model/example_scenes.h"
#include "support/world_builders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace impetus::controller {
namespace {

using model::IntegratorKind;
using testing::makeBall;
using testing::makeEmptyWorld;
using testing::makeGround;

model::Body fixedBody(model::Shape shape)
{
    model::Body body;
    body.name = "wall";
    body.shape = std::move(shape);
    body.fixed = true;
    body.updateDerived();
    return body;
}

// A path from (−3, 0) to (1, 0) meets the unit circle's edge at x = −1, half way; the ellipse of
// semi-axes 2 and 1 at x = −2, a quarter of the way.
TEST(PathEntry, IsTheFractionOfThePathWhereItReachesARoundShape)
{
    EXPECT_NEAR(detail::pathEntry(fixedBody(model::Circle{1}), Vec2(-3, 0), Vec2(1, 0)), 0.5, 1e-15);
    EXPECT_NEAR(detail::pathEntry(fixedBody(model::Ellipse{2, 1}), Vec2(-3, 0), Vec2(1, 0)), 0.25, 1e-15);
    // Along y the ellipse is 1 deep: from (0, 3) to (0, −1) it is reached at y = 1, half way.
    EXPECT_NEAR(detail::pathEntry(fixedBody(model::Ellipse{2, 1}), Vec2(0, 3), Vec2(0, -1)), 0.5, 1e-15);
    // Passing by, moving away, stopping short, starting inside: no entry.
    EXPECT_LT(detail::pathEntry(fixedBody(model::Circle{1}), Vec2(-3, 1.5), Vec2(3, 1.5)), 0);
    EXPECT_LT(detail::pathEntry(fixedBody(model::Circle{1}), Vec2(-3, 0), Vec2(-5, 0)), 0);
    EXPECT_LT(detail::pathEntry(fixedBody(model::Circle{1}), Vec2(-3, 0), Vec2(-1.5, 0)), 0);
    EXPECT_LT(detail::pathEntry(fixedBody(model::Circle{1}), Vec2(0.5, 0), Vec2(3, 0)), 0);
}

// A 2 m × 1 m box: from (−3, 0.2) to (1, 0.2) enters its left face x = −1 half way; a path that
// crosses it whole (a tunnel) enters it too; a path passing 0.1 m above its top face does not.
TEST(PathEntry, IsWhereAPathCrossesABoxsFaceAndCatchesAPathThroughIt)
{
    const model::Body box = fixedBody(model::Box{2, 1});
    EXPECT_NEAR(detail::pathEntry(box, Vec2(-3, 0.2), Vec2(1, 0.2)), 0.5, 1e-15);
    EXPECT_NEAR(detail::pathEntry(box, Vec2(-3, 0), Vec2(5, 0)), 0.25, 1e-15);
    EXPECT_NEAR(detail::pathEntry(box, Vec2(0, 2.5), Vec2(0, -2.5)), 0.4, 1e-15);
    EXPECT_LT(detail::pathEntry(box, Vec2(-3, 0.6), Vec2(3, 0.6)), 0);
    EXPECT_LT(detail::pathEntry(box, Vec2(0.5, 0), Vec2(3, 0)), 0);
}

// An L of two convex pieces: the inner corner's notch is outside it. A path into the notch enters
// nothing; a path through the notch into the upright enters where it meets the upright; a path
// from one piece into the other starts inside.
TEST(PathEntry, FindsTheFirstPieceOfAConcavePolygonAndNeverTheNotch)
{
    // The L: a foot 3 × 1 and an upright 1 × 3 at its left, user frame from (0, 0).
    const model::Body l = fixedBody(model::Polygon{{Vec2(0, 0), Vec2(3, 0), Vec2(3, 1), Vec2(1, 1), Vec2(1, 3), Vec2(0, 3)}});
    const Vec2 offset = l.geometry.centroidOffset; // local = user − offset
    ASSERT_GE(l.geometry.convexPieces.size(), 2u);
    const auto local = [&](Scalar x, Scalar y) { return Vec2(Vec2(x, y) - offset); };
    EXPECT_LT(detail::pathEntry(l, local(4, 2), local(2, 2)), 0); // into the notch
    EXPECT_NEAR(detail::pathEntry(l, local(4, 2), local(0.5, 2)), 3.0 / 3.5, 1e-12); // on into the upright at x = 1
    EXPECT_NEAR(detail::pathEntry(l, local(2, 3), local(2, 0.5)), 2.0 / 2.5, 1e-12); // down into the foot at y = 1
    EXPECT_LT(detail::pathEntry(l, local(2, 0.5), local(0.5, 2)), 0); // foot to upright: inside all along
}

/// A fixed wall 2 m thick whose face is at x = 3 (body 0) and a ball of radius 0.2 m (body 1).
model::World ballBeforeAWall()
{
    model::World world = makeEmptyWorld(IntegratorKind::SemiImplicitEuler, 1.0 / 240);
    model::Body wall = fixedBody(model::Box{2, 10});
    wall.state.position = Vec2(4, 0);
    world.bodies.push_back(wall);
    world.bodies.push_back(makeBall("ball", 1, 0.2, Vec2(2, 0), Vec2(10, 0)));
    return world;
}

// A substep that ends with the ball's centre 0.5 m into the wall: the guard puts it back where its
// path met the face, at two thirds of the way, turned two thirds as far, moving as it moved.
TEST(FixedBodyGuard, PutsACentreThatEnteredAWallBackAtTheFace)
{
    const model::World world = ballBeforeAWall();
    std::vector<model::BodyState> start{world.bodies[0].state, world.bodies[1].state};
    std::vector<model::BodyState> end = start;
    end[1].position = Vec2(3.5, 0);
    end[1].angle = 1.5;
    end[1].velocity = Vec2(7, 1);
    FixedBodyGuard guard;
    EXPECT_EQ(guard.keepOut(world, start, end), 1);
    EXPECT_NEAR(end[1].position.x(), 3.0, 1e-5);
    EXPECT_LT(end[1].position.x(), 3.0);
    EXPECT_EQ(end[1].position.y(), 0.0);
    EXPECT_NEAR(end[1].angle, 1.0, 1e-5);
    EXPECT_EQ(end[1].velocity, Vec2(7, 1));
    EXPECT_EQ(end[0], start[0]); // the wall itself is never moved
    EXPECT_EQ(guard.keptOut(), (std::vector<KeptOut>{{1, 0}}));
}

// A centre that stays outside, or that starts the substep inside (a ball drawn into the wall),
// is left where the solve put it.
TEST(FixedBodyGuard, LeavesPathsThatDoNotEnterAlone)
{
    const model::World world = ballBeforeAWall();
    std::vector<model::BodyState> start{world.bodies[0].state, world.bodies[1].state};
    std::vector<model::BodyState> end = start;
    end[1].position = Vec2(2.9, 0.3);
    FixedBodyGuard guard;
    EXPECT_EQ(guard.keepOut(world, start, end), 0);
    EXPECT_EQ(end[1].position, Vec2(2.9, 0.3));
    start[1].position = Vec2(3.2, 0);
    end[1].position = Vec2(3.6, 0);
    EXPECT_EQ(guard.keepOut(world, start, end), 0);
    EXPECT_EQ(end[1].position, Vec2(3.6, 0));
    EXPECT_TRUE(guard.keptOut().empty());
}

// A number that is not finite is left to the step's own check, which names the body: the guard
// neither puts back a body whose end is NaN nor puts anything back by a wall whose pose is NaN.
TEST(FixedBodyGuard, LeavesNotANumberAloneAndSpreadsItNowhere)
{
    const model::World world = ballBeforeAWall();
    const model::BodyState wall = world.bodies[0].state;
    std::vector<model::BodyState> start{wall, world.bodies[1].state};
    std::vector<model::BodyState> end = start;
    end[1].position = Vec2(std::nan(""), 0);
    end[1].angle = 0.5;
    FixedBodyGuard guard;
    EXPECT_EQ(guard.keepOut(world, start, end), 0);
    EXPECT_TRUE(std::isnan(end[1].position.x()));
    EXPECT_EQ(end[1].angle, 0.5);
    end[1].position = Vec2(3.5, 0);
    end[0].angle = std::nan("");
    EXPECT_EQ(guard.keepOut(world, start, end), 0);
    EXPECT_EQ(end[1].position, Vec2(3.5, 0));
}

// A fixed bar 4 m × 0.2 m that moves up 1.2 m in the substep, through a ball at rest 1 m above its
// centre: in the bar's frame the ball's centre went from 1 m above to 0.2 m below, through the
// top face 0.1 m up, three quarters of the way. The guard puts the ball on the top face where the
// bar is at the end, 1.3 m up.
TEST(FixedBodyGuard, SeesAMovingFixedBodyInItsOwnFrame)
{
    model::World world = makeEmptyWorld(IntegratorKind::SemiImplicitEuler, 1.0 / 240);
    world.bodies.push_back(fixedBody(model::Box{4, 0.2}));
    world.bodies.push_back(makeBall("ball", 1, 0.05, Vec2(0, 1)));
    std::vector<model::BodyState> start{world.bodies[0].state, world.bodies[1].state};
    std::vector<model::BodyState> end = start;
    end[0].position = Vec2(0, 1.2);
    FixedBodyGuard guard;
    EXPECT_EQ(guard.keepOut(world, start, end), 1);
    EXPECT_NEAR(end[1].position.x(), 0.0, 1e-12);
    EXPECT_NEAR(end[1].position.y(), 1.3, 1e-5);
    EXPECT_GT(end[1].position.y(), 1.3);
}

// Twenty fixed pegs in a row, more than the guard tests one by one, so that the broad phase pairs
// them with the paths: a ball whose path crosses the row from x = 0.5 to 12.5 is put back at the
// first peg it meets, and a ball whose path meets none is left alone; with three pegs, tested one
// by one, the same ball stops at the same place.
TEST(FixedBodyGuard, StopsAtTheFirstOfManyFixedBodiesWhicheverWayItPairsThem)
{
    for (const int pegs : {20, 3}) {
        model::World world = makeEmptyWorld(IntegratorKind::SemiImplicitEuler, 1.0 / 240);
        for (int i = 0; i < pegs; ++i) {
            model::Body peg = fixedBody(model::Circle{0.25});
            peg.name = std::string(1, static_cast<char>('a' + i));
            peg.state.position = Vec2(2 + i, 0);
            world.bodies.push_back(peg);
        }
        world.bodies.push_back(makeBall("fast", 1, 0.1, Vec2(0.5, 0)));
        world.bodies.push_back(makeBall("above", 1, 0.1, Vec2(0.5, 1)));
        std::vector<model::BodyState> start;
        for (const model::Body& body : world.bodies)
            start.push_back(body.state);
        std::vector<model::BodyState> end = start;
        const auto fast = static_cast<std::size_t>(pegs);
        end[fast].position = Vec2(12.5, 0);
        end[fast + 1].position = Vec2(12.5, 1);
        FixedBodyGuard guard;
        EXPECT_EQ(guard.keepOut(world, start, end), 1) << pegs << " pegs";
        EXPECT_NEAR(end[fast].position.x(), 1.75, 1e-5) << pegs << " pegs";
        EXPECT_EQ(end[fast + 1].position, Vec2(12.5, 1)) << pegs << " pegs";
    }
}

// A soft body's ellipses are entries of the state list after the bodies: one pushed into the wall
// is put back at the face, its neighbours left where they were.
TEST(FixedBodyGuard, PutsASoftBodysEllipseBackAndNoOtherEllipse)
{
    model::World world = makeEmptyWorld(IntegratorKind::SemiImplicitEuler, 1.0 / 240);
    model::Body wall = fixedBody(model::Box{2, 10});
    wall.state.position = Vec2(4, 0);
    world.bodies.push_back(wall);
    model::Body soft = testing::makeBox("soft", 1, 1, 1, Vec2(2, 0));
    soft.soft = model::SoftSettings{};
    world.bodies.push_back(soft);
    prepareSoftBodies(world);
    ASSERT_EQ(world.softBodies.size(), 1u);
    std::vector<model::BodyState> start;
    gatherStates(world, start);
    ASSERT_GT(start.size(), 5u);
    std::vector<model::BodyState> end = start;
    const std::size_t pushed = 2 + 3; // the fourth ellipse
    end[pushed].position = Vec2(3.4, start[pushed].position.y());
    FixedBodyGuard guard;
    EXPECT_EQ(guard.keepOut(world, start, end), 1);
    EXPECT_NEAR(end[pushed].position.x(), 3.0, 1e-5);
    EXPECT_LT(end[pushed].position.x(), 3.0);
    EXPECT_EQ(guard.keptOut(), (std::vector<KeptOut>{{1, 0}})); // told as the soft body
    for (std::size_t i = 0; i < end.size(); ++i) {
        if (i != pushed) {
            EXPECT_EQ(end[i], start[i]) << "entry " << i;
        }
    }
}

// Where the solve holds, the guard never acts: the base-20 pyramid and the ten-box stack at 1/60 s,
// a ball bouncing on the floor, and the 2000 circles of the turning box (moving walls).
TEST(FixedBodyGuard, NeverActsWhereTheSolveHolds)
{
    std::vector<std::pair<const char*, model::World>> worlds;
    model::SceneOptions options;
    options.timeStep = 1.0 / 60;
    worlds.emplace_back("pyramid", model::makePyramid(20, options));
    worlds.emplace_back("stack", model::makeBoxStack(10, options));
    worlds.emplace_back("turning box", model::makeRotatingBoxWithCircles(2000));
    model::World bounce = makeEmptyWorld(IntegratorKind::Rk4, 1.0 / 60, Vec2(0, -9.81));
    bounce.bodies.push_back(makeGround("floor", 10, 1));
    bounce.bodies.push_back(testing::withMaterial(makeBall("ball", 1, 0.2, Vec2(0, 3)), 0.9, 0.3));
    worlds.emplace_back("bounce", bounce);
    for (auto& [name, world] : worlds) {
        Simulation simulation;
        int guarded = 0;
        for (int i = 0; i < 120; ++i) {
            simulation.step(world);
            guarded += simulation.profile().guardedCentres;
        }
        EXPECT_EQ(guarded, 0) << name;
    }
}

} // namespace
} // namespace impetus::controller
