// The lesson timeline (collide/show/timeline.hpp): segments in order without gaps, the
// simulation clock frozen outside run segments, every simulation frame shown once in order.
#include <doctest/doctest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "collide/show/collision.hpp"
#include "collide/show/collision_program.hpp"
#include "collide/show/collision_summary.hpp"
#include "collide/show/still_timeline.hpp"
#include "collide/show/timeline.hpp"

using namespace collide;
using namespace collide::show;

namespace {

/// The invariants every timeline keeps, checked frame by frame.
void check_invariants(const Timeline& timeline, std::int64_t frames) {
    REQUIRE(!timeline.segments.empty());
    CHECK(timeline.frame_count() == frames);
    CHECK(timeline.segments.front().first_frame == 0);
    for (std::size_t i = 0; i < timeline.segments.size(); ++i) {
        const Segment& s = timeline.segments[i];
        CHECK(s.frames() > 0);
        CHECK(s.start == doctest::Approx(static_cast<double>(s.first_frame) / timeline.fps));
        CHECK(s.end == doctest::Approx(static_cast<double>(s.end_frame) / timeline.fps));
        if (i > 0) CHECK(s.first_frame == timeline.segments[i - 1].end_frame);  // no gap
        // Only a run moves (a card beneath which the simulation runs is the old behaviour).
        if (s.kind == SegmentKind::hold || s.kind == SegmentKind::replay ||
            s.kind == SegmentKind::epilogue || s.kind == SegmentKind::question ||
            s.kind == SegmentKind::reveal)
            CHECK_FALSE(s.moves);
    }
    // The simulation frames shown: 0, then each frame the previous or the next one.
    std::int64_t previous = -1;
    for (std::int64_t k = 0; k < frames; ++k) {
        const Segment& s = timeline.segment_at(k);
        CHECK(s.first_frame <= k);
        CHECK(k < s.end_frame);
        const std::int64_t shown = timeline.sim_frame(k);
        if (k == 0) {
            CHECK(shown == 0);
        } else if (s.moves) {
            CHECK(shown == previous + 1);
        } else {
            CHECK(shown == previous);  // frozen: the clock does not move
        }
        previous = shown;
    }
    CHECK(timeline.last_sim_frame() == previous);
}

TimelineScript lesson_script() {
    TimelineScript script;
    script.fps = 10;
    script.frames = 100;  // 10 s
    script.card_seconds = 2.0;
    script.card_title = "Title";
    script.caption = "Always";
    script.cues = {{4.0, "Hold here", 1.5}, {7.0, "Later", 0.0}};
    script.epilogue_seconds = 2.0;
    script.epilogue_caption = "Summary";
    return script;
}

}  // namespace

TEST_CASE("a run-only timeline shows simulation frame k at video frame k") {
    const Timeline timeline = running_timeline(30, 45, "Words");
    check_invariants(timeline, 45);
    REQUIRE(timeline.segments.size() == 1);
    CHECK(timeline.segments[0].kind == SegmentKind::run);
    CHECK(timeline.segments[0].caption == "Words");
    for (std::int64_t k = 0; k < 45; ++k) CHECK(timeline.sim_frame(k) == k);
    CHECK(timeline.sim_frame_count() == 45);
}

TEST_CASE("card, runs split at captions, a hold and the epilogue, in order, no gap") {
    const Timeline timeline = build_timeline(lesson_script());
    check_invariants(timeline, 100);
    std::vector<SegmentKind> kinds;
    std::vector<std::string> captions;
    for (const Segment& s : timeline.segments) {
        kinds.push_back(s.kind);
        captions.push_back(s.caption);
    }
    const std::vector<SegmentKind> expected{SegmentKind::card, SegmentKind::run,
                                            SegmentKind::hold, SegmentKind::run,
                                            SegmentKind::run,  SegmentKind::epilogue};
    CHECK(kinds == expected);
    CHECK(captions == std::vector<std::string>{"Title", "Always", "Hold here", "Hold here", "Later",
                                               "Summary"});
    const std::vector<Segment>& s = timeline.segments;
    // The card: frames 0..19 frozen on simulation frame 0; the run starts with frame 1.
    CHECK(s[0].end_frame == 20);
    CHECK_FALSE(s[0].moves);
    CHECK(s[0].sim_frame == 0);
    CHECK(s[1].sim_frame == 1);
    // The hold from 4 s for 1.5 s, on the state the run showed last.
    CHECK(s[2].first_frame == 40);
    CHECK(s[2].end_frame == 55);
    CHECK(s[2].sim_frame == s[1].last_sim_frame());
    CHECK(s[3].sim_frame == s[2].sim_frame + 1);
    // The caption at 7 s, the epilogue over the last 2 s on the final state.
    CHECK(s[4].first_frame == 70);
    CHECK(s[5].first_frame == 80);
    CHECK(s[5].sim_frame == s[4].last_sim_frame());
    // Simulation frames 0..45: 100 frames less 20 + 15 + 20 frozen, and frame 0 under the card.
    CHECK(timeline.sim_frame_count() == 100 - 20 - 15 - 20 + 1);
}

TEST_CASE("a card beneath which the simulation runs moves with it") {
    TimelineScript script = lesson_script();
    script.card_waits = false;
    script.cues.clear();
    script.epilogue_seconds = 0.0;
    const Timeline timeline = build_timeline(script);
    check_invariants(timeline, 100);
    REQUIRE(timeline.segments.size() == 2);
    CHECK(timeline.segments[0].moves);
    for (std::int64_t k = 0; k < 100; ++k) CHECK(timeline.sim_frame(k) == k);
}

TEST_CASE("frozen stretches never take the whole video, nor overlap") {
    TimelineScript script = lesson_script();
    script.frames = 5;  // half a second: card and epilogue would cover it all
    Timeline timeline = build_timeline(script);
    check_invariants(timeline, 5);
    bool runs = false;
    for (const Segment& s : timeline.segments) runs = runs || s.kind == SegmentKind::run;
    CHECK(runs);
    // A hold inside the card starts after it; two holds one after the other, not on top.
    script = lesson_script();
    script.cues = {{1.0, "In the card", 1.0}, {2.5, "Next", 1.0}};
    timeline = build_timeline(script);
    check_invariants(timeline, 100);
    REQUIRE(timeline.segments.size() >= 3);
    CHECK(timeline.segments[1].kind == SegmentKind::hold);
    CHECK(timeline.segments[1].first_frame == 20);
    CHECK(timeline.segments[1].end_frame == 30);
    CHECK(timeline.segments[2].kind == SegmentKind::hold);
    CHECK(timeline.segments[2].caption == "Next");
    CHECK(timeline.segments[2].end_frame == 40);
    // A hold into the epilogue is cut short there.
    script = lesson_script();
    script.cues = {{7.5, "Too long", 5.0}};
    timeline = build_timeline(script);
    check_invariants(timeline, 100);
    CHECK(timeline.segment_at(79).kind == SegmentKind::hold);
    CHECK(timeline.segment_at(80).kind == SegmentKind::epilogue);
}

TEST_CASE("a question freezes the picture while the class thinks, then its reveal, then the run") {
    TimelineScript script = lesson_script();
    script.frames = 150;  // 15 s, the epilogue from 13 s
    script.cues = {{6.0, "Hold here", 0.5}};
    // One during the card (it waits for the card's end), one at the hold (it waits for its
    // end), one too late for the epilogue (left out).
    script.questions = {{1.0, 2.0, 1.0, "Which first?", "A first"},
                        {6.0, 2.5, 1.5, "How many?", "Three"},
                        {12.0, 2.0, 1.0, "Too late?", "Yes"}};
    const Timeline timeline = build_timeline(script);
    check_invariants(timeline, 150);
    CHECK(questions_asked(timeline) == std::vector<int>{0, 1});
    std::vector<const Segment*> asked;
    for (const Segment& s : timeline.segments) {
        if (s.kind == SegmentKind::question) asked.push_back(&s);
    }
    REQUIRE(asked.size() == 2);
    for (const Segment* q : asked) {
        CHECK_FALSE(q->moves);
        const Segment& reveal = timeline.segment_at(q->end_frame);
        CHECK(reveal.kind == SegmentKind::reveal);
        CHECK(reveal.question == q->question);
        CHECK(reveal.sim_frame == q->sim_frame);  // the same picture, now with its answer
        const Segment& after = timeline.segment_at(reveal.end_frame);
        CHECK(after.sim_frame == q->sim_frame + 1);  // the run goes on from there
    }
    // The first: 2 s after the card, then 1 s of its answer.
    CHECK(asked[0]->first_frame == 20);
    CHECK(asked[0]->end_frame == 40);
    CHECK(asked[0]->caption == "Which first?");
    CHECK(timeline.segment_at(40).caption == "A first");
    CHECK(timeline.segment_at(40).end_frame == 50);
    CHECK(timeline.segment_at(50).kind == SegmentKind::run);
    // The second after the hold (6..6.5 s): 2.5 s, then 1.5 s.
    CHECK(timeline.segment_at(60).kind == SegmentKind::hold);
    CHECK(asked[1]->first_frame == 65);
    CHECK(asked[1]->frames() == 25);
    CHECK(asked[1]->caption == "How many?");
    CHECK(timeline.segment_at(asked[1]->end_frame).frames() == 15);
    CHECK(timeline.segment_at(asked[1]->end_frame).caption == "Three");
}

TEST_CASE("a question never overlaps a hold or a replay, and leaves the epilogue alone") {
    TimelineScript script = lesson_script();
    script.cues = {{3.0, "Hold here", 2.0}};
    script.questions = {{4.0, 2.0, 1.0, "Q", "A"}};
    Timeline timeline = build_timeline(script);
    check_invariants(timeline, 100);
    // The hold takes 3..5 s: the question waits for its end.
    REQUIRE(questions_asked(timeline) == std::vector<int>{0});
    const Segment* q = nullptr;
    for (const Segment& s : timeline.segments)
        if (s.kind == SegmentKind::question) q = &s;
    REQUIRE(q != nullptr);
    CHECK(q->first_frame == 50);
    // A replay whose frame falls on the question is left out; the question stays.
    script.cues.clear();
    script.questions = {{3.0, 2.0, 1.0, "Q", "A"}};
    script.replays = {{9, 1.0, "Replay"}};  // simulation frame 9: shown at video frame 28
    timeline = build_timeline(script);
    check_invariants(timeline, 100);
    CHECK(questions_asked(timeline) == std::vector<int>{0});
    for (const Segment& s : timeline.segments) CHECK(s.kind != SegmentKind::replay);
    // No room before the epilogue: no question at all, and the timeline is as without it.
    script = lesson_script();
    script.questions = {{7.5, 2.0, 1.0, "Q", "A"}};
    timeline = build_timeline(script);
    CHECK(questions_asked(timeline).empty());
    CHECK(timeline.segments.size() == build_timeline(lesson_script()).segments.size());
}

TEST_CASE("captions on frames: a cue shows from the first frame at or after its time") {
    TimelineScript script;
    script.fps = 15;
    script.frames = 150;
    script.caption = "Always";
    script.cues = {{2.0, "From two", 0.0}, {1.0 / 3.0 + 4.0, "Odd time", 0.0}};
    const Timeline timeline = build_timeline(script);
    check_invariants(timeline, 150);
    LessonPlan lesson;
    lesson.caption = "Always";
    lesson.captions = {{2.0, "From two", "", 0}, {1.0 / 3.0 + 4.0, "Odd time", "", 0}};
    for (std::int64_t k = 0; k < 150; ++k) {
        CHECK(timeline.segment_at(k).caption == lesson.caption_at(static_cast<double>(k) / 15.0));
    }
}

TEST_CASE("the epilogue's card: the final figures side by side and the work ratio") {
    Measurements time;
    time.missed_collisions = 48;
    time.overlapping_pairs = 3;
    time.discs_overlapped = 11;  // seen overlapping in earlier frames, parted since
    time.escaped = 2;
    time.collisions_pair = 100;
    time.overlap_checks = 400000;
    Measurements event;
    event.collisions_pair = 140;
    event.collisions_wall = 10;
    event.queue.pushes = 1500;
    event.queue.pops = 500;
    const SummaryCard card = summary_card({{time, true}, {event, false}}, true, "t = 3.000");
    CHECK(card.title == "In the end, at t = 3.000");
    CHECK(card.columns == std::vector<std::string>{"Time-driven", "Event-driven"});
    REQUIRE(card.rows.size() == 5);  // missed, overlapped, tunnelled, collisions, work
    CHECK(card.rows[0].values == std::vector<std::string>{"48", "0"});
    // Every disc that overlapped in any frame, not the 3 pairs overlapping at the end.
    CHECK(card.rows[1].label == "discs that ever overlapped");
    CHECK(card.rows[1].values == std::vector<std::string>{"11", "0"});
    CHECK(card.rows[2].label == "discs that tunnelled");
    CHECK(card.rows[2].values == std::vector<std::string>{"2", "0"});  // out through the wall
    CHECK(card.rows[3].values == std::vector<std::string>{"100", "150"});
    // The cost graphic's unit: overlap tests against predictions plus queue operations, in the
    // panels' format (thousands separators, no "400.0k").
    CHECK(card.rows[4].values == std::vector<std::string>{"400,000", "2,000"});
    CHECK(card.footer == "Event-driven: 200x less work");
    CHECK(card.footer ==
          "Event-driven: " + work_ratio(work_done(time, true), work_done(event, false)));
    // A periodic box has nothing to leave; one panel has nothing to compare.
    CHECK(summary_card({{time, true}, {event, false}}, false, "t").rows.size() == 4);
    // Through a barrier of immovable discs (the engine counts the escaped ones in it too): the
    // card counts them, in a periodic box as well.
    time.escaped = 0;
    time.tunnelled = 1234;
    for (const bool walls : {true, false}) {
        const SummaryCard through = summary_card({{time, true}, {event, false}}, walls, "t");
        REQUIRE(through.rows.size() == 5);
        CHECK(through.rows[2].label == "discs that tunnelled");
        CHECK(through.rows[2].values == std::vector<std::string>{"1,234", "0"});
    }
    CHECK(summary_card({{event, false}}, false, "t").footer.empty());
    // A 3D scene's card names spheres.
    const SummaryCard spheres = summary_card({{time, true}, {event, false}}, true, "t", true);
    CHECK(spheres.rows[1].label == "spheres that ever overlapped");
    CHECK(spheres.rows[2].label == "spheres that tunnelled");
    CHECK(summary_opacity(0.0) == 0.0F);
    CHECK(summary_opacity(0.25) == doctest::Approx(0.5));
    CHECK(summary_opacity(2.0) == 1.0F);
}

TEST_CASE("the card and its caption say why the collision counts differ, in the panels' words") {
    Measurements event;
    event.collisions_pair = 127;
    Measurements time;
    time.collisions_pair = 106;  // nothing missed, yet fewer: the runs parted (gas)
    const std::vector<SummaryPanel> parted = {{time, true}, {event, false}};
    const SummaryCard card = summary_card(parted, true, "t");
    CHECK(card.rows[0].values == std::vector<std::string>{"0", "0"});
    CHECK(card.note.find("None missed") != std::string::npos);
    CHECK(card.note.find("chaos") != std::string::npos);
    CHECK(epilogue_caption(parted).find("none missed") != std::string::npos);
    CHECK(epilogue_caption(parted).find("every collision") == std::string::npos);

    // Misses explain it: the caption counts them.
    time.missed_collisions = 1234;
    const std::vector<SummaryPanel> missing = {{time, true}, {event, false}};
    CHECK(summary_card(missing, true, "t").note.find("miss") != std::string::npos);
    CHECK(epilogue_caption(missing).find("missed 1,234") != std::string::npos);
    // Discs through a wall, with no pair missed.
    time.missed_collisions = 0;
    time.escaped = 3;
    CHECK(epilogue_caption({{time, true}, {event, false}}).find("wall") != std::string::npos);

    // The same count: nothing to explain.
    time.escaped = 0;
    time.collisions_pair = 127;
    const std::vector<SummaryPanel> agreed = {{time, true}, {event, false}};
    CHECK(summary_card(agreed, true, "t").note.empty());
    CHECK(epilogue_caption(agreed).find("same") != std::string::npos);

    // One panel: no word of the other, whatever the counts.
    for (const std::vector<SummaryPanel>& one :
         {std::vector<SummaryPanel>{{event, false}}, std::vector<SummaryPanel>{{time, true}}}) {
        CHECK(summary_card(one, true, "t").note.empty());
        const std::string caption = epilogue_caption(one);
        for (const char* word : {"both", "two", "differ", "side by side", "Time-driven"})
            CHECK_MESSAGE(caption.find(word) == std::string::npos, caption);
    }
    for (const auto& panels : {parted, missing, agreed})
        CHECK(epilogue_caption(panels).size() <= max_caption_chars);
}

TEST_CASE("a still's frames only run, each with the caption the video reads with that state") {
    const Timeline video = build_timeline(lesson_script());
    const Timeline still = still_timeline(video, 60, "Always");
    check_invariants(still, 60);
    for (const Segment& s : still.segments) CHECK(s.kind == SegmentKind::run);
    // Every state the video shows in a run: the same caption in the still.
    for (std::int64_t k = 0; k < video.frame_count(); ++k) {
        const Segment& s = video.segment_at(k);
        if (s.kind != SegmentKind::run) continue;
        CHECK(still.segment_at(video.sim_frame(k)).caption == s.caption);
    }
    CHECK(still.segment_at(0).caption == "Always");  // shown only under the card
    CHECK(still.segment_at(59).caption == "Later");  // beyond the video: its last caption
}

TEST_CASE("the lesson plan takes a caption's words for the one panel a video shows") {
    Scene scene;
    scene.title = "T";
    CaptionCue two;
    two.at = 3.0;
    two.text = "Left tests every pair; right predicts";
    two.event_text = "The queue predicts";
    two.time_text = "Each step tests every pair";
    CaptionCue plain;
    plain.at = 5.0;
    plain.text = "Chaos";
    scene.render.captions = {two, plain};
    std::vector<std::string> notices;
    LessonRequest request;
    request.duration = 10.0;
    const auto words = [&](bool time_panel, bool event_panel) {
        request.time_panel = time_panel;
        request.event_panel = event_panel;
        return lesson_plan(scene, request, notices);
    };
    const LessonPlan both = words(true, true);
    CHECK(both.captions[0].text == two.text);
    CHECK(both.epilogue_caption == "In the end: what each method counted");
    const LessonPlan event = words(false, true);
    CHECK(event.captions[0].text == "The queue predicts");
    CHECK(event.captions[1].text == "Chaos");  // no other form: the same words
    CHECK(event.epilogue_caption == "In the end: the final figures");
    const LessonPlan time = words(true, false);
    CHECK(time.captions[0].text == "Each step tests every pair");
    CHECK(time.epilogue_caption == "In the end: the final figures");
    // The timeline's epilogue (subtitles, chapters) has the plan's words.
    const Timeline timeline = lesson_timeline(time, 10, 100);
    CHECK(timeline.segments.back().caption == time.epilogue_caption);
    CHECK(notices.empty());
}

TEST_CASE("a slower video moves each caption to the moment it was written for") {
    // The scene's own video: a 2 s card, a question at 5 s frozen 3 + 2.5 s, captions at 3 s,
    // 12 s (held 1 s) and 18 s. Seconds of simulation running before each: 1, 12 - 2 - 5.5 = 4.5,
    // 18 - 2 - 5.5 - 1 = 9.5.
    Scene scene;
    scene.title = "T";
    scene.description = "A card";
    QuestionCue question;
    question.at = 5.0;
    question.think = 3.0;
    scene.render.questions = {question};
    const auto caption = [](double at, const char* text, double hold) {
        CaptionCue cue;
        cue.at = at;
        cue.text = text;
        cue.hold = hold;
        cue.file = "s.toml";
        cue.line = static_cast<int>(at);
        return cue;
    };
    scene.render.captions = {caption(3.0, "Early", 0.0), caption(12.0, "Middle", 1.0),
                             caption(18.0, "Late", 0.0)};
    LessonRequest request;
    request.duration = 22.0;  // a 3 s summary card: the run ends at 19 s
    request.scene_duration = 22.0;
    const auto plan = [&](double slower, std::vector<std::string>& notices) {
        request.slower = slower;
        return lesson_plan(scene, request, notices);
    };
    const auto ats = [](const LessonPlan& lesson) {
        std::vector<double> out;
        for (const CaptionCue& cue : lesson.captions) out.push_back(cue.at);
        return out;
    };

    std::vector<std::string> notices;
    CHECK(ats(plan(1.0, notices)) == std::vector<double>{3.0, 12.0, 18.0});  // as written
    CHECK(notices.empty());

    // Twice as slow: twice the running seconds, the card and the freezes as they were. Late
    // would come at 2 + 19 + 5.5 + 1 = 27.5 s, after the run: left out, and said so.
    const LessonPlan slow = plan(2.0, notices);
    REQUIRE(slow.captions.size() == 2);
    CHECK(slow.captions[0].at == doctest::Approx(4.0));
    CHECK(slow.captions[1].at == doctest::Approx(2.0 + 9.0 + 5.5));
    CHECK(slow.captions[1].text == "Middle");
    REQUIRE(notices.size() == 1);
    CHECK(notices[0].find("s.toml:18: render.captions") == 0);
    CHECK(notices[0].find("2x slower") != std::string::npos);

    // Twice as fast: each moment comes before its caption, which stays where it was written
    // (late, not untrue).
    notices.clear();
    CHECK(ats(plan(0.5, notices)) == std::vector<double>{3.0, 12.0, 18.0});
    CHECK(notices.empty());
}
