// Cost of one BroadPhase::findPairs call on the benchmark scenes, at rest (the order kept from the
// last call is exactly right) and from scratch (a new BroadPhase each time, so std::sort runs);
// and with every box moved a little between calls (a pile settling: the input is never the same
// twice) or a lot (rain falling: every box leaves where it was).
// Run: build/bench/bench/impetus-bench-broad-phase

#include "controller/collision/broad_phase.h"
#include "model/example_scenes.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <variant>
#include <vector>

namespace {

using namespace impetus;

/// One proxy per convex piece, boxes from the pieces' world vertices (or the circle's extent).
std::vector<controller::BroadPhaseProxy> proxiesOf(const model::World& world)
{
    std::vector<controller::BroadPhaseProxy> proxies;
    for (std::uint32_t i = 0; i < world.bodies.size(); ++i) {
        const model::Body& body = world.bodies[i];
        if (const auto* circle = std::get_if<model::Circle>(&body.shape)) {
            const Vec2 r = Vec2::Constant(circle->radius);
            proxies.push_back({{body.state.position - r, body.state.position + r}, i, body.fixed});
            continue;
        }
        for (const auto& piece : body.geometry.convexPieces) {
            controller::Aabb box{body.worldPoint(piece.front()), body.worldPoint(piece.front())};
            for (const Vec2& v : piece) {
                box.lower = box.lower.cwiseMin(body.worldPoint(v));
                box.upper = box.upper.cwiseMax(body.worldPoint(v));
            }
            proxies.push_back({box, i, body.fixed});
        }
    }
    return proxies;
}

/// 10,000 unit boxes scattered at random over a 1 km square, few of them touching.
std::vector<controller::BroadPhaseProxy> spreadApart()
{
    std::mt19937 random(1);
    const auto unit = [&] { return static_cast<Scalar>(random()) / 4294967296.0; };
    std::vector<controller::BroadPhaseProxy> proxies;
    for (std::uint32_t i = 0; i < 10000; ++i) {
        const Vec2 centre(1000 * unit(), 1000 * unit());
        proxies.push_back({{centre - Vec2(0.5, 0.5), centre + Vec2(0.5, 0.5)}, i, false});
    }
    return proxies;
}

void findPairs(benchmark::State& state, const std::vector<controller::BroadPhaseProxy>& proxies, bool warm)
{
    controller::BroadPhase broadPhase;
    std::vector<controller::ProxyPair> pairs;
    broadPhase.findPairs(proxies, pairs);
    for (auto _ : state) {
        if (warm) {
            broadPhase.findPairs(proxies, pairs);
        } else {
            controller::BroadPhase cold;
            cold.findPairs(proxies, pairs);
        }
        benchmark::DoNotOptimize(pairs.data());
    }
    state.counters["proxies"] = static_cast<double>(proxies.size());
    state.counters["pairs"] = static_cast<double>(pairs.size());
}

/// Copies of `proxies`, each box moved by its own random offset of up to `step` on each axis from
/// the first copy, `step` again from the second, and so on, so that consecutive copies differ by
/// about `step` per box.
std::vector<std::vector<controller::BroadPhaseProxy>> moved(const std::vector<controller::BroadPhaseProxy>& proxies,
                                                            Scalar step, int copies)
{
    std::mt19937 random(2);
    const auto offset = [&] { return step * (2 * static_cast<Scalar>(random()) / 4294967296.0 - 1); };
    std::vector<std::vector<controller::BroadPhaseProxy>> frames(1, proxies);
    for (int c = 1; c < copies; ++c) {
        frames.push_back(frames.back());
        for (controller::BroadPhaseProxy& proxy : frames.back()) {
            const Vec2 move(offset(), offset());
            proxy.box.lower += move;
            proxy.box.upper += move;
        }
    }
    return frames;
}

/// One call per frame, the frames in turn (back and forth, so that no jump is larger than `step`).
void findPairsMoving(benchmark::State& state, const std::vector<controller::BroadPhaseProxy>& proxies, Scalar step)
{
    constexpr int kFrames = 8;
    const std::vector<std::vector<controller::BroadPhaseProxy>> frames = moved(proxies, step, kFrames);
    controller::BroadPhase broadPhase;
    std::vector<controller::ProxyPair> pairs;
    broadPhase.findPairs(frames[0], pairs);
    int frame = 0;
    int direction = 1;
    for (auto _ : state) {
        if (frame + direction < 0 || frame + direction >= kFrames)
            direction = -direction;
        frame += direction;
        broadPhase.findPairs(frames[static_cast<std::size_t>(frame)], pairs);
        benchmark::DoNotOptimize(pairs.data());
    }
    state.counters["proxies"] = static_cast<double>(proxies.size());
    state.counters["pairs"] = static_cast<double>(pairs.size());
}

const std::vector<controller::BroadPhaseProxy>& pyramid()
{
    static const auto proxies = proxiesOf(model::makePyramid(100));
    return proxies;
}
const std::vector<controller::BroadPhaseProxy>& pyramidGrid()
{
    static const auto proxies = proxiesOf(model::makePyramidGrid(20, 20, 10));
    return proxies;
}
const std::vector<controller::BroadPhaseProxy>& rain()
{
    static const auto proxies = proxiesOf(model::makePolygonRain(1000, 1));
    return proxies;
}
const std::vector<controller::BroadPhaseProxy>& tumbler()
{
    static const auto proxies = proxiesOf(model::makeRotatingBoxWithCircles(2000));
    return proxies;
}
const std::vector<controller::BroadPhaseProxy>& scattered()
{
    static const auto proxies = spreadApart();
    return proxies;
}

void BM_Pyramid100(benchmark::State& state) { findPairs(state, pyramid(), state.range(0) != 0); }
void BM_PyramidGrid20x20(benchmark::State& state) { findPairs(state, pyramidGrid(), state.range(0) != 0); }
void BM_PolygonRain1000(benchmark::State& state) { findPairs(state, rain(), state.range(0) != 0); }
void BM_RotatingBox2000(benchmark::State& state) { findPairs(state, tumbler(), state.range(0) != 0); }
void BM_SpreadApart10000(benchmark::State& state) { findPairs(state, scattered(), state.range(0) != 0); }
// Arg: the move between calls in µm, 1 µm (a resting pile's jitter) to 0.3 m (more than a box's
// fat margin: rain falling).
void BM_Pyramid100Moving(benchmark::State& state)
{
    findPairsMoving(state, pyramid(), 1e-6 * static_cast<Scalar>(state.range(0)));
}
void BM_PolygonRain1000Moving(benchmark::State& state)
{
    findPairsMoving(state, rain(), 1e-6 * static_cast<Scalar>(state.range(0)));
}

// Arg 1: warm (the kept order is right); arg 0: cold (sorted from scratch).
BENCHMARK(BM_Pyramid100)->ArgName("warm")->Arg(1)->Arg(0)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PyramidGrid20x20)->ArgName("warm")->Arg(1)->Arg(0)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PolygonRain1000)->ArgName("warm")->Arg(1)->Arg(0)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_RotatingBox2000)->ArgName("warm")->Arg(1)->Arg(0)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SpreadApart10000)->ArgName("warm")->Arg(1)->Arg(0)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Pyramid100Moving)->ArgName("um")->Arg(1)->Arg(1000)->Arg(300000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PolygonRain1000Moving)->ArgName("um")->Arg(1000)->Arg(300000)->Unit(benchmark::kMicrosecond);

} // namespace
