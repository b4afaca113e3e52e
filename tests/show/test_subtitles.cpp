// A video's subtitle cues: the title card, then the caption on screen, as plain timed text.
#include <doctest/doctest.h>

#include <algorithm>

#include "collide/show/subtitles.hpp"

namespace collide::show {
namespace {

LessonPlan lesson_with_captions() {
    LessonPlan lesson;
    lesson.title = "Billiards break";
    lesson.description = "A cue ball scatters a rack";
    lesson.intro_seconds = 2.0;
    lesson.caption = "Every collision counts";
    lesson.captions = {{1.0, "Under the card", "", 0},
                       {4.0, "Chaos", "", 0},
                       {6.0, "Chaos", "", 0},
                       {12.0, "After the end", "", 0}};
    return lesson;
}

/// The cues of `lesson` over a `seconds`-long video at 30 frames per second.
Cues cues_of(const LessonPlan& lesson, double seconds) {
    const auto frames = static_cast<std::int64_t>(seconds * 30.0 + 0.5);
    return subtitle_cues(lesson_timeline(lesson, 30, frames), lesson);
}

TEST_CASE("the title card, then each caption as it changes, within the video") {
    const Cues cues = cues_of(lesson_with_captions(), 10.0);
    REQUIRE(cues.size() == 3);
    CHECK(cues[0].start == 0.0);
    CHECK(cues[0].end == 2.0);
    CHECK(cues[0].text == "Billiards break\nA cue ball scatters a rack");
    // The caption that began under the card (at 1 s) shows from the card's end.
    CHECK(cues[1].start == 2.0);
    CHECK(cues[1].end == doctest::Approx(4.0));
    CHECK(cues[1].text == "Under the card");
    // The same words twice are one cue; a caption after the end makes none.
    CHECK(cues[2].start == doctest::Approx(4.0));
    CHECK(cues[2].end == 10.0);
    CHECK(cues[2].text == "Chaos");
}

TEST_CASE("without an intro card the title shows alone, briefly, and no words make no cues") {
    LessonPlan lesson;
    lesson.title = "Gas";
    lesson.caption = "Discs in a box";
    const Cues cues = cues_of(lesson, 4.0);
    REQUIRE(cues.size() == 2);
    CHECK(cues[0].text == "Gas");
    CHECK(cues[0].end == 1.0);  // a quarter of a short video
    CHECK(cues[1].start == 1.0);
    CHECK(cues[1].end == 4.0);
    CHECK(cues[1].text == "Discs in a box");
    CHECK(cues_of(LessonPlan{}, 4.0).empty());
    CHECK(subtitle_cues(Timeline{}, lesson).empty());
}

TEST_CASE("a hold, a replay and the epilogue: the track says what the screen says, when") {
    LessonPlan lesson = lesson_with_captions();
    lesson.captions = {{3.0, "The break", "", 0, 1.0}};
    lesson.replays = {{100, 2.0, "Between two checks the disc jumped through"}};
    lesson.epilogue_seconds = 2.0;
    const Timeline timeline = lesson_timeline(lesson, 30, 360);
    const Cues cues = subtitle_cues(timeline, lesson);
    // Every cue's words are those of the segments it spans, and every segment's words are in
    // the track at its time.
    for (const Segment& segment : timeline.segments) {
        const std::string& expected =
            segment.kind == SegmentKind::card ? cues.front().text : segment.caption;
        const auto covering = std::find_if(cues.begin(), cues.end(), [&](const Cue& cue) {
            return cue.start <= segment.start + 1e-9 && segment.end <= cue.end + 1e-9;
        });
        REQUIRE(covering != cues.end());
        CHECK(covering->text == expected);
    }
    const auto replay =
        std::find_if(timeline.segments.begin(), timeline.segments.end(),
                     [](const Segment& s) { return s.kind == SegmentKind::replay; });
    REQUIRE(replay != timeline.segments.end());
    CHECK(std::any_of(cues.begin(), cues.end(), [&](const Cue& cue) {
        return cue.text == "Between two checks the disc jumped through" &&
               cue.start == doctest::Approx(replay->start) &&
               cue.end == doctest::Approx(replay->end);
    }));
    CHECK(cues.back().text == timeline.segments.back().caption);
    CHECK(cues.back().end == doctest::Approx(12.0));
    for (std::size_t i = 1; i < cues.size(); ++i) CHECK(cues[i].start >= cues[i - 1].end);
}

TEST_CASE("a question and its answer: the track says both, the question first") {
    LessonPlan lesson = lesson_with_captions();
    lesson.captions.clear();
    lesson.questions = {{3.0, 2.0, 1.5, "Which pair collides next?", "B: discs 3 and 7"}};
    const Cues cues = cues_of(lesson, 10.0);
    REQUIRE(cues.size() == 5);
    CHECK(cues[1].text == "Every collision counts");
    CHECK(cues[2].text == "Which pair collides next?");
    CHECK(cues[2].start == doctest::Approx(3.0));
    CHECK(cues[2].end == doctest::Approx(5.0));
    CHECK(cues[3].text == "B: discs 3 and 7");
    CHECK(cues[3].end == doctest::Approx(6.5));
    // Then the run's caption again, to the end.
    CHECK(cues[4].text == "Every collision counts");
    CHECK(cues[4].end == 10.0);
    lesson.questions.clear();
    CHECK(cues_of(lesson, 10.0).size() == 2);
}

TEST_CASE("cues never overlap and never end before they start") {
    const Cues cues =
        cues_from_steps({{0.0, "a"}, {0.0, "b"}, {1.0, ""}, {2.0, "c"}, {5.0, "d"}}, 3.0);
    REQUIRE(cues.size() == 2);
    CHECK(cues[0].text == "b");
    CHECK(cues[0].end == 1.0);
    CHECK(cues[1].text == "c");
    CHECK(cues[1].end == 3.0);
    for (std::size_t i = 1; i < cues.size(); ++i) CHECK(cues[i].start >= cues[i - 1].end);
}

}  // namespace
}  // namespace collide::show
