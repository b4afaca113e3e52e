// Every label of the heap and puzzle lessons fits (#44 item 5): capitals at least 2.8 % of the
// frame height, and a key, a tile's number or a slot's index inside the slot, node or tile it
// labels, with a margin. Read from the painters' own record of what they drew (last_text: the
// text, its box and the shape it labels; the heap's frames laid out without drawing them,
// HeapRenderer::layout_only, which lays them out as a render does) at -q l, m and h, over d-ary
// heaps of arity 2 to 8 (with letters and with words as keys), three panels side by side, and 8-
// and 15-puzzles.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "collide/render/heap_view.hpp"
#include "collide/render/puzzle_view.hpp"
#include "collide/show/heap_program.hpp"
#include "collide/show/puzzle_program.hpp"
#include "collide/sim/pq/heap_record.hpp"
#include "collide/sim/pq/queue_kind.hpp"
#include "collide/sim/puzzle/search.hpp"
#include "render_fixtures.hpp"

namespace collide::render {
namespace {

constexpr float least_share = 0.028F;

struct Preset {
    const char* name;
    int width;
    int height;
    double every;  ///< seconds of video between the frames checked
};
const std::vector<Preset> presets{
    {"-q l", 854, 480, 1.5}, {"-q m", 1280, 720, 3.0}, {"-q h", 1920, 1080, 5.0}};

/// Whether `box` lies inside `shape` (a rectangle with rounded corners) with `margin` to spare.
bool inside(const DrawnShape& box, const DrawnShape& shape, float margin) {
    const float r =
        std::min({shape.corner, 0.5F * (shape.x1 - shape.x0), 0.5F * (shape.y1 - shape.y0)});
    const float xs[] = {box.x0 - margin, box.x1 + margin};
    const float ys[] = {box.y0 - margin, box.y1 + margin};
    for (const float x : xs) {
        for (const float y : ys) {
            if (x < shape.x0 || x > shape.x1 || y < shape.y0 || y > shape.y1) return false;
            // In a corner's square: within its quarter circle.
            const float cx = std::clamp(x, shape.x0 + r, shape.x1 - r);
            const float cy = std::clamp(y, shape.y0 + r, shape.y1 - r);
            if (std::hypot(x - cx, y - cy) > r + 1e-3F) return false;
        }
    }
    return true;
}

/// What of `drawn` breaks the rules, a line each; `labels` counts the text with a shape.
std::string misfits(const std::vector<DrawnText>& drawn, const Preset& p, double t, int& labels) {
    std::ostringstream out;
    const float least = least_share * static_cast<float>(p.height);
    for (const DrawnText& d : drawn) {
        const auto where = [&] {
            return std::string(p.name) + " at " + std::to_string(t) + " s: '" + d.text + "' ";
        };
        if (d.cap_height + 1e-3F < least)
            out << where() << "capitals " << d.cap_height << " px < " << least << "\n";
        if (!d.shape) continue;
        ++labels;
        // A margin of a tenth of a capital: the labels of neighbours never touch.
        if (!inside(d.box, *d.shape, 0.1F * d.cap_height)) {
            out << where() << "box [" << d.box.x0 << ", " << d.box.y0 << ", " << d.box.x1 << ", "
                << d.box.y1 << "] not inside its shape [" << d.shape->x0 << ", " << d.shape->y0
                << ", " << d.shape->x1 << ", " << d.shape->y1 << " r " << d.shape->corner << "]\n";
        }
    }
    return out.str();
}

/// Every frame of `lesson` at every preset, every `every` seconds: what does not fit.
std::string check_heap(const show::HeapProgram& lesson) {
    std::string out;
    for (const Preset& p : presets) {
        HeapViewConfig config;
        config.width = p.width;
        config.height = p.height;
        config.widest_key = lesson.widest_key();
        config.keys = lesson.keys();
        HeapRenderer renderer = HeapRenderer::layout_only(config);
        int labels = 0;
        for (double t = 0.0; t <= lesson.duration(); t += p.every) {
            renderer.lay_out(lesson.frame_at(t));
            out += misfits(renderer.last_text(), p, t, labels);
        }
        CHECK(labels > 0);  // keys and indices were found and checked
    }
    return out.size() > 4000 ? out.substr(0, 4000) + "...\n" : out;
}

show::HeapProgram heap_lesson(const char* ops, const std::string& impls) {
    std::vector<pq::QueueKind> kinds;
    for (std::size_t at = 0; at != std::string::npos;) {
        const std::size_t comma = impls.find(',', at);
        kinds.push_back(pq::parse_queue_kind(impls.substr(at, comma - at)));
        at = comma == std::string::npos ? comma : comma + 1;
    }
    return {pq::HeapRecord::operations(pq::parse_heap_ops(ops), kinds, pq::Orientation::max),
            show::heap_pacing(0.8), 1};
}

/// The renderer's configuration for `lesson` at preset `p`, as `collide heap` makes it.
HeapViewConfig lesson_config(const show::HeapProgram& lesson, const Preset& p) {
    HeapViewConfig config;
    config.width = p.width;
    config.height = p.height;
    config.widest_key = lesson.widest_key();
    config.keys = lesson.keys();
    config.captions = lesson.captions();
    return config;
}

/// Whether two tree nodes overlap: each a pill (a rectangle with round ends of radius `corner`,
/// a disc when as wide as tall), i.e. the points within `corner` of its centre line.
bool nodes_overlap(const DrawnShape& a, const DrawnShape& b) {
    const float ay = 0.5F * (a.y0 + a.y1);
    const float by = 0.5F * (b.y0 + b.y1);
    // The centre lines' horizontal gap (0 where they overlap across), and their distance.
    const float gap =
        std::max({0.0F, b.x0 + b.corner - (a.x1 - a.corner), a.x0 + a.corner - (b.x1 - b.corner)});
    return std::hypot(gap, ay - by) < a.corner + b.corner;
}

/// Whether a tree node (a pill, as above) covers part of the rectangle `box`.
bool node_covers(const DrawnShape& node, const DrawnShape& box) {
    const float y = 0.5F * (node.y0 + node.y1);
    const float dx =
        std::max({0.0F, box.x0 - (node.x1 - node.corner), node.x0 + node.corner - box.x1});
    const float dy = std::max({0.0F, box.y0 - y, y - box.y1});
    return std::hypot(dx, dy) < node.corner;
}

/// What of a heap frame's tree is squashed, a line each: two nodes that overlap, a node over
/// a slot, an index or any other text (title, counters, caption).
std::string squashed(const std::vector<DrawnText>& drawn, const std::string& where) {
    std::ostringstream out;
    std::vector<const DrawnText*> nodes;
    for (const DrawnText& d : drawn) {
        if (d.shape && d.shape->corner > 0.0F) nodes.push_back(&d);
    }
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        for (std::size_t j = i + 1; j < nodes.size(); ++j) {
            if (nodes_overlap(*nodes[i]->shape, *nodes[j]->shape)) {
                const DrawnShape& a = *nodes[i]->shape;
                const DrawnShape& b = *nodes[j]->shape;
                out << where << "nodes '" << nodes[i]->text << "' [" << a.x0 << ", " << a.y0 << ", "
                    << a.x1 << ", " << a.y1 << "] and '" << nodes[j]->text << "' [" << b.x0 << ", "
                    << b.y0 << ", " << b.x1 << ", " << b.y1 << "] overlap\n";
            }
        }
        for (const DrawnText& d : drawn) {
            if (d.shape && d.shape->corner > 0.0F) continue;
            const DrawnShape other =
                d.shape ? *d.shape : DrawnShape{d.box.x0, d.box.y0, d.box.x1, d.box.y1};
            if (node_covers(*nodes[i]->shape, other)) {
                out << where << "node '" << nodes[i]->text << "' [" << nodes[i]->shape->x0 << ", "
                    << nodes[i]->shape->y0 << ", " << nodes[i]->shape->x1 << ", "
                    << nodes[i]->shape->y1 << "] covers '" << d.text << "' [" << other.x0 << ", "
                    << other.y0 << ", " << other.x1 << ", " << other.y1 << "]\n";
            }
        }
    }
    return out.str();
}

/// What a plate laid over the picture (a question's letter, DrawnText::over) covers, a line
/// each: another plate, or any other text or the slot or cell it labels (nodes: squashed).
std::string plates_cover(const std::vector<DrawnText>& drawn, const std::string& where) {
    std::ostringstream out;
    const auto overlap = [](const DrawnShape& a, const DrawnShape& b) {
        return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
    };
    for (std::size_t i = 0; i < drawn.size(); ++i) {
        if (!drawn[i].over || !drawn[i].shape) continue;
        const DrawnShape& plate = *drawn[i].shape;
        for (std::size_t j = 0; j < drawn.size(); ++j) {
            const DrawnText& d = drawn[j];
            if (j == i || (d.shape && d.shape->corner > 0.0F)) continue;
            const DrawnShape other = d.shape ? *d.shape : d.box;
            if (overlap(plate, other)) {
                out << where << "plate '" << drawn[i].text << "' [" << plate.x0 << ", " << plate.y0
                    << ", " << plate.x1 << ", " << plate.y1 << "] covers '" << d.text << "' ["
                    << other.x0 << ", " << other.y0 << ", " << other.x1 << ", " << other.y1
                    << "]\n";
            }
        }
    }
    return out.str();
}

/// How far the point (x, y) lies from a tree node (a pill, as above): 0 inside its outline.
float outside_node(const DrawnShape& node, float x, float y) {
    const float cy = 0.5F * (node.y0 + node.y1);
    const float cx = std::clamp(x, node.x0 + node.corner, node.x1 - node.corner);
    return std::max(0.0F, std::hypot(x - cx, y - cy) - node.corner);
}

/// The leaders of a frame's question plates that pass through a node other than their own (the
/// node nearest the leader's start), a line each.
std::string leaders_cross(const std::vector<DrawnText>& drawn, const std::string& where) {
    std::ostringstream out;
    std::vector<const DrawnText*> nodes;
    for (const DrawnText& d : drawn) {
        if (d.shape && d.shape->corner > 0.0F) nodes.push_back(&d);
    }
    for (const DrawnText& d : drawn) {
        if (d.leader.empty() || nodes.empty()) continue;
        const DrawnSegment& start = d.leader.front();
        const auto own = std::min_element(nodes.begin(), nodes.end(), [&](auto* a, auto* b) {
            return outside_node(*a->shape, start.x0, start.y0) <
                   outside_node(*b->shape, start.x0, start.y0);
        });
        for (const DrawnSegment& l : d.leader) {
            const float length = std::hypot(l.x1 - l.x0, l.y1 - l.y0);
            const int steps = std::max(1, static_cast<int>(length / 0.5F));
            for (const DrawnText* n : nodes) {
                if (n == *own) continue;
                for (int k = 0; k <= steps; ++k) {
                    const float t = static_cast<float>(k) / static_cast<float>(steps);
                    const float x = l.x0 + t * (l.x1 - l.x0);
                    const float y = l.y0 + t * (l.y1 - l.y0);
                    if (outside_node(*n->shape, x, y) <= 0.0F) {
                        out << where << "the leader of plate '" << d.text << "' [" << l.x0 << ", "
                            << l.y0 << " to " << l.x1 << ", " << l.y1 << "] crosses node '"
                            << n->text << "'\n";
                        break;
                    }
                }
            }
        }
    }
    return out.str();
}

}  // namespace

/// Whether `collide heap` draws `lesson` at preset `p` (it refuses what HeapRenderer::fits
/// rejects, judged on the frames at the lesson's fit_check_times).
bool lesson_fits(const show::HeapProgram& lesson, const Preset& p) {
    const HeapViewConfig config = lesson_config(lesson, p);
    const std::vector<double> times = lesson.fit_check_times();
    return std::all_of(times.begin(), times.end(),
                       [&](double t) { return HeapRenderer::fits(config, lesson.frame_at(t)); });
}

/// What is wrong in the frames at rest of `lesson` at preset `p`, sampled every `step` seconds:
/// text out of its shape or under size, nodes squashed. A frame with an exchange under way is
/// skipped (its two keys pass each other by design). Counts the frames checked and the labels.
struct RestCheck {
    std::string bad;
    int labels = 0;
    int frames = 0;
};

RestCheck check_frames_at_rest(const show::HeapProgram& lesson, const Preset& p, double step) {
    HeapRenderer renderer = HeapRenderer::layout_only(lesson_config(lesson, p));
    RestCheck check;
    for (double t = 0.0; t <= lesson.duration(); t += step) {
        const view::HeapFrameView frame = lesson.frame_at(t);
        if (std::any_of(frame.panels.begin(), frame.panels.end(),
                        [](const view::HeapPanelView& v) { return v.swap; }))
            continue;
        renderer.lay_out(frame);
        check.bad += misfits(renderer.last_text(), p, t, check.labels);
        check.bad += squashed(renderer.last_text(),
                              std::string(p.name) + " at " + std::to_string(t) + " s: ");
        ++check.frames;
    }
    if (check.bad.size() > 4000) check.bad = check.bad.substr(0, 4000) + "...\n";
    return check;
}

/// A lesson of `ops` on the panels `impl`, and whether `collide heap` draws it.
struct FitCase {
    const char* ops;
    std::string impl;
    bool fits;  ///< drawn (else refused, at -q l and -q m alike)
};

/// Each case at -q l and -q m: refused or drawn as it says, and where drawn, every frame at rest
/// (sampled every `step` seconds) without a misfit; `on_drawn` adds the case's own checks.
template <class OnDrawn>
void check_fit_cases(const std::vector<FitCase>& cases, double step, OnDrawn on_drawn) {
    for (const FitCase& c : cases) {
        CAPTURE(c.ops);
        CAPTURE(c.impl);
        const show::HeapProgram lesson = heap_lesson(c.ops, c.impl);
        for (const Preset& p : {presets[0], presets[1]}) {
            CAPTURE(p.name);
            CHECK(lesson_fits(lesson, p) == c.fits);
            if (!c.fits) continue;
            const RestCheck check = check_frames_at_rest(lesson, p, step);
            on_drawn(check);
            CHECK_MESSAGE(check.bad.empty(), check.bad);
        }
    }
}

// In the doctest suite `sweep` (tests/CMakeLists.txt): the sanitized builds run this file's other
// cases, which go through the same checks and layouts (check_fit_cases: the word keys' case;
// the indexed heap's map: the three heaps' case); the full build runs this one too.
TEST_CASE(
    "heap trees never squash: 1 to 3 heaps of 11 and 15 keys, indexed among them, -q l and -q m" *
    doctest::test_suite("sweep")) {
    // Issue 44: three heaps side by side with 11 keys at -q l overlapped their nodes, with
    // caption lines reserved that no caption used. Every frame at rest (no exchange under way:
    // the two keys of an exchange pass each other by design) of a lesson that fills the heaps.
    // The indexed heap's map (keys[i] / qp[i]) shares its panel with the tree: beside two other
    // heaps with 11 keys, or beside one with 15, the trees and the map needed ~914 px of 816 at
    // -q l and were drawn squashed; `collide heap` refuses them now (HeapRenderer::fits), and
    // draws the most keys that fit, which are checked here.
    const char* seven = "P Q E X A M L * *";
    const char* eight = "P Q E X A M L S * *";
    const char* eleven = "P Q E X A M L S O R T * *";
    const char* fourteen = "P Q E X A M L S O R T Y U I * *";
    const char* fifteen = "P Q E X A M L S O R T Y U I N * *";
    const std::vector<FitCase> cases{
        {eleven, "binary", true},
        {eleven, "binary,dary:3", true},
        {eleven, "binary,dary:3,dary:4", true},
        {eleven, "indexed", true},
        {eleven, "indexed:2", true},
        {eleven, "binary,indexed", true},
        {eleven, "indexed:3,dary:4", true},
        {eleven, "indexed,binary", true},
        {fifteen, "binary", true},
        {fifteen, "binary,dary:3", true},
        {fifteen, "indexed", true},
        {fifteen, "indexed:2", true},
        // The indexed heap beside two others: at most 8 keys (7 with two indexed heaps).
        {eleven, "binary,dary:3,indexed", false},
        {eight, "binary,dary:3,indexed", true},
        {eleven, "indexed,indexed:3,binary", false},
        {eight, "indexed,indexed:3,binary", false},
        {seven, "indexed,indexed:3,binary", true},
        {eleven, "dary:4,indexed:2,binary", false},
        {seven, "dary:4,indexed:2,binary", true},
        // Beside one other heap: at most 14 keys.
        {fifteen, "indexed,binary", false},
        {fourteen, "indexed,binary", true},
        {fifteen, "binary,indexed:3", false},
        {fourteen, "binary,indexed:3", true}};
    check_fit_cases(cases, 0.2, [](const RestCheck& check) { CHECK(check.frames > 10); });
}

TEST_CASE("heap word keys in two panels: drawn inside their nodes where they fit, else refused") {
    // Issue 44: words as keys in two heaps side by side spilled out of their nodes. Where the
    // trees hold every word inside its node at the lesson size the lesson is drawn (and checked
    // frame by frame); where they cannot, `collide heap` refuses it (HeapRenderer::fits).
    const std::vector<FitCase> cases{
        {"apple banana cherry damson elder fig * *", "binary,dary:4", true},
        {"apple banana cherry damson elder fig grape hazel iris * kiwi *", "binary,dary:4", false},
        {"apple banana cherry damson elder * *", "binary,binary", true},
        {"apple banana cherry damson elder fig grape hazel * *", "dary:3,binary", false}};
    check_fit_cases(cases, 0.3, [](const RestCheck& check) { CHECK(check.labels > 0); });
}

TEST_CASE(
    "heap questions: letter plates and the countdown cover no node, key or plate, 1 to 3 "
    "panels, -q l and m") {
    // Issue 45: `collide heap --questions on` put letter plates on word keys' pill-shaped nodes
    // (the free-place check knew only the radius) and its countdown on a top node; with two or
    // three heaps side by side the trees left no free place beside a node and the plates sat on
    // nodes. Every frame of a question and its reveal, letters and words, 1 to 3 panels (the
    // indexed heap among them): plates cover no node, no text, no slot and no other plate, and
    // their letters are at least 2.8 % of the frame high, inside their plates. A plate's leader
    // passes through no node but its own (it crossed one where a crowded tree left no straight
    // way: it bends round them now).
    const std::vector<std::pair<std::string, std::string>> lessons{
        {"P Q E X A M L S * *", "binary"},
        {"apple banana cherry damson elder fig grape * *", "binary"},
        {"apple banana cherry damson elder fig grape hazel * *", "dary:4"},
        {"P Q E X A M L S * *", "binary,dary:3"},
        {"P Q E X A M L S O R T * *", "binary,dary:3,dary:4"},
        {"P Q E * X A M * P L E *", "binary,dary:3,indexed"},
        {"P Q E X A M L S O R * *", "indexed,binary"},
        {"P Q E X A M L S * *", "binary,dary:3,indexed"},
        {"apple banana cherry damson elder fig * *", "binary,dary:4"}};
    std::ptrdiff_t total_leaders = 0;  // the leaders' test saw some (crowded trees have them)
    for (const auto& [ops, impl] : lessons) {
        CAPTURE(ops);
        CAPTURE(impl);
        show::HeapProgram lesson = heap_lesson(ops.c_str(), impl);
        lesson.ask_questions(true);
        REQUIRE_FALSE(lesson.questions().empty());
        for (const Preset& p : {presets[0], presets[1]}) {
            HeapRenderer renderer = HeapRenderer::layout_only(lesson_config(lesson, p));
            std::string bad;
            int asked = 0;
            int labels = 0;
            std::ptrdiff_t leaders = 0;  // plates on a leader, in this lesson
            for (double t = 0.0; t <= lesson.duration(); t += 0.1) {
                const view::HeapFrameView frame = lesson.frame_at(t);
                const bool question =
                    std::any_of(frame.panels.begin(), frame.panels.end(),
                                [](const view::HeapPanelView& v) { return !v.letters.empty(); });
                // An exchange under way moves its two keys along their edge, over whatever lies
                // there, by design (as in the test above).
                const bool moving =
                    std::any_of(frame.panels.begin(), frame.panels.end(),
                                [](const view::HeapPanelView& v) { return v.swap; });
                if (!question || moving) continue;
                renderer.lay_out(frame);
                const std::string where = std::string(p.name) + " at " + std::to_string(t) + " s: ";
                bad += squashed(renderer.last_text(), where);
                bad += plates_cover(renderer.last_text(), where);
                bad += leaders_cross(renderer.last_text(), where);
                leaders += std::count_if(renderer.last_text().begin(), renderer.last_text().end(),
                                         [](const DrawnText& d) { return !d.leader.empty(); });
                bad += misfits(renderer.last_text(), p, t, labels);
                // Every letter and countdown drawn, on its plate.
                std::size_t letters = 0;
                for (const view::HeapPanelView& v : frame.panels)
                    letters += v.letters.size() + (v.countdown.empty() ? 0 : 1);
                const auto plates =
                    std::count_if(renderer.last_text().begin(), renderer.last_text().end(),
                                  [](const DrawnText& d) { return d.over; });
                CHECK_MESSAGE(static_cast<std::size_t>(plates) == letters,
                              where << plates << " plates for " << letters << " letters");
                ++asked;
            }
            CHECK(asked > 5);
            total_leaders += leaders;
            if (bad.size() > 4000) bad = bad.substr(0, 4000) + "...\n";
            CHECK_MESSAGE(bad.empty(), bad);
        }
    }
    CHECK(total_leaders > 100);
}

TEST_CASE("labels fit: d-ary heaps of arity 2 to 8, letters and words, at -q l, m and h") {
    // Ten keys at once (slot indices of two digits), then words as keys.
    const char* letters = "P Q E X A M * P L E S O * R T";
    const char* words = "apple banana cherry damson elder fig grape hazel iris * kiwi *";
    for (int arity = 2; arity <= 8; ++arity) {
        const std::string impl = arity == 2 ? "binary" : "dary:" + std::to_string(arity);
        CAPTURE(impl);
        const std::string small = check_heap(heap_lesson(letters, impl));
        CHECK_MESSAGE(small.empty(), impl << ", letters:\n" << small);
        const std::string wide = check_heap(heap_lesson(words, impl));
        CHECK_MESSAGE(wide.empty(), impl << ", words:\n" << wide);
    }
}

TEST_CASE("labels fit: three heaps side by side, and the indexed heap's map") {
    const std::string three =
        check_heap(heap_lesson("P Q E X A M * P L E S O * R T", "unordered,ordered,binary"));
    CHECK_MESSAGE(three.empty(), three);
    const std::string words =
        check_heap(heap_lesson("apple banana cherry damson * elder", "unordered,ordered,binary"));
    CHECK_MESSAGE(words.empty(), words);
    const std::string indexed = check_heap(heap_lesson("5 9 3 7 * 3^12", "indexed:2"));
    CHECK_MESSAGE(indexed.empty(), indexed);
}

TEST_CASE("labels fit: 8- and 15-puzzle tiles, one method and two, at -q l, m and h") {
    // A 15-puzzle a dozen moves from the goal (two-digit tiles side by side) and an 8-puzzle.
    for (const char* board : {"1 2 7 3 5 6 11 4 9 10 12 15 13 14 8 0", "8 1 3 4 0 2 7 6 5"}) {
        CAPTURE(board);
        const puzzle::Board start = puzzle::Board::parse(board);
        const std::vector<puzzle::SearchResult> results{
            puzzle::breadth_first(start),
            puzzle::a_star(start, puzzle::Heuristic::manhattan, {pq::QueueFamily::binary, 2})};
        for (const std::size_t methods : {std::size_t{2}, std::size_t{1}}) {
            for (const bool code : {false, true}) {
                if (code && methods == 2) continue;  // the code goes beside one search
                const std::vector<puzzle::SearchResult> shown(results.end() - methods,
                                                              results.end());
                const show::PuzzleProgram lesson(start, shown, code);
                for (const Preset& p : presets) {
                    PuzzleViewConfig config;
                    config.width = p.width;
                    config.height = p.height;
                    PuzzleRenderer renderer(config, test::test_backend());
                    Image image;
                    std::string bad;
                    int labels = 0;
                    for (double t = 0.0; t <= lesson.duration(); t += 1.5 * p.every) {
                        renderer.render(lesson.frame_at(t), image);
                        bad += misfits(renderer.last_text(), p, t, labels);
                    }
                    CHECK(labels > 0);
                    if (bad.size() > 4000) bad = bad.substr(0, 4000) + "...\n";
                    CHECK_MESSAGE(bad.empty(), methods << " method(s)" << (code ? ", code" : "")
                                                       << ":\n"
                                                       << bad);
                }
            }
        }
    }
}

}  // namespace collide::render
