// Scene files: the public contract's section 1, as docs/scene-format.md describes it.

#include "model/scene_io.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace impetus::model {
namespace {

namespace fs = std::filesystem;

const fs::path kDataDir = IMPETUS_SCENE_TEST_DATA;

std::string readText(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void writeText(const fs::path& path, std::string_view text)
{
    std::ofstream out(path, std::ios::binary);
    out << text;
}

std::string describeProblems(const std::vector<SceneProblem>& problems)
{
    std::string out;
    for (const SceneProblem& problem : problems)
        out += "\n  " + problem.toString();
    return out.empty() ? std::string(" (none)") : out;
}

// ------------------------------------------------------------------------------------------------
// Building scene text for the tables below

/// A whole scene around the given `bodies`, `springs`, `joints` and `world` JSON.
std::string scene(const std::string& bodies, const std::string& springs = "[]", const std::string& joints = "[]",
                  const std::string& world = "{}")
{
    return R"({"format":"impetus-scene","version":1,"world":)" + world + R"(,"bodies":)" + bodies +
           R"(,"springs":)" + springs + R"(,"joints":)" + joints + "}";
}

/// A valid dynamic circle called "ball"; `extra` adds keys (with a leading comma).
std::string ballBody(const std::string& extra = "")
{
    return R"({"name":"ball","shape":{"type":"circle","radius":0.5},"position":[0,2])" + extra + "}";
}

/// A valid fixed box called "floor".
const std::string kFloor = R"({"name":"floor","shape":{"type":"box","width":10,"height":1},"position":[0,-0.5],"fixed":true})";

/// A scene with one body: "ball" plus `extra` keys.
std::string ballScene(const std::string& extra) { return scene("[" + ballBody(extra) + "]"); }

/// A scene with one body called "thing" of the given shape.
std::string shapeScene(const std::string& shape)
{
    return scene(R"([{"name":"thing","shape":)" + shape + R"(,"position":[0,0]}])");
}

std::string polygonScene(const std::string& vertices)
{
    return shapeScene(R"({"type":"polygon","vertices":)" + vertices + "}");
}

/// A scene with "ball" and "floor" and the given springs and joints.
std::string pairScene(const std::string& springs, const std::string& joints = "[]")
{
    return scene("[" + ballBody() + "," + kFloor + "]", springs, joints);
}

/// The root keys a scene needs, for cases that vary the root itself.
const std::string kHeader = R"("format":"impetus-scene","version":1)";

// ------------------------------------------------------------------------------------------------
// Bad input: every class of problem the contract lists, each with its exact path and reason.

struct BadSceneCase {
    std::string name;
    std::string json;
    std::string path; ///< the exact path of the expected problem
    std::string phrase; ///< a phrase its reason must contain
    std::size_t problemCount = 1; ///< how many problems the scene has in all
};

void PrintTo(const BadSceneCase& c, std::ostream* out) { *out << c.name; }

class BadScene : public ::testing::TestWithParam<BadSceneCase> {};

TEST_P(BadScene, IsRefusedWithPathAndReason)
{
    const BadSceneCase& c = GetParam();
    SceneLoadResult result;
    ASSERT_NO_THROW(result = parseScene(c.json));
    EXPECT_FALSE(result.ok());
    EXPECT_FALSE(result.world.has_value());
    const bool found = std::any_of(result.problems.begin(), result.problems.end(), [&](const SceneProblem& p) {
        return p.path == c.path && p.reason.find(c.phrase) != std::string::npos;
    });
    EXPECT_TRUE(found) << "expected  " << c.path << ": …" << c.phrase << "…\ngot" << describeProblems(result.problems);
    EXPECT_EQ(result.problems.size(), c.problemCount) << describeProblems(result.problems);
}

const BadSceneCase kBadScenes[] = {
    // The document
    {"broken_json", "{\"format\": \"impetus-scene\",\n \"version\": 1,,\n \"bodies\": []}", "(root)",
     "invalid JSON at line 2, column 15: syntax error"},
    {"empty_document", "", "(root)", "invalid JSON at line 1, column 1"},
    {"trailing_text", scene("[]") + "\n}", "(root)", "invalid JSON at line 2, column 1"},
    {"invalid_utf8", scene(R"([{"name":")" + std::string("\xff") + R"(","shape":{"type":"circle","radius":1},"position":[0,0]}])"),
     "(root)", "invalid JSON"},
    {"root_not_object", "[1, 2]", "(root)", "expected a JSON object (a scene), got an array of 2 values"},
    {"unknown_root_key", "{" + kHeader + R"(,"bodies":[],"gravity":[0,-1]})", "(root)", "unknown key 'gravity'"},
    {"duplicate_key", R"({"format":"impetus-scene","version":1,"version":1,"bodies":[]})", "(root)",
     "duplicate key 'version'"},
    {"missing_format", R"({"version":1,"bodies":[]})", "(root)", "missing required key 'format'"},
    {"wrong_format", R"({"format":"box2d-scene","version":1,"bodies":[]})", "format",
     "not an Impetus scene: format is \"box2d-scene\", expected \"impetus-scene\""},
    {"format_not_string", R"({"format":1,"version":1,"bodies":[]})", "format", "expected a string, got 1"},
    {"missing_version", R"({"format":"impetus-scene","bodies":[]})", "(root)", "missing required key 'version'"},
    {"newer_version", R"({"format":"impetus-scene","version":2,"bodies":[]})", "version",
     "version 2 is newer than this build reads (version 1)"},
    {"older_version", R"({"format":"impetus-scene","version":0,"bodies":[]})", "version",
     "unsupported version 0 (this build reads version 1)"},
    {"version_not_integer", R"({"format":"impetus-scene","version":1.5,"bodies":[]})", "version",
     "expected an integer, got 1.5"},
    {"version_string", R"({"format":"impetus-scene","version":"1","bodies":[]})", "version",
     "expected an integer, got \"1\""},
    {"missing_bodies", "{" + kHeader + "}", "(root)", "missing required key 'bodies'"},
    {"bodies_not_array", "{" + kHeader + R"(,"bodies":{}})", "bodies", "expected an array, got an object"},
    {"springs_not_array", scene("[]", "null"), "springs", "expected an array, got null"},
    {"joints_not_array", scene("[]", "[]", "7"), "joints", "expected an array, got 7"},

    // Numbers JSON can hold but a double cannot
    {"infinite_number", shapeScene(R"({"type":"circle","radius":1e999})"), "bodies[0].shape.radius",
     "number 1e999 is out of range"},
    {"negative_infinite_number", scene(R"([{"name":"a","shape":{"type":"circle","radius":1},"position":[-1e999,0]}])"),
     "bodies[0].position[0]", "number -1e999 is out of range"},
    {"infinite_time_step", scene("[]", "[]", "[]", R"({"timeStep":2e308})"), "world.timeStep", "out of range"},

    // world
    {"world_not_object", scene("[]", "[]", "[]", "[]"), "world", "expected an object, got an empty array"},
    {"world_unknown_key", scene("[]", "[]", "[]", R"({"gravty":[0,-1]})"), "world",
     "unknown key 'gravty' (did you mean 'gravity'?)"},
    {"gravity_wrong_length", scene("[]", "[]", "[]", R"({"gravity":[0,-9.81,0]})"), "world.gravity",
     "expected an array of 2 numbers [x, y], got an array of 3 values"},
    {"gravity_not_number", scene("[]", "[]", "[]", R"({"gravity":[0,"down"]})"), "world.gravity[1]",
     "expected a number, got \"down\""},
    {"unknown_integrator", scene("[]", "[]", "[]", R"({"integrator":"verlet"})"), "world.integrator",
     "unknown integrator 'verlet' (expected one of: euler, semi-implicit-euler, rk4)"},
    {"integrator_not_string", scene("[]", "[]", "[]", R"({"integrator":4})"), "world.integrator",
     "expected a string, got 4"},
    {"zero_time_step", scene("[]", "[]", "[]", R"({"timeStep":0})"), "world.timeStep", "must be greater than 0 (got 0)"},
    {"negative_time_step", scene("[]", "[]", "[]", R"({"timeStep":-0.001})"), "world.timeStep",
     "must be greater than 0 (got -0.001)"},
    {"time_step_not_number", scene("[]", "[]", "[]", R"({"timeStep":"fast"})"), "world.timeStep",
     "expected a number, got \"fast\""},
    {"negative_drag", scene("[]", "[]", "[]", R"({"drag":-0.5})"), "world.drag", "must be 0 or greater (got -0.5)"},

    // bodies
    {"body_not_object", scene("[42]"), "bodies[0]", "expected an object, got 42"},
    {"body_unknown_key", ballScene(R"(,"colour":"#ff0000")"), "bodies[0]", "unknown key 'colour' (did you mean 'color'?)"},
    {"missing_name", scene(R"([{"shape":{"type":"circle","radius":1},"position":[0,0]}])"), "bodies[0]",
     "missing required key 'name'"},
    {"empty_name", scene(R"([{"name":"","shape":{"type":"circle","radius":1},"position":[0,0]}])"), "bodies[0].name",
     "must not be empty"},
    {"name_not_string", scene(R"([{"name":7,"shape":{"type":"circle","radius":1},"position":[0,0]}])"),
     "bodies[0].name", "expected a string, got 7"},
    {"duplicate_name", scene("[" + kFloor + "," + ballBody() + "," + ballBody() + "]"), "bodies[2].name",
     "duplicate name 'ball' (bodies[1] already has it)"},
    {"missing_shape", scene(R"([{"name":"a","position":[0,0]}])"), "bodies[0]", "missing required key 'shape'"},
    {"missing_position", scene(R"([{"name":"a","shape":{"type":"circle","radius":1}}])"), "bodies[0]",
     "missing required key 'position'"},
    {"position_not_array", scene(R"([{"name":"a","shape":{"type":"circle","radius":1},"position":"here"}])"),
     "bodies[0].position", "expected an array of 2 numbers [x, y], got \"here\""},
    {"position_too_short", scene(R"([{"name":"a","shape":{"type":"circle","radius":1},"position":[1]}])"),
     "bodies[0].position", "expected an array of 2 numbers [x, y], got an array of 1 value"},
    {"position_null_element", scene(R"([{"name":"a","shape":{"type":"circle","radius":1},"position":[0,null]}])"),
     "bodies[0].position[1]", "expected a number, got null"},
    {"angle_not_number", ballScene(R"(,"angle":"45deg")"), "bodies[0].angle", "expected a number, got \"45deg\""},
    {"velocity_wrong_length", ballScene(R"(,"velocity":[])"), "bodies[0].velocity",
     "expected an array of 2 numbers [x, y], got an empty array"},
    {"angular_velocity_bool", ballScene(R"(,"angularVelocity":true)"), "bodies[0].angularVelocity",
     "expected a number, got true"},
    {"zero_density", ballScene(R"(,"density":0)"), "bodies[0].density", "must be greater than 0 (got 0)"},
    {"negative_density", ballScene(R"(,"density":-2.5)"), "bodies[0].density", "must be greater than 0 (got -2.5)"},
    {"zero_mass", ballScene(R"(,"mass":0.0)"), "bodies[0].mass", "must be greater than 0 (got 0.0)"},
    {"negative_mass", ballScene(R"(,"mass":-1)"), "bodies[0].mass", "must be greater than 0 (got -1)"},
    {"mass_and_density", ballScene(R"(,"mass":1,"density":2)"), "bodies[0]", "give either 'density' or 'mass', not both"},
    {"restitution_above_one", ballScene(R"(,"restitution":1.5)"), "bodies[0].restitution",
     "must be between 0 and 1 (got 1.5)"},
    {"restitution_negative", ballScene(R"(,"restitution":-0.1)"), "bodies[0].restitution",
     "must be between 0 and 1 (got -0.1)"},
    {"negative_friction", ballScene(R"(,"friction":-0.3)"), "bodies[0].friction", "must be 0 or greater (got -0.3)"},
    {"fixed_not_bool", ballScene(R"(,"fixed":"yes")"), "bodies[0].fixed", "expected true or false, got \"yes\""},
    {"color_name", ballScene(R"(,"color":"red")"), "bodies[0].color", "expected a color \"#rrggbb\", got \"red\""},
    {"color_short", ballScene(R"(,"color":"#fff")"), "bodies[0].color", "expected a color \"#rrggbb\""},
    {"color_bad_digit", ballScene(R"(,"color":"#12345g")"), "bodies[0].color", "expected a color \"#rrggbb\""},
    {"color_not_string", ballScene(R"(,"color":255)"), "bodies[0].color", "expected a string, got 255"},
    {"tiny_body", shapeScene(R"({"type":"circle","radius":1e-200})"), "bodies[0]",
     "mass or moment of inertia out of range"},

    // shapes
    {"shape_not_object", shapeScene(R"("circle")"), "bodies[0].shape", "expected an object, got \"circle\""},
    {"shape_missing_type", shapeScene(R"({"radius":1})"), "bodies[0].shape", "missing required key 'type'"},
    {"shape_type_not_string", shapeScene(R"({"type":1,"radius":1})"), "bodies[0].shape.type", "expected a string, got 1"},
    {"unknown_shape_type", shapeScene(R"({"type":"triangle"})"), "bodies[0].shape.type",
     "unknown shape type 'triangle' (expected one of: circle, ellipse, box, polygon)"},
    {"shape_unknown_key", shapeScene(R"({"type":"circle","radius":1,"radiusX":2})"), "bodies[0].shape",
     "unknown key 'radiusX' for a circle"},
    {"circle_missing_radius", shapeScene(R"({"type":"circle"})"), "bodies[0].shape", "missing required key 'radius'"},
    {"circle_zero_radius", shapeScene(R"({"type":"circle","radius":0})"), "bodies[0].shape.radius",
     "must be greater than 0 (got 0)"},
    {"circle_negative_radius", shapeScene(R"({"type":"circle","radius":-1})"), "bodies[0].shape.radius",
     "must be greater than 0 (got -1)"},
    {"ellipse_zero_radius", shapeScene(R"({"type":"ellipse","radiusX":1,"radiusY":0})"), "bodies[0].shape.radiusY",
     "must be greater than 0"},
    {"box_negative_width", shapeScene(R"({"type":"box","width":-2,"height":1})"), "bodies[0].shape.width",
     "must be greater than 0 (got -2)"},
    {"box_zero_height", shapeScene(R"({"type":"box","width":2,"height":0})"), "bodies[0].shape.height",
     "must be greater than 0"},
    {"polygon_vertices_not_array", polygonScene(R"({"x":0})"), "bodies[0].shape.vertices",
     "expected an array of [x, y] points, got an object"},
    {"polygon_vertex_wrong_length", polygonScene("[[0,0],[1,0,0],[0,1]]"), "bodies[0].shape.vertices[1]",
     "expected an array of 2 numbers [x, y]"},
    {"polygon_bowtie", polygonScene("[[0,0],[1,1],[1,0],[0,1]]"), "bodies[0].shape.vertices",
     "polygon self-intersects (edges 0 and 2)"},
    {"polygon_collinear", polygonScene("[[0,0],[1,0],[2,0]]"), "bodies[0].shape.vertices",
     "polygon has zero area"},
    {"polygon_duplicate_vertex", polygonScene("[[0,0],[1,0],[1,0],[0,1]]"), "bodies[0].shape.vertices",
     "vertices 1 and 2 are the same point"},
    {"polygon_too_few_vertices", polygonScene("[[0,0],[1,0]]"), "bodies[0].shape.vertices",
     "polygon needs at least 3 vertices (got 2)"},

    // soft
    {"soft_not_object", ballScene(R"(,"soft":true)"), "bodies[0].soft", "expected an object, got true"},
    {"soft_unknown_key", ballScene(R"(,"soft":{"stifness":10})"), "bodies[0].soft",
     "unknown key 'stifness' (did you mean 'stiffness'?)"},
    {"soft_zero_density", ballScene(R"(,"soft":{"ellipsesPerSquareMeter":0})"), "bodies[0].soft.ellipsesPerSquareMeter",
     "must be greater than 0"},
    {"soft_density_bad_word", ballScene(R"(,"soft":{"ellipsesPerSquareMeter":"many"})"),
     "bodies[0].soft.ellipsesPerSquareMeter", "expected a number or \"auto\", got \"many\""},
    {"soft_zero_stiffness", ballScene(R"(,"soft":{"stiffness":0})"), "bodies[0].soft.stiffness", "must be greater than 0"},
    {"soft_negative_damping", ballScene(R"(,"soft":{"damping":-1})"), "bodies[0].soft.damping", "must be 0 or greater"},
    {"soft_negative_damping_ratio", ballScene(R"(,"soft":{"dampingRatio":-1})"), "bodies[0].soft.dampingRatio",
     "must be 0 or greater"},
    {"soft_ratio_and_coefficient", ballScene(R"(,"soft":{"dampingRatio":1,"damping":2})"), "bodies[0].soft",
     "give either 'dampingRatio' or 'damping', not both"},
    {"soft_state_unequal_lists", ballScene(R"(,"soft":{"state":{"positions":[[0,0]],"velocities":[]}})"),
     "bodies[0].soft.state", "expected one velocity per position (got 1 positions and 0 velocities)"},
    {"soft_state_empty", ballScene(R"(,"soft":{"state":{"positions":[],"velocities":[]}})"),
     "bodies[0].soft.state.positions", "a grid has at least one ellipse"},
    {"soft_state_missing_velocities", ballScene(R"(,"soft":{"state":{"positions":[[0,0]]}})"),
     "bodies[0].soft.state", "missing required key 'velocities'"},
    {"soft_state_bad_vector", ballScene(R"(,"soft":{"state":{"positions":[[0,"x"]],"velocities":[[0,0]]}})"),
     "bodies[0].soft.state.positions[0][1]", "expected a number"},

    // springs
    {"spring_not_object", pairScene(R"(["ball"])"), "springs[0]", "expected an object, got \"ball\""},
    {"spring_unknown_key", pairScene(R"([{"bodyA":"ball","stiffness":10,"dampng":1}])"), "springs[0]",
     "unknown key 'dampng' (did you mean 'damping'?)"},
    {"spring_missing_body_a", pairScene(R"([{"stiffness":10}])"), "springs[0]", "missing required key 'bodyA'"},
    {"spring_missing_stiffness", pairScene(R"([{"bodyA":"ball"}])"), "springs[0]", "missing required key 'stiffness'"},
    {"spring_unknown_body_a", pairScene(R"([{"bodyA":"bal","stiffness":10}])"), "springs[0].bodyA",
     "unknown body 'bal' (did you mean 'ball'?)"},
    {"spring_unknown_body_b", pairScene(R"([{"bodyA":"ball","bodyB":"roof","stiffness":10}])"), "springs[0].bodyB",
     "unknown body 'roof'"},
    {"spring_body_a_null", pairScene(R"([{"bodyA":null,"stiffness":10}])"), "springs[0].bodyA",
     "expected a body name, got null"},
    {"spring_body_b_not_name", pairScene(R"([{"bodyA":"ball","bodyB":3,"stiffness":10}])"), "springs[0].bodyB",
     "expected a body name or null, got 3"},
    {"spring_to_itself", pairScene(R"([{"bodyA":"ball","bodyB":"ball","stiffness":10}])"), "springs[0].bodyB",
     "a spring cannot attach body 'ball' to itself"},
    {"spring_negative_stiffness", pairScene(R"([{"bodyA":"ball","stiffness":-10}])"), "springs[0].stiffness",
     "must be 0 or greater (got -10)"},
    {"spring_negative_damping", pairScene(R"([{"bodyA":"ball","stiffness":10,"damping":-1}])"), "springs[0].damping",
     "must be 0 or greater"},
    {"spring_negative_rest_length", pairScene(R"([{"bodyA":"ball","stiffness":10,"restLength":-0.5}])"),
     "springs[0].restLength", "must be 0 or greater (got -0.5)"},
    {"spring_anchor_not_vector", pairScene(R"([{"bodyA":"ball","anchorA":0,"stiffness":10}])"), "springs[0].anchorA",
     "expected an array of 2 numbers [x, y], got 0"},

    // joints
    {"joint_not_object", pairScene("[]", "[null]"), "joints[0]", "expected an object, got null"},
    {"joint_missing_type", pairScene("[]", R"([{"bodyA":"ball","anchor":[0,0]}])"), "joints[0]",
     "missing required key 'type'"},
    {"unknown_joint_type", pairScene("[]", R"([{"type":"hinge","bodyA":"ball"}])"), "joints[0].type",
     "unknown joint type 'hinge' (expected one of: pin, rod)"},
    {"pin_unknown_key", pairScene("[]", R"([{"type":"pin","bodyA":"ball","anchor":[0,2],"anchorA":[0,0]}])"),
     "joints[0]", "unknown key 'anchorA' for a pin joint"},
    {"rod_unknown_key", pairScene("[]", R"([{"type":"rod","bodyA":"ball","anchor":[0,0]}])"), "joints[0]",
     "unknown key 'anchor' for a rod joint"},
    {"pin_missing_anchor", pairScene("[]", R"([{"type":"pin","bodyA":"ball"}])"), "joints[0]",
     "missing required key 'anchor'"},
    {"pin_unknown_body_a", pairScene("[]", R"([{"type":"pin","bodyA":"wheel","anchor":[0,0]}])"), "joints[0].bodyA",
     "unknown body 'wheel'"},
    {"rod_unknown_body_b", pairScene("[]", R"([{"type":"rod","bodyA":"ball","bodyB":"flor"}])"), "joints[0].bodyB",
     "unknown body 'flor' (did you mean 'floor'?)"},
    {"joint_body_b_not_name", pairScene("[]", R"([{"type":"pin","bodyA":"ball","bodyB":false,"anchor":[0,0]}])"),
     "joints[0].bodyB", "expected a body name or null, got false"},
    {"pin_to_itself", pairScene("[]", R"([{"type":"pin","bodyA":"ball","bodyB":"ball","anchor":[0,2]}])"),
     "joints[0].bodyB", "a joint cannot attach body 'ball' to itself"},
    {"rod_zero_length", pairScene("[]", R"([{"type":"rod","bodyA":"ball","anchorA":[1,0],"anchorB":[1,2]}])"),
     "joints[0]", "rod has zero length"},
};

INSTANTIATE_TEST_SUITE_P(EveryRule, BadScene, ::testing::ValuesIn(kBadScenes),
                         [](const ::testing::TestParamInfo<BadSceneCase>& param) { return param.param.name; });

TEST(SceneProblems, ThreeSeparateProblemsAreAllReported)
{
    const std::string text = scene(R"([{"name":"ball","shape":{"type":"circle","radius":-1},"position":[0,0]}])",
                                   R"([{"bodyA":"nobody","stiffness":5}])", "[]", R"({"timeStep":0})");
    const SceneLoadResult result = parseScene(text);
    EXPECT_FALSE(result.ok());
    const std::vector<SceneProblem> expected = {
        {"world.timeStep", "must be greater than 0 (got 0)"},
        {"bodies[0].shape.radius", "must be greater than 0 (got -1)"},
        {"springs[0].bodyA", "unknown body 'nobody'"},
    };
    EXPECT_EQ(result.problems, expected) << describeProblems(result.problems);
}

TEST(SceneProblems, ToStringIsPathColonReason)
{
    const SceneLoadResult result = parseScene(shapeScene(R"({"type":"circle","radius":-1})"));
    ASSERT_EQ(result.problems.size(), 1u);
    EXPECT_EQ(result.problems[0].toString(), "bodies[0].shape.radius: must be greater than 0 (got -1)");
}

TEST(SceneProblems, LineAndColumnCountFromTheStartOfTheLine)
{
    // The stray ']' is the 13th byte of line 4.
    const std::string text = "{\n  \"format\": \"impetus-scene\",\n  \"version\": 1,\n  \"bodies\": ]\n}";
    const SceneLoadResult result = parseScene(text);
    ASSERT_EQ(result.problems.size(), 1u) << describeProblems(result.problems);
    EXPECT_EQ(result.problems[0].path, "(root)");
    EXPECT_TRUE(result.problems[0].reason.starts_with("invalid JSON at line 4, column 13:")) << result.problems[0].reason;
}

TEST(SceneProblems, ControlCharactersInKeysAreEscapedInMessages)
{
    const SceneLoadResult result = parseScene(ballScene(R"(,"x\u001b[2Jy":1)"));
    ASSERT_EQ(result.problems.size(), 1u) << describeProblems(result.problems);
    EXPECT_EQ(result.problems[0].reason, "unknown key 'x\\u001b[2Jy'");
}

TEST(SceneProblems, ADuplicateKeyInsideABodyIsNamedAtTheBody)
{
    const SceneLoadResult result =
        parseScene(scene(R"([{"name":"a","name":"b","shape":{"type":"circle","radius":1},"position":[0,0]}])"));
    const std::vector<SceneProblem> expected = {{"bodies[0]", "duplicate key 'name'"}};
    EXPECT_EQ(result.problems, expected) << describeProblems(result.problems);
}

TEST(SceneProblems, ProblemsOfAllSectionsAreCollectedTogether)
{
    // One problem in each section and in each kind of object: none hides another.
    const std::string text = R"({"format":"impetus-scene","version":1,"extra":0,
        "world":{"drag":-1},
        "bodies":[{"name":"a","shape":{"type":"box","width":1,"height":-1},"position":[0,0],"soft":{"damping":-1}},
                  {"name":"b","shape":{"type":"circle","radius":1},"position":[3,0],"friction":-1}],
        "springs":[{"bodyA":"a","bodyB":"c","stiffness":1}],
        "joints":[{"type":"rod","bodyA":"a","bodyB":"a"}]})";
    const SceneLoadResult result = parseScene(text);
    const std::vector<std::string> paths = {"(root)",           "world.drag",         "bodies[0].shape.height",
                                            "bodies[0].soft.damping", "bodies[1].friction", "springs[0].bodyB",
                                            "joints[0].bodyB"};
    ASSERT_EQ(result.problems.size(), paths.size()) << describeProblems(result.problems);
    for (std::size_t i = 0; i < paths.size(); ++i)
        EXPECT_EQ(result.problems[i].path, paths[i]);
}

// ------------------------------------------------------------------------------------------------
// Defaults and load-time derivations

const std::string kMinimalBall = R"({"name":"ball","shape":{"type":"circle","radius":0.5},"position":[1,2]})";

TEST(SceneDefaults, AbsentKeysTakeTheModelDefaults)
{
    const SceneLoadResult result = parseScene(R"({"format":"impetus-scene","version":1,"bodies":[)" + kMinimalBall + "]}");
    ASSERT_TRUE(result.ok()) << describeProblems(result.problems);
    const World& world = *result.world;
    EXPECT_EQ(world.settings, WorldSettings{});
    EXPECT_TRUE(world.springs.empty());
    EXPECT_TRUE(world.joints.empty());
    EXPECT_EQ(world.time, 0.0);
    EXPECT_EQ(world.stepCount, 0);
    ASSERT_EQ(world.bodies.size(), 1u);
    const Body& body = world.bodies[0];
    EXPECT_EQ(body.name, "ball");
    EXPECT_EQ(body.shape, Shape(Circle{0.5}));
    EXPECT_EQ(body.state.position, Vec2(1, 2));
    EXPECT_EQ(body.state.angle, 0.0);
    EXPECT_EQ(body.state.velocity, Vec2::Zero().eval());
    EXPECT_EQ(body.state.angularVelocity, 0.0);
    EXPECT_EQ(body.massSpec, MassSpec{});
    EXPECT_EQ(body.material, Material{});
    EXPECT_FALSE(body.fixed);
    EXPECT_EQ(body.color, Color{});
    EXPECT_FALSE(body.soft.has_value());
}

TEST(SceneDefaults, DerivedBodyDataIsComputedAtLoad)
{
    const SceneLoadResult result = parseScene(scene("[" + ballBody(R"(,"density":2)") + "]"));
    ASSERT_TRUE(result.ok()) << describeProblems(result.problems);
    const Body& body = result.world->bodies[0];
    const double area = std::numbers::pi * 0.25;
    EXPECT_NEAR(body.area, area, 1e-15);
    EXPECT_NEAR(body.mass, 2 * area, 1e-15);
    EXPECT_NEAR(body.inertia, 0.5 * body.mass * 0.25, 1e-15);
    EXPECT_NEAR(body.invMass, 1 / body.mass, 1e-15);
}

TEST(SceneDefaults, MassGivenInKilogramsIsKeptExactly)
{
    const SceneLoadResult result = parseScene(scene("[" + ballBody(R"(,"mass":0.3)") + "]"));
    ASSERT_TRUE(result.ok()) << describeProblems(result.problems);
    const Body& body = result.world->bodies[0];
    EXPECT_EQ(body.massSpec, (MassSpec{MassMode::Mass, 0.3}));
    EXPECT_EQ(body.mass, 0.3);
}

TEST(SceneDefaults, FixedBodiesAreGreyUnlessColoured)
{
    const SceneLoadResult result = parseScene(scene("[" + kFloor + R"(,{"name":"wall","shape":{"type":"box","width":1,"height":4},"position":[5,2],"fixed":true,"color":"#A0B1C2"}])"));
    ASSERT_TRUE(result.ok()) << describeProblems(result.problems);
    EXPECT_EQ(result.world->bodies[0].color, (Color{0x7a, 0x7f, 0x87}));
    EXPECT_EQ(result.world->bodies[1].color, (Color{0xa0, 0xb1, 0xc2}));
    EXPECT_EQ(result.world->bodies[0].invMass, 0.0);
}

TEST(SceneDefaults, SoftKeysDefaultAndAutoSetsAutoDensity)
{
    const SceneLoadResult result =
        parseScene(scene("[" + ballBody(R"(,"soft":{})") + R"(,{"name":"jelly","shape":{"type":"box","width":1,"height":1},"position":[3,0],"soft":{"ellipsesPerSquareMeter":"auto","damping":0}}])"));
    ASSERT_TRUE(result.ok()) << describeProblems(result.problems);
    EXPECT_EQ(result.world->bodies[0].soft, SoftSettings{});
    SoftSettings automatic;
    automatic.autoDensity = true;
    automatic.dampingMode = SoftDampingMode::Coefficient;
    automatic.damping = 0;
    EXPECT_EQ(result.world->bodies[1].soft, automatic);
    // With neither damping key the damping is the default ratio.
    EXPECT_EQ(result.world->bodies[0].soft->dampingMode, SoftDampingMode::Ratio);
    EXPECT_EQ(result.world->bodies[0].soft->dampingRatio, constants::kDefaultSoftDampingRatio);
}

TEST(SceneDefaults, SoftDampingRatioIsReadAsARatio)
{
    const SceneLoadResult result = parseScene(scene("[" + ballBody(R"(,"soft":{"dampingRatio":0.3})") + "]"));
    ASSERT_TRUE(result.ok()) << describeProblems(result.problems);
    EXPECT_EQ(result.world->bodies[0].soft->dampingMode, SoftDampingMode::Ratio);
    EXPECT_EQ(result.world->bodies[0].soft->dampingRatio, 0.3);
}

TEST(SceneDefaults, SoftGridStateIsReadAndAMismatchedOneIsRefused)
{
    const SceneLoadResult result = parseScene(
        scene("[" + ballBody(R"(,"soft":{"state":{"positions":[[0,1],[2,3]],"velocities":[[4,5],[6,7]]}})") + "]"));
    ASSERT_TRUE(result.ok()) << describeProblems(result.problems);
    const SoftGridState expected{{Vec2(0, 1), Vec2(2, 3)}, {Vec2(4, 5), Vec2(6, 7)}};
    EXPECT_EQ(result.world->bodies[0].softState, expected);
    EXPECT_TRUE(serializeScene(*result.world).find(R"("positions")") != std::string::npos);
}

TEST(SceneDefaults, PolygonVerticesAreKeptAsGivenAndPositionIsTheCentroid)
{
    const std::string text = polygonScene("[[0,0],[0,3],[3,0]]"); // clockwise, centroid (1, 1)
    const SceneLoadResult result = parseScene(text);
    ASSERT_TRUE(result.ok()) << describeProblems(result.problems);
    const Body& body = result.world->bodies[0];
    const std::vector<Vec2> given = {Vec2(0, 0), Vec2(0, 3), Vec2(3, 0)};
    EXPECT_EQ(std::get<Polygon>(body.shape).vertices, given);
    EXPECT_NEAR(body.geometry.centroidOffset.x(), 1.0, 1e-15);
    EXPECT_NEAR(body.geometry.centroidOffset.y(), 1.0, 1e-15);
    EXPECT_NEAR(body.area, 4.5, 1e-15);
}

TEST(SceneDefaults, SpringRestLengthIsTheLoadTimeDistanceOfItsAnchors)
{
    // Body A at (1, 2) turned a quarter turn: its anchor (1, 0) is at (1, 3) in the world. The
    // world end is (4, 7), so the spring is a 3-4-5 triangle's hypotenuse.
    const std::string bodies =
        R"([{"name":"a","shape":{"type":"circle","radius":0.5},"position":[1,2],"angle":1.5707963267948966}])";
    const SceneLoadResult result =
        parseScene(scene(bodies, R"([{"bodyA":"a","anchorA":[1,0],"anchorB":[4,7],"stiffness":20}])"));
    ASSERT_TRUE(result.ok()) << describeProblems(result.problems);
    ASSERT_EQ(result.world->springs.size(), 1u);
    const Spring& spring = result.world->springs[0];
    EXPECT_EQ(spring.bodyA, BodyId{0});
    EXPECT_FALSE(spring.bodyB.has_value());
    EXPECT_EQ(spring.damping, 0.0);
    EXPECT_EQ(spring.stiffness, 20.0);
    EXPECT_NEAR(spring.restLength, 5.0, 1e-12);
}

TEST(SceneDefaults, SpringAnchorsDefaultToTheCentresAndBodyBNullIsTheWorld)
{
    const SceneLoadResult result = parseScene(
        pairScene(R"([{"bodyA":"ball","bodyB":"floor","stiffness":1},{"bodyA":"ball","bodyB":null,"stiffness":1,"restLength":0.25}])"));
    ASSERT_TRUE(result.ok()) << describeProblems(result.problems);
    const Spring& between = result.world->springs[0];
    EXPECT_EQ(between.anchorA, Vec2::Zero().eval());
    EXPECT_EQ(between.anchorB, Vec2::Zero().eval());
    EXPECT_EQ(between.bodyB, BodyId{1});
    EXPECT_EQ(between.restLength, 2.5); // ball at (0, 2), floor at (0, −0.5)
    const Spring& toWorld = result.world->springs[1];
    EXPECT_FALSE(toWorld.bodyB.has_value());
    EXPECT_EQ(toWorld.restLength, 0.25);
}

TEST(SceneDefaults, PinAnchorsAreTheHingeInEachBodysFrame)
{
    // "a" at (1, 1) turned +90°: the world point (1, 2) is one metre along its local +x.
    // "b" at (3, 2) unturned: the same point is at (−2, 0) in its frame.
    const std::string bodies =
        R"([{"name":"a","shape":{"type":"circle","radius":0.5},"position":[1,1],"angle":1.5707963267948966},
            {"name":"b","shape":{"type":"circle","radius":0.5},"position":[3,2]}])";
    const SceneLoadResult result = parseScene(scene(bodies, "[]",
        R"([{"type":"pin","bodyA":"a","bodyB":"b","anchor":[1,2]},{"type":"pin","bodyA":"b","anchor":[3,3]}])"));
    ASSERT_TRUE(result.ok()) << describeProblems(result.problems);
    const Joint& pin = result.world->joints[0];
    EXPECT_EQ(pin.type, JointType::Pin);
    EXPECT_EQ(pin.worldAnchor, Vec2(1, 2));
    EXPECT_NEAR(pin.anchorA.x(), 1.0, 1e-15);
    EXPECT_NEAR(pin.anchorA.y(), 0.0, 1e-15);
    EXPECT_NEAR(pin.anchorB.x(), -2.0, 1e-15);
    EXPECT_NEAR(pin.anchorB.y(), 0.0, 1e-15);
    const Joint& toWorld = result.world->joints[1];
    EXPECT_FALSE(toWorld.bodyB.has_value());
    EXPECT_EQ(toWorld.anchorB, Vec2(3, 3));
    EXPECT_NEAR(toWorld.anchorA.y(), 1.0, 1e-15);
}

TEST(SceneDefaults, RodLengthIsTheLoadTimeDistanceOfItsAnchors)
{
    const SceneLoadResult result = parseScene(pairScene(
        "[]", R"([{"type":"rod","bodyA":"ball","anchorA":[0.5,0],"bodyB":"floor","anchorB":[-2.5,0.5]},{"type":"rod","bodyA":"ball","anchorB":[0,5]}])"));
    ASSERT_TRUE(result.ok()) << describeProblems(result.problems);
    const Joint& rod = result.world->joints[0];
    EXPECT_EQ(rod.type, JointType::Rod);
    EXPECT_EQ(rod.anchorA, Vec2(0.5, 0));
    EXPECT_EQ(rod.anchorB, Vec2(-2.5, 0.5));
    // Ends at (0.5, 2) and (−2.5, 0): a 3-by-2 offset.
    EXPECT_NEAR(rod.length, std::sqrt(13.0), 1e-15);
    EXPECT_NEAR(result.world->joints[1].length, 3.0, 1e-15); // (0, 2) to the world point (0, 5)
}

TEST(SceneDefaults, TheContractExampleLoads)
{
    const SceneLoadResult result = loadSceneFile(kDataDir / "contract_example.json");
    ASSERT_TRUE(result.ok()) << describeProblems(result.problems);
    const World& world = *result.world;
    EXPECT_EQ(world.settings.integrator, IntegratorKind::Rk4);
    ASSERT_EQ(world.bodies.size(), 2u);
    EXPECT_TRUE(world.bodies[0].fixed);
    EXPECT_EQ(world.bodies[1].state.velocity, Vec2(2, 0));
    EXPECT_EQ(world.bodies[1].material, (Material{0.5, 0.3}));
}

TEST(SceneDefaults, TheDocumentedExampleLoads)
{
    // docs/scene-format.md shows this file in full.
    const SceneLoadResult result = loadSceneFile(kDataDir / "documented_example.json");
    ASSERT_TRUE(result.ok()) << describeProblems(result.problems);
    const World& world = *result.world;
    EXPECT_EQ(world.bodies.size(), 6u);
    EXPECT_EQ(world.springs.size(), 2u);
    EXPECT_EQ(world.joints.size(), 2u);
    EXPECT_EQ(world.settings.integrator, IntegratorKind::SemiImplicitEuler);
}

TEST(SceneDefaults, TheDocsShowTheDocumentedExampleVerbatim)
{
    const std::string doc = readText(IMPETUS_SCENE_FORMAT_DOC);
    const std::string fence = "```json\n";
    const std::size_t begin = doc.find(fence);
    ASSERT_NE(begin, std::string::npos);
    const std::size_t end = doc.find("```", begin + fence.size());
    ASSERT_NE(end, std::string::npos);
    EXPECT_EQ(doc.substr(begin + fence.size(), end - begin - fence.size()),
              readText(kDataDir / "documented_example.json"));
}

// ------------------------------------------------------------------------------------------------
// Writing and round trips

/// Fills the load-time data of joints the way the format defines it (a pin's body-frame anchors,
/// a rod's length), so that a hand-built world is one the loader could have produced.
void deriveJoint(const World& world, Joint& joint)
{
    const Body& a = world.body(joint.bodyA);
    if (joint.type == JointType::Pin) {
        joint.anchorA = rotate(Vec2(joint.worldAnchor - a.state.position), -a.state.angle);
        if (joint.bodyB) {
            const Body& b = world.body(*joint.bodyB);
            joint.anchorB = rotate(Vec2(joint.worldAnchor - b.state.position), -b.state.angle);
        } else {
            joint.anchorB = joint.worldAnchor;
        }
    } else {
        const Vec2 endB = joint.bodyB ? world.body(*joint.bodyB).worldPoint(joint.anchorB) : joint.anchorB;
        joint.length = (endB - a.worldPoint(joint.anchorA)).norm();
    }
}

/// Every kind of thing a scene can hold, with no value left at its default.
World richWorld()
{
    World world;
    world.settings.gravity = Vec2(0.25, -1.62);
    world.settings.integrator = IntegratorKind::SemiImplicitEuler;
    world.settings.timeStep = 1.0 / 300.0;
    world.settings.drag = 0.05;

    Body ball;
    ball.name = "ball";
    ball.shape = Circle{0.1};
    ball.state = BodyState{Vec2(-1.0 / 3.0, 2.7), 0.3, Vec2(2, -0.1), 1.25};
    ball.massSpec = MassSpec{MassMode::Density, 7.85};
    ball.material = Material{0.9, 0.05};
    ball.color = Color{0x12, 0x34, 0x56};

    Body egg;
    egg.name = "egg";
    egg.shape = Ellipse{0.3, 0.2};
    egg.state.position = Vec2(1.5, 1);
    egg.massSpec = MassSpec{MassMode::Mass, 0.06};
    egg.soft = SoftSettings{true, 64, 1500, SoftDampingMode::Coefficient, 2, 0.5};

    Body crate;
    crate.name = "crate";
    crate.shape = Box{0.8, 0.6};
    crate.state.position = Vec2(3, 0.3);
    crate.state.angle = -0.1;
    crate.soft = SoftSettings{false, 256, 3000, SoftDampingMode::Ratio, 0.7, 1};
    crate.material = Material{0.0, 1.2};

    Body ramp; // concave, counter-clockwise, not centred on its centroid
    ramp.name = "ramp (concave)";
    ramp.shape = Polygon{{Vec2(0, 0), Vec2(4, 0), Vec2(4, 1), Vec2(1, 1), Vec2(1, 3), Vec2(0, 3)}};
    ramp.state.position = Vec2(-3, -1);
    ramp.fixed = true;
    ramp.color = Color{0x7a, 0x7f, 0x87};

    Body arrow; // concave, clockwise
    arrow.name = "arrow";
    arrow.shape = Polygon{{Vec2(0, 0), Vec2(-1, 2), Vec2(0, 1.2), Vec2(1, 2)}};
    arrow.state.position = Vec2(0.5, 4);
    arrow.state.angle = std::numbers::pi / 7;
    arrow.massSpec = MassSpec{MassMode::Density, 0.125};

    for (Body* body : {&ball, &egg, &crate, &ramp, &arrow}) {
        body->updateDerived();
        world.bodies.push_back(*body);
    }

    world.springs.push_back(Spring{BodyId{0}, Vec2(0.05, 0), BodyId{2}, Vec2(-0.4, 0.3), 40, 0.5, 1.1});
    world.springs.push_back(Spring{BodyId{1}, Vec2::Zero(), std::nullopt, Vec2(1.5, 3), 12.5, 0, 0});

    Joint pin;
    pin.type = JointType::Pin;
    pin.bodyA = BodyId{4};
    pin.bodyB = BodyId{2};
    pin.worldAnchor = Vec2(0.7, 3.9);
    Joint pinToWorld;
    pinToWorld.type = JointType::Pin;
    pinToWorld.bodyA = BodyId{1};
    pinToWorld.worldAnchor = Vec2(1.5, 1.3);
    Joint rod;
    rod.type = JointType::Rod;
    rod.bodyA = BodyId{0};
    rod.anchorA = Vec2(0, 0.1);
    rod.bodyB = BodyId{4};
    rod.anchorB = Vec2(0.2, -0.2);
    Joint rodToWorld;
    rodToWorld.type = JointType::Rod;
    rodToWorld.bodyA = BodyId{2};
    rodToWorld.anchorA = Vec2(0.4, 0.3);
    rodToWorld.anchorB = Vec2(3.4, 2);
    for (Joint* joint : {&pin, &pinToWorld, &rod, &rodToWorld}) {
        deriveJoint(world, *joint);
        world.joints.push_back(*joint);
    }
    return world;
}

TEST(SceneRoundTrip, RichWorldIsEqualAfterSerializeAndParse)
{
    const World original = richWorld();
    const std::string text = serializeScene(original);
    const SceneLoadResult result = parseScene(text);
    ASSERT_TRUE(result.ok()) << describeProblems(result.problems) << "\n" << text;
    EXPECT_TRUE(*result.world == original) << text;
    EXPECT_EQ(serializeScene(*result.world), text);
}

TEST(SceneRoundTrip, TimeAndStepCountAreNotSaved)
{
    World world = richWorld();
    world.time = 12.5;
    world.stepCount = 3000;
    const SceneLoadResult result = parseScene(serializeScene(world));
    ASSERT_TRUE(result.ok()) << describeProblems(result.problems);
    EXPECT_EQ(result.world->time, 0.0);
    EXPECT_EQ(result.world->stepCount, 0);
}

TEST(SceneRoundTrip, DoublesComeBackBitForBit)
{
    std::vector<double> values = {0.1,
                                  1.0 / 3.0,
                                  -0.0,
                                  1e23,
                                  9007199254740993.0,
                                  5e-324,
                                  std::numeric_limits<double>::denorm_min(),
                                  std::numeric_limits<double>::min(),
                                  std::numeric_limits<double>::max(),
                                  std::numeric_limits<double>::lowest(),
                                  std::numeric_limits<double>::epsilon()};
    std::mt19937_64 random(20240611);
    while (values.size() < 2000) {
        const double x = std::bit_cast<double>(random());
        if (std::isfinite(x))
            values.push_back(x);
    }
    World world;
    Body body;
    body.name = "probe";
    for (std::size_t i = 0; i + 1 < values.size(); i += 2) {
        body.state.position = Vec2(values[i], values[i + 1]);
        body.state.velocity = Vec2(values[i + 1], values[i]);
        body.state.angle = values[i];
        body.state.angularVelocity = values[i + 1];
        world.bodies = {body};
        world.bodies[0].updateDerived();
        const SceneLoadResult result = parseScene(serializeScene(world));
        ASSERT_TRUE(result.ok()) << describeProblems(result.problems);
        const BodyState& back = result.world->bodies[0].state;
        ASSERT_EQ(std::bit_cast<std::uint64_t>(back.position.x()), std::bit_cast<std::uint64_t>(values[i])) << values[i];
        ASSERT_EQ(std::bit_cast<std::uint64_t>(back.position.y()), std::bit_cast<std::uint64_t>(values[i + 1]))
            << values[i + 1];
        ASSERT_EQ(std::bit_cast<std::uint64_t>(back.angularVelocity), std::bit_cast<std::uint64_t>(values[i + 1]));
    }
}

TEST(SceneRoundTrip, WritesEveryKeyInReadingOrder)
{
    World world;
    Body body;
    body.name = "tri";
    body.shape = Polygon{{Vec2(0, 0), Vec2(3, 0), Vec2(0, 3)}};
    body.state.position = Vec2(1, 1);
    body.fixed = true;
    body.color = Color{0x7a, 0x7f, 0x87};
    body.updateDerived();
    world.bodies.push_back(body);
    world.springs.push_back(Spring{BodyId{0}, Vec2::Zero(), std::nullopt, Vec2(1, 5), 10, 0, 4});
    Joint pin;
    pin.bodyA = BodyId{0};
    pin.worldAnchor = Vec2(1, 1);
    pin.anchorB = pin.worldAnchor;
    world.joints.push_back(pin);

    const std::string expected = R"({
  "format": "impetus-scene",
  "version": 1,
  "world": {
    "gravity": [0.0, -9.81],
    "integrator": "rk4",
    "timeStep": 0.004166666666666667,
    "drag": 0.0
  },
  "bodies": [
    {
      "name": "tri",
      "shape": {
        "type": "polygon",
        "vertices": [
          [0.0, 0.0],
          [3.0, 0.0],
          [0.0, 3.0]
        ]
      },
      "position": [1.0, 1.0],
      "angle": 0.0,
      "velocity": [0.0, 0.0],
      "angularVelocity": 0.0,
      "density": 1.0,
      "restitution": 0.5,
      "friction": 0.5,
      "fixed": true,
      "color": "#7a7f87"
    }
  ],
  "springs": [
    {
      "bodyA": "tri",
      "anchorA": [0.0, 0.0],
      "bodyB": null,
      "anchorB": [1.0, 5.0],
      "stiffness": 10.0,
      "damping": 0.0,
      "restLength": 4.0
    }
  ],
  "joints": [
    {
      "type": "pin",
      "bodyA": "tri",
      "bodyB": null,
      "anchor": [1.0, 1.0]
    }
  ]
}
)";
    EXPECT_EQ(serializeScene(world), expected);
}

TEST(SceneRoundTrip, SoftAutoAndMassAreWrittenAsGiven)
{
    const std::string text = serializeScene(richWorld());
    EXPECT_NE(text.find(R"("ellipsesPerSquareMeter": "auto")"), std::string::npos);
    EXPECT_NE(text.find(R"("ellipsesPerSquareMeter": 256.0)"), std::string::npos);
    EXPECT_NE(text.find(R"("mass": 0.06)"), std::string::npos);
    EXPECT_NE(text.find(R"("density": 7.85)"), std::string::npos);
    // The damping as the body has it: a coefficient, or a ratio.
    EXPECT_NE(text.find(R"("damping": 0.5)"), std::string::npos);
    EXPECT_NE(text.find(R"("dampingRatio": 0.7)"), std::string::npos);
}

// ------------------------------------------------------------------------------------------------
// Files

/// A fresh, empty directory per test, removed afterwards (permissions restored first).
class SceneFiles : public ::testing::Test {
protected:
    void SetUp() override
    {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_dir = fs::path(::testing::TempDir()) / (std::string("impetus_scene_") + info->name());
        std::error_code ec;
        fs::permissions(m_dir, fs::perms::owner_all, fs::perm_options::add, ec);
        fs::remove_all(m_dir, ec);
        fs::create_directories(m_dir);
    }

    void TearDown() override
    {
        std::error_code ec;
        fs::permissions(m_dir, fs::perms::owner_all, fs::perm_options::add, ec);
        fs::remove_all(m_dir, ec);
    }

    std::vector<std::string> entries(const fs::path& dir) const
    {
        std::vector<std::string> names;
        for (const fs::directory_entry& entry : fs::directory_iterator(dir))
            names.push_back(entry.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }

    fs::path m_dir;
};

TEST_F(SceneFiles, SaveThenLoadGivesTheSameWorld)
{
    const fs::path path = m_dir / "rich.json";
    const World world = richWorld();
    const std::optional<std::string> error = saveSceneFile(path, world);
    ASSERT_FALSE(error.has_value()) << *error;
    const SceneLoadResult result = loadSceneFile(path);
    ASSERT_TRUE(result.ok()) << describeProblems(result.problems);
    EXPECT_TRUE(*result.world == world);
    EXPECT_EQ(readText(path), serializeScene(world));
    EXPECT_EQ(entries(m_dir), std::vector<std::string>{"rich.json"}); // no temporary file left
}

TEST_F(SceneFiles, SavingOverAFileReplacesIt)
{
    const fs::path path = m_dir / "scene.json";
    writeText(path, "old contents");
    World world = richWorld();
    ASSERT_FALSE(saveSceneFile(path, world).has_value());
    world.bodies[0].state.position = Vec2(5, 5);
    ASSERT_FALSE(saveSceneFile(path, world).has_value());
    const SceneLoadResult result = loadSceneFile(path);
    ASSERT_TRUE(result.ok()) << describeProblems(result.problems);
    EXPECT_EQ(result.world->bodies[0].state.position, Vec2(5, 5));
    EXPECT_EQ(entries(m_dir), std::vector<std::string>{"scene.json"});
}

TEST_F(SceneFiles, SavingKeepsTheFilesPermissions)
{
    const fs::path path = m_dir / "scene.json";
    writeText(path, "old contents");
    const fs::perms chosen = fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read;
    fs::permissions(path, chosen);
    ASSERT_FALSE(saveSceneFile(path, richWorld()).has_value());
    EXPECT_EQ(fs::status(path).permissions() & fs::perms::all, chosen);
}

TEST_F(SceneFiles, SavingThroughASymlinkUpdatesItsTarget)
{
    const fs::path real = m_dir / "real.json";
    const fs::path link = m_dir / "link.json";
    writeText(real, "old contents");
    fs::create_symlink(real, link);
    ASSERT_FALSE(saveSceneFile(link, richWorld()).has_value());
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
    EXPECT_EQ(readText(real), serializeScene(richWorld()));
}

TEST_F(SceneFiles, SavingOntoADirectoryFailsAndLeavesItAlone)
{
    const fs::path path = m_dir / "scene.json";
    fs::create_directory(path);
    writeText(path / "inside.txt", "keep me");
    const std::optional<std::string> error = saveSceneFile(path, richWorld());
    ASSERT_TRUE(error.has_value());
    EXPECT_NE(error->find("cannot save '" + path.string() + "'"), std::string::npos) << *error;
    EXPECT_NE(error->find("directory"), std::string::npos) << *error;
    EXPECT_TRUE(fs::is_directory(path));
    EXPECT_EQ(readText(path / "inside.txt"), "keep me");
    EXPECT_EQ(entries(m_dir), std::vector<std::string>{"scene.json"});
}

TEST_F(SceneFiles, SavingIntoAnUnwritableDirectoryLeavesTheFileIntact)
{
    const fs::path path = m_dir / "scene.json";
    writeText(path, "the user's scene");
    fs::permissions(m_dir, fs::perms::owner_read | fs::perms::owner_exec);
    {
        // Some users (root, or with CAP_DAC_OVERRIDE) write through read-only directories.
        const fs::path probe = m_dir / "probe";
        std::ofstream out(probe);
        if (out.is_open()) {
            out.close();
            fs::remove(probe);
            GTEST_SKIP() << "this user can write into a read-only directory";
        }
    }
    const std::optional<std::string> error = saveSceneFile(path, richWorld());
    ASSERT_TRUE(error.has_value());
    EXPECT_NE(error->find("cannot save '" + path.string() + "'"), std::string::npos) << *error;
    EXPECT_NE(error->find("Permission denied"), std::string::npos) << *error;
    EXPECT_EQ(readText(path), "the user's scene");
    EXPECT_EQ(entries(m_dir), std::vector<std::string>{"scene.json"});
}

TEST_F(SceneFiles, SavingIntoAMissingDirectoryFails)
{
    const fs::path path = m_dir / "missing" / "scene.json";
    const std::optional<std::string> error = saveSceneFile(path, richWorld());
    ASSERT_TRUE(error.has_value());
    EXPECT_NE(error->find("No such file or directory"), std::string::npos) << *error;
    EXPECT_FALSE(fs::exists(m_dir / "missing"));
}

TEST_F(SceneFiles, AnInvalidWorldIsNotSavedOverAGoodFile)
{
    const fs::path path = m_dir / "scene.json";
    writeText(path, "the user's scene");
    World world = richWorld();
    world.bodies[1].name = world.bodies[0].name;
    const std::optional<std::string> error = saveSceneFile(path, world);
    ASSERT_TRUE(error.has_value());
    EXPECT_NE(error->find("bodies[1].name: duplicate name 'ball'"), std::string::npos) << *error;
    EXPECT_EQ(readText(path), "the user's scene");
    EXPECT_EQ(entries(m_dir), std::vector<std::string>{"scene.json"});
}

TEST_F(SceneFiles, AMissingFileIsOneFileProblem)
{
    const fs::path path = m_dir / "nothing.json";
    const SceneLoadResult result = loadSceneFile(path);
    EXPECT_FALSE(result.ok());
    const std::vector<SceneProblem> expected = {
        {"(file)", "cannot open '" + path.string() + "': No such file or directory"}};
    EXPECT_EQ(result.problems, expected);
}

TEST_F(SceneFiles, ADirectoryIsNotAScene)
{
    const SceneLoadResult result = loadSceneFile(m_dir);
    ASSERT_EQ(result.problems.size(), 1u);
    EXPECT_EQ(result.problems[0].path, "(file)");
    EXPECT_NE(result.problems[0].reason.find("is a directory"), std::string::npos);
}

TEST_F(SceneFiles, AFileWithProblemsReportsThemLikeText)
{
    const fs::path path = m_dir / "bad.json";
    const std::string text = ballScene(R"(,"colour":"#ff0000")");
    writeText(path, text);
    EXPECT_EQ(loadSceneFile(path).problems, parseScene(text).problems);
}

// ------------------------------------------------------------------------------------------------
// Robustness: bad input never throws, never crashes, never gives a world.

TEST(SceneRobustness, EveryTruncationOfAValidSceneIsRefused)
{
    std::string text = serializeScene(richWorld());
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
        text.pop_back();
    for (std::size_t length = 0; length < text.size(); ++length) {
        const SceneLoadResult result = parseScene(std::string_view(text).substr(0, length));
        ASSERT_FALSE(result.ok()) << "prefix of " << length << " bytes";
        ASSERT_EQ(result.problems.size(), 1u);
        ASSERT_EQ(result.problems[0].path, "(root)");
        ASSERT_TRUE(result.problems[0].reason.starts_with("invalid JSON at line ")) << result.problems[0].reason;
    }
}

TEST(SceneRobustness, AnEmptyViewIsBrokenJson)
{
    const SceneLoadResult result = parseScene(std::string_view{});
    ASSERT_EQ(result.problems.size(), 1u);
    EXPECT_TRUE(result.problems[0].reason.starts_with("invalid JSON at line 1, column 1")) << result.problems[0].reason;
}

TEST(SceneRobustness, AByteOrderMarkIsAccepted)
{
    // Windows editors often start UTF-8 files with one.
    const SceneLoadResult result = parseScene("\xEF\xBB\xBF" + ballScene(""));
    EXPECT_TRUE(result.ok()) << describeProblems(result.problems);
}

TEST(SceneRobustness, RandomByteChangesNeverThrowOrGiveAPartialResult)
{
    const std::string original = serializeScene(richWorld());
    std::mt19937 random(7);
    std::uniform_int_distribution<std::size_t> position(0, original.size() - 1);
    std::uniform_int_distribution<int> byte(0, 255);
    int refused = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        std::string text = original;
        for (int changes = 0; changes < 1 + trial % 3; ++changes)
            text[position(random)] = static_cast<char>(byte(random));
        SceneLoadResult result;
        ASSERT_NO_THROW(result = parseScene(text));
        // Either a world and no problems, or problems and no world.
        ASSERT_NE(result.ok(), !result.problems.empty()) << text;
        refused += result.ok() ? 0 : 1;
    }
    EXPECT_GT(refused, 0);
}

TEST(SceneRobustness, DeeplyNestedInputIsRefusedWithoutCrashing)
{
    constexpr int kDepth = 200000;
    const std::string text = "{" + kHeader + R"(,"bodies":[)" + std::string(kDepth, '[') + std::string(kDepth, ']') + "]}";
    const SceneLoadResult result = parseScene(text);
    // Parsing stops at the nesting limit (issue 17): the path is where the limit was crossed.
    ASSERT_EQ(result.problems.size(), 1u);
    EXPECT_EQ(result.problems[0].path.rfind("bodies[0][0]", 0), 0u) << result.problems[0].path;
    EXPECT_EQ(result.problems[0].reason, "nested deeper than 64 levels of arrays and objects (a scene needs 6)");
}

TEST(SceneRobustness, AnOverflowDeepInsideStillNamesItsPath)
{
    const std::string text = polygonScene("[[0,0],[1,0],[0,1e400]]");
    const std::vector<SceneProblem> expected = {
        {"bodies[0].shape.vertices[2][1]", "number 1e400 is out of range (too large for a double)"}};
    EXPECT_EQ(parseScene(text).problems, expected);
}

} // namespace
} // namespace impetus::model
