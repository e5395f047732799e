// TaskPair: both halves of every task run, the caller waits for both, and the worker's writes are
// visible to the caller afterwards.

#include "controller/task_pair.h"

#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <thread>

namespace impetus::controller {
namespace {

TEST(TaskPair, RunsBothHalvesAndWaitsForThem)
{
    TaskPair tasks;
    std::array<long, 2> sums{};
    for (int round = 1; round <= 2000; ++round) {
        tasks.run([&](int half) {
            // Uneven work, so that either side may finish first.
            long local = 0;
            for (int i = 0; i < (half == 0 ? 50 : 500); ++i)
                local += i % 7;
            sums[static_cast<std::size_t>(half)] += local + round;
        });
    }
    long expected0 = 0, expected1 = 0;
    for (int i = 0; i < 50; ++i)
        expected0 += i % 7;
    for (int i = 0; i < 500; ++i)
        expected1 += i % 7;
    const long rounds = 2000L * 2001L / 2;
    EXPECT_EQ(sums[0], 2000 * expected0 + rounds);
    EXPECT_EQ(sums[1], 2000 * expected1 + rounds);
}

TEST(TaskPair, TheSecondHalfRunsOnAnotherThreadWhenThereIsOne)
{
    TaskPair tasks;
    std::array<std::thread::id, 2> ids{};
    std::atomic<bool> secondStarted{false};
    tasks.run([&](int half) {
        ids[static_cast<std::size_t>(half)] = std::this_thread::get_id();
        if (half == 1)
            secondStarted = true;
        // The first half waits for the second to start, so the worker takes it (otherwise the
        // caller may take it itself when it finishes first). With one hardware thread the halves
        // run one after the other and there is nothing to wait for.
        while (half == 0 && TaskPair::twoThreadsAvailable() && !secondStarted)
            std::this_thread::yield();
    });
    EXPECT_EQ(ids[0], std::this_thread::get_id());
    if (TaskPair::twoThreadsAvailable()) {
        EXPECT_NE(ids[1], ids[0]);
    } else {
        EXPECT_EQ(ids[1], ids[0]);
    }
}

// Each half runs exactly once per run, whichever thread takes the second: here the first half is
// too short for the worker to wake, so the caller often takes the second half itself.
TEST(TaskPair, EachHalfRunsExactlyOnceWhoeverTakesIt)
{
    TaskPair tasks;
    std::array<std::atomic<int>, 2> runs{};
    int callerTookSecond = 0;
    for (int round = 0; round < 5000; ++round) {
        std::thread::id second;
        tasks.run([&](int half) {
            ++runs[static_cast<std::size_t>(half)];
            if (half == 1)
                second = std::this_thread::get_id();
        });
        if (second == std::this_thread::get_id())
            ++callerTookSecond;
    }
    EXPECT_EQ(runs[0].load(), 5000);
    EXPECT_EQ(runs[1].load(), 5000);
    if (!TaskPair::twoThreadsAvailable()) {
        EXPECT_EQ(callerTookSecond, 5000);
    }
}

TEST(TaskPair, StopsCleanlyWhetherOrNotItEverRan)
{
    { TaskPair unused; }
    int calls = 0;
    {
        TaskPair used;
        used.run([&](int half) {
            if (half == 1)
                ++calls;
        });
    }
    EXPECT_EQ(calls, 1);
}

} // namespace
} // namespace impetus::controller
