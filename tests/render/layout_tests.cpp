// The layout module (layout.hpp): pure rectangles, checked for every frame size the CLI offers.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <string>

#include "../support/skip.hpp"
#include "collide/show/failure_marks.hpp"
#include "frame_builder.hpp"
#include "layout.hpp"
#include "render_fixtures.hpp"

namespace collide::render {
namespace {

struct Size {
    int width;
    int height;
};

LayoutInput lesson_input(Size size, int panels = 2) {
    LayoutInput in;
    in.width = size.width;
    in.height = size.height;
    for (int i = 0; i < panels; ++i) in.boxes.push_back({1.0, 1.0, Boundary::walls});
    return in;
}

float area(RectF r) {
    return r.width() * r.height();
}

RectF grown(RectF r, float by) {
    return {r.x0 - by, r.y0 - by, r.x1 + by, r.y1 + by};
}

/// Text slots inside the frame, not overlapping each other, the boxes (with their walls) or the
/// column's graphics.
void check_nothing_overlaps_text(const FrameLayout& layout, Size size) {
    for (std::size_t i = 0; i < layout.text.size(); ++i) {
        const TextSlot& a = layout.text[i];
        INFO("slot " << text_role_name(a.role) << " of panel " << a.panel);
        CHECK(a.rect.x0 >= 0.0F);
        CHECK(a.rect.y0 >= 0.0F);
        CHECK(a.rect.x1 <= static_cast<float>(size.width));
        CHECK(a.rect.y1 <= static_cast<float>(size.height));
        for (std::size_t j = i + 1; j < layout.text.size(); ++j) {
            INFO("and slot " << text_role_name(layout.text[j].role) << " of panel "
                             << layout.text[j].panel);
            CHECK_FALSE(overlaps(a.rect, layout.text[j].rect));
        }
        for (const PanelLayout& panel : layout.panels) {
            CHECK_FALSE(overlaps(a.rect, grown(panel.box, 2.0F)));
        }
        CHECK_FALSE(overlaps(a.rect, layout.column.legend_bar));
        CHECK_FALSE(overlaps(a.rect, layout.column.plot));
    }
    for (const PanelLayout& panel : layout.panels) {
        CHECK_FALSE(overlaps(grown(panel.box, 2.0F), layout.column.area));
    }
}

TEST_CASE("lesson layout: two square boxes cover >= 55 % of a 16:9 frame, capitals >= 2.8 %") {
    for (const Size size : {Size{854, 480}, Size{1280, 720}, Size{1920, 1080}, Size{3840, 2160}}) {
        INFO(size.width << "x" << size.height);
        const FrameLayout layout = lesson_layout(lesson_input(size));
        REQUIRE(layout.panels.size() == 2);
        CHECK_FALSE(layout.compact);
        const float frame = static_cast<float>(size.width) * static_cast<float>(size.height);
        CHECK((area(layout.panels[0].box) + area(layout.panels[1].box)) / frame >= 0.55F);
        const float min_cap = 0.028F * static_cast<float>(size.height);
        REQUIRE_FALSE(layout.text.empty());
        for (const TextSlot& slot : layout.text) {
            INFO(text_role_name(slot.role));
            CHECK(slot.cap_height() >= min_cap);
            CHECK(slot.rect.height() >= slot.pixel_height);  // the line fits its slot
        }
        // Headline figures are bigger than the body text.
        const TextSlot* figures = layout.slot(TextRole::figures, 0);
        const TextSlot* title = layout.slot(TextRole::title, 0);
        REQUIRE(figures != nullptr);
        REQUIRE(title != nullptr);
        CHECK(figures->pixel_height > title->pixel_height);
        CHECK(layout.slot(TextRole::caption) != nullptr);
        CHECK(layout.slots(TextRole::cost_value).size() == 2);
        check_nothing_overlaps_text(layout, size);
    }
}

// Issue #29 item 7: a --dt list's 3-5 panels (up to four steps and the event-driven one).
TEST_CASE(
    "lesson layout: three to five boxes keep their shape, capitals >= 2.8 %, nothing overlaps") {
    for (const Size size : {Size{854, 480}, Size{1280, 720}}) {
        for (int panels = 3; panels <= 5; ++panels) {
            for (const Box box : {Box{1.0, 1.0, Boundary::walls}, Box{2.0, 1.0, Boundary::walls}}) {
                INFO(size.width << "x" << size.height << ", " << panels << " panels of "
                                << box.width << "x" << box.height);
                LayoutInput in = lesson_input(size, panels);
                std::fill(in.boxes.begin(), in.boxes.end(), box);
                in.mark_lines.assign(static_cast<std::size_t>(panels), true);
                in.clock_unit = true;
                in.small_plot = true;
                const FrameLayout layout = lesson_layout(in);
                REQUIRE(layout.panels.size() == static_cast<std::size_t>(panels));
                CHECK_FALSE(layout.compact);
                for (std::size_t i = 0; i < layout.panels.size(); ++i) {
                    const RectF b = layout.panels[i].box;
                    // The scene's shape, to the pixel the box is rounded to.
                    CHECK(std::abs(b.width() / b.height() -
                                   static_cast<float>(box.width / box.height)) < 2.0F / b.height());
                    CHECK(b.height() >= 0.2F * static_cast<float>(size.height));
                    for (std::size_t j = i + 1; j < layout.panels.size(); ++j)
                        CHECK_FALSE(overlaps(grown(b, 2.0F), layout.panels[j].box));
                    CHECK_FALSE(overlaps(grown(b, 2.0F), layout.column.area));
                    CHECK(layout.slot(TextRole::title, static_cast<int>(i)) != nullptr);
                    CHECK(layout.slot(TextRole::figures, static_cast<int>(i)) != nullptr);
                }
                const float min_cap = 0.028F * static_cast<float>(size.height);
                for (const TextSlot& slot : layout.text) {
                    INFO(text_role_name(slot.role));
                    CHECK(slot.cap_height() >= min_cap);
                    CHECK(slot.rect.height() >= slot.pixel_height);
                }
                // Every panel's work in the column: the trade-off is read off the bars.
                CHECK(layout.slots(TextRole::cost_value).size() ==
                      static_cast<std::size_t>(panels));
                check_nothing_overlaps_text(layout, size);
            }
        }
    }
}

TEST_CASE("lesson layout: 20 px capitals at 720p") {
    const FrameLayout layout = lesson_layout(lesson_input({1280, 720}));
    CHECK(layout.slot(TextRole::title, 0)->cap_height() >= 20.0F);
    CHECK(layout.slot(TextRole::title, 0)->cap_height() < 22.0F);  // not needlessly bigger
}

TEST_CASE("lesson layout: notes, colour legend, a large plot and one panel never overlap text") {
    for (const Size size :
         {Size{854, 480}, Size{1280, 720}, Size{3840, 2160}, Size{640, 480}, Size{1080, 1080}}) {
        for (const int panels : {1, 2}) {
            LayoutInput in = lesson_input(size, panels);
            in.note_line = true;
            in.color_legend = true;
            in.large_plot = panels == 2;
            INFO(size.width << "x" << size.height << ", " << panels << " panels");
            const FrameLayout layout = lesson_layout(in);
            CHECK(layout.slots(TextRole::note).size() == static_cast<std::size_t>(panels));
            check_nothing_overlaps_text(layout, size);
        }
    }
    // Boxes of other shapes keep their aspect ratio.
    LayoutInput wide = lesson_input({1280, 720});
    wide.boxes = {{2.0, 1.0, Boundary::walls}, {2.0, 1.0, Boundary::walls}};
    const FrameLayout layout = lesson_layout(wide);
    CHECK(layout.panels[0].box.width() == doctest::Approx(2.0 * layout.panels[0].box.height()));
    check_nothing_overlaps_text(layout, {1280, 720});
}

TEST_CASE("lesson layout: a small speed plot fits beside two boxes that keep >= 55 % of 16:9") {
    for (const Size size : {Size{854, 480}, Size{1280, 720}, Size{1920, 1080}, Size{3840, 2160}}) {
        {
            INFO(size.width << "x" << size.height);
            LayoutInput in = lesson_input(size);
            in.small_plot = true;
            const FrameLayout layout = lesson_layout(in);
            const float frame = static_cast<float>(size.width) * static_cast<float>(size.height);
            CHECK((area(layout.panels[0].box) + area(layout.panels[1].box)) / frame >= 0.55F);
            // Readable: at least the axis labels' line and three more lines of data, and the
            // cost graphic and the energy line are still there.
            const float line = layout.body_pixel_height * 1.2F;
            CHECK(layout.column.plot.height() >= 4.0F * line);
            CHECK(layout.column.plot.width() >= 6.0F * layout.body_pixel_height);
            CHECK(layout.slots(TextRole::cost_value).size() == 2);
            CHECK(layout.slots(TextRole::energy).size() == 2);
            // It reaches below the boxes, between the two panels' figures, never onto them.
            CHECK(layout.column.plot.y1 > layout.panels[0].box.y1);
            check_nothing_overlaps_text(layout, size);
            for (const TextSlot* figures : layout.slots(TextRole::figures)) {
                CHECK_FALSE(overlaps(figures->rect, layout.column.plot));
            }
        }
        // A colour legend too (mass colours; speed colours use the plot's axis instead): the
        // legend is kept, the plot only where it still fits, nothing overlaps.
        LayoutInput in = lesson_input(size);
        in.small_plot = true;
        in.color_legend = true;
        const FrameLayout layout = lesson_layout(in);
        CHECK(layout.column.legend_bar.height() > 0.0F);
        check_nothing_overlaps_text(layout, size);
    }
    // One panel: the plot sits right of the box, clear of its figures.
    LayoutInput one = lesson_input({1280, 720}, 1);
    one.small_plot = true;
    one.note_line = true;
    const FrameLayout layout = lesson_layout(one);
    CHECK(layout.column.plot.height() > 0.0F);
    check_nothing_overlaps_text(layout, {1280, 720});
}

TEST_CASE("lesson layout: the queue strip fits under the panels, clear of every other text") {
    for (const Size size :
         {Size{854, 480}, Size{1280, 720}, Size{1920, 1080}, Size{640, 360}, Size{1080, 1080}}) {
        for (const int panels : {1, 2}) {
            LayoutInput in = lesson_input(size, panels);
            in.note_line = panels == 2;
            in.color_legend = true;
            in.queue_panel = panels - 1;  // the event-driven panel is the last
            INFO(size.width << "x" << size.height << ", " << panels << " panels");
            const FrameLayout layout = lesson_layout(in);
            REQUIRE(layout.queue_panel == panels - 1);
            const RectF strip = layout.queue_strip;
            CHECK(strip.height() >= std::round(queue_strip_min_share * size.height) - 0.5F);
            CHECK(strip.height() <= std::round(queue_strip_share * size.height) + 0.5F);
            CHECK(layout.slots(TextRole::queue).size() == 1);
            // Under two panels; beside one (the box takes the frame's height).
            for (const PanelLayout& panel : layout.panels)
                CHECK((panels == 1 ? strip.x0 > panel.box.x1 : strip.y0 > panel.box.y1));
            check_nothing_overlaps_text(layout, size);
        }
    }
    // Without a queue panel there is no strip, and the boxes are as before.
    const FrameLayout plain = lesson_layout(lesson_input({1280, 720}));
    CHECK(plain.queue_panel == -1);
    CHECK(plain.slots(TextRole::queue).empty());
}

TEST_CASE("lesson layout: --code's column sits on the right edge, over the queue strip") {
    for (const Size size : {Size{854, 480}, Size{1280, 720}, Size{1920, 1080}}) {
        for (const int panels : {1, 2}) {
            LayoutInput in = lesson_input(size, panels);
            in.color_legend = true;
            in.queue_panel = panels - 1;
            in.code_rows = 7;
            in.code_width = 0.38F * static_cast<float>(size.width);
            INFO(size.width << "x" << size.height << ", " << panels << " panels");
            const FrameLayout layout = lesson_layout(in);
            check_nothing_overlaps_text(layout, size);
            const RectF code = layout.code;
            REQUIRE(code.width() >= in.code_width - 0.5F);
            CHECK(code.x1 <= static_cast<float>(size.width));
            CHECK(layout.slots(TextRole::code).size() == 7);
            for (const TextSlot* row : layout.slots(TextRole::code)) {
                CHECK(row->rect.y1 <= code.y1 + 0.5F);
                CHECK(row->cap_height() >= 0.028F * static_cast<float>(size.height) - 0.01F);
            }
            for (const PanelLayout& panel : layout.panels) CHECK_FALSE(overlaps(code, panel.box));
            CHECK_FALSE(overlaps(code, layout.column.area));
            CHECK_FALSE(overlaps(code, layout.queue_strip));
            // The strip under it keeps the frame's width.
            CHECK(layout.queue_strip.x1 > code.x0);
            if (panels == 2) {
                // The column goes under the listing: the two boxes stand side by side.
                CHECK(layout.column.area.y0 >= code.y1);
                CHECK(layout.column.area.x0 >= layout.panels[1].box.x1);
                CHECK(layout.panels[1].box.x0 - layout.panels[0].box.x1 <= layout.margin + 0.5F);
            }
        }
    }
    CHECK(lesson_layout(lesson_input({1280, 720})).slots(TextRole::code).empty());
}

TEST_CASE(
    "compact layout below 480 px: boxes fill the frame under the title and one line per "
    "panel, 9 px capitals") {
    for (const Size size : {Size{320, 180}, Size{426, 240}, Size{160, 90}}) {
        INFO(size.width << "x" << size.height);
        const FrameLayout layout = lesson_layout(lesson_input(size));
        CHECK(layout.compact);
        REQUIRE(layout.text.size() == 3);  // the scene's title, then one line per panel
        CHECK(layout.text[0].role == TextRole::title);
        CHECK(layout.text[0].panel == -1);
        CHECK(layout.text[0].rect.y1 <= layout.text[1].rect.y0);
        for (const TextSlot& slot : layout.text) CHECK(slot.cap_height() >= 9.0F);
        const float frame = static_cast<float>(size.width) * static_cast<float>(size.height);
        if (size.width >= 320) {
            CHECK((area(layout.panels[0].box) + area(layout.panels[1].box)) / frame >= 0.70F);
        }
        check_nothing_overlaps_text(layout, size);
    }
}

TEST_CASE("level none: the boxes fill the frame and there is no text") {
    const LayoutInput in = lesson_input({1280, 720});
    const FrameLayout layout = classic_layout(in.width, in.height, false, in.boxes, 0.0F, 0);
    CHECK(layout.text.empty());
    const PanelLayout& panel = layout.panels[0];
    CHECK(std::max(panel.box.width() / panel.area.width(),
                   panel.box.height() / panel.area.height()) >= 0.95F);
}

TEST_CASE("layout JSON names every text line with its pixel height") {
    const FrameLayout layout = lesson_layout(lesson_input({1280, 720}));
    const std::string json = layout_json(layout, OverlayLevel::lesson, 1280, 720);
    CHECK(json.find("\"level\": \"lesson\"") != std::string::npos);
    CHECK(json.find("\"role\": \"caption\"") != std::string::npos);
    CHECK(json.find("\"pixel_height\": 33") != std::string::npos);
    CHECK(json.find("\"box\": [") != std::string::npos);
}

// Issue 44 item 4: note, marks legend and how lines take at most two lines under the figures,
// so that the boxes keep 55 %; one box takes the frame's height beside its text.
TEST_CASE("lesson layout: note, marks and how in two lines: the boxes keep 55 % of 16:9") {
    for (const Size size : {Size{854, 480}, Size{1280, 720}, Size{1920, 1080}, Size{3840, 2160}}) {
        for (const bool right_marks : {false, true}) {
            INFO(size.width << "x" << size.height << (right_marks ? ", marks on both" : ""));
            LayoutInput in = lesson_input(size);
            in.note_line = true;
            in.how_line = true;
            in.mark_lines = {true, right_marks};
            in.small_plot = true;
            in.cost_ratio = true;
            in.clock_unit = true;
            const FrameLayout layout = lesson_layout(in);
            const float frame = static_cast<float>(size.width) * static_cast<float>(size.height);
            CHECK((area(layout.panels[0].box) + area(layout.panels[1].box)) / frame >= 0.55F);
            CHECK(layout.slot(TextRole::note, 0) != nullptr);
            CHECK(layout.slot(TextRole::marks, 0) != nullptr);
            CHECK(layout.slot(TextRole::how, 1) != nullptr);
            check_nothing_overlaps_text(layout, size);
        }
        // One box: the frame's height, its text on the right.
        LayoutInput one = lesson_input(size, 1);
        one.note_line = true;
        one.how_line = true;
        one.mark_lines = {true};
        one.queue_panel = 0;
        const FrameLayout layout = lesson_layout(one);
        const float frame = static_cast<float>(size.width) * static_cast<float>(size.height);
        CHECK(area(layout.panels[0].box) / frame >= 0.42F);
        CHECK(layout.queue_strip.x0 >= layout.panels[0].box.x1);
        CHECK(layout.slots(TextRole::clock).size() >= 1);
        check_nothing_overlaps_text(layout, size);
    }
}

TEST_CASE("lesson layout: the how lines, the work ratio and the clock's unit fit (issue #28)") {
    for (const Size size : {Size{854, 480}, Size{1280, 720}, Size{1920, 1080}, Size{3840, 2160}}) {
        INFO(size.width << "x" << size.height);
        LayoutInput in = lesson_input(size);
        in.how_line = true;
        in.cost_ratio = true;
        in.clock_unit = true;
        const FrameLayout layout = lesson_layout(in);
        const float frame = static_cast<float>(size.width) * static_cast<float>(size.height);
        CHECK((area(layout.panels[0].box) + area(layout.panels[1].box)) / frame >= 0.55F);
        CHECK(layout.slots(TextRole::how).size() == 2);
        CHECK(layout.slots(TextRole::clock).size() == 2);
        CHECK(layout.slots(TextRole::cost_ratio).size() == 1);
        CHECK(layout.slot(TextRole::cost_heading) == nullptr);  // the ratio says it
        CHECK(layout.slots(TextRole::cost_value).size() == 2);
        CHECK(layout.slots(TextRole::energy).size() == 2);  // still room for the energy line
        for (const TextSlot* how : layout.slots(TextRole::how)) {
            CHECK(how->cap_height() >= 0.028F * static_cast<float>(size.height) - 0.01F);
        }
        check_nothing_overlaps_text(layout, size);
    }
}

TEST_CASE("layout JSON carries every text line's strings beside its rectangle") {
    const FrameLayout layout = lesson_layout(lesson_input({1280, 720}));
    SlotTexts drawn;
    drawn.in_slots.assign(layout.text.size(), {});
    drawn.in_slots[0] = {"Time-driven: \"dt\" \\ 1/30", "second"};
    drawn.elsewhere.push_back({layout.text[0], "a label\nin a box"});
    const nlohmann::json json =
        nlohmann::json::parse(layout_json(layout, OverlayLevel::lesson, 1280, 720, &drawn));
    REQUIRE(json.at("text").size() == layout.text.size());
    CHECK(json.at("text")[0].at("text") ==
          std::vector<std::string>{"Time-driven: \"dt\" \\ 1/30", "second"});
    CHECK(json.at("text")[1].at("text").empty());  // a slot with nothing drawn
    REQUIRE(json.at("other_text").size() == 1);
    CHECK(json.at("other_text")[0].at("text") == "a label\nin a box");
    // Without strings: the rectangles alone, as before.
    const nlohmann::json bare =
        nlohmann::json::parse(layout_json(layout, OverlayLevel::lesson, 1280, 720));
    CHECK_FALSE(bare.at("text")[0].contains("text"));
    CHECK_FALSE(bare.contains("other_text"));
}

TEST_CASE("layout JSON gives back a title of quotes, backslashes, tabs and control characters") {
    const FrameLayout layout = lesson_layout(lesson_input({1280, 720}));
    // Every control character, the two JSON must escape, a tab, DEL and some UTF-8.
    std::string title = "\"quoted\" C:\\path\\ \ttab\t \x7f caf\xc3\xa9 ";
    for (char c = 1; c < 0x20; ++c) title += c;
    const std::string variant = "\\\"\\u0041\"\\";  // escapes that must stay text
    SlotTexts drawn;
    drawn.in_slots.assign(layout.text.size(), {});
    drawn.in_slots[0] = {title, variant};
    drawn.elsewhere.push_back({layout.text[0], title});
    const std::string text = layout_json(layout, OverlayLevel::lesson, 1280, 720, &drawn);
    const nlohmann::json json = nlohmann::json::parse(text);
    CHECK(json.at("text")[0].at("text") == std::vector<std::string>{title, variant});
    CHECK(json.at("other_text")[0].at("text") == title);
    // Raw control characters never reach the file (JSON forbids them in strings).
    for (const char c : text) CHECK((static_cast<unsigned char>(c) >= 0x20 || c == '\n'));
    // The numbers keep the values the layout has: whole pixels as integers.
    CHECK(json.at("width") == 1280);
    CHECK(json.at("level") == "lesson");
    CHECK(json.at("panels")[0].at("box")[0].get<double>() ==
          doctest::Approx(layout.panels[0].box.x0));
}

TEST_CASE("figures have thousands separators") {
    CHECK(with_separators(0) == "0");
    CHECK(with_separators(999) == "999");
    CHECK(with_separators(1000) == "1,000");
    CHECK(with_separators(1234567) == "1,234,567");
    CHECK(with_separators(-45000) == "-45,000");
}

TEST_CASE("failure marks persist and fade over one second of video, whatever the frame rate") {
    for (const int fps : {15, 30, 60}) {
        INFO(fps << " fps");
        show::FailureMarks marks;  // the presentation layer keeps them; the painter draws them
        Snapshot s;
        s.time = 0.5;
        s.missed_collisions = {{0.2, 0.3}};
        marks.update(s, 0.0);
        REQUIRE(marks.marks().size() == 1);
        // The time-driven state is held (same time) for a while: the mark is not added again.
        s.missed_collisions = {{0.2, 0.3}};
        int frames_alive = 1;
        for (int k = 1; k < 3 * fps; ++k) {
            const double video = static_cast<double>(k) / fps;
            if (k % 6 == 0) {  // a new step without misses
                s.time += 0.04;
                s.missed_collisions.clear();
            }
            marks.update(s, video);
            if (marks.marks().empty()) break;
            CHECK(marks.marks().size() == 1);
            CHECK(marks.marks()[0].opacity == doctest::Approx(1.0 - video).epsilon(1e-6));
            ++frames_alive;
        }
        // Alive for one second of video: fps frames (within one frame).
        CHECK(frames_alive >= fps - 1);
        CHECK(frames_alive <= fps + 1);
    }
}

TEST_CASE("failure colours are reserved and discs keep 3:1 contrast or get an outline") {
    for (const Theme theme : {Theme::dark, Theme::light}) {
        CHECK(near_failure_color(failure_color(theme)));
        // The failure colour stands out against the box.
        CHECK(contrast_ratio(failure_color(theme), box_fill_color(theme)) >= 3.0);
    }
    // Scene colours near it are moved away; others are untouched.
    const Rgb8 magenta{230, 40, 200};
    CHECK(near_failure_color(magenta));
    CHECK_FALSE(near_failure_color(away_from_failure_color(magenta)));
    const Rgb8 red{224, 48, 48};
    CHECK_FALSE(near_failure_color(red));
    CHECK(away_from_failure_color(red).r == red.r);
    // WCAG contrast: black on white is 21:1, a colour on itself 1:1.
    CHECK(contrast_ratio({0, 0, 0}, {255, 255, 255}) == doctest::Approx(21.0));
    CHECK(contrast_ratio(red, red) == doctest::Approx(1.0));
    // The billiards 8-ball (#202020) is below 3:1 on the dark box: it gets an outline.
    CHECK(contrast_ratio({32, 32, 32}, box_fill_color(Theme::dark)) < min_disc_contrast);
}

/// A walled unit box of `count` unit-mass discs with random velocities.
Snapshot random_gas(std::size_t count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.05, 0.95);
    std::normal_distribution<double> v(0.0, 0.2);
    Snapshot s;
    s.box = {1.0, 1.0, Boundary::walls};
    for (std::size_t i = 0; i < count; ++i) {
        DiscState d;
        d.position = {u(rng), u(rng)};
        d.velocity = {v(rng), v(rng)};
        d.radius = 0.01;
        d.mass = 1.0;
        s.discs.push_back(d);
    }
    return s;
}

bool same_rgb(Rgba8 a, Rgba8 b) {
    return a.r == b.r && a.g == b.g && a.b == b.b;
}

// Counts the glyphs of `color` whose origin lies inside `r`.
int glyphs_inside(const DrawList& list, RectF r, Rgba8 color) {
    int n = 0;
    for (const TextRun& run : list.text) {
        for (const GlyphBox& g : run.glyphs.glyphs()) {
            const bool inside = static_cast<float>(g.x) >= r.x0 && static_cast<float>(g.x) < r.x1 &&
                                static_cast<float>(g.y) >= r.y0 && static_cast<float>(g.y) < r.y1;
            if (inside && same_rgb(g.color, color)) ++n;
        }
    }
    return n;
}

TEST_CASE(
    "more failures than marks: the legend under the box counts the rest, the box holds none") {
    const RenderConfig defaults;
    if (!std::filesystem::exists(defaults.font_path)) {
        COLLIDE_SKIP_TEST("no DejaVu Sans at " << defaults.font_path);
    }
    const RenderConfig config = test::lesson_config(1280, 720);
    const Rgba8 failure = palette(config.theme).failure;
    for (const std::size_t pairs : {std::size_t{10}, show::mark_budget + 25}) {
        INFO(pairs << " overlapping pairs");
        FrameBuilder builder(config);
        Snapshot left = random_gas(2 * pairs, 3);
        for (std::size_t k = 0; k < pairs; ++k)
            left.overlapping_pairs.emplace_back(2 * k, 2 * k + 1);
        const Snapshot right = random_gas(2 * pairs, 4);
        show::FailureMarks marks;
        marks.update(left, 0.0);
        FrameContent frame;
        frame.panels = {{&left, "Time-driven", {}}, {&right, "Event-driven", {}}};
        frame.panels[0].marks = marks.marks();
        frame.panels[0].mark_words = marks.words();
        frame.panels[0].mark_line = true;
        frame.time_text = "t = 1.00";
        const DrawList& list = builder.build(frame);
        CHECK(marks.marks().size() == std::min(pairs, show::mark_budget));
        const TextSlot* legend = builder.layout().slot(TextRole::marks, 0);
        REQUIRE(legend != nullptr);
        const int count = glyphs_inside(list, legend->rect, failure);
        if (pairs > show::mark_budget) {
            CHECK(count >= 8);  // "and 25 more not drawn"
        } else {
            CHECK(count == 0);
        }
        // Nothing but the simulation (and its marks) in either box: no text there.
        for (const PanelLayout& panel : builder.layout().panels) {
            for (const TextRun& run : list.text) {
                for (const GlyphBox& g : run.glyphs.glyphs()) {
                    const bool inside = static_cast<float>(g.x) >= panel.box.x0 &&
                                        static_cast<float>(g.x) < panel.box.x1 &&
                                        static_cast<float>(g.y) >= panel.box.y0 &&
                                        static_cast<float>(g.y) < panel.box.y1;
                    CHECK_FALSE(inside);
                }
            }
        }
    }
}

TEST_CASE("the count of failures not drawn stays under the panel it counts") {
    // Three kinds in the legend of the left panel and more failures than marks (brownian, dense
    // fluid): "and N more not drawn" follows the kinds, never under the other panel's box, at
    // -q l and -q m; a short legend (one kind) keeps it.
    const RenderConfig defaults;
    if (!std::filesystem::exists(defaults.font_path)) {
        COLLIDE_SKIP_TEST("no DejaVu Sans at " << defaults.font_path);
    }
    for (const auto& [width, height] : {std::pair{854, 480}, std::pair{1280, 720}}) {
        for (const bool three_kinds : {false, true}) {
            CAPTURE(width);
            CAPTURE(three_kinds);
            Renderer renderer(test::lesson_config(width, height), test::test_backend());
            const Snapshot left = random_gas(200, 5);
            const Snapshot right = random_gas(200, 6);
            FrameContent frame;
            frame.panels = {{&left, "Time-driven", {}}, {&right, "Event-driven", {}}};
            frame.panels[0].figures = {{"6,564", "missed", true}};
            frame.panels[1].figures = {{"0", "missed", true}};
            frame.panels[0].mark_line = true;
            MarkWords& words = frame.panels[0].mark_words;
            words.items = {{FailureKind::overlapping, "overlapping"}};
            if (three_kinds) {
                words.items.push_back({FailureKind::missed, "missed collision"});
                words.items.push_back({FailureKind::left_box, "left the box"});
            }
            words.unmarked = "and 9,480 more not drawn";
            frame.time_text = "t = 1.00";
            (void)renderer.render(frame);
            const nlohmann::json layout = nlohmann::json::parse(renderer.layout_json(frame));
            const auto right_box = layout.at("panels").at(1).at("box").get<std::vector<float>>();
            float kinds_x1 = 0.0F;
            std::optional<std::vector<float>> count;
            for (const nlohmann::json& ink : layout.at("text_ink")) {
                if (ink.at("role") != "marks") continue;
                const auto rect = ink.at("rect").get<std::vector<float>>();
                if (ink.at("text") == words.unmarked) {
                    count = rect;
                } else {
                    kinds_x1 = std::max(kinds_x1, rect[2]);
                }
            }
            if (!three_kinds) REQUIRE(count.has_value());
            if (count) {
                CAPTURE((*count)[0]);
                CAPTURE((*count)[2]);
                CHECK((*count)[0] > kinds_x1);                  // after the kinds it counts
                CHECK((*count)[0] - kinds_x1 < 0.05F * width);  // beside them, not apart
                CHECK((*count)[2] <= right_box[0]);             // not under the other box
            }
        }
    }
}

TEST_CASE("every plot follows the theme: the light full level's strip has no dark-theme colours") {
    const RenderConfig defaults;
    if (!std::filesystem::exists(defaults.font_path)) {
        COLLIDE_SKIP_TEST("no DejaVu Sans at " << defaults.font_path);
    }
    for (const OverlayLevel level : {OverlayLevel::full, OverlayLevel::lesson}) {
        INFO(overlay_level_name(level));
        RenderConfig config;
        config.width = 1280;
        config.height = 720;
        config.overlays = level;
        config.theme = Theme::light;
        config.speed_max = 0.6;
        FrameBuilder builder(config);
        const Snapshot left = random_gas(300, 1);
        const Snapshot right = random_gas(300, 2);
        FrameContent frame;
        frame.panels = {{&left, "Time-driven", {"steps 40"}}, {&right, "Event-driven", {}}};
        frame.time_text = "t = 2.00";
        frame.energy_line = "Energy conserved";
        frame.energy_drift = {{{0.0, 0.0}, {1.0, 0.01}, {2.0, 0.03}}, {{0.0, 0.0}, {2.0, 0.0}}};
        frame.histogram = PlotSize::small;
        test::add_show_words(frame, config.speed_max);
        const DrawList& list = builder.build(frame);
        const Rgb8 page = rgb(palette(Theme::light).background);
        const PlotColors dark;  // the dark theme's plot colours
        int glyphs = 0;
        for (const TextRun& run : list.text) {
            for (const GlyphBox& g : run.glyphs.glyphs()) {
                ++glyphs;
                // Plot labels, axis numbers, counters: all readable on the light page.
                CHECK(contrast_ratio(rgb(g.color), page) >= 3.0);
            }
        }
        CHECK(glyphs > 50);
        int plot_vertices = 0;
        for (const OverlayVertex& v : list.over.vertices()) {
            CHECK_FALSE(same_rgb(v.color, dark.label));
            CHECK_FALSE(same_rgb(v.color, dark.axis));
            CHECK_FALSE(same_rgb(v.color, dark.curve));
            CHECK_FALSE(same_rgb(v.color, dark.zero_line));
            if (same_rgb(v.color, plot_colors(Theme::light).curve)) ++plot_vertices;
        }
        CHECK(plot_vertices > 0);  // a Maxwell-Boltzmann curve was drawn, in the theme's colour
    }
}

}  // namespace
}  // namespace collide::render
