#pragma once
/// \file
/// What a class sees of `collide heap`: the record of priority-queue operations
/// (collide/sim/pq/heap_record.hpp, steps by kind) turned into words, pacing and frames. Each
/// step gets a caption ("insert S at a[11]; S > H: exchange"), each operation a summary
/// ("insert S: 3 compares, 2 exchanges"), each panel a title; the steps are paced in seconds of
/// video, all panels in lock-step, each operation as long as its longest panel; and
/// `frame_at(t)` fills the painter's view (collide/view/heap.hpp) for any moment. Pure: no
/// drawing, no I/O, no CLI.
///
///     const pq::HeapRecord record = pq::HeapRecord::operations(ops, kinds, Orientation::max);
///     const show::HeapProgram lesson(record, show::heap_pacing(0.8), 1);
///     for (double t = 0; t < lesson.duration(); t += 1.0 / fps)
///     painter.render(lesson.frame_at(t));

#include <cstddef>
#include <string>
#include <vector>

#include "collide/sim/pq/heap_record.hpp"
#include "collide/view/heap.hpp"

namespace collide::show {

/// Pacing of a heap lesson, in seconds of video.
struct HeapPacing {
    double pace = 0.8;   ///< one step; > 0
    double pause = 0.5;  ///< after each operation, >= 0
    double intro = 1.0;  ///< on the start state, >= 0
    double outro = 2.5;  ///< on the final state, >= 0
};

/// The pacing for `pace` seconds per step (0.8 s: a slide, then a moment to see where it
/// landed): a pause of 0.6 steps after each operation, an intro of at least 1 s and an outro of
/// at least 2.5 s. `pace` > 0 (the caller checks the range it accepts).
[[nodiscard]] HeapPacing heap_pacing(double pace) noexcept;

/// The title of a panel showing `kind`: "binary heap", "unordered array", "3-heap",
/// "indexed binary heap", "indexed 4-heap".
[[nodiscard]] std::string panel_title(const pq::QueueKind& kind);

/// "Where does K end up?" (`collide heap --questions on`, issue #45): before a swim or a sink the
/// lesson holds, letters A, B, ... mark candidate slots of one heap panel, and the reveal names
/// the slot the recorded operation leaves K in (followed through the record's own exchanges,
/// never worked out again here).
struct HeapQuestion {
    std::size_t op = 0;     ///< the operation asked about
    std::size_t panel = 0;  ///< the heap panel asked about (the first tree panel)
    /// The question holds before this shown step of the panel's operation (OpText::shown index,
    /// >= 1): the key is in place and about to swim or sink.
    std::size_t before = 0;
    std::string key;                      ///< K
    std::size_t from = 0;                 ///< the slot K starts from
    std::vector<std::size_t> candidates;  ///< slots in letter order (A, B, ...), 2 to 4
    std::size_t answer = 0;               ///< index into candidates: where K ends up
    double think = 0.0;                   ///< seconds of video frozen on the question
    double reveal = 0.0;                  ///< then seconds on the answer
    std::string question;                 ///< "Where does S end up: A, B or C?"
    std::string answer_words;             ///< "Answer: B, S ends up at a[2]"
    [[nodiscard]] double seconds() const noexcept { return think + reveal; }
};

class HeapProgram;

/// The questions `lesson` can ask: one per insert, remove and increase-key of its first heap
/// panel whose key has at least two slots it could end in (heapsort's phases ask none).
/// Candidates: the answer, and slots on K's way (its ancestors for a swim; for a sink the slots
/// it passed, the answer's children and its sibling), their letters shuffled by the operation's
/// index. A question holds at least min_think_seconds, and long enough that the stretch from its
/// operation's start to the reveal lasts 4 s (a chapter ends on it).
[[nodiscard]] std::vector<HeapQuestion> heap_questions(const HeapProgram& lesson);

/// Where one panel is at one moment.
struct HeapPanelMoment {
    const pq::ArrayState* state = nullptr;  ///< never null
    const pq::HeapStep* step = nullptr;     ///< null while holding a state between steps
    double progress = 0.0;                  ///< in [0, 1): how far into `step`
    const std::string* caption = nullptr;   ///< what happens, in words; never null
};

/// Where the whole lesson is at one moment.
struct HeapMoment {
    std::size_t op = 0;     ///< the operation under way or just done (ops().size() at the start)
    bool started = false;   ///< false during the intro
    bool finished = false;  ///< true during the outro (every operation done)
    std::vector<HeapPanelMoment> panels;
    /// A question under way: its index in HeapProgram::questions() (-1: none), whether its
    /// answer shows, and the seconds left to think.
    int question = -1;
    bool reveal = false;
    double think_left = 0.0;
};

/// A heap lesson as a class sees it: captions, pacing and frames over a record.
class HeapProgram {
  public:
    /// `index_base`: the index shown for slot 0 (1 as in the lecture's code, 0 as in its
    /// pseudo-code). Throws Error(input) "pace: must be > 0" for a pace <= 0 or a negative pause,
    /// intro or outro.
    HeapProgram(pq::HeapRecord record, HeapPacing pacing, int index_base = 1);

    [[nodiscard]] const pq::HeapRecord& record() const noexcept { return record_; }
    [[nodiscard]] const HeapPacing& pacing() const noexcept { return pacing_; }
    [[nodiscard]] int index_base() const noexcept { return index_base_; }
    /// One label per operation for the strip of tokens ("P", "*", "3^12"; "build", "sortdown").
    [[nodiscard]] const std::vector<std::string>& op_labels() const noexcept { return labels_; }
    /// The panels' titles joined by ", " ("unordered array, binary heap"), for a summary line.
    [[nodiscard]] std::string name() const;
    /// Seconds of video.
    [[nodiscard]] double duration() const noexcept;
    /// Seconds of video at which each operation starts, then the outro (ops + 1 values).
    [[nodiscard]] const std::vector<double>& op_starts() const noexcept { return op_start_; }
    /// The state of every panel at `seconds` (clamped to [0, duration()]).
    [[nodiscard]] HeapMoment moment_at(double seconds) const;
    /// The frame at `seconds`.
    [[nodiscard]] view::HeapFrameView frame_at(double seconds) const;
    /// The moments (seconds) whose frames must fit the picture for the lesson to be drawn
    /// (`collide heap` refuses it otherwise, HeapRenderer::fits): before any key is returned,
    /// halfway, and after the last operation, in that order.
    [[nodiscard]] std::vector<double> fit_check_times() const;
    /// The pseudocode of `moment` (heap_code.hpp): the listing of the operation under way (the
    /// first during the intro, the last during the outro) and the line its step carries out.
    [[nodiscard]] view::CodeView code_at(const HeapMoment& moment) const;
    /// Every line of every listing the lesson's operations show (the painter sizes its code
    /// column once for the video by them).
    [[nodiscard]] std::vector<view::CodeLineView> code_lines() const;

    /// Whether frames carry the pseudocode (`--code`). Throws Error(input) "code: ..." when the
    /// lesson cannot show it (heap_code_fits: one panel, a heap).
    void show_code(bool on);
    [[nodiscard]] bool shows_code() const noexcept { return code_; }

    /// Whether the lesson asks "where does K end up?" (`--questions on`): heap_questions of the
    /// record, each holding the lesson before its swim or sink; the timing (op_starts(),
    /// duration()) grows by their seconds.
    void ask_questions(bool on);
    /// The questions asked (none unless ask_questions(true)).
    [[nodiscard]] const std::vector<HeapQuestion>& questions() const noexcept { return questions_; }
    /// Seconds of video at which question `q` starts (its reveal starts think seconds later).
    [[nodiscard]] double question_start(std::size_t q) const;
    /// The widest key label of the lesson (for sizing node text once per video).
    [[nodiscard]] std::string widest_key() const;
    /// Every key the lesson shows, each once, in the order they first appear.
    [[nodiscard]] std::vector<std::string> keys() const;
    /// Every caption the lesson shows under its panels (start, steps, summaries, the questions
    /// and their answers), each once: the painter reserves the lines the longest needs.
    [[nodiscard]] std::vector<std::string> captions() const;

    /// The words of one panel: its title, its caption before the first operation, and per
    /// operation the caption of each step shown and a summary.
    struct OpText {
        std::vector<std::size_t> shown;     ///< indices of the record's steps shown, in order
        std::vector<std::string> captions;  ///< one per shown step
        std::string summary;                ///< "insert S: 3 compares, 2 exchanges"
    };
    struct PanelText {
        std::string title;  ///< "binary heap"
        std::string start;  ///< "binary heap, max-oriented: empty"
        std::vector<OpText> ops;
    };
    [[nodiscard]] const std::vector<PanelText>& text() const noexcept { return text_; }

  private:
    [[nodiscard]] view::HeapPanelView panel_view(std::size_t panel,
                                                 const HeapPanelMoment& moment) const;
    /// The keys panel `panel` has returned by `moment` ("returned: X Q"; "returned: -" before
    /// the first), as the trace's "returned" column; "" for a lesson without removals.
    [[nodiscard]] view::ReturnedKeys returned(std::size_t panel, const HeapMoment& moment) const;

    /// op_start_ from the steps, the pauses and the questions.
    void lay_out();
    /// The question asked in operation `op`, if any.
    [[nodiscard]] const HeapQuestion* question_of(std::size_t op) const noexcept;

    pq::HeapRecord record_;
    std::vector<PanelText> text_;
    std::vector<HeapQuestion> questions_;
    std::vector<std::string> labels_;
    std::vector<double> op_start_;  ///< seconds at which each operation starts, then the outro
    HeapPacing pacing_;
    int index_base_ = 1;
    bool code_ = false;
};

}  // namespace collide::show
