#pragma once
/// \file
/// The animation model behind `collide heap`: priority-queue operations turned into a timeline of
/// small steps a class can follow (a key appears, two keys are compared, two keys exchange, a key
/// leaves), one panel per implementation, all in lock-step, each step with a caption in words and
/// the counts of compares and exchanges so far. Pure computation on values: no drawing, no I/O.
///
/// The steps come from the queues themselves: each implementation runs the operations with a
/// QueueRecorder (observer.hpp) and the record is replayed into steps; after every operation the
/// replayed array is checked against the queue's own array.
///
/// Operations (`--ops`), the tokens of `collide pq` plus one:
///   - a key (a word of letters or an integer; all keys of one kind) inserts it;
///   - `*` removes the maximum (the minimum for a min-queue);
///   - `K^V` raises key K to V (increase-key, through the indexed heap's map from key to index;
///     only with `indexed`). With duplicate keys it raises the one inserted first.
/// `--sort` takes keys only: heapsort, construction then sortdown.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "collide/sim/pq/order.hpp"
#include "collide/sim/pq/queue_kind.hpp"
#include "collide/sim/pq/trace.hpp"

namespace collide::pq {

/// One operation of a lesson.
struct LessonOp {
    enum class Kind {
        insert,    ///< insert `key`
        remove,    ///< remove the max (min)
        increase,  ///< raise `key` to `new_key` (indexed only)
    };
    Kind kind = Kind::insert;
    TraceKey key;
    TraceKey new_key;
    std::size_t token = 0;  ///< 1-based position in the operation string
    std::string spelling;   ///< the token as written
};

/// Splits `text` at white space into operations. Throws Error(input)
/// "<option>: token N 'x': why" for a token that is not a key, `*` or `K^V`, for a key of the
/// other kind than the first key (words and numbers do not mix), and for an empty sequence.
[[nodiscard]] std::vector<LessonOp> parse_lesson_ops(std::string_view text,
                                                     std::string_view option = "--ops");

/// The keys of `--sort` (no `*`, no `^`), with the same errors.
[[nodiscard]] std::vector<TraceKey> parse_sort_keys(std::string_view text,
                                                    std::string_view option = "--sort");

/// The array of one panel at one moment.
struct LessonState {
    std::vector<std::string> keys;     ///< the queue's array, slot 0 first
    std::vector<std::size_t> handles;  ///< indexed: each slot's handle (insertion number)
    /// Slots [heap_size, keys.size()) are heapsort's sorted part, set apart (= keys.size() for
    /// every queue).
    std::size_t heap_size = 0;
    std::string caption;          ///< what happens, in words
    std::uint64_t compares = 0;   ///< so far
    std::uint64_t exchanges = 0;  ///< so far (the ordered array's shifts count as exchanges)
};

/// One step of one panel: a state and what happens to it during the step.
struct LessonStep {
    enum class Kind {
        appear,    ///< a new key appears in slot i (already in `state`)
        compare,   ///< the keys in slots i and j are compared
        exchange,  ///< the keys in slots i and j exchange places (`state` is before)
        remove,    ///< the key in slot i (the last) leaves (`state` is before)
        change,    ///< the key in slot i was changed (increase-key; `state` has the new key)
        sink,      ///< heapsort's construction starts a sink at slot i
    };
    Kind kind = Kind::compare;
    std::size_t i = 0;
    std::size_t j = 0;
    std::optional<std::size_t> best;  ///< unordered array's scan: the max so far
    LessonState state;
};

/// One operation in one panel: its steps, then the state it leaves.
struct LessonPanelOp {
    std::vector<LessonStep> steps;
    LessonState end;  ///< caption: a summary ("insert S: 2 compares, 1 exchange")
};

/// One panel: an implementation and its operations.
struct LessonPanel {
    QueueKind kind;
    std::string
        title;         ///< "binary heap", "unordered array", "3-heap", "indexed 2-heap", "heapsort"
    bool tree = true;  ///< drawn as a tree above its array (heaps) or as an array only
    unsigned arity = 2;              ///< children per node when `tree`
    bool shifts = false;             ///< the ordered array: its exchanges are shifts
    LessonState start;               ///< before the first operation
    std::vector<LessonPanelOp> ops;  ///< one per LessonTimeline::op_labels entry
};

/// Pacing of the animation, in seconds of video.
struct LessonPacing {
    double pace = 0.8;   ///< one step; > 0
    double pause = 0.5;  ///< after each operation, >= 0
    double intro = 1.0;  ///< on the start state, >= 0
    double outro = 2.5;  ///< on the final state, >= 0
};

/// Where one panel is at one moment.
struct LessonPanelFrame {
    const LessonState* state = nullptr;  ///< never null
    const LessonStep* step = nullptr;    ///< null while holding a state between steps
    double progress = 0.0;               ///< in [0, 1): how far into `step`
};

/// Where the whole lesson is at one moment.
struct LessonFrame {
    std::size_t op = 0;    ///< the operation under way or just done (op_labels.size() at the start)
    bool started = false;  ///< false during the intro
    bool finished = false;  ///< true during the outro (every operation done)
    std::vector<LessonPanelFrame> panels;
};

/// The whole lesson: panels in lock-step, operation by operation.
class LessonTimeline {
  public:
    /// `--ops`: the operations on each implementation (in the given order, one panel each).
    /// Throws Error(input) naming the token for a removal from an empty queue, an increase-key
    /// without `indexed`, of a key not in the queue or to a smaller key; Error(input) for a queue
    /// kind with_queue rejects.
    static LessonTimeline operations(std::span<const LessonOp> ops,
                                     std::span<const QueueKind> impls, Orientation orientation,
                                     int index_base, LessonPacing pacing);
    /// `--sort`: heapsort of `keys` (ascending for max, descending for min), one panel, two
    /// operations (construction, sortdown).
    static LessonTimeline heapsort(std::span<const TraceKey> keys, Orientation orientation,
                                   int index_base, LessonPacing pacing);

    [[nodiscard]] const std::vector<LessonPanel>& panels() const noexcept { return panels_; }
    /// One label per operation for the strip of tokens ("P", "*", "3^12"; "build", "sortdown").
    [[nodiscard]] const std::vector<std::string>& op_labels() const noexcept { return labels_; }
    /// The most items any panel holds at once (the layout is sized for it).
    [[nodiscard]] std::size_t capacity() const noexcept { return capacity_; }
    /// Seconds of video.
    [[nodiscard]] double duration() const noexcept;
    /// The state of every panel at `seconds` (clamped to [0, duration()]).
    [[nodiscard]] LessonFrame frame_at(double seconds) const;

  private:
    void finish_timing(LessonPacing pacing);

    std::vector<LessonPanel> panels_;
    std::vector<std::string> labels_;
    std::vector<double> op_start_;  ///< seconds at which each operation starts
    std::size_t capacity_ = 0;
    LessonPacing pacing_;
};

}  // namespace collide::pq
