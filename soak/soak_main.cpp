/// \file soak_main.cpp
/// impetus-soak: generates random valid scenes in a closed box and runs each for 10 s, checking
/// for non-finite states, bodies leaving the box and energy growth past the documented bound. Built
/// with AddressSanitizer and UBSan, so that a memory error or undefined behaviour stops it too.
/// scripts/soak runs it; ctest runs 200 scenes. A finding is printed with its seed and written as
/// a scene file, which `impetus-soak --seed N` (or `impetus-cli run`) replays. docs/testing.md.

#include "model/scene_io.h"
#include "soak/random_scene.h"
#include "soak/soak_constants.h"
#include "soak/soak_run.h"

#include <charconv>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace {

using namespace impetus;

constexpr std::string_view kUsage =
    "usage: impetus-soak [--scenes N] [--first-seed N | --seed N] [--time SECONDS]\n"
    "                    [--min-bodies N] [--max-bodies N] [--out FOLDER] [--known FILE] [--verbose]\n"
    "--scenes N      how many scenes, seeds first-seed, first-seed + 1, ... (default 200)\n"
    "--seed N        replays the one scene of seed N (--scenes 1 --first-seed N)\n"
    "--time SECONDS  simulated time per scene (default 10)\n"
    "--out FOLDER    where a scene with a finding is written, as soak-seed-N.json (default .)\n"
    "--known FILE    seeds of open findings, one a line ('#' starts a comment): reported, not failed\n"
    "exit codes: 0 no new finding, 1 a scene had a finding not in --known, 2 bad usage\n";

struct Options {
    std::uint64_t scenes = 200;
    std::uint64_t firstSeed = 1;
    Scalar time = soak::kSoakTime;
    soak::RandomSceneOptions scene;
    std::filesystem::path out = ".";
    std::optional<std::filesystem::path> known;
    bool verbose = false;
};

struct UsageError {
    std::string message;
};

template <typename Number>
Number parse(std::string_view flag, const std::string& text)
{
    Number value{};
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size())
        throw UsageError{std::string(flag) + ": '" + text + "' is not a number"};
    return value;
}

Options parseOptions(const std::vector<std::string>& args)
{
    Options options;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& flag = args[i];
        if (flag == "--verbose") {
            options.verbose = true;
            continue;
        }
        if (i + 1 >= args.size())
            throw UsageError{"unknown argument or missing value: '" + flag + "'"};
        const std::string& value = args[++i];
        if (flag == "--scenes") {
            options.scenes = parse<std::uint64_t>(flag, value);
        } else if (flag == "--first-seed") {
            options.firstSeed = parse<std::uint64_t>(flag, value);
        } else if (flag == "--seed") {
            options.firstSeed = parse<std::uint64_t>(flag, value);
            options.scenes = 1;
        } else if (flag == "--time") {
            options.time = parse<double>(flag, value);
        } else if (flag == "--min-bodies") {
            options.scene.minBodies = parse<int>(flag, value);
        } else if (flag == "--max-bodies") {
            options.scene.maxBodies = parse<int>(flag, value);
        } else if (flag == "--out") {
            options.out = value;
        } else if (flag == "--known") {
            options.known = value;
        } else {
            throw UsageError{"unknown argument '" + flag + "'"};
        }
    }
    if (!(options.time > 0))
        throw UsageError{"--time must be positive"};
    if (options.scene.minBodies < 1 || options.scene.maxBodies < options.scene.minBodies)
        throw UsageError{"--min-bodies must be at least 1 and at most --max-bodies"};
    return options;
}

/// The seeds listed in `path`: one number a line, '#' to the end of a line is a comment.
std::set<std::uint64_t> readKnownSeeds(const std::filesystem::path& path)
{
    std::ifstream file(path);
    if (!file)
        throw UsageError{"--known: cannot read '" + path.string() + "'"};
    std::set<std::uint64_t> seeds;
    std::string line;
    while (std::getline(file, line)) {
        line = line.substr(0, line.find('#'));
        std::istringstream words(line);
        std::string word;
        if (words >> word)
            seeds.insert(parse<std::uint64_t>("--known", word));
    }
    return seeds;
}

} // namespace

int main(int argc, char** argv)
{
    Options options;
    std::set<std::uint64_t> known;
    try {
        options = parseOptions(std::vector<std::string>(argv + 1, argv + argc));
        if (options.known)
            known = readKnownSeeds(*options.known);
    } catch (const UsageError& e) {
        std::cerr << "impetus-soak: " << e.message << "\n\n" << kUsage;
        return 2;
    }

    std::uint64_t findings = 0;
    std::uint64_t knownFindings = 0;
    Scalar largestGrowth = 0;
    std::uint64_t largestGrowthSeed = 0;
    for (std::uint64_t seed = options.firstSeed; seed < options.firstSeed + options.scenes; ++seed) {
        model::World world;
        try {
            world = soak::makeRandomScene(seed, options.scene);
        } catch (const std::exception& e) {
            std::cerr << "impetus-soak: " << e.what() << '\n';
            return 1;
        }
        const soak::SoakResult result = soak::runSoakScene(world, options.time);
        if (result.largestEnergyGrowth > largestGrowth) {
            largestGrowth = result.largestEnergyGrowth;
            largestGrowthSeed = seed;
        }
        if (options.verbose)
            std::cout << "seed " << seed << ": " << world.bodies.size() << " bodies, " << result.steps
                      << " steps, energy growth " << result.largestEnergyGrowth
                      << (result.finding ? ", FINDING" : "") << std::endl;
        const bool isKnown = known.contains(seed);
        if (!result.finding) {
            if (isKnown)
                std::cout << "seed " << seed << ": a known finding that no longer happens; take it off "
                          << options.known->string() << " and enable its regression test" << std::endl;
            continue;
        }
        ++(isKnown ? knownFindings : findings);
        const std::filesystem::path file = options.out / ("soak-seed-" + std::to_string(seed) + ".json");
        const std::optional<std::string> error = model::saveSceneFile(file, world);
        std::cout << "seed " << seed << (isKnown ? " (known)" : "") << ": " << result.finding->check << " at t = " << result.finding->time
                  << " s: " << result.finding->detail << "; scene "
                  << (error ? "not written: " + *error : "written to " + file.string()) << std::endl;
    }
    std::cout << "impetus-soak: " << options.scenes << (options.scenes == 1 ? " scene" : " scenes") << " from seed "
              << options.firstSeed << ", "
              << options.time << " s each: " << findings << " with a new finding, " << knownFindings
              << " with a known one; ";
    if (largestGrowth > 0)
        std::cout << "largest energy growth " << largestGrowth << " of the energy above the box's floor (seed "
                  << largestGrowthSeed << "; bound " << soak::kEnergyGrowthBound << ")" << std::endl;
    else
        std::cout << "no scene's energy grew above the box's floor (bound " << soak::kEnergyGrowthBound << ")"
                  << std::endl;
    return findings == 0 ? 0 : 1;
}
