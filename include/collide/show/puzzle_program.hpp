#pragma once
/// \file
/// What a class sees of `collide puzzle`: the recorded searches (collide/sim/puzzle/search.hpp)
/// turned into the painter's view (collide/view/puzzle.hpp) for any moment of the video: titles,
/// counters, the tree's rows and their labels, the queue's front, captions. Pure: no drawing, no
/// I/O, no CLI.
///
/// The timeline: a moment on the start, then the searches grow on one shared clock (the number
/// of expansions grows geometrically with time, so the first boards are seen one by one and a
/// 180,000-board BFS still ends in seconds; a search that is done waits, so the cheaper one is
/// seen to finish first), a pause, the solutions played back move by move one after the other
/// (one moving board at a time, a second a move), a hold.
///
/// With the code (`--code`, one search): the first expansions walk the listing of
/// puzzle_code.hpp line by line (search_line_seconds a line: the board leaves the queue, is
/// tested, its neighbours go in), the middle runs fast with the loop's line marked, and the
/// goal's expansion walks again to "stop".

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "collide/show/puzzle_code.hpp"
#include "collide/sim/puzzle/board.hpp"
#include "collide/sim/puzzle/search.hpp"
#include "collide/view/puzzle.hpp"

namespace collide::show {

/// "1,234,567".
[[nodiscard]] std::string with_thousands(std::uint64_t n);

/// Expansions walked line by line at the start of a search shown with its code (then it runs
/// fast until the goal's expansion, walked too).
inline constexpr std::size_t walked_expansions = 3;

/// "Which board does A* expand next?" (`collide puzzle --questions on`, issue #45): early in an
/// A* search the video stops, letters two boards at the front of the queue (their labels say
/// moves + estimate = priority) and reveals the one the recorded search expands next.
struct PuzzleQuestion {
    std::size_t panel = 0;  ///< the A* panel asked about
    std::size_t step = 0;   ///< expansions done when it asks; the answer is expansion `step`
    /// Node ids of the search, in letter order (A, B); one is SearchResult::expansions[step], the
    /// other a board queued with a higher priority (so the picture decides between them).
    std::vector<std::uint32_t> candidates;
    std::size_t answer = 0;    ///< index into candidates
    double lesson_at = 0.0;    ///< the lesson's time it freezes at (its clock without questions)
    double think = 0.0;        ///< seconds of video frozen on the question
    double reveal = 0.0;       ///< then seconds on the answer
    std::string question;      ///< "Which board does A* expand next: A or B?"
    std::string answer_words;  ///< "Answer: B, 2+6=8: the lowest moves + estimate"
    [[nodiscard]] double seconds() const noexcept { return think + reveal; }
};

class PuzzleProgram {
  public:
    /// Which state of the queue a frame shows while an expansion is under way.
    enum class QueueMoment : std::uint8_t {
        before_pop,  ///< before the board under way leaves it (it is at the front, marked)
        popped,      ///< after it left, before its neighbours went in
        after,       ///< after the neighbours went in
    };

    /// Where a search shown with its code is at a moment of the video.
    struct CodeMoment {
        std::size_t shown = 0;  ///< expansions drawn in the tree, the one under way included
        std::optional<SearchLine> line;  ///< the line marked; none during the playback
        QueueMoment queue = QueueMoment::after;
    };

    /// `results`: one or two solved searches of `start` (kept by reference: they must outlive
    /// this object); `code`: show the search loop beside the one search. Throws Error(runtime)
    /// for an unsolved one, or for code with two searches (a caller's bug).
    PuzzleProgram(const puzzle::Board& start, const std::vector<puzzle::SearchResult>& results,
                  bool code = false);

    /// Whether the frames carry the code.
    [[nodiscard]] bool shows_code() const noexcept { return code_; }
    /// With the code: where the search is at `seconds`. Precondition: shows_code().
    [[nodiscard]] CodeMoment code_at(double seconds) const;

    /// Seconds of video (the questions included).
    [[nodiscard]] double duration() const noexcept;
    /// The times below are on the lesson's own clock, which stops during a question (the video
    /// from question_start(q) on is seconds() later than it).
    /// When the searches start growing, and when the last one has finished.
    [[nodiscard]] double search_start() const noexcept { return intro_; }
    [[nodiscard]] double search_end() const noexcept { return intro_ + search_seconds_; }
    /// When the playback of the solutions starts.
    [[nodiscard]] double playback_start() const noexcept;
    /// When search `i`'s solution starts to play (the first at playback_start()).
    [[nodiscard]] double playback_turn(std::size_t i) const noexcept;
    /// Playback seconds per move.
    [[nodiscard]] double seconds_per_move() const noexcept { return per_move_; }

    /// Expansions shown for search `i` at `seconds` (0 .. its expansions).
    [[nodiscard]] std::size_t step_at(std::size_t i, double seconds) const noexcept;

    /// The frame at `seconds` (clamped to the video).
    [[nodiscard]] view::PuzzleFrameView frame_at(double seconds) const;

    /// Whether the video asks "which board does A* expand next?" (`--questions on`): one
    /// question per A* search, at its first expansion after which the queue's front holds a
    /// board of a higher priority than the next one; the video grows by its seconds.
    void ask_questions(bool on);
    [[nodiscard]] const std::vector<PuzzleQuestion>& questions() const noexcept {
        return questions_;
    }
    /// Seconds of video at which question `q` starts (its reveal starts think seconds later).
    [[nodiscard]] double question_start(std::size_t q) const;

    /// The video's name, for a slide page's title: "8-puzzle".
    [[nodiscard]] std::string name() const;

  private:
    struct Side {
        const puzzle::SearchResult* result = nullptr;
        std::vector<std::vector<std::uint32_t>> by_depth;  ///< expansion indices per depth
        std::vector<std::uint16_t> deepest;                ///< deepest depth after k expansions
        std::vector<std::uint32_t> path;                   ///< the solution's node ids
    };

    /// A walked line of the code: from `start` (seconds of video) on, expansion `expansion`.
    struct Beat {
        double start = 0.0;
        std::size_t expansion = 0;
        SearchLine line = SearchLine::pop;
    };

    void pace_code();
    /// The frame at `t` seconds of the lesson's own clock (no questions).
    [[nodiscard]] view::PuzzleFrameView lesson_frame(double t) const;
    /// Letters, countdown and words of question `q` on `view` (`left`: seconds to think).
    void pose(const PuzzleQuestion& q, bool reveal, double left, view::PuzzleFrameView& view) const;
    /// The question of search `i`, if it has one to ask.
    [[nodiscard]] std::optional<PuzzleQuestion> question_for(std::size_t i) const;
    [[nodiscard]] view::PuzzlePanelView search_panel(const Side& side, std::size_t step,
                                                     QueueMoment queue = QueueMoment::after) const;
    [[nodiscard]] view::PuzzlePanelView playback_panel(const Side& side, double t) const;
    [[nodiscard]] view::PuzzleBoardView board_view(const Side& side, std::uint32_t id) const;
    [[nodiscard]] std::string title(const Side& side) const;
    /// The counters after `step` expansions with `in_queue` boards queued (shown while
    /// searching, not once `done`).
    [[nodiscard]] std::vector<std::string> counters(const Side& side, std::size_t step,
                                                    std::size_t in_queue, bool done) const;

    puzzle::Board start_;
    std::vector<Side> sides_;
    std::size_t most_expansions_ = 0;
    std::size_t longest_solution_ = 0;
    double intro_ = 2.5;           ///< the start, before any expansion
    double search_seconds_ = 0.0;  ///< the growth of the largest search
    double pause_ = 2.0;           ///< the finished trees, before the playback
    double per_move_ = 1.0;        ///< playback seconds per move: a class follows each one
    double between_ = 1.0;         ///< between one solution's goal and the next one's start
    double outro_ = 2.5;           ///< the solved boards, at the end
    std::vector<double> turns_;    ///< when each solution plays, from playback_start()
    double playback_length_ = 0.0;
    bool code_ = false;
    view::PuzzleShown shown_;                ///< the boards each panel draws (by the board's side)
    std::vector<Beat> beats_;                ///< with the code: the walked lines, in time order
    double fast_start_ = 0.0;                ///< with the code: when the fast middle starts
    double fast_seconds_ = 0.0;              ///< ... and how long it runs
    std::size_t fast_from_ = 0;              ///< ... the expansions shown when it starts
    std::size_t fast_count_ = 0;             ///< ... the expansions it adds
    std::vector<PuzzleQuestion> questions_;  ///< in time order
};

}  // namespace collide::show
