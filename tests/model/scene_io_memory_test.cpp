// Running out of memory while reading a scene (issue 17, item 4, F7): a message, never an abort.
//
// This test program replaces the global operator new with one that can be given a budget: while
// armed, an allocation that would take the live heap past the budget throws std::bad_alloc, as a
// real allocator does when memory (or `ulimit -v`) runs out. Memory freed makes room again, as it
// does for real. Before the fix, freeing the half-built document (nlohmann's destructor allocates
// a stack to flatten it) threw from a destructor and the program aborted with exit 134.

#include "model/scene_io.h"

#include <gtest/gtest.h>

#include <malloc.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <string>

namespace {

std::atomic<bool> g_armed{false};
std::atomic<std::size_t> g_live{0};
std::atomic<std::size_t> g_peak{0};
std::atomic<std::size_t> g_budget{0};

void* allocate(std::size_t size)
{
    void* p = std::malloc(size == 0 ? 1 : size);
    if (!p)
        throw std::bad_alloc();
    const std::size_t got = malloc_usable_size(p);
    const std::size_t live = g_live.fetch_add(got) + got;
    if (g_armed.load() && live > g_budget.load()) {
        g_live.fetch_sub(got);
        std::free(p);
        throw std::bad_alloc();
    }
    std::size_t peak = g_peak.load();
    while (live > peak && !g_peak.compare_exchange_weak(peak, live)) {
    }
    return p;
}

void release(void* p) noexcept
{
    if (!p)
        return;
    g_live.fetch_sub(malloc_usable_size(p));
    std::free(p);
}

} // namespace

void* operator new(std::size_t size) { return allocate(size); }
void* operator new[](std::size_t size) { return allocate(size); }
void operator delete(void* p) noexcept { release(p); }
void operator delete[](void* p) noexcept { release(p); }
void operator delete(void* p, std::size_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t) noexcept { release(p); }

namespace impetus::model {
namespace {

/// A valid scene of `count` circles: large enough that its document holds big arrays.
std::string manyBodies(int count)
{
    std::string text = R"({"format":"impetus-scene","version":1,"world":{"gravity":[0,0]},"bodies":[)";
    for (int k = 0; k < count; ++k) {
        if (k > 0)
            text += ',';
        text += R"({"name":"body-number-)" + std::to_string(k) +
                R"(","shape":{"type":"polygon","vertices":[[0,0],[1,0],[1,1],[0,1]]},"position":[)" +
                std::to_string(3 * (k % 100)) + ',' + std::to_string(3 * (k / 100)) + "]}";
    }
    return text + "]}";
}

/// parseScene with the heap limited to what is live now plus `allowance` bytes.
SceneLoadResult parseWithAllowance(const std::string& text, std::size_t allowance)
{
    g_budget = g_live.load() + allowance;
    g_armed = true;
    SceneLoadResult result = parseScene(text);
    g_armed = false;
    return result;
}

TEST(SceneOutOfMemory, EveryShortfallGivesAMessageNotAnAbort)
{
    constexpr int kBodies = 4000;
    const std::string text = manyBodies(kBodies);

    // What a full read needs: its peak above what was live before it.
    const std::size_t before = g_live.load();
    g_peak = before;
    const SceneLoadResult full = parseScene(text);
    ASSERT_TRUE(full.ok());
    ASSERT_EQ(full.world->bodies.size(), static_cast<std::size_t>(kBodies));
    const std::size_t need = g_peak.load() - before;

    // Memory runs out at a tenth, a fifth, … of the way: in the middle of the parse, of the
    // document's big arrays, of the bodies being built. Each time the whole read is refused with
    // one message, and the process lives on.
    constexpr int kTrials = 10;
    for (int trial = 1; trial < kTrials; ++trial) {
        const std::size_t allowance = need * static_cast<std::size_t>(trial) / kTrials;
        const SceneLoadResult result = parseWithAllowance(text, allowance);
        ASSERT_FALSE(result.ok()) << "allowance " << allowance << " of " << need;
        ASSERT_EQ(result.problems.size(), 1u);
        EXPECT_EQ(result.problems.front().path, "(root)");
        EXPECT_NE(result.problems.front().reason.find("out of memory while reading the scene"), std::string::npos)
            << result.problems.front().reason;
    }
    // With room to spare it reads again, to the same world. (Exactly `need` is not always enough:
    // the sizes counted are malloc's usable sizes, which depend on which freed blocks it reuses.)
    const SceneLoadResult again = parseWithAllowance(text, 2 * need);
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(again.world->bodies.size(), full.world->bodies.size());
}

} // namespace
} // namespace impetus::model
