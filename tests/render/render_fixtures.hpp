#pragma once
// Shared fixtures of the renderer tests: small deterministic snapshots and frame contents.

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "collide/image.hpp"
#include "collide/render/renderer.hpp"
#include "collide/show/plot_words.hpp"
#include "collide/snapshot.hpp"
#include "collide/video/png.hpp"

namespace collide::render::test {

/// The backend the pixel tests render on: COLLIDE_TEST_GL (a --gl name: osmesa, egl, ...) or
/// auto. ctest runs the suite once more with COLLIDE_TEST_GL=egl (tests/CMakeLists.txt).
inline Backend test_backend() {
    const char* name = std::getenv("COLLIDE_TEST_GL");
    if (name == nullptr || *name == '\0') return Backend::automatic;
    return parse_backend(name, "COLLIDE_TEST_GL");
}

/// `count` discs of radius `radius` on a jittered grid in a box, velocities from a fixed seed.
inline Snapshot gas_snapshot(std::size_t count, double radius, Box box, std::uint32_t seed,
                             double time = 0.0) {
    Snapshot s;
    s.time = time;
    s.box = box;
    std::mt19937 rng(seed);
    std::normal_distribution<double> velocity(0.0, 0.5);
    std::uniform_real_distribution<double> jitter(-0.2, 0.2);
    const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(count))));
    for (std::size_t i = 0; i < count; ++i) {
        DiscState d;
        const double cx = (static_cast<double>(i % side) + 0.5 + jitter(rng)) / side;
        const double cy = (static_cast<double>(i / side) + 0.5 + jitter(rng)) / side;
        d.position = {cx * box.width, cy * box.height};
        d.velocity = {velocity(rng), velocity(rng)};
        d.radius = radius;
        d.mass = 1.0;
        d.color = {static_cast<std::uint8_t>(80 + (i * 37) % 170),
                   static_cast<std::uint8_t>(80 + (i * 91) % 170), 200};
        d.tagged = (i % 7 == 0);
        s.discs.push_back(d);
    }
    return s;
}

inline RenderConfig small_config(bool overlays) {
    RenderConfig config;
    config.width = 320;
    config.height = 180;
    config.overlays = overlays ? OverlayLevel::full : OverlayLevel::none;
    return config;
}

/// The lesson level (the title card, the figures in words, the captions) at `width` x `height`,
/// the rest of the configuration as the defaults.
inline RenderConfig lesson_config(int width, int height) {
    RenderConfig config;
    config.width = width;
    config.height = height;
    config.overlays = OverlayLevel::lesson;
    return config;
}

/// One disc at `position` (box units) with the given radius and colour.
inline DiscState disc_at(Vec2 position, double radius, Rgb8 color) {
    DiscState d;
    d.position = position;
    d.radius = radius;
    d.mass = 1.0;
    d.color = color;
    return d;
}

/// Writes `image` to $COLLIDE_RENDER_DUMP_DIR/<name>.png when that variable is set, so a human
/// can look at what the tests render; does nothing otherwise.
inline void dump_if_requested(const Image& image, const std::string& name) {
    const char* dir = std::getenv("COLLIDE_RENDER_DUMP_DIR");
    if (dir == nullptr || *dir == '\0') return;
    std::filesystem::create_directories(dir);
    video::write_png(image, std::filesystem::path(dir) / (name + ".png"));
}

/// A layout coordinate (pixels, float) rounded to the nearest pixel index.
inline int px(float v) {
    return static_cast<int>(std::lround(v));
}

/// The RGB of pixel (x, y) (row 0 is the top row).
inline Rgb8 rgb_at(const Image& image, int x, int y) {
    const std::uint8_t* p = image.pixel(x, y);
    return {p[0], p[1], p[2]};
}

/// Number of pixels in [x0, x1) x [y0, y1) whose colour is within `tolerance` of `color`.
inline int count_near(const Image& image, Rgb8 color, int tolerance, int x0 = 0, int y0 = 0,
                      int x1 = -1, int y1 = -1) {
    if (x1 < 0) x1 = image.width;
    if (y1 < 0) y1 = image.height;
    int count = 0;
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            const std::uint8_t* p = image.pixel(x, y);
            if (std::abs(p[0] - color.r) <= tolerance && std::abs(p[1] - color.g) <= tolerance &&
                std::abs(p[2] - color.b) <= tolerance) {
                ++count;
            }
        }
    }
    return count;
}

/// The plots' words and the cost graphic's values, as the app's FrameComposer fills them from the
/// presentation layer (collide_show) for a video whose speed range tops at `speed_max`.
inline void add_show_words(FrameContent& frame, double speed_max) {
    frame.speed_plot = show::speed_plot_words(speed_max);
    frame.drift_plot = show::drift_plot_words(frame.energy_drift);
    for (PanelContent& panel : frame.panels) {
        panel.cost_text = show::cost_text(panel.cost);
        panel.cost_words = show::cost_in_words(panel.cost);
    }
}

}  // namespace collide::render::test
