// Scene generation and validation cost: both should grow as N (cell grids), up to 10^6 discs.
// Figures go to docs/benchmarks.md (## Scenes) with the command that produced them.

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "collide/sim/generate.hpp"
#include "collide/sim/scene_check.hpp"

namespace {

using namespace collide;

// N discs at packing fraction eta in the unit box; same seed every time.
Scene generated(std::size_t n, double eta, Boundary boundary) {
    Scene s;
    s.box.boundary = boundary;
    GenerateSpec g;
    g.count = n;
    g.radius = std::sqrt(eta / (static_cast<double>(n) * std::numbers::pi));
    g.seed = 7;
    generate_discs(s, g);
    return s;
}

// Lattice path (eta = 0.5, above the random-placement limit): the event-engine benchmarks' fluid.
void BM_GenerateLattice(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    for (auto _ : state) benchmark::DoNotOptimize(generated(n, 0.5, Boundary::periodic));
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

// Random sequential addition (eta = 0.3).
void BM_GenerateRandom(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    for (auto _ : state) benchmark::DoNotOptimize(generated(n, 0.3, Boundary::periodic));
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

// Validation of a dense (eta = 0.7) scene: finiteness, box, overlaps with the grid.
void BM_Validate(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    const Scene s = generated(n, 0.7, Boundary::walls);
    for (auto _ : state) validate_scene(s);
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

// The O(N^2) pair loop validation avoids, for the ratio at small N.
void BM_ValidateBruteForcePairs(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    const Scene s = generated(n, 0.7, Boundary::walls);
    for (auto _ : state) {
        std::size_t overlaps = 0;
        for (std::size_t i = 0; i < n; ++i) {
            for (std::size_t j = i + 1; j < n; ++j) {
                const double sum = s.discs[i].radius + s.discs[j].radius;
                overlaps += norm2(s.discs[i].position - s.discs[j].position) < sum * sum ? 1 : 0;
            }
        }
        benchmark::DoNotOptimize(overlaps);
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

}  // namespace

BENCHMARK(BM_GenerateLattice)
    ->RangeMultiplier(10)
    ->Range(1000, 1000000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GenerateRandom)
    ->RangeMultiplier(10)
    ->Range(1000, 1000000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Validate)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ValidateBruteForcePairs)
    ->RangeMultiplier(10)
    ->Range(1000, 10000)
    ->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
