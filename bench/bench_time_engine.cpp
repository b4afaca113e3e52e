// The time-driven engine's cost and its failures, for docs/benchmarks.md ("Time-driven engine"):
//  - BM_TimeEngineCost: wall-clock seconds per simulated time unit, all-pairs vs grid, versus N;
//  - BM_TimeEngineMisses: missed collisions and escapes versus dt for one gas (counters only; the
//    timing of that one is incidental).

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "collide/sim/time_engine.hpp"

namespace {

/// n = side^2 discs of radius r on a jittered lattice in the unit box with walls, velocities
/// uniform in [-1, 1]^2 (speed scale ~0.8), equal masses. Fixed seed: every run sees the same gas.
collide::Scene lattice_gas(std::size_t side, double r) {
    std::mt19937_64 rng(2024);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    collide::Scene scene;
    scene.name = "bench-gas";
    const double spacing = 1.0 / static_cast<double>(side);
    const double jitter = 0.45 * (spacing - 2.0 * r);
    for (std::size_t ix = 0; ix < side; ++ix) {
        for (std::size_t iy = 0; iy < side; ++iy) {
            collide::Disc d;
            d.position = {(static_cast<double>(ix) + 0.5) * spacing + jitter * unit(rng),
                          (static_cast<double>(iy) + 0.5) * spacing + jitter * unit(rng)};
            d.velocity = {unit(rng), unit(rng)};
            d.radius = r;
            scene.discs.push_back(d);
        }
    }
    return scene;
}

/// Radius giving packing fraction eta for n discs in the unit box.
double radius_for(std::size_t n, double eta) {
    return std::sqrt(eta / (3.14159265358979 * static_cast<double>(n)));
}

// Args: side (N = side^2), detection (0 all-pairs, 1 grid). dt = 1e-3, eta = 0.2, 0.05 time units.
void BM_TimeEngineCost(benchmark::State& state) {
    const auto side = static_cast<std::size_t>(state.range(0));
    const std::size_t n = side * side;
    const collide::Scene scene = lattice_gas(side, radius_for(n, 0.2));
    collide::EngineOptions options;
    options.engine = collide::EngineKind::time;
    options.dt = 1e-3;
    options.td_detect = state.range(1) == 0 ? collide::OverlapDetection::all_pairs
                                            : collide::OverlapDetection::grid;
    const double span = 0.05;
    collide::Measurements last;
    for (auto _ : state) {
        collide::sim::TimeEngine engine(scene, options);
        engine.advance_to(span);
        last = engine.measurements();
        benchmark::DoNotOptimize(last.kinetic_energy);
    }
    state.SetLabel(std::string(collide::to_string(options.td_detect)));
    state.counters["N"] = static_cast<double>(n);
    state.counters["checks_per_step"] =
        static_cast<double>(last.overlap_checks) / static_cast<double>(last.steps);
    state.counters["s_per_time_unit"] = last.seconds_per_time_unit;
    state.counters["collisions"] = static_cast<double>(last.collisions_pair + last.collisions_wall);
}
BENCHMARK(BM_TimeEngineCost)
    ->ArgsProduct({{10, 20, 32, 45}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

// Args: dt in units of 1e-4. N = 400, eta = 0.2 (r ~ 0.0126), 1 time unit, grid detection.
void BM_TimeEngineMisses(benchmark::State& state) {
    const collide::Scene scene = lattice_gas(20, radius_for(400, 0.2));
    collide::EngineOptions options;
    options.engine = collide::EngineKind::time;
    options.dt = static_cast<double>(state.range(0)) * 1e-4;
    options.td_detect = collide::OverlapDetection::grid;
    collide::Measurements last;
    for (auto _ : state) {
        collide::sim::TimeEngine engine(scene, options);
        engine.advance_to(1.0);
        last = engine.measurements();
    }
    state.counters["dt"] = options.dt;
    state.counters["collisions"] = static_cast<double>(last.collisions_pair);
    state.counters["missed"] = static_cast<double>(last.missed_collisions);
    state.counters["escaped"] = static_cast<double>(last.escaped);
    state.counters["max_overlap_seen"] = last.max_overlap_seen;
    state.counters["energy_drift"] = last.energy_drift;
}
BENCHMARK(BM_TimeEngineMisses)
    ->Arg(1)
    ->Arg(10)
    ->Arg(50)
    ->Arg(100)
    ->Arg(250)
    ->Arg(500)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
