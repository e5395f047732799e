// The scene builders: body counts and order, bodies that start touching but never overlapping
// (pyramid rows rest with a gap of exactly 0), valid random polygons, Box2D v3's scenes as v3
// lays them out, determinism, and the rotation of fixed bodies that stands in for a kinematic
// container.

#include "model/example_scenes.h"

#include "model/polygon.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <variant>
#include <vector>

namespace impetus::model {
namespace {

/// A body's convex pieces in world coordinates: polygons, or one circle.
struct WorldShape {
    std::vector<std::vector<Vec2>> polygons;
    Vec2 centre = Vec2::Zero();
    Scalar radius = 0; ///< > 0 for a circle
    Vec2 lower = Vec2::Zero();
    Vec2 upper = Vec2::Zero();
};

WorldShape worldShape(const Body& body)
{
    WorldShape shape;
    if (const auto* circle = std::get_if<Circle>(&body.shape)) {
        shape.centre = body.state.position;
        shape.radius = circle->radius;
        shape.lower = shape.centre - Vec2::Constant(shape.radius);
        shape.upper = shape.centre + Vec2::Constant(shape.radius);
        return shape;
    }
    shape.lower = Vec2::Constant(std::numeric_limits<Scalar>::infinity());
    shape.upper = -shape.lower;
    for (const auto& piece : body.geometry.convexPieces) {
        std::vector<Vec2>& polygon = shape.polygons.emplace_back();
        for (const Vec2& v : piece) {
            polygon.push_back(body.worldPoint(v));
            shape.lower = shape.lower.cwiseMin(polygon.back());
            shape.upper = shape.upper.cwiseMax(polygon.back());
        }
    }
    return shape;
}

/// The largest gap along the outward normals of `a`'s edges between `a` and `b` (SAT). Positive:
/// apart; zero: touching; negative: overlapping by at least that much along every edge normal.
Scalar faceSeparation(const std::vector<Vec2>& a, const std::vector<Vec2>& b)
{
    Scalar best = -std::numeric_limits<Scalar>::infinity();
    for (std::size_t i = 0; i < a.size(); ++i) {
        const Vec2 edge = a[(i + 1) % a.size()] - a[i];
        const Vec2 normal = Vec2(edge.y(), -edge.x()).normalized();
        Scalar nearest = std::numeric_limits<Scalar>::infinity();
        for (const Vec2& v : b)
            nearest = std::min(nearest, normal.dot(v - a[i]));
        best = std::max(best, nearest);
    }
    return best;
}

/// Separation of two convex polygons, or of a polygon and a circle, or of two circles: the SAT
/// distance, which is ≥ 0 exactly when the shapes do not overlap.
Scalar separation(const std::vector<Vec2>& a, const std::vector<Vec2>& b)
{
    return std::max(faceSeparation(a, b), faceSeparation(b, a));
}

Scalar separation(const std::vector<Vec2>& polygon, const Vec2& centre, Scalar radius)
{
    Scalar best = -std::numeric_limits<Scalar>::infinity();
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vec2 edge = polygon[(i + 1) % polygon.size()] - polygon[i];
        const Vec2 normal = Vec2(edge.y(), -edge.x()).normalized();
        best = std::max(best, normal.dot(centre - polygon[i]) - radius);
    }
    // The one axis a circle adds: from the nearest vertex to its centre.
    const Vec2 nearest = *std::min_element(polygon.begin(), polygon.end(), [&](const Vec2& p, const Vec2& q) {
        return (p - centre).squaredNorm() < (q - centre).squaredNorm();
    });
    const Vec2 axis = (centre - nearest).normalized();
    Scalar deepest = std::numeric_limits<Scalar>::infinity();
    for (const Vec2& v : polygon)
        deepest = std::min(deepest, axis.dot(centre - v));
    return std::max(best, deepest - radius);
}

Scalar separation(const WorldShape& a, const WorldShape& b)
{
    if (a.radius > 0 && b.radius > 0)
        return (a.centre - b.centre).norm() - a.radius - b.radius;
    if (a.radius > 0)
        return separation(b, a);
    Scalar result = std::numeric_limits<Scalar>::infinity();
    // Two bodies are as far apart as their closest pair of convex pieces.
    for (const auto& p : a.polygons) {
        if (b.radius > 0)
            result = std::min(result, separation(p, b.centre, b.radius));
        for (const auto& q : b.polygons)
            result = std::min(result, separation(p, q));
    }
    return result;
}

struct Contact {
    std::size_t a;
    std::size_t b;
    Scalar separation;
};

/// Every pair of bodies whose bounding boxes touch or overlap, with their SAT separation. A
/// sweep along x keeps the 22,000-body grid quick.
std::vector<Contact> closePairs(const World& world)
{
    std::vector<WorldShape> shapes;
    for (const Body& body : world.bodies)
        shapes.push_back(worldShape(body));
    std::vector<std::size_t> order(shapes.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](std::size_t i, std::size_t j) { return shapes[i].lower.x() < shapes[j].lower.x(); });
    std::vector<Contact> contacts;
    for (std::size_t k = 0; k < order.size(); ++k) {
        const WorldShape& a = shapes[order[k]];
        for (std::size_t m = k + 1; m < order.size() && shapes[order[m]].lower.x() <= a.upper.x(); ++m) {
            const WorldShape& b = shapes[order[m]];
            if (b.lower.y() > a.upper.y() || a.lower.y() > b.upper.y())
                continue;
            contacts.push_back({std::min(order[k], order[m]), std::max(order[k], order[m]), separation(a, b)});
        }
    }
    return contacts;
}

/// Fails for every pair of bodies that overlap.
void expectNoOverlap(const World& world)
{
    for (const Contact& contact : closePairs(world)) {
        EXPECT_GE(contact.separation, 0) << world.bodies[contact.a].name << " overlaps "
                                         << world.bodies[contact.b].name;
    }
}

std::size_t countFixed(const World& world)
{
    return static_cast<std::size_t>(
        std::count_if(world.bodies.begin(), world.bodies.end(), [](const Body& b) { return b.fixed; }));
}

// ---- The separation helper itself, on cases worked by hand ---------------------------------------

TEST(SceneTestGeometry, SeparationOfKnownPairs)
{
    Body box;
    box.shape = Box{1, 1};
    box.updateDerived();
    Body other = box;
    other.state.position = Vec2(1, 0); // sharing an edge
    EXPECT_EQ(separation(worldShape(box), worldShape(other)), 0);
    other.state.position = Vec2(0.75, 0.5); // overlapping by 0.25 along x
    EXPECT_NEAR(separation(worldShape(box), worldShape(other)), -0.25, 1e-15);
    other.state.position = Vec2(2, 2); // corner to corner, 1 m apart along each axis
    EXPECT_NEAR(separation(worldShape(box), worldShape(other)), 1, 1e-15);

    Body ball;
    ball.shape = Circle{0.5};
    ball.updateDerived();
    ball.state.position = Vec2(1.5, 1.5); // beyond the corner (0.5, 0.5): √2 − 0.5 away
    EXPECT_NEAR(separation(worldShape(box), worldShape(ball)), std::sqrt(2.0) - 0.5, 1e-15);
    ball.state.position = Vec2(0, 0.9); // overlapping the top face by 0.1
    EXPECT_NEAR(separation(worldShape(ball), worldShape(box)), -0.1, 1e-15);
}

// ---- Pyramids ------------------------------------------------------------------------------------

TEST(ExampleScenes, PyramidOfBase100Has5050BoxesOnOneGround)
{
    const World world = makePyramid(100);
    ASSERT_EQ(world.bodies.size(), 5051u);
    EXPECT_TRUE(world.bodies[0].fixed);
    EXPECT_EQ(countFixed(world), 1u);
    for (std::size_t i = 1; i < world.bodies.size(); ++i) {
        const Body& body = world.bodies[i];
        ASSERT_TRUE(std::holds_alternative<Box>(body.shape));
        EXPECT_EQ(std::get<Box>(body.shape), (Box{1, 1}));
        EXPECT_EQ(body.material.friction, 0.6);
        EXPECT_EQ(body.material.restitution, 0);
        EXPECT_EQ(body.mass, 1); // 1 m² at the default 1 kg/m²
    }
    // The ground's top is y = 0 and it is wider than the pyramid.
    const WorldShape ground = worldShape(world.bodies[0]);
    EXPECT_EQ(ground.upper.y(), 0);
    EXPECT_LE(ground.lower.x(), -50);
    EXPECT_GE(ground.upper.x(), 50);
    EXPECT_EQ(world.settings.integrator, IntegratorKind::SemiImplicitEuler);
    EXPECT_EQ(world.settings.timeStep, constants::kDefaultTimeStep);
}

TEST(ExampleScenes, PyramidRowsRestExactlyOnEachOther)
{
    const int base = 100;
    const World world = makePyramid(base);
    expectNoOverlap(world);
    // Every box rests (separation exactly 0, not 1e-16) on the ground or on two boxes below it,
    // and the top box ends the body list.
    std::vector<int> supports(world.bodies.size(), 0);
    for (const Contact& contact : closePairs(world)) {
        const Body& a = world.bodies[contact.a];
        const Body& b = world.bodies[contact.b];
        if (contact.separation != 0 || a.state.position.y() == b.state.position.y())
            continue;
        ++supports[a.state.position.y() > b.state.position.y() ? contact.a : contact.b];
    }
    for (std::size_t i = 1; i < world.bodies.size(); ++i) {
        const bool bottomRow = world.bodies[i].state.position.y() == 0.5;
        EXPECT_GE(supports[i], bottomRow ? 1 : 2) << world.bodies[i].name;
    }
    EXPECT_EQ(world.bodies.back().state.position, Vec2(0, base - 0.5));
}

TEST(ExampleScenes, PyramidGridCountsOrderAndSpacing)
{
    const int countX = 20;
    const int countY = 20;
    const int base = 10;
    const World world = makePyramidGrid(countX, countY, base);
    const std::size_t perPyramid = base * (base + 1) / 2;
    ASSERT_EQ(world.bodies.size(), countY + countX * countY * perPyramid);
    EXPECT_EQ(countFixed(world), static_cast<std::size_t>(countY));
    for (int row = 0; row < countY; ++row)
        EXPECT_TRUE(world.bodies[static_cast<std::size_t>(row)].fixed);

    // The documented index of each pyramid's top box holds the highest box of that pyramid.
    for (std::size_t p = 0; p < static_cast<std::size_t>(countX * countY); ++p) {
        const std::size_t first = countY + p * perPyramid;
        const std::size_t top = countY + (p + 1) * perPyramid - 1;
        for (std::size_t i = first; i < top; ++i)
            ASSERT_LT(world.bodies[i].state.position.y(), world.bodies[top].state.position.y());
        EXPECT_EQ(world.bodies[top].state.position.x(), world.bodies[first + base / 2].state.position.x() - 0.5)
            << "pyramid " << p << " is not symmetric about its top box";
    }

    // Bodies touch only within one pyramid and its own ground: no two pyramids touch.
    const auto pyramidOf = [&](std::size_t i) -> std::ptrdiff_t {
        return i < static_cast<std::size_t>(countY) ? -1 : static_cast<std::ptrdiff_t>((i - countY) / perPyramid);
    };
    for (const Contact& contact : closePairs(world)) {
        ASSERT_GE(contact.separation, 0)
            << world.bodies[contact.a].name << " overlaps " << world.bodies[contact.b].name;
        if (contact.separation > 0)
            continue;
        const std::ptrdiff_t pa = pyramidOf(contact.a);
        const std::ptrdiff_t pb = pyramidOf(contact.b);
        if (pa >= 0 && pb >= 0) {
            EXPECT_EQ(pa, pb) << world.bodies[contact.a].name << " touches " << world.bodies[contact.b].name;
        } else {
            // A ground (the lower index) under a bottom-row box of a pyramid in its own row.
            EXPECT_EQ(static_cast<std::ptrdiff_t>(contact.a), pb / countX);
        }
    }
}

// ---- Polygon rain --------------------------------------------------------------------------------

TEST(ExampleScenes, PolygonRainPolygonsAreValidConvexAndInSize)
{
    const int count = 1000;
    const World world = makePolygonRain(count, 7);
    ASSERT_EQ(world.bodies.size(), 3u + count);
    EXPECT_EQ(countFixed(world), 3u);
    for (std::size_t i = 3; i < world.bodies.size(); ++i) {
        const Body& body = world.bodies[i];
        ASSERT_TRUE(std::holds_alternative<Polygon>(body.shape));
        const std::vector<Vec2>& vertices = std::get<Polygon>(body.shape).vertices;
        EXPECT_TRUE(validatePolygon(vertices).empty()) << body.name;
        EXPECT_TRUE(isConvex(vertices)) << body.name;
        EXPECT_GE(vertices.size(), 3u);
        EXPECT_LE(vertices.size(), 8u) << "Box2D takes at most 8 vertices";
        EXPECT_EQ(body.geometry.convexPieces.size(), 1u);
        // On a circle of radius 0.15–0.4 m about the body's own origin.
        const Scalar radius = vertices.front().norm();
        EXPECT_GE(radius, 0.15);
        EXPECT_LT(radius, 0.4);
        for (const Vec2& v : vertices)
            EXPECT_NEAR(v.norm(), radius, 1e-12);
    }
    expectNoOverlap(world);
}

TEST(ExampleScenes, PolygonRainFallsIntoItsContainer)
{
    const World world = makePolygonRain(500, 3);
    const WorldShape floor = worldShape(world.bodies[0]);
    const WorldShape left = worldShape(world.bodies[1]);
    const WorldShape right = worldShape(world.bodies[2]);
    EXPECT_EQ(floor.upper.y(), 0);
    EXPECT_EQ(left.lower.y(), 0);
    EXPECT_EQ(right.lower.y(), 0);
    for (std::size_t i = 3; i < world.bodies.size(); ++i) {
        const WorldShape polygon = worldShape(world.bodies[i]);
        EXPECT_GT(polygon.lower.x(), left.upper.x());
        EXPECT_LT(polygon.upper.x(), right.lower.x());
        EXPECT_GT(polygon.lower.y(), 0);
        EXPECT_LT(polygon.upper.y(), left.upper.y()) << "every polygon starts below the rim";
    }
}

TEST(ExampleScenes, PolygonRainUsesTheRawGeneratorOutputOnly)
{
    // std::mt19937's sequence is fixed by the standard; the builder maps it to numbers itself
    // (k = 3 + x mod 6, u = x / 2³²), so the first polygon can be rebuilt here from the raw output.
    // A standard-library distribution would make this fail on some library.
    std::mt19937 random(2024);
    const auto next = [&] { return static_cast<Scalar>(random()) / 4294967296.0; };
    const int k = 3 + static_cast<int>(random() % 6);
    const Scalar radius = 0.15 + 0.25 * next();
    const Scalar spacing = 2 * std::numbers::pi / k;
    const Scalar phase = spacing * next();
    std::vector<Vec2> expected;
    for (int i = 0; i < k; ++i) {
        const Scalar angle = phase + spacing * (i + 0.4 * next());
        expected.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
    }
    const World world = makePolygonRain(1, 2024);
    EXPECT_EQ(std::get<Polygon>(world.bodies[3].shape).vertices, expected);
}

TEST(ExampleScenes, PolygonRainDependsOnTheSeed)
{
    EXPECT_NE(makePolygonRain(50, 1), makePolygonRain(50, 2));
}

// ---- Rotating box --------------------------------------------------------------------------------

TEST(ExampleScenes, RotatingBoxHoldsItsCirclesInsideFourWalls)
{
    const World world = makeRotatingBoxWithCircles();
    ASSERT_EQ(world.bodies.size(), 2004u);
    EXPECT_EQ(countFixed(world), 4u);
    Vec2 insideLower = Vec2::Constant(-std::numeric_limits<Scalar>::infinity());
    Vec2 insideUpper = -insideLower;
    for (std::size_t i = 0; i < 4; ++i) {
        ASSERT_TRUE(world.bodies[i].fixed);
        const WorldShape wall = worldShape(world.bodies[i]);
        // The inside of the container is where no wall is.
        if (wall.upper.y() < 0)
            insideLower.y() = wall.upper.y();
        else if (wall.lower.y() > 0)
            insideUpper.y() = wall.lower.y();
        else if (wall.upper.x() < 0)
            insideLower.x() = wall.upper.x();
        else
            insideUpper.x() = wall.lower.x();
    }
    EXPECT_EQ(insideLower, -insideUpper) << "the container is centred on the origin";
    for (std::size_t i = 4; i < world.bodies.size(); ++i) {
        const Body& body = world.bodies[i];
        ASSERT_EQ(std::get<Circle>(body.shape).radius, 0.25);
        const WorldShape circle = worldShape(body);
        EXPECT_GT(circle.lower.x(), insideLower.x());
        EXPECT_GT(circle.lower.y(), insideLower.y());
        EXPECT_LT(circle.upper.x(), insideUpper.x());
        EXPECT_LT(circle.upper.y(), insideUpper.y());
    }
    expectNoOverlap(world);
}

TEST(ExampleScenes, SpinFixedBodiesGivesOnlyTheFixedOnesARigidRotation)
{
    World world = makeRotatingBoxWithCircles(10);
    const World start = world;
    const Vec2 pivot(1, 2);
    const Scalar omega = 0.5;
    spinFixedBodies(world, pivot, omega);
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        const BodyState& before = start.bodies[i].state;
        const BodyState& after = world.bodies[i].state;
        if (!world.bodies[i].fixed) {
            EXPECT_EQ(after, before);
            continue;
        }
        // v = ω × (x − pivot) = ω·(−r.y, r.x); the poses are untouched.
        const Vec2 r = before.position - pivot;
        EXPECT_NEAR(after.velocity.x(), -omega * r.y(), 1e-12);
        EXPECT_NEAR(after.velocity.y(), omega * r.x(), 1e-12);
        EXPECT_EQ(after.angularVelocity, omega);
        EXPECT_EQ(after.position, before.position);
        EXPECT_EQ(after.angle, before.angle);
    }
}

// ---- Box2D v3's scenes ------------------------------------------------------------------------------

/// The wall of the smash lies on a 0.4 m grid, and 0.4 is not exact in binary: neighbours that
/// touch may come out a few ulps of 30 m (about 1e-14 m) apart or into each other.
constexpr Scalar kGridRounding = 1e-12;

TEST(ExampleScenes, SmashSendsADenseBlockIntoAWallOfTouchingBoxes)
{
    const int columns = 120;
    const int rows = 80;
    const World world = makeSmash(columns, rows);
    ASSERT_EQ(world.bodies.size(), 1u + columns * rows);
    EXPECT_EQ(countFixed(world), 0u);
    EXPECT_EQ(world.settings.gravity, Vec2::Zero());
    const Body& block = world.bodies[0];
    EXPECT_EQ(std::get<Box>(block.shape), (Box{8, 8}));
    EXPECT_EQ(block.mass, 8 * 64); // 64 m² at 8 kg/m²
    EXPECT_EQ(block.state.velocity, Vec2(40, 0));
    EXPECT_EQ(block.state.position, Vec2(-20, 0));
    const WorldShape front = worldShape(block);
    for (std::size_t i = 1; i < world.bodies.size(); ++i) {
        const Body& box = world.bodies[i];
        EXPECT_EQ(std::get<Box>(box.shape), (Box{0.4, 0.4}));
        EXPECT_NEAR(box.mass, 0.16, 1e-15);
        EXPECT_EQ(box.state.velocity, Vec2::Zero());
        EXPECT_GE(worldShape(box).lower.x(), 29.8 - kGridRounding);
    }
    // The block's front face meets the wall after (29.8 − (−16)) m / 40 m/s, about 1.15 s.
    EXPECT_NEAR((29.8 - front.upper.x()) / 40, 1.145, 1e-12);
    // The wall's boxes touch their neighbours and overlap none.
    std::size_t touching = 0;
    for (const Contact& contact : closePairs(world)) {
        ASSERT_GE(contact.separation, -kGridRounding)
            << world.bodies[contact.a].name << " overlaps " << world.bodies[contact.b].name;
        if (std::abs(contact.separation) <= kGridRounding)
            ++touching;
    }
    // Every pair of side or top neighbours touches: (columns − 1)·rows + columns·(rows − 1).
    EXPECT_GE(touching, static_cast<std::size_t>((columns - 1) * rows + columns * (rows - 1)));
}

TEST(ExampleScenes, SpinnerStirsItsBodiesInsideAClosedRing)
{
    const int count = 6076;
    const World world = makeSpinner(count);
    const std::size_t ring = 360;
    ASSERT_EQ(world.bodies.size(), ring + 1 + count);
    EXPECT_EQ(countFixed(world), ring + 1);
    const Vec2 centre(0, 32);

    // The ring: 360 blocks whose inner faces are chords of the 40 m circle, each touching the
    // next (the last touches the first), none rotating.
    for (std::size_t i = 0; i < ring; ++i) {
        const Body& block = world.bodies[i];
        ASSERT_TRUE(block.fixed);
        EXPECT_EQ(block.state.angularVelocity, 0);
        ASSERT_EQ(block.geometry.convexPieces.size(), 1u);
        const std::vector<Vec2>& piece = block.geometry.convexPieces[0];
        ASSERT_EQ(piece.size(), 4u);
        Scalar nearest = std::numeric_limits<Scalar>::infinity();
        for (const Vec2& v : piece)
            nearest = std::min(nearest, (block.worldPoint(v) - centre).norm());
        EXPECT_NEAR(nearest, 40, 1e-12) << block.name;
        const Scalar gap = separation(worldShape(block), worldShape(world.bodies[(i + 1) % ring]));
        EXPECT_NEAR(gap, 0, 1e-12) << block.name;
        EXPECT_EQ(block.material.friction, 0.1);
    }

    // The arm: fixed, frictionless, turning about its own centre at 5 rad/s.
    const Body& arm = world.bodies[ring];
    EXPECT_TRUE(arm.fixed);
    EXPECT_EQ(arm.state.position, Vec2(0, 12));
    EXPECT_EQ(arm.state.velocity, Vec2::Zero());
    EXPECT_EQ(arm.state.angularVelocity, kSpinnerAngularVelocity);
    EXPECT_EQ(arm.material.friction, 0);
    EXPECT_EQ(std::get<Box>(arm.shape), (Box{1.2, 40.4}));

    // The bodies: capsule, circle, square in turn, 0.25 kg/m², all inside the ring.
    for (std::size_t n = 0; n < static_cast<std::size_t>(count); ++n) {
        const Body& body = world.bodies[ring + 1 + n];
        EXPECT_FALSE(body.fixed);
        EXPECT_EQ(body.density(), 0.25);
        EXPECT_NEAR(body.mass, 0.25 * body.area, 1e-15);
        EXPECT_EQ(body.material.friction, 0.1);
        EXPECT_EQ(body.material.restitution, 0.1);
        switch (n % 3) {
        case 0: {
            const std::vector<Vec2>& octagon = std::get<Polygon>(body.shape).vertices;
            ASSERT_EQ(octagon.size(), 8u) << "Box2D takes at most 8 vertices";
            EXPECT_TRUE(isConvex(octagon));
            // Inscribed in the capsule: every vertex 0.25 m from the segment (−0.25, 0)–(0.25, 0).
            for (const Vec2& v : octagon) {
                const Vec2 nearest(std::clamp(v.x(), -0.25, 0.25), 0);
                EXPECT_NEAR((v - nearest).norm(), 0.25, 1e-15);
            }
            break;
        }
        case 1:
            EXPECT_EQ(std::get<Circle>(body.shape).radius, 0.35);
            break;
        default:
            EXPECT_EQ(std::get<Box>(body.shape), (Box{0.7, 0.7}));
        }
        const WorldShape shape = worldShape(body);
        for (const Vec2& corner : {shape.lower, shape.upper, Vec2(shape.lower.x(), shape.upper.y()),
                                   Vec2(shape.upper.x(), shape.lower.y())})
            EXPECT_LT((corner - centre).norm(), 40) << body.name;
    }
    // v3's grid: 92 to a row from (−23, 2) m on a 0.5 m pitch (a capsule's centroid lies on its
    // grid point up to rounding).
    EXPECT_NEAR((world.bodies[ring + 1].state.position - Vec2(-23, 2)).norm(), 0, 1e-15);
    EXPECT_EQ(world.bodies[ring + 1 + 91].state.position, Vec2(22.5, 2));
    EXPECT_EQ(world.bodies[ring + 1 + 92].state.position, Vec2(-23, 2.5));
}

TEST(ExampleScenes, TumblerHoldsItsBoxesInsideFourWallsAroundThePivot)
{
    const int gridCount = 45;
    const World world = makeTumbler(gridCount);
    ASSERT_EQ(world.bodies.size(), 4u + gridCount * gridCount);
    EXPECT_EQ(countFixed(world), 4u);
    const Vec2 pivot(0, kTumblerPivotHeight);
    Vec2 insideLower = Vec2::Constant(-std::numeric_limits<Scalar>::infinity());
    Vec2 insideUpper = -insideLower;
    for (std::size_t i = 0; i < 4; ++i) {
        ASSERT_TRUE(world.bodies[i].fixed);
        const WorldShape wall = worldShape(world.bodies[i]);
        if (wall.upper.y() < pivot.y())
            insideLower.y() = wall.upper.y();
        else if (wall.lower.y() > pivot.y())
            insideUpper.y() = wall.lower.y();
        else if (wall.upper.x() < 0)
            insideLower.x() = wall.upper.x();
        else
            insideUpper.x() = wall.lower.x();
    }
    // v3's container: 19 m inside, centred on the pivot.
    EXPECT_EQ(insideLower, Vec2(pivot - Vec2(9.5, 9.5)));
    EXPECT_EQ(insideUpper, Vec2(pivot + Vec2(9.5, 9.5)));
    for (std::size_t i = 4; i < world.bodies.size(); ++i) {
        const Body& body = world.bodies[i];
        ASSERT_EQ(std::get<Box>(body.shape), (Box{0.25, 0.25}));
        const WorldShape box = worldShape(body);
        EXPECT_GT(box.lower.x(), insideLower.x());
        EXPECT_GT(box.lower.y(), insideLower.y());
        EXPECT_LT(box.upper.x(), insideUpper.x());
        EXPECT_LT(box.upper.y(), insideUpper.y());
    }
    EXPECT_NEAR((world.bodies[4].state.position - Vec2(-9, 1)).norm(), 0, 1e-14);
    expectNoOverlap(world);
}

TEST(ExampleScenes, JointGridHangsFromSevenFixedDiscsByPinsBetweenNeighbours)
{
    const int size = 100;
    const World world = makeJointGrid(size);
    ASSERT_EQ(world.bodies.size(), static_cast<std::size_t>(size * size));
    ASSERT_EQ(world.joints.size(), static_cast<std::size_t>(2 * size * (size - 1)));
    EXPECT_EQ(countFixed(world), 7u);
    for (int k = 0; k < size; ++k) {
        for (int i = 0; i < size; ++i) {
            const Body& disc = world.bodies[static_cast<std::size_t>(k * size + i)];
            EXPECT_EQ(disc.state.position, Vec2(k, -i));
            EXPECT_EQ(std::get<Circle>(disc.shape).radius, 0.4);
            EXPECT_EQ(disc.fixed, i == 0 && k >= 47 && k <= 53) << disc.name;
        }
    }
    for (const Joint& joint : world.joints) {
        EXPECT_EQ(joint.type, JointType::Pin);
        ASSERT_TRUE(joint.bodyB.has_value());
        const Body& a = world.body(joint.bodyA);
        const Body& b = world.body(*joint.bodyB);
        // Neighbours, pinned halfway between their centres, and both anchors on that point.
        EXPECT_EQ((b.state.position - a.state.position).norm(), 1);
        EXPECT_EQ(joint.worldAnchor, Vec2((a.state.position + b.state.position) / 2));
        EXPECT_EQ(a.worldPoint(joint.anchorA), joint.worldAnchor);
        EXPECT_EQ(b.worldPoint(joint.anchorB), joint.worldAnchor);
        EXPECT_LT(joint.bodyA, *joint.bodyB);
    }
    expectNoOverlap(world);
}

// ---- Small scenes --------------------------------------------------------------------------------

TEST(ExampleScenes, NewtonsCradleBallsTouchInARowAndTheFirstMoves)
{
    const World world = makeNewtonsCradle(5, 2.0);
    ASSERT_EQ(world.bodies.size(), 5u);
    EXPECT_EQ(world.settings.gravity, Vec2::Zero());
    for (std::size_t i = 0; i < 5; ++i) {
        const Body& ball = world.bodies[i];
        EXPECT_FALSE(ball.fixed);
        EXPECT_EQ(ball.material.restitution, 1);
        EXPECT_EQ(ball.material.friction, 0);
        EXPECT_EQ(ball.state.position.y(), 0);
        EXPECT_EQ(ball.state.velocity, i == 0 ? Vec2(2, 0) : Vec2::Zero());
    }
    // Neighbours touch (distance of centres = sum of radii, exactly), no one overlaps.
    for (std::size_t i = 0; i + 1 < 5; ++i) {
        EXPECT_EQ(separation(worldShape(world.bodies[i]), worldShape(world.bodies[i + 1])), 0);
        EXPECT_LT(world.bodies[i].state.position.x(), world.bodies[i + 1].state.position.x());
    }
    expectNoOverlap(world);
}

TEST(ExampleScenes, BoxStackRestsExactlyOnItsGround)
{
    const World world = makeBoxStack(10);
    ASSERT_EQ(world.bodies.size(), 11u);
    EXPECT_TRUE(world.bodies[0].fixed);
    EXPECT_EQ(worldShape(world.bodies[0]).upper.y(), 0);
    for (std::size_t i = 1; i < world.bodies.size(); ++i) {
        EXPECT_FALSE(world.bodies[i].fixed);
        EXPECT_EQ(separation(worldShape(world.bodies[i - 1]), worldShape(world.bodies[i])), 0);
        EXPECT_EQ(world.bodies[i].state.position, Vec2(0, static_cast<Scalar>(i) - 0.5));
    }
    expectNoOverlap(world);
}

TEST(ExampleScenes, OptionsReachEveryBodyAndTheWorld)
{
    const SceneOptions options{.friction = 0.3, .restitution = 0.2, .timeStep = 1.0 / 60};
    for (const World& world : {makePyramid(5, options), makePyramidGrid(2, 2, 3, options),
                               makePolygonRain(20, 1, options), makeRotatingBoxWithCircles(20, options),
                               makeSmash(3, 2, options), makeSpinner(20, options), makeTumbler(4, options),
                               makeJointGrid(8, options), makeNewtonsCradle(3, 1, options),
                               makeBoxStack(3, options)}) {
        EXPECT_EQ(world.settings.timeStep, 1.0 / 60);
        for (const Body& body : world.bodies) {
            // The spinner's arm is frictionless whatever the options say (as in Box2D v3).
            if (body.name != "arm") {
                EXPECT_EQ(body.material.friction, 0.3) << body.name;
            }
            EXPECT_EQ(body.material.restitution, 0.2) << body.name;
        }
    }
}

TEST(ExampleScenes, BuildersAreDeterministic)
{
    EXPECT_EQ(makePyramid(20), makePyramid(20));
    EXPECT_EQ(makePyramidGrid(3, 2, 5), makePyramidGrid(3, 2, 5));
    EXPECT_EQ(makePolygonRain(300, 42), makePolygonRain(300, 42));
    EXPECT_EQ(makeRotatingBoxWithCircles(300), makeRotatingBoxWithCircles(300));
    EXPECT_EQ(makeSmash(10, 8), makeSmash(10, 8));
    EXPECT_EQ(makeSpinner(200), makeSpinner(200));
    EXPECT_EQ(makeTumbler(10), makeTumbler(10));
    EXPECT_EQ(makeJointGrid(10), makeJointGrid(10));
    EXPECT_EQ(makeNewtonsCradle(), makeNewtonsCradle());
    EXPECT_EQ(makeBoxStack(), makeBoxStack());
}

TEST(ExampleScenes, BodyNamesAreUnique)
{
    for (const World& world : {makePyramidGrid(3, 2, 4), makePolygonRain(50, 1), makeRotatingBoxWithCircles(50),
                               makeSmash(4, 3), makeSpinner(50), makeTumbler(5), makeJointGrid(6)}) {
        std::vector<std::string> names;
        for (const Body& body : world.bodies) {
            EXPECT_FALSE(body.name.empty());
            names.push_back(body.name);
        }
        std::sort(names.begin(), names.end());
        EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end());
    }
}

} // namespace
} // namespace impetus::model
