// Text through HarfBuzz and FreeType: titles, counters and the time produce glyph pixels where the
// layout puts the header and the strip; no text, no glyph pixels.
#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "../support/skip.hpp"
#include "../support/temp_dir.hpp"
#include "collide/error.hpp"
#include "collide/show/collision_summary.hpp"
#include "font.hpp"
#include "layout.hpp"
#include "render_fixtures.hpp"

namespace collide::render {
namespace {

/// Pixels in `r` that are bright (text is near-white on the dark background).
int bright_pixels(const Image& image, RectF r) {
    int count = 0;
    for (int y = static_cast<int>(r.y0); y < static_cast<int>(r.y1); ++y) {
        for (int x = static_cast<int>(r.x0); x < static_cast<int>(r.x1); ++x) {
            if (test::rgb_at(image, x, y).g > 120) ++count;
        }
    }
    return count;
}

TEST_CASE("titles, counters and time text put glyphs in the header and the strip") {
    const RenderConfig config = test::small_config(true);
    if (!std::filesystem::exists(config.font_path)) {
        COLLIDE_SKIP_TEST("no DejaVu Sans at " << config.font_path);
    }
    Renderer renderer(config, test::test_backend());
    const Snapshot s = test::gas_snapshot(0, 0.05, {1.0, 1.0, Boundary::walls}, 1);
    FrameContent blank;  // same layout as `titled` (one counter row), but no text in it
    blank.panels = {{&s, "", {""}}};
    FrameContent titled;
    titled.panels = {{&s, "Event-driven", {"events 1234"}}};
    titled.time_text = "t = 3.25";
    const Image without = renderer.render(blank);
    const Image with = renderer.render(titled);
    test::dump_if_requested(with, "text_header");

    const FontAtlas font(config.font_path, font_pixel_height(config.height));
    const FrameLayout layout = compute_layout(config, {s.box}, font.line_height());
    const RectF header = layout.panels[0].header;
    CHECK(bright_pixels(without, header) == 0);
    const int glyphs = bright_pixels(with, header);
    CHECK(glyphs > 40);  // two short lines of ~11 px text
    CHECK(glyphs < static_cast<int>(0.5F * header.width() * header.height()));  // not a filled box
    CHECK(bright_pixels(with, layout.strip) > bright_pixels(without, layout.strip) + 10);
}

/// Every string the renderer drew in `frame`, the last frame it drew (--layout-json's lines and
/// the text drawn outside them).
std::vector<std::string> drawn_strings(const Renderer& renderer, const FrameContent& frame) {
    const nlohmann::json json = nlohmann::json::parse(renderer.layout_json(frame));
    std::vector<std::string> out;
    for (const nlohmann::json& line : json.at("text")) {
        if (!line.contains("text")) continue;
        for (const nlohmann::json& text : line.at("text")) out.push_back(text.get<std::string>());
    }
    if (json.contains("other_text")) {
        for (const nlohmann::json& text : json.at("other_text"))
            out.push_back(text.at("text").get<std::string>());
    }
    return out;
}

TEST_CASE("the end card's labels are drawn whole at -q l and -q m: discs or spheres, 2-5 columns") {
    // Issue 44: the card says "... that ever overlapped" beside the live "0 overlapping"; the
    // longer words must still fit the labels' column, which was narrower beside a --dt list.
    if (!std::filesystem::exists(RenderConfig{}.font_path))
        COLLIDE_SKIP_TEST("no DejaVu Sans at " << RenderConfig{}.font_path);
    Measurements time;  // gas-3d's counts with --dt 0.002 (the widest values)
    time.missed_collisions = 4;
    time.discs_overlapped = 62;
    time.escaped = 1;
    time.collisions_pair = 2136;
    time.overlap_checks = 94810000;
    Measurements event;
    event.collisions_pair = 2085;
    event.queue.pushes = 100000;
    event.queue.pops = 25000;
    const Snapshot s = test::gas_snapshot(4, 0.05, {1.0, 1.0, Boundary::walls}, 1);
    for (const bool spheres : {false, true}) {
        for (const std::size_t steps : {std::size_t{1}, std::size_t{2}, std::size_t{4}}) {
            std::vector<show::SummaryPanel> panels;
            for (std::size_t k = 0; k < steps; ++k)
                panels.push_back(
                    {time, true, steps > 1 ? 0.0125 * static_cast<double>(k + 1) : 0.0});
            panels.push_back({event, false});
            FrameContent frame;
            for (std::size_t k = 0; k < panels.size(); ++k) frame.panels.push_back({&s, "", {}});
            frame.summary = show::summary_card(panels, true, "t = 30.000", spheres);
            REQUIRE(frame.summary.rows.size() == 5);
            CHECK(frame.summary.rows[1].label.find("ever overlapped") != std::string::npos);
            for (const auto& [width, height] : {std::pair{854, 480}, std::pair{1280, 720}}) {
                CAPTURE(spheres);
                CAPTURE(steps);
                CAPTURE(width);
                Renderer renderer(test::lesson_config(width, height), test::test_backend());
                const Image image = renderer.render(frame);
                test::dump_if_requested(image, "summary_card_" + std::to_string(spheres) + "_" +
                                                   std::to_string(steps) + "_" +
                                                   std::to_string(height));
                const std::vector<std::string> drawn = drawn_strings(renderer, frame);
                const auto whole = [&](const std::string& text) {
                    return std::find(drawn.begin(), drawn.end(), text) != drawn.end();
                };
                // A label on one line, or on two beside five columns (four dt): "spheres that
                // ever" over "overlapped", drawn one after the other.
                const auto whole_in_lines = [&](const std::string& text) {
                    if (whole(text)) return true;
                    for (std::size_t k = 0; k + 1 < drawn.size(); ++k)
                        if (drawn[k] + " " + drawn[k + 1] == text) return true;
                    return false;
                };
                for (const SummaryRow& row : frame.summary.rows) {
                    CAPTURE(row.label);
                    CHECK(whole_in_lines(row.label));
                }
                for (const std::string& heading : frame.summary.columns) CHECK(whole(heading));
                for (const SummaryRow& row : frame.summary.rows) {
                    CAPTURE(row.label);
                    for (const std::string& value : row.values) CHECK(whole(value));
                }
                for (const std::string& text : drawn) {
                    CAPTURE(text);
                    CHECK(text.find("...") == std::string::npos);
                }
            }
        }
    }
}

TEST_CASE("a 480p two-panel frame shows the speed legend's colour bar in the strip") {
    RenderConfig config;
    config.width = 854;
    config.height = 480;
    config.color_mode = ColorMode::speed;
    config.speed_max = 1.5;
    config.overlays = OverlayLevel::full;  // the expert level's strip
    if (!std::filesystem::exists(config.font_path)) {
        COLLIDE_SKIP_TEST("no DejaVu Sans at " << config.font_path);
    }
    Renderer renderer(config, test::test_backend());
    Snapshot left = test::gas_snapshot(200, 0.015, {1.0, 1.0, Boundary::walls}, 8, 4.0);
    const Snapshot right = test::gas_snapshot(200, 0.015, {1.0, 1.0, Boundary::periodic}, 8, 4.0);
    left.overlapping_pairs = {{10, 11}};
    left.missed_collisions = {{0.3, 0.6}};
    FrameContent frame;
    frame.panels = {{&left, "Time-driven, dt = 0.02", {"steps 200", "checks 3.9M", "missed 17"}},
                    {&right, "Event-driven (priority queue)", {"events 1840", "queue 412"}}};
    frame.time_text = "t = 4.00   (x0.5 speed)";
    frame.energy_drift = {{{0.0, 0.0}, {2.0, 0.004}, {4.0, 0.011}}, {{0.0, 0.0}, {4.0, 0.0}}};
    frame.notes = {"red halo: overlapping discs", "yellow flash: missed collision"};
    const Image image = renderer.render(frame);
    test::dump_if_requested(image, "frame_480p");

    const FontAtlas font(config.font_path, font_pixel_height(config.height));
    const RectF strip = compute_layout(config, {left.box, right.box}, font.line_height()).strip;
    const auto in_strip = [&](Rgb8 c) {
        return test::count_near(image, c, 0, static_cast<int>(strip.x0), static_cast<int>(strip.y0),
                                static_cast<int>(strip.x1), static_cast<int>(strip.y1));
    };
    constexpr int segments = 32;  // renderer.cpp's legend
    CHECK(in_strip(colormap(0.5 / segments)) > 10);
    CHECK(in_strip(colormap((segments - 0.5) / segments)) > 10);
}

TEST_CASE("a missing font file is a runtime error naming it") {
    RenderConfig config = test::small_config(true);
    config.font_path = "/nonexistent/font.ttf";
    CHECK_THROWS_WITH_AS(Renderer(config, test::test_backend()),
                         doctest::Contains("/nonexistent/font.ttf"), Error);
}

TEST_CASE("a truncated or damaged font is a runtime error naming it, not a crash") {
    // Under stb_truetype both of these ended in SIGSEGV; FreeType survives them but would draw
    // what the damage says (wrong or missing glyphs), so the font is checked before use.
    const std::string font = RenderConfig{}.font_path;
    if (!std::filesystem::exists(font)) COLLIDE_SKIP_TEST("no DejaVu Sans at " << font);
    std::ifstream in(font, std::ios::binary);
    const std::string data{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    REQUIRE(data.size() > 100000);
    const collide::test::TempDir dir("font_damage");
    const auto write = [&](const std::string& name, const std::string& bytes) {
        const std::filesystem::path path = dir.path / name;
        std::ofstream(path, std::ios::binary) << bytes;
        return path.string();
    };
    std::string damaged = data;
    for (std::size_t i = data.size() / 2; i < data.size() / 2 + 4096; ++i) damaged[i] = '\xff';
    for (const std::string& path :
         {write("truncated.ttf", data.substr(0, data.size() / 2)),
          write("short.ttf", data.substr(0, 10)), write("damaged.ttf", damaged)}) {
        CAPTURE(path);
        CHECK_THROWS_WITH_AS(FontAtlas(path, 20.0F), doctest::Contains(path.c_str()), Error);
    }
    CHECK(FontAtlas(write("whole.ttf", data), 20.0F).line_height() > 0.0F);
}

TEST_CASE("text larger than 4K lesson text still fits the font atlas") {
    // `thumbnail --size 8192x4608` asked for glyphs larger than the largest atlas (exit 1).
    const std::string font = RenderConfig{}.font_path;
    if (!std::filesystem::exists(font)) COLLIDE_SKIP_TEST("no DejaVu Sans at " << font);
    for (const float pixels : {90.0F, 200.0F, 400.0F}) {
        CAPTURE(pixels);
        const FontAtlas atlas(font, pixels);
        CHECK(atlas.text_width("W") > 0.5F * pixels);
    }
}

TEST_CASE("word wrap is linear in the text, however long its lines") {
    // Before, each word re-measured the whole line: a word and 300,000 spaces (one endless line
    // of empty words) took minutes; a description of a megabyte hung the first frame.
    const std::string font = RenderConfig{}.font_path;
    if (!std::filesystem::exists(font)) COLLIDE_SKIP_TEST("no DejaVu Sans at " << font);
    const FontAtlas atlas(font, 16.0F);
    const auto start = std::chrono::steady_clock::now();
    const std::vector<std::string> spaces =
        wrap_words(atlas, "a" + std::string(300'000, ' '), 1e9F);
    const std::vector<std::string> words = wrap_words(atlas, std::string(300'000, 'a'), 100.0F);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(seconds < 5.0);
    CHECK(spaces.size() == 1);
    CHECK(words.size() == 1);  // one word wider than the line gets a line of its own
    // The same lines as measuring each candidate line whole.
    const std::string text = "the quick brown fox jumps over the lazy dog  twice, and again";
    for (const float width : {40.0F, 90.0F, 150.0F, 400.0F}) {
        CAPTURE(width);
        for (const std::string& line : wrap_words(atlas, text, width)) {
            CHECK((atlas.text_width(line) <= width + 0.01F || line.find(' ') == std::string::npos));
        }
    }
}

TEST_CASE("UTF-8 decoding: multi-byte characters become one code point each") {
    const std::vector<std::uint32_t> points = decode_utf8("t \xC2\xB7 \xC3\xA9");
    REQUIRE(points.size() == 5);
    CHECK(points[2] == 0xB7);
    CHECK(points[4] == 0xE9);
}

}  // namespace
}  // namespace collide::render
