// SceneDocument: every edit is one undoable command, removal re-indexes, runs undo to their start.

#include "model/scene_io.h"
#include "test_worlds.h"
#include "view/scene_document.h"
#include "view/scene_loading.h"
#include "view/simulation_runner.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using impetus::Vec2;
using impetus::view::BodyPose;
using impetus::view::SceneDocument;
using impetus::view::Selection;
namespace model = impetus::model;
namespace test = impetus::view::test;

namespace {

/// Three free boxes a, b, c; a spring a–c, a spring b–world, a rod b–c and a pin c–world.
model::World threeBodyWorld()
{
    model::World world;
    world.settings.gravity = Vec2::Zero();
    world.bodies.push_back(test::makeBody("a", model::Box{0.5, 0.5}, Vec2(0, 0)));
    world.bodies.push_back(test::makeBody("b", model::Box{0.5, 0.5}, Vec2(2, 0)));
    world.bodies.push_back(test::makeBody("c", model::Box{0.5, 0.5}, Vec2(4, 0)));
    model::Spring ac;
    ac.bodyA = model::BodyId{0};
    ac.bodyB = model::BodyId{2};
    ac.restLength = 4;
    model::Spring bWorld;
    bWorld.bodyA = model::BodyId{1};
    bWorld.anchorB = Vec2(2, 3);
    bWorld.restLength = 3;
    world.springs = {ac, bWorld};
    model::Joint rod;
    rod.type = model::JointType::Rod;
    rod.bodyA = model::BodyId{1};
    rod.bodyB = model::BodyId{2};
    rod.length = 2; // centre to centre, as loading would derive it
    model::Joint pin;
    pin.type = model::JointType::Pin;
    pin.bodyA = model::BodyId{2};
    pin.worldAnchor = Vec2(4, 0); // c's centre: anchorA is zero, anchorB is the world point
    pin.anchorB = Vec2(4, 0);
    world.joints = {rod, pin};
    return world;
}

/// The parts of a world an edit may change (not time, contacts or collision counters).
bool sameScene(const model::World& a, const model::World& b)
{
    return a.settings == b.settings && a.bodies == b.bodies && a.springs == b.springs && a.joints == b.joints;
}

} // namespace

class SceneDocumentTest : public QObject {
    Q_OBJECT

private slots:
    void setBodyUndoesAndRedoes();
    void setBodyRecomputesDerivedFields();
    void removingBodyTakesItsSpringsAndJointsAndReindexes();
    void removingSpringAloneKeepsBodies();
    void consecutivePosesOfOneGestureMerge();
    void runUndoesBackToItsStart();
    void stepsMergeAndUndo();
    void resetIsUndoable();
    void editWhileRunningKeepsRunning();
    void worldSettingsUndo();
    void uniqueNamesCountUp();
    void modifiedFollowsTheUndoStack();
    void runAloneIsNotUnsavedWork();
    void saveAndLoadRoundTrip();
    void selectionDropsInvalidIndices();
    void movedPinnedBodySavesItsHinge();
};

void SceneDocumentTest::setBodyUndoesAndRedoes()
{
    SceneDocument document;
    document.setScene(threeBodyWorld(), QString(), QStringLiteral("three"));
    const model::World before = document.world();
    model::Body changed = document.world().bodies[1];
    changed.material.restitution = 0.9;
    document.setBody(1, changed, QStringLiteral("Change restitution"));
    QCOMPARE(document.world().bodies[1].material.restitution, 0.9);
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Change restitution"));

    document.undoStack()->undo();
    QVERIFY(sameScene(document.world(), before));
    document.undoStack()->redo();
    QCOMPARE(document.world().bodies[1].material.restitution, 0.9);
}

void SceneDocumentTest::setBodyRecomputesDerivedFields()
{
    SceneDocument document;
    document.setScene(threeBodyWorld(), QString(), QStringLiteral("three"));
    model::Body bigger = document.world().bodies[0];
    bigger.shape = model::Box{2, 1};
    bigger.massSpec = model::MassSpec{model::MassMode::Density, 3};
    document.setBody(0, bigger, QStringLiteral("Resize"));
    const model::Body& body = document.world().bodies[0];
    QCOMPARE(body.area, 2.0);
    QCOMPARE(body.mass, 6.0);
    // I = m(w² + h²)/12 for a rectangle about its centre.
    QVERIFY(qAbs(body.inertia - 6.0 * (4 + 1) / 12) < 1e-12);
}

void SceneDocumentTest::removingBodyTakesItsSpringsAndJointsAndReindexes()
{
    SceneDocument document;
    document.setScene(threeBodyWorld(), QString(), QStringLiteral("three"));
    const model::World before = document.world();

    document.remove(Selection{{1}, {}, {}}, QStringLiteral("Delete"));
    const model::World& after = document.world();
    QCOMPARE(after.bodies.size(), std::size_t(2));
    QCOMPARE(after.bodies[0].name, std::string("a"));
    QCOMPARE(after.bodies[1].name, std::string("c"));
    // The spring a–c stays and now names c by its new index; b's spring and rod went with b.
    QCOMPARE(after.springs.size(), std::size_t(1));
    QCOMPARE(after.springs[0].bodyA.index, 0u);
    QCOMPARE(after.springs[0].bodyB->index, 1u);
    QCOMPARE(after.joints.size(), std::size_t(1));
    QVERIFY(after.joints[0].type == model::JointType::Pin);
    QCOMPARE(after.joints[0].bodyA.index, 1u);

    document.undoStack()->undo();
    QVERIFY(sameScene(document.world(), before));
    document.undoStack()->redo();
    QCOMPARE(document.world().bodies.size(), std::size_t(2));
    QCOMPARE(document.world().springs[0].bodyB->index, 1u);
}

void SceneDocumentTest::removingSpringAloneKeepsBodies()
{
    SceneDocument document;
    document.setScene(threeBodyWorld(), QString(), QStringLiteral("three"));
    const model::World before = document.world();
    document.remove(Selection{{}, {0}, {1}}, QStringLiteral("Delete"));
    QCOMPARE(document.world().bodies.size(), std::size_t(3));
    QCOMPARE(document.world().springs.size(), std::size_t(1));
    QCOMPARE(document.world().springs[0].bodyA.index, 1u);
    QCOMPARE(document.world().joints.size(), std::size_t(1));
    QVERIFY(document.world().joints[0].type == model::JointType::Rod);
    document.undoStack()->undo();
    QVERIFY(sameScene(document.world(), before));
}

void SceneDocumentTest::consecutivePosesOfOneGestureMerge()
{
    SceneDocument document;
    document.setScene(threeBodyWorld(), QString(), QStringLiteral("three"));
    const int drag = document.newGesture();
    document.setPoses({0}, {BodyPose{Vec2(0.5, 0), 0}}, QStringLiteral("Move"), drag);
    document.setPoses({0}, {BodyPose{Vec2(1.0, 0.5), 0}}, QStringLiteral("Move"), drag);
    QCOMPARE(document.undoStack()->count(), 1);
    QCOMPARE(document.world().bodies[0].state.position, Vec2(1.0, 0.5));

    document.setPoses({0}, {BodyPose{Vec2(2, 2), 1}}, QStringLiteral("Move"), document.newGesture());
    QCOMPARE(document.undoStack()->count(), 2);
    document.undoStack()->undo();
    QCOMPARE(document.world().bodies[0].state.position, Vec2(1.0, 0.5));
    document.undoStack()->undo();
    QCOMPARE(document.world().bodies[0].state.position, Vec2(0, 0));
}

void SceneDocumentTest::runUndoesBackToItsStart()
{
    SceneDocument document;
    model::World world = test::risingBallWorld();
    document.setScene(world, QString(), QStringLiteral("rising"));
    const model::World start = document.world();

    document.runner().play();
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Run"));
    document.runner().advanceWallTime(0.25);
    document.runner().pause();
    const model::World ran = document.world();
    QVERIFY(ran.time > 0);

    document.undoStack()->undo();
    QVERIFY(document.world() == start);
    document.undoStack()->redo();
    QVERIFY(document.world() == ran);
}

void SceneDocumentTest::stepsMergeAndUndo()
{
    SceneDocument document;
    document.setScene(test::risingBallWorld(), QString(), QStringLiteral("rising"));
    const model::World start = document.world();
    document.stepOnce();
    document.stepOnce();
    document.stepOnce();
    QCOMPARE(document.world().stepCount, std::int64_t(3));
    QCOMPARE(document.undoStack()->count(), 1);
    document.undoStack()->undo();
    QVERIFY(document.world() == start);
    document.undoStack()->redo();
    QCOMPARE(document.world().stepCount, std::int64_t(3));
}

void SceneDocumentTest::resetIsUndoable()
{
    SceneDocument document;
    document.setScene(test::risingBallWorld(), QString(), QStringLiteral("rising"));
    const model::World start = document.world();
    document.runner().play();
    document.runner().advanceWallTime(0.1);
    document.runner().pause();
    const model::World ran = document.world();

    document.resetToLastPlay();
    QVERIFY(document.world() == start);
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Reset"));
    document.undoStack()->undo();
    QVERIFY(document.world() == ran);
}

void SceneDocumentTest::editWhileRunningKeepsRunning()
{
    SceneDocument document;
    document.setScene(test::risingBallWorld(), QString(), QStringLiteral("rising"));
    document.runner().play();
    document.runner().advanceWallTime(0.05);
    model::Body ball = document.world().bodies[0];
    ball.material.friction = 0.1;
    document.setBody(0, ball, QStringLiteral("Change friction"));
    QVERIFY(document.runner().isRunning());
    QCOMPARE(document.world().bodies[0].material.friction, 0.1);
    const std::int64_t steps = document.world().stepCount;
    document.runner().advanceWallTime(0.05);
    QVERIFY(document.world().stepCount > steps);
    QCOMPARE(document.world().bodies[0].material.friction, 0.1);
    document.runner().pause();
}

void SceneDocumentTest::worldSettingsUndo()
{
    SceneDocument document;
    document.setScene(threeBodyWorld(), QString(), QStringLiteral("three"));
    model::WorldSettings settings = document.world().settings;
    settings.gravity = Vec2(0, -1.62);
    settings.integrator = model::IntegratorKind::Euler;
    document.setWorldSettings(settings, QStringLiteral("Moon gravity"));
    QCOMPARE(document.world().settings.gravity, Vec2(0, -1.62));
    document.undoStack()->undo();
    QCOMPARE(document.world().settings.gravity, Vec2::Zero());
    QVERIFY(document.world().settings.integrator == model::IntegratorKind::Rk4);
}

void SceneDocumentTest::uniqueNamesCountUp()
{
    SceneDocument document;
    QCOMPARE(document.uniqueBodyName(QStringLiteral("box")), QStringLiteral("box 1"));
    model::Body box;
    box.shape = model::Box{1, 1};
    box.name = "box 1";
    document.addBody(box, QStringLiteral("Draw box"));
    box.name = "box 3";
    document.addBody(box, QStringLiteral("Draw box"));
    QCOMPARE(document.uniqueBodyName(QStringLiteral("box")), QStringLiteral("box 2"));
    QCOMPARE(document.selection(), (Selection{{1}, {}, {}}));
}

void SceneDocumentTest::modifiedFollowsTheUndoStack()
{
    SceneDocument document;
    document.setScene(threeBodyWorld(), QString(), QStringLiteral("three"));
    QSignalSpy modified(&document, &SceneDocument::modifiedChanged);
    QVERIFY(!document.isModified());
    document.remove(Selection{{0}, {}, {}}, QStringLiteral("Delete"));
    QVERIFY(document.isModified());
    QVERIFY(document.hasUnsavedEdits());
    document.undoStack()->undo();
    QVERIFY(!document.isModified());
    QVERIFY(!document.hasUnsavedEdits());
    QCOMPARE(modified.count(), 2);
}

void SceneDocumentTest::runAloneIsNotUnsavedWork()
{
    SceneDocument document;
    document.setScene(test::risingBallWorld(), QString(), QStringLiteral("rising"));
    document.runner().play();
    document.runner().advanceWallTime(0.05);
    document.runner().pause();
    document.stepOnce();
    QVERIFY(document.isModified());
    QVERIFY(!document.hasUnsavedEdits());
    model::Body ball = document.world().bodies[0];
    ball.color = model::Color{1, 2, 3};
    document.setBody(0, ball, QStringLiteral("Colour"));
    QVERIFY(document.hasUnsavedEdits());
}

void SceneDocumentTest::saveAndLoadRoundTrip()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("three.json"));
    SceneDocument document;
    document.setScene(threeBodyWorld(), QString(), QStringLiteral("three"));
    model::Body moved = document.world().bodies[2];
    moved.state.angle = 0.3;
    document.setBody(2, moved, QStringLiteral("Turn"));
    QVERIFY(document.isModified());

    QVERIFY(!document.saveAs(path).has_value());
    QVERIFY(!document.isModified());
    QCOMPARE(document.filePath(), path);
    QCOMPARE(document.displayName(), QStringLiteral("three"));

    const model::SceneLoadResult loaded = impetus::view::loadScene(path);
    QVERIFY(loaded.ok());
    QCOMPARE(model::serializeScene(*loaded.world), model::serializeScene(document.world()));
    QCOMPARE(loaded.world->bodies[2].state.angle, 0.3);

    // A folder that does not exist: an error, and the document keeps its file and state.
    const std::optional<QString> error = document.saveAs(dir.filePath(QStringLiteral("missing/x.json")));
    QVERIFY(error.has_value());
    QVERIFY(!error->isEmpty());
    QCOMPARE(document.filePath(), path);
}

void SceneDocumentTest::selectionDropsInvalidIndices()
{
    SceneDocument document;
    document.setScene(threeBodyWorld(), QString(), QStringLiteral("three"));
    QSignalSpy changed(&document, &SceneDocument::selectionChanged);
    document.setSelection(Selection{{2, 0, 7, 2}, {5}, {1}});
    QCOMPARE(document.selection(), (Selection{{0, 2}, {}, {1}}));
    QCOMPARE(changed.count(), 1);
    document.remove(Selection{{2}, {}, {}}, QStringLiteral("Delete"));
    QVERIFY(document.selection().empty());
}

void SceneDocumentTest::movedPinnedBodySavesItsHinge()
{
    // Two boxes pinned together at (1, 0.5); both are then moved up by 2 m.
    model::World world;
    world.bodies.push_back(test::makeBody("a", model::Box{1, 1}, Vec2(0, 0)));
    world.bodies.push_back(test::makeBody("b", model::Box{1, 1}, Vec2(2, 0)));
    const model::Joint pin = test::pinAt(world, model::BodyId{0}, model::BodyId{1}, Vec2(1, 0.5));
    world.joints.push_back(pin);
    SceneDocument document;
    document.setScene(world, QString(), QStringLiteral("pinned"));
    document.setPoses({0, 1}, {BodyPose{Vec2(0, 2), 0}, BodyPose{Vec2(2, 2), 0}}, QStringLiteral("Move"),
                      document.newGesture());

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("pinned.json"));
    QVERIFY(!document.saveAs(path).has_value());
    const model::SceneLoadResult loaded = impetus::view::loadScene(path);
    QVERIFY(loaded.ok());
    const model::Joint& reloaded = loaded.world->joints.at(0);
    QCOMPARE(reloaded.worldAnchor, Vec2(1, 2.5));
    QVERIFY((reloaded.anchorA - pin.anchorA).norm() < 1e-12);
    QVERIFY((reloaded.anchorB - pin.anchorB).norm() < 1e-12);
    // The document's own joint is untouched by saving.
    QCOMPARE(document.world().joints[0].worldAnchor, Vec2(1, 0.5));
}

QTEST_MAIN(SceneDocumentTest)
#include "scene_document_test.moc"
