// Every word of the heap and puzzle lessons is legible from the back of a hall (#28 item 7):
// capitals at least 2.8 % of the frame height, as in the collision video. Checked on the
// painters' own record of the text they drew (last_text; the heap's frames laid out without
// drawing them, HeapRenderer::layout_only) over the frames of the lessons of
// docs/heap.md and of the puzzle, at -q l (854x480) and -q m (1280x720).
#include <doctest/doctest.h>

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

constexpr float lesson_share = 0.028F;

struct Frame {
    int width;
    int height;
    double every;  ///< seconds of video between the frames checked
};
// -q l and -q m (fewer frames at 720p: its layout is the same, scaled).
const std::vector<Frame> frames{{854, 480, 1.0}, {1280, 720, 2.5}};

/// The text of `drawn` smaller than the lesson size, as "'text' 12.3 px" lines.
std::string too_small(const std::vector<DrawnText>& drawn, int height, double t) {
    std::string out;
    const float least = lesson_share * static_cast<float>(height);
    for (const DrawnText& d : drawn) {
        if (d.cap_height + 1e-3F < least) {
            out += "  at " + std::to_string(t) + " s, " + std::to_string(height) + "p: '" + d.text +
                   "' capitals " + std::to_string(d.cap_height) + " px < " + std::to_string(least) +
                   "\n";
        }
    }
    return out;
}

std::string check_heap(const show::HeapProgram& lesson) {
    std::string out;
    for (const Frame& f : frames) {
        HeapViewConfig config;
        config.width = f.width;
        config.height = f.height;
        config.widest_key = lesson.widest_key();
        if (lesson.shows_code()) config.code_lines = lesson.code_lines();
        HeapRenderer renderer = HeapRenderer::layout_only(config);
        for (double t = 0.0; t <= lesson.duration(); t += f.every) {
            renderer.lay_out(lesson.frame_at(t));
            REQUIRE_FALSE(renderer.last_text().empty());
            out += too_small(renderer.last_text(), f.height, t);
        }
    }
    return out;
}

show::HeapProgram heap_program(const char* ops, const char* impls,
                               pq::Orientation orientation = pq::Orientation::max) {
    std::vector<pq::QueueKind> kinds;
    std::string list = impls;
    for (std::size_t at = 0; at != std::string::npos;) {
        const std::size_t comma = list.find(',', at);
        kinds.push_back(pq::parse_queue_kind(list.substr(at, comma - at)));
        at = comma == std::string::npos ? comma : comma + 1;
    }
    return {pq::HeapRecord::operations(pq::parse_heap_ops(ops), kinds, orientation),
            show::heap_pacing(0.8), 1};
}

}  // namespace

TEST_CASE("lesson text: the heap lessons of docs/heap.md write nothing under 2.8 % capitals") {
    const char* trace = "P Q E * X A M * P L E *";
    CHECK_MESSAGE(check_heap(heap_program(trace, "unordered,ordered")).empty(), "arrays");
    const std::string heap = check_heap(heap_program(trace, "binary"));
    CHECK_MESSAGE(heap.empty(), heap);
    CHECK(check_heap(heap_program("T P R N H O A E I G S", "binary")).empty());
    const std::string analysis = check_heap(heap_program(trace, "unordered,ordered,binary"));
    CHECK_MESSAGE(analysis.empty(), analysis);
    CHECK(check_heap(heap_program(trace, "dary:3")).empty());
    const std::string dary =
        check_heap(heap_program(trace, "binary,dary:3,dary:4", pq::Orientation::min));
    CHECK_MESSAGE(dary.empty(), dary);
    const std::string indexed = check_heap(heap_program("5 9 3 7 * 3^12", "indexed:2"));
    CHECK_MESSAGE(indexed.empty(), indexed);
    const std::string sort = check_heap(
        show::HeapProgram(pq::HeapRecord::heapsort(pq::parse_sort_keys("S O R T E X A M P L E"),
                                                   pq::Orientation::max),
                          show::heap_pacing(0.8), 1));
    CHECK_MESSAGE(sort.empty(), sort);
}

TEST_CASE("lesson text: heap --code's listings are lesson text, and every line fits its column") {
    const auto with_code = [](show::HeapProgram lesson) {
        lesson.show_code(true);
        return lesson;
    };
    const char* trace = "P Q E * X A M * P L E *";
    const std::string heap = check_heap(with_code(heap_program(trace, "binary")));
    CHECK_MESSAGE(heap.empty(), heap);
    const std::string dary = check_heap(
        with_code(heap_program("T P R N H O A E I G S * *", "dary:3", pq::Orientation::min)));
    CHECK_MESSAGE(dary.empty(), dary);
    const std::string up = check_heap(with_code(heap_program("5 9 3 7 * 3^12", "indexed:2")));
    CHECK_MESSAGE(up.empty(), up);
    const std::string down =
        check_heap(with_code(heap_program("1 5 3 9 7 1^8", "indexed:2", pq::Orientation::min)));
    CHECK_MESSAGE(down.empty(), down);
    for (const pq::Orientation o : {pq::Orientation::max, pq::Orientation::min}) {
        const show::HeapProgram sort = with_code(show::HeapProgram(
            pq::HeapRecord::heapsort(pq::parse_sort_keys("S O R T E X A M P L E"), o),
            show::heap_pacing(0.8), 1));
        const std::string small = check_heap(sort);
        CHECK_MESSAGE(small.empty(), small);
    }
    // No line of any listing is cut ("..."): each fits the code column at -q l and -q m.
    for (const Frame& f : frames) {
        const show::HeapProgram lessons[] = {
            with_code(heap_program(trace, "binary")),
            with_code(heap_program("1 5 3 9 7 1^8", "indexed:2", pq::Orientation::min)),
            with_code(show::HeapProgram(
                pq::HeapRecord::heapsort(pq::parse_sort_keys("S O R T E X A M P L E"),
                                         pq::Orientation::min),
                show::heap_pacing(0.8), 1))};
        for (const show::HeapProgram& lesson : lessons) {
            HeapViewConfig config;
            config.width = f.width;
            config.height = f.height;
            config.code_lines = lesson.code_lines();
            HeapRenderer renderer = HeapRenderer::layout_only(config);
            for (double t = 0.0; t <= lesson.duration(); t += 4.0) {
                const view::HeapFrameView frame = lesson.frame_at(t);
                renderer.lay_out(frame);
                REQUIRE(frame.code);
                for (const view::CodeLineView& line : frame.code->lines) {
                    bool drawn_whole = false;
                    for (const DrawnText& d : renderer.last_text())
                        drawn_whole |= d.text == line.text;
                    CHECK_MESSAGE(drawn_whole, f.height << "p: '" << line.text << "' was cut");
                }
            }
        }
    }
}

TEST_CASE("lesson text: the puzzle writes nothing under 2.8 % capitals, digits and labels too") {
    for (const char* board : {"8 1 3 4 0 2 7 6 5", "8 6 7 2 5 4 3 0 1"}) {
        const puzzle::Board start = puzzle::Board::parse(board);
        const std::vector<puzzle::SearchResult> results{
            puzzle::breadth_first(start),
            puzzle::a_star(start, puzzle::Heuristic::manhattan, {pq::QueueFamily::binary, 2})};
        for (std::size_t methods : {std::size_t{2}, std::size_t{1}}) {
            const std::vector<puzzle::SearchResult> shown(results.end() - methods, results.end());
            const show::PuzzleProgram lesson(start, shown);
            for (const Frame& f : frames) {
                PuzzleViewConfig config;
                config.width = f.width;
                config.height = f.height;
                PuzzleRenderer renderer(config, test::test_backend());
                Image image;
                std::string small;
                for (double t = 0.0; t <= lesson.duration(); t += 2.0 * f.every) {
                    renderer.render(lesson.frame_at(t), image);
                    REQUIRE_FALSE(renderer.last_text().empty());
                    small += too_small(renderer.last_text(), f.height, t);
                }
                CHECK_MESSAGE(small.empty(), board << ", " << methods << " method(s):\n" << small);
            }
        }
    }
}

TEST_CASE("lesson text: puzzle --code's listing and its title are lesson text and drawn whole") {
    const puzzle::Board start = puzzle::Board::parse("5 2 8 1 0 4 7 6 3");
    for (const bool bfs : {false, true}) {
        const std::vector<puzzle::SearchResult> results{
            bfs ? puzzle::breadth_first(start)
                : puzzle::a_star(start, puzzle::Heuristic::manhattan,
                                 {pq::QueueFamily::binary, 2})};
        const show::PuzzleProgram lesson(start, results, true);
        for (const Frame& f : frames) {
            PuzzleViewConfig config;
            config.width = f.width;
            config.height = f.height;
            PuzzleRenderer renderer(config, test::test_backend());
            Image image;
            std::string small;
            for (double t = 0.0; t <= lesson.duration(); t += f.every) {
                const view::PuzzleFrameView frame = lesson.frame_at(t);
                REQUIRE(frame.code);
                renderer.render(frame, image);
                small += too_small(renderer.last_text(), f.height, t);
                // No line of the listing, nor its title, is cut ("..."): each fits its column.
                std::vector<std::string> whole{frame.code->title};
                for (const view::CodeLineView& line : frame.code->lines) whole.push_back(line.text);
                for (const std::string& text : whole) {
                    bool drawn_whole = false;
                    for (const DrawnText& d : renderer.last_text()) drawn_whole |= d.text == text;
                    CHECK_MESSAGE(drawn_whole, f.height << "p: '" << text << "' was cut");
                }
            }
            CHECK_MESSAGE(small.empty(), (bfs ? "BFS" : "A*") << " with code:\n" << small);
        }
    }
}

}  // namespace collide::render
