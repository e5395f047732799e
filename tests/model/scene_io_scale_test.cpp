// Messages that stay right at extreme scales (issue 17, item 5, F4/F5): lengths of 1e160 m or
// 1e-200 m are legal numbers, and the reason a scene with them is refused (or not) must be the
// real one, not an artefact of squares that overflow or underflow.

#include "model/polygon.h"
#include "model/scene_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace impetus::model {
namespace {

std::string problemsOf(const SceneLoadResult& result)
{
    std::string text;
    for (const SceneProblem& problem : result.problems)
        text += problem.toString() + '\n';
    return text;
}

// bad-cases/F4_rod_far_anchor_says_zero_length.json: anchors 1e160 m apart were "zero length".
TEST(SceneScale, ARodWithFarAnchorsHasItsLength)
{
    const SceneLoadResult result = parseScene(R"({"format":"impetus-scene","version":1,
        "bodies":[{"name":"a","shape":{"type":"box","width":0.5,"height":0.5},"position":[0,3]}],
        "joints":[{"type":"rod","bodyA":"a","bodyB":null,"anchorB":[0,1e160]}]})");
    ASSERT_TRUE(result.ok()) << problemsOf(result);
    EXPECT_DOUBLE_EQ(result.world->joints.at(0).length, 1e160);
}

TEST(SceneScale, ASpringWithFarAnchorsHasAFiniteRestLength)
{
    const SceneLoadResult result = parseScene(R"({"format":"impetus-scene","version":1,
        "bodies":[{"name":"a","shape":{"type":"box","width":0.5,"height":0.5},"position":[0,0]}],
        "springs":[{"bodyA":"a","anchorB":[3e160,4e160],"stiffness":1}]})");
    ASSERT_TRUE(result.ok()) << problemsOf(result);
    EXPECT_DOUBLE_EQ(result.world->springs.at(0).restLength, 5e160);
}

// bad-cases/F5_big_triangle_called_collinear.json: a right triangle with 1e160 m legs was
// "collinear"; it is a fine triangle whose mass is too large for a double, and that is the reason.
TEST(SceneScale, AHugeTriangleIsRefusedForItsMassNotAsCollinear)
{
    const SceneLoadResult result = parseScene(R"({"format":"impetus-scene","version":1,"bodies":[{"name":"p",
        "shape":{"type":"polygon","vertices":[[0,0],[1e160,0],[0,1e160]]},"position":[0,3]}]})");
    ASSERT_FALSE(result.ok());
    ASSERT_EQ(result.problems.size(), 1u) << problemsOf(result);
    EXPECT_EQ(result.problems[0].path, "bodies[0]");
    EXPECT_NE(result.problems[0].reason.find("mass or moment of inertia out of range"), std::string::npos)
        << result.problems[0].reason;
}

// The same triangle 1e-200 m across had "vertices 0 and 1 are the same point"; its mass is what
// underflows.
TEST(SceneScale, ATinyTriangleIsRefusedForItsMassNotAsOnePoint)
{
    const SceneLoadResult result = parseScene(R"({"format":"impetus-scene","version":1,"bodies":[{"name":"p",
        "shape":{"type":"polygon","vertices":[[0,0],[1e-200,0],[0,1e-200]]},"position":[0,3]}]})");
    ASSERT_FALSE(result.ok());
    ASSERT_EQ(result.problems.size(), 1u) << problemsOf(result);
    EXPECT_NE(result.problems[0].reason.find("mass or moment of inertia out of range"), std::string::npos)
        << result.problems[0].reason;
}

std::vector<std::string> messages(const std::vector<PolygonIssue>& issues)
{
    std::vector<std::string> out;
    for (const PolygonIssue& issue : issues)
        out.push_back(issue.message);
    return out;
}

std::vector<Vec2> scaled(const std::vector<Vec2>& vertices, Scalar factor)
{
    std::vector<Vec2> out;
    for (const Vec2& v : vertices)
        out.push_back(v * factor);
    return out;
}

// Validation gives the same verdict at every scale a double can hold: a shape and its copy
// 2^±600 times larger are the same shape.
TEST(PolygonScale, VerdictsDoNotDependOnSize)
{
    const std::vector<std::vector<Vec2>> shapes = {
        {{0, 0}, {1, 0}, {0, 1}}, // valid triangle
        {{0, 0}, {2, 0}, {2, 2}, {1, 0.5}, {0, 2}}, // valid concave
        {{0, 0}, {1, 0}, {2, 0}}, // collinear
        {{0, 0}, {1, 1}, {1, 0}, {0, 1}}, // bowtie
        {{0, 0}, {1, 0}, {1, 0}, {0, 1}}, // repeated vertex
    };
    const std::vector<Scalar> factors = {std::ldexp(1.0, 600), std::ldexp(1.0, -600), 1e160, 1e-200};
    for (const std::vector<Vec2>& shape : shapes) {
        const std::vector<std::string> reference = messages(validatePolygon(shape));
        for (const Scalar factor : factors)
            EXPECT_EQ(messages(validatePolygon(scaled(shape, factor))), reference) << "factor " << factor;
    }
}

} // namespace
} // namespace impetus::model
