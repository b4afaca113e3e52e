// Golden images at 320x180: a few whole frames compared with a tolerance (a channel may differ by
// more than 2 on at most 0.1% of the pixels), so small rasteriser changes pass and real ones fail.
// Regenerate deliberately with COLLIDE_UPDATE_GOLDENS=1 (then LOOK at the new PNGs).
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "../support/skip.hpp"
#include "render_fixtures.hpp"

namespace collide::render {
namespace {

namespace fs = std::filesystem;

constexpr int channel_tolerance = 2;
constexpr double max_differing_fraction = 0.001;

fs::path golden_path(const std::string& name) {
    return fs::path(COLLIDE_TESTS_DIR) / "render" / "golden" / (name + ".png");
}

bool updating_goldens() {
    const char* flag = std::getenv("COLLIDE_UPDATE_GOLDENS");
    return flag != nullptr && std::string(flag) == "1";
}

/// Pixels with some channel differing by more than the tolerance.
std::size_t differing_pixels(const Image& a, const Image& b) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
        for (std::size_t c = 0; c < 4; ++c) {
            if (std::abs(a.rgba[i + c] - b.rgba[i + c]) > channel_tolerance) {
                ++count;
                break;
            }
        }
    }
    return count;
}

void check_against_golden(const Image& image, const std::string& name) {
    test::dump_if_requested(image, "golden_" + name);
    const fs::path path = golden_path(name);
    if (updating_goldens()) {
        video::write_png(image, path);
        COLLIDE_SKIP_TEST("golden image rewritten, not compared: " << path.string());
    }
    REQUIRE_MESSAGE(fs::exists(path),
                    "missing golden " << path.string() << " (run with COLLIDE_UPDATE_GOLDENS=1)");
    const Image golden = video::read_png(path);
    REQUIRE(golden.width == image.width);
    REQUIRE(golden.height == image.height);
    const std::size_t differing = differing_pixels(image, golden);
    const auto allowed =
        static_cast<std::size_t>(max_differing_fraction * image.width * image.height);
    INFO("golden " << name << ": " << differing << " pixels differ (allowed " << allowed << ")");
    CHECK(differing <= allowed);
}

TEST_CASE("golden: two panels with overlays, speed colours and failure markers") {
    RenderConfig config = test::small_config(true);
    config.color_mode = ColorMode::speed;
    config.speed_max = 1.5;
    Renderer renderer(config, Backend::osmesa);
    Snapshot left = test::gas_snapshot(60, 0.03, {1.0, 1.0, Boundary::walls}, 11, 2.0);
    const Snapshot right = test::gas_snapshot(60, 0.03, {1.0, 1.0, Boundary::walls}, 11, 2.0);
    left.discs[3].position = left.discs[4].position + Vec2{0.03, 0.0};
    left.overlapping_pairs = {{3, 4}};
    left.missed_collisions = {{0.5, 0.5}};
    left.discs[5].position = {1.2, 0.5};
    left.discs[5].escaped = true;
    FrameContent frame;
    frame.panels = {{&left, "Time-driven, dt = 0.05", {"steps 40", "missed 3"}},
                    {&right, "Event-driven", {"events 812"}}};
    frame.time_text = "t = 2.00";
    frame.energy_drift = {{{0.0, 0.0}, {1.0, 0.01}, {2.0, 0.03}},
                          {{0.0, 0.0}, {1.0, 0.0}, {2.0, 0.0}}};
    frame.notes = {"red halo: overlap"};
    check_against_golden(renderer.render(frame), "two_panels_speed");
}

TEST_CASE("golden: periodic box with trails crossing the seam, overlays off") {
    RenderConfig config = test::small_config(false);
    config.color_mode = ColorMode::tag;
    Renderer renderer(config, Backend::osmesa);
    Snapshot s = test::gas_snapshot(30, 0.04, {2.0, 1.0, Boundary::periodic}, 5);
    s.discs[0].tagged = true;
    s.discs[0].velocity = {0.9, 0.35};
    s.discs[0].position = {1.5, 0.7};
    FrameContent frame;
    frame.panels = {{&s, "", {}}};
    Image image;
    for (int step = 0; step < 12; ++step) {
        s.time = 0.1 * step;
        for (DiscState& d : s.discs) {
            if (!d.tagged) continue;
            d.position = d.position + 0.1 * d.velocity;
            d.position.x = std::fmod(d.position.x + s.box.width, s.box.width);
            d.position.y = std::fmod(d.position.y + s.box.height, s.box.height);
        }
        renderer.render(frame, image);
    }
    check_against_golden(image, "periodic_trails_tag");
}

TEST_CASE("golden: one panel in scene colours with title and counters") {
    Renderer renderer(test::small_config(true), Backend::osmesa);
    const Snapshot s = test::gas_snapshot(25, 0.05, {1.6, 0.9, Boundary::walls}, 3, 0.5);
    FrameContent frame;
    frame.panels = {{&s, "Event-driven (priority queue)", {"events 42", "queue 97"}}};
    frame.time_text = "t = 0.50";
    check_against_golden(renderer.render(frame), "one_panel_scene");
}

}  // namespace
}  // namespace collide::render
