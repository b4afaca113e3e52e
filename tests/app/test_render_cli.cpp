// End-to-end tests of `collide render` and `collide thumbnail`: the files a user gets, read back.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "../support/shell.hpp"
#include "../support/skip.hpp"
#include "../support/temp_dir.hpp"
#include "collide/image.hpp"
#include "collide/video/png.hpp"
#include "golden_image.hpp"
#include "run_collide.hpp"

namespace fs = std::filesystem;
using collide::Image;
using collide::test::capture;
using collide::test::check_golden;
using collide::test::have_ffprobe;
using collide::test::run_collide;
using collide::test::share_of_differing_pixels;
using collide::test::shell_quoted;

namespace {

using collide::test::TempDir;

std::string read_bytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("render: a 2-second side-by-side MP4 that plays everywhere") {
    if (!have_ffprobe()) {
        COLLIDE_SKIP_TEST("ffprobe is not installed (scripts/setup.sh --test installs it)");
    }
    TempDir dir("mp4");
    const fs::path out = dir.path / "t.mp4";
    const auto r =
        run_collide("render tunnelling --size 320x180 --fps 12 --duration 2 --progress none -o " +
                    out.string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    CHECK(r.output.find("24 frames") != std::string::npos);
    const std::string probe = capture(
        "ffprobe -v error -select_streams v:0 -count_frames -show_entries "
        "stream=codec_name,pix_fmt,width,height,nb_read_frames,r_frame_rate:format=duration -of "
        "default=nw=1 " +
        out.string());
    CHECK(probe.find("codec_name=h264") != std::string::npos);
    CHECK(probe.find("pix_fmt=yuv420p") != std::string::npos);
    CHECK(probe.find("width=320") != std::string::npos);
    CHECK(probe.find("height=180") != std::string::npos);
    CHECK(probe.find("nb_read_frames=24") != std::string::npos);
    CHECK(probe.find("r_frame_rate=12/1") != std::string::npos);
    CHECK(probe.find("duration=2.0") != std::string::npos);
}

TEST_CASE("render --format gif: peak memory does not grow with the number of frames") {
    // The palette pass used to keep every frame (0.9 MB at 640x360) queued in memory until the
    // end: 105 more frames cost ~90 MB. Flat memory leaves a few MB for the encoders' buffers.
    const collide::test::TempDir dir("gif_memory");
    const auto peak_kib = [&](const std::string& duration) {
        const auto r = collide::test::run_collide_measured(
            "render gas --mode event --size 640x360 --fps 15 --duration " + duration +
            " --format gif -o \"" + (dir.path / ("gas_" + duration + ".gif")).string() + "\"");
        REQUIRE_MESSAGE(r.exit_code == 0, r.output);
        return r.peak_rss_kib;
    };
    const long short_clip = peak_kib("1");  // 15 frames
    const long long_clip = peak_kib("8");   // 120 frames
    MESSAGE("peak resident size: " << short_clip / 1024 << " MiB for 15 frames, "
                                   << long_clip / 1024 << " MiB for 120");
    CHECK(long_clip <= short_clip + 16 * 1024);
}

TEST_CASE("render: the same scene and options give a byte-identical file") {
    TempDir dir("determinism");
    const std::string args = "render gas --size 320x180 --fps 10 --duration 1 --progress none -o ";
    const auto a = run_collide(args + (dir.path / "a.mp4").string());
    const auto b = run_collide(args + (dir.path / "b.mp4").string());
    REQUIRE_MESSAGE(a.exit_code == 0, a.output);
    REQUIRE_MESSAGE(b.exit_code == 0, b.output);
    const std::string bytes = read_bytes(dir.path / "a.mp4");
    CHECK(bytes.size() > 1000);
    CHECK(bytes == read_bytes(dir.path / "b.mp4"));
}

TEST_CASE("render --last-frame equals thumbnail --at the end time") {
    TempDir dir("last");
    // 1 s at 10 fps and speed 0.5 without card or summary: the last frame (k = 9) is at t = 0.45
    const auto last = run_collide(
        "render gas --size 320x180 --fps 10 --duration 1 --speed 0.5 --last-frame --no-intro "
        "--no-epilogue --progress none -o " +
        (dir.path / "last.png").string());
    REQUIRE_MESSAGE(last.exit_code == 0, last.output);
    const auto thumb =
        run_collide("thumbnail gas --size 320x180 --fps 10 --speed 0.5 --at 0.45 -o " +
                    (dir.path / "thumb.png").string());
    REQUIRE_MESSAGE(thumb.exit_code == 0, thumb.output);
    const Image a = collide::video::read_png(dir.path / "last.png");
    const Image b = collide::video::read_png(dir.path / "thumb.png");
    CHECK(a.width == 320);
    CHECK(share_of_differing_pixels(a, b) == 0.0);
    // With the card (0.25 s, 3 frames, the simulation waiting) and the summary (0.2 s, 2 frames)
    // the video shows 6 states: its last simulation frame is at t = 0.25, and --last-frame
    // shows that state, without the summary card over it.
    const auto carded = run_collide(
        "render gas --size 320x180 --fps 10 --duration 1 --speed 0.5 --last-frame "
        "--progress none -o " +
        (dir.path / "carded.png").string());
    REQUIRE_MESSAGE(carded.exit_code == 0, carded.output);
    CHECK_MESSAGE(carded.output.find("t = 0.25 ") != std::string::npos, carded.output);
    const auto early =
        run_collide("thumbnail gas --size 320x180 --fps 10 --speed 0.5 --at 0.25 -o " +
                    (dir.path / "early.png").string());
    REQUIRE_MESSAGE(early.exit_code == 0, early.output);
    CHECK(share_of_differing_pixels(collide::video::read_png(dir.path / "carded.png"),
                                    collide::video::read_png(dir.path / "early.png")) == 0.0);
}

TEST_CASE("render: a hold beyond the video exits 2 naming the file, line and field") {
    TempDir dir("hold");
    const fs::path scene = dir.path / "h.toml";
    std::ofstream(scene) << "[box]\nwidth = 1.0\nheight = 1.0\n"
                            "[[disc]]\nposition = [0.3, 0.5]\nvelocity = [0.1, 0]\nradius = 0.05\n"
                            "[render]\nduration = 4\n"
                            "[[render.captions]]\nat = 3\ntext = \"Look\"\nhold = 2\n";
    const fs::path mp4 = dir.path / "h.mp4";
    const auto r = run_collide("render " + scene.string() + " --progress none -o " + mp4.string());
    CHECK(r.exit_code == 2);
    CHECK_MESSAGE(
        r.output.find("h.toml:13: render.captions[0].hold: beyond the video") != std::string::npos,
        r.output);
    CHECK(!fs::exists(mp4));
}

TEST_CASE("render --timeline-json: every segment in order, the clock frozen outside runs") {
    TempDir dir("timeline");
    const fs::path json = dir.path / "t.json";
    const auto r = run_collide("render newtons-cradle --size 320x180 --fps 10 --progress none -o " +
                               (dir.path / "c.mp4").string() + " --timeline-json " + json.string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    std::ifstream in(json);
    std::stringstream text;
    text << in.rdbuf();
    const std::string t = text.str();
    // The card, the run, the hold on the first hit, the summary.
    const std::size_t card = t.find("\"kind\": \"card\"");
    const std::size_t hold = t.find("\"kind\": \"hold\"");
    const std::size_t epilogue = t.find("\"kind\": \"epilogue\"");
    CHECK(card != std::string::npos);
    CHECK(hold != std::string::npos);
    CHECK(epilogue != std::string::npos);
    CHECK(card < hold);
    CHECK(hold < epilogue);
    CHECK(t.find("\"caption\": \"The striker stops, the last disc moves off\"") !=
          std::string::npos);
    CHECK(t.find("\"frames\": 170") != std::string::npos);
    // Only for videos.
    const auto still = run_collide("thumbnail gas --timeline-json " + json.string());
    CHECK(still.exit_code == 2);
}

TEST_CASE(
    "render --replay: tunnelling replays its first failure, frozen, and none replays nothing") {
    TempDir dir("replay");
    const fs::path json = dir.path / "t.json";
    const std::string common = "render tunnelling --size 480x270 --fps 10 --progress none -o " +
                               (dir.path / "t.mp4").string() + " --timeline-json " + json.string();
    const auto read = [&] {
        std::ifstream in(json);
        std::stringstream text;
        text << in.rdbuf();
        return text.str();
    };
    const auto r = run_collide(common);
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    const std::string t = read();
    const std::size_t replay = t.find("\"kind\": \"replay\"");
    REQUIRE_MESSAGE(replay != std::string::npos, t);
    CHECK(t.find("\"kind\": \"replay\"", replay + 1) == std::string::npos);  // only the first
    CHECK(t.find("\"caption\": \"Between two checks the disc jumped through: no overlap was "
                 "ever seen\"") != std::string::npos);
    // The simulation clock stands still during the replay.
    const std::size_t start = t.find("\"sim_start\": ", replay);
    const std::size_t end = t.find("\"sim_end\": ", replay);
    REQUIRE(start != std::string::npos);
    REQUIRE(end != std::string::npos);
    const double sim_start = std::stod(t.substr(start + 13));
    const double sim_end = std::stod(t.substr(end + 11));
    CHECK(sim_start == sim_end);
    CHECK(t.find("\"moves\": false", replay) < t.find("\"kind\"", replay + 1));

    const auto none = run_collide(common + " --replay none");
    REQUIRE_MESSAGE(none.exit_code == 0, none.output);
    CHECK(read().find("\"kind\": \"replay\"") == std::string::npos);
}

TEST_CASE("render --replay and [render] replay: a bad value exits 2 naming the option or field") {
    TempDir dir("replay-bad");
    const fs::path mp4 = dir.path / "x.mp4";
    const auto option =
        run_collide("render tunnelling --replay some --progress none -o " + mp4.string());
    CHECK(option.exit_code == 2);
    CHECK_MESSAGE(option.output.find("--replay") != std::string::npos, option.output);
    const fs::path scene = dir.path / "r.toml";
    std::ofstream(scene) << "[box]\nwidth = 1.0\nheight = 1.0\n"
                            "[[disc]]\nposition = [0.3, 0.5]\nvelocity = [0.1, 0]\nradius = 0.05\n"
                            "[render]\nreplay = \"some\"\n";
    const auto hint =
        run_collide("render " + scene.string() + " --progress none -o " + mp4.string());
    CHECK(hint.exit_code == 2);
    CHECK_MESSAGE(hint.output.find("r.toml:9") != std::string::npos, hint.output);
    CHECK_MESSAGE(hint.output.find("render.replay") != std::string::npos, hint.output);
    CHECK(!fs::exists(mp4));
    // A replay_tag no disc carries is named where it was written, by `check` too.
    std::ofstream(scene) << "[box]\nwidth = 1.0\nheight = 1.0\n"
                            "[[disc]]\nposition = [0.3, 0.5]\nradius = 0.05\ntag = \"wall\"\n"
                            "[render]\nreplay_tag = \"barrier\"\n";
    for (const std::string& command :
         {"render " + scene.string() + " --progress none -o " + mp4.string(),
          "check " + scene.string()}) {
        const auto tag = run_collide(command);
        CAPTURE(command);
        CHECK(tag.exit_code == 2);
        CHECK_MESSAGE(tag.output.find("r.toml:9") != std::string::npos, tag.output);
        CHECK_MESSAGE(tag.output.find("render.replay_tag: no disc has the tag \"barrier\"") !=
                          std::string::npos,
                      tag.output);
    }
    CHECK(!fs::exists(mp4));
}

TEST_CASE("thumbnail: every built-in scene in both modes matches its golden image") {
    TempDir dir("golden");
    const std::string list = run_collide("scenes").output;
    int scenes = 0;
    for (const char* name : {"billiards", "brownian", "dense-fluid", "diffusion", "gas",
                             "maxwell-boltzmann", "newtons-cradle", "tunnelling"}) {
        CHECK_MESSAGE(list.find(name) != std::string::npos, name);
        const fs::path out = dir.path / (std::string(name) + ".png");
        const auto r = run_collide(std::string("thumbnail ") + name +
                                   " --size 320x180 --fps 10 --at 0.05 -o " + out.string());
        REQUIRE_MESSAGE(r.exit_code == 0, r.output);
        check_golden(out, name);
        ++scenes;
    }
    CHECK(scenes == 8);
}

TEST_CASE("thumbnail: event-only and time-only modes render one panel each") {
    TempDir dir("modes");
    for (const char* mode : {"event", "time"}) {
        const fs::path out = dir.path / (std::string(mode) + ".png");
        const auto r =
            run_collide(std::string("thumbnail newtons-cradle --size 320x180 --at 0.5 --mode ") +
                        mode + " -o " + out.string());
        REQUIRE_MESSAGE(r.exit_code == 0, r.output);
        check_golden(out, std::string("newtons-cradle-") + mode);
    }
}

TEST_CASE("render: bad options and scenes exit 2 with a message and create no output") {
    TempDir dir("bad");
    const fs::path out = dir.path / "x.mp4";
    const std::string o = " -o " + out.string();
    struct Case {
        std::string args;
        std::string mentions;
    };
    const Case cases[] = {
        {"render no-such-scene --progress none" + o, "no-such-scene"},
        {"render gas --mode sideways --progress none" + o, "--mode"},
        {"render gas -q z --progress none" + o, "-q"},
        {"render gas --size 12x34x56 --progress none" + o, "--size"},
        {"render gas --fps 0 --progress none" + o, "--fps"},
        {"render gas --duration -3 --progress none" + o, "--duration"},
        {"render gas --dt 0 --progress none" + o, "--dt"},
        {"render gas --engine warp --progress none" + o, "--engine"},
        {"render gas --pq fibonacci --engine classic --progress none" + o, "--pq"},
        {"render gas --format avi --progress none" + o, "--format"},
        {"render gas --progress none -o /nonexistent-dir/x.mp4", "/nonexistent-dir"},
        {"thumbnail gas --at -1 -o " + (dir.path / "x.png").string(), "--at"},
        {"render gas --overlays loud --progress none" + o, "--overlays"},
        {"render gas --theme neon --progress none" + o, "--theme"},
    };
    for (const Case& c : cases) {
        const auto r = run_collide(c.args);
        CHECK_MESSAGE(r.exit_code == 2, c.args << "\n" << r.output);
        CHECK_MESSAGE(r.output.find(c.mentions) != std::string::npos, c.args << "\n" << r.output);
    }
    CHECK(fs::is_empty(dir.path));  // nothing written, not even a temporary
}

TEST_CASE("render: a caption too wide for the frame's caption line exits 2 saying how much fits") {
    TempDir dir("caption_fit");
    const fs::path scene = dir.path / "cap.toml";
    std::ofstream(scene) << "title = \"Two discs\"\n[box]\nwidth = 1.0\nheight = 1.0\n"
                            "[[disc]]\nposition = [0.3, 0.5]\nvelocity = [0.1, 0]\nradius = 0.05\n"
                            "[[disc]]\nposition = [0.7, 0.5]\nvelocity = [-0.1, 0]\nradius = 0.05\n"
                            "[render]\nduration = 4\n"
                            "caption = \"Watch both discs meet in the middle and bounce back\"\n"
                            "[[render.captions]]\nat = 2\n"
                            "text = \"WWWWWWWWWWWWWWWWWWWWWWWWWWWWWWWWWWWWWWWWWWWWWWWWWWWW\"\n";
    const fs::path png = dir.path / "x.png";
    const fs::path mp4 = dir.path / "x.mp4";
    // 52 wide letters are within the 64 characters a scene may write, but not within 1280 px.
    const auto wide =
        run_collide("render " + scene.string() + " --progress none -o " + mp4.string());
    CHECK(wide.exit_code == 2);
    CHECK_MESSAGE(
        wide.output.find("cap.toml:17: render.captions.text: too long for the caption "
                         "line of a 1280x720 frame: 44 of its characters fit") != std::string::npos,
        wide.output);
    CHECK(!fs::exists(mp4));
    // The scene's caption (51 characters) fits 16:9 but not a square 600 px frame.
    const auto square =
        run_collide("thumbnail " + scene.string() + " --at 1 --size 600x600 -o " + png.string());
    CHECK(square.exit_code == 2);
    CHECK_MESSAGE(square.output.find("cap.toml:15: render.caption: too long for the caption line "
                                     "of a 600x600 frame") != std::string::npos,
                  square.output);
    CHECK(!fs::exists(png));
    // Below 480 px wide the compact form shows no caption: nothing to check.
    const auto thumb =
        run_collide("thumbnail " + scene.string() + " --at 1 --size 320x180 -o " + png.string());
    CHECK_MESSAGE(thumb.exit_code == 0, thumb.output);
}

TEST_CASE("thumbnail --seed: the same seed gives the same picture, another seed another one") {
    TempDir dir("seed");
    const auto shot = [&](const std::string& seed, const std::string& name) {
        const fs::path out = dir.path / name;
        const auto r =
            run_collide("thumbnail maxwell-boltzmann --size 320x180 --at 0 --mode event --seed " +
                        seed + " -o " + out.string());
        REQUIRE_MESSAGE(r.exit_code == 0, r.output);
        return collide::video::read_png(out);
    };
    const Image a = shot("5", "a.png");
    const Image b = shot("5", "b.png");
    const Image c = shot("6", "c.png");
    CHECK(share_of_differing_pixels(a, b) == 0.0);
    CHECK(share_of_differing_pixels(a, c) > 0.01);
    CHECK(
        run_collide("thumbnail gas --seed banana -o " + (dir.path / "d.png").string()).exit_code ==
        2);
}

TEST_CASE("render --gl: OSMesa and EGL surfaceless give byte-identical files") {
    TempDir dir("gl");
    const std::string video = "render gas --size 320x180 --fps 10 --duration 2 --progress none";
    const std::string still = "thumbnail gas --size 320x180 --at 1";
    const auto osmesa = run_collide(video + " --gl osmesa -o " + (dir.path / "o.mp4").string());
    const auto egl = run_collide(video + " --gl egl -o " + (dir.path / "e.mp4").string());
    if (osmesa.output.find("built without it") != std::string::npos ||
        egl.output.find("built without it") != std::string::npos) {
        COLLIDE_SKIP_TEST("this build lacks OSMesa or EGL");
    }
    REQUIRE_MESSAGE(osmesa.exit_code == 0, osmesa.output);
    REQUIRE_MESSAGE(egl.exit_code == 0, egl.output);
    const std::string bytes = read_bytes(dir.path / "o.mp4");
    CHECK(bytes.size() > 1000);
    CHECK(bytes == read_bytes(dir.path / "e.mp4"));
    const auto osmesa_png = run_collide(still + " --gl osmesa -o " + (dir.path / "o.png").string());
    const auto egl_png = run_collide(still + " --gl egl -o " + (dir.path / "e.png").string());
    REQUIRE_MESSAGE(osmesa_png.exit_code == 0, osmesa_png.output);
    REQUIRE_MESSAGE(egl_png.exit_code == 0, egl_png.output);
    CHECK(read_bytes(dir.path / "o.png") == read_bytes(dir.path / "e.png"));
}

TEST_CASE("render --gl: an unknown backend, or one beside --preview, exits 2 naming --gl") {
    TempDir dir("gl_bad");
    const fs::path out = dir.path / "x.mp4";
    const std::string unknown = collide::test::run_collide_bad_input(
        "render gas --duration 1 --gl vulkan -o " + out.string());
    CHECK(unknown.find("--gl: expected a GL backend (auto, osmesa, egl, egl-device or glfw), got "
                       "'vulkan'") != std::string::npos);
    const std::string with_preview = collide::test::run_collide_bad_input(
        "render gas --duration 1 --gl osmesa --preview -o " + out.string());
    CHECK(with_preview.find("--gl: 'osmesa' beside --preview: --preview renders the frames through "
                            "glfw") != std::string::npos);
    CHECK_FALSE(fs::exists(out));
}

namespace {
/// The engines' counts from a summary line ("engines: time-driven ... (N pair tests: ...), ...").
std::string engine_counts(const std::string& output) {
    const std::size_t at = output.find("engines:");
    if (at == std::string::npos) return {};
    std::string counts;
    bool inside = false;
    for (std::size_t i = at; i < output.size() && output[i] != '\n'; ++i) {
        if (output[i] == '(') inside = true;
        if (inside) counts += output[i];
        if (output[i] == ')') inside = false;
    }
    return counts;
}
}  // namespace

TEST_CASE("render: -q l and -q m simulate the same systems (the preset never changes dt)") {
    TempDir dir("presets");
    std::string counts[2];
    int i = 0;
    for (const char* q : {"l", "m"}) {
        const fs::path out = dir.path / (std::string(q) + ".png");
        // t = 2 is a frame time at 15 and 30 fps alike.
        const auto r =
            run_collide(std::string("thumbnail diffusion --at 2 -q ") + q + " -o " + out.string());
        REQUIRE_MESSAGE(r.exit_code == 0, r.output);
        counts[i++] = engine_counts(r.output);
    }
    CHECK_FALSE(counts[0].empty());
    CHECK(counts[0] == counts[1]);
}

TEST_CASE("thumbnail --layout-json writes the rectangles, with lesson text at least 2.8 % high") {
    TempDir dir("layout");
    const fs::path json = dir.path / "layout.json";
    const auto r = run_collide("thumbnail tunnelling --at 1 --size 1280x720 -o " +
                               (dir.path / "t.png").string() + " --layout-json " + json.string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    std::ifstream in(json);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK(text.find("\"level\": \"lesson\"") != std::string::npos);
    CHECK(text.find("\"role\": \"figures\"") != std::string::npos);
    // Every cap height written is >= 20.16 px (2.8 % of 720).
    std::size_t at = 0;
    int lines = 0;
    while ((at = text.find("\"cap_height\": ", at)) != std::string::npos) {
        at += 14;
        CHECK(std::stod(text.substr(at)) >= 20.1);
        ++lines;
    }
    CHECK(lines >= 8);
}

// Issue #29 item 7: the dt trade-off in one picture.
TEST_CASE("render --dt A,B,C: a playable MP4 with a panel per step, each step's misses reported") {
    if (!have_ffprobe()) {
        COLLIDE_SKIP_TEST("ffprobe is not installed (scripts/setup.sh --test installs it)");
    }
    TempDir dir("dtlist");
    const fs::path out = dir.path / "dt.mp4";
    const fs::path layout = dir.path / "layout.json";
    const auto r = run_collide(
        "render tunnelling -q l --duration 3 --dt 0.01,0.02,0.04 "
        "--progress none --json --layout-json " +
        layout.string() + " -o " + out.string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    const std::string probe = capture(
        "ffprobe -v error -select_streams v:0 -show_entries stream=codec_name,width,height -of "
        "default=nw=1 " +
        out.string());
    CHECK(probe.find("codec_name=h264") != std::string::npos);
    CHECK(probe.find("width=854") != std::string::npos);
    // Four panels laid out, each with its title and its work bar.
    std::ifstream in(layout);
    const std::string json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK(json.find("\"panels\": [") != std::string::npos);
    std::size_t boxes = 0;
    for (std::size_t at = json.find("\"box\""); at != std::string::npos;
         at = json.find("\"box\"", at + 1))
        ++boxes;
    CHECK(boxes == 4);
    // Each step's missed count is the one `simulate --engine time --dt X` reports at the
    // video's last simulation time.
    const auto value_after = [&](const std::string& key, std::size_t from) {
        const std::size_t at = r.output.find("\"" + key + "\": ", from);
        REQUIRE(at != std::string::npos);
        const std::size_t begin = at + key.size() + 4;
        return r.output.substr(begin, r.output.find_first_of(",}\n", begin) - begin);
    };
    const std::string until = value_after("sim_time", 0);
    for (const char* dt : {"0.01", "0.02", "0.04"}) {
        INFO("dt = " << dt);
        const std::size_t panel = r.output.find(std::string("\"dt\": ") + dt);
        REQUIRE(panel != std::string::npos);
        const std::string missed = value_after("missed_collisions", panel);
        const auto s =
            run_collide("simulate tunnelling --engine time --until " + until + " --dt " + dt);
        REQUIRE_MESSAGE(s.exit_code == 0, s.output);
        CHECK(s.output.find("missed_collisions: " + missed + "\n") != std::string::npos);
    }
    CHECK(value_after("missed_collisions", r.output.find("\"dt\": 0.04")) != "0");
}

TEST_CASE("render --dt with more than four steps, or a step twice, exits 2 naming --dt") {
    TempDir dir("dtbad");
    const fs::path out = dir.path / "x.mp4";
    for (const char* list : {"0.01,0.02,0.03,0.04,0.05", "0.01,0.01", "0.01,-1", "0.01,abc"}) {
        INFO(list);
        const auto r = run_collide(std::string("render gas --dt ") + list + " -o " + out.string());
        CHECK(r.exit_code == 2);
        CHECK(r.output.find("--dt: ") != std::string::npos);
        CHECK_FALSE(fs::exists(out));
    }
    const auto five = run_collide("render gas --dt 0.01,0.02,0.03,0.04,0.05 -o " + out.string());
    CHECK(five.output.find("2 to 4 steps") != std::string::npos);
}

namespace {
/// The strings --layout-json gives for every slot of `role`, in the file's order.
std::vector<std::string> texts_of(const std::string& json, const std::string& role) {
    std::vector<std::string> out;
    const nlohmann::json layout = nlohmann::json::parse(json);  // outlives the loop over it
    for (const nlohmann::json& slot : layout.at("text")) {
        if (slot.at("role") != role || !slot.contains("text")) continue;
        for (const nlohmann::json& text : slot.at("text")) out.push_back(text.get<std::string>());
    }
    return out;
}

/// 1,234,567 as a number.
double count_in(const std::string& text) {
    std::string digits;
    for (const char c : text) {
        if (c >= '0' && c <= '9') digits += c;
    }
    return digits.empty() ? -1.0 : std::stod(digits);
}

/// The number after "key": in a `collide simulate --json` output.
double json_number(const std::string& json, const std::string& key) {
    const std::size_t at = json.find("\"" + key + "\": ");
    return at == std::string::npos ? -1.0 : std::stod(json.substr(at + key.size() + 4));
}
}  // namespace

TEST_CASE("the cost graphic's numbers and ratio on screen are the engines' counts (issue #28)") {
    TempDir dir("ratio");
    const fs::path json = dir.path / "layout.json";
    const auto r = run_collide("thumbnail gas --at 3 --size 1280x720 -o " +
                               (dir.path / "t.png").string() + " --layout-json " + json.string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    const std::string text = read_bytes(json);
    const std::vector<std::string> values = texts_of(text, "cost-value");
    REQUIRE(values.size() == 2);
    const std::vector<std::string> ratio = texts_of(text, "cost-ratio");
    REQUIRE(ratio.size() == 1);
    // The same unit on both sides: pair computations (overlap tests and contact times against
    // predictions), plus the event-driven engine's queue operations.
    const auto time =
        run_collide("simulate gas --until 3 --json --engine time --dt 0.033333333333333333");
    const auto event = run_collide("simulate gas --until 3 --json --engine fast");
    REQUIRE_MESSAGE(time.exit_code == 0, time.output);
    REQUIRE_MESSAGE(event.exit_code == 0, event.output);
    const double time_work =
        json_number(time.output, "overlap_checks") + json_number(time.output, "predictions");
    const double event_work =
        json_number(event.output, "predictions") + json_number(event.output, "pq_pushes") +
        json_number(event.output, "pq_pops") + json_number(event.output, "pq_updates");
    CHECK(count_in(values[0]) == time_work);
    CHECK(count_in(values[1]) == event_work);
    CAPTURE(ratio[0]);
    REQUIRE(ratio[0].find("x less work") != std::string::npos);
    const double shown = std::stod(ratio[0]);
    const double exact = time_work / event_work;
    CHECK(std::abs(shown - exact) <= 0.005 * exact + 0.5);
}

TEST_CASE("thumbnail's summary line says the time-driven panel's work in its words and digits") {
    // The panel's cost graphic counts pair tests (overlap checks and the roll-backs'
    // contact-time computations); the line printed once used to give the overlap checks alone,
    // under another name (3,056,625 beside the panel's 3,056,956 for this scene at t = 3).
    TempDir dir("cost_line");
    const fs::path json = dir.path / "layout.json";
    const auto r = run_collide("thumbnail tunnelling --at 3 --size 1280x720 -o " +
                               shell_quoted((dir.path / "t.png").string()) + " --layout-json " +
                               shell_quoted(json.string()));
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    const std::string text = read_bytes(json);
    const std::vector<std::string> labels = texts_of(text, "cost-label");
    const std::vector<std::string> values = texts_of(text, "cost-value");
    REQUIRE(labels.size() == 2);
    REQUIRE(values.size() == 2);
    CHECK(labels[0] == "pair tests");
    // "time-driven 0.01 s (3,056,956 pair tests: 3,056,625 overlap checks + 331 contact-time
    // computations)": the panel's figure and label, then what the figure is made of.
    const std::string line = values[0] + " " + labels[0] + ": ";
    const std::size_t at = r.output.find(line);
    REQUIRE_MESSAGE(at != std::string::npos, r.output);
    const std::size_t checks_end = r.output.find(" overlap checks + ", at);
    const std::size_t solves_end = r.output.find(" contact-time computations)", at);
    REQUIRE(checks_end != std::string::npos);
    REQUIRE(solves_end != std::string::npos);
    const std::size_t solves_at = checks_end + std::string(" overlap checks + ").size();
    const double checks =
        count_in(r.output.substr(at + line.size(), checks_end - at - line.size()));
    const double solves = count_in(r.output.substr(solves_at, solves_end - solves_at));
    CHECK(checks > 0.0);
    CHECK(solves > 0.0);  // this scene's roll-backs solve contact times
    CHECK(checks + solves == count_in(values[0]));

    // A --dt list: a panel per step, each bar labelled with its step, the line a figure each.
    const auto list = run_collide(
        "thumbnail tunnelling --dt 0.01,0.02,0.04 --at 2 --size "
        "1280x720 -o " +
        shell_quoted((dir.path / "dt.png").string()) + " --layout-json " +
        shell_quoted(json.string()));
    REQUIRE_MESSAGE(list.exit_code == 0, list.output);
    const std::vector<std::string> steps = texts_of(read_bytes(json), "cost-value");
    REQUIRE(steps.size() == 4);  // three steps, then the event-driven panel
    std::size_t from = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        CAPTURE(steps[i]);
        from = list.output.find(steps[i] + " pair tests: ", from);
        CHECK(from != std::string::npos);
    }
}

// Failures that did not fit the figures row continued on the how line and took it: brownian's
// time-driven panel lost its why ("Each step: all N²/2 pairs") once discs had left the box
// (tunnelled out through the wall).
TEST_CASE("the how line keeps its why after failures that continued on it (issue #28 item 4)") {
    TempDir dir("how_line");
    const fs::path json = dir.path / "layout.json";
    const auto r = run_collide("thumbnail brownian --at 4 --size 1280x720 -o " +
                               (dir.path / "t.png").string() + " --layout-json " + json.string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    const nlohmann::json layout = nlohmann::json::parse(read_bytes(json));
    std::string how;
    for (const auto& slot : layout["text"]) {
        if (slot["role"] == "how" && slot["panel"] == 0)
            for (const auto& t : slot["text"]) how += t.get<std::string>() + "|";
    }
    CAPTURE(how);
    CHECK(how.find(" tunnelled|") != std::string::npos);  // a failure continued here
    CHECK(how.find("Each step: all N\u00b2/2 pairs|") != std::string::npos);
}

// The queue strip takes the how line that failures continue on, and insets the boxes: the
// time-driven row under its box had room for "0 missed" only, and "overlapping" was dropped.
TEST_CASE("render --queue: every failure kind stays among the figures (issue #28 item 2)") {
    TempDir dir("queue_figures");
    const fs::path json = dir.path / "layout.json";
    for (const char* size : {"1280x720", "854x480"}) {
        CAPTURE(size);
        const auto r =
            run_collide(std::string("thumbnail gas --queue --at 2 --size ") + size + " -o " +
                        (dir.path / "t.png").string() + " --layout-json " + json.string());
        REQUIRE_MESSAGE(r.exit_code == 0, r.output);
        std::string figures;
        for (const std::string& f : texts_of(read_bytes(json), "figures")) figures += f + "|";
        CAPTURE(figures);
        CHECK(figures.find(" missed|") != std::string::npos);
        CHECK(figures.find(" overlapping|") != std::string::npos);
    }
}

// The strip's words and the in-box times to go were drawn at 0.7 of the lesson's size.
TEST_CASE("render --queue: every text, the strip's and the box's labels too, is lesson size") {
    TempDir dir("queue_text");
    const fs::path json = dir.path / "layout.json";
    for (const char* engine : {"fast", "classic"}) {
        CAPTURE(engine);
        const auto r = run_collide(std::string("thumbnail gas --queue --at 2 --engine ") + engine +
                                   " --size 1280x720 -o " + (dir.path / "t.png").string() +
                                   " --layout-json " + json.string());
        REQUIRE_MESSAGE(r.exit_code == 0, r.output);
        const nlohmann::json layout = nlohmann::json::parse(read_bytes(json));
        double body = 0.0;
        for (const auto& slot : layout["text"]) {
            CHECK(slot["cap_height"].get<double>() >= 0.028 * 720 - 0.05);
            if (slot["role"] == "caption") body = slot["pixel_height"].get<double>();
        }
        REQUIRE(body > 0.0);
        int labels = 0;
        for (const auto& text : layout["other_text"]) {
            CAPTURE(text.dump());
            CHECK(text["pixel_height"].get<double>() >= body);
            ++labels;
        }
        CHECK(labels >= 2);  // the times to go and the next event's disc numbers
    }
}

TEST_CASE("render --queue: classic and fast engines show their queue, byte-identical run to run") {
    TempDir dir("queue");
    const std::string base =
        "render gas --size 640x360 --fps 10 --duration 1 --slow-motion 2 --progress none ";
    for (const char* engine : {"classic --pq binary", "classic --pq ordered", "fast"}) {
        CAPTURE(engine);
        const std::string args = base + "--queue 3 --engine " + engine + " -o ";
        const auto a = run_collide(args + (dir.path / "a.mp4").string());
        const auto b = run_collide(args + (dir.path / "b.mp4").string());
        REQUIRE_MESSAGE(a.exit_code == 0, a.output);
        REQUIRE_MESSAGE(b.exit_code == 0, b.output);
        const std::string bytes = read_bytes(dir.path / "a.mp4");
        CHECK(bytes.size() > 1000);
        CHECK(bytes == read_bytes(dir.path / "b.mp4"));
    }
    // The queue changes the picture: the same still with and without it.
    const std::string still = "thumbnail gas --size 640x360 --at 1 --engine classic -o ";
    const auto with = run_collide(still + (dir.path / "with.png").string() + " --queue");
    const auto without = run_collide(still + (dir.path / "without.png").string());
    REQUIRE_MESSAGE(with.exit_code == 0, with.output);
    REQUIRE_MESSAGE(without.exit_code == 0, without.output);
    CHECK(share_of_differing_pixels(collide::video::read_png(dir.path / "with.png"),
                                    collide::video::read_png(dir.path / "without.png")) > 0.05);
}

TEST_CASE("render --queue --code: the loop's lines in --layout-json, lesson size, one marked") {
    TempDir dir("queue_code");
    const fs::path json = dir.path / "layout.json";
    const auto r =
        run_collide("thumbnail gas --queue --code --mode event --at 1 --size 1280x720 -o " +
                    (dir.path / "c.png").string() + " --layout-json " + json.string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    std::ifstream in(json);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::vector<std::string> lines = texts_of(text, "code");
    REQUIRE(lines.size() == 7);  // the title and the loop's six lines
    CHECK(lines[0] == "event-driven loop");
    CHECK(lines[2] == "e = delete the minimum");
    CHECK(lines[3] == "if e is invalidated: skip it");
    CHECK(lines[5] == "resolve e");
    // Every slot (the code's too) is lesson text: capitals >= 2.8 % of 720.
    for (std::size_t at = 0; (at = text.find("\"cap_height\": ", at)) != std::string::npos;) {
        at += 14;
        CHECK(std::stod(text.substr(at)) >= 20.1);
    }
    // Without --code, no code slot.
    const auto plain = run_collide("thumbnail gas --queue --mode event --at 1 --size 1280x720 -o " +
                                   (dir.path / "p.png").string() + " --layout-json " +
                                   (dir.path / "p.json").string());
    REQUIRE_MESSAGE(plain.exit_code == 0, plain.output);
    std::ifstream pin(dir.path / "p.json");
    const std::string ptext((std::istreambuf_iterator<char>(pin)),
                            std::istreambuf_iterator<char>());
    CHECK(texts_of(ptext, "code").empty());
}

TEST_CASE("render --queue --code --mode both: the panel titles are drawn whole beside the code") {
    // --layout-json records each slot's text as drawn: a title cut to fit ends in "...".
    TempDir dir("queue_code_titles");
    for (const char* size : {"854x480", "1280x720"}) {
        CAPTURE(size);
        const fs::path json = dir.path / "layout.json";
        const auto r = run_collide("thumbnail gas --queue --code --mode both --at 3 --size " +
                                   std::string(size) + " -o " + (dir.path / "c.png").string() +
                                   " --layout-json " + json.string());
        REQUIRE_MESSAGE(r.exit_code == 0, r.output);
        std::ifstream in(json);
        const std::string text((std::istreambuf_iterator<char>(in)),
                               std::istreambuf_iterator<char>());
        const std::vector<std::string> titles = texts_of(text, "title");
        REQUIRE(titles.size() == 2);
        CHECK(titles[0] == "Time-driven: dt = 1/30");
        CHECK(titles[1] == "Event-driven");
        for (const std::string& title : titles) {
            CHECK_MESSAGE(title.find("...") == std::string::npos, title << " was cut");
        }
    }
}

TEST_CASE("render --code where it cannot be shown: exit 2 naming --code, nothing written") {
    TempDir dir("queue_code_bad");
    const auto contains = [](const std::string& haystack, const std::string& needle) {
        return haystack.find(needle) != std::string::npos;
    };
    using collide::test::run_collide_bad_input;
    const std::string out = " -o " + (dir.path / "x.mp4").string();
    CHECK(contains(run_collide_bad_input("render gas --code" + out),
                   "--code: shows the event-driven loop beside its queue; add --queue"));
    CHECK(contains(run_collide_bad_input("render gas --queue --code --overlays full" + out),
                   "--code: the code is drawn at the lesson level only, not with --overlays "
                   "full"));
    CHECK(contains(run_collide_bad_input("render gas --queue --code --overlays none" + out),
                   "--code: the code is drawn at the lesson level only"));
    CHECK(contains(run_collide_bad_input("render gas --queue --code --size 640x360" + out),
                   "--code: needs a frame at least 854 pixels wide"));
    CHECK(contains(run_collide_bad_input("render gas-3d --queue --code" + out),
                   "--code: not for 3D scenes"));
    CHECK(fs::is_empty(dir.path));
}

// Discs that jumped through tunnelling's barriers were counted nowhere and left unmarked
// (#44 item 3): once they do, the time-driven figures count them ("tunnelled") and the marks'
// legend names their diamond. At the start nothing has tunnelled: no such figure.
TEST_CASE("thumbnail tunnelling: discs through the barrier are a figure and a mark") {
    TempDir dir("tunnelled");
    const fs::path json = dir.path / "layout.json";
    const auto figures_at = [&](const std::string& at, const std::string& size) {
        const auto r =
            run_collide("thumbnail tunnelling --at " + at + " --size " + size + " -o " +
                        (dir.path / "t.png").string() + " --layout-json " + json.string());
        REQUIRE_MESSAGE(r.exit_code == 0, r.output);
        std::string figures;
        for (const std::string& f : texts_of(read_bytes(json), "figures")) figures += f + "|";
        return figures;
    };
    CHECK(figures_at("0", "1280x720").find("tunnelled") == std::string::npos);
    for (const char* size : {"1280x720", "854x480"}) {
        CAPTURE(size);
        const std::string figures = figures_at("6", size);
        CAPTURE(figures);
        const std::size_t word = figures.find(" tunnelled|");
        REQUIRE(word != std::string::npos);
        const std::size_t start = figures.rfind('|', word);
        const std::string value =
            figures.substr(start == std::string::npos ? 0 : start + 1,
                           word - (start == std::string::npos ? 0 : start + 1));
        CAPTURE(value);
        CHECK(std::stoi(value) > 0);
        std::string marks;
        for (const std::string& m : texts_of(read_bytes(json), "marks")) marks += m + "|";
        CAPTURE(marks);
        CHECK(marks.find("went through a barrier") != std::string::npos);
    }
}

// A 320x180 thumbnail (the compact form: no card, no caption) named nothing of what it shows
// (#44 item 5): its top line now carries the scene's title, in capitals of at least 9 px.
TEST_CASE("a 320x180 thumbnail carries the scene's title over its panels") {
    TempDir dir("thumbnail_title");
    const fs::path json = dir.path / "layout.json";
    // spheres-freeze's title is too wide for 320 px: what it shows ("Hard spheres freeze").
    for (const char* scene : {"tunnelling", "billiards", "newtons-cradle", "spheres-freeze"}) {
        CAPTURE(scene);
        const auto r =
            run_collide(std::string("thumbnail ") + scene + " --size 320x180 -o " +
                        (dir.path / "t.png").string() + " --layout-json " + json.string());
        REQUIRE_MESSAGE(r.exit_code == 0, r.output);
        const nlohmann::json layout = nlohmann::json::parse(read_bytes(json));
        CHECK(layout["compact"] == true);
        const std::string toml =
            read_bytes(fs::path(COLLIDE_ASSETS_DIR) / "scenes" / (std::string(scene) + ".toml"));
        std::string drawn;
        float top_of_panels = 1e9F;
        float title_bottom = 0.0F;
        for (const auto& slot : layout["text"]) {
            if (slot["role"] == "title" && slot["panel"] == -1) {
                for (const auto& t : slot["text"]) drawn += t.get<std::string>();
                CHECK(slot["cap_height"].get<double>() >= 9.0);
                title_bottom = slot["rect"][3].get<float>();
            } else {
                top_of_panels = std::min(top_of_panels, slot["rect"][1].get<float>());
            }
        }
        CAPTURE(drawn);
        // The scene's own title, or the words after its colon (the first letter a capital).
        CHECK(drawn.size() >= 8);
        REQUIRE(drawn.find("...") == std::string::npos);
        const std::size_t start = toml.find("title = \"");
        REQUIRE(start != std::string::npos);
        const std::string title = toml.substr(start + 9, toml.find('"', start + 9) - start - 9);
        CAPTURE(title);
        CHECK((title == drawn ||
               title.ends_with(": " + std::string(1, static_cast<char>(drawn[0] + 32)) +
                               drawn.substr(1))));
        CHECK(title_bottom <= top_of_panels);
    }
}
