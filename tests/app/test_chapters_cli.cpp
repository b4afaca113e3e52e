// Chapters and the slide player: `collide render` puts the timeline's chapters into the MP4
// (ffprobe lists them), into a WebVTT chapters file, and writes a slide folder whose page, opened
// in headless Chromium from file://, stops at each chapter's end and goes on at a key press.
// Bad input exits 2 and writes nothing.
#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "../support/files.hpp"
#include "../support/shell.hpp"
#include "../support/skip.hpp"
#include "../support/temp_dir.hpp"
#include "headless_browser.hpp"
#include "multilingual_scene.hpp"
#include "run_collide.hpp"
#include "subtitle_file.hpp"

namespace fs = std::filesystem;
using collide::test::capture;
using collide::test::chromium_program;
using collide::test::finished_test_log;
using collide::test::have_ffprobe;
using collide::test::parse_subtitles;
using collide::test::ParsedCue;
using collide::test::run_collide;
using collide::test::TempDir;

namespace {

/// The multilingual scene's chapters at 10 fps: the 1 s card (a quarter of 4 s), the caption,
/// the caption from 2.5 s, the epilogue (a fifth of 4 s).
struct Expected {
    double start;
    double end;
    const char* title;
};
const std::vector<Expected> expected_chapters = {
    {0.0, 1.0, "Zderzenia: Δt ≈ 0.01 s"},
    {1.0, 2.5, "Kule się zderzają"},
    {2.5, 3.2, "Energia ± 0: E = ½mv²"},
    {3.2, 4.0, "In the end: what each method counted"},
};

/// The chapters ffprobe reads from `file`: "start_time=", "end_time=", "TAG:title=" lines.
std::vector<ParsedCue> probed_chapters(const fs::path& file) {
    std::istringstream lines(
        capture("ffprobe -v error -show_entries chapter=start_time,end_time:chapter_tags=title -of "
                "default=nw=1 " +
                file.string()));
    std::vector<ParsedCue> chapters;
    std::string line;
    while (std::getline(lines, line)) {
        if (line.rfind("start_time=", 0) == 0) {
            chapters.push_back({std::stod(line.substr(11)), 0.0, ""});
        } else if (line.rfind("end_time=", 0) == 0 && !chapters.empty()) {
            chapters.back().end = std::stod(line.substr(9));
        } else if (line.rfind("TAG:title=", 0) == 0 && !chapters.empty()) {
            chapters.back().text = line.substr(10);
        }
    }
    return chapters;
}

/// Width and height from a PNG's IHDR chunk; {0, 0} when `bytes` is no PNG.
std::pair<int, int> png_size(const std::string& bytes) {
    if (bytes.size() < 24 || bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0 ||
        bytes.compare(12, 4, "IHDR") != 0)
        return {0, 0};
    const auto be32 = [&](std::size_t at) {
        int value = 0;
        for (std::size_t i = 0; i < 4; ++i)
            value = value * 256 + static_cast<unsigned char>(bytes[at + i]);
        return value;
    };
    return {be32(16), be32(20)};
}

std::string render_args(const fs::path& scene) {
    return "render " + scene.string() + " --size 320x180 --fps 10 --progress none --lang pl ";
}

}  // namespace

TEST_CASE("render: the MP4 carries the timeline's chapters, and the chapters file parses") {
    if (!have_ffprobe()) COLLIDE_SKIP_TEST("ffprobe is not installed");
    TempDir dir("chapters");
    const fs::path scene = dir.path / "scene.toml";
    collide::test::write_file(scene, collide::test::multilingual_scene);
    const fs::path out = dir.path / "t.mp4";
    const fs::path vtt = dir.path / "chapters.vtt";
    const auto r =
        run_collide(render_args(scene) + "-o " + out.string() + " --chapters-file " + vtt.string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);

    const std::vector<ParsedCue> probed = probed_chapters(out);
    const std::vector<ParsedCue> file = parse_subtitles(collide::test::read_all(vtt), true);
    REQUIRE(probed.size() == expected_chapters.size());
    REQUIRE(file.size() == expected_chapters.size());
    for (std::size_t i = 0; i < expected_chapters.size(); ++i) {
        CAPTURE(i);
        CHECK(probed[i].text == expected_chapters[i].title);
        CHECK(probed[i].start == doctest::Approx(expected_chapters[i].start).epsilon(0.002));
        CHECK(probed[i].end == doctest::Approx(expected_chapters[i].end).epsilon(0.002));
        CHECK(file[i].text == expected_chapters[i].title);
        CHECK(file[i].start == doctest::Approx(expected_chapters[i].start));
        CHECK(file[i].end == doctest::Approx(expected_chapters[i].end));
    }
    // The chapters' own text track (how MP4 stores them) is no second subtitle track a player
    // would offer: FFmpeg reads it as data.
    CHECK(capture("ffprobe -v error -show_entries stream=codec_type -of csv=p=0 " + out.string()) ==
          "video\nsubtitle\ndata\n");

    const fs::path plain = dir.path / "plain.mp4";
    const auto none = run_collide(render_args(scene) + "--chapters none -o " + plain.string());
    REQUIRE_MESSAGE(none.exit_code == 0, none.output);
    CHECK(probed_chapters(plain).empty());
}

TEST_CASE("heap videos get a chapter per operation, none shorter than 4 s") {
    if (!have_ffprobe()) COLLIDE_SKIP_TEST("ffprobe is not installed");
    TempDir dir("heap_chapters");
    // Twelve operations of one to four steps each, as docs/heap.md's lessons; and the d-ary
    // heaps side by side (longer operations).
    for (const std::string impls : {"binary", "binary,dary:3,dary:4"}) {
        CAPTURE(impls);
        const fs::path out = dir.path / (std::to_string(impls.size()) + ".mp4");
        const auto r = run_collide("heap --ops \"P Q E * X A M * P L E *\" --impl " + impls +
                                   " --size 480x270 --fps 10 --progress none -o " + out.string());
        REQUIRE_MESSAGE(r.exit_code == 0, r.output);
        const double seconds = std::stod(
            capture("ffprobe -v error -show_entries format=duration -of csv=p=0 " + out.string()));
        const std::vector<ParsedCue> chapters = probed_chapters(out);
        REQUIRE(chapters.size() >= 2);
        CHECK(static_cast<double>(chapters.size()) <= seconds / 4.0);
        CHECK(chapters.front().start == doctest::Approx(0.0));
        CHECK(chapters.back().end == doctest::Approx(seconds).epsilon(0.01));
        for (std::size_t i = 0; i < chapters.size(); ++i) {
            CAPTURE(i);
            CAPTURE(chapters[i].text);
            CHECK(chapters[i].end - chapters[i].start >= 4.0 - 1e-3);
            if (i > 0) CHECK(chapters[i].start == doctest::Approx(chapters[i - 1].end));
            // Named by operations, not by a step's caption ("S > H: exchange").
            CHECK((chapters[i].text.find("insert") != std::string::npos ||
                   chapters[i].text.find("remove") != std::string::npos ||
                   chapters[i].text.find("delete") != std::string::npos));
            CHECK(chapters[i].text.find("exchange") == std::string::npos);
        }
        CHECK(chapters.front().text.find("insert P") == 0);
    }
}

TEST_CASE("render --slides: a folder with the page, the video, a still per chapter, the VTTs") {
    TempDir dir("slides");
    const fs::path scene = dir.path / "scene.toml";
    collide::test::write_file(scene, collide::test::multilingual_scene);
    const fs::path out = dir.path / "t.mp4";
    const fs::path slides = dir.path / "talk";
    const auto r =
        run_collide(render_args(scene) + "-o " + out.string() + " --slides " + slides.string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    CHECK(collide::test::entries(slides) ==
          std::vector<std::string>{"chapter-01.png", "chapter-02.png", "chapter-03.png",
                                   "chapter-04.png", "chapters.vtt", "index.html", "subtitles.vtt",
                                   "video.mp4"});
    CHECK(collide::test::read_all(slides / "video.mp4") == collide::test::read_all(out));
    for (int i = 1; i <= 4; ++i) {
        CAPTURE(i);
        const auto size =
            png_size(collide::test::read_all(slides / ("chapter-0" + std::to_string(i) + ".png")));
        CHECK(size.first == 320);
        CHECK(size.second == 180);
    }
    CHECK(parse_subtitles(collide::test::read_all(slides / "chapters.vtt"), true).size() == 4);
    CHECK(parse_subtitles(collide::test::read_all(slides / "subtitles.vtt"), true).size() == 4);
    const std::string page = collide::test::read_all(slides / "index.html");
    CHECK(page.find("src=\"video.mp4\"") != std::string::npos);
    CHECK(page.find("<track kind=\"subtitles\" src=\"subtitles.vtt\" srclang=\"pl\"") !=
          std::string::npos);
    CHECK(page.find("Kule się zderzają") != std::string::npos);
    CHECK(page.find("http") == std::string::npos);  // nothing from the network

    // Again into the same folder: an earlier slide folder is replaced as a whole.
    const auto again =
        run_collide(render_args(scene) + "-o " + out.string() + " --slides " + slides.string());
    REQUIRE_MESSAGE(again.exit_code == 0, again.output);
    CHECK(collide::test::entries(slides).size() == 8);
}

TEST_CASE("render --slides, --chapters, --chapters-file: bad input exits 2 and writes nothing") {
    TempDir dir("slides_bad");
    const fs::path keep = dir.path / "mine";
    fs::create_directory(keep);
    collide::test::write_file(keep / "notes.txt", "the lecturer's notes");
    const fs::path out = dir.path / "t.mp4";
    const std::string base = "render billiards --size 160x90 --fps 5 --duration 1 --progress none ";
    const std::string mp4 = "-o " + out.string() + " ";
    struct Case {
        std::string args;
        std::string message;
    };
    const std::vector<Case> cases = {
        {"-o " + (dir.path / "t.gif").string() + " --slides " + (dir.path / "s").string(),
         "--slides: the slide player plays an MP4"},
        {"--format png -o " + (dir.path / "frames").string() + " --slides " +
             (dir.path / "s").string(),
         "--slides: the slide player plays an MP4"},
        {"--last-frame -o " + (dir.path / "t.png").string() + " --slides " +
             (dir.path / "s").string(),
         "--slides: a still (PNG) has no chapters"},
        {mp4 + "--slides " + (dir.path / "missing" / "s").string(), "--slides"},
        {mp4 + "--slides " + keep.string(), "holds other files ('notes.txt')"},
        {mp4 + "--slides " + out.string() + ".d --chapters-file " +
             (dir.path / "missing" / "c.vtt").string(),
         "--chapters-file"},
        {mp4 + "--chapters-file " + (dir.path / "c.srt").string(), "a WebVTT file name (.vtt)"},
        {mp4 + "--chapters-file " + out.string(), "--chapters-file"},
        {mp4 + "--chapters list", "--chapters: expected embed or none"},
        {"-o " + (dir.path / "t.gif").string() + " --chapters embed",
         "only an MP4 carries chapters"},
        {mp4 + "--slides " + dir.path.string(), "--slides"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.args);
        const auto r = run_collide(base + c.args);
        CHECK(r.exit_code == 2);
        CHECK_MESSAGE(r.output.find(c.message) != std::string::npos, r.output);
        CHECK(collide::test::entries(dir.path) == std::vector<std::string>{"mine"});
        CHECK(collide::test::entries(keep) == std::vector<std::string>{"notes.txt"});
    }
    // Unwritable: a folder whose parent refuses new entries (not for root, who may write anyway).
    if (geteuid() != 0) {
        const fs::path locked = dir.path / "locked";
        fs::create_directory(locked);
        fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
        const auto r = run_collide(base + mp4 + "--slides " + (locked / "s").string());
        CHECK(r.exit_code == 2);
        CHECK_MESSAGE(r.output.find("--slides") != std::string::npos, r.output);
        CHECK(collide::test::entries(locked).empty());
        fs::permissions(locked, fs::perms::owner_all);
    }
}

namespace {

/// A line of the page's test log: its words after `prefix`, split at spaces.
std::vector<std::string> log_line(const std::string& log, const std::string& prefix, int nth = 0) {
    std::istringstream lines(log);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.rfind(prefix + " ", 0) != 0 || nth-- > 0) continue;
        std::istringstream words(line.substr(prefix.size() + 1));
        std::vector<std::string> out;
        std::string word;
        while (words >> word) out.push_back(word);
        return out;
    }
    return {};
}

}  // namespace

TEST_CASE("the slide player in headless Chromium from file:// stops at chapter ends, keys go on") {
    const std::string chromium = chromium_program();
    if (chromium.empty()) COLLIDE_SKIP_TEST("chromium is not installed (scripts/setup.sh --test)");
    TempDir dir("slides_browser");
    const fs::path scene = dir.path / "scene.toml";
    collide::test::write_file(scene, collide::test::multilingual_scene);
    const fs::path slides = dir.path / "talk";
    const auto r = run_collide(render_args(scene) + "-o " + (dir.path / "t.mp4").string() +
                               " --slides " + slides.string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    // The page's ?test script presses the right arrow twice and the left arrow once, logging
    // where the video stopped; Chromium's virtual time lets the page run that long, then the DOM
    // (with the log) is read.
    const std::string log = finished_test_log(
        chromium, dir.path / "profile", "file://" + slides.string() + "/index.html?test", 20000);
    INFO("test log: " << log);
    CHECK(log.find("error") == std::string::npos);
    REQUIRE(log.find("end") != std::string::npos);
    CHECK(log_line(log, "chapters") == std::vector<std::string>{"4"});
    // The card, two captions and the epilogue's words: the track says what each chapter shows.
    CHECK(log_line(log, "subtitles") == std::vector<std::string>{"4"});
    // The first press plays the title card and stops before it fades (1 s card, its last 0.5 s
    // fading: the frame at 0.5 s, shown from its middle); the second plays the first caption's
    // chapter to its last frame (2.4 s). Each time still paused 0.3 s later.
    const std::vector<std::string> first = log_line(log, "stop", 0);
    const std::vector<std::string> second = log_line(log, "stop", 1);
    REQUIRE(first.size() == 3);
    REQUIRE(second.size() == 3);
    CHECK(first[0] == "0");
    CHECK(std::stod(first[1]) == doctest::Approx(0.55).epsilon(0.001));
    CHECK(first[2] == "paused");
    CHECK(second[0] == "1");
    CHECK(std::stod(second[1]) == doctest::Approx(2.45).epsilon(0.001));
    CHECK(second[2] == "paused");
    // The left arrow: back to where the first chapter stopped.
    const std::vector<std::string> back = log_line(log, "back");
    REQUIRE(back.size() == 2);
    CHECK(back[0] == "0");
    CHECK(std::stod(back[1]) == doctest::Approx(0.55).epsilon(0.001));
}

namespace {

/// A small scene that asks which collision comes first at 2 s (think 2 s, then the answer).
constexpr const char* question_scene = R"(title = "Which first?"

[box]
width = 1.0
height = 1.0
boundary = "walls"

[[generate]]
count = 12
radius = 0.05
mass = 1.0
temperature = 0.02
seed = 4

[render]
duration = 10.0
caption = "Twelve discs"

[[render.questions]]
at = 2.0
kind = "next-collision"
think = 2
)";

/// The first segment of `kind` in a --timeline-json file: {start, end} in seconds of video.
std::pair<double, double> segment_of(const nlohmann::json& timeline, const std::string& kind) {
    for (const nlohmann::json& s : timeline["segments"]) {
        if (s["kind"] == kind) return {s["start"].get<double>(), s["end"].get<double>()};
    }
    return {-1.0, -1.0};
}

/// The title the page's log gave chapter `chapter` ("title 2 Pause and think: ...").
std::string logged_title(const std::string& log, const std::string& chapter) {
    const std::string prefix = "title " + chapter + " ";
    const std::size_t at = log.find(prefix);
    if (at == std::string::npos) return "";
    const std::size_t from = at + prefix.size();
    return log.substr(from, log.find('\n', from) - from);
}

}  // namespace

TEST_CASE("the slide player stops on the question, not its answer, and the right arrow reveals") {
    const std::string chromium = chromium_program();
    if (chromium.empty()) COLLIDE_SKIP_TEST("chromium is not installed (scripts/setup.sh --test)");
    TempDir dir("slides_question");
    const fs::path scene = dir.path / "scene.toml";
    collide::test::write_file(scene, question_scene);
    const fs::path slides = dir.path / "talk";
    const fs::path timeline_file = dir.path / "t.json";
    const auto r =
        run_collide("render " + scene.string() + " --size 320x180 --fps 10 --progress none -o " +
                    (dir.path / "t.mp4").string() + " --slides " + slides.string() +
                    " --timeline-json " + timeline_file.string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    std::ifstream in(timeline_file);
    const nlohmann::json timeline = nlohmann::json::parse(in);
    const auto [question_start, question_end] = segment_of(timeline, "question");
    const auto [reveal_start, reveal_end] = segment_of(timeline, "reveal");
    REQUIRE(question_start >= 0.0);
    REQUIRE(reveal_start >= question_end - 1e-9);
    // ?test=9: the right arrow pressed for every chapter (fewer than 9), each stop logged with
    // its chapter's title.
    const std::string log = finished_test_log(
        chromium, dir.path / "profile", "file://" + slides.string() + "/index.html?test=9", 30000);
    INFO("test log: " << log);
    CHECK(log.find("error") == std::string::npos);
    REQUIRE(log.find("end") != std::string::npos);
    int question = -1;
    for (int n = 0; n < 9 && question < 0; ++n) {
        const std::vector<std::string> stop = log_line(log, "stop", n);
        if (stop.size() == 3 && logged_title(log, stop[0]).rfind("Pause and think", 0) == 0)
            question = n;
    }
    REQUIRE_MESSAGE(question >= 0, "no stop on a chapter titled with the question");
    // The player holds a frame of the question (the letters, the countdown), not the reveal's.
    const std::vector<std::string> asked = log_line(log, "stop", question);
    CHECK(asked[2] == "paused");
    const double asked_at = std::stod(asked[1]);
    CHECK(asked_at > question_start);
    CHECK(asked_at < question_end);
    CHECK(asked_at < reveal_start);
    // The next press plays the reveal and stops at its end, on the answer.
    const std::vector<std::string> answered = log_line(log, "stop", question + 1);
    REQUIRE(answered.size() == 3);
    CHECK(answered[2] == "paused");
    CHECK(std::stoi(answered[0]) == std::stoi(asked[0]) + 1);
    CHECK(logged_title(log, answered[0]).rfind("Answer: ", 0) == 0);
    const double answered_at = std::stod(answered[1]);
    CHECK(answered_at > reveal_start);
    CHECK(answered_at < reveal_end);
}
