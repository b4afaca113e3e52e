// The instant replay (collide/show/replay.hpp, timeline.hpp): where a replay sits on the
// timeline, the simulation clock frozen during it, and what the two panels draw: the ghosts of
// the failing disc at steps k and k + 1 exactly where the engine had it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "collide/show/replay.hpp"
#include "collide/show/timeline.hpp"
#include "collide/sim/time_engine.hpp"

using namespace collide;
using namespace collide::show;

namespace {

/// A disc through a resting heavy one in step 1 (0.1 .. 0.2), no check seeing them touch.
Scene head_on() {
    Scene s;
    s.name = "head-on";
    s.box = Box{1.0, 1.0, Boundary::walls};
    const auto disc = [](Vec2 p, Vec2 v, double mass) {
        Disc d;
        d.position = p;
        d.velocity = v;
        d.radius = 0.01;
        d.mass = mass;
        return d;
    };
    s.discs = {disc({0.35, 0.5}, {1.0, 0.0}, 1.0), disc({0.5, 0.5}, {0.0, 0.0}, 1e5)};
    return s;
}

ReplayFailure first_failure(const Scene& scene, double dt) {
    EngineOptions options;
    options.engine = EngineKind::time;
    options.dt = dt;
    sim::TimeEngine engine(scene, options);
    engine.advance_to(1.0);
    REQUIRE(!engine.failures().empty());
    ReplayFailure failure;
    failure.step = engine.failures().front();
    failure.dt = dt;
    return failure;
}

TimelineScript script_with_replay(std::int64_t after, double seconds) {
    TimelineScript script;
    script.fps = 10;
    script.frames = 100;
    script.card_seconds = 1.0;
    script.caption = "Always";
    script.cues = {{2.0, "Hold", 1.0}};
    script.replays = {{after, seconds, "Replayed"}};
    script.epilogue_seconds = 1.0;
    return script;
}

}  // namespace

TEST_CASE("a replay follows the first frame that shows its simulation frame, frozen on it") {
    // Card 0..10 (sim 0), run from sim 1 at frame 10; the hold at 2 s (frame 20) freezes sim 10.
    const Timeline timeline = build_timeline(script_with_replay(15, 2.0));
    std::int64_t replays = 0;
    for (const Segment& s : timeline.segments) {
        if (s.kind != SegmentKind::replay) continue;
        ++replays;
        CHECK_FALSE(s.moves);
        CHECK(s.sim_frame == 15);
        CHECK(s.caption == "Replayed");
        CHECK(s.frames() == 20);
        // The frame before shows simulation frame 15 running, for the first time.
        CHECK(timeline.sim_frame(s.first_frame - 1) == 15);
        CHECK(timeline.segment_at(s.first_frame - 1).moves);
        for (std::int64_t k = s.first_frame; k < s.end_frame; ++k)
            CHECK(timeline.sim_frame(k) == 15);
        CHECK(timeline.sim_frame(s.end_frame) == 16);  // then it resumes
    }
    CHECK(replays == 1);
    // No gap, segments in order.
    for (std::size_t i = 1; i < timeline.segments.size(); ++i)
        CHECK(timeline.segments[i].first_frame == timeline.segments[i - 1].end_frame);
    CHECK(timeline.frame_count() == 100);
}

TEST_CASE("a replay waits until the caption just shown has been read, holding the picture") {
    TimelineScript script = script_with_replay(12, 2.0);
    const std::string words = "Each step moves a disc five times the thickness of a barrier";
    script.cues = {{2.0, words, 0.0}};
    // Card 0..10 (sim 0); sim 1 at frame 10, the caption from frame 20 (sim 11), sim 12 at 21.
    const Timeline timeline = build_timeline(script);
    const auto replay =
        std::find_if(timeline.segments.begin(), timeline.segments.end(),
                     [](const Segment& s) { return s.kind == SegmentKind::replay; });
    REQUIRE(replay != timeline.segments.end());
    REQUIRE(replay != timeline.segments.begin());
    const Segment& lead = *std::prev(replay);
    CHECK(lead.kind == SegmentKind::hold);
    CHECK(lead.caption == words);
    CHECK_FALSE(lead.moves);
    CHECK(lead.sim_frame == 12);
    CHECK(timeline.sim_frame(lead.first_frame - 1) == 12);  // it follows the failure's frame
    CHECK(replay->sim_frame == 12);
    CHECK(replay->start - 2.0 == doctest::Approx(caption_reading_seconds(words)));
    CHECK(caption_reading_seconds(words) > 1.5);
    CHECK(timeline.sim_frame(replay->end_frame) == 13);
    // A caption read long enough before gets no hold: the replay follows the failure's frame.
    const Timeline read = build_timeline(script_with_replay(40, 2.0));
    const auto later = std::find_if(read.segments.begin(), read.segments.end(),
                                    [](const Segment& s) { return s.kind == SegmentKind::replay; });
    REQUIRE(later != read.segments.end());
    CHECK(read.segment_at(later->first_frame - 1).moves);
}

TEST_CASE("caption reading time: about 200 words a minute, between 1.5 s and 4 s") {
    CHECK(caption_reading_seconds("") == 1.5);
    CHECK(caption_reading_seconds("Hold") == 1.5);
    CHECK(caption_reading_seconds("one two three four five six seven eight") ==
          doctest::Approx(2.9));
    CHECK(caption_reading_seconds(std::string(200, 'a') + std::string(" b").append(60, ' ')) ==
          1.5);
    std::string many;
    for (int i = 0; i < 40; ++i) many += "word ";
    CHECK(caption_reading_seconds(many) == 4.0);
}

TEST_CASE("a replay that would run into the epilogue, or a frame never shown, is left out") {
    const Timeline late = build_timeline(script_with_replay(70, 2.0));
    for (const Segment& s : late.segments) CHECK(s.kind != SegmentKind::replay);
    const Timeline never = build_timeline(script_with_replay(5000, 2.0));
    for (const Segment& s : never.segments) CHECK(s.kind != SegmentKind::replay);
}

TEST_CASE("first_frame_after_step: the first frame whose time has taken step k + 1") {
    FrameClock clock;
    clock.interval = 0.04;
    clock.count = 100;
    clock.last_time = 99 * 0.04;
    CHECK(first_frame_after_step(1, 0.1, clock) == 5);  // t = 0.2 is frame 5
    CHECK(first_frame_after_step(0, 0.1, clock) == 3);  // t = 0.1: frame 3 (0.12) is the first
    CHECK(first_frame_after_step(0, 0.01, clock) == 1);
    CHECK(first_frame_after_step(500, 0.1, clock) == -1);
}

TEST_CASE("replay frames: the ghosts at steps k and k + 1 are the engine's states") {
    const Scene scene = head_on();
    const double dt = 0.1;
    const ReplayFailure failure = first_failure(scene, dt);
    CHECK(failure.step.step == 1);
    // The engine's states at k dt and (k + 1) dt.
    EngineOptions options;
    options.engine = EngineKind::time;
    options.dt = dt;
    sim::TimeEngine engine(scene, options);
    engine.advance_to(0.1);
    const Vec2 at_k = engine.snapshot().discs[0].position;
    engine.advance_to(0.2);
    const Vec2 at_k1 = engine.snapshot().discs[0].position;

    const auto has_ghost = [](const ReplayView& view, Vec2 where, bool filled) {
        for (const GhostDisc& g : view.ghosts) {
            if (g.filled == filled && std::abs(g.where.x - where.x) < 1e-12 &&
                std::abs(g.where.y - where.y) < 1e-12)
                return true;
        }
        return false;
    };
    // Zooming in: step k is shown, k + 1 not yet.
    const ReplayViews start = replay_views(failure, scene.box, 0.1);
    CHECK(has_ghost(start.time_driven, at_k, false));
    CHECK_FALSE(has_ghost(start.time_driven, at_k1, false));
    CHECK(start.zoom.magnification > 1.0);
    // Held: both checks, the jump between them and where they touched.
    const ReplayViews held =
        replay_views(failure, scene.box, 0.5 * (replay_slow_end + replay_hold_end));
    CHECK(has_ghost(held.time_driven, at_k, false));
    CHECK(has_ghost(held.time_driven, at_k1, false));
    REQUIRE(!held.time_driven.lines.empty());
    CHECK(held.time_driven.lines[0].from.x == doctest::Approx(at_k.x));
    CHECK(held.time_driven.lines[0].to.x == doctest::Approx(at_k1.x));
    CHECK(held.time_driven.lines[0].failure);
    const BoxZoom target = replay_target(failure, scene.box);
    CHECK(held.zoom.magnification == doctest::Approx(target.magnification));
    CHECK(held.zoom.centre.x == doctest::Approx(target.centre.x));
    // The zoom holds the move: both states lie in the enlarged view.
    const double half = 0.5 / target.magnification;
    CHECK(std::abs(at_k.x - target.centre.x) < half);
    CHECK(std::abs(at_k1.x - target.centre.x) < half);
    // Halfway through the slow move the disc overlaps the other one: in the failure colour.
    const double middle =
        replay_zoom_in + failure.step.contact / dt * (replay_slow_end - replay_zoom_in) + 0.05;
    const ReplayViews moving = replay_views(failure, scene.box, middle);
    bool overlapping = false;
    for (const GhostDisc& g : moving.time_driven.ghosts)
        overlapping = overlapping || (g.filled && g.failure);
    CHECK(overlapping);
    // The end: back to the whole box.
    const ReplayViews end = replay_views(failure, scene.box, replay_seconds);
    CHECK(end.zoom.magnification == doctest::Approx(1.0));
}

TEST_CASE("replay words: the caption, the checks, and the event-driven prediction") {
    const Scene scene = head_on();
    ReplayFailure failure = first_failure(scene, 0.1);
    CHECK(replay_caption(failure) ==
          "Between two checks the disc jumped through: no overlap was ever seen");
    PredictedHit hit;
    hit.time = 0.13;
    hit.a = {0.49, 0.5};
    hit.b = {0.51, 0.5};
    failure.predicted = hit;
    const ReplayViews held = replay_views(failure, scene.box, replay_hold_end - 0.1);
    std::vector<std::string> time_words;
    for (const BoxLabel& l : held.time_driven.labels) time_words.push_back(l.text);
    CHECK(time_words.at(0) == "check t = 0.1");
    CHECK(std::find(time_words.begin(), time_words.end(), "check t = 0.2") != time_words.end());
    CHECK(std::find(time_words.begin(), time_words.end(), "hit t = 0.13, unseen") !=
          time_words.end());
    REQUIRE(!held.event_driven.labels.empty());
    CHECK(held.event_driven.labels[0].text == "predicted hit t = 0.13");
    CHECK(held.event_driven.ghosts.size() == 2);
    // Without a predicted hit (the event-driven run had parted), the panel says why it is empty.
    ReplayFailure parted = failure;
    parted.predicted.reset();
    const ReplayViews apart = replay_views(parted, scene.box, replay_hold_end - 0.1);
    REQUIRE(apart.event_driven.labels.size() == 2);
    CHECK(apart.event_driven.labels[0].text == parted_words[0]);
    CHECK(apart.event_driven.labels[1].text == parted_words[1]);
    CHECK(apart.event_driven.ghosts.empty());
    const std::vector<TimelineReplay> cues = replay_cues({failure});
    REQUIRE(cues.size() == 1);
    CHECK(cues[0].seconds == replay_seconds);
    CHECK(cues[0].caption == replay_caption(failure));
}
