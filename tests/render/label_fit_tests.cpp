// Every label of the heap and puzzle lessons fits (#44 item 5): capitals at least 2.8 % of the
// frame height, and a key, a tile's number or a slot's index inside the slot, node or tile it
// labels, with a margin. Read from the painters' own record of what they drew (last_text: the
// text, its box and the shape it labels) at -q l, m and h, over d-ary heaps of arity 2 to 8 (with
// letters and with words as keys), three panels side by side, and 8- and 15-puzzles.
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
        HeapRenderer renderer(config, test::test_backend());
        Image image;
        int labels = 0;
        for (double t = 0.0; t <= lesson.duration(); t += p.every) {
            renderer.render(lesson.frame_at(t), image);
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

}  // namespace

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
