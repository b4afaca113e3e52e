// The priority-queue lesson view (heap_view.hpp): tree layout, panel layout, legibility limits,
// input checks, pixel checks of highlights and slides, and golden frames at 480x270 (tolerant
// comparison as in golden_tests.cpp; regenerate with COLLIDE_UPDATE_GOLDENS=1, then LOOK).
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "../support/assert_death.hpp"
#include "../support/input_error.hpp"
#include "../support/skip.hpp"
#include "collide/assert.hpp"
#include "collide/error.hpp"
#include "collide/render/heap_view.hpp"
#include "collide/show/heap_program.hpp"
#include "collide/sim/pq/heap_record.hpp"
#include "collide/sim/pq/queue_kind.hpp"
#include "heap_view_layout.hpp"
#include "render_fixtures.hpp"

namespace collide::render {
namespace {

namespace fs = std::filesystem;

view::HeapPanelView binary_panel(const std::vector<std::string>& keys, std::size_t capacity) {
    view::HeapPanelView p;
    p.title = "binary heap (max)";
    p.counters = {{"compares", "3"}, {"exchanges", "2"}};
    p.sorted_label = "sorted";
    p.caption = "insert S at a[6]; S > P: exchange";
    p.capacity = capacity;
    for (const std::string& k : keys) p.slots.push_back({k, view::SlotMark::plain});
    return p;
}

view::HeapFrameView frame_of(std::vector<view::HeapPanelView> panels) {
    view::HeapFrameView f;
    f.tokens = {"P", "Q", "E", "*", "X", "S"};
    f.current_token = 5;
    f.panels = std::move(panels);
    return f;
}

HeapViewConfig config_of(int width, int height) {
    HeapViewConfig c;
    c.width = width;
    c.height = height;
    return c;
}

/// Pixels whose colour is within 40 of `c` on every channel.
std::size_t pixels_near(const Image& image, Rgb8 c) {
    std::size_t n = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const Rgb8 p = test::rgb_at(image, x, y);
            n += std::abs(p.r - c.r) < 40 && std::abs(p.g - c.g) < 40 && std::abs(p.b - c.b) < 40;
        }
    }
    return n;
}

constexpr Rgb8 amber{240, 170, 40};
constexpr Rgb8 blue{70, 145, 240};

// ------------------------------------------------------------------------------ golden frames

bool updating_goldens() {
    const char* flag = std::getenv("COLLIDE_UPDATE_GOLDENS");
    return flag != nullptr && std::string(flag) == "1";
}

void check_golden(const Image& image, const std::string& name) {
    const fs::path path = fs::path(COLLIDE_TESTS_DIR) / "render" / "golden" / (name + ".png");
    test::dump_if_requested(image, "golden_" + name);
    if (updating_goldens()) {
        video::write_png(image, path);
        MESSAGE("updated golden image " << path.string());
        return;
    }
    REQUIRE_MESSAGE(fs::exists(path), "missing golden " << path.string());
    const Image golden = video::read_png(path);
    REQUIRE(golden.width == image.width);
    REQUIRE(golden.height == image.height);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        for (std::size_t c = 0; c < 4; ++c) {
            if (std::abs(image.rgba[i + c] - golden.rgba[i + c]) > 2) {
                ++differing;
                break;
            }
        }
    }
    const auto allowed = static_cast<std::size_t>(0.001 * image.width * image.height);
    INFO("golden " << name << ": " << differing << " pixels differ (allowed " << allowed << ")");
    CHECK(differing <= allowed);
}

}  // namespace

TEST_CASE("heap view: a binary tree's nodes sit level by level, parents over their children") {
    const std::vector<PointF> p = tree_positions(11, 2);
    REQUIRE(p.size() == 11);
    CHECK(tree_levels(11, 2) == 4);
    CHECK(tree_leaves(11, 2) == 6);
    CHECK(p[0].y == 0.0F);
    CHECK(p[10].y == 1.0F);
    CHECK(p[1].y == doctest::Approx(1.0 / 3.0));
    for (std::size_t i = 1; i < p.size(); ++i) {
        CHECK(p[i].y > p[(i - 1) / 2].y);  // children below their parent
    }
    CHECK(p[1].x == doctest::Approx(0.5F * (p[3].x + p[4].x)));
    CHECK(p[1].x < p[0].x);
    CHECK(p[0].x < p[2].x);
    // No two nodes of a level overlap: x strictly increasing along each level.
    for (std::size_t i = 4; i < 6; ++i) CHECK(p[i].x < p[i + 1].x);
    for (const PointF& q : p) {
        CHECK(q.x >= 0.0F);
        CHECK(q.x <= 1.0F);
    }
}

TEST_CASE("heap view: d-ary trees, single nodes and empty trees") {
    CHECK(tree_levels(0, 3) == 0);
    CHECK(tree_levels(1, 3) == 1);
    CHECK(tree_levels(4, 3) == 2);
    CHECK(tree_levels(5, 3) == 3);
    CHECK(tree_leaves(13, 3) == 9);
    CHECK(tree_positions(1, 2)[0].x == 0.5F);
    CHECK(tree_positions(1, 2)[0].y == 0.5F);
    const std::vector<PointF> p = tree_positions(4, 3);
    CHECK(p[0].x == doctest::Approx(p[2].x));  // the middle child under the root
    CHECK(tree_positions(0, 2).empty());
}

TEST_CASE("heap view: panels share one row and the legible limit shrinks with them") {
    const std::vector<RectF> r = panel_rects(3, {0.0F, 0.0F, 320.0F, 100.0F}, 10.0F);
    REQUIRE(r.size() == 3);
    CHECK(r[0].width() == doctest::Approx(100.0F));
    CHECK(r[2].x1 == doctest::Approx(320.0F));
    CHECK(r[1].y0 == 0.0F);
    CHECK(max_legible_keys(1) == 36);
    CHECK(max_legible_keys(3) == 12);
    CHECK(max_legible_keys(5) == 7);  // the lecture's trace holds 7 keys at most
}

TEST_CASE("heap view: panels share the row by need (an indexed heap's map column)") {
    const RectF area{0.0F, 0.0F, 320.0F, 100.0F};
    // Every need within an equal share: equal widths, as panel_rects.
    std::vector<RectF> r = panel_rects_by_need({50.0F, 90.0F, 100.0F}, area, 10.0F);
    REQUIRE(r.size() == 3);
    for (const RectF& p : r) CHECK(p.width() == doctest::Approx(100.0F));
    // One needs more: it gets it, the others share the rest, the row still ends at the area's.
    r = panel_rects_by_need({60.0F, 140.0F, 60.0F}, area, 10.0F);
    CHECK(r[1].width() == doctest::Approx(140.0F));
    CHECK(r[0].width() == doctest::Approx(80.0F));
    CHECK(r[2].width() == doctest::Approx(80.0F));
    CHECK(r[1].x0 == doctest::Approx(r[0].x1 + 10.0F));
    CHECK(r[2].x1 == doctest::Approx(320.0F));
    // A share that a second panel then needs more than: both get their need.
    r = panel_rects_by_need({20.0F, 150.0F, 95.0F}, area, 10.0F);
    CHECK(r[1].width() == doctest::Approx(150.0F));
    CHECK(r[2].width() == doctest::Approx(95.0F));
    CHECK(r[0].width() == doctest::Approx(55.0F));
    // More than the row holds: equal widths, as panel_rects.
    r = panel_rects_by_need({150.0F, 300.0F, 150.0F}, area, 10.0F);
    for (const RectF& p : r) CHECK(p.width() == doctest::Approx(100.0F));
    CHECK(r[2].x1 == doctest::Approx(320.0F));
}

TEST_CASE("heap view: a bad config is an input error, a bad frame a failed assertion") {
    HeapViewConfig tiny = config_of(32, 90);
    CHECK_THROWS_AS(HeapRenderer(tiny, test::test_backend()), Error);
    // Frames come from collide's own code: a broken one is a programmer error (assert.hpp).
    if (!asserts_enabled) COLLIDE_SKIP_TEST("assertions are off in this build type");
    using collide::test::assertion_failure;
    using collide::test::contains;
    HeapRenderer renderer(config_of(160, 90), test::test_backend());
    const auto failure = [&](const view::HeapFrameView& f) {
        return assertion_failure([&] { (void)renderer.render(f); });
    };
    CHECK(contains(failure(view::HeapFrameView{}), "a heap frame has 1 to max_heap_panels panels"));
    view::HeapPanelView too_many = binary_panel({"A", "B", "C"}, 2);
    CHECK(contains(failure(frame_of({too_many})), "no more slots than the capacity"));
    view::HeapPanelView bad_swap = binary_panel({"A", "B"}, 3);
    bad_swap.swap = view::HeapSwapView{0, 2, 0.5F};
    CHECK(contains(failure(frame_of({bad_swap})), "an exchange of slots that exist"));
}

TEST_CASE("heap view: compared keys light up amber, exchanged ones blue, frames repeat exactly") {
    HeapRenderer renderer(config_of(480, 270), test::test_backend());
    view::HeapPanelView plain = binary_panel({"T", "P", "R", "N", "H"}, 7);
    const Image before = renderer.render(frame_of({plain}));
    view::HeapPanelView compared = plain;
    compared.slots[1].mark = view::SlotMark::compared;
    compared.slots[4].mark = view::SlotMark::compared;
    const Image lit = renderer.render(frame_of({compared}));
    // Two nodes and two slots turn amber (the token tab is amber in both frames).
    CHECK(pixels_near(lit, amber) > pixels_near(before, amber) + 400);
    view::HeapPanelView moving = plain;
    moving.slots[1].mark = view::SlotMark::moving;
    moving.slots[4].mark = view::SlotMark::moving;
    moving.swap = view::HeapSwapView{4, 1, 0.5F};
    const Image sliding = renderer.render(frame_of({moving}));
    CHECK(pixels_near(sliding, blue) > pixels_near(before, blue) + 400);
    CHECK(renderer.render(frame_of({moving})).rgba == sliding.rgba);  // deterministic
    // Halfway through the exchange the frame differs from both ends.
    moving.swap->t = 0.0F;
    const Image start = renderer.render(frame_of({moving}));
    CHECK(start.rgba != sliding.rgba);
}

TEST_CASE("golden: the lecture's binary heap mid-exchange, 480x270") {
    HeapRenderer renderer(config_of(480, 270), test::test_backend());
    view::HeapPanelView p =
        binary_panel({"T", "P", "R", "N", "H", "O", "A", "E", "I", "G", "S"}, 11);
    p.slots[10].mark = view::SlotMark::moving;
    p.slots[4].mark = view::SlotMark::moving;
    p.swap = view::HeapSwapView{10, 4, 0.4F};
    p.caption = "insert S at a[11]; exchange S and H";
    check_golden(renderer.render(frame_of({p})), "heap_binary_exchange");
}

TEST_CASE("golden: arrays and a heap side by side, the scan and a shift, 480x270") {
    HeapRenderer renderer(config_of(480, 270), test::test_backend());
    view::HeapPanelView unordered;
    unordered.title = "unordered array (max)";
    unordered.counters = {{"compares", "2"}, {"exchanges", "0"}};
    unordered.caption = "scan for the max: X > P, new max X";
    unordered.tree = false;
    unordered.capacity = 7;
    unordered.slots = {
        {"P", view::SlotMark::plain}, {"E", view::SlotMark::best}, {"X", view::SlotMark::compared}};
    view::HeapPanelView ordered = unordered;
    ordered.title = "ordered array (max)";
    ordered.counters = {{"compares", "2"}, {"shifts", "1"}};
    ordered.caption = "insert M at a[3]; shift P right to a[3]";
    ordered.slots = {
        {"E", view::SlotMark::plain}, {"P", view::SlotMark::moving}, {"M", view::SlotMark::moving}};
    ordered.swap = view::HeapSwapView{1, 2, 0.5F};
    view::HeapPanelView heap = binary_panel({"X", "E", "P"}, 7);
    heap.slots[0].mark = view::SlotMark::compared;
    heap.slots[2].mark = view::SlotMark::compared;
    check_golden(renderer.render(frame_of({unordered, ordered, heap})), "heap_three_panels");
}

TEST_CASE("golden: the indexed heap's map and heapsort's sorted part, 480x270") {
    HeapRenderer renderer(config_of(480, 270), test::test_backend());
    view::HeapPanelView indexed = binary_panel({"12", "7", "5"}, 4);
    indexed.title = "indexed binary heap (max)";
    indexed.show_map = true;
    indexed.map_title = "keys[i] / qp[i]";
    indexed.slots[0].mark = view::SlotMark::changed;
    indexed.map = {{"5", "3", false}, {"12", "1", true}, {"7", "2", false}};
    indexed.caption = "increase 3 to 12: qp[] says 3 is at a[3]; set a[3] = 12";
    HeapViewConfig config = config_of(480, 270);
    config.widest_key = "12";
    HeapRenderer wide_keys(config, test::test_backend());
    check_golden(wide_keys.render(frame_of({indexed})), "heap_indexed_map");

    view::HeapPanelView sort =
        binary_panel({"P", "O", "M", "L", "E", "A", "E", "R", "S", "T", "X"}, 11);
    sort.title = "heapsort (ascending)";
    sort.heap_size = 7;
    sort.slots[1].mark = view::SlotMark::compared;
    sort.slots[2].mark = view::SlotMark::compared;
    sort.caption = "sortdown; sink P: larger child? O > M";
    view::HeapFrameView f = frame_of({sort});
    f.tokens = {"build", "sortdown"};
    f.current_token = 1;
    check_golden(renderer.render(f), "heap_sortdown");
}

TEST_CASE("heap view: a complete d-ary layout puts each parent over its middle child") {
    // The 3-heap of the lecture's trace (7 keys at most): compact, its root is off its middle
    // child; complete, every level is spread as if full and the tree is symmetric.
    CHECK(tree_columns(7, 3, false) == 5);
    CHECK(tree_columns(7, 3, true) == 9);
    CHECK(tree_columns(11, 2, true) == 8);
    const std::vector<PointF> p = tree_positions(7, 3, true);
    CHECK(p[0].x == doctest::Approx(0.5F));
    CHECK(p[2].x == doctest::Approx(p[0].x));                    // the middle child under the root
    CHECK(p[5].x == doctest::Approx(p[1].x));                    // node 1's middle child under it
    CHECK(p[2].x - p[1].x == doctest::Approx(p[3].x - p[2].x));  // siblings evenly apart
    CHECK(p[4].x == doctest::Approx(0.0F));                      // the first column
    // Compact: the root is the centre of the whole tree.
    const std::vector<PointF> c = tree_positions(7, 3, false);
    CHECK(c[0].x == doctest::Approx(0.5F));
    CHECK(c[1].x == doctest::Approx(0.5F * (c[4].x + c[6].x)));
}

TEST_CASE("heap view: a question's letters and countdown are lesson size (--questions on)") {
    HeapRenderer renderer(config_of(854, 480), test::test_backend());
    view::HeapPanelView panel = binary_panel({"X", "T", "S", "P", "L", "R", "A"}, 7);
    panel.letters = {{0, "A", false}, {2, "B", false}, {5, "C", true}};
    panel.countdown = "Think: 3";
    const view::HeapFrameView frame = frame_of({panel});
    (void)renderer.render(frame);
    const float lesson = 0.028F * 480.0F;
    for (const std::string expected : {"A", "B", "C", "Think: 3"}) {
        CAPTURE(expected);
        const auto& drawn = renderer.last_text();
        // The letter's plate text (a key "A" is drawn too: the largest of them is the node's).
        const bool found = std::any_of(drawn.begin(), drawn.end(), [&](const DrawnText& t) {
            return t.text == expected && t.cap_height >= lesson - 0.5F;
        });
        CHECK(found);
    }
    // The reveal draws the same letters; a frame without a question draws none.
    panel.reveal = true;
    panel.countdown.clear();
    (void)renderer.render(frame_of({panel}));
    const auto& shown = renderer.last_text();
    CHECK(std::count_if(shown.begin(), shown.end(),
                        [](const DrawnText& t) { return t.text == "B"; }) == 1);
    (void)renderer.render(frame_of({binary_panel({"X", "T", "S"}, 7)}));
    const auto& none = renderer.last_text();
    CHECK(std::none_of(none.begin(), none.end(),
                       [](const DrawnText& t) { return t.text == "B" || t.text == "Think: 3"; }));
}

TEST_CASE(
    "heap view: a layout-only renderer records the text a drawing one draws, frame by frame") {
    // HeapRenderer::layout_only: the tests that read only last_text (label_fit_tests.cpp,
    // algorithm_text_tests.cpp) lay thousands of frames out without drawing them. Every field
    // of every text (place, size, the shape it labels, a plate's leader) is the drawn one's,
    // over a lesson with questions (plates and leaders), an exchange, the indexed heap's map
    // and words as keys.
    const std::vector<pq::QueueKind> kinds{pq::parse_queue_kind("binary"),
                                           pq::parse_queue_kind("indexed:2")};
    show::HeapProgram lesson(
        pq::HeapRecord::operations(
            pq::parse_heap_ops("apple banana cherry * damson elder fig * grape"), kinds,
            pq::Orientation::max),
        show::heap_pacing(0.8), 1);
    lesson.ask_questions(true);
    HeapViewConfig config = config_of(854, 480);
    config.widest_key = lesson.widest_key();
    config.keys = lesson.keys();
    config.captions = lesson.captions();
    HeapRenderer drawing(config, test::test_backend());
    HeapRenderer layout = HeapRenderer::layout_only(config);
    const auto same_shape = [](const DrawnShape& a, const DrawnShape& b) {
        return a.x0 == b.x0 && a.y0 == b.y0 && a.x1 == b.x1 && a.y1 == b.y1 && a.corner == b.corner;
    };
    std::size_t texts = 0;
    std::size_t plates = 0;
    for (double t = 0.0; t <= lesson.duration(); t += 0.25) {
        CAPTURE(t);
        const view::HeapFrameView frame = lesson.frame_at(t);
        (void)drawing.render(frame);
        layout.lay_out(frame);
        const std::vector<DrawnText>& drawn = drawing.last_text();
        const std::vector<DrawnText>& laid = layout.last_text();
        REQUIRE(laid.size() == drawn.size());
        for (std::size_t i = 0; i < drawn.size(); ++i) {
            CAPTURE(drawn[i].text);
            CHECK(laid[i].text == drawn[i].text);
            CHECK(laid[i].cap_height == drawn[i].cap_height);
            CHECK(same_shape(laid[i].box, drawn[i].box));
            REQUIRE(laid[i].shape.has_value() == drawn[i].shape.has_value());
            if (drawn[i].shape) CHECK(same_shape(*laid[i].shape, *drawn[i].shape));
            CHECK(laid[i].over == drawn[i].over);
            REQUIRE(laid[i].leader.size() == drawn[i].leader.size());
            for (std::size_t k = 0; k < drawn[i].leader.size(); ++k) {
                const DrawnSegment& a = laid[i].leader[k];
                const DrawnSegment& b = drawn[i].leader[k];
                CHECK((a.x0 == b.x0 && a.y0 == b.y0 && a.x1 == b.x1 && a.y1 == b.y1));
            }
            plates += drawn[i].over ? 1 : 0;
        }
        texts += drawn.size();
    }
    CHECK(texts > 100);
    CHECK(plates > 0);  // question frames were among them
    // It has no context: drawing with it is a programmer error.
    if (!asserts_enabled) COLLIDE_SKIP_TEST("assertions are off in this build type");
    const std::string failure =
        collide::test::assertion_failure([&] { (void)layout.render(lesson.frame_at(0.0)); });
    CHECK(collide::test::contains(failure, "a renderer made with a context draws"));
}

}  // namespace collide::render
