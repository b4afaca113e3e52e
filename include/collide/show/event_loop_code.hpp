#pragma once
/// \file
/// The pseudocode of `collide render --queue --code`: the event-driven simulation's main loop
/// (delete the minimum, skip it if invalidated, move all discs, resolve, predict) in the
/// project's own words, and which line the frame shows under way. Each pop walks the lines:
/// for code_line_seconds of video each, a valid event marks "delete the minimum", "if e is
/// invalidated", "resolve e" and "predict ...", a stale one "delete the minimum" and "if e is
/// invalidated"; between walks the clock runs and "move all discs" is marked. The newest pop
/// (QueueView::popped) decides; a pop that comes before the walk of the last is done starts its
/// own. Pure: no drawing.

#include <cstddef>
#include <vector>

#include "collide/snapshot.hpp"
#include "collide/view/code.hpp"

namespace collide::show {

/// Seconds of video each line of a pop's walk stays marked (a valid event's walk: 4 of them).
inline constexpr double code_line_seconds = 0.35;

/// Seconds of video a popped event stays highlighted on the queue strip without the code.
inline constexpr double queue_pop_seconds = 0.8;

/// How long the queue strip keeps a popped event highlighted (`stale`: thrown away): with the
/// code (`code`), as long as its walk through the loop's lines, so the strip and the marked line
/// tell of the same pop until "predict" is done; without, queue_pop_seconds.
[[nodiscard]] double pop_highlight_seconds(bool stale, bool code) noexcept;

/// The lines of the listing, in order.
enum class LoopLine : std::size_t {
    loop = 0,  ///< "while the queue is not empty:"
    pop,       ///< "e = delete the minimum"
    check,     ///< "if e is invalidated: skip it"
    move,      ///< "move all discs to e's time"
    resolve,   ///< "resolve e"
    predict,   ///< "predict e's discs' next events"
};

/// The listing (its lines in LoopLine's order) with no line marked.
[[nodiscard]] view::CodeView event_loop_code();

/// The line under way at simulation time `now` for a queue whose latest pops are `queue.popped`
/// (oldest first, each at its time), with `speed` simulation time per second of video (> 0;
/// otherwise "move"). Before any pop the discs move towards the first event: "move".
[[nodiscard]] LoopLine event_loop_line(const QueueView& queue, double now, double speed) noexcept;

/// event_loop_code() with event_loop_line marked.
[[nodiscard]] view::CodeView event_loop_view(const QueueView& queue, double now, double speed);

}  // namespace collide::show
