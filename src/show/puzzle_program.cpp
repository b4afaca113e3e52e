#include "collide/show/puzzle_program.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "collide/error.hpp"
#include "collide/show/ease.hpp"
#include "collide/show/heap_program.hpp"
#include "collide/show/questions.hpp"

namespace collide::show {

namespace {

using puzzle::Method;
using puzzle::SearchResult;
using view::PuzzleMark;

/// Fraction of a move's time the tile takes to slide; the rest holds still.
constexpr double slide_part = 0.7;

std::string plural(std::size_t n, const char* word) {
    return with_thousands(n) + " " + word + (n == 1 ? "" : "s");
}

std::string puzzle_name(int side) {
    return std::to_string(side * side - 1) + "-puzzle";
}

/// "Manhattan distance", "Hamming distance": the lecture's names for the estimates.
std::string estimate_words(puzzle::Heuristic h) {
    std::string name(puzzle::to_string(h));
    if (!name.empty()) name[0] = static_cast<char>(name[0] - 'a' + 'A');
    return name + " distance";
}

/// The queue's front while expansion `k` of `r` is under way: before its board left (that
/// board first), or after (`popped`), but before its neighbours went in; `size` receives the
/// queue's length then. Stale entries taken out just before expansion k have gone already.
std::vector<std::uint32_t> queue_during(const SearchResult& r, std::size_t k, bool popped,
                                        std::size_t shown, std::size_t& size) {
    std::size_t gone = 0;  // stale entries taken out before expansion k
    for (const puzzle::SearchNode& n : r.nodes) gone += n.stale && n.popped == k ? 1 : 0;
    std::vector<std::uint32_t> front = r.queue_front(k, shown + gone + 1);
    std::erase_if(front, [&](std::uint32_t id) {
        const puzzle::SearchNode& n = r.nodes[id];
        return (n.stale && n.popped == k) || (popped && id == r.expansions[k]);
    });
    size = r.queue_size(k) - gone - (popped ? 1 : 0);
    if (front.size() > shown) front.resize(shown);
    return front;
}

/// How many entries of the ascending list `indices` are below `step`.
std::size_t count_below(const std::vector<std::uint32_t>& indices, std::size_t step) {
    return static_cast<std::size_t>(std::lower_bound(indices.begin(), indices.end(), step) -
                                    indices.begin());
}

}  // namespace

std::string with_thousands(std::uint64_t n) {
    const std::string digits = std::to_string(n);
    std::string out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

PuzzleProgram::PuzzleProgram(const puzzle::Board& start, const std::vector<SearchResult>& results,
                             bool code)
    : start_(start), code_(code), shown_(view::puzzle_shown(start.side(), results.size(), code)) {
    if (results.empty() || results.size() > 2)
        throw_runtime_error("puzzle video: needs one or two searches");
    if (code && results.size() != 1)
        throw_runtime_error("puzzle video: the code goes beside one search");
    for (const SearchResult& r : results) {
        if (!r.solved()) throw_runtime_error("puzzle video: a search without a solution");
        Side side;
        side.result = &r;
        side.deepest.push_back(0);
        for (std::size_t k = 0; k < r.expansions.size(); ++k) {
            const std::uint16_t depth = r.nodes[r.expansions[k]].moves;
            if (side.by_depth.size() <= depth) side.by_depth.resize(depth + 1U);
            side.by_depth[depth].push_back(static_cast<std::uint32_t>(k));
            side.deepest.push_back(std::max(side.deepest.back(), depth));
        }
        side.path = r.solution_path();
        most_expansions_ = std::max(most_expansions_, r.expansions.size());
        longest_solution_ = std::max(longest_solution_, side.path.size() - 1);
        sides_.push_back(std::move(side));
    }
    // About 3 s for a handful of boards, 13 s for the 180,000 of a hardest 8-puzzle's BFS.
    search_seconds_ =
        std::min(16.0, 3.0 + 2.0 * std::log10(static_cast<double>(most_expansions_) + 1.0));
    // The solutions play one after the other, each from its own start.
    double t = 0.0;
    for (const Side& side : sides_) {
        turns_.push_back(t);
        t += per_move_ * static_cast<double>(side.path.size() - 1) + between_;
    }
    playback_length_ = t - between_;
    if (code_) pace_code();
}

void PuzzleProgram::pace_code() {
    const SearchResult& r = *sides_.front().result;
    const std::size_t total = r.expansions.size();  // >= 1: the goal's expansion is the last
    double t = intro_;
    const auto walk = [&](std::size_t k) {
        for (const SearchLine line : search_walk(r, k)) {
            beats_.push_back({t, k, line});
            t += search_line_seconds;
        }
    };
    fast_from_ = std::min(walked_expansions, total - 1);
    for (std::size_t k = 0; k < fast_from_; ++k) walk(k);
    fast_start_ = t;
    fast_count_ = total - 1 - fast_from_;
    // The fast middle grows as the search without code does, a little shorter: the walks
    // already take their time.
    fast_seconds_ =
        fast_count_ == 0
            ? 0.0
            : std::min(12.0, 2.0 + 2.0 * std::log10(static_cast<double>(fast_count_) + 1.0));
    t += fast_seconds_;
    walk(total - 1);
    search_seconds_ = t - intro_;
}

PuzzleProgram::CodeMoment PuzzleProgram::code_at(double seconds) const {
    const std::size_t total = sides_.front().result->expansions.size();
    if (seconds >= playback_start()) return {total, std::nullopt, QueueMoment::after};
    // Finished: the goal has left the queue and the search stops there.
    if (seconds >= search_end()) return {total, SearchLine::goal, QueueMoment::popped};
    if (seconds < search_start()) return {0, SearchLine::start, QueueMoment::after};
    if (seconds >= fast_start_ && seconds < fast_start_ + fast_seconds_) {
        const double u = (seconds - fast_start_) / fast_seconds_;
        const double grown = std::floor(std::pow(static_cast<double>(fast_count_) + 1.0, u) - 1.0);
        const std::size_t added =
            std::min(fast_count_, static_cast<std::size_t>(std::max(0.0, grown)));
        return {fast_from_ + added, SearchLine::loop, QueueMoment::after};
    }
    const auto later = std::upper_bound(beats_.begin(), beats_.end(), seconds,
                                        [](double s, const Beat& b) { return s < b.start; });
    const Beat& beat = *std::prev(later);  // beats_ starts at search_start()
    QueueMoment queue = QueueMoment::popped;
    if (beat.line == SearchLine::pop) queue = QueueMoment::before_pop;
    if (beat.line == SearchLine::insert) queue = QueueMoment::after;
    return {beat.expansion + 1, beat.line, queue};
}

double PuzzleProgram::playback_start() const noexcept {
    return search_end() + pause_;
}

double PuzzleProgram::playback_turn(std::size_t i) const noexcept {
    return playback_start() + turns_[i];
}

double PuzzleProgram::duration() const noexcept {
    double asked = 0.0;
    for (const PuzzleQuestion& q : questions_) asked += q.seconds();
    return playback_start() + playback_length_ + outro_ + asked;
}

namespace {

/// Expansions a question may wait for: the first ones, which the video shows one by one.
constexpr std::size_t question_steps = 40;
/// Seconds a class looks at the two boards' labels before the answer.
constexpr double puzzle_think_seconds = 4.0;

}  // namespace

std::optional<PuzzleQuestion> PuzzleProgram::question_for(std::size_t i) const {
    const SearchResult& r = *sides_[i].result;
    if (r.method != Method::astar) return std::nullopt;
    const std::size_t last = std::min(question_steps, r.expansions.size() - 1);
    for (std::size_t step = 1; step <= last; ++step) {
        // The answer is the search's own next expansion; the other board is one at the queue's
        // front that the rule "lowest moves + estimate first" puts after it.
        const std::uint32_t next = r.expansions[step];
        const puzzle::SearchNode& answer = r.nodes[next];
        std::optional<std::uint32_t> other;
        for (const std::uint32_t id : r.queue_front(step, 8)) {
            const puzzle::SearchNode& n = r.nodes[id];
            if (id == next || n.stale || n.board == answer.board) continue;
            if (n.priority > answer.priority) {
                other = id;
                break;
            }
        }
        if (!other) continue;
        // The lesson's time at which the frame shows `step` expansions, the queue after them.
        double at = search_start();
        const double tick = 1.0 / 600.0;
        while (at < search_end()) {
            const bool there =
                code_ ? code_at(at).shown == step && code_at(at).queue == QueueMoment::after
                      : step_at(i, at) == step;
            if (there) break;
            at += tick;
        }
        if (!(at < search_end())) continue;
        PuzzleQuestion q;
        q.panel = i;
        q.step = step;
        // Which letter the answer gets: by the step, never always A.
        const bool first = (step * 2654435761U + i) % 2 == 0;
        q.candidates = first ? std::vector<std::uint32_t>{next, *other}
                             : std::vector<std::uint32_t>{*other, next};
        q.answer = first ? 0 : 1;
        q.lesson_at = at;
        q.think = std::max(min_think_seconds, puzzle_think_seconds);
        q.reveal = reveal_seconds;
        q.question = "Which board does A* expand next: A or B?";
        q.answer_words = "Answer: " + candidate_letter(q.answer) + ", " +
                         std::to_string(answer.moves) + "+" +
                         std::to_string(answer.priority - answer.moves) + "=" +
                         std::to_string(answer.priority) + ": the lowest moves + estimate";
        return q;
    }
    return std::nullopt;
}

void PuzzleProgram::ask_questions(bool on) {
    questions_.clear();
    if (!on) return;
    for (std::size_t i = 0; i < sides_.size(); ++i) {
        if (std::optional<PuzzleQuestion> q = question_for(i)) questions_.push_back(std::move(*q));
    }
    std::sort(
        questions_.begin(), questions_.end(),
        [](const PuzzleQuestion& a, const PuzzleQuestion& b) { return a.lesson_at < b.lesson_at; });
}

double PuzzleProgram::question_start(std::size_t q) const {
    double before = 0.0;
    for (std::size_t k = 0; k < q; ++k) before += questions_.at(k).seconds();
    return questions_.at(q).lesson_at + before;
}

void PuzzleProgram::pose(const PuzzleQuestion& q, bool reveal, double left,
                         view::PuzzleFrameView& view) const {
    view::PuzzlePanelView& p = view.panels[q.panel];
    const Side& side = sides_[q.panel];
    p.queue.clear();
    for (std::size_t c = 0; c < q.candidates.size(); ++c) {
        view::PuzzleBoardView b = board_view(side, q.candidates[c]);
        b.label = candidate_letter(c) + ": " + b.label;
        if (reveal && c == q.answer) b.mark = PuzzleMark::current;
        p.queue.push_back(std::move(b));
    }
    // Short lines: the status and the queue's column are narrow at the lesson's text size (the
    // whole words are the caption: the subtitles and chapters).
    p.queue_title = "next out?";
    p.queue_more = reveal ? "Answer: " + candidate_letter(q.answer) : countdown_words(left);
    p.status = reveal ? "Answer: " + candidate_letter(q.answer) + ", the lowest priority"
                      : "A* expands next: A or B?";
    p.caption = reveal ? q.answer_words : q.question;
}

view::PuzzleFrameView PuzzleProgram::frame_at(double seconds) const {
    double t = std::clamp(seconds, 0.0, duration());
    // The lesson's clock stops while a question holds.
    for (const PuzzleQuestion& q : questions_) {
        if (t < q.lesson_at) break;
        if (t < q.lesson_at + q.seconds()) {
            view::PuzzleFrameView view = lesson_frame(q.lesson_at);
            const bool reveal = t >= q.lesson_at + q.think;
            pose(q, reveal, q.lesson_at + q.think - t, view);
            return view;
        }
        t -= q.seconds();
    }
    return lesson_frame(t);
}

std::size_t PuzzleProgram::step_at(std::size_t i, double seconds) const noexcept {
    if (code_) return code_at(seconds).shown;
    const std::size_t total = sides_[i].result->expansions.size();
    const double u = (seconds - intro_) / search_seconds_;
    if (u <= 0.0) return 0;
    if (u >= 1.0) return total;
    const double grown = std::floor(std::pow(static_cast<double>(most_expansions_) + 1.0, u) - 1.0);
    return std::min(total, static_cast<std::size_t>(std::max(0.0, grown)));
}

std::string PuzzleProgram::name() const {
    return "8-puzzle";
}

std::string PuzzleProgram::title(const Side& side) const {
    const SearchResult& r = *side.result;
    if (r.method == Method::bfs) return "Breadth-first search";
    return "A*, " + estimate_words(r.heuristic) + ", " + panel_title(r.queue);
}

std::vector<std::string> PuzzleProgram::counters(const Side& side, std::size_t step,
                                                 std::size_t in_queue, bool done) const {
    const SearchResult& r = *side.result;
    // Two short lines a class can read from the back (the boards enqueued are the sum of the
    // two, give or take the stale entries: `collide puzzle --solve` prints them all).
    std::vector<std::string> out{"expanded " + with_thousands(step)};
    if (done) {
        out.push_back("largest queue " + with_thousands(r.stats.max_queue));
    } else {
        out.push_back("in queue " + with_thousands(in_queue));
    }
    return out;
}

view::PuzzleBoardView PuzzleProgram::board_view(const Side& side, std::uint32_t id) const {
    const SearchResult& r = *side.result;
    const puzzle::Board b = r.board_of(id);
    view::PuzzleBoardView view;
    view.side = b.side();
    for (int i = 0; i < b.cells(); ++i) view.tiles.push_back(static_cast<std::uint8_t>(b.tile(i)));
    const puzzle::SearchNode& n = r.nodes[id];
    if (r.method == Method::astar) {
        view.label = std::to_string(n.moves) + "+" + std::to_string(n.priority - n.moves) + "=" +
                     std::to_string(n.priority);
    } else {
        view.label = "depth " + std::to_string(n.moves);
    }
    return view;
}

view::PuzzlePanelView PuzzleProgram::search_panel(const Side& side, std::size_t step,
                                                  QueueMoment queue) const {
    const SearchResult& r = *side.result;
    // Done once the goal has been taken out and tested (not while it is leaving the queue).
    const bool done = step == r.expansions.size() && queue != QueueMoment::before_pop;
    view::PuzzlePanelView p;
    p.title = title(side);
    if (done) {
        p.status = "solved: " + plural(r.solution_length(), "move");
    } else if (r.method == Method::bfs) {
        p.status = "depth d before depth d+1";
    } else {
        p.status = "lowest moves + estimate first";
    }

    // The tree: the deepest rows reached, each with its most recent boards.
    p.shown = shown_;
    const std::size_t rows = shown_.rows;
    if (step > 0) {
        // The deepest rows, but never without the board being expanded: A* may come back up
        // the tree, and then the rows follow it (keeping up to two deeper rows below it).
        const std::size_t current = r.nodes[r.expansions[step - 1]].moves;
        const std::size_t deepest = std::min<std::size_t>(side.deepest[step], current + 2);
        const std::size_t first = deepest + 1 > rows ? deepest + 1 - rows : 0;
        // One short line (the panel is narrow at the lesson's text size): which depths are
        // left out; their boards are in the counters.
        const auto range = [](std::size_t from, std::size_t to) {
            return from == to ? std::to_string(from)
                              : std::to_string(from) + "-" + std::to_string(to);
        };
        std::vector<std::string> left_out;
        if (first > 0) left_out.push_back(range(0, first - 1));
        if (deepest < side.deepest[step])
            left_out.push_back(range(deepest + 1, side.deepest[step]));
        if (!left_out.empty()) {
            const bool one =
                left_out.size() == 1 && left_out.front().find('-') == std::string::npos;
            p.hidden_rows = std::string(one ? "depth " : "depths ") + left_out.front() +
                            (left_out.size() > 1 ? ", " + left_out.back() : "") + " not shown";
        }
        std::vector<std::uint32_t> above;  // expansion indices drawn in the row above
        for (std::size_t d = first; d <= deepest; ++d) {
            const std::vector<std::uint32_t>& list = side.by_depth[d];
            const std::size_t count = count_below(list, step);
            const std::size_t shown = std::min(count, shown_.row_boards);
            view::PuzzleRowView row;
            row.label = "depth " + std::to_string(d);
            row.count = plural(count, "board");
            std::vector<std::uint32_t> picks(
                list.begin() + static_cast<std::ptrdiff_t>(count - shown),
                list.begin() + static_cast<std::ptrdiff_t>(count));
            // Once solved, each row keeps the solution's board in view (leftmost), so the path
            // from the start to the goal reads down the tree.
            if (done && d < side.path.size() && !picks.empty()) {
                const std::uint32_t on_path = r.nodes[side.path[d]].popped;
                if (std::find(picks.begin(), picks.end(), on_path) == picks.end()) {
                    picks.erase(picks.begin());
                    picks.insert(picks.begin(), on_path);
                }
            }
            std::vector<std::uint32_t> here;
            for (const std::uint32_t k : picks) {
                const std::uint32_t id = r.expansions[k];
                view::PuzzleBoardView b = board_view(side, id);
                if (r.method == Method::bfs) b.label = "#" + with_thousands(k + 1U);
                if (done && id == r.goal) {
                    b.mark = PuzzleMark::goal;
                } else if (k + 1 == step) {
                    b.mark = PuzzleMark::current;
                } else if (done &&
                           std::find(side.path.begin(), side.path.end(), id) != side.path.end()) {
                    b.mark = PuzzleMark::solution;
                }
                const std::uint32_t parent = r.nodes[id].parent;
                if (parent != puzzle::no_node) {
                    const auto it = std::find(above.begin(), above.end(), r.nodes[parent].popped);
                    if (it != above.end()) b.parent = static_cast<int>(it - above.begin());
                }
                row.boards.push_back(std::move(b));
                here.push_back(k);
            }
            p.rows.push_back(std::move(row));
            above = std::move(here);
        }
    }

    if (step == 0) {
        p.board = board_view(side, 0);
        p.caption = "start: Manhattan " + std::to_string(puzzle::manhattan(start_)) + ", Hamming " +
                    std::to_string(puzzle::hamming(start_));
    }

    // The queue's front.
    p.queue_title = "next out";
    std::vector<std::uint32_t> front;
    std::size_t size = 0;
    if (queue == QueueMoment::after || step == 0) {
        front = r.queue_front(step, shown_.queue);
        size = r.queue_size(step);
    } else {
        front = queue_during(r, step - 1, queue == QueueMoment::popped, shown_.queue, size);
    }
    for (std::uint32_t id : front) p.queue.push_back(board_view(side, id));
    if (queue == QueueMoment::before_pop && !p.queue.empty())
        p.queue.front().mark = PuzzleMark::current;  // the board about to leave
    p.counters = counters(side, step, size, done);
    if (size > front.size()) p.queue_more = "+" + with_thousands(size - front.size()) + " more";
    if (size == 0) p.queue_more = "(empty)";
    return p;
}

view::PuzzlePanelView PuzzleProgram::playback_panel(const Side& side, double t) const {
    const SearchResult& r = *side.result;
    view::PuzzlePanelView p;
    p.title = title(side);
    p.counters = counters(side, r.expansions.size(), 0, true);
    p.status = "solution: " + plural(side.path.size() - 1, "move");
    p.playback = true;
    const std::size_t moves = side.path.size() - 1;
    if (t < 0.0) {  // the other solution plays first: this one waits on its start
        p.board = board_view(side, side.path.front());
        p.caption = "its " + plural(moves, "move") + " come next";
        return p;
    }
    const double at = t / per_move_;
    const auto m = static_cast<std::size_t>(std::floor(at));
    if (m >= moves) {
        p.board = board_view(side, side.path.back());
        p.caption = "solved in " + plural(moves, "move");
        p.board.mark = PuzzleMark::goal;
        return p;
    }
    const puzzle::Board before = r.board_of(side.path[m]);
    const puzzle::Board after = r.board_of(side.path[m + 1]);
    p.board = board_view(side, side.path[m + 1]);
    p.slide = {after.blank(), before.blank(), ease((at - static_cast<double>(m)) / slide_part)};
    const puzzle::Move move = before.move_to(after);
    p.caption = "move " + std::to_string(m + 1) + " of " + std::to_string(moves) + ": " +
                std::to_string(move.tile) + " slides " +
                std::string(puzzle::to_string(move.direction));
    return p;
}

view::PuzzleFrameView PuzzleProgram::lesson_frame(double t) const {
    view::PuzzleFrameView view;
    view.heading = puzzle_name(start_.side()) + " " + start_.to_string() + ": " +
                   (sides_.size() == 1 ? title(sides_.front())
                                       : std::string("breadth-first search against A*"));
    for (std::size_t i = 0; i < sides_.size(); ++i) {
        if (t >= playback_start()) {
            view.panels.push_back(playback_panel(sides_[i], t - playback_turn(i)));
        } else if (code_) {
            const CodeMoment m = code_at(t);
            view.panels.push_back(search_panel(sides_[i], m.shown, m.queue));
        } else {
            view.panels.push_back(search_panel(sides_[i], step_at(i, t)));
        }
    }
    if (code_) {
        view.code = search_code(sides_.front().result->method);
        if (const std::optional<SearchLine> line = code_at(t).line)
            view.code->current = static_cast<std::size_t>(*line);
    }
    return view;
}

}  // namespace collide::show
