#include "controller/task_pair.h"

#include "model/constants.h"

namespace impetus::controller {

namespace {

/// Waits until `value` reaches at least `target`: spins a while first, since the solvers hand out
/// a task every few tens of microseconds and a sleep and wake-up costs about as much; then sleeps.
void waitUntilAtLeast(const std::atomic<std::uint64_t>& value, std::uint64_t target)
{
    for (int i = 0; i < constants::kTaskSpinCount; ++i) {
        if (value.load(std::memory_order_acquire) >= target)
            return;
#if defined(__x86_64__) || defined(__i386__)
        // Tells the processor this is a wait loop: it stops speculating down the loop, and a
        // sibling hardware thread gets the core's resources meanwhile.
        __builtin_ia32_pause();
#endif
    }
    for (;;) {
        const std::uint64_t now = value.load(std::memory_order_acquire);
        if (now >= target)
            return;
        value.wait(now, std::memory_order_acquire);
    }
}

} // namespace

TaskPair::~TaskPair()
{
    if (!m_worker.joinable())
        return;
    m_stop.store(true, std::memory_order_release);
    m_generation.fetch_add(1, std::memory_order_acq_rel);
    m_generation.notify_one();
    m_worker.join();
}

bool TaskPair::twoThreadsAvailable() { return std::thread::hardware_concurrency() >= 2; }

void TaskPair::run(const std::function<void(int)>& task)
{
    if (!twoThreadsAvailable()) {
        task(0);
        task(1);
        return;
    }
    if (!m_worker.joinable())
        m_worker = std::thread([this] { workerLoop(); });
    m_task = &task;
    const std::uint64_t generation = m_generation.fetch_add(1, std::memory_order_acq_rel) + 1;
    m_generation.notify_one();
    task(0);
    // Whoever comes first runs the second half. On a busy machine the worker may not have been
    // given a processor yet: then this thread runs it too rather than wait, and the step costs
    // what it would on one thread instead of more.
    std::uint64_t unclaimed = generation - 1;
    if (m_claimed.compare_exchange_strong(unclaimed, generation, std::memory_order_acq_rel))
        task(1);
    else
        waitUntilAtLeast(m_done, generation);
    m_task = nullptr;
}

void TaskPair::workerLoop()
{
    std::uint64_t seen = 0;
    for (;;) {
        waitUntilAtLeast(m_generation, seen + 1);
        seen = m_generation.load(std::memory_order_acquire);
        if (m_stop.load(std::memory_order_acquire))
            return;
        // The task of generation `seen` is there to take until the caller takes it itself.
        std::uint64_t unclaimed = seen - 1;
        if (!m_claimed.compare_exchange_strong(unclaimed, seen, std::memory_order_acq_rel))
            continue;
        (*m_task)(1);
        m_done.store(seen, std::memory_order_release);
        m_done.notify_one();
    }
}

void inHalves(TaskPair* tasks, std::size_t count, const std::function<void(std::size_t, std::size_t)>& work)
{
    inTwoParts(tasks, count / 2, count, work);
}

void inTwoParts(TaskPair* tasks, std::size_t cut, std::size_t count,
                const std::function<void(std::size_t, std::size_t)>& work)
{
    if (tasks)
        tasks->run([&](int part) { part == 0 ? work(0, cut) : work(cut, count); });
    else
        work(0, count);
}

} // namespace impetus::controller
