// The layout module (layout.hpp): pure rectangles, checked for every frame size the CLI offers.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "frame_builder.hpp"
#include "layout.hpp"

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
    in.level = OverlayLevel::lesson;
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
        const FrameLayout layout = compute_layout(lesson_input(size));
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

TEST_CASE("lesson layout: 20 px capitals at 720p") {
    const FrameLayout layout = compute_layout(lesson_input({1280, 720}));
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
            const FrameLayout layout = compute_layout(in);
            CHECK(layout.slots(TextRole::note).size() == static_cast<std::size_t>(panels));
            check_nothing_overlaps_text(layout, size);
        }
    }
    // Boxes of other shapes keep their aspect ratio.
    LayoutInput wide = lesson_input({1280, 720});
    wide.boxes = {{2.0, 1.0, Boundary::walls}, {2.0, 1.0, Boundary::walls}};
    const FrameLayout layout = compute_layout(wide);
    CHECK(layout.panels[0].box.width() == doctest::Approx(2.0 * layout.panels[0].box.height()));
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
            const FrameLayout layout = compute_layout(in);
            REQUIRE(layout.queue_panel == panels - 1);
            const RectF strip = layout.queue_strip;
            CHECK(strip.height() >= std::round(queue_strip_share * size.height) - 0.5F);
            CHECK(layout.slots(TextRole::queue).size() == 1);
            for (const PanelLayout& panel : layout.panels) CHECK(strip.y0 > panel.box.y1);
            check_nothing_overlaps_text(layout, size);
        }
    }
    // Without a queue panel there is no strip, and the boxes are as before.
    const FrameLayout plain = compute_layout(lesson_input({1280, 720}));
    CHECK(plain.queue_panel == -1);
    CHECK(plain.slots(TextRole::queue).empty());
}

TEST_CASE("compact layout below 480 px: boxes fill the frame, one line per panel, 9 px capitals") {
    for (const Size size : {Size{320, 180}, Size{426, 240}, Size{160, 90}}) {
        INFO(size.width << "x" << size.height);
        const FrameLayout layout = compute_layout(lesson_input(size));
        CHECK(layout.compact);
        CHECK(layout.text.size() == 2);  // one line per panel
        for (const TextSlot& slot : layout.text) CHECK(slot.cap_height() >= 9.0F);
        const float frame = static_cast<float>(size.width) * static_cast<float>(size.height);
        if (size.width >= 320) {
            CHECK((area(layout.panels[0].box) + area(layout.panels[1].box)) / frame >= 0.70F);
        }
        check_nothing_overlaps_text(layout, size);
    }
}

TEST_CASE("level none: the boxes fill the frame and there is no text") {
    LayoutInput in = lesson_input({1280, 720});
    in.level = OverlayLevel::none;
    const FrameLayout layout = compute_layout(in);
    CHECK(layout.text.empty());
    const PanelLayout& panel = layout.panels[0];
    CHECK(std::max(panel.box.width() / panel.area.width(),
                   panel.box.height() / panel.area.height()) >= 0.95F);
}

TEST_CASE("layout JSON names every text line with its pixel height") {
    const FrameLayout layout = compute_layout(lesson_input({1280, 720}));
    const std::string json = layout_json(layout, 1280, 720);
    CHECK(json.find("\"level\": \"lesson\"") != std::string::npos);
    CHECK(json.find("\"role\": \"caption\"") != std::string::npos);
    CHECK(json.find("\"pixel_height\": 33") != std::string::npos);
    CHECK(json.find("\"box\": [") != std::string::npos);
}

TEST_CASE("figures have thousands separators") {
    CHECK(with_separators(0) == "0");
    CHECK(with_separators(999) == "999");
    CHECK(with_separators(1000) == "1,000");
    CHECK(with_separators(1234567) == "1,234,567");
    CHECK(with_separators(-45000) == "-45,000");
}

TEST_CASE("failure markers persist and fade over one second of video, whatever the frame rate") {
    for (const int fps : {15, 30, 60}) {
        INFO(fps << " fps");
        MarkerMemory memory;
        Snapshot s;
        s.time = 0.5;
        s.missed_collisions = {{0.2, 0.3}};
        memory.update(s, 0.0);
        REQUIRE(memory.markers().size() == 1);
        // The time-driven state is held (same time) for a while: the marker is not added again.
        s.missed_collisions = {{0.2, 0.3}};
        int frames_alive = 1;
        for (int k = 1; k < 3 * fps; ++k) {
            const double video = static_cast<double>(k) / fps;
            if (k % 6 == 0) {  // a new step without misses
                s.time += 0.04;
                s.missed_collisions.clear();
            }
            memory.update(s, video);
            if (memory.markers().empty()) break;
            CHECK(memory.markers().size() == 1);
            CHECK(MarkerMemory::opacity(memory.markers()[0], video) ==
                  doctest::Approx(1.0 - video).epsilon(1e-6));
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

}  // namespace
}  // namespace collide::render
