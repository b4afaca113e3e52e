// The collision video's program (collide/show/collision.hpp): titles, counters, figures, the
// clock and the energy line, as pure functions of measurements and the frame clock.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "collide/number_text.hpp"
#include "collide/show/collision.hpp"
#include "collide/sim/pq/queue_kind.hpp"

using namespace collide;
using namespace collide::show;

namespace {

/// The clock of a video of `seconds` at `fps` frames per second and `speed` (as the app's
/// video_clock makes it).
FrameClock clock_of(double seconds, double speed, int fps) {
    FrameClock clock;
    clock.interval = speed / fps;
    clock.count = std::llround(seconds * fps);
    clock.last_time = static_cast<double>(clock.count - 1) * clock.interval;
    return clock;
}

}  // namespace

TEST_CASE("on-screen counters are deterministic counts, the same for the same measurements") {
    Measurements m;
    m.t = 2.0;
    m.steps = 200;
    m.overlap_checks = 1'000'000;
    m.missed_collisions = 7;
    m.escaped = 2;
    const auto td = time_driven_counters(m, 1e-3);
    CHECK(td == time_driven_counters(m, 1e-3));
    const auto joined = [](const std::vector<std::string>& lines) {
        std::string all;
        for (const auto& l : lines) all += l + "\n";
        return all;
    };
    CHECK(joined(td).find("missed  7") != std::string::npos);
    CHECK(joined(td).find("escaped  2") != std::string::npos);
    CHECK(joined(event_driven_counters(m, 0.0)).find("events") != std::string::npos);
}

TEST_CASE("counts on screen have one format: thousands separators, as on the cards") {
    CHECK(short_count(0.0) == "0");
    CHECK(short_count(999.0) == "999");
    CHECK(short_count(12'345.0) == "12,345");
    CHECK(short_count(4.56e6) == "4,560,000");
    CHECK(short_count(221'190'000.4) == "221,190,000");
    CHECK(short_count(7.5e9) == "7,500,000,000");
    CHECK(short_count(-3e13) == "-30,000,000,000,000");
    // Per unit of time in scenes written in SI units (picoseconds): no 20-digit counts.
    CHECK(short_count(2.394e17) == "2.39e+17");
    CHECK(short_count(4.2e-4) == "0.00042");
    // The card's and the panel's figure of one count read the same.
    CHECK(short_count(4404.0) == with_separators(4404));
}

TEST_CASE("the on-screen clock resolves one frame interval, whatever the units") {
    // Built-in scenes: three decimals, as in every video so far.
    CHECK(clock_label(12.3456, clock_of(10.0, 1.0, 30), 1.0) == "t = 12.346   (1/s)");
    // An argon scene in SI units: the video spans 5e-11 s, frames 3.3e-13 s apart.
    const FrameClock si = clock_of(10.0, 5e-12, 15);
    CHECK(clock_label(si.time(149), si, 5e-12) == "t = 4.9667e-11   (5e-12/s)");
    // Huge units: no 46-digit clock.
    const FrameClock huge = clock_of(10.0, 7e44, 15);
    CHECK(clock_label(huge.time(149), huge, 7e44) == "t = 6.9533e+45   (7e+44/s)");
    // Long runs in ordinary units: as many digits as it takes.
    const FrameClock long_run = clock_of(600.0, 1e4, 30);
    CHECK(clock_label(long_run.time(12345), long_run, 1e4) == "t = 4115000   (1e+04/s)");
    for (const FrameClock& clock : {si, huge, long_run}) {
        for (std::int64_t k = 1; k < clock.count; ++k) {
            CAPTURE(k);
            REQUIRE(clock_label(clock.time(k - 1), clock, 1.0) !=
                    clock_label(clock.time(k), clock, 1.0));
        }
    }
}

TEST_CASE("the lesson column shows the time (its unit under it), the full level its rate too") {
    const FrameClock clock = clock_of(10.0, 1.0, 30);
    // Frames 1/30 apart: two decimals tell them apart.
    CHECK(clock_text(2.5, clock, 1.0, OverlayLevel::lesson) == "t = 2.50");
    CHECK(clock_text(2.5, clock, 1.0, OverlayLevel::full) == "t = 2.500   (1/s)");
    // brownian: 3 time units a second at 30 fps, frames 0.1 apart.
    CHECK(clock_text(45.0, clock_of(20.0, 3.0, 30), 3.0, OverlayLevel::lesson) == "t = 45.0");
    const FrameClock si = clock_of(10.0, 5e-12, 15);
    CHECK(clock_text(si.time(149), si, 5e-12, OverlayLevel::lesson) == "t = 4.9667e-11");
    CHECK(std::string(time_unit) == "time units");
    for (const FrameClock& c : {clock, clock_of(20.0, 3.0, 30), clock_of(20.0, 0.05, 15), si}) {
        for (std::int64_t k = 1; k < c.count; ++k) {
            CAPTURE(k);
            REQUIRE(clock_text(c.time(k - 1), c, 1.0, OverlayLevel::lesson) !=
                    clock_text(c.time(k), c, 1.0, OverlayLevel::lesson));
        }
    }
}

TEST_CASE("dt reads as written, or as the whole fraction it is") {
    CHECK(dt_text(0.05) == "0.05");
    CHECK(dt_text(0.0125) == "0.0125");
    CHECK(dt_text(1.0 / 30.0) == "1/30");  // not 0.0333
    CHECK(dt_text(0.2 / 30.0) == "1/150");
    CHECK(dt_text(2.0 / 75.0) == "2/75");
    CHECK(dt_text(0.1 / 3.0 * 2.0) == "1/15");
    CHECK(dt_text(std::numbers::pi / 100.0) == "0.0314");  // no fraction: three digits
    CHECK(dt_text(1e-13 / 3.0) == "3.33e-14");
    CHECK(time_lesson_title(1.0 / 30.0) == "Time-driven: steps of dt = 1/30");
}

TEST_CASE("the step note says what a class sees happen") {
    CHECK(step_note(0.01, 0.02).empty());  // shorter than a frame
    CHECK(step_note(0.02, 0.01) == "Moves only every 2nd frame");
    CHECK(step_note(0.03, 0.01) == "Moves only every 3rd frame");
    // dense-fluid at 30 fps: dt = 0.01, frames 0.2 / 30 apart: 1.5 frames a step.
    CHECK(step_note(0.01, 0.2 / 30.0) == "Moves on 2 of every 3 frames");
    CHECK(step_note(0.025, 0.01) == "Moves on 2 of every 5 frames");
    CHECK(step_note(std::numbers::pi / 100.0, 0.01) == "Moves about once every 3.1 frames");
    CHECK(whole_frames_per_step(0.02, 0.01) == 2);
    CHECK(whole_frames_per_step(0.01, 0.2 / 30.0) == 1);  // no fixed pattern of one
    CHECK(whole_frames_per_step(0.01, 0.02) == 1);
}

TEST_CASE("panel titles: plain words at the lesson level, the queue named for the classic engine") {
    EngineOptions classic;
    classic.engine = EngineKind::classic;
    classic.pq = pq::parse_queue_kind("binary");
    EngineOptions time;
    time.engine = EngineKind::time;
    time.dt = 0.0125;
    CHECK(panel_title(true, OverlayLevel::lesson, time) == "Time-driven: steps of dt = 0.0125");
    CHECK(panel_title(true, OverlayLevel::full, time) == "Time-driven, dt = 0.0125");
    CHECK(panel_title(false, OverlayLevel::lesson, classic).rfind("Event-driven: queue (", 0) == 0);
    CHECK(panel_title(false, OverlayLevel::none, EngineOptions{}) ==
          "Event-driven (priority queue)");
}

TEST_CASE("lesson figures are plain words with thousands separators") {
    Measurements m;
    m.missed_collisions = 12345;
    m.overlapping_pairs = 3;
    m.escaped = 0;
    m.collisions_pair = 1000000;
    const auto td = time_driven_figures(m, true);
    REQUIRE(td.size() == 3);  // nobody tunnelled: no "tunnelled" figure yet
    CHECK(td[0].value == "12,345");
    CHECK(td[0].label == "missed");
    CHECK(td[0].failure);
    CHECK(td[2].value == "1,000,000");
    m.escaped = 4;  // out through the wall: tunnelled
    REQUIRE(time_driven_figures(m, true).size() == 4);
    CHECK(time_driven_figures(m, true)[2].value == "4");
    CHECK(time_driven_figures(m, true)[2].label == "tunnelled");
    CHECK(time_driven_figures(m, true)[2].failure);
    CHECK(time_driven_figures(m, false).size() == 3);  // periodic boxes have nothing to leave
    m.escaped = 0;
    m.tunnelled = 1500;  // through a barrier (the engine counts the escaped discs in it too)
    for (const bool walls : {true, false}) {
        REQUIRE(time_driven_figures(m, walls).size() == 4);
        CHECK(time_driven_figures(m, walls)[2].value == "1,500");
        CHECK(time_driven_figures(m, walls)[2].label == "tunnelled");
    }
    m.tunnelled = 0;
    const auto ed = event_driven_figures(m);
    CHECK(ed[0].value == "1,000,000");
    CHECK(ed[0].label == "collisions");
    CHECK(ed[1].value == "0");
    // One collision is "1 collision", in both panels.
    m.collisions_pair = 0;
    m.collisions_wall = 1;
    CHECK(event_driven_figures(m)[0].label == "collision");
    CHECK(time_driven_figures(m, false).back().label == "collision");
}

TEST_CASE("each panel's work is pair computations: tests and predictions, plus queue operations") {
    Measurements m;
    m.missed_collisions = 1234;
    m.overlap_checks = 500;
    m.predictions = 9;
    m.collisions_pair = 40;
    m.collisions_wall = 2;
    m.queue.pushes = 70;
    m.queue.pops = 30;
    m.queue.updates = 25;
    const PanelWords td = panel_words(m, true, true, 0.0);
    CHECK(td.compact_line == "1,234 missed");
    CHECK(td.cost_label == "pair tests");
    CHECK(td.cost == 509.0);  // overlap tests and contact times
    CHECK(td.counters == time_driven_counters(m, 0.0));
    CHECK(td.how.find("N\u00b2/2") != std::string::npos);
    const PanelWords ed = panel_words(m, false, true, 0.0);
    CHECK(ed.compact_line == "42 collisions");
    CHECK(ed.cost_label == "pairs + queue");
    CHECK(ed.cost == 134.0);  // predictions, pushes, pops and updates
    CHECK(ed.how.find("log N") != std::string::npos);
    CHECK(panel_words(m, false, true, 0.0, EngineKind::classic).how.find("2N") !=
          std::string::npos);
}

TEST_CASE("the time-driven summary line: the panel's figure and label, then its two parts") {
    Measurements m;
    m.overlap_checks = 3'056'625;
    m.predictions = 331;
    const PanelWords td = panel_words(m, true, true, 0.0);
    CHECK(time_driven_work_line(m) == td.cost_text + " " + td.cost_label +
                                          ": 3,056,625 overlap checks + 331 contact-time "
                                          "computations");
    CHECK(td.cost_text == "3,056,956");
}

TEST_CASE("the work ratio is the engines' counts divided, in words") {
    // brownian at t = 60 (issue #28): 2.39 G pair tests against 14 M predictions and 1.85 M
    // queue operations.
    CHECK(work_ratio(2.39e9, 14.0e6 + 1.85e6) == "151x less work");
    CHECK(work_ratio(1000.0, 400.0) == "2.5x less work");
    CHECK(work_ratio(1000.0, 30.0) == "33x less work");
    CHECK(work_ratio(300.0, 1000.0) == "3.3x more work");
    CHECK(work_ratio(998.0, 100.0) == "10x less work");
    CHECK(work_ratio(1000.0, 1000.0) == "the same work");
    CHECK(work_ratio(0.0, 10.0).empty());  // nothing to compare yet
    CHECK(work_ratio(10.0, 0.0).empty());
    // The ratio of the words is the ratio of the counts, at any size.
    for (double t : {1e3, 3.7e5, 2.39e9, 8.1e12}) {
        for (double e : {7.0, 1.3e3, 4.4e6}) {
            if (t < e) continue;
            const std::string words = work_ratio(t, e);
            CAPTURE(words);
            const double shown = std::stod(words.substr(0, words.find('x')));
            CHECK(std::abs(shown - t / e) <= 0.05 * (t / e) + 0.5);
        }
    }
}

TEST_CASE("the energy line names the engine that does not conserve energy") {
    CHECK(energy_line({}).empty());
    CHECK(energy_line({{false, 0.0}}) == "Energy conserved");
    CHECK(energy_line({{true, round_off_drift}}) == "Energy conserved");
    CHECK(energy_line({{true, 1e-6}}) == "Energy not conserved");
    CHECK(energy_line({{true, 0.0}, {false, 1e-12}}) == "Both conserve energy");
    CHECK(energy_line({{true, 1e-3}, {false, 1e-12}}) == "Time-driven: energy drifts");
    CHECK(energy_line({{true, 0.0}, {false, 1e-3}}) == "Event-driven: energy drifts");
    CHECK(energy_line({{true, 1e-3}, {false, 1e-3}}) == "Neither conserves energy");
}

TEST_CASE("the queue strip's words: the fast engine re-predicts, the classic one throws away") {
    QueueView q;
    q.name = "binary heap";
    q.size = 1234;
    q.stale_entries = 56;
    q.next.resize(5);
    q.pops = 40;
    q.stale_pops = 3;
    const QueueWords classic = queue_words(q, 0.0);
    CHECK(classic.heading == "Event queue: binary heap, 1,234 entries, 56 stale");
    CHECK(classic.legend == "Next 5 collisions, time to go");
    // One listed collision reads as one ("Next 1 collisions" was seen in gas with --queue).
    QueueView one = q;
    one.next.resize(1);
    CHECK(queue_words(one, 0.0).legend == "Next collision, time to go");
    // None listed, one entry: no "Next 0 collisions", no "1 entries" (billiards before the break).
    QueueView none = q;
    none.next.clear();
    none.size = 1;
    none.stale_entries = 0;
    CHECK(queue_words(none, 0.0).legend == "No collision predicted yet");
    CHECK(queue_words(none, 0.0).heading == "Event queue: binary heap, 1 entry");
    CHECK(classic.stale_popped == "  stale: skipped");
    CHECK(classic.counts == "3 of 40 pops stale");
    q.one_per_disc = true;
    const QueueWords fast = queue_words(q, 0.0);
    CHECK(fast.heading == "Event queue: binary heap, 1,234 entries (one per disc)");
    CHECK(fast.stale_popped == "  stale: re-predict");
    CHECK(fast.counts == "40 pops, 3 stale");
    CHECK(fast.counts_lines == std::vector<std::string>{"40 pops", "3 stale"});
    CHECK(classic.counts_lines == std::vector<std::string>{"40 pops", "3 stale"});
    // The next event's discs are named in the box as the strip names them.
    q.next[0].a = 3;
    q.next[0].b = 7;
    q.next[0].kind = EventKind::pair;
    CHECK(queue_words(q, 0.0).next_discs == std::vector<std::string>{"3", "7"});
    q.next[0].kind = EventKind::xwall;
    CHECK(queue_words(q, 0.0).next_discs == std::vector<std::string>{"3"});
    // Every other listed event's discs are numbered too, each once, none of the next event's
    // again; cell crossings are not drawn, so not numbered (issue 44 item 4).
    q.next = {{0.1, EventKind::pair, 3, 7},
              {0.2, EventKind::pair, 7, 9},
              {0.3, EventKind::ywall, 9, 0},
              {0.4, EventKind::cell, 11, 0},
              {0.5, EventKind::pair, 12, 3}};
    std::vector<std::string> numbers;
    for (const QueueWords::NumberedDisc& d : queue_words(q, 0.0).listed_discs) {
        CHECK(d.number == std::to_string(d.disc));
        numbers.push_back(d.number);
    }
    CHECK(numbers == std::vector<std::string>{"9", "12"});
}

TEST_CASE("the queue strip's fixed legends come from the words, the row caption by shape") {
    QueueView q;
    q.size = 1234;
    q.slots.resize(7);
    const QueueWords heap = queue_words(q, 0.0);
    CHECK(heap.popped_heading == "Popped (newest first)");
    CHECK(heap.resolved_popped == "  resolved");
    CHECK(heap.crossing_popped == "  crossing");
    CHECK(heap.stale_slot == "stale");
    CHECK(heap.fresh_leaving == "popped");
    CHECK(heap.below == "+1,227 below");
    CHECK(heap.row_caption.empty());  // a heap is drawn as a tree, no row
    // The same in fewer words for a narrow strip: shorter, and still naming the queue and size.
    q.name = "indexed 4-ary heap";
    q.one_per_disc = true;
    const QueueWords narrow = queue_words(q, 0.0);
    CHECK(narrow.short_heading == "Indexed 4-ary heap, 1,234 entries");
    CHECK(narrow.short_heading.size() < narrow.heading.size());
    CHECK(narrow.short_popped_heading == "Popped");
    q.size = 7;
    CHECK(queue_words(q, 0.0).below.empty());  // every entry shown
    q.shape = QueueShape::ordered_array;
    CHECK(queue_words(q, 0.0).row_caption == "Sorted: the next event is at the end (shown first)");
    q.shape = QueueShape::unordered_array;
    q.top_index = 4;
    CHECK(queue_words(q, 0.0).row_caption ==
          "Stored as pushed; every pop scans for the earliest (slot 4)");
}

TEST_CASE("the queue strip's event labels and times to go are the show's, in the view's order") {
    QueueView q;
    QueuedEvent pair;
    pair.kind = EventKind::pair;
    pair.a = 17;
    pair.b = 18;
    pair.t = 10.42;
    QueuedEvent wall = pair;
    wall.kind = EventKind::ywall;
    wall.a = 5;
    wall.t = 10.0 + 3.1e-5;
    QueuedEvent cell = pair;
    cell.kind = EventKind::cell;
    cell.a = 9;
    cell.t = 9.0;  // already past: no negative time to go
    q.next = {pair, wall};
    q.slots = {wall, pair, cell};
    q.popped = {cell, pair};
    const QueueWords words = queue_words(q, 10.0);
    CHECK(words.next_times == std::vector<std::string>{"0.42", "3.1e-05"});
    CHECK(words.slot_labels == std::vector<std::string>{"5 wall", "17-18", "9 cell"});
    CHECK(words.slot_times == std::vector<std::string>{"3.1e-05", "0.42", "0"});
    CHECK(words.popped_labels == std::vector<std::string>{"9 cell", "17-18"});
    q.slots[0].kind = EventKind::xwall;
    q.slots[0].t = 10.0 + 123.456;
    CHECK(queue_words(q, 10.0).slot_labels.front() == "5 wall");
    CHECK(queue_words(q, 10.0).slot_times.front() == "123");
}

TEST_CASE("the colour key names the colour scale's ends and range in the mode's words") {
    const ColorKeyWords speed = color_key(ColorMode::speed, 0.0, 1.5, 1.0, 1.0);
    CHECK(speed.low == "slow");
    CHECK(speed.high == "fast");
    CHECK(speed.quantity == "speed");
    CHECK(speed.low_value == "0");
    CHECK(speed.high_value == "1.5");
    CHECK(speed.tagged.empty());
    const ColorKeyWords mass = color_key(ColorMode::mass, 0.0, 1.5, 0.001, 12345.0);
    CHECK(mass.low == "light");
    CHECK(mass.high == "heavy");
    CHECK(mass.quantity == "mass (log)");
    CHECK(mass.low_value == "0.001");
    CHECK(mass.high_value == "1.23e+04");
    const ColorKeyWords tag = color_key(ColorMode::tag, 0.0, 1.5, 1.0, 1.0);
    CHECK(tag.tagged == "tagged");
    CHECK(tag.quantity.empty());
    const ColorKeyWords scene = color_key(ColorMode::scene, 0.0, 1.5, 1.0, 1.0);
    CHECK(scene.low.empty());
    CHECK(scene.tagged.empty());
}

TEST_CASE("the queue picture's budget is the video's, the number of events the caller's") {
    const QueueViewLimits limits = queue_picture(7);
    CHECK(limits.next_events == 7);
    CHECK(limits.tree_level_nodes == queue_tree_level_nodes);
    CHECK(limits.tree_levels == queue_tree_levels);
    CHECK(limits.array_slots == queue_array_slots);
}

TEST_CASE("the captions to fit: the scene's caption and every cue, each named where written") {
    LessonPlan lesson;
    CHECK(captions_shown(lesson, "").empty());
    lesson.caption = "Always";
    lesson.captions = {{2.0, "From two", "s.toml", 7}};
    const std::vector<CaptionSource> shown = captions_shown(lesson, "s.toml:3: render.caption");
    REQUIRE(shown.size() == 2);
    CHECK(shown[0].text == "Always");
    CHECK(shown[0].field == "s.toml:3: render.caption");
    CHECK(shown[1].file == "s.toml");
    CHECK(shown[1].line == 7);
    CHECK(shown[1].field == "render.captions.text");
    CHECK(captions_shown(lesson, "")[0].field == "render.caption");
    // The timeline: the caption until the first cue, the intro card fading out at its end.
    CHECK(lesson.caption_at(1.0) == "Always");
    CHECK(lesson.caption_at(2.0) == "From two");
    lesson.intro_seconds = intro_seconds;
    CHECK(lesson.intro_opacity(0.0) == 1.0F);
    CHECK(lesson.intro_opacity(intro_seconds) == 0.0F);
}
