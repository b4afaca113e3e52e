#include "collide/show/event_loop_code.hpp"

#include <cmath>
#include <iterator>

namespace collide::show {

view::CodeView event_loop_code() {
    view::CodeView code;
    code.title = "event-driven loop";
    // Lines short enough for the listing to stand beside two boxes of 35 % of the frame at the
    // lesson's text size (issue 44).
    code.lines = {{0, "while events are queued:"},
                  {1, "e = delete the minimum"},
                  {1, "if e is invalidated: skip it"},
                  {1, "move discs to e's time"},
                  {1, "resolve e"},
                  {1, "predict e's discs' events"}};
    return code;
}

namespace {

// A valid event's walk skips the move: the discs have just arrived at its time.
constexpr LoopLine valid_walk[] = {LoopLine::pop, LoopLine::check, LoopLine::resolve,
                                   LoopLine::predict};
constexpr LoopLine stale_walk[] = {LoopLine::pop, LoopLine::check};

}  // namespace

double pop_highlight_seconds(bool stale, bool code) noexcept {
    if (!code) return queue_pop_seconds;
    const std::size_t lines = stale ? std::size(stale_walk) : std::size(valid_walk);
    return static_cast<double>(lines) * code_line_seconds;
}

LoopLine event_loop_line(const QueueView& queue, double now, double speed) noexcept {
    if (queue.popped.empty() || !(speed > 0.0)) return LoopLine::move;
    const QueuedEvent& last = queue.popped.back();
    const double age = (now - last.t) / speed / code_line_seconds;  // in lines of the walk
    if (!(age >= 0.0)) return LoopLine::move;
    const auto step = static_cast<std::size_t>(std::floor(age));
    if (last.stale) return step < std::size(stale_walk) ? stale_walk[step] : LoopLine::move;
    return step < std::size(valid_walk) ? valid_walk[step] : LoopLine::move;
}

view::CodeView event_loop_view(const QueueView& queue, double now, double speed) {
    view::CodeView code = event_loop_code();
    code.current = static_cast<std::size_t>(event_loop_line(queue, now, speed));
    return code;
}

}  // namespace collide::show
