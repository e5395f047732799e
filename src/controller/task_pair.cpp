#include "controller/task_pair.h"

#include "model/constants.h"

namespace impetus::controller {

namespace {

/// Waits until `value` differs from `old`: spins a while first, since the solvers hand out a task
/// every few tens of microseconds and a futex sleep and wake-up costs about as much; then sleeps.
void waitForChange(const std::atomic<std::uint64_t>& value, std::uint64_t old)
{
    for (int i = 0; i < constants::kTaskSpinCount; ++i) {
        if (value.load(std::memory_order_acquire) != old)
            return;
    }
    while (value.load(std::memory_order_acquire) == old)
        value.wait(old, std::memory_order_acquire);
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
    waitForChange(m_done, generation - 1);
    m_task = nullptr;
}

void TaskPair::workerLoop()
{
    std::uint64_t seen = 0;
    for (;;) {
        waitForChange(m_generation, seen);
        seen = m_generation.load(std::memory_order_acquire);
        if (m_stop.load(std::memory_order_acquire))
            return;
        (*m_task)(1);
        m_done.store(seen, std::memory_order_release);
        m_done.notify_one();
    }
}

} // namespace impetus::controller
