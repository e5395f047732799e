// Scene files that are not scenes at all: devices, oversized files, absurd nesting (issue 17,
// item 4). What the CLI and the app share, model::loadSceneFile and model::parseScene, refuses
// them with one message instead of reading forever or running out of memory.

#include "model/scene_io.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace impetus::model {
namespace {

namespace fs = std::filesystem;

/// A scratch folder of its own per test.
class SceneLimits : public ::testing::Test {
protected:
    void SetUp() override
    {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_dir = fs::temp_directory_path() / (std::string("impetus-scene-limits-") + info->name());
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }

    fs::path m_dir;
};

std::string onlyProblem(const SceneLoadResult& result)
{
    EXPECT_FALSE(result.ok());
    EXPECT_EQ(result.problems.size(), 1u);
    return result.problems.empty() ? std::string() : result.problems.front().toString();
}

// /dev/null reads as an empty file, so before the fix it was "invalid JSON … unexpected end of
// input"; /dev/zero, the same kind of file, never ended.
TEST_F(SceneLimits, ADeviceIsNotARegularFile)
{
    EXPECT_EQ(onlyProblem(loadSceneFile("/dev/null")),
              "(file): cannot open '/dev/null': it is a device, not a regular file");
}

TEST_F(SceneLimits, ALinkToADeviceIsRefusedLikeTheDevice)
{
    const fs::path link = m_dir / "scene.json";
    fs::create_symlink("/dev/zero", link);
    EXPECT_NE(onlyProblem(loadSceneFile(link)).find("it is a device, not a regular file"), std::string::npos);
}

TEST_F(SceneLimits, AFileOverTheCapIsRefusedBeforeItIsRead)
{
    const fs::path huge = m_dir / "huge.json";
    std::ofstream(huge) << "{";
    fs::resize_file(huge, kMaxSceneFileBytes + 1);
    EXPECT_EQ(onlyProblem(loadSceneFile(huge)),
              "(file): cannot read '" + huge.string() +
                  "': the file is larger than the 64 MiB (67108864 bytes) a scene file may have");
}

TEST_F(SceneLimits, AFileAtTheCapIsRead)
{
    // Exactly the cap: read, and judged as JSON (a '{' then zero bytes, which JSON does not allow).
    const fs::path full = m_dir / "full.json";
    std::ofstream(full) << "{";
    fs::resize_file(full, kMaxSceneFileBytes);
    const std::string problem = onlyProblem(loadSceneFile(full));
    EXPECT_NE(problem.find("(root): invalid JSON"), std::string::npos) << problem;
}

std::string nested(std::size_t depth) { return std::string(depth, '[') + std::string(depth, ']'); }

// At the limit the document is read and refused for what it is; one level more is refused as too
// deep, at the path where the limit was crossed.
TEST(SceneNesting, TheLimitIsExact)
{
    const std::string atLimit = onlyProblem(parseScene(nested(kMaxJsonDepth)));
    EXPECT_EQ(atLimit, "(root): expected a JSON object (a scene), got an array of 1 value");
    const std::string beyond = onlyProblem(parseScene(nested(kMaxJsonDepth + 1)));
    EXPECT_NE(beyond.find(": nested deeper than 64 levels of arrays and objects"), std::string::npos) << beyond;
    std::string path;
    for (std::size_t level = 0; level < kMaxJsonDepth; ++level)
        path += "[0]";
    EXPECT_EQ(beyond.substr(0, path.size() + 1), path + ":");
}

TEST(SceneNesting, DeepInsideAScene)
{
    const std::string text = R"({"format":"impetus-scene","version":1,"bodies":[{"name":)" + nested(100) + "}]}";
    const std::string problem = onlyProblem(parseScene(text));
    EXPECT_EQ(problem.rfind("bodies[0].name[0][0]", 0), 0u) << problem;
    EXPECT_NE(problem.find("nested deeper than 64 levels"), std::string::npos) << problem;
}

// Ten million levels (the probe's file) are refused at once: the parser stops at level 65.
TEST(SceneNesting, TenMillionLevelsAreRefused)
{
    constexpr std::size_t kProbeDepth = 10'000'000;
    const std::string problem = onlyProblem(parseScene(nested(kProbeDepth)));
    EXPECT_NE(problem.find("nested deeper than 64 levels"), std::string::npos) << problem;
}

/// A scene of one soft body of `shape` (JSON) whose `soft` object is `soft` (JSON).
std::string softScene(const std::string& shape, const std::string& soft)
{
    return R"({"format":"impetus-scene","version":1,"bodies":[{"name":"jelly","shape":)" + shape +
           R"(,"position":[0,0],"soft":)" + soft + "}]}";
}

// Found while fuzzing `impetus-cli run` (issue 16): a density of 1e12 per m² on a 1 m box was read,
// and the grid builder's columns × rows (a million each) overflowed its int, undefined behaviour;
// the release CLI then died "out of memory". 1e30 per m² even ran, silently, as a grid of one
// ellipse (the column count's lround overflowed). Now such a scene is refused with the sizes.
TEST(SoftGridLimit, ADensityBeyondTheCapIsRefusedWithTheGridSize)
{
    EXPECT_EQ(onlyProblem(parseScene(softScene(R"({"type":"box","width":1,"height":1})",
                                               R"({"ellipsesPerSquareMeter":1e12})"))),
              "bodies[0].soft.ellipsesPerSquareMeter: a grid of 1e+12 ellipses (1e+12 per m² over the 1 m × 1 m "
              "the shape spans), more than the 1e+06 a soft body may have");
    const std::string absurd = onlyProblem(
        parseScene(softScene(R"({"type":"circle","radius":0.5})", R"({"ellipsesPerSquareMeter":1e30})")));
    EXPECT_EQ(absurd.rfind("bodies[0].soft.ellipsesPerSquareMeter: a grid of 1e+30 ellipses", 0), 0u) << absurd;
}

// The cap counts the shape's bounding box, as the grid builder lays its lattice: an ellipse
// 2000 m × 2 m at "auto" (64 per m² at least) would have 256,000 cells; 20,000 m × 2 m, 2.56e6.
TEST(SoftGridLimit, AutoIsJudgedAtItsLowestDensity)
{
    EXPECT_TRUE(parseScene(softScene(R"({"type":"ellipse","radiusX":1000,"radiusY":1})",
                                     R"({"ellipsesPerSquareMeter":"auto"})"))
                    .ok());
    const std::string problem = onlyProblem(parseScene(
        softScene(R"({"type":"ellipse","radiusX":10000,"radiusY":1})", R"({"ellipsesPerSquareMeter":"auto"})")));
    EXPECT_NE(problem.find("a grid of 2.56e+06 ellipses (\"auto\" (at least 64 per m²) over the 2e+04 m × 2 m"),
              std::string::npos)
        << problem;
}

// Exactly at the cap is still read: a 10 m square polygon at 10,000 per m².
TEST(SoftGridLimit, TheCapItselfIsAllowed)
{
    const std::string square = R"({"type":"polygon","vertices":[[0,0],[10,0],[10,10],[0,10]]})";
    EXPECT_TRUE(parseScene(softScene(square, R"({"ellipsesPerSquareMeter":10000})")).ok());
    EXPECT_FALSE(parseScene(softScene(square, R"({"ellipsesPerSquareMeter":10001})")).ok());
}

} // namespace
} // namespace impetus::model
