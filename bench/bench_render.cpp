// Renderer benchmarks on the offscreen backend (llvmpipe): draw and readback separately, overlays
// none (0), lesson (1, the default) and full (2), N discs per panel. Figures go to
// docs/benchmarks.md, section "Renderer".
//   cmake --build build/dev --target bench_render && build/dev/bench/bench_render
//   COLLIDE_BENCH_GL=egl build/dev/bench/bench_render     # EGL surfaceless instead of OSMesa
// The frame is the product's: 1280x720, two panels (time-driven, event-driven), each showing N
// discs at a packing fraction of 0.15 (so the covered pixel area is the same for every N); the
// "discs" counter is the total drawn, 2N (10^3 .. 10^5).

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "collide/render/renderer.hpp"
#include "collide/show/plot_words.hpp"

namespace {

using namespace collide;
using namespace collide::render;

/// COLLIDE_BENCH_GL (a --gl name) or auto: run once per backend to compare them side by side.
Backend bench_backend() {
    const char* name = std::getenv("COLLIDE_BENCH_GL");
    return name != nullptr && *name != '\0' ? parse_backend(name, "COLLIDE_BENCH_GL")
                                            : Backend::automatic;
}

constexpr double packing_fraction = 0.15;

Snapshot gas(std::size_t count, std::uint32_t seed, Boundary boundary) {
    Snapshot s;
    s.box = {1.0, 1.0, boundary};
    const double radius =
        std::sqrt(packing_fraction / (std::numbers::pi * static_cast<double>(count)));
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> where(radius, 1.0 - radius);
    std::normal_distribution<double> velocity(0.0, 0.5);
    s.discs.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        DiscState& d = s.discs[i];
        d.position = {where(rng), where(rng)};
        d.velocity = {velocity(rng), velocity(rng)};
        d.radius = radius;
        d.mass = 1.0;
        d.color = {static_cast<std::uint8_t>(80 + i % 170), 120, 200};
        d.tagged = i % 500 == 0;
    }
    return s;
}

struct Scenario {
    Snapshot left;
    Snapshot right;
    FrameContent frame;
    Renderer renderer;

    Scenario(std::size_t count, int overlays)
        : left(gas(count, 1, Boundary::walls)),
          right(gas(count, 2, Boundary::periodic)),
          renderer(config(overlays), bench_backend()) {
        frame.panels = {{&left, "Time-driven, dt = 0.01", {"steps 100", "missed 3"}},
                        {&right, "Event-driven (priority queue)", {"events 12345"}}};
        frame.time_text = "t = 1.00";
        // What the lesson level shows (ignored by the other levels).
        frame.panels[0].figures = {{"1,234", "missed", true}, {"12", "overlapping", true}};
        frame.panels[1].figures = {{"12,345", "collisions", false}, {"0", "missed", true}};
        frame.panels[0].cost_label = "pair tests";
        frame.panels[0].cost = 1.2e6;
        frame.panels[1].cost_label = "queue steps";
        frame.panels[1].cost = 2.4e4;
        frame.panels[1].accent = panel_accent(false);
        frame.caption = "Fast discs slip through the barrier between two time steps";
        frame.energy_line = "Energy conserved";
        frame.histogram = PlotSize::small;  // the lesson default with >= 200 moving discs
        for (int p = 0; p < 2; ++p) {
            std::vector<DriftPoint> series;
            for (int i = 0; i < 200; ++i) series.push_back({0.01 * i, 1e-4 * i * p});
            frame.energy_drift.push_back(series);
        }
        // The plots' words and the costs' values as the presentation layer writes them.
        frame.speed_plot = show::speed_plot_words(config(overlays).speed_max);
        frame.drift_plot = show::drift_plot_words(frame.energy_drift);
        for (PanelContent& panel : frame.panels) {
            panel.cost_text = show::cost_text(panel.cost);
            panel.cost_words = show::cost_in_words(panel.cost);
        }
    }

    /// 0: none, 1: lesson (the default), 2: full.
    static RenderConfig config(int overlays) {
        RenderConfig c;
        c.width = 1280;
        c.height = 720;
        c.color_mode = ColorMode::speed;
        c.speed_max = 2.0;
        c.overlays = overlays == 0   ? OverlayLevel::none
                     : overlays == 1 ? OverlayLevel::lesson
                                     : OverlayLevel::full;
        return c;
    }
};

void set_counters(benchmark::State& state) {
    state.counters["fps"] =
        benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["discs"] = static_cast<double>(2 * state.range(0));
}

// Draw only: build instances and overlays, issue GL, glFinish.
void BM_draw(benchmark::State& state) {
    Scenario s(static_cast<std::size_t>(state.range(0)), static_cast<int>(state.range(1)));
    for (auto _ : state) s.renderer.draw(s.frame);
    set_counters(state);
}

// Readback only: glReadPixels of the last frame into a reused image.
void BM_read_pixels(benchmark::State& state) {
    Scenario s(static_cast<std::size_t>(state.range(0)), static_cast<int>(state.range(1)));
    Image image;
    s.renderer.draw(s.frame);
    for (auto _ : state) {
        s.renderer.read_pixels(image);
        benchmark::DoNotOptimize(image.rgba.data());
    }
    set_counters(state);
}

// The whole frame: draw + readback (what `collide render` pays per frame).
void BM_render(benchmark::State& state) {
    Scenario s(static_cast<std::size_t>(state.range(0)), static_cast<int>(state.range(1)));
    Image image;
    for (auto _ : state) {
        s.renderer.render(s.frame, image);
        benchmark::DoNotOptimize(image.rgba.data());
    }
    set_counters(state);
}

void sizes(benchmark::internal::Benchmark* b) {
    for (const int overlays : {0, 1, 2}) {  // none, lesson, full
        for (const int n : {500, 5000, 15000, 50000}) b->Args({n, overlays});
    }
    // Process CPU time (llvmpipe's rasteriser threads included): on a shared machine it is the
    // honest measure of work; fps is frames per CPU second. Wall time is printed too.
    b->ArgNames({"N", "overlays"})->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
}

BENCHMARK(BM_draw)->Apply(sizes);
BENCHMARK(BM_read_pixels)
    ->Args({5000, 1})
    ->ArgNames({"N", "overlays"})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime();
BENCHMARK(BM_render)->Apply(sizes);

}  // namespace

BENCHMARK_MAIN();
