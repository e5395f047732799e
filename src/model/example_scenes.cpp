#include "model/example_scenes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
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
constexpr Scalar kTumblerCircleRadius = 0.25;
constexpr Scalar kTumblerPitch = 0.6;
constexpr Scalar kTumblerRoom = 1.5;

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

/// Appends a body with everything derived. Names are unique because every caller numbers them.
void addBody(World& world, std::string name, Shape shape, const Vec2& position, bool fixed,
             const SceneOptions& options)
{
    Body body;
    body.name = std::move(name);
    body.shape = std::move(shape);
    body.state.position = position;
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
    const Scalar gridSide = columns * kTumblerPitch;
    // Whole metres, so that the walls' coordinates are exact.
    const Scalar halfInside = std::ceil(kTumblerRoom * gridSide / 2);
    const Scalar wallCentre = halfInside + kWallThickness / 2;
    const Scalar outside = 2 * (halfInside + kWallThickness);

    // The bottom and top walls run the full outside width, the side walls fit between them, so
    // the four meet at the corners without overlapping.
    addBody(world, "bottom wall", Box{outside, kWallThickness}, Vec2(0, -wallCentre), true, options);
    addBody(world, "right wall", Box{kWallThickness, 2 * halfInside}, Vec2(wallCentre, 0), true, options);
    addBody(world, "top wall", Box{outside, kWallThickness}, Vec2(0, wallCentre), true, options);
    addBody(world, "left wall", Box{kWallThickness, 2 * halfInside}, Vec2(-wallCentre, 0), true, options);

    const Scalar first = -(columns - 1) * kTumblerPitch / 2;
    for (int n = 0; n < circles; ++n) {
        const Vec2 position(first + (n % columns) * kTumblerPitch, first + (n / columns) * kTumblerPitch);
        addBody(world, "circle" + std::to_string(n), Circle{kTumblerCircleRadius}, position, false, options);
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
