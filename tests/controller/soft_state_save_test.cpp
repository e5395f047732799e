// Saving a soft body mid-run (issue 16, item 5): the file keeps every ellipse's position and
// velocity (scene key `soft.state`), so that the loaded scene continues exactly where the run was.

#include "controller/simulation.h"
#include "controller/soft/soft_body_builder.h"
#include "controller/solver_under_test.h"
#include "model/constants.h"
#include "model/scene_io.h"
#include "support/world_builders.h"

#include <gtest/gtest.h>

#include <string>

namespace impetus {
namespace {

using testing::makeBox;
using testing::makeEmptyWorld;
using testing::makeGround;
using testing::withMaterial;

/// A soft box thrown spinning at a wall of fixed ground, so that its grid wobbles and its ellipses
/// touch the ground while it is saved.
model::World wobblingSoftBox()
{
    model::World world = makeEmptyWorld(model::IntegratorKind::Rk4, constants::kDefaultTimeStep,
                                        Vec2(0, -constants::kStandardGravity));
    world.bodies.push_back(withMaterial(makeGround("ground", 20, 1), 0, 0.5));
    model::Body box = makeBox("jelly", 1, 1, 0.5, Vec2(0, 0.6), 0.3);
    box.state.velocity = Vec2(1, -2);
    box.state.angularVelocity = 2;
    box.soft = model::SoftSettings{};
    world.bodies.push_back(box);
    return world;
}

void step(controller::Simulation& simulation, model::World& world, int steps)
{
    for (int i = 0; i < steps; ++i)
        simulation.step(world);
}

TEST(SoftStateSave, ARunSavedMidwayContinuesExactlyAfterLoading)
{
    model::World running = wobblingSoftBox();
    controller::Simulation simulation(controller::settingsUnderTest());
    step(simulation, running, 60); // 0.25 s: it has landed and is squashed
    ASSERT_FALSE(running.softBodies.at(0).rigidCopy);

    const std::string saved = model::serializeScene(running);
    ASSERT_NE(saved.find("\"state\""), std::string::npos);
    model::SceneLoadResult loaded = model::parseScene(saved);
    ASSERT_TRUE(loaded.ok()) << loaded.problems.front().toString();
    model::World restored = std::move(*loaded.world);
    controller::prepareSoftBodies(restored);
    ASSERT_EQ(restored.softBodies.size(), 1u);
    EXPECT_EQ(restored.softBodies[0].positions, running.softBodies[0].positions);
    EXPECT_EQ(restored.softBodies[0].velocities, running.softBodies[0].velocities);
    EXPECT_FALSE(restored.bodies[1].softState.has_value()); // applied once, then dropped

    // Both go on for 0.5 s, the restored one with a fresh Simulation, as a reopened file would.
    controller::Simulation fresh(controller::settingsUnderTest());
    step(simulation, running, 120);
    step(fresh, restored, 120);
    const model::SoftGrid& a = running.softBodies[0];
    const model::SoftGrid& b = restored.softBodies[0];
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_NEAR((a.positions[i] - b.positions[i]).norm(), 0, 1e-12) << "ellipse " << i;
        EXPECT_NEAR((a.velocities[i] - b.velocities[i]).norm(), 0, 1e-12) << "ellipse " << i;
    }
    EXPECT_NEAR((running.bodies[1].state.position - restored.bodies[1].state.position).norm(), 0, 1e-12);
}

TEST(SoftStateSave, AStateThatDoesNotFitTheGridGivesAFreshGrid)
{
    // A state with a different ellipse count (the file was saved at another density, or edited)
    // cannot be put on the grid: the body starts as a rigid copy of its state, as without one.
    model::World world = wobblingSoftBox();
    world.bodies[1].softState = model::SoftGridState{{Vec2(0, 1)}, {Vec2(0, 0)}};
    controller::prepareSoftBodies(world);
    EXPECT_TRUE(world.softBodies.at(0).rigidCopy);
    EXPECT_GT(world.softBodies[0].size(), 1u);
    EXPECT_FALSE(world.bodies[1].softState.has_value());
}

TEST(SoftStateSave, AGridThatHasNotMovedIsNotWritten)
{
    // A scene opened and saved again without a run keeps its file as it was: no `state`.
    model::World world = wobblingSoftBox();
    controller::prepareSoftBodies(world);
    EXPECT_EQ(model::serializeScene(world).find("\"state\""), std::string::npos);
}

} // namespace
} // namespace impetus
