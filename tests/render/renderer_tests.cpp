// Pixel checks of the renderer on OSMesa: discs land where the layout says, with the right colour,
// rows top-down; tiny and huge discs; periodic images; escaped discs; failure markers; errors.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include "../support/assert_death.hpp"
#include "../support/input_error.hpp"
#include "../support/skip.hpp"
#include "collide/assert.hpp"
#include "collide/error.hpp"
#include "collide/show/failure_marks.hpp"
#include "layout.hpp"
#include "render_fixtures.hpp"

namespace collide::render {
namespace {

using test::count_near;
using test::disc_at;
using test::rgb_at;

constexpr Rgb8 red{255, 0, 0};
constexpr Rgb8 green{0, 255, 0};
constexpr Rgb8 box_fill{34, 36, 46};  // box_fill_color in renderer.cpp

/// Renders one panel (overlays off) and hands back the image and the panel's layout.
struct OnePanel {
    Image image;
    PanelLayout layout;
};

OnePanel render_one(const Snapshot& snapshot, RenderConfig config = test::small_config(false)) {
    Renderer renderer(config, test::test_backend());
    FrameContent frame;
    frame.panels = {{&snapshot, "", {}}};
    OnePanel out;
    out.image = renderer.render(frame);
    out.layout = compute_layout(config, {snapshot.box}, 0.0F).panels.at(0);
    return out;
}

Snapshot empty_snapshot(Box box) {
    Snapshot s;
    s.box = box;
    return s;
}

TEST_CASE("a disc lands at its centre with its colour, rows top-down") {
    Snapshot s = empty_snapshot({16.0, 9.0, Boundary::walls});
    s.discs = {disc_at({4.0, 6.5}, 1.0, red), disc_at({12.0, 2.0}, 1.0, green)};
    const OnePanel r = render_one(s);
    test::dump_if_requested(r.image, "pixel_two_discs");
    REQUIRE(r.image.width == 320);
    REQUIRE(r.image.height == 180);
    REQUIRE(r.image.rgba.size() == 320u * 180u * 4u);

    const PointF red_c = r.layout.to_pixels({4.0, 6.5}, s.box);
    const PointF green_c = r.layout.to_pixels({12.0, 2.0}, s.box);
    // y up in the box, y down in the image: the higher disc is in the upper rows.
    CHECK(red_c.y < 90.0F);
    CHECK(green_c.y > 90.0F);
    const auto px = [](float v) { return static_cast<int>(std::floor(v)); };
    CHECK(rgb_at(r.image, px(red_c.x), px(red_c.y)) == red);
    CHECK(rgb_at(r.image, px(green_c.x), px(green_c.y)) == green);

    // Inside 80% of the radius is the disc's colour, beyond 130% is the box fill.
    const double rad = 1.0 * r.layout.scale;
    for (const auto& [dx, dy] :
         {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
        const int xi = px(red_c.x + static_cast<float>(0.8 * rad * dx));
        const int yi = px(red_c.y + static_cast<float>(0.8 * rad * dy));
        CHECK(rgb_at(r.image, xi, yi) == red);
        const int xo = px(red_c.x + static_cast<float>(1.3 * rad * dx));
        const int yo = px(red_c.y + static_cast<float>(1.3 * rad * dy));
        CHECK(rgb_at(r.image, xo, yo) == box_fill);
    }
    // Area: pi r^2 pixels within a few percent (the antialiased rim is half in, half out).
    const double area = std::numbers::pi * rad * rad;
    const int reds = count_near(r.image, red, 100);
    CHECK(std::abs(reds - area) < 0.05 * area);
    // The alpha channel is opaque everywhere (encoders ignore it, PNGs must not be see-through).
    for (std::size_t i = 3; i < r.image.rgba.size(); i += 4) REQUIRE(r.image.rgba[i] == 255);
}

// Scenes may be written in any units from 1e-50 to 1e50 (validate_scene): the picture depends on
// the scene's shape only. (A floor on the pixels per unit once made boxes of 1e20 units 10^11
// pixels wide, and the frame failed with a GL error.)
TEST_CASE("the same scene in tiny or huge units gives the same picture") {
    const auto scaled = [](double unit) {
        Snapshot s = empty_snapshot({16.0 * unit, 9.0 * unit, Boundary::walls});
        s.discs = {disc_at({4.0 * unit, 6.5 * unit}, 1.0 * unit, red),
                   disc_at({12.0 * unit, 2.0 * unit}, 0.5 * unit, green)};
        return render_one(s).image;
    };
    const Image reference = scaled(1.0);
    CHECK(count_near(reference, red, 10) > 100);
    for (const double unit : {1e-45, 1e-12, 1e20, 1e45}) {
        CAPTURE(unit);
        const Image image = scaled(unit);
        REQUIRE(image.rgba.size() == reference.rgba.size());
        std::size_t differing = 0;
        for (std::size_t i = 0; i < image.rgba.size(); ++i)
            differing += image.rgba[i] != reference.rgba[i];
        CHECK(differing <= 8);  // the rounding of a few rim pixels at most
    }
}

TEST_CASE("a disc one pixel across is still visible") {
    Snapshot s = empty_snapshot({16.0, 9.0, Boundary::walls});
    RenderConfig config = test::small_config(false);
    const double scale = compute_layout(config, {s.box}, 0.0F).panels[0].scale;
    s.discs = {disc_at({8.0, 4.5}, 0.5 / scale, {255, 255, 255})};  // radius 0.5 px
    const OnePanel r = render_one(s, config);
    test::dump_if_requested(r.image, "pixel_one_px_disc");
    const PointF c = r.layout.to_pixels({8.0, 4.5}, s.box);
    int brightest = 0;
    int lit = 0;
    double coverage = 0.0;  // sum of the disc's share of each pixel, from the green channel
    for (int y = static_cast<int>(c.y) - 3; y <= static_cast<int>(c.y) + 3; ++y) {
        for (int x = static_cast<int>(c.x) - 3; x <= static_cast<int>(c.x) + 3; ++x) {
            const int g = rgb_at(r.image, x, y).g;
            brightest = std::max(brightest, g);
            if (g > box_fill.g + 10) ++lit;
            coverage += static_cast<double>(g - box_fill.g) / (255.0 - box_fill.g);
        }
    }
    CHECK(brightest > box_fill.g + 50);  // clearly visible against the box
    CHECK(lit >= 1);
    CHECK(lit <= 9);  // and still about a pixel: no blob
    // Antialiasing keeps its total brightness: pi r^2 = 0.785 pixels' worth.
    CHECK(coverage == doctest::Approx(std::numbers::pi * 0.25).epsilon(0.3));
}

/// Renders one disc of `radius_px` at the centre of a frame and checks its rim and area.
void check_crisp_disc(RenderConfig config, double radius_px, const std::string& name) {
    Snapshot s = empty_snapshot({16.0, 9.0, Boundary::walls});
    const double scale = compute_layout(config, {s.box}, 0.0F).panels[0].scale;
    s.discs = {disc_at({8.0, 4.5}, radius_px / scale, red)};
    const OnePanel r = render_one(s, config);
    test::dump_if_requested(r.image, name);
    const PointF c = r.layout.to_pixels({8.0, 4.5}, s.box);
    const int row = static_cast<int>(c.y);
    int rim = 0;  // pixels on the centre row that are neither the disc nor the box
    int inside = 0;
    for (int x = 0; x < r.image.width; ++x) {
        const Rgb8 p = rgb_at(r.image, x, row);
        if (p == red) {
            ++inside;
        } else if (!(p == box_fill) && x > r.layout.box.x0 + 1 && x < r.layout.box.x1 - 1) {
            ++rim;
        }
    }
    CHECK(rim <= 4);  // at most two blended pixels per edge
    CHECK(std::abs(inside - 2.0 * radius_px) <= 2.0);
    const double area = std::numbers::pi * radius_px * radius_px;
    CHECK(std::abs(count_near(r.image, red, 100) - area) < 0.02 * area);
}

TEST_CASE("a disc half the frame high is crisp: a one-pixel antialiased rim") {
    // 320x180: drawn as a point sprite; 1280x720 (360 px across): too big for one, a quad.
    check_crisp_disc(test::small_config(false), 45.0, "pixel_half_frame_disc");
    RenderConfig large = test::small_config(false);
    large.width = 1280;
    large.height = 720;
    check_crisp_disc(large, 180.0, "pixel_half_frame_disc_720p");
}

TEST_CASE("a disc crossing the frame edge is drawn up to the edge") {
    // Point sprites vanish when their centre leaves the frame: such discs must go as quads.
    RenderConfig config = test::small_config(false);
    Snapshot s = empty_snapshot({1.0, 1.0, Boundary::walls});
    DiscState gone = disc_at({-0.9, 0.5}, 0.3, green);  // escaped, pinned just left of the box
    gone.escaped = true;
    s.discs = {gone};
    const OnePanel r = render_one(s, config);
    test::dump_if_requested(r.image, "pixel_frame_edge_disc");
    // Its red ring reaches past the left edge of the frame: the first column shows it.
    CHECK(count_near(r.image, {255, 70, 70}, 40, 0, 0, 1, r.image.height) > 10);
    CHECK(count_near(r.image, green, 40) > 100);
}

TEST_CASE("in a periodic box a disc straddling an edge shows on both sides") {
    Snapshot s = empty_snapshot({10.0, 10.0, Boundary::periodic});
    s.discs = {disc_at({9.8, 5.0}, 1.0, red)};
    const OnePanel r = render_one(s);
    test::dump_if_requested(r.image, "pixel_periodic_image");
    const PointF left_edge = r.layout.to_pixels({0.3, 5.0}, s.box);  // inside the wrapped image
    CHECK(rgb_at(r.image, static_cast<int>(left_edge.x), static_cast<int>(left_edge.y)) == red);
    // Nothing is drawn outside the box on either side (the images are clipped to it).
    const int outside_left =
        count_near(r.image, red, 60, 0, 0, static_cast<int>(r.layout.box.x0) - 1, r.image.height);
    const int outside_right = count_near(r.image, red, 60, static_cast<int>(r.layout.box.x1) + 2, 0,
                                         r.image.width, r.image.height);
    CHECK(outside_left == 0);
    CHECK(outside_right == 0);
}

TEST_CASE("an escaped disc is drawn outside the box, ringed in red") {
    Snapshot s = empty_snapshot({10.0, 10.0, Boundary::walls});
    DiscState gone = disc_at({-40.0, 5.0}, 0.5, green);  // far outside, left
    gone.escaped = true;
    s.discs = {gone};
    const OnePanel r = render_one(s);
    test::dump_if_requested(r.image, "pixel_escaped_disc");
    const int box_left = static_cast<int>(r.layout.box.x0);
    const int greens = count_near(r.image, green, 40, 0, 0, box_left - 1, r.image.height);
    CHECK(greens > 10);
    CHECK(count_near(r.image, {255, 70, 70}, 40, 0, 0, box_left - 1, r.image.height) > 5);
    // Nothing of it inside the box.
    CHECK(count_near(r.image, green, 40, box_left + 1, 0, r.image.width, r.image.height) == 0);
}

TEST_CASE("failure markers: red halo on an overlapping pair, flash where a collision was missed") {
    Snapshot s = empty_snapshot({16.0, 9.0, Boundary::walls});
    s.discs = {disc_at({4.0, 4.5}, 0.6, {200, 200, 200}), disc_at({4.8, 4.5}, 0.6, {200, 200, 200}),
               disc_at({12.0, 4.5}, 0.4, {200, 200, 200})};
    Snapshot clean = s;
    s.overlapping_pairs = {{0, 1}};
    s.missed_collisions = {{12.0, 7.0}};
    const OnePanel marked = render_one(s);
    const OnePanel plain = render_one(clean);
    test::dump_if_requested(marked.image, "pixel_failure_markers");
    CHECK(count_near(marked.image, {240, 45, 45}, 30) > 20);
    CHECK(count_near(plain.image, {240, 45, 45}, 30) == 0);
    const PointF flash = marked.layout.to_pixels({12.0, 7.0}, s.box);
    const Rgb8 at_flash =
        rgb_at(marked.image, static_cast<int>(flash.x), static_cast<int>(flash.y));
    const Rgb8 before = rgb_at(plain.image, static_cast<int>(flash.x), static_cast<int>(flash.y));
    CHECK(at_flash.r > before.r + 100);  // bright yellow over the dark box
    CHECK(at_flash.g > before.g + 100);
}

TEST_CASE("speed mode colours a disc by |v| through the colormap over the fixed range") {
    Snapshot s = empty_snapshot({16.0, 9.0, Boundary::walls});
    DiscState fast = disc_at({4.0, 4.5}, 1.0, red);
    fast.velocity = {3.0, 4.0};  // |v| = 5 = speed_max
    DiscState slow = disc_at({12.0, 4.5}, 1.0, red);
    s.discs = {fast, slow};
    RenderConfig config = test::small_config(false);
    config.color_mode = ColorMode::speed;
    config.speed_max = 5.0;
    const OnePanel r = render_one(s, config);
    const PointF a = r.layout.to_pixels(fast.position, s.box);
    const PointF b = r.layout.to_pixels(slow.position, s.box);
    CHECK(rgb_at(r.image, static_cast<int>(a.x), static_cast<int>(a.y)) == colormap(1.0));
    CHECK(rgb_at(r.image, static_cast<int>(b.x), static_cast<int>(b.y)) == colormap(0.0));
    CHECK(!(colormap(0.0) == colormap(1.0)));
}

TEST_CASE("rendering is deterministic and render(frame, out) matches render(frame)") {
    const Snapshot s = test::gas_snapshot(200, 0.02, {1.0, 1.0, Boundary::walls}, 7);
    Renderer renderer(test::small_config(true), test::test_backend());
    FrameContent frame;
    frame.panels = {{&s, "Event-driven", {"events 12"}}, {&s, "Time-driven", {"steps 3"}}};
    const Image first = renderer.render(frame);
    Renderer fresh(test::small_config(true), test::test_backend());  // no trails drawn yet
    Image second;
    fresh.render(frame, second);
    CHECK(first.rgba == second.rgba);
}

TEST_CASE("bad frames are failed assertions (programmer errors), not crashes") {
    if (!asserts_enabled) COLLIDE_SKIP_TEST("assertions are off in this build type");
    using collide::test::assertion_failure;
    using collide::test::contains;
    Renderer renderer(test::small_config(false), test::test_backend());
    const auto failure = [&](const FrameContent& frame) {
        return assertion_failure([&] { renderer.draw(frame); });
    };
    CHECK(contains(failure(FrameContent{}), "a frame has 1 to max_frame_panels panels"));
    const Snapshot s = test::gas_snapshot(20, 0.02, {1.0, 1.0, Boundary::walls}, 7);
    FrameContent three;
    // Five panels (a --dt list of four steps and the event-driven one) at most.
    three.panels = {{&s, "a", {}}, {&s, "b", {}}, {&s, "c", {}},
                    {&s, "d", {}}, {&s, "e", {}}, {&s, "f", {}}};
    CHECK(contains(failure(three), "a frame has 1 to max_frame_panels panels"));
    FrameContent null_panel;
    null_panel.panels = {{nullptr, "", {}}};
    CHECK(contains(failure(null_panel), "every panel has a snapshot"));
}

TEST_CASE("bad configs are input errors, not crashes") {
    RenderConfig bad = test::small_config(false);
    bad.width = 10;
    CHECK_THROWS_AS(Renderer(bad, test::test_backend()), Error);
    bad = test::small_config(false);
    bad.speed_max = bad.speed_min;
    CHECK_THROWS_WITH_AS(bad.validate(), doctest::Contains("speed_max"), Error);
    CHECK_THROWS_AS((void)parse_color_mode("rainbow"), Error);
    CHECK(parse_color_mode("mass") == ColorMode::mass);
}

}  // namespace
}  // namespace collide::render

namespace collide::render {
namespace {

/// Renders one lesson-level frame at 854x480 (the layout it used comes back too).
struct LessonFrame {
    Image image;
    FrameLayout layout;
};

LessonFrame render_lesson(const Snapshot& snapshot, Theme theme = Theme::dark) {
    RenderConfig config = test::lesson_config(854, 480);
    config.theme = theme;
    Renderer renderer(config, test::test_backend());
    FrameContent frame;
    frame.panels = {{&snapshot, "Event-driven", {}}};
    frame.panels[0].figures = {{"0", "missed", true}};
    show::FailureMarks marks;  // as the app chooses them
    marks.update(snapshot, 0.0);
    frame.panels[0].marks = marks.marks();
    LessonFrame out;
    out.image = renderer.render(frame);
    LayoutInput in;
    in.width = 854;
    in.height = 480;
    in.boxes = {snapshot.box};
    out.layout = lesson_layout(in);
    return out;
}

TEST_CASE("lesson: a disc without 3:1 contrast against the box gets an outline") {
    if (!std::filesystem::exists(RenderConfig{}.font_path)) {
        COLLIDE_SKIP_TEST("no DejaVu Sans at " << RenderConfig{}.font_path);
    }
    for (const Theme theme : {Theme::dark, Theme::light}) {
        const Rgb8 faint = theme == Theme::dark ? Rgb8{32, 32, 32} : Rgb8{245, 245, 245};
        const Rgb8 clear = theme == Theme::dark ? Rgb8{240, 240, 240} : Rgb8{20, 20, 20};
        REQUIRE(contrast_ratio(faint, box_fill_color(theme)) < min_disc_contrast);
        Snapshot s = empty_snapshot({10.0, 10.0, Boundary::walls});
        s.discs = {disc_at({5.0, 5.0}, 1.0, faint)};
        const LessonFrame r = render_lesson(s, theme);
        const RectF box = r.layout.panels[0].box;
        // The outline: pixels of high contrast with the box inside the box.
        int outlined = 0;
        for (int y = static_cast<int>(box.y0) + 2; y < static_cast<int>(box.y1) - 2; ++y) {
            for (int x = static_cast<int>(box.x0) + 2; x < static_cast<int>(box.x1) - 2; ++x) {
                if (contrast_ratio(rgb_at(r.image, x, y), box_fill_color(theme)) >= 3.0) {
                    ++outlined;
                }
            }
        }
        CHECK_MESSAGE(outlined > 20, theme_name(theme));
        // A clear colour needs none: only its own pixels stand out.
        s.discs = {disc_at({5.0, 5.0}, 1.0, clear)};
        const LessonFrame plain = render_lesson(s, theme);
        CHECK(count_near(plain.image, clear, 8) > 100);
    }
}

TEST_CASE(
    "lesson: escaped discs stay out of the picture, with a marker in the failure colour at the "
    "edge") {
    if (!std::filesystem::exists(RenderConfig{}.font_path)) {
        COLLIDE_SKIP_TEST("no DejaVu Sans at " << RenderConfig{}.font_path);
    }
    Snapshot s = empty_snapshot({10.0, 10.0, Boundary::walls});
    DiscState gone = disc_at({-40.0, 5.0}, 0.5, green);  // far outside, left
    gone.escaped = true;
    s.discs = {gone};
    const LessonFrame r = render_lesson(s);
    CHECK(count_near(r.image, green, 40) == 0);  // nowhere: not over the text, not in the box
    const RectF box = r.layout.panels[0].box;
    CHECK(count_near(r.image, failure_color(Theme::dark), 40, static_cast<int>(box.x0),
                     static_cast<int>(box.y0), static_cast<int>(box.x0) + 30,
                     static_cast<int>(box.y1)) > 10);
}

}  // namespace
}  // namespace collide::render

namespace collide::render {
namespace {

// `--mode event --overlays full` drew the event-driven engine's plots in the time-driven orange:
// the strip chose a series' colour by its panel's index, not by the panel's engine.
TEST_CASE(
    "full level: each plot series is drawn in its panel's engine accent, whatever its index") {
    RenderConfig config = test::small_config(true);
    config.width = 640;
    config.height = 360;
    const Snapshot s = test::gas_snapshot(40, 0.03, {1.6, 0.9, Boundary::walls}, 5, 1.0);
    const auto frame_with = [&](bool time_driven) {
        FrameContent frame;
        frame.panels = {{&s, "Event-driven (priority queue)", {"events 42"}}};
        frame.panels[0].time_driven = time_driven;
        frame.time_text = "t = 1.000";
        frame.energy_drift = {{{0.0, 0.0}, {0.5, 2e-3}, {1.0, -1e-3}}};
        test::add_show_words(frame, config.speed_max);
        return frame;
    };
    const Rgb8 orange = panel_accent(true);
    const Rgb8 blue = panel_accent(false);
    Renderer event_only(config, test::test_backend());
    const Image event = event_only.render(frame_with(false));
    test::dump_if_requested(event, "full_event_only_accent");
    CHECK(count_near(event, orange, 12) == 0);
    CHECK(count_near(event, blue, 12) > 20);
    // The same panel as the time-driven engine: its series are orange (the test can fail).
    Renderer time_only(config, test::test_backend());
    CHECK(count_near(time_only.render(frame_with(true)), orange, 12) > 20);
}

}  // namespace
}  // namespace collide::render
