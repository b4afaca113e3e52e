// The lesson's failure marks by kind (failure_marks.hpp): a ring, a cross, an arrow out of the
// edge, each named in a legend under the box; dashed periodic edges; and the contrast of every
// colour pair the painters use (theme.hpp), in both themes.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "../support/skip.hpp"
#include "collide/show/failure_marks.hpp"
#include "layout.hpp"
#include "render_fixtures.hpp"
#include "theme.hpp"

namespace collide::render {
namespace {

using test::count_near;
using test::px;
using test::rgb_at;

bool have_font() {
    return std::filesystem::exists(RenderConfig{}.font_path);
}

struct Lesson {
    Image image;
    FrameLayout layout;
    std::string json;
};

/// One panel at the lesson level, 854x480, with `marks` and a legend line.
Lesson render_marks(const Snapshot& s, const std::vector<FailureMark>& marks, MarkWords words,
                    Theme theme = Theme::dark) {
    RenderConfig config = test::lesson_config(854, 480);
    config.theme = theme;
    Renderer renderer(config, test::test_backend());
    FrameContent frame;
    frame.panels = {{&s, "Time-driven", {}}};
    frame.panels[0].figures = {{"3", "failures", true}};
    frame.panels[0].marks = marks;
    frame.panels[0].mark_words = std::move(words);
    frame.panels[0].mark_line = true;
    Lesson out;
    out.image = renderer.render(frame);
    out.json = renderer.layout_json(frame);
    LayoutInput in;
    in.width = config.width;
    in.height = config.height;
    in.boxes = {s.box};
    in.mark_lines = {true};
    out.layout = lesson_layout(in);
    return out;
}

TEST_CASE("a failure of each kind is drawn with its own mark, and the legend names each") {
    if (!have_font()) COLLIDE_SKIP_TEST("no DejaVu Sans at " << RenderConfig{}.font_path);
    for (const Theme theme : {Theme::dark, Theme::light}) {
        INFO(theme_name(theme));
        Snapshot s;
        s.box = {10.0, 10.0, Boundary::walls};
        const std::vector<FailureMark> marks = {
            {FailureKind::missed, {3.0, 7.0}, {}, 1.0, 1.0F},
            {FailureKind::overlapping, {7.0, 7.0}, {}, 1.0, 1.0F},
            {FailureKind::left_box, {10.0, 3.0}, {1.0, 0.0}, 1.0, 1.0F},
        };
        MarkWords words;
        for (const FailureKind kind :
             {FailureKind::missed, FailureKind::overlapping, FailureKind::left_box})
            words.items.push_back({kind, show::failure_name(kind)});
        const Lesson r = render_marks(s, marks, words, theme);
        test::dump_if_requested(r.image,
                                std::string("marks_by_kind_") + std::string(theme_name(theme)));
        const Rgb8 failure = failure_color(theme);
        const PanelLayout& panel = r.layout.panels.at(0);
        const auto near = [&](PointF p, int half) {
            return count_near(r.image, failure, 40, px(p.x) - half, px(p.y) - half,
                              px(p.x) + half + 1, px(p.y) + half + 1);
        };
        const float radius = static_cast<float>(panel.scale);  // size 1 box unit
        // Missed: a ring, empty in the middle, drawn at its radius.
        const PointF ring = panel.to_pixels({3.0, 7.0}, s.box);
        CHECK(near(ring, 2) == 0);
        CHECK(near({ring.x + radius, ring.y}, 2) > 0);
        CHECK(near({ring.x, ring.y - radius}, 2) > 0);
        // Overlapping: a cross, filled in the middle and along its diagonals.
        const PointF cross = panel.to_pixels({7.0, 7.0}, s.box);
        CHECK(near(cross, 1) > 0);
        CHECK(near({cross.x + 0.5F * radius, cross.y + 0.5F * radius}, 2) > 0);
        CHECK(near({cross.x + radius, cross.y}, 2) == 0);  // no ring around it
        // Left the box: an arrow to the right edge, its tip just inside: nothing of it beyond
        // the box and its wall, where the text beside the box begins.
        const PointF exit = panel.to_pixels({10.0, 3.0}, s.box);
        CHECK(count_near(r.image, failure, 40, px(panel.box.x1) - 6, px(exit.y) - 3,
                         px(panel.box.x1), px(exit.y) + 4) > 0);
        CHECK(count_near(r.image, failure, 40, px(panel.box.x1), px(exit.y) - 40,
                         px(panel.box.x1) + 40, px(exit.y) + 41) == 0);
        CHECK(near({exit.x - 10.0F, exit.y}, 2) > 0);  // the shaft, inside
        // Nowhere else in the box: no plate, no note.
        const int in_box = count_near(r.image, failure, 40, px(panel.box.x0), px(panel.box.y0),
                                      px(panel.box.x1), px(panel.box.y1));
        const int exit_side = count_near(r.image, failure, 40, px(exit.x) - 30, px(exit.y) - 30,
                                         px(panel.box.x1), px(exit.y) + 31);
        CHECK(in_box == near(ring, px(radius) + 4) + near(cross, px(radius) + 4) + exit_side);
        // The legend: under the figures, outside the box (one box: its text is on its right),
        // its symbols in the failure colour and its words in the text colour.
        const TextSlot* legend = r.layout.slot(TextRole::marks, 0);
        REQUIRE(legend != nullptr);
        CHECK_FALSE(overlaps(legend->rect, panel.box));
        CHECK(legend->rect.y0 >= r.layout.slot(TextRole::figures, 0)->rect.y1);
        const Rgb8 text = rgb(palette(theme).text);
        CHECK(count_near(r.image, failure, 40, px(legend->rect.x0), px(legend->rect.y0),
                         px(legend->rect.x1), px(legend->rect.y1)) > 20);
        CHECK(count_near(r.image, text, 40, px(legend->rect.x0), px(legend->rect.y0),
                         px(legend->rect.x1), px(legend->rect.y1)) > 50);
        CHECK(r.json.find("\"marks\"") != std::string::npos);
    }
}

TEST_CASE("the presentation layer's marks reach the picture: escaped discs marked at the edge") {
    if (!have_font()) COLLIDE_SKIP_TEST("no DejaVu Sans at " << RenderConfig{}.font_path);
    Snapshot s;
    s.time = 1.0;
    s.box = {10.0, 10.0, Boundary::walls};
    DiscState gone = test::disc_at({-4.0, 5.0}, 0.5, {0, 255, 0});
    gone.velocity = {-1.0, 0.0};
    gone.escaped = true;
    s.discs = {gone};
    show::FailureMarks marks;
    marks.update(s, 0.0);
    REQUIRE(marks.marks().size() == 1);
    const Lesson r = render_marks(s, marks.marks(), marks.words());
    const PanelLayout& panel = r.layout.panels.at(0);
    const PointF exit = panel.to_pixels({0.0, 5.0}, s.box);
    // The arrow's tip, just inside the left edge at the height where it left; nothing of it
    // left of the box.
    CHECK(count_near(r.image, failure_color(Theme::dark), 40, px(panel.box.x0), px(exit.y) - 3,
                     px(panel.box.x0) + 6, px(exit.y) + 4) > 0);
    CHECK(count_near(r.image, failure_color(Theme::dark), 40, 0, px(exit.y) - 40, px(panel.box.x0),
                     px(exit.y) + 41) == 0);
    CHECK(count_near(r.image, {0, 255, 0}, 40) == 0);  // the disc itself is not drawn
}

// The full level drew escaped discs outside the box, over the counters, with magenta halos and
// flashes for the other kinds and no legend.
TEST_CASE("the full level draws the same marks by kind, with their legend on the notice line") {
    if (!have_font()) COLLIDE_SKIP_TEST("no DejaVu Sans at " << RenderConfig{}.font_path);
    Snapshot s;
    s.time = 1.0;
    s.box = {10.0, 10.0, Boundary::walls};
    DiscState gone = test::disc_at({-4.0, 5.0}, 0.5, {0, 255, 0});
    gone.velocity = {-1.0, 0.0};
    gone.escaped = true;
    s.discs = {gone, test::disc_at({3.0, 3.0}, 0.5, {0, 0, 255})};
    s.missed_collisions = {{7.0, 7.0}};
    show::FailureMarks marks;
    marks.update(s, 0.0);
    REQUIRE(marks.marks().size() == 2);
    RenderConfig config;
    config.width = 854;
    config.height = 480;
    config.overlays = OverlayLevel::full;
    Renderer renderer(config, test::test_backend());
    FrameContent frame;
    frame.panels = {{&s, "Time-driven", {}}};
    frame.panels[0].marks = marks.marks();
    frame.panels[0].mark_words = marks.words();
    const Image image = renderer.render(frame);
    test::dump_if_requested(image, "full_level_marks");
    const FrameLayout layout =
        compute_layout(config, {s.box}, font_pixel_height(config.height) * 1.2F, 0);
    const PanelLayout& panel = layout.panels.at(0);
    const Rgb8 failure = failure_color(Theme::dark);
    CHECK(count_near(image, {0, 255, 0}, 40) == 0);  // the escaped disc is not drawn anywhere
    // An arrow to the left edge where it left, inside the box; a ring where the collision was
    // missed.
    const PointF exit = panel.to_pixels({0.0, 5.0}, s.box);
    CHECK(count_near(image, failure, 40, px(panel.box.x0), px(exit.y) - 3, px(panel.box.x0) + 6,
                     px(exit.y) + 4) > 0);
    CHECK(count_near(image, failure, 40, 0, px(exit.y) - 40, px(panel.box.x0), px(exit.y) + 41) ==
          0);
    const PointF ring = panel.to_pixels({7.0, 7.0}, s.box);
    CHECK(count_near(image, failure, 40, px(ring.x) - 2, px(ring.y) - 2, px(ring.x) + 3,
                     px(ring.y) + 3) == 0);  // a ring, not a flash: empty in the middle
    // The legend names both kinds on the bottom line, with their symbols.
    const std::string json = renderer.layout_json(frame);
    CHECK(json.find(show::failure_name(FailureKind::missed)) != std::string::npos);
    CHECK(json.find(show::failure_name(FailureKind::left_box)) != std::string::npos);
    CHECK(count_near(image, failure, 40, 0, config.height - px(layout.margin) * 3, config.width,
                     config.height) > 20);
}

TEST_CASE("a periodic box's edges are dashed, a walled box's solid") {
    if (!have_font()) COLLIDE_SKIP_TEST("no DejaVu Sans at " << RenderConfig{}.font_path);
    for (const Boundary boundary : {Boundary::walls, Boundary::periodic}) {
        Snapshot s;
        s.box = {10.0, 10.0, boundary};
        const Lesson r = render_marks(s, {}, {});
        const PanelLayout& panel = r.layout.panels.at(0);
        const Palette p = palette(Theme::dark);
        const Rgb8 edge = rgb(boundary == Boundary::walls ? p.wall : p.wrap_edge);
        // Along the line just above the box: runs of the edge colour and of the page.
        const int y = px(panel.box.y0) - 1;
        int changes = 0;
        bool last = false;
        for (int x = px(panel.box.x0) + 2; x < px(panel.box.x1) - 2; ++x) {
            const Rgb8 c = rgb_at(r.image, x, y);
            const bool on =
                std::abs(c.r - edge.r) + std::abs(c.g - edge.g) + std::abs(c.b - edge.b) < 30;
            if (x > px(panel.box.x0) + 2 && on != last) ++changes;
            last = on;
        }
        if (boundary == Boundary::walls) {
            CHECK(changes == 0);
        } else {
            CHECK(changes >= 10);
        }
    }
}

TEST_CASE("contrast: every colour pair the painters use, in both themes") {
    for (const Theme theme : {Theme::dark, Theme::light}) {
        for (const ColorPair& pair : color_pairs(theme)) {
            const double ratio = contrast_ratio(pair.color, pair.background);
            INFO(theme_name(theme) << ": " << pair.what << " " << ratio << ":1");
            CHECK(ratio >= pair.minimum);
        }
    }
}

TEST_CASE("contrast: a question's arrows and candidates apart from each other and the box") {
    // How far apart two colours lie (RGB distance): a class tells them apart at a glance.
    const auto distance = [](Rgb8 x, Rgb8 y) {
        return std::hypot(x.r - y.r, x.g - y.g, x.b - y.b);
    };
    for (const Theme theme : {Theme::dark, Theme::light}) {
        CAPTURE(theme_name(theme));
        const Palette p = palette(theme);
        const Rgb8 arrow = motion_arrow_color(theme);
        CHECK(contrast_ratio(arrow, rgb(p.box_fill)) >= mark_contrast);
        for (int i = 0; i < static_cast<int>(candidate_tints); ++i) {
            CAPTURE(i);
            const Rgb8 tint = candidate_color(i, theme);
            // On the box and on a letter's plate (the box's colour).
            CHECK(contrast_ratio(tint, rgb(p.box_fill)) >= text_contrast);
            // Never an arrow's colour, the failure colour (the reveal's) or the next event's.
            CHECK(distance(tint, arrow) >= 100.0);
            CHECK(distance(tint, rgb(p.failure)) >= 80.0);
            CHECK_FALSE(near_failure_color(tint));
            CHECK(distance(tint, next_event_color(theme)) >= 80.0);
            for (int j = 0; j < i; ++j) CHECK(distance(tint, candidate_color(j, theme)) >= 100.0);
        }
        // Past the last, the colours cycle (a question never has more than four candidates).
        CHECK(distance(candidate_color(static_cast<int>(candidate_tints), theme),
                       candidate_color(0, theme)) == 0.0);
    }
}

TEST_CASE("contrast: every colour pair of the heap lesson and the puzzle, in both themes") {
    for (const Theme theme : {Theme::dark, Theme::light}) {
        std::vector<ColorPair> pairs = heap_color_pairs(theme);
        const std::vector<ColorPair> puzzle = puzzle_color_pairs(theme);
        pairs.insert(pairs.end(), puzzle.begin(), puzzle.end());
        CHECK(pairs.size() > 40);
        for (const ColorPair& pair : pairs) {
            const double ratio = contrast_ratio(pair.color, pair.background);
            INFO(theme_name(theme) << ": " << std::string(pair.what) << " " << ratio << ":1");
            CHECK(ratio >= pair.minimum);
        }
    }
}

TEST_CASE("contrast: trails keep 3:1 down to their faintest segment, whatever the disc colour") {
    std::vector<Rgb8> colors = {{240, 240, 240}, {255, 255, 255}, {0, 0, 0},     {32, 32, 32},
                                {242, 194, 48},  {32, 80, 192},   {208, 48, 32}, {96, 32, 128},
                                {224, 112, 32},  {32, 112, 64},   {128, 32, 32}, {250, 160, 40},
                                {120, 122, 135}};
    for (int k = 0; k <= 20; ++k) colors.push_back(colormap(k / 20.0));
    for (const Theme theme : {Theme::dark, Theme::light}) {
        const Rgb8 fill = box_fill_color(theme);
        for (const Rgb8 c : colors) {
            const TrailLook look = trail_look(c, theme);
            // The trail's faintest alpha, as TrailHistory::draw truncates it.
            const auto alpha = static_cast<std::uint8_t>(trail_max_alpha * look.min_share);
            const Rgb8 faintest = blend(look.color, fill, static_cast<float>(alpha) / 255.0F);
            INFO(theme_name(theme) << " colour " << int(c.r) << "," << int(c.g) << "," << int(c.b));
            CHECK(contrast_ratio(faintest, fill) >= mark_contrast);
            CHECK(look.min_share < 1.0F);  // it still fades
        }
    }
}

TEST_CASE("contrast: a fading failure ring never gets fainter than 3:1 against the box") {
    for (const Theme theme : {Theme::dark, Theme::light}) {
        const Palette p = palette(theme);
        const float floor = mark_floor(theme);
        CHECK(floor < 1.0F);
        CHECK(contrast_ratio(blend(rgb(p.failure), rgb(p.box_fill), floor), rgb(p.box_fill)) >=
              mark_contrast);
    }
    // The light theme's accents, too faint on the page before (2:1), keep 3:1 as bars and
    // 4.5:1 as the cost label's text.
    const Rgb8 page = rgb(palette(Theme::light).background);
    for (const bool time_driven : {true, false}) {
        CHECK(contrast_ratio(panel_accent(time_driven, Theme::light), page) >= mark_contrast);
        CHECK(contrast_ratio(accent_text(panel_accent(time_driven, Theme::light), Theme::light),
                             page) >= text_contrast);
    }
    CHECK(panel_accent(true, Theme::dark) == panel_accent(true));  // dark: unchanged
}

}  // namespace
}  // namespace collide::render
