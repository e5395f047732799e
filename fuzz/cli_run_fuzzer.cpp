/// \file cli_run_fuzzer.cpp
/// libFuzzer target for `impetus-cli run` (scripts/fuzz, docs/testing.md): the input is a scene
/// file, and the CLI's own code (app::runCli, in process) loads it and steps it for a few steps with
/// a summary and a CSV, as a lab script would. Whatever the scene, the run must end with one of
/// the documented exit codes, and a successful run must write a summary that is JSON with no null
/// in it (the contract: a non-finite result is exit 1, never a null in the summary).

#include "app/cli.h"
#include "controller/soft/soft_body_builder.h"
#include "controller/soft/soft_stability.h"
#include "model/constants.h"
#include "model/scene_io.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;

/// Steps each input is run for: enough for contacts, springs, joints and soft grids to be built,
/// solved and summed, few enough that one execution stays well under a millisecond for a small
/// scene, so that a million executions fit in a fuzzing session.
constexpr const char* kFuzzSteps = "12";

/// Every few steps a CSV row per body, so that the CSV writer runs on every input too.
constexpr const char* kFuzzSampleEvery = "4";

/// The most soft-grid ellipses a scene may have to be run, about (its bounding square's area times
/// the grid density). Legal scenes can be as heavy as the user likes; the fuzzer runs tiny ones,
/// so that every execution is fast and a slow input means a hang, not a big scene.
constexpr double kMaxFuzzEllipses = 4096;

/// The most ellipse-substeps a step may cost: ellipses times the substeps their stiffness needs
/// (controller::softStability). A stiff soft box of the examples needs 64 substeps and took 15 s
/// for 12 steps under the sanitizers on a loaded machine: a slow scene, not a hang.
constexpr double kMaxFuzzEllipseSubsteps = 16384;

/// True when a scene that loads is small enough to be run here (kMaxFuzzEllipses,
/// kMaxFuzzEllipseSubsteps).
bool tiny(const impetus::model::World& world)
{
    double ellipses = 0;
    for (const impetus::model::Body& body : world.bodies) {
        if (!body.soft || body.fixed)
            continue;
        const double side = 2 * body.geometry.boundingRadius;
        const double density = body.soft->autoDensity ? impetus::constants::kSoftAutoDensities[0]
                                                      : body.soft->ellipsesPerSquareMeter;
        ellipses += side * side * density;
    }
    if (ellipses > kMaxFuzzEllipses)
        return false;
    if (ellipses == 0)
        return true;
    // "auto" as the run resolves it: --auto-density below gives the lowest density.
    impetus::model::World grids = world;
    for (impetus::model::Body& body : grids.bodies) {
        if (body.soft && body.soft->autoDensity) {
            body.soft->autoDensity = false;
            body.soft->ellipsesPerSquareMeter = impetus::constants::kSoftAutoDensities[0];
        }
    }
    impetus::controller::prepareSoftBodies(grids);
    std::size_t built = 0;
    for (const impetus::model::SoftGrid& grid : grids.softBodies)
        built += grid.size();
    const int substeps = impetus::controller::softStability(grids).substeps;
    return static_cast<double>(built) * substeps <= kMaxFuzzEllipseSubsteps;
}

/// The density "auto" soft bodies run at, per m²: the lowest automatic one, so that a scene's cost
/// does not depend on the cost model's choice (up to 16,384 ellipses, kSoftAutoHeadlessBudget).
constexpr const char* kFuzzAutoDensity = "64";

/// A folder of this process's own, for the scene file and the CSV (the CLI reads a path, and
/// checks that its outputs are not the scene).
struct ScratchFiles {
    fs::path folder;
    fs::path scene;
    fs::path csv;

    ScratchFiles()
    {
        folder = fs::temp_directory_path() / ("impetus-cli-fuzz-" + std::to_string(getpid()));
        fs::create_directories(folder);
        scene = folder / "scene.json";
        csv = folder / "out.csv";
    }
    ~ScratchFiles()
    {
        std::error_code ignored;
        fs::remove_all(folder, ignored);
    }
    ScratchFiles(const ScratchFiles&) = delete;
    ScratchFiles& operator=(const ScratchFiles&) = delete;
};

[[noreturn]] void fail(const std::string& what)
{
    std::fprintf(stderr, "cli_run_fuzzer: %s\n", what.c_str());
    std::abort();
}

/// True when `value` holds a null anywhere.
bool holdsNull(const nlohmann::json& value)
{
    if (value.is_null())
        return true;
    if (value.is_structured()) {
        for (const nlohmann::json& item : value)
            if (holdsNull(item))
                return true;
    }
    return false;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    // A scene too big to run fast is left out; one that does not load still goes to the CLI,
    // whose refusal is part of what is tested.
    const impetus::model::SceneLoadResult loaded =
        impetus::model::parseScene(std::string_view(reinterpret_cast<const char*>(data), size));
    if (loaded.ok() && !tiny(*loaded.world))
        return 0;

    static ScratchFiles files;
    {
        std::ofstream scene(files.scene, std::ios::binary | std::ios::trunc);
        scene.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
        if (!scene)
            fail("cannot write the scratch scene file " + files.scene.string());
    }
    const std::vector<std::string> args = {"run",        files.scene.string(), "--steps", kFuzzSteps,
                                           "--summary",  "-",                  "--csv",   files.csv.string(),
                                           "--sample-every", kFuzzSampleEvery,  "--auto-density", kFuzzAutoDensity};
    std::ostringstream out;
    std::ostringstream err;
    const int code = impetus::app::runCli(args, out, err, false);
    if (code != impetus::app::kExitOk && code != impetus::app::kExitRuntimeFailure &&
        code != impetus::app::kExitBadInput)
        fail("undocumented exit code " + std::to_string(code));
    if (code != impetus::app::kExitOk && err.str().empty())
        fail("a failed run must say why on stderr");
    if (code == impetus::app::kExitOk) {
        const nlohmann::json summary = nlohmann::json::parse(out.str(), nullptr, false);
        if (summary.is_discarded())
            fail("the summary is not JSON:\n" + out.str());
        if (holdsNull(summary))
            fail("the summary holds a null:\n" + out.str());
    }
    return 0;
}
