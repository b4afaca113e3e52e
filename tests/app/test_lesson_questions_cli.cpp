// `collide heap --questions on` and `collide puzzle --questions on` end to end (issue #45): the
// real program asks "where does K end up?" and "which board does A* expand next?" in its
// subtitles and chapters, `--questions none` (the default) asks nothing, and a bad value is
// refused naming the option.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../support/temp_dir.hpp"
#include "run_collide.hpp"
#include "subtitle_file.hpp"

using collide::test::parse_subtitles;
using collide::test::run_collide;
using collide::test::run_collide_bad_input;
using collide::test::shell_quoted;
using collide::test::TempDir;
namespace fs = std::filesystem;

namespace {

// Small and quick: 320x180 at 5 frames per second.
const std::string quick = " --size 320x180 --fps 5 --pace 0.1 --progress none ";

std::string text_of(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The cues of `file` whose text starts with `head`.
std::size_t cues_starting(const fs::path& file, const std::string& head) {
    std::size_t n = 0;
    for (const auto& cue : parse_subtitles(text_of(file), file.extension() == ".vtt"))
        n += cue.text.rfind(head, 0) == 0;
    return n;
}

/// The kinds of the timeline's segments in order, checked back to back from frame 0; a
/// question's segment is followed by its reveal, and holds at least 2 s.
std::vector<std::string> segment_kinds(const fs::path& file) {
    std::ifstream in(file);
    const nlohmann::json timeline = nlohmann::json::parse(in);
    std::vector<std::string> kinds;
    std::int64_t frame = 0;
    const nlohmann::json& segments = timeline["segments"];
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const nlohmann::json& s = segments[i];
        CHECK(s["first_frame"].get<std::int64_t>() == frame);
        frame = s["end_frame"].get<std::int64_t>();
        CHECK(frame > s["first_frame"].get<std::int64_t>());
        kinds.push_back(s["kind"].get<std::string>());
        if (kinds.back() == "question") {
            CHECK(s["end"].get<double>() - s["start"].get<double>() >= 2.0 - 1e-9);
            REQUIRE(i + 1 < segments.size());
            CHECK(segments[i + 1]["kind"] == "reveal");
            CHECK(s["caption"].get<std::string>().find('?') != std::string::npos);
            CHECK(segments[i + 1]["caption"].get<std::string>().rfind("Answer: ", 0) == 0);
        }
    }
    CHECK(frame == timeline["frames"].get<std::int64_t>());
    return kinds;
}

std::size_t count_of(const std::vector<std::string>& kinds, const std::string& kind) {
    return static_cast<std::size_t>(std::count(kinds.begin(), kinds.end(), kind));
}

}  // namespace

TEST_CASE(
    "collide heap --questions on asks where each key ends up, in the subtitles and "
    "the chapters, and none (the default) asks nothing") {
    TempDir dir("heap_questions");
    const std::string ops = "heap --ops \"S O R T * E X\" --min" + quick;
    const auto on = run_collide(ops + "--questions on -o " + shell_quoted(dir.path / "on.mp4") +
                                " --subtitles-file " + shell_quoted(dir.path / "on.srt") +
                                " --chapters-file " + shell_quoted(dir.path / "on.vtt") +
                                " --timeline-json " + shell_quoted(dir.path / "on.json"));
    REQUIRE_MESSAGE(on.exit_code == 0, on.output);
    const std::vector<std::string> kinds = segment_kinds(dir.path / "on.json");
    CHECK(count_of(kinds, "question") == 6);
    CHECK(count_of(kinds, "reveal") == 6);
    // S alone asks nothing; O, R, T, the remove, E and X each ask and answer.
    CHECK(cues_starting(dir.path / "on.srt", "Where does ") == 6);
    CHECK(cues_starting(dir.path / "on.srt", "Answer: ") == 6);
    const std::string chapters = text_of(dir.path / "on.vtt");
    CHECK(chapters.find("Where does O end up: A or B?") != std::string::npos);

    for (const std::string& quiet : {std::string(), std::string("--questions none ")}) {
        CAPTURE(quiet);
        const auto off = run_collide(ops + quiet + "-o " + shell_quoted(dir.path / "off.mp4") +
                                     " --subtitles-file " + shell_quoted(dir.path / "off.srt") +
                                     " --timeline-json " + shell_quoted(dir.path / "off.json"));
        REQUIRE_MESSAGE(off.exit_code == 0, off.output);
        CHECK(segment_kinds(dir.path / "off.json") == std::vector<std::string>{"run"});
        fs::remove(dir.path / "off.json");
        CHECK(cues_starting(dir.path / "off.srt", "Where does ") == 0);
        CHECK(cues_starting(dir.path / "off.srt", "Answer: ") == 0);
        fs::remove(dir.path / "off.mp4");
        fs::remove(dir.path / "off.srt");
    }
}

TEST_CASE("collide heap --questions refuses anything but on or none, before writing") {
    TempDir dir("heap_questions_bad");
    const std::string out = run_collide_bad_input("heap --ops \"P Q\" --questions maybe" + quick +
                                                  "-o " + shell_quoted(dir.path / "q.mp4"));
    CHECK(out.find("--questions") != std::string::npos);
    CHECK_FALSE(fs::exists(dir.path / "q.mp4"));
}

TEST_CASE("collide puzzle --questions on asks which board A* expands next, and none asks nothing") {
    TempDir dir("puzzle_questions");
    const std::string board =
        "puzzle \"1 2 3 4 0 6 7 5 8\" --size 854x480 --fps 4 --progress none ";
    const auto on = run_collide(board + "--questions on -o " + shell_quoted(dir.path / "on.mp4") +
                                " --subtitles-file " + shell_quoted(dir.path / "on.vtt") +
                                " --chapters-file " + shell_quoted(dir.path / "chapters.vtt") +
                                " --timeline-json " + shell_quoted(dir.path / "on.json"));
    REQUIRE_MESSAGE(on.exit_code == 0, on.output);
    CHECK(segment_kinds(dir.path / "on.json") ==
          std::vector<std::string>{"run", "question", "reveal", "run"});
    const std::string subtitles = text_of(dir.path / "on.vtt");
    CHECK(subtitles.find("Which board does A* expand next: A or B?") != std::string::npos);
    CHECK(subtitles.find("Answer: ") != std::string::npos);
    CHECK(text_of(dir.path / "chapters.vtt").find("expand next") != std::string::npos);

    const auto off = run_collide(board + "-o " + shell_quoted(dir.path / "off.mp4") +
                                 " --subtitles-file " + shell_quoted(dir.path / "off.vtt") +
                                 " --timeline-json " + shell_quoted(dir.path / "off.json"));
    REQUIRE_MESSAGE(off.exit_code == 0, off.output);
    CHECK(segment_kinds(dir.path / "off.json") == std::vector<std::string>{"run"});
    CHECK(text_of(dir.path / "off.vtt").find("expand next") == std::string::npos);

    const std::string bad =
        run_collide_bad_input(board + "--questions yes -o " + shell_quoted(dir.path / "bad.mp4"));
    CHECK(bad.find("--questions") != std::string::npos);
    CHECK_FALSE(fs::exists(dir.path / "bad.mp4"));
}

TEST_CASE("collide heap and puzzle --timeline-json: refused for a still, before writing") {
    TempDir dir("lesson_timeline_still");
    const std::string heap = run_collide_bad_input(
        "heap --ops \"P Q\" --questions on --last-frame" + quick + "-o " +
        shell_quoted(dir.path / "h.png") + " --timeline-json " + shell_quoted(dir.path / "h.json"));
    CHECK(heap.find("--timeline-json") != std::string::npos);
    const std::string puzzle = run_collide_bad_input(
        "puzzle \"1 2 3 4 0 6 7 5 8\" --last-frame --size 854x480 --progress none -o " +
        shell_quoted(dir.path / "p.png") + " --timeline-json " + shell_quoted(dir.path / "p.json"));
    CHECK(puzzle.find("--timeline-json") != std::string::npos);
    CHECK(fs::is_empty(dir.path));
}
