#include "view/timeline.h"

#include "view/simulation_runner.h"
#include "view/view_constants.h"

#include <algorithm>
#include <variant>

namespace impetus::view {

namespace {

/// Bytes a vector holds on the heap.
template <class T>
std::size_t heapBytes(const std::vector<T>& v)
{
    return v.capacity() * sizeof(T);
}

std::size_t bodyHeapBytes(const model::Body& body)
{
    std::size_t bytes = body.name.capacity();
    if (const auto* polygon = std::get_if<model::Polygon>(&body.shape))
        bytes += heapBytes(polygon->vertices);
    bytes += heapBytes(body.geometry.outline);
    bytes += heapBytes(body.geometry.convexPieces) + heapBytes(body.geometry.pieceNormals);
    for (const std::vector<Vec2>& piece : body.geometry.convexPieces)
        bytes += heapBytes(piece);
    for (const std::vector<Vec2>& normals : body.geometry.pieceNormals)
        bytes += heapBytes(normals);
    return bytes;
}

std::size_t gridHeapBytes(const model::SoftGrid& grid)
{
    std::size_t bytes = heapBytes(grid.cellEllipse) + heapBytes(grid.ellipseCell) + heapBytes(grid.restPositions) +
                        heapBytes(grid.springs) + heapBytes(grid.positions) + heapBytes(grid.velocities);
    for (const model::SoftSpringField& field : grid.springFields)
        bytes += heapBytes(field.stiffness) + heapBytes(field.restLength);
    return bytes;
}

} // namespace

std::size_t worldBytes(const model::World& world)
{
    std::size_t bytes = sizeof(model::World) + heapBytes(world.bodies) + heapBytes(world.springs) +
                        heapBytes(world.joints) + heapBytes(world.contacts) + heapBytes(world.softBodies);
    for (const model::Body& body : world.bodies)
        bytes += bodyHeapBytes(body);
    for (const model::SoftGrid& grid : world.softBodies)
        bytes += gridHeapBytes(grid);
    return bytes;
}

Timeline::Timeline(SimulationRunner& runner, QObject* parent)
    : QObject(parent)
    , m_runner(runner)
    , m_interval(constants::kKeyframeIntervalSteps)
    , m_budget(constants::kTimelineMemoryBudgetBytes)
{
    connect(&m_runner, &SimulationRunner::stepped, this, &Timeline::onStepped);
    connect(&m_runner, &SimulationRunner::worldChanged, this, &Timeline::onWorldChanged);
    connect(&m_runner, &SimulationRunner::sceneReplaced, this, &Timeline::onSceneReplaced);
    connect(&m_runner, &SimulationRunner::runningChanged, this, &Timeline::onRunningChanged);
    restart();
}

std::int64_t Timeline::firstStep() const { return m_keyframes.front().world.stepCount; }

std::int64_t Timeline::currentStep() const { return m_runner.world().stepCount; }

void Timeline::setMemoryBudget(std::size_t bytes)
{
    m_budget = bytes;
    thin();
}

std::size_t Timeline::keyframeBefore(std::int64_t step) const
{
    const auto after = std::ranges::upper_bound(m_keyframes, step, {},
                                                [](const Keyframe& k) { return k.world.stepCount; });
    return after == m_keyframes.begin() ? 0 : static_cast<std::size_t>(after - m_keyframes.begin()) - 1;
}

model::World Timeline::stateAt(std::int64_t step)
{
    step = std::clamp(step, firstStep(), m_lastStep);
    model::World world = m_keyframes[keyframeBefore(step)].world;
    // The engine is deterministic: the same steps from the same world give the same bits, so
    // this is the state the run had at `step`.
    while (world.stepCount < step)
        m_replay.step(world);
    return world;
}

const model::World& Timeline::runStart(std::int64_t step) const
{
    std::size_t k = keyframeBefore(step);
    while (k > 0 && !m_keyframes[k].essential)
        --k;
    return m_keyframes[k].world;
}

void Timeline::seek(std::int64_t step)
{
    model::World world = stateAt(step);
    m_showing = true;
    m_runner.showState(std::move(world));
    m_showing = false;
}

void Timeline::stepBack()
{
    const std::int64_t current = currentStep();
    if (current > firstStep())
        seek(current - 1);
}

void Timeline::restart()
{
    m_keyframes.clear();
    m_bytes = 0;
    m_interval = constants::kKeyframeIntervalSteps;
    addKeyframe(m_runner.world(), true);
    m_lastStep = m_runner.world().stepCount;
}

void Timeline::onSceneReplaced()
{
    restart();
    emit futureDiscarded(m_lastStep);
    emit rangeChanged();
}

void Timeline::onStepped()
{
    const model::World& world = m_runner.world();
    if (world.stepCount <= m_lastStep)
        return; // Step forward along the recorded run: nothing new
    m_lastStep = world.stepCount;
    if (world.stepCount - m_keyframes.back().world.stepCount >= m_interval)
        addKeyframe(world, false);
    emit rangeChanged();
}

void Timeline::onWorldChanged()
{
    if (m_showing)
        return;
    const model::World& world = m_runner.world();
    const std::int64_t step = world.stepCount;
    if (step < firstStep()) {
        restart();
        emit futureDiscarded(step);
        emit rangeChanged();
        return;
    }
    // Undo or Reset back to a state kept as a keyframe (a Play, an edit) goes there, keeping
    // the run after it: nothing was edited.
    const std::size_t k = keyframeBefore(step);
    if (step <= m_lastStep && m_keyframes[k].world.stepCount == step && m_keyframes[k].world == world)
        return;
    truncateAfter(step);
    if (m_keyframes.back().world.stepCount == step) {
        m_bytes -= m_keyframes.back().bytes;
        m_keyframes.pop_back();
    }
    if (m_keyframes.empty()) {
        restart();
    } else {
        addKeyframe(world, true);
    }
    emit futureDiscarded(step);
    emit rangeChanged();
}

void Timeline::onRunningChanged(bool running)
{
    if (!running)
        return;
    const model::World& world = m_runner.world();
    const std::int64_t step = world.stepCount;
    if (step < m_lastStep) {
        truncateAfter(step);
        emit futureDiscarded(step);
        emit rangeChanged();
    }
    // Kept so that Reset (back to this Play) finds it and keeps the run that follows.
    if (m_keyframes.back().world.stepCount != step)
        addKeyframe(world, false);
}

void Timeline::truncateAfter(std::int64_t step)
{
    while (m_keyframes.size() > 1 && m_keyframes.back().world.stepCount > step) {
        m_bytes -= m_keyframes.back().bytes;
        m_keyframes.pop_back();
    }
    m_lastStep = step;
}

void Timeline::addKeyframe(const model::World& world, bool essential)
{
    Keyframe keyframe{world, worldBytes(world), essential};
    m_bytes += keyframe.bytes;
    m_keyframes.push_back(std::move(keyframe));
    thin();
}

void Timeline::thin()
{
    while (m_bytes > m_budget) {
        // Keep a periodic keyframe only where the one kept before it is at least a (doubled)
        // interval back: about every other one goes. The newest always stays, so that the run
        // goes on from it without a long replay.
        m_interval *= 2;
        std::vector<Keyframe> kept;
        kept.reserve(m_keyframes.size());
        std::size_t bytes = 0;
        bool dropped = false;
        for (std::size_t i = 0; i < m_keyframes.size(); ++i) {
            Keyframe& k = m_keyframes[i];
            const bool last = i + 1 == m_keyframes.size();
            if (!k.essential && !last && !kept.empty() &&
                k.world.stepCount - kept.back().world.stepCount < m_interval) {
                dropped = true;
                continue;
            }
            bytes += k.bytes;
            kept.push_back(std::move(k));
        }
        m_keyframes = std::move(kept);
        m_bytes = bytes;
        // Only the start, the edits and the newest left, or an interval longer than the run:
        // nothing more to give.
        if (!dropped && (m_keyframes.size() <= 2 || m_interval > m_lastStep))
            break;
    }
}

} // namespace impetus::view
