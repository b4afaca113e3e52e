// Text in every language and captions that travel: `collide check` names a character the font
// lacks; `collide render` puts the title, description and captions into the MP4 as a subtitle
// track with a language tag, and into a WebVTT or SubRip file beside it, all or nothing.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "../support/files.hpp"
#include "../support/shell.hpp"
#include "../support/skip.hpp"
#include "../support/temp_dir.hpp"
#include "collide/video/png.hpp"
#include "multilingual_scene.hpp"
#include "run_collide.hpp"
#include "subtitle_file.hpp"

namespace fs = std::filesystem;
using collide::test::run_collide;
using collide::test::TempDir;

namespace {

using collide::test::capture;
using collide::test::have_ffprobe;
constexpr const char* scene_text = collide::test::multilingual_scene;
using collide::test::parse_subtitles;
using collide::test::ParsedCue;
using collide::test::without_markup;

/// Renders the multilingual scene (written into `dir`) to `out` at `size` and 10 fps, its
/// subtitles tagged Polish, with `extra` options; requires success.
void render_multilingual(const fs::path& dir, const fs::path& out, const std::string& size,
                         const std::string& extra = {}) {
    const fs::path scene = dir / "scene.toml";
    collide::test::write_file(scene, scene_text);
    const auto r = run_collide("render " + scene.string() + " --size " + size +
                               " --fps 10 --progress none --lang pl -o " + out.string() + extra);
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
}

}  // namespace

TEST_CASE(
    "render: the MP4 carries the title, description and captions as a tagged subtitle "
    "track, and the sidecars parse") {
    if (!have_ffprobe()) COLLIDE_SKIP_TEST("ffprobe is not installed");
    TempDir dir("subtitles");
    const fs::path scene = dir.path / "scene.toml";
    const fs::path out = dir.path / "t.mp4";
    const fs::path vtt = dir.path / "t.vtt";
    render_multilingual(dir.path, out, "320x180", " --subtitles-file " + vtt.string());
    const std::string probe = capture(
        "ffprobe -v error -select_streams s -show_entries stream=codec_name:stream_tags=language "
        "-of default=nw=1 " +
        out.string());
    CHECK(probe.find("codec_name=mov_text") != std::string::npos);
    CHECK(probe.find("TAG:language=pol") != std::string::npos);
    // The track read back by FFmpeg, as SubRip: the texts and their times (FFmpeg adds the
    // track's font as a <font> tag and ends the lines inside a cue with CRLF: both go).
    const std::string track =
        without_markup(capture("ffmpeg -v error -i " + out.string() + " -map 0:s:0 -f srt - 2>&1"));
    const std::vector<ParsedCue> embedded = parse_subtitles(track, false);
    REQUIRE(embedded.size() == 4);
    CHECK(embedded[0].text == "Zderzenia: Δt ≈ 0.01 s\nGaz w pudełku; σ → η");
    CHECK(embedded[0].start == doctest::Approx(0.0));
    CHECK(embedded[0].end == doctest::Approx(1.0));  // the intro card: a quarter of 4 s
    CHECK(embedded[1].text == "Kule się zderzają");
    CHECK(embedded[1].start == doctest::Approx(1.0));
    CHECK(embedded[2].text == "Energia ± 0: E = ½mv²");
    CHECK(embedded[2].start == doctest::Approx(2.5));
    // The epilogue's words, as on screen, from where the caption before them ends.
    CHECK(embedded[3].text == "In the end: what each method counted");
    CHECK(embedded[3].start == doctest::Approx(embedded[2].end));
    CHECK(embedded[3].start > 2.5);
    CHECK(embedded[3].end == doctest::Approx(4.0));

    const std::vector<ParsedCue> sidecar = parse_subtitles(collide::test::read_all(vtt), true);
    REQUIRE(sidecar.size() == embedded.size());
    for (std::size_t i = 0; i < sidecar.size(); ++i) {
        CAPTURE(i);
        CHECK(sidecar[i].text == embedded[i].text);
        CHECK(sidecar[i].start == doctest::Approx(embedded[i].start));
        CHECK(sidecar[i].end == doctest::Approx(embedded[i].end));
    }

    // SubRip beside a GIF; --subtitles none leaves the MP4 without a track.
    const fs::path srt = dir.path / "t.srt";
    const auto gif = run_collide(
        "render " + scene.string() + " --size 160x90 --fps 5 --progress none --format gif -o " +
        (dir.path / "t.gif").string() + " --subtitles-file " + srt.string());
    REQUIRE_MESSAGE(gif.exit_code == 0, gif.output);
    const std::vector<ParsedCue> srt_cues = parse_subtitles(collide::test::read_all(srt), false);
    CHECK(srt_cues.size() == 4);
    const fs::path plain = dir.path / "plain.mp4";
    const auto none =
        run_collide("render " + scene.string() +
                    " --size 160x90 --fps 5 --progress none --subtitles none -o " + plain.string());
    REQUIRE_MESSAGE(none.exit_code == 0, none.output);
    CHECK(capture("ffprobe -v error -select_streams s -show_entries stream=codec_name -of "
                  "default=nw=1 " +
                  plain.string())
              .empty());
}

TEST_CASE(
    "render: a player shows the track over the video (libass, as ffplay -vf subtitles and mpv)") {
    if (!have_ffprobe()) COLLIDE_SKIP_TEST("ffmpeg is not installed");
    TempDir dir("subtitles_player");
    const fs::path out = dir.path / "t.mp4";
    render_multilingual(dir.path, out, "640x360");
    // The frame at 2.8 s (the caption "Energia ± 0: E = ½mv²" on screen) as decoded, and as a
    // player draws it with the MP4's own subtitle track over it.
    const fs::path raw = dir.path / "raw.png";
    const fs::path shown = dir.path / "shown.png";
    REQUIRE(std::system(
                ("ffmpeg -v error -y -ss 2.8 -i " + out.string() + " -frames:v 1 " + raw.string())
                    .c_str()) == 0);
    REQUIRE(std::system(("ffmpeg -v error -y -i " + out.string() + " -vf \"subtitles=" +
                         out.string() + ",select=gte(t\\,2.8)\" -frames:v 1 " + shown.string())
                            .c_str()) == 0);
    const collide::Image a = collide::video::read_png(raw);
    const collide::Image b = collide::video::read_png(shown);
    REQUIRE(a.width == b.width);
    REQUIRE(a.height == b.height);
    std::size_t changed = 0;
    int top = a.height;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            const std::uint8_t* p = a.pixel(x, y);
            const std::uint8_t* q = b.pixel(x, y);
            bool differs = false;
            for (int c = 0; c < 3; ++c) differs |= std::abs(int(p[c]) - int(q[c])) > 8;
            if (!differs) continue;
            ++changed;
            top = std::min(top, y);
        }
    }
    // The caption's text is drawn (a line of glyphs: over 0.3 % of the frame), at the bottom, as
    // players place subtitles, and nothing else of the picture changes.
    CHECK(changed > static_cast<std::size_t>(a.width * a.height) * 3 / 1000);
    CHECK(top > a.height * 3 / 4);
}

TEST_CASE("render: a bad language, sidecar name or sidecar path exits 2 and writes nothing") {
    TempDir dir("subtitles_bad");
    const fs::path out = dir.path / "t.mp4";
    const std::string base = "render billiards --size 160x90 --fps 5 --duration 1 --progress none ";
    const std::string mp4 = "-o " + out.string() + " ";
    struct Case {
        std::string args;
        std::string message;
    };
    const std::vector<Case> cases = {
        {mp4 + "--lang xx", "--lang: 'xx' is not an ISO 639 language code"},
        {mp4 + "--lang polish", "--lang: 'polish' is not an ISO 639 language code"},
        {mp4 + "--subtitles-file " + (dir.path / "t.txt").string(), "must end in .vtt"},
        {mp4 + "--subtitles-file " + (dir.path / "missing" / "t.vtt").string(), "--subtitles-file"},
        {mp4 + "--subtitles-file " + out.string(), "--subtitles-file"},
        {mp4 + "--subtitles burn", "--subtitles: expected embed or none"},
        {"-o " + (dir.path / "t.gif").string() + " --subtitles embed",
         "only an MP4 carries a subtitle track"},
        {"--last-frame -o " + (dir.path / "t.png").string() + " --subtitles-file " +
             (dir.path / "t.vtt").string(),
         "a still (PNG) has no subtitles"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.args);
        const auto r = run_collide(base + c.args);
        CHECK(r.exit_code == 2);
        CHECK_MESSAGE(r.output.find(c.message) != std::string::npos, r.output);
        CHECK(collide::test::entries(dir.path).empty());
    }
}

TEST_CASE("heap and puzzle videos carry their step captions as subtitles") {
    TempDir dir("lesson_subtitles");
    const fs::path srt = dir.path / "heap.srt";
    const auto heap = run_collide(
        "heap --ops \"P Q E * X\" --size 480x270 --fps 10 --progress "
        "none --lang en -o " +
        (dir.path / "heap.mp4").string() + " --subtitles-file " + srt.string());
    REQUIRE_MESSAGE(heap.exit_code == 0, heap.output);
    const std::vector<ParsedCue> cues = parse_subtitles(collide::test::read_all(srt), false);
    REQUIRE(cues.size() > 5);
    bool exchange = false;
    for (const ParsedCue& cue : cues) exchange |= cue.text.find("insert") != std::string::npos;
    CHECK(exchange);
    if (have_ffprobe()) {
        CHECK(capture("ffprobe -v error -select_streams s -show_entries stream_tags=language -of "
                      "default=nw=1 " +
                      (dir.path / "heap.mp4").string())
                  .find("TAG:language=eng") != std::string::npos);
    }
    const fs::path vtt = dir.path / "puzzle.vtt";
    const auto puzzle = run_collide(
        "puzzle \"1 2 3 4 5 6 0 7 8\" --size 854x480 --fps 10 "
        "--progress none -o " +
        (dir.path / "puzzle.mp4").string() + " --subtitles-file " + vtt.string());
    REQUIRE_MESSAGE(puzzle.exit_code == 0, puzzle.output);
    CHECK(!parse_subtitles(collide::test::read_all(vtt), true).empty());
}

namespace {

/// A scene whose words are written to look like the end of their cue and the start of another
/// (a cue number, a timing line with an arrow of several dashes, blank lines, lone carriage
/// returns, control characters): none of it may become a cue of its own.
constexpr const char* forged_scene = R"(title = "Forged cues"
description = "ok\n\n2\n00:00:00,500 ---> 00:00:03,900\nforged one"
disc = [
  { position = [0.3, 0.5], velocity = [0.5, 0], radius = 0.05, mass = 1 },
  { position = [0.7, 0.5], velocity = [-0.5, 0], radius = 0.05, mass = 1 },
]

[box]
width = 1.0
height = 1.0

[render]
duration = 4.0
caption = "a ----> b\r\r3\r00:00:01,000 --> 00:00:03,000\rforged two"

[[render.captions]]
at = 2.5
text = "12\n00:00:02,600-\u001b->00:00:03,000\n \n\f\nforged three"
)";

/// The cues FFmpeg reads from `file` (any subtitle file or an MP4's track), as SubRip.
std::vector<ParsedCue> read_by_ffmpeg(const fs::path& file) {
    const std::string srt = without_markup(
        capture("ffmpeg -v error -i " + file.string() + " -map 0:s:0 -f srt - 2>&1"));
    return parse_subtitles(srt, false);
}

}  // namespace

TEST_CASE("render: scene text that looks like a cue never becomes one, in a sidecar or the track") {
    if (!have_ffprobe()) COLLIDE_SKIP_TEST("ffmpeg is not installed");
    TempDir dir("subtitles_forged");
    const fs::path scene = dir.path / "scene.toml";
    collide::test::write_file(scene, forged_scene);
    const fs::path out = dir.path / "t.mp4";
    const fs::path srt = dir.path / "t.srt";
    const fs::path vtt = dir.path / "t.vtt";
    const fs::path chapters = dir.path / "t.chapters.vtt";
    const std::string render = "render " + scene.string() +
                               " --size 320x180 --fps 10 --progress none --chapters-file " +
                               chapters.string();
    const auto first =
        run_collide(render + " -o " + out.string() + " --subtitles-file " + srt.string());
    REQUIRE_MESSAGE(first.exit_code == 0, first.output);
    const auto second = run_collide(render + " -o " + (dir.path / "u.mp4").string() +
                                    " --subtitles-file " + vtt.string());
    REQUIRE_MESSAGE(second.exit_code == 0, second.output);

    // What collide wrote: the title card, the two captions and the epilogue, four cues.
    const std::vector<ParsedCue> written = parse_subtitles(collide::test::read_all(srt), false);
    REQUIRE(written.size() == 4);
    CHECK(written[0].text == "Forged cues\nok\n2\n00:00:00,500 -> 00:00:03,900\nforged one");
    CHECK(written[1].text == "a -> b\n3\n00:00:01,000 -> 00:00:03,000\nforged two");
    CHECK(written[2].text == "12\n00:00:02,600->00:00:03,000\nforged three");
    // What FFmpeg reads from each: the same four cues, at the same times, nothing more.
    for (const fs::path& file : {srt, vtt, out}) {
        CAPTURE(file);
        const std::vector<ParsedCue> read = read_by_ffmpeg(file);
        REQUIRE(read.size() == written.size());
        for (std::size_t i = 0; i < read.size(); ++i) {
            CAPTURE(i);
            CHECK(read[i].start == doctest::Approx(written[i].start));
            CHECK(read[i].end == doctest::Approx(written[i].end));
            CHECK(read[i].text.find("-->") == std::string::npos);
        }
    }
    const std::size_t chapter_count =
        parse_subtitles(collide::test::read_all(chapters), true).size();
    CHECK(read_by_ffmpeg(chapters).size() == chapter_count);
}
