// A scene's `lesson` block (docs/scene-format.md, "Lessons"): read, refused with the JSON path of
// each problem, written back whole; and the Lesson type's own rules.

#include "model/lesson.h"
#include "model/scene_io.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

namespace impetus::model {
namespace {

/// A scene with a fixed floor and a ball hanging on a spring (spring 0) and a rod (joint 0) from
/// world points, and `lesson` (JSON text) as its lesson, if not empty.
std::string sceneWithLesson(const std::string& lesson)
{
    std::string text = R"({"format":"impetus-scene","version":1,"bodies":[)"
                       R"({"name":"floor","shape":{"type":"box","width":4,"height":0.2},"position":[0,0],"fixed":true},)"
                       R"({"name":"ball","shape":{"type":"circle","radius":0.2},"position":[0,1]}],)"
                       R"("springs":[{"bodyA":"ball","anchorA":[0,0],"anchorB":[0,2],"stiffness":50}],)"
                       R"("joints":[{"type":"rod","bodyA":"ball","anchorA":[0,0],"anchorB":[1,2]}])";
    if (!lesson.empty())
        text += R"(,"lesson":)" + lesson;
    return text + "}";
}

std::string describe(const std::vector<SceneProblem>& problems)
{
    std::string out;
    for (const SceneProblem& problem : problems)
        out += "\n  " + problem.toString();
    return out;
}

/// True when one of `problems` is at `path` and its reason contains `words`.
bool hasProblem(const std::vector<SceneProblem>& problems, const std::string& path, const std::string& words)
{
    for (const SceneProblem& problem : problems) {
        if (problem.path == path && problem.reason.find(words) != std::string::npos)
            return true;
    }
    return false;
}

constexpr const char* kFullLesson = R"({
  "title": "Roll the ball",
  "instructions": "Push it **gently**.",
  "editable": [{"body": "ball", "attributes": ["velocity", "friction"]}],
  "editableWorld": ["gravity"],
  "editableSprings": [{"spring": 0, "attributes": ["stiffness", "restLength"]}],
  "editableJoints": [{"joint": 0, "attributes": ["anchors"]}],
  "questions": [{"prompt": "How far does it roll?", "answer": 1.5, "unit": "m", "tolerance": 0.1},
                {"prompt": "A pure number?", "answer": -2, "tolerance": 0.5}]
})";

TEST(LessonReading, ASceneWithoutALessonHasNone)
{
    const SceneLoadResult result = parseScene(sceneWithLesson(""));
    ASSERT_TRUE(result.ok()) << describe(result.problems);
    EXPECT_FALSE(result.world->lesson.has_value());
    // And writing it adds no lesson key: a scene without a lesson is unchanged by this addition.
    EXPECT_EQ(serializeScene(*result.world).find("\"lesson\""), std::string::npos);
}

TEST(LessonReading, ReadsEveryPart)
{
    const SceneLoadResult result = parseScene(sceneWithLesson(kFullLesson));
    ASSERT_TRUE(result.ok()) << describe(result.problems);
    ASSERT_TRUE(result.world->lesson.has_value());
    const Lesson& lesson = *result.world->lesson;
    EXPECT_EQ(lesson.title, "Roll the ball");
    EXPECT_EQ(lesson.instructions, "Push it **gently**.");
    const BodyId floor{0};
    const BodyId ball{1};
    EXPECT_TRUE(lesson.allows(ball, BodyAttribute::Velocity));
    EXPECT_TRUE(lesson.allows(ball, BodyAttribute::Friction));
    EXPECT_FALSE(lesson.allows(ball, BodyAttribute::Position));
    EXPECT_FALSE(lesson.allows(floor, BodyAttribute::Friction));
    EXPECT_TRUE(lesson.allows(WorldAttribute::Gravity));
    EXPECT_FALSE(lesson.allows(WorldAttribute::TimeStep));
    ASSERT_EQ(lesson.questions.size(), 2u);
    EXPECT_EQ(lesson.questions[0].prompt, "How far does it roll?");
    EXPECT_EQ(lesson.questions[0].answer, 1.5);
    EXPECT_EQ(lesson.questions[0].unit, "m");
    EXPECT_EQ(lesson.questions[0].tolerance, 0.1);
    EXPECT_EQ(lesson.questions[1].unit, "");
}

TEST(LessonReading, OnlyTheTitleIsRequired)
{
    const SceneLoadResult result = parseScene(sceneWithLesson(R"({"title":"Watch"})"));
    ASSERT_TRUE(result.ok()) << describe(result.problems);
    const Lesson& lesson = *result.world->lesson;
    EXPECT_EQ(lesson.title, "Watch");
    EXPECT_TRUE(lesson.instructions.empty());
    EXPECT_TRUE(lesson.editableBodies.empty());
    EXPECT_TRUE(lesson.editableWorld.none());
    EXPECT_TRUE(lesson.questions.empty());
}

TEST(LessonWriting, RoundTripKeepsTheLesson)
{
    const SceneLoadResult first = parseScene(sceneWithLesson(kFullLesson));
    ASSERT_TRUE(first.ok()) << describe(first.problems);
    const std::string text = serializeScene(*first.world);
    const SceneLoadResult second = parseScene(text);
    ASSERT_TRUE(second.ok()) << describe(second.problems) << "\n" << text;
    EXPECT_EQ(second.world->lesson, first.world->lesson);
    EXPECT_EQ(serializeScene(*second.world), text);
}

TEST(LessonReading, ReadsWhichJointsStudentsMayMove)
{
    const SceneLoadResult result = parseScene(sceneWithLesson(kFullLesson));
    ASSERT_TRUE(result.ok()) << describe(result.problems);
    const Lesson& lesson = *result.world->lesson;
    ASSERT_EQ(lesson.editableJoints.size(), 1u);
    EXPECT_TRUE(lesson.allows(std::size_t{0}, JointAttribute::Anchors));
    EXPECT_FALSE(lesson.allows(std::size_t{1}, JointAttribute::Anchors));
    const std::string text = serializeScene(*result.world);
    EXPECT_NE(text.find(R"("editableJoints": [)"), std::string::npos) << text;
    EXPECT_NE(text.find(R"("joint": 0,
        "attributes": ["anchors"])"),
              std::string::npos)
        << text;
    // A lesson without the key locks every joint, and is written with an empty list.
    const SceneLoadResult locked = parseScene(sceneWithLesson(R"({"title":"t"})"));
    ASSERT_TRUE(locked.ok()) << describe(locked.problems);
    EXPECT_TRUE(locked.world->lesson->editableJoints.empty());
    EXPECT_FALSE(locked.world->lesson->allows(std::size_t{0}, JointAttribute::Anchors));
    EXPECT_NE(serializeScene(*locked.world).find(R"("editableJoints": [])"), std::string::npos);
}

TEST(LessonReading, ReadsWhichSpringAttributesStudentsMayChange)
{
    const SceneLoadResult result = parseScene(sceneWithLesson(kFullLesson));
    ASSERT_TRUE(result.ok()) << describe(result.problems);
    const Lesson& lesson = *result.world->lesson;
    ASSERT_EQ(lesson.editableSprings.size(), 1u);
    EXPECT_TRUE(lesson.allows(std::size_t{0}, SpringAttribute::Stiffness));
    EXPECT_TRUE(lesson.allows(std::size_t{0}, SpringAttribute::RestLength));
    EXPECT_FALSE(lesson.allows(std::size_t{0}, SpringAttribute::Damping));
    EXPECT_FALSE(lesson.allows(std::size_t{0}, SpringAttribute::Anchors));
    EXPECT_FALSE(lesson.allows(std::size_t{1}, SpringAttribute::Stiffness));
    const std::string text = serializeScene(*result.world);
    EXPECT_NE(text.find(R"("editableSprings": [)"), std::string::npos) << text;
    EXPECT_NE(text.find(R"("spring": 0,
        "attributes": ["stiffness", "restLength"])"),
              std::string::npos)
        << text;
}

TEST(LessonWriting, FollowsARenamedBodyAndDropsARemovedOne)
{
    SceneLoadResult result = parseScene(sceneWithLesson(kFullLesson));
    ASSERT_TRUE(result.ok()) << describe(result.problems);
    World world = *result.world;
    world.bodies[1].name = "marble";
    SceneLoadResult renamed = parseScene(serializeScene(world));
    ASSERT_TRUE(renamed.ok()) << describe(renamed.problems);
    EXPECT_TRUE(renamed.world->lesson->allows(BodyId{1}, BodyAttribute::Velocity));

    // The floor goes: the ball moves down to index 0 and keeps what it may change.
    world.lesson->removeBodies({true, false});
    world.bodies.erase(world.bodies.begin());
    world.springs[0].bodyA = BodyId{0};
    world.joints[0].bodyA = BodyId{0};
    SceneLoadResult removed = parseScene(serializeScene(world));
    ASSERT_TRUE(removed.ok()) << describe(removed.problems);
    EXPECT_TRUE(removed.world->lesson->allows(BodyId{0}, BodyAttribute::Friction));
    ASSERT_EQ(removed.world->lesson->editableBodies.size(), 1u);
}

/// One bad lesson and the problem it must give.
struct BadLesson {
    const char* name;
    const char* lesson;
    const char* path;
    const char* words;
};

class LessonRefusal : public ::testing::TestWithParam<BadLesson> {};

TEST_P(LessonRefusal, NamesThePathAndTheReason)
{
    const BadLesson& bad = GetParam();
    const SceneLoadResult result = parseScene(sceneWithLesson(bad.lesson));
    EXPECT_FALSE(result.ok());
    EXPECT_FALSE(result.world.has_value());
    EXPECT_TRUE(hasProblem(result.problems, bad.path, bad.words))
        << "wanted " << bad.path << ": …" << bad.words << "…, got" << describe(result.problems);
}

const BadLesson kBadLessons[] = {
    {"not-an-object", R"([1])", "lesson", "expected an object"},
    {"unknown-key", R"({"title":"t","hint":"x"})", "lesson", "unknown key 'hint'"},
    {"missing-title", R"({"instructions":"x"})", "lesson", "missing required key 'title'"},
    {"empty-title", R"({"title":""})", "lesson.title", "must not be empty"},
    {"title-not-a-string", R"({"title":3})", "lesson.title", "expected a string, got 3"},
    {"editable-not-an-array", R"({"title":"t","editable":{}})", "lesson.editable", "expected an array"},
    {"editable-unknown-key", R"({"title":"t","editable":[{"body":"ball","attributes":["angle"],"locked":true}]})",
     "lesson.editable[0]", "unknown key 'locked'"},
    {"editable-unknown-body", R"({"title":"t","editable":[{"body":"bal","attributes":["angle"]}]})",
     "lesson.editable[0].body", "unknown body 'bal'"},
    {"editable-body-twice",
     R"({"title":"t","editable":[{"body":"ball","attributes":["angle"]},{"body":"ball","attributes":["mass"]}]})",
     "lesson.editable[1].body", "listed twice (lesson.editable[0]"},
    {"editable-unknown-attribute", R"({"title":"t","editable":[{"body":"ball","attributes":["colour"]}]})",
     "lesson.editable[0].attributes[0]", "unknown attribute 'colour'"},
    {"editable-attribute-twice", R"({"title":"t","editable":[{"body":"ball","attributes":["angle","angle"]}]})",
     "lesson.editable[0].attributes[1]", "listed twice"},
    {"editable-no-attributes", R"({"title":"t","editable":[{"body":"ball","attributes":[]}]})",
     "lesson.editable[0].attributes", "at least one attribute"},
    {"editable-world-unknown", R"({"title":"t","editableWorld":["wind"]})", "lesson.editableWorld[0]",
     "unknown attribute 'wind'"},
    {"springs-not-an-array", R"({"title":"t","editableSprings":{"spring":0}})", "lesson.editableSprings",
     "expected an array"},
    {"spring-unknown-key", R"({"title":"t","editableSprings":[{"spring":0,"attributes":["damping"],"body":"ball"}]})",
     "lesson.editableSprings[0]", "unknown key 'body'"},
    {"spring-missing-index", R"({"title":"t","editableSprings":[{"attributes":["damping"]}]})",
     "lesson.editableSprings[0]", "missing required key 'spring'"},
    {"spring-out-of-range", R"({"title":"t","editableSprings":[{"spring":1,"attributes":["damping"]}]})",
     "lesson.editableSprings[0].spring", "no spring 1 (the scene has 1 spring, index 0)"},
    {"spring-negative", R"({"title":"t","editableSprings":[{"spring":-1,"attributes":["damping"]}]})",
     "lesson.editableSprings[0].spring", "no spring -1"},
    {"spring-not-whole", R"({"title":"t","editableSprings":[{"spring":0.5,"attributes":["damping"]}]})",
     "lesson.editableSprings[0].spring", "expected the index of a spring (a whole number)"},
    {"spring-by-name", R"({"title":"t","editableSprings":[{"spring":"ball","attributes":["damping"]}]})",
     "lesson.editableSprings[0].spring", "expected the index of a spring"},
    {"spring-twice",
     R"({"title":"t","editableSprings":[{"spring":0,"attributes":["damping"]},{"spring":0,"attributes":["stiffness"]}]})",
     "lesson.editableSprings[1].spring", "spring 0 is listed twice (lesson.editableSprings[0]"},
    {"spring-unknown-attribute", R"({"title":"t","editableSprings":[{"spring":0,"attributes":["length"]}]})",
     "lesson.editableSprings[0].attributes[0]", "unknown attribute 'length' (expected one of: stiffness, damping, restLength, anchors)"},
    {"spring-no-attributes", R"({"title":"t","editableSprings":[{"spring":0,"attributes":[]}]})",
     "lesson.editableSprings[0].attributes", "at least one attribute (leave the spring out to lock it)"},
    {"joints-not-an-array", R"({"title":"t","editableJoints":{"joint":0}})", "lesson.editableJoints",
     "expected an array"},
    {"joint-unknown-key", R"({"title":"t","editableJoints":[{"joint":0,"attributes":["anchors"],"spring":0}]})",
     "lesson.editableJoints[0]", "unknown key 'spring'"},
    {"joint-missing-index", R"({"title":"t","editableJoints":[{"attributes":["anchors"]}]})",
     "lesson.editableJoints[0]", "missing required key 'joint'"},
    {"joint-out-of-range", R"({"title":"t","editableJoints":[{"joint":1,"attributes":["anchors"]}]})",
     "lesson.editableJoints[0].joint", "no joint 1 (the scene has 1 joint, index 0)"},
    {"joint-not-whole", R"({"title":"t","editableJoints":[{"joint":"0","attributes":["anchors"]}]})",
     "lesson.editableJoints[0].joint", "expected the index of a joint (a whole number), got \"0\""},
    {"joint-twice",
     R"({"title":"t","editableJoints":[{"joint":0,"attributes":["anchors"]},{"joint":0,"attributes":["anchors"]}]})",
     "lesson.editableJoints[1].joint", "joint 0 is listed twice (lesson.editableJoints[0]"},
    {"joint-unknown-attribute", R"({"title":"t","editableJoints":[{"joint":0,"attributes":["length"]}]})",
     "lesson.editableJoints[0].attributes[0]", "unknown attribute 'length' (expected one of: anchors)"},
    {"joint-no-attributes", R"({"title":"t","editableJoints":[{"joint":0,"attributes":[]}]})",
     "lesson.editableJoints[0].attributes", "at least one attribute (leave the joint out to lock it)"},
    {"question-not-an-object", R"({"title":"t","questions":["why?"]})", "lesson.questions[0]",
     "expected an object"},
    {"question-unknown-key", R"({"title":"t","questions":[{"prompt":"p","answer":1,"tolerance":1,"hint":"h"}]})",
     "lesson.questions[0]", "unknown key 'hint'"},
    {"question-no-answer", R"({"title":"t","questions":[{"prompt":"p","tolerance":1}]})", "lesson.questions[0]",
     "missing required key 'answer'"},
    {"question-answer-a-string", R"({"title":"t","questions":[{"prompt":"p","answer":"1","tolerance":1}]})",
     "lesson.questions[0].answer", "expected a number"},
    {"question-empty-prompt", R"({"title":"t","questions":[{"prompt":"","answer":1,"tolerance":1}]})",
     "lesson.questions[0].prompt", "must not be empty"},
    {"question-zero-tolerance", R"({"title":"t","questions":[{"prompt":"p","answer":1,"tolerance":0}]})",
     "lesson.questions[0].tolerance", "greater than 0"},
    {"question-no-tolerance", R"({"title":"t","questions":[{"prompt":"p","answer":1}]})", "lesson.questions[0]",
     "missing required key 'tolerance'"},
    {"question-unit-a-number", R"({"title":"t","questions":[{"prompt":"p","answer":1,"tolerance":1,"unit":5}]})",
     "lesson.questions[0].unit", "expected a string"},
    {"answer-too-large", R"({"title":"t","questions":[{"prompt":"p","answer":1e999,"tolerance":1}]})",
     "lesson.questions[0].answer", "out of range"},
};

std::string badLessonName(const ::testing::TestParamInfo<BadLesson>& param)
{
    std::string name = param.param.name;
    for (char& c : name)
        c = c == '-' ? '_' : c;
    return name;
}

INSTANTIATE_TEST_SUITE_P(Bad, LessonRefusal, ::testing::ValuesIn(kBadLessons), badLessonName);

TEST(LessonRefusal, ASceneWithoutSpringsSaysSo)
{
    std::string text = sceneWithLesson(R"({"title":"t","editableSprings":[{"spring":0,"attributes":["damping"]}]})");
    const std::string springs = R"("springs":[{"bodyA":"ball","anchorA":[0,0],"anchorB":[0,2],"stiffness":50}])";
    text.replace(text.find(springs), springs.size(), R"("springs":[])");
    const SceneLoadResult result = parseScene(text);
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(hasProblem(result.problems, "lesson.editableSprings[0].spring", "no spring 0 (the scene has no springs)"))
        << describe(result.problems);
}

TEST(LessonRefusal, ReportsEveryProblemAtOnce)
{
    const SceneLoadResult result = parseScene(sceneWithLesson(
        R"({"title":"","editable":[{"body":"nobody","attributes":["angle"]}],"questions":[{"prompt":"p","answer":1,"tolerance":-1}]})"));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(hasProblem(result.problems, "lesson.title", "must not be empty"));
    EXPECT_TRUE(hasProblem(result.problems, "lesson.editable[0].body", "unknown body"));
    EXPECT_TRUE(hasProblem(result.problems, "lesson.questions[0].tolerance", "greater than 0"));
}

TEST(LessonRefusal, DuplicateKeysInsideTheLessonAreFound)
{
    const SceneLoadResult result =
        parseScene(sceneWithLesson(R"({"title":"a","questions":[{"prompt":"p","prompt":"q","answer":1,"tolerance":1}]})"));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(hasProblem(result.problems, "lesson.questions[0]", "duplicate key 'prompt'")) << describe(result.problems);
}

// ---- The Lesson type ----------------------------------------------------------------------------

TEST(LessonType, QuestionAcceptsWithinTheToleranceOnly)
{
    const LessonQuestion question{"angle?", 26.57, "°", 1.0};
    EXPECT_TRUE(question.accepts(26.57));
    EXPECT_TRUE(question.accepts(27.5));
    EXPECT_TRUE(question.accepts(25.6));
    EXPECT_FALSE(question.accepts(27.6));
    EXPECT_FALSE(question.accepts(25.5));
    EXPECT_FALSE(question.accepts(std::numeric_limits<double>::quiet_NaN()));
    EXPECT_FALSE(question.accepts(std::numeric_limits<double>::infinity()));
}

TEST(LessonType, SetEditableKeepsEntriesSortedAndDropsEmptyOnes)
{
    Lesson lesson;
    BodyAttributes angle;
    angle.set(static_cast<std::size_t>(BodyAttribute::Angle));
    lesson.setEditable(BodyId{3}, angle);
    lesson.setEditable(BodyId{1}, angle);
    ASSERT_EQ(lesson.editableBodies.size(), 2u);
    EXPECT_EQ(lesson.editableBodies[0].body, BodyId{1});
    EXPECT_EQ(lesson.editableBodies[1].body, BodyId{3});
    lesson.setEditable(BodyId{1}, BodyAttributes());
    ASSERT_EQ(lesson.editableBodies.size(), 1u);
    EXPECT_EQ(lesson.editableBodies[0].body, BodyId{3});
    EXPECT_TRUE(lesson.allows(BodyId{3}, BodyAttribute::Angle));
    EXPECT_FALSE(lesson.allows(BodyId{3}, BodyAttribute::Position));
}

TEST(LessonType, ChangedAttributesNamesWhatAnEditChanges)
{
    Body before;
    before.name = "block";
    before.shape = Box{1, 1};
    before.updateDerived();
    Body after = before;
    EXPECT_TRUE(changedAttributes(before, after).none());
    after.material.friction = 0.9;
    after.state.angle = 0.3;
    after.massSpec = MassSpec{MassMode::Mass, 2};
    after.updateDerived();
    const BodyAttributes changed = changedAttributes(before, after);
    EXPECT_EQ(changed.count(), 3u);
    EXPECT_TRUE(changed.test(static_cast<std::size_t>(BodyAttribute::Friction)));
    EXPECT_TRUE(changed.test(static_cast<std::size_t>(BodyAttribute::Angle)));
    EXPECT_TRUE(changed.test(static_cast<std::size_t>(BodyAttribute::Mass)));

    WorldSettings settings;
    WorldSettings moon = settings;
    moon.gravity = Vec2(0, -1.62);
    const WorldAttributes world = changedAttributes(settings, moon);
    EXPECT_EQ(world.count(), 1u);
    EXPECT_TRUE(world.test(static_cast<std::size_t>(WorldAttribute::Gravity)));
}

TEST(LessonType, AttributeNamesReadBack)
{
    for (const BodyAttribute attribute : kBodyAttributes)
        EXPECT_EQ(bodyAttributeFromName(attributeName(attribute)), attribute);
    for (const WorldAttribute attribute : kWorldAttributes)
        EXPECT_EQ(worldAttributeFromName(attributeName(attribute)), attribute);
    for (const SpringAttribute attribute : kSpringAttributes)
        EXPECT_EQ(springAttributeFromName(attributeName(attribute)), attribute);
    EXPECT_FALSE(bodyAttributeFromName("colour").has_value());
    EXPECT_FALSE(springAttributeFromName("length").has_value());
}

// Springs are listed by index: removing springs drops their entries and renumbers the rest, as
// removing bodies does for bodies. An edit names what it changed; moving a spring to other bodies
// is not an attribute at all.
TEST(LessonType, SpringEntriesFollowRemovalsAndEditsNameTheirAttributes)
{
    Lesson lesson;
    SpringAttributes stiffness;
    stiffness.set(static_cast<std::size_t>(SpringAttribute::Stiffness));
    SpringAttributes damping;
    damping.set(static_cast<std::size_t>(SpringAttribute::Damping));
    lesson.setEditableSpring(3, stiffness);
    lesson.setEditableSpring(1, damping);
    lesson.setEditableSpring(2, stiffness);
    lesson.setEditableSpring(2, SpringAttributes());
    ASSERT_EQ(lesson.editableSprings.size(), 2u);
    EXPECT_EQ(lesson.editableSprings[0].spring, 1u);
    EXPECT_EQ(lesson.editableSprings[1].spring, 3u);
    lesson.removeSprings({true, true, false, false});
    ASSERT_EQ(lesson.editableSprings.size(), 1u);
    EXPECT_EQ(lesson.editableSprings[0].spring, 1u);
    EXPECT_TRUE(lesson.allows(std::size_t{1}, SpringAttribute::Stiffness));

    Spring before;
    Spring after = before;
    EXPECT_TRUE(changedAttributes(before, after).none());
    after.restLength = 2;
    after.anchorB = Vec2(1, 0);
    const SpringAttributes changed = changedAttributes(before, after);
    EXPECT_EQ(changed.count(), 2u);
    EXPECT_TRUE(changed.test(static_cast<std::size_t>(SpringAttribute::RestLength)));
    EXPECT_TRUE(changed.test(static_cast<std::size_t>(SpringAttribute::Anchors)));
    EXPECT_FALSE(changesEnds(before, after));
    after.bodyB = BodyId{1};
    EXPECT_TRUE(changesEnds(before, after));
}

// Joints too are listed by index. Moving a rod's end or a pin's hinge changes its anchors (a
// pin's derived anchors and a rod's length with them); another type or other bodies is not an
// attribute.
TEST(LessonType, JointEntriesFollowRemovalsAndEditsNameTheirAttributes)
{
    EXPECT_EQ(attributeName(JointAttribute::Anchors), "anchors");
    EXPECT_EQ(jointAttributeFromName("anchors"), JointAttribute::Anchors);
    EXPECT_FALSE(jointAttributeFromName("hinge").has_value());
    Lesson lesson;
    JointAttributes anchors;
    anchors.set(static_cast<std::size_t>(JointAttribute::Anchors));
    lesson.setEditableJoint(2, anchors);
    lesson.setEditableJoint(0, anchors);
    lesson.setEditableJoint(0, JointAttributes());
    ASSERT_EQ(lesson.editableJoints.size(), 1u);
    lesson.removeJoints({true, false, false});
    ASSERT_EQ(lesson.editableJoints.size(), 1u);
    EXPECT_EQ(lesson.editableJoints[0].joint, 1u);
    EXPECT_TRUE(lesson.allows(std::size_t{1}, JointAttribute::Anchors));
    lesson.removeJoints({false, true});
    EXPECT_TRUE(lesson.editableJoints.empty());

    Joint before;
    before.type = JointType::Rod;
    before.anchorB = Vec2(0, 2);
    before.length = 2;
    Joint after = before;
    EXPECT_TRUE(changedAttributes(before, after).none());
    after.impulse = Vec2(3, 0); // the solver's state, not an attribute
    EXPECT_TRUE(changedAttributes(before, after).none());
    after.anchorB = Vec2(0, 3);
    after.length = 3;
    EXPECT_TRUE(changedAttributes(before, after).test(static_cast<std::size_t>(JointAttribute::Anchors)));
    EXPECT_FALSE(changesEnds(before, after));
    after.type = JointType::Pin;
    EXPECT_TRUE(changesEnds(before, after));
    after = before;
    after.bodyB = BodyId{1};
    EXPECT_TRUE(changesEnds(before, after));
}

} // namespace
} // namespace impetus::model
