#include "soak/random_scene.h"

#include "controller/soft/soft_body_builder.h"
#include "controller/soft/soft_stability.h"
#include "model/scene_io.h"
#include "model/scene_warnings.h"
#include "soak/soak_constants.h"

#include <algorithm>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace impetus::soak {

namespace {

using model::Body;
using model::BodyId;
using model::World;

constexpr Scalar kTwoPi = 2 * std::numbers::pi;

// Shares of the draws. Chosen so that a couple of hundred scenes meet every kind several times.
constexpr Scalar kMassGivenShare = 0.5; ///< mass given as `mass`, else as `density`
constexpr Scalar kFastShare = 0.3; ///< a speed uniform up to kMaxSpeed
constexpr Scalar kWideSpeedShare = 0.3; ///< a speed log-uniform over four decades
constexpr Scalar kSlowSpeed = 5.0; ///< m/s: the rest are slow
constexpr Scalar kMinWideSpeed = 0.01; ///< m/s
constexpr Scalar kSoftShare = 0.35; ///< a scene with a soft body
constexpr Scalar kObstacleShare = 0.3; ///< a scene with a fixed obstacle inside
constexpr Scalar kDragShare = 0.2; ///< a scene with drag
constexpr Scalar kRestLengthGivenShare = 0.5; ///< a spring's rest length given, not the load-time one
constexpr Scalar kToWorldShare = 0.3; ///< a spring or joint to the world, not to a body
constexpr int kMaxSprings = 3;
constexpr int kMaxJoints = 3;
/// Convex polygons have 3 to this many vertices, stars twice 3 to kMaxStarPoints.
constexpr int kMaxConvexVertices = 8;
constexpr int kMaxStarPoints = 6;
/// Smallest angle between two neighbouring vertices of a convex polygon, rad: keeps vertices
/// apart (a sliver is legal, but the loader's job to judge, and the fuzzer's to test).
constexpr Scalar kMinVertexGap = 0.3;
/// A soft grid too stiff for its integrator has its stiffness divided by kSofteningFactor, at
/// most kMaxSoftening times (a factor of a million), before it is made rigid.
constexpr Scalar kSofteningFactor = 4;
constexpr int kMaxSoftening = 10;
/// An ellipse's or box's aspect ratio, at most.
constexpr Scalar kMaxAspect = 4.0;
/// Anchors lie within this fraction of the body's bounding radius from its centre.
constexpr Scalar kAnchorReach = 0.5;
/// A rest length given is this range times the load-time length.
constexpr Scalar kMinRestFactor = 0.5;
constexpr Scalar kMaxRestFactor = 1.5; ///< see kMinRestFactor

/// Shape kinds, so that each is drawn about equally often.
enum class ShapeKind { Circle, Ellipse, Box, ConvexPolygon, ConcavePolygon, Count };

Body makeWall(std::string name, Vec2 centre, Scalar width, Scalar height)
{
    Body wall;
    wall.name = std::move(name);
    wall.shape = model::Box{width, height};
    wall.state.position = centre;
    wall.fixed = true;
    wall.updateDerived();
    return wall;
}

/// A convex polygon with vertices on a circle of `radius` at sorted random angles.
model::Polygon convexPolygon(SceneRandom& random, Scalar radius)
{
    const int count = random.integer(3, kMaxConvexVertices);
    std::vector<Scalar> angles;
    for (;;) {
        angles.clear();
        for (int i = 0; i < count; ++i)
            angles.push_back(random.uniform(0, kTwoPi));
        std::sort(angles.begin(), angles.end());
        bool apart = kTwoPi - angles.back() + angles.front() >= kMinVertexGap;
        for (std::size_t i = 1; i < angles.size(); ++i)
            apart = apart && angles[i] - angles[i - 1] >= kMinVertexGap;
        if (apart)
            break;
    }
    model::Polygon polygon;
    for (const Scalar angle : angles)
        polygon.vertices.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
    return polygon;
}

/// A concave polygon: a star of 3 to kMaxStarPoints points, or an L.
model::Polygon concavePolygon(SceneRandom& random, Scalar radius)
{
    model::Polygon polygon;
    if (random.chance(0.5)) {
        const int points = random.integer(3, kMaxStarPoints);
        const Scalar inner = radius * random.uniform(0.3, 0.7);
        const Scalar turn = random.uniform(0, kTwoPi);
        for (int i = 0; i < 2 * points; ++i) {
            const Scalar angle = turn + kTwoPi * i / (2 * points);
            const Scalar r = i % 2 == 0 ? radius : inner;
            polygon.vertices.emplace_back(r * std::cos(angle), r * std::sin(angle));
        }
    } else {
        // An L in a square of side s centred on the origin, its arms t thick.
        const Scalar s = radius * std::numbers::sqrt2;
        const Scalar t = s * random.uniform(0.2, 0.6);
        const Scalar h = s / 2;
        polygon.vertices = {Vec2(-h, -h), Vec2(h, -h), Vec2(h, -h + t), Vec2(-h + t, -h + t), Vec2(-h + t, h),
                            Vec2(-h, h)};
    }
    return polygon;
}

/// A shape whose bounding circle has radius `radius` or less.
model::Shape randomShape(SceneRandom& random, Scalar radius)
{
    const auto kind = static_cast<ShapeKind>(random.integer(0, static_cast<int>(ShapeKind::Count) - 1));
    switch (kind) {
    case ShapeKind::Circle:
        return model::Circle{radius};
    case ShapeKind::Ellipse:
        return model::Ellipse{radius, radius / random.uniform(1, kMaxAspect)};
    case ShapeKind::Box: {
        // Half-diagonal = radius.
        const Scalar angle = std::atan(1 / random.uniform(1, kMaxAspect));
        return model::Box{2 * radius * std::cos(angle), 2 * radius * std::sin(angle)};
    }
    case ShapeKind::ConvexPolygon:
        return convexPolygon(random, radius);
    case ShapeKind::ConcavePolygon:
    case ShapeKind::Count:
        break;
    }
    model::Polygon polygon = concavePolygon(random, radius);
    // Either winding is legal.
    if (random.chance(0.5))
        std::reverse(polygon.vertices.begin(), polygon.vertices.end());
    return polygon;
}

Scalar randomSpeed(SceneRandom& random)
{
    if (random.chance(kFastShare))
        return random.uniform(0, kMaxSpeed);
    if (random.chance(kWideSpeedShare / (1 - kFastShare)))
        return random.logUniform(kMinWideSpeed, kMaxSpeed);
    return random.uniform(0, kSlowSpeed);
}

/// A dynamic body at `centre` with a shape, mass, motion and material drawn at random.
Body randomBody(SceneRandom& random, int index, Vec2 centre)
{
    Body body;
    body.name = "body-" + std::to_string(index);
    body.shape = randomShape(random, random.uniform(kMinBodyRadius, kMaxBodyRadius));
    body.state.position = centre;
    body.state.angle = random.uniform(0, kTwoPi);
    const Scalar direction = random.uniform(0, kTwoPi);
    body.state.velocity = randomSpeed(random) * Vec2(std::cos(direction), std::sin(direction));
    body.state.angularVelocity = random.uniform(-kMaxSpin, kMaxSpin);
    body.material.restitution = random.unit();
    body.material.friction = random.unit();
    body.updateDerived();
    const Scalar mass = random.logUniform(kMinMass, kMaxMass);
    body.massSpec = random.chance(kMassGivenShare) ? model::MassSpec{model::MassMode::Mass, mass}
                                                     : model::MassSpec{model::MassMode::Density, mass / body.area};
    body.updateDerived();
    return body;
}

/// A random point of `body`'s own frame near its centre, m.
Vec2 randomAnchor(SceneRandom& random, const Body& body)
{
    const Scalar reach = kAnchorReach * body.geometry.boundingRadius;
    return Vec2(random.uniform(-reach, reach), random.uniform(-reach, reach));
}

/// Reduced mass of the pair, or body A's mass for a link to the world, kg.
Scalar reducedMass(const World& world, BodyId a, std::optional<BodyId> b)
{
    const Scalar ma = world.body(a).mass;
    if (!b)
        return ma;
    const Scalar mb = world.body(*b).mass;
    return ma * mb / (ma + mb);
}

/// Two different dynamic bodies within the tested mass ratio (kMaxContactMassRatio), or one body
/// and the world; nothing when no such pair exists.
std::optional<std::pair<BodyId, std::optional<BodyId>>> randomLink(SceneRandom& random, const World& world,
                                                                   const std::vector<BodyId>& dynamic)
{
    const BodyId a = dynamic[static_cast<std::size_t>(random.integer(0, static_cast<int>(dynamic.size()) - 1))];
    if (random.chance(kToWorldShare))
        return std::make_pair(a, std::optional<BodyId>());
    std::vector<BodyId> partners;
    for (const BodyId b : dynamic) {
        const Scalar ratio = world.body(a).mass / world.body(b).mass;
        if (b != a && ratio <= constants::kMaxContactMassRatio && 1 / ratio <= constants::kMaxContactMassRatio)
            partners.push_back(b);
    }
    if (partners.empty())
        return std::nullopt;
    return std::make_pair(a, std::optional<BodyId>(
                                 partners[static_cast<std::size_t>(random.integer(0, static_cast<int>(partners.size()) - 1))]));
}

/// A world point near body `a`, inside the box, m.
Vec2 worldPointNear(SceneRandom& random, const Body& a)
{
    const Scalar reach = kCellSize / 2;
    Vec2 p = a.state.position + Vec2(random.uniform(-reach, reach), random.uniform(-reach, reach));
    p.x() = std::clamp(p.x(), -kBoxHalfWidth, kBoxHalfWidth);
    p.y() = std::clamp(p.y(), Scalar(0), kBoxHeight);
    return p;
}

/// Softens a spring too stiff, or too strongly damped, for the world's integrator at its step
/// (model::longestStableSpringStep, with the bodies' turns at the anchors): such a spring is
/// legal, but the program says it will blow up (model::sceneWarnings), so that outcome is
/// expected, not a finding. Its stiffness is scaled by s² and its damping by s, which scales every
/// rate of its motion by s and keeps its damping ratio, until its longest stable step is the
/// scene's over kSpringStableShare.
void keepSpringStable(const World& world, model::Spring& spring)
{
    const Scalar h = model::springIntegratorStep(world);
    const std::optional<Scalar> longest = model::longestStableSpringStep(world, spring);
    if (!longest || !(h > kSpringStableShare * *longest))
        return;
    const Scalar scale = kSpringStableShare * *longest / h;
    spring.stiffness *= scale * scale;
    spring.damping *= scale;
}

void addSprings(SceneRandom& random, World& world, const std::vector<BodyId>& dynamic)
{
    const int count = random.integer(0, kMaxSprings);
    for (int i = 0; i < count; ++i) {
        const auto link = randomLink(random, world, dynamic);
        if (!link)
            continue;
        model::Spring spring;
        spring.bodyA = link->first;
        spring.bodyB = link->second;
        spring.anchorA = randomAnchor(random, world.body(spring.bodyA));
        spring.anchorB = spring.bodyB ? randomAnchor(random, world.body(*spring.bodyB))
                                      : worldPointNear(random, world.body(spring.bodyA));
        const Scalar mu = reducedMass(world, spring.bodyA, spring.bodyB);
        const Scalar omega = random.uniform(1, kMaxSpringOmega);
        spring.stiffness = mu * omega * omega;
        spring.damping = 2 * random.uniform(0, kMaxSpringDampingRatio) * std::sqrt(spring.stiffness * mu);
        const Vec2 endA = world.body(spring.bodyA).worldPoint(spring.anchorA);
        const Vec2 endB = spring.bodyB ? world.body(*spring.bodyB).worldPoint(spring.anchorB) : spring.anchorB;
        spring.restLength = (endB - endA).norm();
        if (random.chance(kRestLengthGivenShare))
            spring.restLength *= random.uniform(kMinRestFactor, kMaxRestFactor);
        keepSpringStable(world, spring);
        world.springs.push_back(spring);
    }
}

void addJoints(SceneRandom& random, World& world, const std::vector<BodyId>& dynamic)
{
    const int count = random.integer(0, kMaxJoints);
    for (int i = 0; i < count; ++i) {
        const auto link = randomLink(random, world, dynamic);
        if (!link)
            continue;
        model::Joint joint;
        joint.bodyA = link->first;
        joint.bodyB = link->second;
        const Body& a = world.body(joint.bodyA);
        if (random.chance(0.5)) {
            joint.type = model::JointType::Pin;
            joint.worldAnchor = joint.bodyB ? Vec2(0.5 * (a.state.position + world.body(*joint.bodyB).state.position))
                                            : worldPointNear(random, a);
        } else {
            joint.type = model::JointType::Rod;
            joint.anchorA = randomAnchor(random, a);
            joint.anchorB = joint.bodyB ? randomAnchor(random, world.body(*joint.bodyB)) : worldPointNear(random, a);
        }
        world.joints.push_back(joint);
    }
}

/// Softens a soft body whose grid is too stiff for its integrator even at kMaxSoftSubsteps
/// substeps, until it is not, or makes it rigid when no stiffness is soft enough (explicit Euler
/// on an undamped grid). Such a grid is legal, but the program says it will blow up
/// (controller::softStability's message): that outcome is expected, not a finding.
void keepSoftBodiesStable(World& world)
{
    for (int attempt = 0;; ++attempt) {
        World trial = world;
        controller::prepareSoftBodies(trial);
        const controller::SoftStability stability = controller::softStability(trial);
        if (stability.stable)
            return;
        Body& body = world.body(stability.body);
        if (attempt < kMaxSoftening)
            body.soft->stiffness /= kSofteningFactor;
        else
            body.soft.reset();
    }
}

} // namespace

Scalar SceneRandom::unit()
{
    // The top 53 bits of one draw, as a double in [0, 1).
    constexpr int kMantissaBits = 53;
    return static_cast<Scalar>(m_engine() >> (64 - kMantissaBits)) * std::ldexp(1.0, -kMantissaBits);
}

Scalar SceneRandom::logUniform(Scalar low, Scalar high)
{
    return low * std::pow(high / low, unit());
}

int SceneRandom::integer(int low, int high)
{
    const auto span = static_cast<Scalar>(high - low + 1);
    return std::min(high, low + static_cast<int>(unit() * span));
}

void addClosedBox(World& world)
{
    const Scalar outerWidth = 2 * kBoxHalfWidth + 2 * kWallThickness;
    const Scalar outerHeight = kBoxHeight + 2 * kWallThickness;
    const Scalar half = kWallThickness / 2;
    world.bodies.push_back(makeWall("wall-floor", Vec2(0, -half), outerWidth, kWallThickness));
    world.bodies.push_back(makeWall("wall-ceiling", Vec2(0, kBoxHeight + half), outerWidth, kWallThickness));
    world.bodies.push_back(makeWall("wall-left", Vec2(-kBoxHalfWidth - half, kBoxHeight / 2), kWallThickness, outerHeight));
    world.bodies.push_back(makeWall("wall-right", Vec2(kBoxHalfWidth + half, kBoxHeight / 2), kWallThickness, outerHeight));
}

World makeRandomScene(std::uint64_t seed, const RandomSceneOptions& options)
{
    SceneRandom random(seed);
    World world;
    switch (random.integer(0, 3)) {
    case 0:
        world.settings.gravity = Vec2::Zero();
        break;
    case 1: {
        const Scalar direction = random.uniform(0, kTwoPi);
        world.settings.gravity = random.uniform(0, kMaxGravity) * Vec2(std::cos(direction), std::sin(direction));
        break;
    }
    default:
        break; // the standard gravity, half of the scenes
    }
    world.settings.integrator = static_cast<model::IntegratorKind>(random.integer(0, 2));
    const int stepsPerSecond[] = {240, 240, 120, 60};
    world.settings.timeStep = 1.0 / stepsPerSecond[random.integer(0, 3)];
    if (random.chance(kDragShare))
        world.settings.drag = random.uniform(0, kMaxDrag);

    addClosedBox(world);

    // The box's cells in a random order; each body takes the next.
    const int columns = static_cast<int>(2 * kBoxHalfWidth / kCellSize);
    const int rows = static_cast<int>(kBoxHeight / kCellSize);
    std::vector<Vec2> cells;
    for (int row = 0; row < rows; ++row)
        for (int column = 0; column < columns; ++column)
            cells.emplace_back(-kBoxHalfWidth + (column + 0.5) * kCellSize, (row + 0.5) * kCellSize);
    for (std::size_t i = cells.size(); i > 1; --i)
        std::swap(cells[i - 1], cells[static_cast<std::size_t>(random.integer(0, static_cast<int>(i) - 1))]);

    const int count = std::min(random.integer(options.minBodies, options.maxBodies), static_cast<int>(cells.size()) - 1);
    std::vector<BodyId> dynamic;
    for (int i = 0; i < count; ++i) {
        dynamic.push_back(BodyId{static_cast<std::uint32_t>(world.bodies.size())});
        world.bodies.push_back(randomBody(random, i, cells[static_cast<std::size_t>(i)]));
    }
    if (random.chance(kSoftShare)) {
        Body& soft = world.body(dynamic[static_cast<std::size_t>(random.integer(0, count - 1))]);
        soft.soft = model::SoftSettings{};
        soft.soft->ellipsesPerSquareMeter = random.uniform(kMinSoftDensity, kMaxSoftDensity);
        soft.soft->stiffness = random.uniform(kMinSoftStiffness, kMaxSoftStiffness);
        // Either way of giving the grid's damping (SoftSettings::dampingMode): a damping ratio,
        // the default, or a coefficient in N·s/m. Setting only the coefficient, as the generator
        // did before the ratio came, left it unused: every soft body had the default ratio.
        if (random.chance(0.5)) {
            soft.soft->dampingMode = model::SoftDampingMode::Coefficient;
            soft.soft->damping = random.uniform(0, kMaxSoftDamping);
        } else {
            soft.soft->dampingRatio = random.uniform(kMinSoftDampingRatio, kMaxSoftDampingRatio);
        }
    }
    if (random.chance(kObstacleShare)) {
        Body obstacle = randomBody(random, count, cells[static_cast<std::size_t>(count)]);
        obstacle.name = "obstacle";
        obstacle.fixed = true;
        obstacle.state.velocity = Vec2::Zero(); // a fixed body that moves does work: not in a closed box
        obstacle.state.angularVelocity = 0;
        obstacle.updateDerived();
        world.bodies.push_back(obstacle);
    }
    addSprings(random, world, dynamic);
    addJoints(random, world, dynamic);

    // Through the loader, as a scene file would come: that fills in what it derives, and a scene
    // the loader refuses, or one outside the tested ranges, is the generator's bug.
    model::SceneLoadResult loaded = model::parseScene(model::serializeScene(world));
    if (!loaded.ok())
        throw std::logic_error("seed " + std::to_string(seed) + ": the generated scene does not load: " +
                               loaded.problems.front().toString());
    if (const auto warnings = model::sceneWarnings(*loaded.world); !warnings.empty())
        throw std::logic_error("seed " + std::to_string(seed) + ": the generated scene is outside the tested ranges: " +
                               warnings.front().toString());
    keepSoftBodiesStable(*loaded.world);
    return std::move(*loaded.world);
}

} // namespace impetus::soak
