// `collide render --queue --code` (collide/show/event_loop_code.hpp): the event-driven loop's
// marked line follows the queue's latest pop. A valid event walks "delete the minimum", "if e is
// invalidated", "resolve e", "predict ..."; a stale one stops at the check; between walks the
// clock runs and "move discs" is marked. Checked against the pops of a QueueView.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "collide/show/event_loop_code.hpp"

using namespace collide;
using show::code_line_seconds;
using show::event_loop_line;
using show::LoopLine;

namespace {

QueuedEvent popped_at(double t, bool stale) {
    QueuedEvent e;
    e.t = t;
    e.stale = stale;
    return e;
}

/// The lines marked at the middle of each line's time after the pop at `t`, `count` of them.
std::vector<LoopLine> walk(const QueueView& q, double t, double speed, int count) {
    std::vector<LoopLine> out;
    for (int k = 0; k < count; ++k)
        out.push_back(event_loop_line(q, t + (k + 0.5) * code_line_seconds * speed, speed));
    return out;
}

}  // namespace

TEST_CASE("event loop code: the listing names the loop's phases in order") {
    const view::CodeView code = show::event_loop_code();
    REQUIRE(code.lines.size() == 6);
    const auto text = [&](LoopLine l) { return code.lines[static_cast<std::size_t>(l)].text; };
    CHECK(text(LoopLine::loop).find("while") == 0);
    CHECK(text(LoopLine::pop).find("delete the minimum") != std::string::npos);
    CHECK(text(LoopLine::check).find("invalidated") != std::string::npos);
    CHECK(text(LoopLine::move).find("move discs") == 0);
    CHECK(text(LoopLine::resolve).find("resolve") == 0);
    CHECK(text(LoopLine::predict).find("predict") == 0);
    CHECK_FALSE(code.current.has_value());
}

TEST_CASE("event loop code: a valid pop walks pop, check, resolve, predict, then the discs move") {
    const double speed = 0.05;  // simulation time per second of video
    QueueView q;
    q.popped = {popped_at(0.2, true), popped_at(1.0, false)};
    CHECK(walk(q, 1.0, speed, 5) == std::vector<LoopLine>{LoopLine::pop, LoopLine::check,
                                                          LoopLine::resolve, LoopLine::predict,
                                                          LoopLine::move});
    // Long after the pop, until the next: the clock runs towards the next event.
    CHECK(event_loop_line(q, 1.0 + 10.0 * speed, speed) == LoopLine::move);
    CHECK(show::event_loop_view(q, 1.0 + 0.5 * code_line_seconds * speed, speed).current ==
          static_cast<std::size_t>(LoopLine::pop));
}

TEST_CASE("event loop code: a stale pop stops at the check: it is skipped, nothing resolved") {
    const double speed = 0.05;
    QueueView q;
    q.popped = {popped_at(1.0, false), popped_at(2.0, true)};
    CHECK(walk(q, 2.0, speed, 3) ==
          std::vector<LoopLine>{LoopLine::pop, LoopLine::check, LoopLine::move});
}

TEST_CASE("event loop code: the newest pop decides, and before any pop the discs move") {
    const double speed = 0.05;
    QueueView q;
    CHECK(event_loop_line(q, 0.0, speed) == LoopLine::move);
    // A pop during the last one's walk starts its own walk.
    q.popped = {popped_at(1.0, false), popped_at(1.0 + 1.5 * code_line_seconds * speed, false)};
    CHECK(event_loop_line(q, q.popped.back().t + 0.1 * code_line_seconds * speed, speed) ==
          LoopLine::pop);
    // No speed known: nothing to pace the walk by.
    CHECK(event_loop_line(q, q.popped.back().t, 0.0) == LoopLine::move);
}

TEST_CASE("event loop code: the queue strip's highlight lasts exactly the pop's walk") {
    const double speed = 0.05;
    for (const bool stale : {false, true}) {
        CAPTURE(stale);
        QueueView q;
        q.popped = {popped_at(1.0, stale)};
        const double lit = show::pop_highlight_seconds(stale, true);
        REQUIRE(lit > 0.0);
        // Just before the highlight ends the walk is on its last line; just after, it is done.
        const double eps = 0.01;
        CHECK(event_loop_line(q, 1.0 + (lit - eps) * speed, speed) ==
              (stale ? LoopLine::check : LoopLine::predict));
        CHECK(event_loop_line(q, 1.0 + (lit + eps) * speed, speed) == LoopLine::move);
    }
    // Without the code the strip keeps its own, shorter highlight.
    CHECK(show::pop_highlight_seconds(false, false) == show::queue_pop_seconds);
    CHECK(show::pop_highlight_seconds(true, false) == show::queue_pop_seconds);
}
