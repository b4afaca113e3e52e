// TOML scenes: every key, every error with file:line and key, includes, generators, render hints.

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../support/input_error.hpp"
#include "collide/error.hpp"
#include "collide/scene/load.hpp"
#include "collide/scene/save.hpp"
#include "collide/sim/scene_check.hpp"

using namespace collide;

namespace {

Scene parse(const std::string& text, const std::filesystem::path& base = ".") {
    return parse_toml_scene(text, "s.toml", base);
}

std::string toml_error(const std::string& text, const std::filesystem::path& base = ".") {
    return test::input_error_message([&] { (void)parse(text, base); });
}

using collide::test::contains;

// A temporary directory removed at the end of the test.
struct TempDir {
    std::filesystem::path path;
    explicit TempDir(const std::string& name)
        : path(std::filesystem::temp_directory_path() / name) {
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~TempDir() { std::filesystem::remove_all(path); }
    void write(const std::string& file, const std::string& text) const {
        std::ofstream(path / file) << text;
    }
};

}  // namespace

TEST_CASE("toml: explicit discs with every key") {
    const Scene s = parse(R"(
title = "Two discs"
description = "for a test"
[box]
width = 2.0
height = 1
boundary = "periodic"
[[disc]]
position = [0.5, 0.5]
velocity = [0.1, -0.2]
radius = 0.1
mass = 3
color = "#e03010"
tag = "tracer"
[[disc]]
position = [1.5, 0.5]
radius = 0.05
color = [1, 2, 3]
)");
    CHECK(s.title == "Two discs");
    CHECK(s.box.width == 2.0);
    CHECK(s.box.height == 1.0);
    CHECK(s.box.boundary == Boundary::periodic);
    REQUIRE(s.discs.size() == 2);
    CHECK(s.discs[0].position == Vec2{0.5, 0.5});
    CHECK(s.discs[0].velocity == Vec2{0.1, -0.2});
    CHECK(s.discs[0].radius == 0.1);
    CHECK(s.discs[0].mass == 3.0);
    CHECK(s.discs[0].color == Rgb8{0xe0, 0x30, 0x10});
    CHECK(s.discs[0].tag == "tracer");
    CHECK(s.discs[1].velocity == Vec2{0.0, 0.0});
    CHECK(s.discs[1].mass == 1.0);
    CHECK(s.discs[1].color == Rgb8{1, 2, 3});
    CHECK(s.discs[1].tag.empty());
}

TEST_CASE("toml: defaults are the unit box with walls") {
    const Scene s = parse("[[disc]]\nposition = [0.5, 0.5]\nradius = 0.1\n");
    CHECK(s.box.width == 1.0);
    CHECK(s.box.boundary == Boundary::walls);
    CHECK(s.discs.size() == 1);
}

TEST_CASE("toml: render hints") {
    const Scene s = parse(R"(
[render]
color_mode = "mass"
trails = true
overlays = false
duration = 12
speed = 0.5
dt = 0.25
)");
    CHECK(s.render.color_mode == ColorMode::mass);
    CHECK(s.render.trails == true);
    CHECK(s.render.overlays == OverlayLevel::none);
    CHECK(s.render.duration == 12.0);
    CHECK(s.render.speed == 0.5);
    CHECK(s.render.dt == 0.25);
    CHECK(contains(toml_error("[render]\ncolor_mode = \"rainbow\"\n"),
                   "s.toml:2: render.color_mode: expected one of scene, speed, mass, tag"));
    CHECK(contains(toml_error("[render]\ndt = 0\n"), "s.toml:2: render.dt: must be > 0"));
    CHECK(contains(toml_error("[render]\ntrails = 1\n"),
                   "s.toml:2: render.trails: expected true or false"));
}

TEST_CASE("toml: generators, with colour by speed and discs placed before them avoided") {
    const Scene s = parse(R"(
[[disc]]
position = [0.5, 0.5]
radius = 0.2
mass = 10
tag = "tracer"
[[generate]]
packing_fraction = 0.3
radius = 0.01
mass = 1.0
temperature = 2.0
region = [[0.0, 0.0], [1.0, 1.0]]
color = "speed"
seed = 7
tag = "gas"
[[generate]]
count = 5
radius = 0.002
speed = 0.5
color = "#3060e0"
)");
    CHECK(s.discs.size() == 1 + 955 + 5);
    CHECK(s.discs[1].tag == "gas");
    CHECK(s.render.color_mode == ColorMode::speed);
    CHECK(norm(s.discs.back().velocity) == doctest::Approx(0.5));
    CHECK(s.discs.back().color == Rgb8{0x30, 0x60, 0xe0});
    // the same text gives the same scene
    const Scene again = parse(R"(
[[disc]]
position = [0.5, 0.5]
radius = 0.2
mass = 10
tag = "tracer"
[[generate]]
packing_fraction = 0.3
radius = 0.01
mass = 1.0
temperature = 2.0
region = [[0.0, 0.0], [1.0, 1.0]]
color = "speed"
seed = 7
tag = "gas"
[[generate]]
count = 5
radius = 0.002
speed = 0.5
color = "#3060e0"
)");
    REQUIRE(again.discs.size() == s.discs.size());
    for (std::size_t i = 0; i < s.discs.size(); ++i)
        CHECK(again.discs[i].position == s.discs[i].position);
}

TEST_CASE("toml: unknown keys are refused with the nearest valid one") {
    CHECK(contains(toml_error("[[disc]]\nposition = [0.5, 0.5]\nradus = 0.1\n"),
                   "s.toml:3: disc[0]: unknown key 'radus' (did you mean 'radius'?)"));
    CHECK(contains(toml_error("titel = \"x\"\n"),
                   "s.toml:1: unknown key 'titel' (did you mean 'title'?)"));
    CHECK(contains(toml_error("[box]\nboundry = \"walls\"\n"),
                   "s.toml:2: box: unknown key 'boundry' (did you mean 'boundary'?)"));
    CHECK(contains(toml_error("[[generate]]\ncount = 3\nradius = 0.01\ntemprature = 1\n"),
                   "generate[0]: unknown key 'temprature' (did you mean 'temperature'?)"));
    CHECK(contains(toml_error("[render]\nfps = 30\n"),
                   "s.toml:2: render: unknown key 'fps' (valid keys: color_mode"));
}

TEST_CASE("toml: bad values name the key and its line") {
    CHECK(contains(toml_error("[[disc]]\nposition = [0.5, 0.5]\nradius = -0.1\n"),
                   "s.toml:3: disc[0].radius: must be > 0 (got -0.1)"));
    CHECK(contains(toml_error("[[disc]]\nposition = [0.5, 0.5]\nradius = 0.1\nmass = 0\n"),
                   "s.toml:4: disc[0].mass: must be > 0"));
    CHECK(contains(toml_error("[[disc]]\nposition = [0.5, nan]\nradius = 0.1\n"),
                   "s.toml:2: disc[0].position[1]: not a finite number"));
    CHECK(
        contains(toml_error("[[disc]]\nposition = [0.5, 0.5]\nvelocity = [inf, 0]\nradius = 0.1\n"),
                 "disc[0].velocity[0]: not a finite number"));
    CHECK(contains(toml_error("[[disc]]\nposition = [0.5]\nradius = 0.1\n"),
                   "s.toml:2: disc[0].position: expected [x, y]"));
    CHECK(contains(toml_error("[[disc]]\nposition = [0.5, 0.5]\nradius = \"big\"\n"),
                   "disc[0].radius: expected a number"));
    CHECK(contains(toml_error("[[disc]]\nradius = 0.1\n"),
                   "s.toml:1: disc[0].position: missing (required)"));
    CHECK(contains(toml_error("[[disc]]\nposition = [0.5, 0.5]\nradius = 0.1\ncolor = \"red\"\n"),
                   "disc[0].color: expected \"#rrggbb\""));
    CHECK(
        contains(toml_error("[[disc]]\nposition = [0.5, 0.5]\nradius = 0.1\ncolor = [0, 256, 0]\n"),
                 "colour channels are 0..255"));
    CHECK(contains(toml_error("[box]\nwidth = -1\n"), "s.toml:2: box.width: must be > 0"));
    CHECK(contains(toml_error("[box]\nboundary = \"torus\"\n"),
                   "s.toml:2: box.boundary: expected \"walls\" or \"periodic\""));
    CHECK(contains(toml_error("box = 3\n"), "s.toml:1: box: expected a table"));
    CHECK(
        contains(toml_error("[disc]\nposition = [0.5, 0.5]\n"), "disc: expected [[disc]] tables"));
}

TEST_CASE("toml: physical problems found by validation name the [[disc]] and its line") {
    CHECK(contains(toml_error("[[disc]]\nposition = [0.95, 0.5]\nradius = 0.1\n"),
                   "s.toml:1: disc[0]: centre (0.95, 0.5), radius 0.1: right edge"));
    CHECK(contains(toml_error("[[disc]]\nposition = [0.5, 0.5]\nradius = 0.1\n\n[[disc]]\nposition "
                              "= [0.6, 0.5]\nradius = 0.1\n"),
                   "s.toml:5: disc[1]: overlaps s.toml:1: disc[0] at t = 0"));
}

TEST_CASE("toml: generator errors carry the line of the key they blame, else the block's") {
    CHECK(contains(toml_error("\n[[generate]]\npacking_fraction = 0.95\nradius = 0.01\n"),
                   "s.toml:3: generate[0].packing_fraction: 0.95 is above the maximum 0.85"));
    CHECK(contains(toml_error("[[generate]]\nradius = 0.01\n\ncount = 5000\n"),
                   "s.toml:4: generate[0].count: 5000 discs of radius 0.01 give packing fraction"));
    CHECK(contains(toml_error("[[generate]]\ncount = 3\n\n\nradius = 0.01\nregion = [[0.5, 0.5], "
                              "[0.4, 0.6]]\n"),
                   "s.toml:6: generate[0].region: the second corner must lie above and right"));
    // The second block: its own field's line.
    CHECK(contains(toml_error("[[generate]]\ncount = 3\nradius = 0.01\n[[generate]]\ncount = 3\n"
                              "radius = 0.01\nregion = [[0.5, 0.5], [0.4, 0.6]]\n"),
                   "s.toml:7: generate[1].region"));
    CHECK(contains(toml_error("[[generate]]\nradius = 0.01\n"),
                   "s.toml:1: generate[0]: give count or packing_fraction"));
    CHECK(contains(toml_error("[[generate]]\ncount = 0\nradius = 0.01\n"),
                   "generate[0].count: must be >= 1"));
    CHECK(
        contains(toml_error("[[generate]]\ncount = 3\nradius = 0.01\ntemperature = 1\nspeed = 1\n"),
                 "not both"));
    CHECK(
        contains(toml_error("[[generate]]\ncount = 3\nradius = 0.01\nregion = [[0, 0], [2, 1]]\n"),
                 "generate[0].region"));
    CHECK(contains(toml_error("[[generate]]\ncount = 3\nradius = 0.01\nseed = -1\n"),
                   "generate[0].seed: must be >= 0"));
}

TEST_CASE("toml: syntax errors give the line") {
    CHECK(contains(toml_error("title = \"x\"\n[box\nwidth = 1\n"), "s.toml:2: TOML syntax error"));
}

TEST_CASE("toml: include pulls algs4 files in, relative to the scene, with their own lines") {
    const TempDir dir("collide_test_toml_include");
    dir.write("two.txt", "2\n0.2 0.2 0 0 0.05 1 0 0 0\n0.8 0.8 0 0 0.05 1 0 0 0\n");
    dir.write("bad.txt", "1\n0.2 0.2 0 0 0.05 1 0 0\n");
    dir.write("clash.txt", "1\n0.55 0.5 0 0 0.05 1 0 0 0\n");
    const Scene s =
        parse("include = [\"two.txt\"]\n[[disc]]\nposition = [0.5, 0.5]\nradius = 0.1\n", dir.path);
    CHECK(s.discs.size() == 3);
    CHECK(s.discs[0].position == Vec2{0.2, 0.2});
    CHECK(s.discs[2].radius == 0.1);
    CHECK(
        contains(toml_error("include = \"bad.txt\"\n", dir.path), "bad.txt:2: expected 9 columns"));
    const std::string absent = toml_error("include = [\"none.txt\"]\n", dir.path);
    CHECK(contains(absent, "s.toml:1: include[0]: "));
    CHECK(contains(absent, "none.txt: cannot open the scene file: No such file"));
    CHECK(contains(toml_error("include = [\"two.txt\", \"other.toml\"]\n", dir.path),
                   "s.toml:1: include[1]: only algs4 .txt files"));
    CHECK(contains(
        toml_error("include = \"clash.txt\"\n[[disc]]\nposition = [0.5, 0.5]\nradius = 0.1\n",
                   dir.path),
        "s.toml:2: disc[0]: overlaps "));
}

TEST_CASE("nearest_name suggests plausible typos only") {
    const std::vector<std::string> keys = {"radius", "mass", "position", "velocity"};
    CHECK(nearest_name("radus", keys) == "radius");
    CHECK(nearest_name("postion", keys) == "position");
    CHECK(nearest_name("mas", keys) == "mass");
    CHECK(nearest_name("frobnicate", keys).empty());
}

TEST_CASE("toml: periodic positions are wrapped into the box") {
    const Scene s =
        parse("[box]\nboundary = \"periodic\"\n[[disc]]\nposition = [1.25, -0.25]\nradius = 0.1\n");
    CHECK(s.discs[0].position == Vec2{0.25, 0.75});
}

TEST_CASE("toml: bad explicit discs are reported before any generator runs") {
    CHECK(contains(toml_error("[[disc]]\nposition = [0.5, 0.5]\nradius = 0.1\nvelocity = [0, "
                              "nan]\n[[generate]]\ncount = 3\nradius = 0.01\n"),
                   "s.toml:4: disc[0].velocity[1]: not a finite number"));
}

TEST_CASE("toml: generator blocks without a seed get different streams") {
    const Scene s = parse(R"(
[[generate]]
count = 1
radius = 0.01
region = [[0.0, 0.0], [0.5, 1.0]]
[[generate]]
count = 1
radius = 0.01
region = [[0.5, 0.0], [1.0, 1.0]]
)");
    REQUIRE(s.discs.size() == 2);
    // same relative position in each half would mean the same random stream
    CHECK(s.discs[1].position.y != s.discs[0].position.y);
}

TEST_CASE("toml: the scene's story: description, caption, timed captions, theme, overlays") {
    const Scene s = parse(R"(title = "T"
description = "What it shows"
[render]
duration = 10
overlays = "full"
theme = "light"
histogram = "large"
caption = "The whole video"
[[render.captions]]
at = 2
text = "First"
[[render.captions]]
at = 5.5
text = "Second"
)");
    CHECK(s.description == "What it shows");
    CHECK(s.render.overlays == OverlayLevel::full);
    CHECK(s.render.theme == Theme::light);
    CHECK(s.render.histogram == PlotSize::large);
    CHECK(s.render.caption == std::optional<std::string>("The whole video"));
    REQUIRE(s.render.captions.size() == 2);
    CHECK(s.render.captions[1].at == 5.5);
    CHECK(s.render.captions[1].text == "Second");
    CHECK(s.render.captions[1].line == 13);
    CHECK(parse("[render]\noverlays = true\n").render.overlays == OverlayLevel::lesson);
    // "auto" is the default (where it teaches): the same as no histogram key.
    CHECK_FALSE(parse("[render]\nhistogram = \"auto\"\n").render.histogram.has_value());
    CHECK(contains(toml_error("[render]\nhistogram = \"huge\"\n"),
                   "render.histogram: expected one of auto, none, small, large"));
}

TEST_CASE("toml: bad captions name the file, line and field and say what is allowed") {
    const std::string long_text(65, 'x');
    const std::string too_long = toml_error("[render]\ncaption = \"" + long_text + "\"\n");
    CHECK(contains(too_long, "s.toml:2"));
    CHECK(contains(too_long, "render.caption"));
    CHECK(contains(too_long, "at most 64 characters, got 65"));
    const std::string order = toml_error(
        "[render]\n[[render.captions]]\nat = 3\ntext = \"a\"\n[[render.captions]]\nat = 2\n"
        "text = \"b\"\n");
    CHECK(contains(order, "s.toml:6"));
    CHECK(contains(order, "render.captions[1].at"));
    CHECK(contains(order, "out of order"));
    const std::string beyond =
        toml_error("[render]\nduration = 5\n[[render.captions]]\nat = 7\ntext = \"late\"\n");
    CHECK(contains(beyond, "s.toml:4"));
    CHECK(contains(beyond, "beyond the video"));
    const std::string cue_too_long =
        toml_error("[render]\n[[render.captions]]\nat = 1\ntext = \"" + long_text + "\"\n");
    CHECK(contains(cue_too_long, "render.captions[0].text"));
    CHECK(contains(cue_too_long, "at most 64"));
    CHECK(contains(toml_error("[render]\ntheme = \"neon\"\n"), "render.theme"));
    CHECK(contains(toml_error("[render]\noverlays = \"some\"\n"), "render.overlays"));
    CHECK(contains(toml_error("[render]\n[[render.captions]]\ntext = \"no time\"\n"),
                   "render.captions[0].at"));
}

TEST_CASE("toml: a caption's hold freezes the video within it, and reads back") {
    const Scene s = parse(
        "[render]\nduration = 10\n[[render.captions]]\nat = 2\ntext = \"Look\"\n"
        "hold = 1.5\n");
    REQUIRE(s.render.captions.size() == 1);
    CHECK(s.render.captions[0].hold == 1.5);
    std::ostringstream out;
    write_toml_scene(out, s);
    CHECK(parse(out.str()).render.captions[0].hold == 1.5);
    // Beyond the video: the file, the hold's line and its field.
    const std::string beyond = toml_error(
        "[render]\nduration = 5\n[[render.captions]]\nat = 4\ntext = \"late\"\nhold = 2\n");
    CHECK(contains(beyond, "s.toml:6"));
    CHECK(contains(beyond, "render.captions[0].hold"));
    CHECK(contains(beyond, "beyond the video"));
    const std::string negative =
        toml_error("[render]\n[[render.captions]]\nat = 1\ntext = \"a\"\nhold = -1\n");
    CHECK(contains(negative, "render.captions[0].hold"));
    CHECK(contains(negative, ">= 0"));
}

TEST_CASE("toml: a caption's words for one panel (event, time) are read, checked and read back") {
    const Scene s = parse(
        "[render]\n[[render.captions]]\nat = 2\ntext = \"Left tests pairs; right predicts\"\n"
        "event = \"The queue predicts\"\ntime = \"Each step tests pairs\"\n"
        "[[render.captions]]\nat = 3\ntext = \"Both\"\n");
    REQUIRE(s.render.captions.size() == 2);
    CHECK(s.render.captions[0].event_text == "The queue predicts");
    CHECK(s.render.captions[0].time_text == "Each step tests pairs");
    CHECK_FALSE(s.render.captions[1].event_text.has_value());
    CHECK_FALSE(s.render.captions[1].time_text.has_value());
    std::ostringstream out;
    write_toml_scene(out, s);
    const Scene again = parse(out.str());
    CHECK(again.render.captions[0].event_text == "The queue predicts");
    CHECK(again.render.captions[0].time_text == "Each step tests pairs");
    CHECK_FALSE(again.render.captions[1].event_text.has_value());
    // Each form is a caption: one line at most, named by its field.
    const std::string long_text(65, 'x');
    const std::string too_long = toml_error(
        "[render]\n[[render.captions]]\nat = 1\ntext = \"a\"\n"
        "time = \"" +
        long_text + "\"\n");
    CHECK(contains(too_long, "render.captions[0].time"));
    CHECK(contains(too_long, "at most 64"));
    CHECK(contains(toml_error("[render]\n[[render.captions]]\nat = 1\ntext = \"a\"\nevent = 3\n"),
                   "render.captions[0].event"));
}

TEST_CASE("toml: a number too small for a double reads as 0, as in algs4 files and on the CLI") {
    const Scene s = parse(
        "[[disc]]\nposition = [0.5, 0.5]\nvelocity = [1e-400, -1e-400]\n"
        "radius = 0.1\n");
    CHECK(s.discs[0].velocity.x == 0.0);
    CHECK(s.discs[0].velocity.y == 0.0);
    // A UTF-8 byte order mark is accepted here too.
    CHECK(parse("\xEF\xBB\xBF[[disc]]\nposition = [0.5, 0.5]\nradius = 0.1\n").discs.size() == 1);
}

TEST_CASE("toml: nesting deeper than the limit is refused before the parser recurses into it") {
    // 50,000 dotted parts overflowed toml++'s stack (SIGSEGV); its own limit covers arrays and
    // inline tables only. Each form is refused with the file, the line and the depth allowed.
    std::string dotted = "a";
    for (int i = 0; i < 50000; ++i) dotted += ".a";
    std::string header = "title = \"t\"\n[a";
    for (int i = 0; i < 50000; ++i) header += ".a";
    header += "]\n";
    // Inline tables whose keys are dotted: each within the limit, together far beyond it.
    std::string mixed = "x = ";
    for (int i = 0; i < 40; ++i) mixed += "{ a.b.c = ";
    mixed += "1";
    for (int i = 0; i < 40; ++i) mixed += " }";
    mixed += "\n";
    for (const std::string& text : {dotted + " = 1\n", header, "[[a.b]]\n" + mixed}) {
        const std::string message = toml_error(text);
        CAPTURE(message.substr(0, 200));
        CHECK(message.size() < 300);
        CHECK(contains(message, "nested too deeply: at most 64 levels"));
    }
    CHECK(contains(toml_error(header), "s.toml:2: "));
    // Quoted dots are part of one key, and a string's brackets are text: within the limit.
    std::string quoted = "title = \"";
    for (int i = 0; i < 200; ++i) quoted += "[{.";
    quoted += "\"\n\"";
    for (int i = 0; i < 200; ++i) quoted += "a.";
    quoted += "\" = 1\n";
    const std::string unknown = toml_error(quoted);
    CHECK(contains(unknown, "unknown key"));
    CHECK_FALSE(contains(unknown, "nested too deeply"));
    // An ordinary scene's nesting is far from the limit.
    CHECK(parse("[render]\n[[render.captions]]\nat = 0\ntext = \"a.b [c] {d}\"\n"
                "[[disc]]\nposition = [0.5, 0.5]\nradius = 0.1\n")
              .discs.size() == 1);
}

TEST_CASE("toml: a scene of millions of tiny values is refused before it is parsed") {
    // `title = [{},{},...]`: about 3 bytes a value, about 100 bytes each once parsed.
    std::string text = "title = [";
    for (int i = 0; i < 2'000'001; ++i) text += "{},";
    text += "]\n";
    const std::string message = toml_error(text);
    CHECK(contains(message, "more than 2000000 values"));
    CHECK(contains(message, "s.toml:1: "));
}

TEST_CASE("toml: every scene text has a bound: title, description and tags") {
    const std::string long_title(256, 'T');
    const std::string title_error = toml_error("title = \"" + long_title + "\"\n");
    CHECK(contains(title_error, "s.toml:1: title: too long: at most 255 characters, got 256"));
    const std::string long_description(1'000'000, 'd');
    const std::string description_error =
        toml_error("title = \"t\"\ndescription = \"" + long_description + "\"\n");
    CHECK(contains(description_error, "s.toml:2: description: too long: at most 600 characters"));
    CHECK(description_error.size() < 200);
    CHECK(contains(toml_error("[[disc]]\nposition = [0.5, 0.5]\nradius = 0.1\ntag = \"" +
                              std::string(65, 'x') + "\"\n"),
                   "disc[0].tag: too long: at most 64"));
    // At the bound, in characters (not bytes): accepted.
    std::string accented;
    for (int i = 0; i < 600; ++i) accented += "\xC3\xA9";  // é
    CHECK(parse("description = \"" + accented +
                "\"\n[[disc]]\nposition = [0.5, 0.5]\n"
                "radius = 0.1\n")
              .description == accented);
}

TEST_CASE("toml: a huge unknown key is refused quickly, its echo cut, without a suggestion") {
    // Before: a 10 MB key took 34 s and a gigabyte (an edit-distance table against every valid
    // key) and the whole key came back in the message.
    const std::string key(2'000'000, 'k');
    const std::string message = toml_error(key + " = 1\n");
    CHECK(contains(message, "s.toml:1: unknown key 'kkkk"));
    CHECK(contains(message, "... (2000000 bytes)"));
    CHECK(message.size() < 300);
    CHECK(nearest_name(key, {"title", "description"}).empty());
    CHECK(nearest_name("titel", {"title", "description"}) == "title");
    CHECK(contains(toml_error("[render]\ntheme = \"" + std::string(100'000, 'x') + "\"\n"),
                   "(100000 bytes)"));
}
