// One caption at a time, in the words of the panels shown: `collide render` with --mode event or
// --mode time writes no word of the absent panel into any built-in scene's subtitles; a video
// that draws its captions carries its subtitle track switched off (ffprobe's disposition), and
// the slide player, opened in headless Chromium, draws no text track over the video.
#include <doctest/doctest.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
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
using collide::test::without_markup;

namespace {

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

/// `phrase` in `text` as whole words ("left" in "Left: ...", not in "leftover"), any case.
bool says(const std::string& text, const std::string& phrase) {
    const std::string t = lower(text);
    const auto letter = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; };
    for (std::size_t at = t.find(phrase); at != std::string::npos; at = t.find(phrase, at + 1)) {
        const bool starts = at == 0 || !letter(t[at - 1]);
        const std::size_t end = at + phrase.size();
        const bool ends = end == t.size() || !letter(t[end]);
        if (starts && ends) return true;
    }
    return false;
}

/// The built-in scenes (`collide scenes` lists them, one name first on each line).
std::vector<std::string> built_in_scenes() {
    const auto r = run_collide("scenes");
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    std::vector<std::string> names;
    std::istringstream lines(r.output);
    std::string line;
    while (std::getline(lines, line)) {
        std::istringstream words(line);
        std::string name;
        if (words >> name && fs::exists(fs::path(COLLIDE_ASSETS_DIR) / "scenes" / (name + ".toml")))
            names.push_back(name);
    }
    return names;
}

/// Every subtitle of `scene` rendered with `mode` (a small, slow-frame video: the cues are the
/// timeline's, whatever the size and frame rate).
std::vector<ParsedCue> mode_subtitles(const TempDir& dir, const std::string& scene,
                                      const std::string& mode, const std::string& extra = "") {
    const fs::path vtt = dir.path / (scene + "-" + mode + ".vtt");
    const auto r = run_collide("render " + scene + " --mode " + mode + extra +
                               " --size 320x180 --fps 5 --progress none -o " +
                               (dir.path / (scene + "-" + mode + ".mp4")).string() +
                               " --subtitles-file " + vtt.string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    return parse_subtitles(collide::test::read_all(vtt), true);
}

/// The value of `disposition.default` ffprobe reads for the first subtitle stream of `file`.
std::string subtitle_default(const fs::path& file) {
    std::string out = capture(
        "ffprobe -v error -select_streams s:0 -show_entries stream_disposition=default -of "
        "default=nw=1:nk=1 " +
        file.string());
    out.erase(std::remove_if(out.begin(), out.end(),
                             [](unsigned char c) { return std::isspace(c) != 0; }),
              out.end());
    return out;
}

}  // namespace

TEST_CASE("render --mode event and --mode time: no subtitle speaks of the absent panel") {
    TempDir dir("captions_modes");
    // Words that only make sense beside the other panel.
    const std::vector<std::string> two_panels = {"left", "right", "both", "side by side",
                                                 "the two"};
    const std::vector<std::string> time_words = {"time-driven"};
    const std::vector<std::string> event_words = {"event-driven", "queue", "predicts", "predicted"};
    const std::vector<std::string> scenes = built_in_scenes();
    REQUIRE(scenes.size() >= 10);
    for (const std::string& scene : scenes) {
        for (const std::string mode : {"event", "time"}) {
            CAPTURE(scene);
            CAPTURE(mode);
            const std::vector<ParsedCue> cues = mode_subtitles(dir, scene, mode);
            REQUIRE(cues.size() >= 3);  // the card, captions, the epilogue
            std::vector<std::string> absent = two_panels;
            for (const std::string& w : mode == "event" ? time_words : event_words)
                absent.push_back(w);
            for (const ParsedCue& cue : cues) {
                for (const std::string& word : absent)
                    CHECK_MESSAGE(!says(cue.text, word), "\"" << cue.text << "\" says " << word);
            }
        }
    }
}

TEST_CASE("render: the scene's own words for one panel replace the two-panel caption") {
    TempDir dir("captions_forms");
    const std::vector<ParsedCue> both = [&] {
        const fs::path vtt = dir.path / "both.vtt";
        const auto r =
            run_collide("render gas --questions none --size 320x180 --fps 5 --progress none -o " +
                        (dir.path / "both.mp4").string() + " --subtitles-file " + vtt.string());
        REQUIRE_MESSAGE(r.exit_code == 0, r.output);
        return parse_subtitles(collide::test::read_all(vtt), true);
    }();
    const auto has = [](const std::vector<ParsedCue>& cues, const std::string& text) {
        return std::any_of(cues.begin(), cues.end(),
                           [&](const ParsedCue& c) { return c.text == text; });
    };
    CHECK(has(both, "Left tests every pair each step; right predicts collisions"));
    CHECK(has(both, "In the end: what each method counted"));
    // Without the questions (a time-driven video asks none), so the captions pair one for one.
    const std::vector<ParsedCue> event = mode_subtitles(dir, "gas", "event", " --questions none");
    CHECK(has(event, "The queue predicts each collision before it happens"));
    CHECK(has(event, "In the end: the final figures"));
    const std::vector<ParsedCue> time = mode_subtitles(dir, "gas", "time", " --questions none");
    CHECK(has(time, "Each step tests every pair of discs for overlap"));
    // At the same moment in each video: one cue for one cue.
    CHECK(event.size() == both.size());
    CHECK(time.size() == both.size());
}

TEST_CASE("render: the subtitle track is off by default when the picture draws the captions") {
    if (!have_ffprobe()) COLLIDE_SKIP_TEST("ffprobe is not installed");
    TempDir dir("captions_disposition");
    const fs::path scene = dir.path / "scene.toml";
    collide::test::write_file(scene, collide::test::multilingual_scene);
    const std::string base =
        "render " + scene.string() + " --size 320x180 --fps 10 --progress none --lang pl ";
    // The lesson level draws every caption: the track is there, switched off.
    const fs::path lesson = dir.path / "lesson.mp4";
    const auto r = run_collide(base + "-o " + lesson.string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    CHECK(subtitle_default(lesson) == "0");
    const std::string track =
        without_markup(capture("ffmpeg -v error -i " + lesson.string() + " -map 0:s:0 -f srt -"));
    CHECK(parse_subtitles(track, false).size() == 4);
    // --overlays full draws no caption: the track is the default one.
    const fs::path full = dir.path / "full.mp4";
    const auto f = run_collide(base + "--overlays full -o " + full.string());
    REQUIRE_MESSAGE(f.exit_code == 0, f.output);
    CHECK(subtitle_default(full) == "1");
    // The video's frames are decoded whole after the change (the index is intact).
    CHECK(capture("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                  "stream=nb_read_frames -of default=nw=1:nk=1 " +
                  lesson.string())
              .find("40") == 0);
    // Heap videos draw their step captions too.
    const fs::path heap = dir.path / "heap.mp4";
    const auto h = run_collide("heap --ops \"P Q E\" --size 480x270 --fps 10 --progress none -o " +
                               heap.string());
    REQUIRE_MESSAGE(h.exit_code == 0, h.output);
    CHECK(subtitle_default(heap) == "0");
}

TEST_CASE("the slide player and a <track> page in headless Chromium draw no caption twice") {
    const std::string chromium = chromium_program();
    if (chromium.empty()) COLLIDE_SKIP_TEST("chromium is not installed (scripts/setup.sh --test)");
    TempDir dir("captions_browser");
    const fs::path scene = dir.path / "scene.toml";
    collide::test::write_file(scene, collide::test::multilingual_scene);
    const fs::path slides = dir.path / "talk";
    const fs::path vtt = dir.path / "t.vtt";
    const auto r = run_collide("render " + scene.string() +
                               " --size 320x180 --fps 10 --progress none --lang pl -o " +
                               (dir.path / "t.mp4").string() + " --slides " + slides.string() +
                               " --subtitles-file " + vtt.string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);

    // The slide player: its cues are loaded, no track is drawn, at the start or at any stop.
    const std::string page = collide::test::read_all(slides / "index.html");
    CHECK(page.find("label=\"Subtitles\" default") == std::string::npos);
    const std::string log = finished_test_log(
        chromium, dir.path / "profile", "file://" + slides.string() + "/index.html?test", 20000);
    INFO("test log: " << log);
    REQUIRE(log.find("end") != std::string::npos);
    CHECK(log.find("subtitles 4") != std::string::npos);
    CHECK(log.find("showing 0") != std::string::npos);
    CHECK(log.find("showing 1") == std::string::npos);

    // A page of one's own with the sidecar as docs/outputs.md shows it (no `default`): the
    // browser loads the cues and draws none over the video's own.
    collide::test::write_file(dir.path / "own.html",
                              "<!DOCTYPE html><html><body><video id=\"v\" src=\"t.mp4\" muted>"
                              "<track kind=\"subtitles\" src=\"t.vtt\" srclang=\"pl\"></video>"
                              "<pre id=\"test-log\"></pre><script>"
                              "const v = document.getElementById('v');"
                              "const t = v.textTracks[0];"
                              "setTimeout(function () {"
                              "  document.getElementById('test-log').textContent ="
                              "    'tracks ' + v.textTracks.length + ' mode ' + t.mode + ' end';"
                              "}, 500);</script></body></html>");
    const std::string own = finished_test_log(chromium, dir.path / "profile2",
                                              "file://" + (dir.path / "own.html").string(), 5000);
    INFO("own page: " << own);
    REQUIRE(own.find("end") != std::string::npos);
    CHECK(own.find("tracks 1") != std::string::npos);
    CHECK(own.find("mode showing") == std::string::npos);
}
