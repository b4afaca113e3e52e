// `collide heap` as a class sees it (collide/show/heap_program.hpp): the words of every step and
// operation, the pacing (panels in lock-step, each operation as long as its longest panel), and
// the frames the painter takes (highlights, an exchange under way, the indexed heap's map).
#include <doctest/doctest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "../support/input_error.hpp"
#include "collide/show/ease.hpp"
#include "collide/show/heap_program.hpp"

using namespace collide;
using collide::show::ease;
using collide::show::HeapProgram;
using collide::test::contains;
using collide::test::input_error_message;

namespace {

const show::HeapPacing pacing{1.0, 0.5, 1.0, 2.0};

HeapProgram lesson(const char* ops, std::vector<pq::QueueKind> kinds,
                   pq::Orientation orientation = pq::Orientation::max, int index_base = 1) {
    return {pq::HeapRecord::operations(pq::parse_heap_ops(ops), kinds, orientation), pacing,
            index_base};
}

/// The time at which step `step` of operation `op` starts, plus `into` of a step.
double time_of(const HeapProgram& t, std::size_t op, std::size_t step, double into) {
    double s = pacing.intro;
    for (std::size_t k = 0; k < op; ++k) {
        std::size_t steps = 0;
        for (const auto& p : t.text()) steps = std::max(steps, p.ops[k].shown.size());
        s += static_cast<double>(steps) * pacing.pace + pacing.pause;
    }
    return s + (static_cast<double>(step) + into) * pacing.pace;
}

bool has_caption(const HeapProgram::PanelText& panel, const std::string& text) {
    for (const HeapProgram::OpText& op : panel.ops) {
        if (std::find(op.captions.begin(), op.captions.end(), text) != op.captions.end())
            return true;
    }
    return false;
}

}  // namespace

TEST_CASE("heap lesson: slides ease in and out") {
    CHECK(ease(0.0) == 0.0F);
    CHECK(ease(1.0) == 1.0F);
    CHECK(ease(0.5) == doctest::Approx(0.5F));
    CHECK(ease(-1.0) == 0.0F);
    CHECK(ease(2.0) == 1.0F);
    CHECK(ease(0.1) < 0.1F);  // slow start
}

TEST_CASE("heap lesson: the lecture's insert of S into a binary heap, in words") {
    const HeapProgram t = lesson("T P R N H O A E I G S", {{pq::QueueFamily::binary, 2}});
    const HeapProgram::PanelText& panel = t.text().front();
    CHECK(panel.title == "binary heap");
    CHECK(panel.start == "binary heap, max-oriented: empty");
    const HeapProgram::OpText& insert_s = panel.ops[10];
    REQUIRE(insert_s.captions.size() == 6);  // appear, (compare, exchange) x 2, compare
    CHECK(insert_s.captions[0] == "insert S at a[11]");
    CHECK(insert_s.captions[1] == "insert S at a[11]; S > H: exchange");
    CHECK(insert_s.captions[2] == "insert S at a[11]; exchange S and H");
    CHECK(insert_s.captions[3] == "insert S at a[11]; S > P: exchange");
    CHECK(insert_s.captions[5] == "insert S at a[11]; S < T: stop");
    CHECK(insert_s.summary == "insert S: 3 compares, 2 exchanges");
}

TEST_CASE("heap lesson: remove-max in words, with 0-based slot names") {
    const HeapProgram t =
        lesson("P Q E X A *", {{pq::QueueFamily::binary, 2}}, pq::Orientation::max, 0);
    const HeapProgram::OpText& remove = t.text().front().ops.back();
    REQUIRE(remove.captions.size() >= 3);
    CHECK(remove.captions[0] == "remove max: exchange the root X with the last, A");
    CHECK(remove.captions[1] == "remove max: X leaves a[4]");
    CHECK(remove.captions[2].rfind("remove max; sink A: ", 0) == 0);
    CHECK(remove.summary.rfind("remove max X: ", 0) == 0);
}

TEST_CASE("heap lesson: the arrays show their scan and their shifts") {
    const HeapProgram t =
        lesson("P Q E A *", {{pq::QueueFamily::unordered, 0}, {pq::QueueFamily::ordered, 0}});
    const HeapProgram::PanelText& unordered = t.text()[0];
    const HeapProgram::PanelText& ordered = t.text()[1];
    CHECK(has_caption(unordered, "insert P at a[1], the end: nothing else to do"));
    CHECK(has_caption(unordered, "scan for the max: Q > P, new max Q"));
    CHECK(has_caption(unordered, "remove max: exchange Q with the last, A"));
    CHECK(has_caption(ordered, "insert E at a[3]; P > E: shift P right"));
    CHECK(has_caption(ordered, "insert E at a[3]; shift Q right to a[3]"));
    CHECK(ordered.ops[2].summary == "insert E: 2 compares, 2 shifts");
}

TEST_CASE("heap lesson: a min-queue's words") {
    const HeapProgram t = lesson("P Q E", {{pq::QueueFamily::dary, 3}}, pq::Orientation::min);
    const HeapProgram::PanelText& panel = t.text().front();
    CHECK(panel.title == "3-heap");
    CHECK(panel.start == "3-heap, min-oriented: empty");
    CHECK(has_caption(panel, "insert E at a[3]; E < P: exchange"));
    CHECK(t.frame_at(0.0).panels[0].title == "3-heap (min)");
}

TEST_CASE("heap lesson: increase-key through the indexed heap's map, in words") {
    const HeapProgram t = lesson("5 9 3 7 * 3^12", {{pq::QueueFamily::indexed, 2}});
    const HeapProgram::PanelText& panel = t.text().front();
    CHECK(panel.title == "indexed binary heap");
    const HeapProgram::OpText& increase = panel.ops.back();
    REQUIRE(increase.captions.size() >= 2);
    CHECK(increase.captions[0] == "increase 3 to 12: qp[] says 3 is at a[3]; set a[3] = 12");
    CHECK(increase.captions[1] == "increase 3 to 12; 12 > 3: a larger key may have to swim up");
    CHECK(t.op_labels().back() == "3^12");
}

TEST_CASE("heap lesson: heapsort builds the heap, then sorts down, in words") {
    const HeapProgram t(pq::HeapRecord::heapsort(pq::parse_sort_keys("S O R T E X A M P L E"),
                                                 pq::Orientation::max),
                        pacing, 1);
    CHECK(t.op_labels() == std::vector<std::string>{"build", "sortdown"});
    const HeapProgram::PanelText& panel = t.text().front();
    CHECK(panel.title == "heapsort");
    CHECK(panel.start == "heapsort 11 keys into ascending order");
    CHECK(panel.ops[0].captions.front() == "build the heap: sink E at a[5]");
    CHECK(panel.ops[0].summary.rfind("heap built: ", 0) == 0);
    CHECK(panel.ops[1].captions.front() ==
          "sortdown: exchange max X with E at a[11]; X is in place");
    CHECK(panel.ops[1].captions[1].rfind("sortdown; sink E: ", 0) == 0);
    CHECK(panel.ops[1].summary.rfind("sortdown done: ", 0) == 0);
    // The sortdown's sinks are recorded, but its exchange already says which key sinks.
    const pq::PanelOp& sortdown = t.record().panels().front().ops[1];
    CHECK(panel.ops[1].shown.size() < sortdown.steps.size());
    for (const std::size_t s : panel.ops[1].shown)
        CHECK(sortdown.steps[s].kind != pq::HeapStep::Kind::sink);
    // The last words give the totals the counters show: one total on screen, not two.
    const view::HeapPanelView end = t.frame_at(t.duration()).panels.front();
    CHECK(end.caption == panel.ops[1].summary);
    CHECK(contains(end.caption, "heapsort in all: " + end.counters[0].value + " compares, " +
                                    end.counters[1].value + " exchanges"));
    CHECK(end.sorted_label == "sorted");
    CHECK(end.returned.empty());  // nothing is removed: the keys stay, sorted
}

TEST_CASE("heap lesson: the keys removed so far, as the trace's returned column") {
    const HeapProgram t = lesson("P Q E * X A M *", {{pq::QueueFamily::binary, 2}});
    using Keys = std::vector<std::string>;
    CHECK(t.frame_at(0.0).panels[0].returned.label == "returned:");
    CHECK(t.frame_at(0.0).panels[0].returned.keys == Keys{"-"});
    CHECK(t.frame_at(t.duration()).panels[0].returned.keys == Keys{"Q", "X"});
    // Mid-way through the first removal the key is still leaving, not yet returned.
    CHECK(t.frame_at(time_of(t, 3, 0, 0.5)).panels[0].returned.keys == Keys{"-"});
    CHECK(t.frame_at(time_of(t, 4, 0, 0.5)).panels[0].returned.keys == Keys{"Q"});
    CHECK(lesson("P Q E", {{pq::QueueFamily::binary, 2}}).frame_at(0.0).panels[0].returned.empty());
}

TEST_CASE("heap lesson: the moments checked for fit are the start, halfway and the end") {
    // `collide heap` and the label tests judge a lesson's fit on these frames alone.
    for (const char* ops : {"P Q E * X A M *", "P Q", "P Q E X A M P L E * * *"}) {
        CAPTURE(ops);
        const HeapProgram t = lesson(ops, {{pq::QueueFamily::binary, 2}});
        const std::vector<double> times = t.fit_check_times();
        REQUIRE(times.size() == 3);
        CHECK(times[0] == 0.0);
        CHECK(times[1] == doctest::Approx(0.5 * t.duration()));
        CHECK(times[2] == t.duration());
        // Before any operation, and after the last one: every token done.
        CHECK_FALSE(t.frame_at(times[0]).current_token);
        REQUIRE(t.frame_at(times[2]).current_token);
        CHECK(*t.frame_at(times[2]).current_token == t.op_labels().size());
    }
    // Questions lengthen the lesson: the moments follow its duration.
    HeapProgram asked = lesson("P Q E X A M", {{pq::QueueFamily::binary, 2}});
    const double before = asked.duration();
    asked.ask_questions(true);
    REQUIRE(asked.duration() > before);
    CHECK(asked.fit_check_times().back() == asked.duration());
}

TEST_CASE("heap lesson: panels move in lock-step, each operation paced by its longest panel") {
    const HeapProgram t =
        lesson("P Q E *", {{pq::QueueFamily::unordered, 0}, {pq::QueueFamily::binary, 2}});
    double expected = pacing.intro + pacing.outro;
    for (std::size_t op = 0; op < 4; ++op) {
        std::size_t steps = 0;
        for (const pq::HeapPanel& p : t.record().panels())
            steps = std::max(steps, p.ops[op].steps.size());
        expected += static_cast<double>(steps) * pacing.pace + pacing.pause;
    }
    CHECK(t.duration() == doctest::Approx(expected));
    CHECK(!t.moment_at(0.0).started);
    CHECK(t.moment_at(0.0).panels[0].state->keys.empty());
    CHECK(*t.moment_at(0.0).panels[0].caption == "unordered array, max-oriented: empty");
    // The first step of the first operation: both panels show P appearing.
    const show::HeapMoment f = t.moment_at(pacing.intro + 0.2);
    CHECK(f.started);
    CHECK(f.op == 0);
    for (const show::HeapPanelMoment& p : f.panels) {
        REQUIRE(p.step != nullptr);
        CHECK(p.step->kind == pq::HeapStep::Kind::appear);
        CHECK(p.progress == doctest::Approx(0.2));
    }
    // Counters never go down.
    std::uint64_t last = 0;
    for (double s = 0.0; s <= t.duration(); s += 0.05) {
        const std::uint64_t c = t.moment_at(s).panels[1].state->compares;
        CHECK(c >= last);
        last = c;
    }
    CHECK(t.name() == "unordered array, binary heap");
}

TEST_CASE("heap lesson: the pacing for a pace, and a pace of zero is refused") {
    const show::HeapPacing slow = show::heap_pacing(2.0);
    CHECK(slow.pace == 2.0);
    CHECK(slow.pause == doctest::Approx(1.2));
    CHECK(slow.intro == doctest::Approx(3.0));
    CHECK(slow.outro == doctest::Approx(6.0));
    const show::HeapPacing fast = show::heap_pacing(0.2);
    CHECK(fast.intro == 1.0);
    CHECK(fast.outro == 2.5);
    const auto record = pq::HeapRecord::operations(
        pq::parse_heap_ops("P"), std::vector<pq::QueueKind>{{pq::QueueFamily::binary, 2}},
        pq::Orientation::max);
    CHECK(contains(input_error_message([&] {
                       (void)HeapProgram(record, {0.0, 0.1, 0.0, 0.0});
                   }),
                   "pace: must be > 0"));
}

TEST_CASE("heap lesson: frames hold tokens, highlights, an exchange under way, counters, titles") {
    const HeapProgram t = lesson("P Q", {{pq::QueueFamily::binary, 2}});
    const view::HeapFrameView intro = t.frame_at(0.0);
    CHECK(!intro.current_token);
    CHECK(intro.tokens == std::vector<std::string>{"P", "Q"});
    REQUIRE(intro.panels.size() == 1);
    CHECK(intro.panels[0].slots.empty());
    CHECK(intro.panels[0].title == "binary heap (max)");
    CHECK(intro.panels[0].capacity == 2);
    CHECK(intro.panels[0].tree);

    // insert Q: appear, compare Q with P, exchange.
    const view::HeapFrameView compare = t.frame_at(time_of(t, 1, 1, 0.5));
    REQUIRE(compare.current_token);
    CHECK(*compare.current_token == 1);
    const auto& c = compare.panels[0];
    CHECK(c.slots[0].mark == view::SlotMark::compared);
    CHECK(c.slots[1].mark == view::SlotMark::compared);
    CHECK(c.caption == "insert Q at a[2]; Q > P: exchange");
    CHECK(c.counters == std::vector<view::HeapCounter>{{"compares", "1"}, {"exchanges", "0"}});

    const view::HeapPanelView x = t.frame_at(time_of(t, 1, 2, 0.4)).panels[0];
    REQUIRE(x.swap);
    CHECK(x.swap->a == 1);
    CHECK(x.swap->b == 0);
    CHECK(x.swap->t == doctest::Approx(ease(0.5)));  // the slide takes 80 % of the step
    CHECK(x.slots[0].mark == view::SlotMark::moving);

    const view::HeapFrameView end = t.frame_at(t.duration());
    CHECK(*end.current_token == 2);  // all done
    CHECK(end.panels[0].slots[0].key == "Q");
    CHECK(!end.panels[0].swap);
    CHECK(end.panels[0].caption == "insert Q: 1 compare, 1 exchange");
    CHECK(t.widest_key() == "W");  // one-letter keys: the default width
}

TEST_CASE("heap lesson: the indexed heap's map, in handle order, with the exchange lit") {
    const HeapProgram t = lesson("5 9 3", {{pq::QueueFamily::indexed, 2}}, pq::Orientation::max, 0);
    // insert 9: appear, compare 9 with 5, exchange (step 2).
    const view::HeapPanelView p = t.frame_at(time_of(t, 1, 2, 0.5)).panels[0];
    REQUIRE(p.show_map);
    REQUIRE(p.map.size() == 2);
    CHECK(p.map[0].key == "5");
    CHECK(p.map[0].index == "0");
    CHECK(p.map[1].key == "9");
    CHECK(p.map[1].index == "1");
    CHECK(p.map[0].updated);
    CHECK(p.map[1].updated);
    // The slide over (the step's rest), the keys have landed: the lit entries say where.
    const view::HeapPanelView rest = t.frame_at(time_of(t, 1, 2, 0.95)).panels[0];
    REQUIRE(rest.swap);
    CHECK(rest.swap->t == 1.0F);
    CHECK(rest.map[0].index == "1");
    CHECK(rest.map[1].index == "0");
    CHECK(rest.map[0].updated);
    const view::HeapPanelView end = t.frame_at(t.duration()).panels[0];
    CHECK(end.map[0].index == "1");  // 5 went down to slot 1
    CHECK(!end.map[0].updated);
    CHECK(end.index_base == 0);
}

TEST_CASE("heap lesson: heapsort sets the sorted part apart, arrays are not trees") {
    const HeapProgram sort(
        pq::HeapRecord::heapsort(pq::parse_sort_keys("S O R T"), pq::Orientation::max), pacing, 1);
    const view::HeapPanelView end = sort.frame_at(sort.duration()).panels[0];
    CHECK(end.heap_size == 0);
    CHECK(end.title == "heapsort (ascending)");
    const HeapProgram arrays = lesson("Q P *", {{pq::QueueFamily::ordered, 0}});
    const view::HeapPanelView a = arrays.frame_at(arrays.duration()).panels[0];
    CHECK(!a.tree);
    CHECK(a.heap_size == SIZE_MAX);
    CHECK(a.counters[1] == view::HeapCounter{"shifts", "1"});
}
