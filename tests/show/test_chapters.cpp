// Chapters (collide/show/chapters.hpp) from the lesson timeline and from step cues, and the slide
// player's page (collide/show/slide_player.hpp).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "collide/show/chapters.hpp"
#include "collide/show/heap_program.hpp"
#include "collide/show/replay.hpp"
#include "collide/show/slide_player.hpp"
#include "collide/show/timeline.hpp"
#include "collide/sim/pq/heap_record.hpp"
#include "collide/sim/pq/queue_kind.hpp"

using namespace collide;
using namespace collide::show;

namespace {

/// 10 s at 10 fps: a 2 s card, "Always", a held caption at 4 s, another at 7 s, a 2 s epilogue.
TimelineScript chapters_script() {
    TimelineScript script;
    script.fps = 10;
    script.frames = 100;
    script.card_seconds = 2.0;
    script.card_title = "Gas in a box";
    script.caption = "Always";
    script.cues = {{4.0, "Hold\nhere", 1.5}, {7.0, "Later", 0.0}};
    script.epilogue_seconds = 2.0;
    script.epilogue_caption = "In the end";
    return script;
}

Segment segment(SegmentKind kind, std::int64_t first, std::int64_t end, std::string caption) {
    Segment s;
    s.kind = kind;
    s.first_frame = first;
    s.end_frame = end;
    s.start = static_cast<double>(first) / 10.0;
    s.end = static_cast<double>(end) / 10.0;
    s.moves = kind == SegmentKind::run;
    s.caption = std::move(caption);
    return s;
}

}  // namespace

TEST_CASE("chapters: the card, each caption (its hold and run together), the epilogue") {
    const Chapters chapters = timeline_chapters(build_timeline(chapters_script()), 0.5);
    REQUIRE(chapters.size() == 5);
    const std::vector<std::string> titles{"Gas in a box", "Always", "Hold here", "Later",
                                          "In the end"};
    const std::vector<double> starts{0.0, 2.0, 4.0, 7.0, 8.0};
    const std::vector<double> ends{2.0, 4.0, 7.0, 8.0, 10.0};
    // The last frame of each, the card's before its last half second fades it out.
    const std::vector<double> stills{1.5, 3.9, 6.9, 7.9, 9.9};
    for (std::size_t i = 0; i < chapters.size(); ++i) {
        CAPTURE(i);
        CHECK(chapters[i].title == titles[i]);
        CHECK(chapters[i].start == doctest::Approx(starts[i]));
        CHECK(chapters[i].end == doctest::Approx(ends[i]));
        CHECK(chapters[i].still == doctest::Approx(stills[i]));
    }
    CHECK(timeline_chapters(build_timeline(chapters_script())).front().still ==
          doctest::Approx(1.9));
    CHECK(timeline_chapters(Timeline{}).empty());
}

TEST_CASE("chapters: a replay is one chapter of its own and missing words get the part's name") {
    Timeline timeline;
    timeline.fps = 10;
    timeline.segments = {segment(SegmentKind::card, 0, 10, ""),
                         segment(SegmentKind::run, 10, 30, ""),
                         segment(SegmentKind::replay, 30, 40, "a missed collision"),
                         segment(SegmentKind::replay, 40, 45, "slowly"),
                         segment(SegmentKind::run, 45, 50, ""),
                         segment(SegmentKind::epilogue, 50, 60, "")};
    const Chapters chapters = timeline_chapters(timeline);
    REQUIRE(chapters.size() == 4);
    CHECK(chapters[0].title == "Title");
    CHECK(chapters[1].title == "The simulation runs");
    CHECK(chapters[2].title == "Replay: a missed collision");
    CHECK(chapters[2].start == doctest::Approx(3.0));
    CHECK(chapters[2].end == doctest::Approx(4.5));
    // Half a second of run after the replay is no stop of its own: the epilogue starts there.
    CHECK(chapters[3].title == "The final figures");
    CHECK(chapters[3].start == doctest::Approx(4.5));
    CHECK(chapters[3].end == doctest::Approx(6.0));
    CHECK(chapters[3].still == doctest::Approx(5.9));
}

TEST_CASE("chapters: a caption back for less than a second joins the chapter after it") {
    Timeline timeline;
    timeline.fps = 10;
    timeline.segments = {segment(SegmentKind::run, 0, 30, "First"),
                         segment(SegmentKind::replay, 30, 40, "a missed step"),
                         segment(SegmentKind::run, 40, 43, "First"),
                         segment(SegmentKind::question, 43, 63, "Will it see it?"),
                         segment(SegmentKind::reveal, 63, 73, "No"),
                         segment(SegmentKind::run, 73, 83, "Second"),
                         segment(SegmentKind::run, 83, 88, "Brief"),
                         segment(SegmentKind::run, 88, 95, "Second"),
                         segment(SegmentKind::run, 95, 100, "Third")};
    for (Segment& s : timeline.segments) s.moves = s.kind == SegmentKind::run;
    timeline.segments[3].question = 0;
    timeline.segments[4].question = 0;
    const Chapters chapters = timeline_chapters(timeline);
    std::vector<std::string> titles;
    for (const Chapter& chapter : chapters) titles.push_back(chapter.title);
    // "First" back for 0.3 s after the replay joins the question; "Second" (1 s) stays, and so
    // does "Brief", shown for the first time, however short; "Second" back for 0.7 s joins
    // "Third"; "Third", the last, has nothing after it and stays.
    const std::vector<std::string> expected{
        "First", "Replay: a missed step", "Will it see it?", "No", "Second", "Brief", "Third"};
    REQUIRE(titles == expected);
    CHECK(chapters[2].start == doctest::Approx(4.0));
    CHECK(chapters[2].still == doctest::Approx(6.2));  // still the question's last frame
    CHECK(chapters[1].end == doctest::Approx(4.0));
    CHECK(chapters[6].start == doctest::Approx(8.8));
    for (std::size_t i = 1; i < chapters.size(); ++i)
        CHECK(chapters[i].start == doctest::Approx(chapters[i - 1].end));
}

TEST_CASE("chapters: a replay's still is its whole picture, before the replay fades out") {
    // A replay of replay_seconds, and a will-see question whose reveal replays its step: a
    // handout page and a slide show the failure at the end of the replay's hold, not the nearly
    // empty frame the replay fades to.
    const auto replay_frames = static_cast<std::int64_t>(replay_seconds * 10.0);
    Timeline timeline;
    timeline.fps = 10;
    timeline.segments = {segment(SegmentKind::run, 0, 30, ""),
                         segment(SegmentKind::replay, 30, 30 + replay_frames, "a missed step"),
                         segment(SegmentKind::run, 30 + replay_frames, 100, ""),
                         segment(SegmentKind::question, 100, 120, "Will it see it?"),
                         segment(SegmentKind::reveal, 120, 120 + replay_frames, "No"),
                         segment(SegmentKind::epilogue, 180, 200, "")};
    timeline.segments[3].question = 0;
    timeline.segments[4].question = 0;
    timeline.segments[4].moves = false;
    const double hold = std::floor(replay_hold_end * 10.0 - 1e-9) / 10.0;  // its last held frame
    const Chapters chapters = timeline_chapters(timeline, 0.0, {true});
    REQUIRE(chapters.size() == 6);
    CHECK(chapters[1].title == "Replay: a missed step");
    CHECK(chapters[1].still == doctest::Approx(3.0 + hold));
    CHECK(chapters[1].still < chapters[1].end - 0.5);
    CHECK(chapters[4].title == "No");
    CHECK(chapters[4].still == doctest::Approx(12.0 + hold));
    // A reveal that only shows its answer keeps its last frame.
    const Chapters plain = timeline_chapters(timeline, 0.0, {false});
    CHECK(plain[4].still == doctest::Approx(12.0 + replay_seconds - 0.1));
    CHECK(plain[1].still == doctest::Approx(3.0 + hold));
}

TEST_CASE(
    "chapters: a question and its answer are two chapters: the player stops on the question") {
    TimelineScript script = chapters_script();
    script.cues.clear();
    script.questions = {{3.0, 2.0, 1.0, "Which pair collides next?", "B: discs 3 and 7"}};
    const Chapters chapters = timeline_chapters(build_timeline(script), 0.5);
    std::vector<std::string> titles;
    for (const Chapter& chapter : chapters) titles.push_back(chapter.title);
    const std::vector<std::string> expected{
        "Gas in a box",     "Always", "Which pair collides next?",
        "B: discs 3 and 7", "Always", "In the end"};
    REQUIRE(titles == expected);
    // Stopped at the question's last frame: the question still on screen, its answer not yet.
    CHECK(chapters[2].start == doctest::Approx(3.0));
    CHECK(chapters[2].still == doctest::Approx(4.9));
    CHECK(chapters[3].start == doctest::Approx(5.0));
    CHECK(chapters[3].end == doctest::Approx(6.0));
}

TEST_CASE("chapters from step cues: back to back from 0, one line each, repeats merged") {
    const Cues cues = {{0.5, 1.0, "insert P"},
                       {1.0, 2.0, "binary heap: swim\nd-ary heap: swim"},
                       {2.0, 3.0, "binary heap: swim\nd-ary heap: swim"},
                       {3.5, 4.0, "delete the maximum"},
                       {9.0, 9.5, "past the end"}};
    const Chapters chapters = chapters_from_cues(cues, 5.0, 10);
    REQUIRE(chapters.size() == 3);
    CHECK(chapters[0].start == 0.0);
    CHECK(chapters[0].end == 1.0);
    CHECK(chapters[1].title == "binary heap: swim / d-ary heap: swim");
    CHECK(chapters[1].end == 3.5);
    CHECK(chapters[2].title == "delete the maximum");
    CHECK(chapters[2].end == 5.0);
    CHECK(chapters[0].still == doctest::Approx(0.9));
    CHECK(chapters[2].still == doctest::Approx(4.9));
    CHECK(chapters_from_cues({}, 5.0, 10).empty());
}

TEST_CASE("one_line: line breaks become the separator, spaces collapse, ends trimmed") {
    CHECK(one_line("  a  b \n\n c\r\n") == "a b c");
    CHECK(one_line("x\ny", " / ") == "x / y");
    CHECK(one_line("") == "");
}

TEST_CASE("the slide page: the video, the track, the chapters as data, nothing fetched") {
    SlidePage page;
    page.title = "Zderzenia </title> & \"more\"";
    page.video = "video.mp4";
    page.subtitles = "subtitles.vtt";
    page.language = "pl";
    page.cues = {{0.0, 1.0, "Δt ≈ 0.01 </script>"}};
    page.chapters = {{0.0, 1.0, "Tytuł", 0.5}, {1.0, 2.5, "He said \"go\"\\ @CUES@", 2.4}};
    page.fps = 15;
    const std::string html = slide_page_html(page);
    CHECK(html.find("<title>Zderzenia &lt;/title&gt; &amp; &quot;more&quot;</title>") !=
          std::string::npos);
    CHECK(html.find("<video id=\"video\" src=\"video.mp4\"") != std::string::npos);
    CHECK(html.find("<track kind=\"subtitles\" src=\"subtitles.vtt\" srclang=\"pl\"") !=
          std::string::npos);
    CHECK(html.find("{start: 1, end: 2.5, still: 2.4, text: \"He said \\\"go\\\"\\\\ @CUES@\"}") !=
          std::string::npos);
    CHECK(html.find("Δt ≈ 0.01 \\u003c/script\\u003e") != std::string::npos);
    CHECK(html.find("const frame = 1 / 15;") != std::string::npos);
    // One closing script tag (the page's own): no text can end the script early.
    CHECK(html.find("</script>") == html.rfind("</script>"));
    // Self-contained: nothing from the network.
    CHECK(html.find("http") == std::string::npos);
    CHECK(html.find("<link") == std::string::npos);
    CHECK(html.find("<script src") == std::string::npos);
    page.subtitles.clear();
    CHECK(slide_page_html(page).find("<track kind") == std::string::npos);
}

TEST_CASE("heap chapters: one per operation, short ones grouped, none under 4 s") {
    const std::vector<pq::QueueKind> kinds{pq::parse_queue_kind("binary")};
    for (const double pace : {0.3, 0.8, 2.0}) {
        CAPTURE(pace);
        const HeapProgram lesson(
            pq::HeapRecord::operations(pq::parse_heap_ops("P Q E * X A M * P L E *"), kinds,
                                       pq::Orientation::max),
            heap_pacing(pace), 1);
        const double seconds = lesson.duration();
        const Chapters chapters = heap_chapters(lesson, seconds, 30);
        REQUIRE(!chapters.empty());
        CHECK(chapters.front().start == 0.0);
        CHECK(chapters.back().end == seconds);
        CHECK(static_cast<double>(chapters.size()) <= seconds / min_heap_chapter_seconds);
        std::size_t ops_named = 0;
        for (std::size_t i = 0; i < chapters.size(); ++i) {
            CAPTURE(chapters[i].title);
            if (seconds >= min_heap_chapter_seconds)
                CHECK(chapters[i].end - chapters[i].start >= min_heap_chapter_seconds);
            if (i > 0) CHECK(chapters[i].start == chapters[i - 1].end);
            CHECK(chapters[i].still >= chapters[i].start);
            CHECK(chapters[i].still < chapters[i].end);
            // Each chapter starts where one of its operations does (the first at 0).
            if (i > 0) {
                CHECK(std::find(lesson.op_starts().begin(), lesson.op_starts().end(),
                                chapters[i].start) != lesson.op_starts().end());
            }
            ops_named +=
                chapters[i].title.find("operations)") != std::string::npos
                    ? 4
                    : static_cast<std::size_t>(
                          std::count(chapters[i].title.begin(), chapters[i].title.end(), ',') + 1);
        }
        CHECK(chapters.front().title.rfind("insert P", 0) == 0);
        if (pace >= 2.0) {
            // Long steps: an operation fills its own chapter.
            CHECK(chapters.size() >= 6);
            CHECK(chapters[1].title.find(',') == std::string::npos);
        }
        CHECK(ops_named >= 4);
    }
}

TEST_CASE("heap chapters: heapsort's two phases by name: a short video is one chapter") {
    const HeapProgram sort(pq::HeapRecord::heapsort(pq::parse_sort_keys("S O R T E X A M P L E"),
                                                    pq::Orientation::max),
                           heap_pacing(0.8), 1);
    const Chapters phases = heap_chapters(sort, sort.duration(), 30);
    REQUIRE(phases.size() == 2);
    CHECK(phases[0].title == "build the heap");
    CHECK(phases[1].title == "sortdown");
    const std::vector<pq::QueueKind> binary{pq::parse_queue_kind("binary")};
    const HeapProgram one(
        pq::HeapRecord::operations(pq::parse_heap_ops("P"), binary, pq::Orientation::max),
        HeapPacing{0.5, 0.0, 0.5, 0.5}, 1);
    const Chapters single = heap_chapters(one, one.duration(), 30);
    REQUIRE(single.size() == 1);
    CHECK(single[0].title == "insert P");
    CHECK(single[0].end == one.duration());
}
