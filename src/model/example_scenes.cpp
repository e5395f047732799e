#include "model/example_scenes.h"

#include "model/pin_anchors.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace impetus::model {

namespace {

/// Side of every stacked box, m. Box2D's benchmarks use 1 m boxes (half-extent 0.5).
constexpr Scalar kBoxSize = 1.0;

/// Thickness of grounds and container walls, m.
constexpr Scalar kWallThickness = 1.0;

/// Gap between neighbouring pyramids of makePyramidGrid, m, and clearance above each one's top.
constexpr Scalar kPyramidGap = 2.0;

/// Polygon rain: grid cell (one polygon each), m, and the widest grid, cells.
constexpr Scalar kRainCell = 1.0;
constexpr int kRainColumns = 40;
/// Polygon rain: the circle the vertices lie on has a radius in [kRainMinRadius, kRainMaxRadius), m.
constexpr Scalar kRainMinRadius = 0.15;
constexpr Scalar kRainMaxRadius = 0.4;
/// Polygon rain: the vertex count is drawn from kRainMinVertices … kRainMaxVertices. Eight is the
/// most Box2D accepts in one polygon, so the benchmark needs no splitting.
constexpr int kRainMinVertices = 3;
constexpr int kRainMaxVertices = 8;
/// Polygon rain: each vertex angle is jittered by up to this fraction of the even spacing 2π/k.
/// Below 0.5 keeps consecutive vertices at least half a spacing apart (no slivers, no near
/// duplicates) and every gap below π, so the circle's centre stays inside the polygon.
constexpr Scalar kRainAngleJitter = 0.4;

/// Rotating box: circle radius and grid pitch, m, and the container's inside side as a multiple of
/// the grid's side (room for the circles to tumble).
constexpr Scalar kRotatingBoxCircleRadius = 0.25;
constexpr Scalar kRotatingBoxPitch = 0.6;
constexpr Scalar kRotatingBoxRoom = 1.5;

// Box2D v3's scenes (its shared/benchmarks.c), with its sizes.

/// Smash: the block's side (m), density (kg/m²), start x (m) and speed along +x (m/s); the wall's
/// box side (m, also the grid pitch) and the x of its first column (m).
constexpr Scalar kSmashBlockSize = 8.0;
constexpr Scalar kSmashBlockDensity = 8.0;
constexpr Scalar kSmashBlockStartX = -20.0;
constexpr Scalar kSmashBlockSpeed = 40.0;
constexpr Scalar kSmashBoxSize = 0.4;
constexpr Scalar kSmashWallLeft = 30.0;

/// Spinner: the ring's segment count, radius (m) and centre height (m).
constexpr int kSpinnerRingSegments = 360;
constexpr Scalar kSpinnerRingRadius = 40.0;
constexpr Scalar kSpinnerRingCentreY = 32.0;
/// Spinner: the arm, v3's box of half extents 0.4 m × 20 m rounded by 0.2 m, as its full extent
/// (m), and the height of its centre, which is also its pivot (m).
constexpr Scalar kSpinnerArmWidth = 1.2;
constexpr Scalar kSpinnerArmLength = 40.4;
constexpr Scalar kSpinnerArmCentreY = 12.0;
/// Spinner: the bodies' density (kg/m²), the grid's pitch (m), its first cell (m) and its width
/// in cells: x runs from −23 m in steps of 0.5 m while below 23 m.
constexpr Scalar kSpinnerDensity = 0.25;
constexpr Scalar kSpinnerPitch = 0.5;
constexpr Scalar kSpinnerGridLeft = -23.0;
constexpr Scalar kSpinnerGridBottom = 2.0;
constexpr int kSpinnerColumns = 92;
/// Spinner: the capsule (a segment of half length kSpinnerCapsuleHalfLength swept by a disc of
/// radius kSpinnerCapsuleRadius, m) as an octagon: each cap is a half polygon of
/// kSpinnerCapSegments edges inscribed in its half circle. Three keeps the octagon within Box2D's
/// 8 vertices per polygon.
constexpr Scalar kSpinnerCapsuleHalfLength = 0.25;
constexpr Scalar kSpinnerCapsuleRadius = 0.25;
constexpr int kSpinnerCapSegments = 3;
/// Spinner: the circle's radius and the square's side, m.
constexpr Scalar kSpinnerCircleRadius = 0.35;
constexpr Scalar kSpinnerSquareSize = 0.7;
/// Spinner: the bodies come in turn as a capsule, a circle and a square.
constexpr int kSpinnerShapeKinds = 3;

/// Tumbler: the container's inside half side (m), the boxes' side (m) and their grid pitch (m).
constexpr Scalar kTumblerHalfInside = 9.5;
constexpr Scalar kTumblerBoxSize = 0.25;
constexpr Scalar kTumblerPitch = 0.4;

/// Joint grid: the discs' radius (m), the grid pitch (m), and how many fixed discs lie on each
/// side of the middle one in the top row.
constexpr Scalar kJointGridRadius = 0.4;
constexpr Scalar kJointGridPitch = 1.0;
constexpr int kJointGridFixedHalfWidth = 3;

/// Radius of the cradle's balls, m.
constexpr Scalar kCradleRadius = 0.5;

/// Width of makeBoxStack's ground, m.
constexpr Scalar kStackGroundWidth = 10.0;

/// Fixed scenery is drawn in the same neutral grey the scene loader gives a fixed body without a
/// colour, so built and loaded scenes look alike.
constexpr Color kFixedColor{0x7a, 0x7f, 0x87};

World makeWorld(const SceneOptions& options)
{
    World world;
    world.settings.integrator = IntegratorKind::SemiImplicitEuler;
    world.settings.timeStep = options.timeStep;
    return world;
}

/// Appends a body with everything derived, of `density` kg/m² (the default 1 unless given).
/// Names are unique because every caller numbers them.
void addBody(World& world, std::string name, Shape shape, const Vec2& position, bool fixed,
             const SceneOptions& options, Scalar density = MassSpec{}.value)
{
    Body body;
    body.name = std::move(name);
    body.shape = std::move(shape);
    body.state.position = position;
    body.massSpec = MassSpec{MassMode::Density, density};
    body.material = Material{options.restitution, options.friction};
    body.fixed = fixed;
    if (fixed)
        body.color = kFixedColor;
    body.updateDerived();
    world.bodies.push_back(std::move(body));
}

/// Adds one pyramid whose bottom row rests on y = floorTop, centred on x = centreX. Every
/// coordinate is a multiple of 0.5 m, exact in binary, so rows rest on each other with a gap of
/// exactly 0, not 1e-16.
void addPyramid(World& world, int base, Scalar centreX, Scalar floorTop, const std::string& prefix,
                const SceneOptions& options)
{
    for (int row = 0; row < base; ++row) {
        const int count = base - row;
        const Scalar y = floorTop + (row + 0.5) * kBoxSize;
        const Scalar left = centreX - (count - 1) * kBoxSize / 2;
        for (int i = 0; i < count; ++i) {
            addBody(world, prefix + std::to_string(row) + "_" + std::to_string(i), Box{kBoxSize, kBoxSize},
                    Vec2(left + i * kBoxSize, y), false, options);
        }
    }
}

/// A uniform number in [0, 1) from one 32-bit output of the generator. std::mt19937's outputs are
/// fixed by the standard, but std::uniform_real_distribution's mapping is not, so the mapping is
/// spelled out here: the 32 bits over 2³², exact in a double.
Scalar unitInterval(std::mt19937& random)
{
    return static_cast<Scalar>(random()) / 4294967296.0;
}

/// A whole number in [low, high] from one output of the generator. The modulo bias is below 1e-9
/// for these small ranges, and unlike std::uniform_int_distribution it is the same everywhere.
int integerIn(std::mt19937& random, int low, int high)
{
    const auto span = static_cast<std::uint32_t>(high - low + 1);
    return low + static_cast<int>(static_cast<std::uint32_t>(random()) % span);
}

/// A convex polygon with k vertices on a circle of the given radius about the origin,
/// counter-clockwise. Points on a circle are always in convex position, and the jittered even
/// spacing keeps them apart, so the polygon is valid by construction.
std::vector<Vec2> randomConvexPolygon(std::mt19937& random)
{
    const int k = integerIn(random, kRainMinVertices, kRainMaxVertices);
    const Scalar radius = kRainMinRadius + (kRainMaxRadius - kRainMinRadius) * unitInterval(random);
    const Scalar spacing = 2 * std::numbers::pi / k;
    const Scalar phase = spacing * unitInterval(random);
    std::vector<Vec2> vertices;
    vertices.reserve(static_cast<std::size_t>(k));
    for (int i = 0; i < k; ++i) {
        const Scalar angle = phase + spacing * (i + kRainAngleJitter * unitInterval(random));
        vertices.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
    }
    return vertices;
}

/// Appends a polygon body whose vertices are given in world coordinates relative to `origin`:
/// the body's position becomes its centroid, origin + centroidOffset.
void addPolygonAt(World& world, std::string name, std::vector<Vec2> vertices, const Vec2& origin, bool fixed,
                  const SceneOptions& options, Scalar density = MassSpec{}.value)
{
    addBody(world, std::move(name), Polygon{std::move(vertices)}, origin, fixed, options, density);
    Body& body = world.bodies.back();
    body.state.position = origin + body.geometry.centroidOffset;
}

/// The convex polygon inscribed in a capsule along x (a segment from −halfLength to +halfLength
/// swept by a disc of `radius`), counter-clockwise: each cap is a half polygon of `capSegments`
/// edges, its vertices on the cap's half circle.
std::vector<Vec2> capsulePolygon(Scalar halfLength, Scalar radius, int capSegments)
{
    std::vector<Vec2> vertices;
    const Scalar step = std::numbers::pi / capSegments;
    // The right cap from straight down to straight up, then the left cap from up to down.
    for (int i = 0; i <= capSegments; ++i) {
        const Scalar angle = -std::numbers::pi / 2 + i * step;
        vertices.emplace_back(halfLength + radius * std::cos(angle), radius * std::sin(angle));
    }
    for (int i = 0; i <= capSegments; ++i) {
        const Scalar angle = std::numbers::pi / 2 + i * step;
        vertices.emplace_back(-halfLength + radius * std::cos(angle), radius * std::sin(angle));
    }
    return vertices;
}

/// A pin joint between bodies a and b at the world point `anchor`, with its anchors in the
/// bodies' frames as a scene file's loader derives them.
Joint pinJoint(const World& world, std::uint32_t a, std::uint32_t b, const Vec2& anchor)
{
    Joint joint;
    joint.type = JointType::Pin;
    joint.bodyA = BodyId{a};
    joint.bodyB = BodyId{b};
    joint.worldAnchor = anchor;
    derivePinAnchors(world, joint);
    return joint;
}

} // namespace

World makePyramid(int base, const SceneOptions& options)
{
    World world = makeWorld(options);
    const Scalar groundWidth = 2 * base * kBoxSize;
    addBody(world, "ground", Box{groundWidth, kWallThickness}, Vec2(0, -kWallThickness / 2), true, options);
    addPyramid(world, base, 0, 0, "box", options);
    return world;
}

World makePyramidGrid(int countX, int countY, int base, const SceneOptions& options)
{
    World world = makeWorld(options);
    const Scalar pitchX = base * kBoxSize + kPyramidGap;
    const Scalar pitchY = base * kBoxSize + kWallThickness + kPyramidGap;
    // Each ground reaches half a gap beyond the outermost pyramids.
    const Scalar groundWidth = countX * pitchX;
    for (int row = 0; row < countY; ++row) {
        addBody(world, "ground" + std::to_string(row), Box{groundWidth, kWallThickness},
                Vec2(0, row * pitchY - kWallThickness / 2), true, options);
    }
    for (int row = 0; row < countY; ++row) {
        for (int column = 0; column < countX; ++column) {
            const Scalar centreX = (column - (countX - 1) / 2.0) * pitchX;
            const std::string prefix = "pyramid" + std::to_string(row * countX + column) + "_box";
            addPyramid(world, base, centreX, row * pitchY, prefix, options);
        }
    }
    return world;
}

World makePolygonRain(int count, unsigned seed, const SceneOptions& options)
{
    World world = makeWorld(options);
    const int columns = std::max(1, std::min(count, kRainColumns));
    const int rows = (count + columns - 1) / columns;
    const Scalar gridWidth = columns * kRainCell;
    const Scalar gridBottom = 1.0; // the lowest row's cells start 1 m above the floor
    const Scalar wallHeight = gridBottom + rows * kRainCell + 1.0;
    const Scalar inside = gridWidth + 2.0; // 1 m clear of the grid on each side
    const Scalar floorWidth = inside + 2 * kWallThickness;

    addBody(world, "floor", Box{floorWidth, kWallThickness}, Vec2(0, -kWallThickness / 2), true, options);
    const Scalar wallX = (inside + kWallThickness) / 2;
    addBody(world, "left wall", Box{kWallThickness, wallHeight}, Vec2(-wallX, wallHeight / 2), true, options);
    addBody(world, "right wall", Box{kWallThickness, wallHeight}, Vec2(wallX, wallHeight / 2), true, options);

    std::mt19937 random(seed);
    for (int n = 0; n < count; ++n) {
        const int row = n / columns;
        const int column = n % columns;
        const Vec2 cellCentre(-gridWidth / 2 + (column + 0.5) * kRainCell, gridBottom + (row + 0.5) * kRainCell);
        addBody(world, "polygon" + std::to_string(n), Polygon{randomConvexPolygon(random)}, cellCentre, false,
                options);
        // The body's position is its centroid, which is not the circle's centre the vertices were
        // drawn about. Placing the centroid at cellCentre + centroidOffset puts the circle's centre
        // on the cell centre, so the polygon stays inside its cell and never touches a neighbour.
        Body& body = world.bodies.back();
        body.state.position = cellCentre + body.geometry.centroidOffset;
    }
    return world;
}

World makeRotatingBoxWithCircles(int circles, const SceneOptions& options)
{
    World world = makeWorld(options);
    const int columns = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<Scalar>(circles)))));
    const Scalar gridSide = columns * kRotatingBoxPitch;
    // Whole metres, so that the walls' coordinates are exact.
    const Scalar halfInside = std::ceil(kRotatingBoxRoom * gridSide / 2);
    const Scalar wallCentre = halfInside + kWallThickness / 2;
    const Scalar outside = 2 * (halfInside + kWallThickness);

    // The bottom and top walls run the full outside width, the side walls fit between them, so
    // the four meet at the corners without overlapping.
    addBody(world, "bottom wall", Box{outside, kWallThickness}, Vec2(0, -wallCentre), true, options);
    addBody(world, "right wall", Box{kWallThickness, 2 * halfInside}, Vec2(wallCentre, 0), true, options);
    addBody(world, "top wall", Box{outside, kWallThickness}, Vec2(0, wallCentre), true, options);
    addBody(world, "left wall", Box{kWallThickness, 2 * halfInside}, Vec2(-wallCentre, 0), true, options);

    const Scalar first = -(columns - 1) * kRotatingBoxPitch / 2;
    for (int n = 0; n < circles; ++n) {
        const Vec2 position(first + (n % columns) * kRotatingBoxPitch, first + (n / columns) * kRotatingBoxPitch);
        addBody(world, "circle" + std::to_string(n), Circle{kRotatingBoxCircleRadius}, position, false, options);
    }
    return world;
}

void spinFixedBodies(World& world, const Vec2& pivot, Scalar angularVelocity)
{
    for (Body& body : world.bodies) {
        if (!body.fixed)
            continue;
        body.state.velocity = cross(angularVelocity, Vec2(body.state.position - pivot));
        body.state.angularVelocity = angularVelocity;
    }
}

World makeSmash(int columns, int rows, const SceneOptions& options)
{
    World world = makeWorld(options);
    world.settings.gravity = Vec2::Zero();
    addBody(world, "block", Box{kSmashBlockSize, kSmashBlockSize}, Vec2(kSmashBlockStartX, 0), false, options,
            kSmashBlockDensity);
    world.bodies.back().state.velocity = Vec2(kSmashBlockSpeed, 0);
    for (int i = 0; i < columns; ++i) {
        for (int j = 0; j < rows; ++j) {
            const Vec2 position(kSmashWallLeft + i * kSmashBoxSize, (j - rows / 2.0) * kSmashBoxSize);
            addBody(world, "box" + std::to_string(i) + "_" + std::to_string(j), Box{kSmashBoxSize, kSmashBoxSize},
                    position, false, options);
        }
    }
    return world;
}

World makeSpinner(int count, const SceneOptions& options)
{
    World world = makeWorld(options);

    // The ring: the chain's points clockwise from angle 0, as v3 lays them out; block n lies
    // outside the segment from point n to point n + 1, listed counter-clockwise.
    const Vec2 centre(0, kSpinnerRingCentreY);
    const auto ringPoint = [&](int n, Scalar radius) {
        const Scalar angle = -2 * std::numbers::pi * n / kSpinnerRingSegments;
        return Vec2(centre + radius * Vec2(std::cos(angle), std::sin(angle)));
    };
    for (int n = 0; n < kSpinnerRingSegments; ++n) {
        const Vec2 inner0 = ringPoint(n, kSpinnerRingRadius);
        const Vec2 inner1 = ringPoint(n + 1, kSpinnerRingRadius);
        const Vec2 outer0 = ringPoint(n, kSpinnerRingRadius + kWallThickness);
        const Vec2 outer1 = ringPoint(n + 1, kSpinnerRingRadius + kWallThickness);
        addPolygonAt(world, "ring" + std::to_string(n), {Vec2::Zero(), outer1 - inner1, outer0 - inner1, inner0 - inner1},
                     inner1, true, options);
    }

    SceneOptions armOptions = options;
    armOptions.friction = 0;
    addBody(world, "arm", Box{kSpinnerArmWidth, kSpinnerArmLength}, Vec2(0, kSpinnerArmCentreY), true, armOptions);
    world.bodies.back().state.angularVelocity = kSpinnerAngularVelocity;

    const std::vector<Vec2> capsule =
        capsulePolygon(kSpinnerCapsuleHalfLength, kSpinnerCapsuleRadius, kSpinnerCapSegments);
    for (int n = 0; n < count; ++n) {
        const Vec2 position(kSpinnerGridLeft + (n % kSpinnerColumns) * kSpinnerPitch,
                            kSpinnerGridBottom + (n / kSpinnerColumns) * kSpinnerPitch);
        std::string name = "body" + std::to_string(n);
        switch (n % kSpinnerShapeKinds) {
        case 0:
            addPolygonAt(world, std::move(name), capsule, position, false, options, kSpinnerDensity);
            break;
        case 1:
            addBody(world, std::move(name), Circle{kSpinnerCircleRadius}, position, false, options, kSpinnerDensity);
            break;
        default:
            addBody(world, std::move(name), Box{kSpinnerSquareSize, kSpinnerSquareSize}, position, false, options,
                    kSpinnerDensity);
        }
    }
    return world;
}

World makeTumbler(int gridCount, const SceneOptions& options)
{
    World world = makeWorld(options);
    const Scalar pivotY = kTumblerPivotHeight;
    const Scalar wallCentre = kTumblerHalfInside + kWallThickness / 2;
    const Scalar outside = 2 * (kTumblerHalfInside + kWallThickness);
    const Scalar inside = 2 * kTumblerHalfInside;
    addBody(world, "bottom wall", Box{outside, kWallThickness}, Vec2(0, pivotY - wallCentre), true, options);
    addBody(world, "right wall", Box{kWallThickness, inside}, Vec2(wallCentre, pivotY), true, options);
    addBody(world, "top wall", Box{outside, kWallThickness}, Vec2(0, pivotY + wallCentre), true, options);
    addBody(world, "left wall", Box{kWallThickness, inside}, Vec2(-wallCentre, pivotY), true, options);

    const Scalar first = -kTumblerPitch / 2 * gridCount;
    for (int row = 0; row < gridCount; ++row) {
        for (int column = 0; column < gridCount; ++column) {
            const Vec2 position(first + column * kTumblerPitch, pivotY + first + row * kTumblerPitch);
            addBody(world, "box" + std::to_string(row) + "_" + std::to_string(column),
                    Box{kTumblerBoxSize, kTumblerBoxSize}, position, false, options);
        }
    }
    return world;
}

World makeJointGrid(int size, const SceneOptions& options)
{
    World world = makeWorld(options);
    const int middle = size / 2;
    for (int k = 0; k < size; ++k) {
        for (int i = 0; i < size; ++i) {
            const bool fixed = i == 0 && std::abs(k - middle) <= kJointGridFixedHalfWidth;
            addBody(world, "disc" + std::to_string(k) + "_" + std::to_string(i), Circle{kJointGridRadius},
                    Vec2(k * kJointGridPitch, -i * kJointGridPitch), fixed, options);
            const auto index = static_cast<std::uint32_t>(world.bodies.size() - 1);
            const Vec2 position = world.bodies.back().state.position;
            if (i > 0)
                world.joints.push_back(pinJoint(world, index - 1, index, position + Vec2(0, kJointGridPitch / 2)));
            if (k > 0) {
                world.joints.push_back(pinJoint(world, index - static_cast<std::uint32_t>(size), index,
                                                position - Vec2(kJointGridPitch / 2, 0)));
            }
        }
    }
    return world;
}

World makeNewtonsCradle(int balls, Scalar speed, const SceneOptions& options)
{
    World world = makeWorld(options);
    world.settings.gravity = Vec2::Zero();
    for (int n = 0; n < balls; ++n) {
        addBody(world, "ball" + std::to_string(n), Circle{kCradleRadius}, Vec2(2 * kCradleRadius * n, 0), false,
                options);
    }
    if (!world.bodies.empty())
        world.bodies.front().state.velocity = Vec2(speed, 0);
    return world;
}

World makeBoxStack(int count, const SceneOptions& options)
{
    World world = makeWorld(options);
    addBody(world, "ground", Box{kStackGroundWidth, kWallThickness}, Vec2(0, -kWallThickness / 2), true, options);
    for (int n = 0; n < count; ++n) {
        addBody(world, "box" + std::to_string(n), Box{kBoxSize, kBoxSize}, Vec2(0, (n + 0.5) * kBoxSize), false,
                options);
    }
    return world;
}

} // namespace impetus::model
