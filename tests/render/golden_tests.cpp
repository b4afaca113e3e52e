// Golden images at 320x180: a few whole frames compared with a tolerance (a channel may differ by
// more than 2 on at most 0.1% of the pixels), so small rasteriser changes pass and real ones fail.
// Regenerate deliberately with COLLIDE_UPDATE_GOLDENS=1 (then LOOK at the new PNGs).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../support/skip.hpp"
#include "collide/show/collision.hpp"
#include "collide/show/event_loop_code.hpp"
#include "collide/show/failure_marks.hpp"
#include "layout.hpp"
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
    Renderer renderer(config, test::test_backend());
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
    // Each panel's engine, as the program sets it: the plots draw each series in its accent.
    frame.panels[0].time_driven = true;
    frame.panels[1].time_driven = false;
    frame.time_text = "t = 2.00";
    frame.energy_drift = {{{0.0, 0.0}, {1.0, 0.01}, {2.0, 0.03}},
                          {{0.0, 0.0}, {1.0, 0.0}, {2.0, 0.0}}};
    // The marks and their legend as the app chooses them: a ring, a cross, an arrow at the edge.
    show::FailureMarks marks(show::mark_budget, true);
    marks.update(left, 0.0);
    frame.panels[0].marks = marks.marks();
    frame.panels[0].mark_words = marks.words();
    frame.notes = {"dt = 0.05"};
    frame.color_key = show::color_key(config.color_mode, config.speed_min, config.speed_max,
                                      config.mass_min, config.mass_max);
    test::add_show_words(frame, config.speed_max);
    check_against_golden(renderer.render(frame), "two_panels_speed");
}

TEST_CASE("golden: periodic box with trails crossing the seam, overlays off") {
    RenderConfig config = test::small_config(false);
    config.color_mode = ColorMode::tag;
    Renderer renderer(config, test::test_backend());
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
    const RenderConfig config = test::small_config(true);
    Renderer renderer(config, test::test_backend());
    const Snapshot s = test::gas_snapshot(25, 0.05, {1.6, 0.9, Boundary::walls}, 3, 0.5);
    FrameContent frame;
    frame.panels = {{&s, "Event-driven (priority queue)", {"events 42", "queue 97"}}};
    frame.time_text = "t = 0.50";
    test::add_show_words(frame, config.speed_max);
    check_against_golden(renderer.render(frame), "one_panel_scene");
}

/// A classic engine's queue as the engines report it: a binary heap whose root is stale, the
/// next collisions (a pair and two walls), and the latest pops, one of them stale and just popped.
QueueView classic_queue(double now) {
    QueueView q;
    q.name = "binary heap";
    q.shape = QueueShape::heap;
    q.arity = 2;
    q.size = 170;
    q.stale_entries = 121;
    q.levels = 3;
    q.slots = {
        {now + 0.05, EventKind::pair, 10, 13, true}, {now + 0.2, EventKind::pair, 0, 1},
        {now + 0.1, EventKind::xwall, 2, 0},         {now + 0.3, EventKind::pair, 4, 5, true},
        {now + 0.25, EventKind::ywall, 3, 0},        {now + 0.4, EventKind::pair, 6, 7},
        {now + 0.15, EventKind::xwall, 8, 0, true}};
    q.next = {{now + 0.1, EventKind::xwall, 2, 0},
              {now + 0.2, EventKind::pair, 0, 1},
              {now + 0.25, EventKind::ywall, 3, 0}};
    q.popped = {{now - 0.5, EventKind::pair, 1, 4},
                {now - 0.2, EventKind::ywall, 5, 0},
                {now - 0.01, EventKind::pair, 3, 9, true}};
    q.pops = 76;
    q.stale_pops = 37;
    return q;
}

Snapshot queue_snapshot() {
    Snapshot s = test::gas_snapshot(14, 0.05, {1.0, 1.0, Boundary::walls}, 4, 0.3);
    s.time = 2.0;
    s.discs[0].position = {0.3, 0.3};
    s.discs[1].position = {0.6, 0.45};
    s.discs[2].position = {0.8, 0.7};
    s.discs[2].velocity = {0.4, 0.1};
    s.discs[3].position = {0.2, 0.8};
    s.discs[3].velocity = {0.0, 0.5};
    return s;
}

FrameContent queue_frame(const Snapshot& left, const Snapshot& right) {
    FrameContent frame;
    frame.panels = {{&left, "Time-driven", {}}, {&right, "Event-driven", {}}};
    frame.panels[0].figures = {{"0", "missed", true}};
    frame.panels[1].figures = {{"39", "collisions", false}};
    // The queue strip's words, as the collision video's program writes them.
    if (right.queue) frame.panels[1].queue_words = show::queue_words(*right.queue, right.time);
    frame.time_text = "t = 2.000";
    frame.speed = 1.0;
    // How long a pop stays lit, as the collision video's program sets it (no --code).
    frame.pop_highlight = {show::pop_highlight_seconds(false, false),
                           show::pop_highlight_seconds(true, false)};
    frame.video_time = 2.0;
    test::add_show_words(frame, RenderConfig{}.speed_max);
    return frame;
}

TEST_CASE("golden: the event queue of the classic loop under the panels, 640x360") {
    const RenderConfig config = test::lesson_config(640, 360);
    Renderer renderer(config, test::test_backend());
    const Snapshot left = queue_snapshot();
    Snapshot right = queue_snapshot();
    right.queue = classic_queue(right.time);
    check_against_golden(renderer.render(queue_frame(left, right)), "queue_classic_heap");
}

TEST_CASE("golden: an ordered array's queue, and the fast engine's in a compact frame") {
    RenderConfig config = test::lesson_config(640, 360);
    Renderer renderer(config, test::test_backend());
    const Snapshot left = queue_snapshot();
    Snapshot right = queue_snapshot();
    QueueView q = classic_queue(right.time);
    q.name = "ordered array";
    q.shape = QueueShape::ordered_array;
    std::sort(q.slots.begin(), q.slots.end(),
              [](const QueuedEvent& a, const QueuedEvent& b) { return a.t < b.t; });
    right.queue = q;
    check_against_golden(renderer.render(queue_frame(left, right)), "queue_ordered_array");

    // Compact (thumbnails): the lines in the box only, no labels, no strip.
    config.width = 320;
    config.height = 180;
    Renderer compact(config, test::test_backend());
    q = classic_queue(right.time);
    q.name = "indexed 4-ary heap";
    q.arity = 4;
    q.levels = 2;
    q.one_per_disc = true;
    q.slots.resize(5);
    right.queue = q;
    check_against_golden(compact.render(queue_frame(left, right)), "queue_fast_compact");
}

TEST_CASE("queue: drawn only when the snapshot carries one, the next event in its colour") {
    const RenderConfig config = test::lesson_config(640, 360);
    Renderer renderer(config, test::test_backend());
    const Snapshot left = queue_snapshot();
    Snapshot right = queue_snapshot();
    const Image without = renderer.render(queue_frame(left, right));
    right.queue = classic_queue(right.time);
    Renderer again(config, test::test_backend());
    const Image with = again.render(queue_frame(left, right));
    CHECK(with.rgba != without.rgba);
    // The highlight colour (the next event's tick, ring and label, the heap's root) appears only
    // with the queue.
    const Rgb8 next{255, 196, 40};
    CHECK(test::count_near(without, next, 20) == 0);
    CHECK(test::count_near(with, next, 20) > 40);
    // A snapshot without a queue after one with it: the frame is as if it never had one.
    right.queue.reset();
    CHECK(again.render(queue_frame(left, right)).rgba == without.rgba);
}

// Issue 44 item 4: the queue's labels never cover a disc (they move to a free place, a leader
// line to what they name), and every disc of a listed event is numbered.
TEST_CASE("queue: labels clear of every disc, every listed event's discs numbered") {
    for (const std::size_t discs : {std::size_t{14}, std::size_t{25}}) {
        CAPTURE(discs);
        Renderer renderer(test::lesson_config(1280, 720), test::test_backend());
        Snapshot left = test::gas_snapshot(discs, 0.05, {1.0, 1.0, Boundary::walls}, 4, 0.3);
        left.time = 2.0;
        Snapshot right = left;
        QueueView q = classic_queue(right.time);
        // Five events, pairs of neighbours whose labels would sit on the discs between them.
        q.next = {{2.1, EventKind::pair, 0, 1},
                  {2.2, EventKind::pair, 2, 3},
                  {2.25, EventKind::xwall, 5, 0},
                  {2.3, EventKind::pair, 6, 7},
                  {2.4, EventKind::pair, 8, 9}};
        right.queue = q;
        const FrameContent frame = queue_frame(left, right);
        (void)renderer.render(frame);
        const nlohmann::json layout = nlohmann::json::parse(renderer.layout_json(frame));
        const nlohmann::json& panel = layout.at("panels").at(1);
        const auto box = panel.at("box").get<std::vector<float>>();
        const auto scale = panel.at("pixels_per_unit").get<double>();
        std::vector<RectF> disc_rects;
        for (const DiscState& d : right.discs) {
            const auto x = static_cast<float>(box[0] + d.position.x * scale);
            const auto y = static_cast<float>(box[1] + (right.box.height - d.position.y) * scale);
            const auto r = static_cast<float>(d.radius * scale);
            disc_rects.push_back({x - r, y - r, x + r, y + r});
        }
        std::vector<std::string> in_box;
        for (const nlohmann::json& label : layout.at("other_text")) {
            if (label.at("role") != "queue") continue;
            const auto v = label.at("rect").get<std::vector<float>>();
            const RectF rect{v[0], v[1], v[2], v[3]};
            if (rect.x0 < box[0] || rect.x1 > box[2] || rect.y0 < box[1] || rect.y1 > box[3])
                continue;  // the strip's text
            for (const nlohmann::json& text : label.at("text"))
                in_box.push_back(text.get<std::string>());
            for (const RectF& disc : disc_rects) {
                CAPTURE(label.dump());
                CHECK_FALSE(overlaps(rect, disc));
            }
        }
        // Each time to go and each disc of the five events: 0, 1 (the next), 2, 3, 5, 6, 7, 8, 9.
        for (const char* number : {"0", "1", "2", "3", "5", "6", "7", "8", "9"}) {
            CAPTURE(number);
            CHECK(std::count(in_box.begin(), in_box.end(), std::string(number)) == 1);
        }
        CHECK(in_box.size() >= 9 + 5);
    }
}

/// The crowded-box case's variants: one panel or two, with --code's listing or without, at the
/// -q l and -q m frame sizes.
struct CrowdedVariant {
    bool code = false;
    bool one_panel = false;
};

RectF rect_of(const nlohmann::json& v) {
    const auto r = v.get<std::vector<float>>();
    return {r[0], r[1], r[2], r[3]};
}

TEST_CASE("queue: in a box with no free place every listed disc is numbered outside the box") {
    // dense-fluid's case: discs packed so tight that no label fits between them. The numbers go
    // to the nearest free place of the frame, each with a leader line, never over a disc, another
    // panel's box, the code or any text.
    for (const CrowdedVariant variant : {CrowdedVariant{false, false}, CrowdedVariant{false, true},
                                         CrowdedVariant{true, true}, CrowdedVariant{true, false}}) {
        for (const auto& [width, height] : {std::pair{854, 480}, std::pair{1280, 720}}) {
            for (const std::size_t discs : {std::size_t{900}, std::size_t{1600}}) {
                CAPTURE(discs);
                CAPTURE(variant.code);
                CAPTURE(variant.one_panel);
                CAPTURE(width);
                RenderConfig config = test::small_config(true);
                config.width = width;
                config.height = height;
                config.overlays = OverlayLevel::lesson;
                Renderer renderer(config, test::test_backend());
                const double radius = 0.45 / std::sqrt(static_cast<double>(discs));
                Snapshot left =
                    test::gas_snapshot(discs, radius, {1.0, 1.0, Boundary::walls}, 5, 0.3);
                left.time = 2.0;
                Snapshot right = left;
                QueueView q = classic_queue(right.time);
                const auto last = static_cast<std::uint32_t>(discs - 1);
                q.next = {{2.1, EventKind::pair, 0, 1},
                          {2.2, EventKind::pair, 100, 101},
                          {2.25, EventKind::xwall, 450, 0},
                          {2.3, EventKind::pair, 700, 701},
                          {2.4, EventKind::pair, last, last - 1}};
                right.queue = q;
                FrameContent frame = queue_frame(left, right);
                // dense-fluid's time-driven panel: a note with its step indicator and a marks line,
                // the lines under the boxes that the numbers keep clear of.
                frame.panels[0].note = "Moves only every 12th frame";
                frame.panels[0].step_period = 12;
                frame.panels[0].mark_line = true;
                frame.panels[0].mark_words.items = {{FailureKind::overlapping, "overlapping"},
                                                    {FailureKind::missed, "missed collision"}};
                if (variant.code) frame.code = show::event_loop_view(q, right.time, 1.0);
                if (variant.one_panel) frame.panels.erase(frame.panels.begin());
                test::dump_if_requested(renderer.render(frame),
                                        "crowded_" + std::to_string(discs) + "_" +
                                            std::to_string(width) + (variant.code ? "_code" : "") +
                                            (variant.one_panel ? "_one" : "_two"));
                const nlohmann::json layout = nlohmann::json::parse(renderer.layout_json(frame));
                const nlohmann::json& panels = layout.at("panels");
                const nlohmann::json& panel = panels.at(panels.size() - 1);
                const RectF box = rect_of(panel.at("box"));
                const auto scale = panel.at("pixels_per_unit").get<double>();
                std::vector<RectF> disc_rects;
                for (const DiscState& d : right.discs) {
                    const auto x = static_cast<float>(box.x0 + d.position.x * scale);
                    const auto y =
                        static_cast<float>(box.y0 + (right.box.height - d.position.y) * scale);
                    const auto r = static_cast<float>(d.radius * scale);
                    // Discs are drawn scissored to their box: a disc at a wall ends at the box's
                    // edge.
                    disc_rects.push_back({std::max(x - r, box.x0), std::max(y - r, box.y0),
                                          std::min(x + r, box.x1), std::min(y + r, box.y1)});
                }
                // What a number must stay off: the other panel's box, the queue strip, the code's
                // rows and the caption.
                std::vector<RectF> keep_off;
                RectF strip{};
                for (const nlohmann::json& slot : layout.at("text")) {
                    const std::string role = slot.at("role").get<std::string>();
                    if (role == "queue") strip = rect_of(slot.at("rect"));
                    if (role == "queue" || role == "code" || role == "caption")
                        keep_off.push_back(rect_of(slot.at("rect")));
                }
                if (!variant.one_panel) keep_off.push_back(rect_of(panels.at(0).at("box")));
                std::vector<std::string> numbers;
                std::vector<RectF> plates;
                for (const nlohmann::json& label : layout.at("other_text")) {
                    if (label.at("role") != "queue") continue;
                    const RectF rect = rect_of(label.at("rect"));
                    if (overlaps(rect, strip)) continue;  // the strip's own text
                    CAPTURE(label.dump());
                    CHECK(rect.x0 >= 0.0F);
                    CHECK(rect.y0 >= 0.0F);
                    CHECK(rect.x1 <= static_cast<float>(width));
                    CHECK(rect.y1 <= static_cast<float>(height));
                    for (const RectF& other : keep_off) CHECK_FALSE(overlaps(rect, other));
                    for (const RectF& plate : plates) CHECK_FALSE(overlaps(rect, plate));
                    plates.push_back(rect);
                    for (const nlohmann::json& text : label.at("text"))
                        numbers.push_back(text.get<std::string>());
                    for (const RectF& disc : disc_rects) CHECK_FALSE(overlaps(rect, disc));
                }
                // Every listed disc is numbered once, at every size, with one box or two.
                for (const std::uint32_t disc :
                     {0U, 1U, 100U, 101U, 450U, 700U, 701U, last - 1, last}) {
                    CAPTURE(disc);
                    CHECK(std::count(numbers.begin(), numbers.end(), std::to_string(disc)) == 1);
                }
            }
        }
    }
}

}  // namespace
}  // namespace collide::render
