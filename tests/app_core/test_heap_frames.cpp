// `collide heap`'s frames as values (heap_frames.hpp): what the model's steps become on screen.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "heap_frames.hpp"

using namespace collide;
using collide::app::ease;
using collide::app::heap_frame_at;
using collide::app::HeapShow;

namespace {

const pq::LessonPacing pacing{1.0, 0.5, 1.0, 2.0};

pq::LessonTimeline lesson(const char* ops, std::vector<pq::QueueKind> kinds) {
    return pq::LessonTimeline::operations(pq::parse_lesson_ops(ops), kinds, pq::Orientation::max, 1,
                                          pacing);
}

/// The time at which panel 0 starts step `step` of operation `op`, plus `into` of a step.
double time_of(const pq::LessonTimeline& t, std::size_t op, std::size_t step, double into) {
    double s = pacing.intro;
    for (std::size_t k = 0; k < op; ++k) {
        std::size_t steps = 0;
        for (const auto& p : t.panels()) steps = std::max(steps, p.ops[k].steps.size());
        s += static_cast<double>(steps) * pacing.pace + pacing.pause;
    }
    return s + (static_cast<double>(step) + into) * pacing.pace;
}

}  // namespace

TEST_CASE("heap frames: slides ease in and out") {
    CHECK(ease(0.0) == 0.0F);
    CHECK(ease(1.0) == 1.0F);
    CHECK(ease(0.5) == doctest::Approx(0.5F));
    CHECK(ease(-1.0) == 0.0F);
    CHECK(ease(2.0) == 1.0F);
    CHECK(ease(0.1) < 0.1F);  // slow start
}

TEST_CASE("heap frames: tokens, highlights, an exchange under way, counters and titles") {
    const pq::LessonTimeline t = lesson("P Q", {{pq::QueueFamily::binary, 2}});
    HeapShow show;
    const render::HeapFrameView intro = heap_frame_at(t, show, 0.0);
    CHECK(!intro.current_token);
    CHECK(intro.tokens == std::vector<std::string>{"P", "Q"});
    REQUIRE(intro.panels.size() == 1);
    CHECK(intro.panels[0].slots.empty());
    CHECK(intro.panels[0].title == "binary heap (max)");
    CHECK(intro.panels[0].capacity == 2);
    CHECK(intro.panels[0].tree);

    // insert Q: appear, compare Q with P, exchange.
    const render::HeapFrameView compare = heap_frame_at(t, show, time_of(t, 1, 1, 0.5));
    REQUIRE(compare.current_token);
    CHECK(*compare.current_token == 1);
    const auto& c = compare.panels[0];
    CHECK(c.slots[0].mark == render::SlotMark::compared);
    CHECK(c.slots[1].mark == render::SlotMark::compared);
    CHECK(c.caption == "insert Q at a[2]; Q > P: exchange");
    CHECK(c.counters == std::vector<std::string>{"compares 1", "exchanges 0"});

    const render::HeapPanelView x = heap_frame_at(t, show, time_of(t, 1, 2, 0.4)).panels[0];
    REQUIRE(x.swap);
    CHECK(x.swap->a == 1);
    CHECK(x.swap->b == 0);
    CHECK(x.swap->t == doctest::Approx(ease(0.5)));  // the slide takes 80 % of the step
    CHECK(x.slots[0].mark == render::SlotMark::moving);

    const render::HeapFrameView end = heap_frame_at(t, show, t.duration());
    CHECK(*end.current_token == 2);  // all done
    CHECK(end.panels[0].slots[0].key == "Q");
    CHECK(!end.panels[0].swap);
}

TEST_CASE("heap frames: the indexed heap's map, in handle order, with the exchange lit") {
    const pq::LessonTimeline t = lesson("5 9 3", {{pq::QueueFamily::indexed, 2}});
    HeapShow show;
    show.index_base = 0;
    // insert 9: appear, compare 9 with 5, exchange (step 2).
    const render::HeapPanelView p = heap_frame_at(t, show, time_of(t, 1, 2, 0.5)).panels[0];
    REQUIRE(p.show_map);
    REQUIRE(p.map.size() == 2);
    CHECK(p.map[0].key == "5");
    CHECK(p.map[0].index == "0");
    CHECK(p.map[1].key == "9");
    CHECK(p.map[1].index == "1");
    CHECK(p.map[0].updated);
    CHECK(p.map[1].updated);
    // The slide over (the step's rest), the keys have landed: the lit entries say where.
    const render::HeapPanelView rest = heap_frame_at(t, show, time_of(t, 1, 2, 0.95)).panels[0];
    REQUIRE(rest.swap);
    CHECK(rest.swap->t == 1.0F);
    CHECK(rest.map[0].index == "1");
    CHECK(rest.map[1].index == "0");
    CHECK(rest.map[0].updated);
    const render::HeapPanelView end = heap_frame_at(t, show, t.duration()).panels[0];
    CHECK(end.map[0].index == "1");  // 5 went down to slot 1
    CHECK(!end.map[0].updated);
}

TEST_CASE("heap frames: heapsort sets the sorted part apart, arrays are not trees") {
    const pq::LessonTimeline sort = pq::LessonTimeline::heapsort(pq::parse_sort_keys("S O R T"),
                                                                 pq::Orientation::max, 1, pacing);
    HeapShow show;
    show.sort = true;
    const render::HeapPanelView end = heap_frame_at(sort, show, sort.duration()).panels[0];
    CHECK(end.heap_size == 0);
    CHECK(end.title == "heapsort (ascending)");
    const pq::LessonTimeline arrays = lesson("Q P *", {{pq::QueueFamily::ordered, 0}});
    const render::HeapPanelView a = heap_frame_at(arrays, HeapShow{}, arrays.duration()).panels[0];
    CHECK(!a.tree);
    CHECK(a.heap_size == SIZE_MAX);
    CHECK(a.counters[1] == "shifts 1");
}
