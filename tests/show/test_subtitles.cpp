// A video's subtitle cues: the title card, then the caption on screen, as plain timed text.
#include <doctest/doctest.h>

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

TEST_CASE("the title card, then each caption as it changes, within the video") {
    const Cues cues = subtitle_cues(lesson_with_captions(), 10.0);
    REQUIRE(cues.size() == 3);
    CHECK(cues[0].start == 0.0);
    CHECK(cues[0].end == 2.0);
    CHECK(cues[0].text == "Billiards break\nA cue ball scatters a rack");
    // The caption that began under the card (at 1 s) shows from the card's end.
    CHECK(cues[1].start == 2.0);
    CHECK(cues[1].end == 4.0);
    CHECK(cues[1].text == "Under the card");
    // The same words twice are one cue; a caption after the end makes none.
    CHECK(cues[2].start == 4.0);
    CHECK(cues[2].end == 10.0);
    CHECK(cues[2].text == "Chaos");
}

TEST_CASE("without an intro card the title shows alone, briefly, and no words make no cues") {
    LessonPlan lesson;
    lesson.title = "Gas";
    lesson.caption = "Discs in a box";
    const Cues cues = subtitle_cues(lesson, 4.0);
    REQUIRE(cues.size() == 2);
    CHECK(cues[0].text == "Gas");
    CHECK(cues[0].end == 1.0);  // a quarter of a short video
    CHECK(cues[1].start == 1.0);
    CHECK(cues[1].end == 4.0);
    CHECK(subtitle_cues(LessonPlan{}, 4.0).empty());
    CHECK(subtitle_cues(lesson, 0.0).empty());
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
