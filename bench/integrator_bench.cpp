// Cost of one fixed step under each integrator, on a hanging chain of N balls joined by springs
// (one coupled system). Run: build/bench/bench/impetus-bench-integrators

#include "controller/simulation.h"

#include <benchmark/benchmark.h>

namespace {

using namespace impetus;

model::World makeChain(model::IntegratorKind kind, int links)
{
    model::World world;
    world.settings.integrator = kind;
    for (int i = 0; i < links; ++i) {
        model::Body ball;
        ball.name = "link" + std::to_string(i);
        ball.shape = model::Circle{0.05};
        ball.state.position = Vec2(0.3 * (i + 1), 0);
        ball.updateDerived();
        world.bodies.push_back(ball);
        model::Spring spring;
        spring.bodyA = model::BodyId{static_cast<std::uint32_t>(i)};
        if (i > 0)
            spring.bodyB = model::BodyId{static_cast<std::uint32_t>(i - 1)};
        spring.stiffness = 200;
        spring.damping = 0.5;
        spring.restLength = 0.3;
        world.springs.push_back(spring);
    }
    return world;
}

void stepChain(benchmark::State& state, model::IntegratorKind kind)
{
    model::World world = makeChain(kind, static_cast<int>(state.range(0)));
    controller::Simulation simulation;
    for (auto _ : state) {
        simulation.step(world);
        benchmark::DoNotOptimize(world.bodies.back().state.position);
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_Euler(benchmark::State& state) { stepChain(state, model::IntegratorKind::Euler); }
void BM_SemiImplicitEuler(benchmark::State& state) { stepChain(state, model::IntegratorKind::SemiImplicitEuler); }
void BM_Rk4(benchmark::State& state) { stepChain(state, model::IntegratorKind::Rk4); }

BENCHMARK(BM_Euler)->Arg(10)->Arg(1000);
BENCHMARK(BM_SemiImplicitEuler)->Arg(10)->Arg(1000);
BENCHMARK(BM_Rk4)->Arg(10)->Arg(1000);

} // namespace
