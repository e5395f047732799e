#pragma once
/// \file task_pair.h
/// Runs one task on two threads at once: the caller's and one worker thread. The solvers use it to
/// work on two halves of a large world side by side (docs/physics.md, "Two threads").

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <thread>

namespace impetus::controller {

/// A worker thread that runs `task(1)` while the calling thread runs `task(0)`, and returns when
/// both are done. If the worker has not started task(1) by the time task(0) is done (a busy
/// machine), the calling thread runs it itself. The worker is started on the first run() and stopped by the destructor. On a
/// machine with one hardware thread, run() calls task(0) and then task(1) on the caller's thread:
/// a task whose two halves touch disjoint data gives the same bits either way.
class TaskPair {
public:
    TaskPair() = default;
    TaskPair(const TaskPair&) = delete;
    TaskPair& operator=(const TaskPair&) = delete;
    ~TaskPair();

    /// Runs task(0) here and task(1) on the worker, and waits for both. `task` must not throw.
    void run(const std::function<void(int)>& task);

    /// True when run() really uses two threads on this machine.
    static bool twoThreadsAvailable();

private:
    void workerLoop();

    std::thread m_worker;
    const std::function<void(int)>* m_task = nullptr;
    /// Bumped by run() to hand the worker a task; the worker waits for it to change.
    std::atomic<std::uint64_t> m_generation{0};
    /// The last generation whose second half someone (the worker or the caller) has taken.
    std::atomic<std::uint64_t> m_claimed{0};
    /// Set to the generation the worker has finished.
    std::atomic<std::uint64_t> m_done{0};
    std::atomic<bool> m_stop{false};
};

/// Runs work(0, count / 2) and work(count / 2, count) on two threads when `tasks` is given, or
/// work(0, count) on this one. For loops whose iterations touch disjoint data, so that either way
/// gives the same bits.
void inHalves(TaskPair* tasks, std::size_t count, const std::function<void(std::size_t, std::size_t)>& work);

/// Runs work(0, cut) and work(cut, count) on two threads when `tasks` is given, or work(0, count)
/// on this one: inHalves with the cut where the caller wants it.
void inTwoParts(TaskPair* tasks, std::size_t cut, std::size_t count,
                const std::function<void(std::size_t, std::size_t)>& work);

} // namespace impetus::controller
