// Video benchmarks: RGBA -> yuv420p conversion per size, and whole-writer encoding
// throughput with libx264 per preset. Figures go to docs/benchmarks.md, section "Video".
//   cmake --build build/release --target bench_video && build/release/bench/bench_video

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "collide/image.hpp"
#include "collide/video/video_writer.hpp"
#include "rgba_to_yuv.hpp"

namespace {

using collide::Image;
using namespace collide::video;
using namespace collide::video::detail;

/// A frame like the renderer's: flat background, a few hundred anti-aliased discs.
Image disc_frame(int width, int height, int index) {
    Image image(width, height);
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        image.rgba[i] = 24;
        image.rgba[i + 1] = 28;
        image.rgba[i + 2] = 36;
        image.rgba[i + 3] = 255;
    }
    const double radius = height / 40.0;
    for (int disc = 0; disc < 300; ++disc) {
        const double cx = std::fmod(disc * 97.3 + index * (1.0 + disc % 5), width);
        const double cy = std::fmod(disc * 53.1 + index * (0.5 + disc % 3), height);
        const std::uint8_t r = static_cast<std::uint8_t>(80 + (disc * 37) % 170);
        const std::uint8_t g = static_cast<std::uint8_t>(80 + (disc * 71) % 170);
        const std::uint8_t b = static_cast<std::uint8_t>(80 + (disc * 13) % 170);
        for (int y = std::max(0, int(cy - radius - 1)); y < std::min(height, int(cy + radius + 2));
             ++y) {
            for (int x = std::max(0, int(cx - radius - 1));
                 x < std::min(width, int(cx + radius + 2)); ++x) {
                const double d = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
                const double coverage = std::clamp(radius + 0.5 - d, 0.0, 1.0);
                if (coverage <= 0.0) continue;
                std::uint8_t* p = image.pixel(x, y);
                p[0] = static_cast<std::uint8_t>(p[0] + coverage * (r - p[0]));
                p[1] = static_cast<std::uint8_t>(p[1] + coverage * (g - p[1]));
                p[2] = static_cast<std::uint8_t>(p[2] + coverage * (b - p[2]));
            }
        }
    }
    return image;
}

struct Planes {
    std::vector<std::uint8_t> y, u, v;
    Yuv420View view;
    Planes(int w, int h) : y(std::size_t(w) * h), u(std::size_t(w / 2) * (h / 2)), v(u.size()) {
        view = {y.data(), u.data(), v.data(), w, w / 2, w / 2};
    }
};

int width_for(int height) {
    return height * 16 / 9;
}

void BM_ConvertHand(benchmark::State& state) {
    const int height = int(state.range(0));
    const int width = width_for(height);
    const Image frame = disc_frame(width, height, 0);
    Planes planes(width, height);
    for (auto _ : state) {
        rgba_to_yuv420_bt709(frame.rgba.data(), std::ptrdiff_t(frame.stride()), width, height,
                             planes.view);
        benchmark::DoNotOptimize(planes.y.data());
    }
}
BENCHMARK(BM_ConvertHand)->Arg(720)->Arg(1080)->Unit(benchmark::kMillisecond)->UseRealTime();

/// Whole VideoWriter (queue, conversion, libx264, MP4 muxing) at 720p30: frames per second.
void BM_EncodeX264(benchmark::State& state, const char* preset) {
    constexpr int width = 1280;
    constexpr int height = 720;
    constexpr int frames = 60;
    std::vector<Image> clip;
    for (int i = 0; i < frames; ++i) clip.push_back(disc_frame(width, height, i));
    set_libav_verbose(false);
    const auto path = std::filesystem::temp_directory_path() /
                      ("collide-bench-" + std::to_string(::getpid()) + ".mp4");
    std::uintmax_t bytes = 0;
    for (auto _ : state) {
        VideoOptions options;
        options.path = path;
        options.width = width;
        options.height = height;
        options.fps = 30;
        options.preset = preset;
        VideoWriter writer(options);
        for (const Image& frame : clip) writer.write(frame);
        writer.finish();
        bytes = std::filesystem::file_size(path);
    }
    std::filesystem::remove(path);
    state.SetItemsProcessed(state.iterations() * frames);  // items/s = encoded frames per second
    state.counters["kB_per_s_of_video"] = double(bytes) / 1000.0 / (frames / 30.0);
    state.SetLabel(std::string("libx264 ") + preset + ", crf 20, 720p30, 60 frames");
}
BENCHMARK_CAPTURE(BM_EncodeX264, ultrafast, "ultrafast")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);
BENCHMARK_CAPTURE(BM_EncodeX264, veryfast, "veryfast")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);
BENCHMARK_CAPTURE(BM_EncodeX264, medium, "medium")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);

}  // namespace

BENCHMARK_MAIN();
