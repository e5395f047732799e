// The example scenes the app ships (resources/examples, docs/examples.md): every one loads with no
// problem and runs, and those that carry a textbook result reproduce it. The expected values come
// from the formulas, with the parameters read from the scene files, never from an earlier run.

#include "controller/diagnostics.h"
#include "controller/simulation.h"
#include "model/scene_io.h"
#include "support/pendulum_theory.h"

#include <gtest/gtest.h>

#include "model/constants.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace impetus {
namespace {

namespace fs = std::filesystem;

const fs::path kExamplesDir = IMPETUS_EXAMPLES_DIR;

/// The examples the editor's Examples menu promises (issue 4): a missing one fails here.
const std::vector<std::string> kPromisedExamples = {
    "billiards.json", "box-stack.json", "default.json", "incline.json", "newtons-cradle.json",
    "pendulum.json", "projectile.json", "pyramid.json", "spaceship-asteroids.json",
    "spring.json", "spring-chain.json"};

/// The file names of every *.json in the examples folder, sorted.
std::vector<std::string> exampleFileNames()
{
    std::vector<std::string> names;
    std::error_code error;
    for (const fs::directory_entry& entry : fs::directory_iterator(kExamplesDir, error)) {
        if (entry.is_regular_file() && entry.path().extension() == ".json")
            names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

/// Reads an example. A scene that does not load throws with its problems, which fails the test
/// that asked for it with that message.
model::World loadExample(const std::string& fileName)
{
    model::SceneLoadResult result = model::loadSceneFile(kExamplesDir / fileName);
    if (!result.ok()) {
        std::string message = fileName;
        message += " does not load:";
        for (const model::SceneProblem& problem : result.problems) {
            message += "\n  ";
            message += problem.toString();
        }
        throw std::runtime_error(message);
    }
    return std::move(*result.world);
}

/// The index of the body called `name`; throws when the scene has none (the test then fails).
std::size_t indexOf(const model::World& world, std::string_view name)
{
    const std::optional<model::BodyId> id = world.findBody(name);
    if (!id) {
        std::string message = "no body called ";
        message += name;
        throw std::runtime_error(message);
    }
    return id->index;
}

bool isFinite(const model::BodyState& s)
{
    return s.position.allFinite() && s.velocity.allFinite() && std::isfinite(s.angle) &&
           std::isfinite(s.angularVelocity);
}

/// The number of fixed steps in `seconds` of the world's time.
int stepsIn(const model::World& world, Scalar seconds)
{
    return static_cast<int>(std::lround(seconds / world.settings.timeStep));
}

/// Steps `world` for `seconds`.
void run(controller::Simulation& simulation, model::World& world, Scalar seconds)
{
    for (int i = stepsIn(world, seconds); i > 0; --i)
        simulation.step(world);
}

/// Mean period of a signal from its upward zero crossings, interpolated linearly between steps.
/// `signal` is sampled once per step for `seconds`.
Scalar periodOfUpwardCrossings(controller::Simulation& simulation, model::World& world, Scalar seconds,
                               const std::function<Scalar(const model::World&)>& signal)
{
    std::vector<Scalar> crossings;
    Scalar previous = signal(world);
    Scalar previousTime = world.time;
    for (int i = stepsIn(world, seconds); i > 0; --i) {
        simulation.step(world);
        const Scalar current = signal(world);
        if (previous < 0 && current >= 0)
            crossings.push_back(previousTime + (world.time - previousTime) * previous / (previous - current));
        previous = current;
        previousTime = world.time;
    }
    if (crossings.size() < 2)
        return 0;
    return (crossings.back() - crossings.front()) / static_cast<Scalar>(crossings.size() - 1);
}

// ---- Every example ----------------------------------------------------------------------------

TEST(ExampleScenes, EveryPromisedExampleIsShipped)
{
    const std::vector<std::string> shipped = exampleFileNames();
    for (const std::string& name : kPromisedExamples)
        EXPECT_NE(std::find(shipped.begin(), shipped.end(), name), shipped.end()) << name << " is missing";
}

class ExampleScene : public ::testing::TestWithParam<std::string> {};

TEST_P(ExampleScene, LoadsWithoutProblems)
{
    const model::SceneLoadResult result = model::loadSceneFile(kExamplesDir / GetParam());
    for (const model::SceneProblem& problem : result.problems)
        ADD_FAILURE() << problem.toString();
    ASSERT_TRUE(result.ok());
    EXPECT_FALSE(result.world->bodies.empty());
}

// Three simulated seconds with every state finite after every step. No example has a motor (no
// fixed body moves), so the total energy may not grow either: an explosion would show here.
TEST_P(ExampleScene, RunsThreeSecondsFiniteAndGainsNoEnergy)
{
    model::World world = loadExample(GetParam());
    controller::Simulation simulation;
    const controller::Energy start = controller::computeEnergy(world);
    for (int i = stepsIn(world, 3.0); i > 0; --i) {
        simulation.step(world);
        for (const model::Body& body : world.bodies)
            ASSERT_TRUE(isFinite(body.state)) << body.name << " at t = " << world.time << " s";
    }
    const controller::Energy end = controller::computeEnergy(world);
    const Scalar scale = std::abs(start.kinetic) + std::abs(start.potential) + std::abs(start.elastic);
    EXPECT_LE(end.total(), start.total() + 0.01 * scale + 1e-9)
        << "kinetic " << end.kinetic << " J, potential " << end.potential << " J, elastic " << end.elastic << " J";
}

std::string testNameOf(const ::testing::TestParamInfo<std::string>& info)
{
    std::string name = fs::path(info.param).stem().string();
    for (char& c : name) {
        if (!std::isalnum(static_cast<unsigned char>(c)))
            c = '_';
    }
    return name;
}

INSTANTIATE_TEST_SUITE_P(Resources, ExampleScene, ::testing::ValuesIn(exampleFileNames()), testNameOf);

// ---- Examples with a textbook result -----------------------------------------------------------

// A block sliding down a fixed incline: a = g(sin θ − μ cos θ) along the slope.
TEST(InclineExample, BlockSlidesWithTheTextbookAcceleration)
{
    model::World world = loadExample("incline.json");
    const std::size_t block = indexOf(world, "block");
    const model::Body& ramp = world.bodies[indexOf(world, "incline")];
    const Scalar theta = -world.bodies[block].state.angle;
    // The block lies on the ramp's slope: the ramp's vertices rise at θ.
    const auto& vertices = std::get<model::Polygon>(ramp.shape).vertices;
    ASSERT_EQ(vertices.size(), 3u);
    const Vec2 span = vertices[1] - vertices[2]; // from the top corner to the foot of the slope
    EXPECT_NEAR(std::atan2(-span.y(), span.x()), theta, 1e-6);
    // One material on both faces, so the contact has exactly that μ.
    const Scalar mu = world.bodies[block].material.friction;
    ASSERT_EQ(ramp.material.friction, mu);
    const Scalar g = -world.settings.gravity.y();
    const Scalar expected = g * (std::sin(theta) - mu * std::cos(theta));
    ASSERT_GT(expected, 0) << "the block must slide";

    const Vec2 downSlope(std::cos(theta), -std::sin(theta));
    controller::Simulation simulation;
    run(simulation, world, 0.25);
    const Scalar t1 = world.time;
    const Scalar v1 = world.bodies[block].state.velocity.dot(downSlope);
    const Vec2 x1 = world.bodies[block].state.position;
    run(simulation, world, 1.0);
    const Scalar dt = world.time - t1;
    const Scalar v2 = world.bodies[block].state.velocity.dot(downSlope);
    const Scalar travelled = (world.bodies[block].state.position - x1).dot(downSlope);
    EXPECT_NEAR((v2 - v1) / dt, expected, 0.01 * expected);
    EXPECT_NEAR(travelled, v1 * dt + expected * dt * dt / 2, 0.01 * travelled);
    // Still on the slope, flat on it, not tumbling.
    EXPECT_NEAR(world.bodies[block].state.angle, -theta, 1e-3);
}

// A ball launched at speed v and angle θ over level ground: it returns to its launch height
// v²·sin 2θ / g further on, after rising v²·sin²θ / (2g).
TEST(ProjectileExample, RangeAndApexMatchTheFormulas)
{
    model::World world = loadExample("projectile.json");
    const std::size_t ball = indexOf(world, "ball");
    const Vec2 start = world.bodies[ball].state.position;
    const Vec2 launch = world.bodies[ball].state.velocity;
    const Scalar v = launch.norm();
    const Scalar theta = std::atan2(launch.y(), launch.x());
    const Scalar g = -world.settings.gravity.y();
    ASSERT_EQ(world.settings.drag, 0);
    const Scalar range = v * v * std::sin(2 * theta) / g;
    const Scalar apex = v * v * std::sin(theta) * std::sin(theta) / (2 * g);

    controller::Simulation simulation;
    Scalar highest = start.y();
    // Step while the ball flies free; stop at the step in which it touches the ground.
    model::World before = world;
    for (int i = stepsIn(world, 5.0); i > 0; --i) {
        before = world;
        simulation.step(world);
        if (world.bodies[ball].collisionCount > 0)
            break;
        highest = std::max(highest, world.bodies[ball].state.position.y());
    }
    ASSERT_GT(world.bodies[ball].collisionCount, 0) << "the ball never landed";
    // From the last free state, the ball falls the remaining height (less than one step's worth)
    // to its launch height: y + vy·t − g·t²/2 = y₀.
    const model::BodyState& last = before.bodies[ball].state;
    const Scalar drop = last.position.y() - start.y();
    ASSERT_GE(drop, 0);
    const Scalar vy = last.velocity.y();
    const Scalar t = (vy + std::sqrt(vy * vy + 2 * g * drop)) / g;
    const Scalar landedAt = last.position.x() + last.velocity.x() * t;
    EXPECT_NEAR(landedAt - start.x(), range, 0.01 * range);
    EXPECT_NEAR(highest - start.y(), apex, 0.01 * apex);
    // The scene's target strip marks that point.
    const model::Body& target = world.bodies[indexOf(world, "target")];
    EXPECT_NEAR(target.state.position.x(), start.x() + range, 0.01 * range);
}

// A bob on a rod released from rest at θ₀: T = 4√(L/g)·K(sin(θ₀/2)).
TEST(PendulumExample, PeriodMatchesTheLargeAmplitudeFormula)
{
    model::World world = loadExample("pendulum.json");
    const std::size_t bob = indexOf(world, "bob");
    ASSERT_EQ(world.joints.size(), 1u);
    const model::Joint& rod = world.joints[0];
    ASSERT_EQ(rod.type, model::JointType::Rod);
    ASSERT_FALSE(rod.bodyB.has_value());
    ASSERT_EQ(rod.anchorA, Vec2::Zero()); // hung by its centre: a simple pendulum
    const Vec2 pivot = rod.anchorB;
    const Vec2 arm = world.bodies[bob].state.position - pivot;
    const Scalar length = arm.norm();
    const Scalar theta0 = std::atan2(arm.x(), -arm.y());
    const Scalar expected = testing::pendulumPeriod(length, -world.settings.gravity.y(), theta0);

    controller::Simulation simulation;
    const Scalar period = periodOfUpwardCrossings(simulation, world, 4.5 * expected, [&](const model::World& w) {
        return w.bodies[bob].state.position.x() - pivot.x();
    });
    EXPECT_NEAR(period, expected, 0.005 * expected);
    // The rod keeps its length.
    EXPECT_NEAR((world.bodies[bob].state.position - pivot).norm(), length, 1e-3);
}

// Newton's cradle: the pulled-back ball arrives at √(2gL(1 − cos θ₀)); one ball leaves at that
// speed and the others stay (nearly) at rest.
TEST(NewtonsCradleExample, OneBallInOneBallOut)
{
    model::World world = loadExample("newtons-cradle.json");
    std::vector<std::size_t> balls;
    for (int i = 1; i <= 5; ++i)
        balls.push_back(indexOf(world, "ball" + std::to_string(i)));
    ASSERT_EQ(world.joints.size(), balls.size());
    const Scalar g = -world.settings.gravity.y();
    // Each ball hangs from a rod; its lowest point is one rod length below the rod's world anchor.
    std::vector<Scalar> lowest(balls.size());
    for (const model::Joint& rod : world.joints) {
        const auto it = std::find(balls.begin(), balls.end(), rod.bodyA.index);
        ASSERT_NE(it, balls.end());
        lowest[static_cast<std::size_t>(it - balls.begin())] = rod.anchorB.y() - rod.length;
    }
    const Scalar drop = world.bodies[balls[0]].state.position.y() - lowest[0];
    const Scalar incoming = std::sqrt(2 * g * drop);
    // The speed a ball has, or had, at the bottom of its swing (energy along the rod's arc).
    // A ball at rest may hang up to the rods' position slop below the nominal bottom (the rod
    // stretched within what the position passes allow): that is checked, and counts as speed 0.
    const auto bottomSpeed = [&](std::size_t i) {
        const model::BodyState& s = world.bodies[balls[i]].state;
        EXPECT_GT(s.position.y() - lowest[i], -constants::kLinearSlop) << "ball" << i + 1 << " hangs below its rod";
        return std::sqrt(std::max(0.0, s.velocity.squaredNorm() + 2 * g * (s.position.y() - lowest[i])));
    };

    controller::Simulation simulation;
    Scalar speedBeforeImpact = 0;
    for (int i = stepsIn(world, 2.0); i > 0 && world.bodies[balls[0]].collisionCount == 0; --i) {
        speedBeforeImpact = world.bodies[balls[0]].state.velocity.norm();
        simulation.step(world);
    }
    ASSERT_GT(world.bodies[balls[0]].collisionCount, 0) << "the first ball never struck";
    EXPECT_NEAR(speedBeforeImpact, incoming, 0.005 * incoming);
    // Let the blow pass along the row (the balls are 1 mm apart).
    run(simulation, world, 0.05);
    EXPECT_NEAR(bottomSpeed(4), incoming, 0.01 * incoming);
    EXPECT_GT(world.bodies[balls[4]].state.velocity.x(), 0);
    for (std::size_t i = 0; i < 4; ++i)
        EXPECT_LT(bottomSpeed(i), 0.05 * incoming) << "ball" << i + 1;
}

// Seed S1's scenario: the ship crosses the field and hits asteroids, and in zero gravity the
// impulses are internal, so the total momentum stays what it was.
TEST(SpaceshipExample, ShipHitsAsteroidsAndMomentumIsKept)
{
    model::World world = loadExample("spaceship-asteroids.json");
    ASSERT_EQ(world.settings.gravity, Vec2::Zero());
    ASSERT_EQ(world.settings.drag, 0);
    const std::size_t ship = indexOf(world, "spaceship");
    const Scalar startX = world.bodies[ship].state.position.x();
    const Vec2 momentum = controller::linearMomentum(world);
    controller::Simulation simulation;
    run(simulation, world, 6.0);
    EXPECT_GT(world.bodies[ship].collisionCount, 0);
    EXPECT_GE(world.collisionCount, world.bodies[ship].collisionCount);
    EXPECT_GT(world.bodies[ship].state.position.x() - startX, 8.0) << "the ship did not get through";
    EXPECT_LT((controller::linearMomentum(world) - momentum).norm(), 1e-9 * momentum.norm());
}

/// Steps 5 s and checks that the body `top` (the top box of a stack) moved less than 1 cm and
/// turned less than 0.01 rad: the stack still stands.
void expectTopBoxStays(model::World& world, std::string_view top)
{
    const std::size_t index = indexOf(world, top);
    const Vec2 start = world.bodies[index].state.position;
    controller::Simulation simulation;
    run(simulation, world, 5.0);
    const Vec2 moved = world.bodies[index].state.position - start;
    EXPECT_LT(std::abs(moved.x()), 0.01) << top << " moved sideways";
    EXPECT_LT(std::abs(moved.y()), 0.01) << top << " sank or fell";
    EXPECT_LT(std::abs(world.bodies[index].state.angle), 0.01) << top << " tilted";
}

TEST(BoxStackExample, ColumnAndLeaningStackStillStandAfterFiveSeconds)
{
    model::World world = loadExample("box-stack.json");
    expectTopBoxStays(world, "box10");
    model::World again = loadExample("box-stack.json");
    expectTopBoxStays(again, "book6");
}

// The leaning stack reaches past the table edge as far as the book-stacking problem allows, less
// the scene's safety margin: (w/2)·H_n at most, and more than one block width.
TEST(BoxStackExample, LeaningStackOverhangsWithinTheHarmonicLimit)
{
    const model::World world = loadExample("box-stack.json");
    const model::Body& table = world.bodies[indexOf(world, "table")];
    const Scalar edge = table.state.position.x() + std::get<model::Box>(table.shape).width / 2;
    const model::Body& top = world.bodies[indexOf(world, "book6")];
    const Scalar w = std::get<model::Box>(top.shape).width;
    Scalar harmonic = 0;
    for (int k = 1; k <= 6; ++k)
        harmonic += 1.0 / k;
    const Scalar overhang = top.state.position.x() + w / 2 - edge;
    EXPECT_LT(overhang, w / 2 * harmonic);
    EXPECT_GT(overhang, w);
}

TEST(PyramidExample, StillStandsAfterFiveSeconds)
{
    model::World world = loadExample("pyramid.json");
    expectTopBoxStays(world, world.bodies.back().name);
}

// A billiards break seen from above: the balls have one mass m and the table pulls each with the
// drag −b·v, so until a ball reaches a cushion the total momentum obeys dp/dt = −(b/m)·p whatever
// the collisions do: p(t) = p₀·e^(−bt/m), along the cue's line.
TEST(BilliardsExample, BreakKeepsMomentumUntilACushion)
{
    model::World world = loadExample("billiards.json");
    ASSERT_EQ(world.settings.gravity, Vec2::Zero());
    Scalar mass = 0;
    std::vector<model::BodyId> cushions;
    for (std::uint32_t i = 0; i < world.bodies.size(); ++i) {
        const model::Body& body = world.bodies[i];
        if (body.fixed) {
            cushions.push_back(model::BodyId{i});
            continue;
        }
        if (mass == 0)
            mass = body.mass;
        ASSERT_EQ(body.mass, mass) << body.name;
    }
    const Scalar b = world.settings.drag;
    const Vec2 p0 = controller::linearMomentum(world);
    ASSERT_GT(p0.norm(), 0);
    const auto isCushion = [&](model::BodyId id) {
        return std::find(cushions.begin(), cushions.end(), id) != cushions.end();
    };

    controller::Simulation simulation;
    model::World before = world;
    bool cushionHit = false;
    for (int i = stepsIn(world, 5.0); i > 0 && !cushionHit; --i) {
        before = world;
        simulation.step(world);
        for (const controller::CollisionEvent& event : simulation.events())
            cushionHit = cushionHit || isCushion(event.bodyA) || isCushion(event.bodyB);
    }
    ASSERT_TRUE(cushionHit) << "no ball reached a cushion";
    // `before` is the last state with no cushion in play; the break must have happened by then.
    int moving = 0;
    for (const model::Body& body : before.bodies)
        moving += body.state.velocity.norm() > 0.05 ? 1 : 0;
    EXPECT_GE(moving, 8) << "the rack did not break";
    const Vec2 p = controller::linearMomentum(before);
    const Vec2 expected = p0 * std::exp(-b * before.time / mass);
    EXPECT_NEAR(p.x(), expected.x(), 1e-3 * p0.norm());
    EXPECT_NEAR(p.y(), expected.y(), 1e-3 * p0.norm());
}

// Springs: the lone weight oscillates with T = 2π√(m/k); the damped chain of four settles where
// spring i (from the top) carries the (5 − i) masses below it, stretched by (5 − i)·m·g/k.
TEST(SpringChainExample, LoneWeightHasTheSpringPeriod)
{
    model::World world = loadExample("spring-chain.json");
    const std::size_t weight = indexOf(world, "weight");
    const model::Spring& spring = world.springs[0];
    ASSERT_EQ(spring.bodyA.index, weight);
    ASSERT_EQ(spring.damping, 0);
    const Scalar m = world.bodies[weight].mass;
    const Scalar k = spring.stiffness;
    const Scalar g = -world.settings.gravity.y();
    const Scalar expected = 2 * std::numbers::pi_v<Scalar> * std::sqrt(m / k);
    // Equilibrium: the anchor's height less the stretched spring and the anchor's offset.
    const Scalar equilibrium = spring.anchorB.y() - (spring.restLength + m * g / k) - spring.anchorA.y();
    controller::Simulation simulation;
    const Scalar period = periodOfUpwardCrossings(simulation, world, 10.0, [&](const model::World& w) {
        return w.bodies[weight].state.position.y() - equilibrium;
    });
    EXPECT_NEAR(period, expected, 0.005 * expected);
}

// The puck on the air table (no gravity, a zero-length spring to the origin) is the isotropic
// oscillator: x(t) = x₀ cos ωt + (v₀/ω) sin ωt, so after one period T = 2π√(m/k) it is back where
// it started, moving as it started.
TEST(SpringExample, PuckIsBackWhereItStartedAfterOnePeriod)
{
    model::World world = loadExample("spring.json");
    const std::size_t puck = indexOf(world, "puck");
    const model::Spring& spring = world.springs[0];
    ASSERT_EQ(world.settings.gravity, Vec2::Zero());
    ASSERT_EQ(spring.restLength, 0);
    const Scalar omega = std::sqrt(spring.stiffness / world.bodies[puck].mass);
    const model::BodyState start = world.bodies[puck].state;
    const Scalar period = 2 * std::numbers::pi_v<Scalar> / omega;
    controller::Simulation simulation;
    const auto steps = static_cast<int>(std::lround(period / world.settings.timeStep));
    for (int i = 0; i < steps; ++i)
        simulation.step(world);
    // Whole steps miss the period by at most half a step, at 1.5 m/s: under 4 mm.
    const Scalar slack = 0.5 * world.settings.timeStep * start.velocity.norm() * 1.01;
    EXPECT_LT((world.bodies[puck].state.position - start.position).norm(), slack);
    EXPECT_EQ(world.bodies[puck].collisionCount, 0);
}

TEST(SpringChainExample, ChainSettlesAtTheStaticStretches)
{
    model::World world = loadExample("spring-chain.json");
    const Scalar g = -world.settings.gravity.y();
    controller::Simulation simulation;
    run(simulation, world, 60.0);
    const int chain = 4;
    for (int i = 1; i <= chain; ++i) {
        const std::size_t index = indexOf(world, "mass" + std::to_string(i));
        const auto spring = std::find_if(world.springs.begin(), world.springs.end(),
                                         [&](const model::Spring& s) { return s.bodyA.index == index; });
        ASSERT_NE(spring, world.springs.end());
        const model::Body& body = world.bodies[index];
        const Vec2 top = body.worldPoint(spring->anchorA);
        const Vec2 above = spring->bodyB ? world.body(*spring->bodyB).worldPoint(spring->anchorB) : spring->anchorB;
        const Scalar stretch = (above - top).norm() - spring->restLength;
        const Scalar expected = (chain - i + 1) * body.mass * g / spring->stiffness;
        EXPECT_NEAR(stretch, expected, 0.01 * expected) << "spring above mass" << i;
    }
}

// ---- Lessons: each stored answer against the engine and against the textbook -------------------
//
// The four lessons (docs/examples.md, "Lessons") store the answers to their questions. Each one is
// measured here in the engine as a student would measure it in the app, and worked out from the
// textbook formula with the scene's own numbers; the question must accept both.

/// The lesson of `world`; throws (failing the test) when the scene has none.
const model::Lesson& lessonOf(const model::World& world)
{
    if (!world.lesson)
        throw std::runtime_error("the scene has no lesson");
    return *world.lesson;
}

/// Expects question `index` of `lesson` to accept both the engine's `measured` value and the
/// textbook's `formula`.
void expectAnswerMatches(const model::Lesson& lesson, std::size_t index, Scalar measured, Scalar formula)
{
    ASSERT_LT(index, lesson.questions.size());
    const model::LessonQuestion& question = lesson.questions[index];
    EXPECT_TRUE(question.accepts(measured)) << question.prompt << "\n  engine " << measured << ", stored answer "
                                            << question.answer << " ± " << question.tolerance;
    EXPECT_TRUE(question.accepts(formula)) << question.prompt << "\n  textbook " << formula << ", stored answer "
                                           << question.answer << " ± " << question.tolerance;
}

/// The incline lesson's board and block turned together by `turn` (rad) about the mean of their
/// centres, as the Rotate tool turns the two when both are selected.
model::World turnedTogether(model::World world, std::size_t board, std::size_t block, Scalar turn)
{
    const Vec2 pivot = (world.bodies[board].state.position + world.bodies[block].state.position) / 2;
    for (const std::size_t i : {board, block}) {
        model::BodyState& state = world.bodies[i].state;
        state.position = pivot + rotate(Vec2(state.position - pivot), turn);
        state.angle += turn;
    }
    return world;
}

/// True when the block, left alone for 1.5 s on the board turned to `angle`, has moved more than
/// a centimetre: it slides.
bool blockSlides(const model::World& start, std::size_t board, std::size_t block, Scalar angle)
{
    model::World world = turnedTogether(start, board, block, angle - start.bodies[board].state.angle);
    const Vec2 before = world.bodies[block].state.position;
    controller::Simulation simulation;
    run(simulation, world, 1.5);
    return (world.bodies[block].state.position - before).norm() > 0.01;
}

TEST(InclineLesson, StoredAnswersMatchTheEngineAndTanThetaEqualsMu)
{
    const model::World start = loadExample("lesson-incline-friction.json");
    const model::Lesson& lesson = lessonOf(start);
    ASSERT_EQ(lesson.questions.size(), 2u);
    const std::size_t board = indexOf(start, "board");
    const std::size_t block = indexOf(start, "block");
    // The student turns the board and the block: the lesson leaves those two free, and no more.
    for (const std::size_t i : {board, block}) {
        EXPECT_TRUE(lesson.allows(model::BodyId{static_cast<std::uint32_t>(i)}, model::BodyAttribute::Angle));
        EXPECT_TRUE(lesson.allows(model::BodyId{static_cast<std::uint32_t>(i)}, model::BodyAttribute::Position));
        EXPECT_FALSE(lesson.allows(model::BodyId{static_cast<std::uint32_t>(i)}, model::BodyAttribute::Friction));
    }
    const Scalar mu = start.bodies[block].material.friction;
    ASSERT_EQ(start.bodies[board].material.friction, mu); // one material: the contact's μ is μ
    constexpr Scalar kDegree = std::numbers::pi / 180;

    // Question 1: the angle at which the block starts to slide, found by bisection in the engine.
    Scalar holds = start.bodies[board].state.angle;
    Scalar slides = 45 * kDegree;
    ASSERT_FALSE(blockSlides(start, board, block, holds)) << "the block must rest at the start";
    ASSERT_TRUE(blockSlides(start, board, block, slides));
    while (slides - holds > 0.01 * kDegree) {
        const Scalar middle = (holds + slides) / 2;
        (blockSlides(start, board, block, middle) ? slides : holds) = middle;
    }
    const Scalar critical = (holds + slides) / 2 / kDegree;
    expectAnswerMatches(lesson, 0, critical, std::atan(mu) / kDegree);

    // Question 2: the acceleration along the board at 40°, a = g(sin θ − μ cos θ).
    const Scalar steep = 40 * kDegree;
    model::World world = turnedTogether(start, board, block, steep - start.bodies[board].state.angle);
    const Vec2 downSlope(-std::cos(steep), -std::sin(steep));
    controller::Simulation simulation;
    run(simulation, world, 0.25);
    const Scalar t1 = world.time;
    const Scalar v1 = world.bodies[block].state.velocity.dot(downSlope);
    run(simulation, world, 0.5);
    const Scalar measured = (world.bodies[block].state.velocity.dot(downSlope) - v1) / (world.time - t1);
    const Scalar g = -start.settings.gravity.y();
    expectAnswerMatches(lesson, 1, measured, g * (std::sin(steep) - mu * std::cos(steep)));
}

TEST(CartCrashLesson, StoredAnswersMatchTheEngineAndMomentumIsKept)
{
    const model::World start = loadExample("lesson-cart-crash.json");
    const model::Lesson& lesson = lessonOf(start);
    ASSERT_EQ(lesson.questions.size(), 4u);
    const std::size_t red = indexOf(start, "red cart");
    const std::size_t blue = indexOf(start, "blue cart");
    const Scalar m1 = start.bodies[red].mass;
    const Scalar m2 = start.bodies[blue].mass;
    const Scalar v1 = start.bodies[red].state.velocity.x();
    const Scalar v2 = start.bodies[blue].state.velocity.x();
    const Scalar momentum = m1 * v1 + m2 * v2;

    // Question 1: the total momentum before the crash, as the status bar shows it.
    expectAnswerMatches(lesson, 0, controller::linearMomentum(start).x(), momentum);

    // Questions 2 and 3: with e = 0 the carts move on together, and kinetic energy is lost.
    ASSERT_EQ(start.bodies[red].material.restitution, 0);
    model::World world = start;
    controller::Simulation simulation;
    run(simulation, world, 3.0);
    ASSERT_GE(world.collisionCount, 1);
    const Scalar together = momentum / (m1 + m2);
    expectAnswerMatches(lesson, 1, world.bodies[red].state.velocity.x(), together);
    expectAnswerMatches(lesson, 1, world.bodies[blue].state.velocity.x(), together);
    const Scalar lost = controller::computeEnergy(start).kinetic - controller::computeEnergy(world).kinetic;
    expectAnswerMatches(lesson, 2, lost, (m1 * v1 * v1 + m2 * v2 * v2 - (m1 + m2) * together * together) / 2);
    EXPECT_NEAR(controller::linearMomentum(world).x(), momentum, 1e-9);

    // Question 4: restitution 1 on both carts (which the lesson lets students change).
    EXPECT_TRUE(lesson.allows(model::BodyId{static_cast<std::uint32_t>(red)}, model::BodyAttribute::Restitution));
    EXPECT_TRUE(lesson.allows(model::BodyId{static_cast<std::uint32_t>(blue)}, model::BodyAttribute::Restitution));
    model::World elastic = start;
    elastic.bodies[red].material.restitution = 1;
    elastic.bodies[blue].material.restitution = 1;
    controller::Simulation elasticSimulation;
    run(elasticSimulation, elastic, 3.0);
    expectAnswerMatches(lesson, 3, elastic.bodies[blue].state.velocity.x(), ((m2 - m1) * v2 + 2 * m1 * v1) / (m1 + m2));
    EXPECT_NEAR(controller::linearMomentum(elastic).x(), momentum, 1e-9);
}

TEST(PendulumLesson, StoredPeriodsMatchTheEngineAndTheLargeAmplitudeFormula)
{
    const model::World start = loadExample("lesson-pendulum-length.json");
    const model::Lesson& lesson = lessonOf(start);
    ASSERT_EQ(lesson.questions.size(), 4u);
    EXPECT_TRUE(lesson.allows(model::WorldAttribute::Gravity));
    // Length, amplitude and pivot of the pendulum whose bob is `name`, from the scene.
    struct Pendulum {
        std::size_t bob;
        Vec2 pivot;
        Scalar length;
        Scalar amplitude;
    };
    const auto pendulum = [&start](std::string_view name) {
        Pendulum p{indexOf(start, name), Vec2::Zero(), 0, 0};
        const auto rod = std::find_if(start.joints.begin(), start.joints.end(),
                                      [&](const model::Joint& j) { return j.bodyA.index == p.bob; });
        if (rod == start.joints.end() || rod->bodyB || rod->anchorA != Vec2::Zero())
            throw std::runtime_error("each bob hangs by its centre on a rod to the world");
        p.pivot = rod->anchorB;
        const Vec2 arm = start.bodies[p.bob].state.position - p.pivot;
        p.length = arm.norm();
        p.amplitude = std::atan2(arm.x(), -arm.y());
        return p;
    };
    const Pendulum longest = pendulum("long bob");
    const Pendulum shortest = pendulum("short bob");
    const auto measure = [](model::World world, const Pendulum& p) {
        controller::Simulation simulation;
        const Scalar g = -world.settings.gravity.y();
        const Scalar seconds = 4.5 * testing::pendulumPeriod(p.length, g, p.amplitude);
        return periodOfUpwardCrossings(simulation, world, seconds, [&p](const model::World& w) {
            return w.bodies[p.bob].state.position.x() - p.pivot.x();
        });
    };
    const Scalar g = -start.settings.gravity.y();
    const Scalar tLong = measure(start, longest);
    const Scalar tShort = measure(start, shortest);
    const Scalar formulaLong = testing::pendulumPeriod(longest.length, g, longest.amplitude);
    const Scalar formulaShort = testing::pendulumPeriod(shortest.length, g, shortest.amplitude);
    expectAnswerMatches(lesson, 0, tLong, formulaLong);
    expectAnswerMatches(lesson, 1, tShort, formulaShort);
    expectAnswerMatches(lesson, 2, tLong / tShort, formulaLong / formulaShort);
    // The small-angle period would be wrong here: the answer needs the finite-amplitude correction.
    EXPECT_FALSE(lesson.questions[0].accepts(2 * std::numbers::pi * std::sqrt(longest.length / g)));

    // Question 4: on the Moon.
    constexpr Scalar kMoonGravity = 1.62;
    model::World moon = start;
    moon.settings.gravity = Vec2(0, -kMoonGravity);
    expectAnswerMatches(lesson, 3, measure(moon, longest),
                        testing::pendulumPeriod(longest.length, kMoonGravity, longest.amplitude));
}

// The spring lab: students may change the spring's stiffness and nothing else. Each stored answer
// holds both the engine's period (from the block's upward crossings of its rest point) and
// T = 2π√(m/k), at the k each question asks for.
TEST(SpringLesson, StoredPeriodsMatchTheEngineAndTwoPiRootMOverK)
{
    const model::World start = loadExample("lesson-spring-period.json");
    const model::Lesson& lesson = lessonOf(start);
    ASSERT_EQ(lesson.questions.size(), 4u);
    ASSERT_EQ(start.springs.size(), 1u);
    EXPECT_TRUE(lesson.allows(std::size_t{0}, model::SpringAttribute::Stiffness));
    EXPECT_FALSE(lesson.allows(std::size_t{0}, model::SpringAttribute::RestLength));
    EXPECT_TRUE(lesson.editableBodies.empty());
    const std::size_t block = indexOf(start, "block");
    const Scalar mass = start.bodies[block].mass;
    const Vec2 wallEnd = start.bodies[indexOf(start, "wall")].worldPoint(start.springs[0].anchorB);
    // Where the block rests: the spring at its rest length.
    const Scalar rest = wallEnd.x() + start.springs[0].restLength - start.springs[0].anchorA.x();
    const auto period = [&](Scalar stiffness) {
        model::World world = start;
        world.springs[0].stiffness = stiffness;
        controller::Simulation simulation;
        const Scalar formula = 2 * std::numbers::pi * std::sqrt(mass / stiffness);
        const Scalar measured = periodOfUpwardCrossings(simulation, world, 4.5 * formula,
                                                        [&](const model::World& w) { return w.bodies[block].state.position.x() - rest; });
        return std::pair{measured, formula};
    };
    const auto [t40, formula40] = period(40);
    const auto [t160, formula160] = period(160);
    expectAnswerMatches(lesson, 0, t40, formula40);
    expectAnswerMatches(lesson, 1, t160, formula160);
    expectAnswerMatches(lesson, 2, t160 / t40, 0.5);
    // Question 4: the stiffness the student finds for 2 s, checked by running it.
    const Scalar forTwoSeconds = lesson.questions[3].answer;
    EXPECT_NEAR(period(forTwoSeconds).first, 2.0, 0.002);
    expectAnswerMatches(lesson, 3, forTwoSeconds, 4 * std::numbers::pi * std::numbers::pi * mass / 4);
}

// Tuning a pendulum: students may move the rod's ends and nothing else. The bob stays where it
// is, 0.15 m off the pivot's vertical, so the amplitude is asin(0.15 m / L). Each stored answer
// holds the engine's period (the bob's upward crossings of the pivot's vertical) and
// T = 4√(L/g)·K(sin(θ₀/2)); the seconds pendulum's length, set as a student would by moving the
// pivot straight down, swings in 2 s.
TEST(PendulumTuningLesson, StoredLengthAndPeriodsMatchTheEngineWithThePivotMoved)
{
    const model::World start = loadExample("lesson-pendulum-tuning.json");
    const model::Lesson& lesson = lessonOf(start);
    ASSERT_EQ(lesson.questions.size(), 3u);
    ASSERT_EQ(start.joints.size(), 1u);
    EXPECT_TRUE(lesson.allows(std::size_t{0}, model::JointAttribute::Anchors));
    EXPECT_TRUE(lesson.editableBodies.empty());
    EXPECT_TRUE(lesson.editableWorld.none());
    const std::size_t bob = indexOf(start, "bob");
    const model::Joint& rod = start.joints[0];
    ASSERT_EQ(rod.type, model::JointType::Rod);
    ASSERT_FALSE(rod.bodyB.has_value());
    const Vec2 bobAt = start.bodies[bob].state.position;
    const Scalar side = bobAt.x() - rod.anchorB.x();
    const Scalar g = -start.settings.gravity.y();
    // The period with the pivot moved straight up or down until the rod is `length` long, in the
    // engine and by the formula.
    const auto period = [&](Scalar length) {
        model::World world = start;
        model::Joint& moved = world.joints[0];
        moved.anchorB = Vec2(rod.anchorB.x(), bobAt.y() + std::sqrt(length * length - side * side));
        moved.length = (moved.anchorB - bobAt).norm();
        EXPECT_NEAR(moved.length, length, 1e-12);
        controller::Simulation simulation;
        const Scalar amplitude = std::asin(side / length);
        const Scalar formula = testing::pendulumPeriod(length, g, amplitude);
        const Scalar measured = periodOfUpwardCrossings(simulation, world, 4.5 * formula,
                                                        [&](const model::World& w) { return w.bodies[bob].state.position.x() - moved.anchorB.x(); });
        return std::pair{measured, formula};
    };
    const auto [tStart, formulaStart] = period(rod.length);
    EXPECT_NEAR(rod.length, 1.5, 1e-6); // the bob's position is stored to 6 decimals
    expectAnswerMatches(lesson, 0, tStart, formulaStart);
    // Question 2: the length the student finds for 2 s, checked by running it.
    const Scalar secondsLength = lesson.questions[1].answer;
    const auto [tSeconds, formulaSeconds] = period(secondsLength);
    EXPECT_NEAR(tSeconds, 2.0, 0.002);
    EXPECT_NEAR(formulaSeconds, 2.0, 0.002);
    // A hair under g/π², the small-angle seconds pendulum: the 8.7° swing makes it slower.
    EXPECT_LT(secondsLength, g / (std::numbers::pi * std::numbers::pi));
    const auto [tQuarter, formulaQuarter] = period(rod.length / 4);
    expectAnswerMatches(lesson, 2, tQuarter, formulaQuarter);
    // At 23.6° the small-angle period, half the first, is too short to be accepted.
    EXPECT_FALSE(lesson.questions[2].accepts(2 * std::numbers::pi * std::sqrt(rod.length / 4 / g)));
}

} // namespace
} // namespace impetus
