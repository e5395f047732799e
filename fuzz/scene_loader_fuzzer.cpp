/// \file scene_loader_fuzzer.cpp
/// libFuzzer target for the scene loader (scripts/fuzz, docs/testing.md): any bytes go to
/// model::parseScene. Whatever the bytes, reading must return a world or problems, never crash,
/// hang, leak or trip a sanitizer. A scene that loads must also survive what the program then does
/// with it: the range warnings, and a save that reads back as the same world.

#include "model/scene_io.h"
#include "model/scene_warnings.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace {

/// Stops the run with a message libFuzzer records with the input: a broken property is a finding
/// as much as a crash is.
[[noreturn]] void fail(const char* what)
{
    std::fprintf(stderr, "scene_loader_fuzzer: %s\n", what);
    std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace impetus::model;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const SceneLoadResult loaded = parseScene(text);
    if (loaded.ok() == !loaded.problems.empty())
        fail("a load result must be a world or problems, never both or neither");
    if (!loaded.ok())
        return 0;

    (void)sceneWarnings(*loaded.world);

    // The contract's round trip: parseScene(serializeScene(w)) gives w again.
    const SceneLoadResult again = parseScene(serializeScene(*loaded.world));
    if (!again.ok())
        fail("a loaded scene, saved, does not load again");
    if (!(*again.world == *loaded.world))
        fail("a loaded scene, saved and loaded again, is not the same world");
    return 0;
}
