#pragma once
/// \file
/// What one frame of a priority-queue lesson (`collide heap`) shows, as plain values: the strip
/// of operations, and per panel a queue's array (keys and their highlights), an exchange or a
/// fade under way, the indexed heap's map, a title, counters and a caption. The presentation
/// layer (collide/show/heap_program.hpp) fills it for frame k; the painter
/// (collide/render/heap_view.hpp) draws it. Std-only: no simulation types, no drawing.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "collide/view/code.hpp"

namespace collide::view {

/// How one key is highlighted.
enum class SlotMark : std::uint8_t {
    plain,
    compared,  ///< one of the two keys being compared
    moving,    ///< one of the two keys being exchanged (or shifted)
    inserted,  ///< a key that just appeared
    changed,   ///< a key just changed (increase-key)
    best,      ///< the unordered array's scan: the max (min) so far
    leaving,   ///< the key being removed (fades out over HeapPanelView::fade)
    sinking,   ///< heapsort's construction: the root of the next sink
};

/// One slot of a queue's array (and the node of the tree that holds the same key).
struct HeapSlotView {
    std::string key;
    SlotMark mark = SlotMark::plain;
};

/// Two slots whose keys are on their way to each other's place: at t = 0 each is in its own
/// slot, at t = 1 in the other's (the presentation layer eases t).
struct HeapSwapView {
    std::size_t a = 0;
    std::size_t b = 0;
    float t = 0.0F;
};

/// One column of the indexed heap's map, for one handle i (the lecture's IndexMinPQ): its key,
/// keys[i], and the array index it sits at, qp[i].
struct HeapMapRow {
    std::string key;
    std::string index;     ///< as shown, e.g. "3"
    bool updated = false;  ///< its index changes in the exchange under way
};

/// A panel's counter, drawn "label value" ("compares 12").
struct HeapCounter {
    std::string label;  ///< "compares"
    std::string value;  ///< "12"
    friend bool operator==(const HeapCounter&, const HeapCounter&) = default;
};

/// The keys removed so far, as the trace's "returned" column, drawn "returned: X Q P" (oldest
/// first; where the line is too narrow the oldest give way to an ellipsis).
struct ReturnedKeys {
    std::string label;              ///< "returned:"; empty: the line is not drawn
    std::vector<std::string> keys;  ///< oldest first; {"-"} before the first removal
    [[nodiscard]] bool empty() const noexcept { return label.empty(); }
};

/// A question's letter on one node of the tree (`collide heap --questions on`): "A" beside the
/// node of slot `slot`, on a plate clear of the key.
struct HeapLetterView {
    std::size_t slot = 0;
    std::string letter;   ///< "A"
    bool answer = false;  ///< the reveal: this letter is the answer (drawn lit, the others faint)
};

/// One queue.
struct HeapPanelView {
    std::string title;                  ///< "binary heap (max)"
    std::vector<HeapCounter> counters;  ///< e.g. {{"compares", "12"}, {"exchanges", "5"}}
    /// The keys removed so far (a lesson without removals: empty, no line).
    ReturnedKeys returned;
    /// Heapsort: the label under the array's sorted part ("sorted").
    std::string sorted_label;
    std::string caption;  ///< what happens, wrapped to the panel's width
    bool tree = true;     ///< a heap: tree above the array; false: array only
    unsigned arity = 2;   ///< children per node (tree only), >= 2
    /// Slots the layout holds (the most keys the queue ever holds in this video), so that nodes
    /// keep their places for the whole video. >= slots.size().
    std::size_t capacity = 0;
    std::vector<HeapSlotView> slots;  ///< the array, slot 0 first
    /// Slots [heap_size, slots.size()) are heapsort's sorted part: set apart in the array, not
    /// in the tree. heap_size >= slots.size() means none.
    std::size_t heap_size = SIZE_MAX;
    std::optional<HeapSwapView> swap;  ///< an exchange under way
    float fade = 1.0F;                 ///< opacity of inserted (fading in) / leaving keys, [0, 1]
    int index_base = 1;                ///< the index shown under slot 0
    bool show_map = false;             ///< indexed heap: draw `map` beside the tree
    std::string map_title;             ///< the map's heading, in the lecture's names
    std::vector<HeapMapRow> map;
    /// A question under way on this panel: the candidates' letters (empty: none) and, while the
    /// class thinks, the countdown ("Think: 3"; empty during the reveal).
    std::vector<HeapLetterView> letters;
    std::string countdown;
    bool reveal = false;  ///< the letters show the answer
};

/// One frame.
struct HeapFrameView {
    std::vector<std::string> tokens;  ///< the operations, shown in a strip on top
    /// The operation under way (marked); tokens before it are done. Unset: none yet.
    std::optional<std::size_t> current_token;
    std::vector<HeapPanelView> panels;  ///< 1 to max_heap_panels, left to right, top to bottom
    /// `--code`: the pseudocode of the operation under way, drawn beside the panels; unset:
    /// none (the frame as without the option).
    std::optional<CodeView> code;
};

}  // namespace collide::view
