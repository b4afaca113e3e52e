// `collide heap` end to end: videos, GIFs, PNG sequences and last frames written (byte-identical
// from run to run), and every kind of bad input refused with exit 2 before anything is written.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>

#include "../support/temp_dir.hpp"
#include "collide/video/png.hpp"
#include "run_collide.hpp"

using collide::test::run_collide;
using collide::test::run_collide_bad_input;
using collide::test::shell_quoted;
using collide::test::TempDir;
namespace fs = std::filesystem;

namespace {

// Small and quick: a few seconds of 320x180 video at 5 frames per second.
const std::string quick = " --size 320x180 --fps 5 --pace 0.1 --progress none ";

bool contains(const std::string& haystack, const std::string& needle) {
    return haystack.find(needle) != std::string::npos;
}

std::string bytes_of(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("collide heap renders the lecture's trace to MP4, byte-identical from run to run") {
    TempDir dir("heap_mp4");
    const fs::path a = dir.path / "a.mp4";
    const fs::path b = dir.path / "b.mp4";
    const std::string ops = "heap --ops \"P Q E * X A M * P L E *\"" + quick;
    const auto r = run_collide(ops + "-o " + shell_quoted(a));
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    CHECK(contains(r.output, "binary heap, 12 operations"));
    REQUIRE(run_collide(ops + "-o " + shell_quoted(b)).exit_code == 0);
    CHECK(fs::file_size(a) > 1000);
    CHECK(bytes_of(a) == bytes_of(b));
}

TEST_CASE("collide heap: side by side as GIF, heapsort as a PNG sequence, the last frame as PNG") {
    TempDir dir("heap_formats");
    const auto three = run_collide("heap --ops \"P Q E * X\" --impl unordered,ordered,binary" +
                                   quick + "-o " + shell_quoted(dir.path / "three.gif"));
    REQUIRE_MESSAGE(three.exit_code == 0, three.output);
    CHECK(contains(three.output, "unordered array, ordered array, binary heap"));
    CHECK(fs::file_size(dir.path / "three.gif") > 1000);

    const auto sort = run_collide("heap --sort \"S O R T E X\" --format png" + quick + "-o " +
                                  shell_quoted(dir.path / "frames"));
    REQUIRE_MESSAGE(sort.exit_code == 0, sort.output);
    std::size_t frames = 0;
    for (const auto& entry : fs::directory_iterator(dir.path / "frames")) {
        frames += entry.path().extension() == ".png";
    }
    CHECK(frames > 10);

    const fs::path last = dir.path / "last.png";
    const auto still = run_collide("heap --ops \"5 9 3 7 * 3^12\" --impl indexed:2 --last-frame" +
                                   quick + "-o " + shell_quoted(last));
    REQUIRE_MESSAGE(still.exit_code == 0, still.output);
    const collide::Image image = collide::video::read_png(last);
    CHECK(image.width == 320);
    CHECK(image.height == 180);
}

TEST_CASE("collide heap --theme light draws dark text on a light page, as collide render does") {
    TempDir dir("heap_theme");
    const auto still = [&](const std::string& theme, const char* name) {
        const fs::path png = dir.path / name;
        const auto r = run_collide("heap --ops \"P Q E * X\" --last-frame" + quick + theme +
                                   " -o " + shell_quoted(png));
        REQUIRE_MESSAGE(r.exit_code == 0, r.output);
        return collide::video::read_png(png);
    };
    // Mean brightness of the frame and its darkest pixel's brightness.
    const auto brightness = [](const collide::Image& image) {
        double sum = 0.0;
        int darkest = 255 * 3;
        for (std::size_t i = 0; i + 3 < image.rgba.size(); i += 4) {
            const int v = image.rgba[i] + image.rgba[i + 1] + image.rgba[i + 2];
            sum += v;
            darkest = std::min(darkest, v);
        }
        return std::pair<double, int>{sum / (3.0 * static_cast<double>(image.rgba.size() / 4)),
                                      darkest / 3};
    };
    const auto [dark_mean, dark_min] = brightness(still("", "dark.png"));
    const auto [light_mean, light_min] = brightness(still("--theme light", "light.png"));
    CHECK(dark_mean < 80.0);    // the default: a dark page
    CHECK(light_mean > 180.0);  // a light page...
    CHECK(light_min < 60);      // ...with dark text on it
    CHECK(brightness(still("--theme dark", "dark2.png")).first == doctest::Approx(dark_mean));
    CHECK(contains(run_collide_bad_input("heap --ops P --theme sepia" + quick + "-o " +
                                         shell_quoted(dir.path / "x.mp4")),
                   "--theme: expected a theme (dark or light), got 'sepia'"));
    CHECK(!fs::exists(dir.path / "x.mp4"));
}

TEST_CASE("collide heap: bad tokens exit 2 naming the token and its position") {
    TempDir dir("heap_bad_tokens");
    const std::string out = " -o " + shell_quoted(dir.path / "x.mp4");
    CHECK(contains(run_collide_bad_input("heap --ops \"P ? *\"" + quick + out),
                   "--ops: token 2 '?'"));
    CHECK(contains(run_collide_bad_input("heap --ops \"P * *\"" + quick + out),
                   "token 3 '*': removes from an empty queue"));
    CHECK(contains(run_collide_bad_input("heap --ops \"5 3 3^9\"" + quick + out),
                   "token 3 '3^9': increase-key needs --impl indexed"));
    CHECK(contains(run_collide_bad_input("heap --ops \"5 3 3^1\" --impl indexed" + quick + out),
                   "increase-key to a smaller key"));
    CHECK(contains(run_collide_bad_input("heap --ops \"5 X\"" + quick + out), "token 2 'X'"));
    CHECK(contains(run_collide_bad_input("heap --sort \"S O * T\"" + quick + out),
                   "--sort: token 3 '*'"));
    CHECK(fs::is_empty(dir.path));  // nothing written
}

TEST_CASE("collide heap: bad options and inputs too big to draw legibly exit 2") {
    TempDir dir("heap_bad_options");
    const std::string out = " -o " + shell_quoted(dir.path / "x.mp4");
    CHECK(contains(run_collide_bad_input("heap" + quick + out), "give either --ops"));
    CHECK(contains(run_collide_bad_input("heap --ops P --sort P" + quick + out),
                   "give either --ops"));
    CHECK(contains(run_collide_bad_input("heap --sort \"B A\" --impl ordered" + quick + out),
                   "--impl"));
    CHECK(contains(
        run_collide_bad_input("heap --ops P --impl heap" + quick + out),
        "--impl: expected a queue: unordered, ordered, binary, dary:D or indexed[:D], got 'heap'"));
    CHECK(contains(run_collide_bad_input("heap --ops P --index-base 2" + quick + out),
                   "--index-base: expected 0 or 1, got '2'"));
    CHECK(contains(run_collide_bad_input("heap --ops P --pace 0" + quick + out), "--pace"));
    CHECK(contains(
        run_collide_bad_input("heap --ops P" + quick + "-o " + shell_quoted(dir.path / "x.txt")),
        "-o: expected a .mp4 or .gif path"));
    CHECK(contains(run_collide_bad_input("heap --ops P --last-frame" + quick + out),
                   "expected a .png path"));
    CHECK(contains(run_collide_bad_input("heap --ops P" + quick + "-o " +
                                         shell_quoted(dir.path / "missing" / "x.mp4")),
                   "missing"));
    // 13 keys at once in three panels: more than 36 / 3 = 12 can be drawn legibly.
    const std::string thirteen = "\"A B C D E F G H I J K L M\"";
    const std::string big = run_collide_bad_input("heap --ops " + thirteen +
                                                  " --impl unordered,ordered,binary" + quick + out);
    CHECK(contains(big, "holds up to 13 keys at once, but at most 12 can be drawn legibly"));
    CHECK(run_collide("heap --ops " + thirteen + " --last-frame" + quick + "-o " +
                      shell_quoted(dir.path / "one.png"))
              .exit_code == 0);  // one panel takes up to 36
    CHECK(!fs::exists(dir.path / "x.mp4"));
}

TEST_CASE("heap and puzzle read --fps as render does: decimal digits, never octal or hex") {
    // CLI11 alone read `--fps 010` as octal 8 and `--fps 0x1E` as hex 30.
    TempDir out("heap_fps_digits");
    const std::string video = (out.path / "h.mp4").string();
    const auto r = run_collide(
        "heap --ops \"1 2 *\" --size 640x360 --progress none --fps 010 -o '" + video + "'");
    CAPTURE(r.output);
    CHECK(r.exit_code == 0);
    CHECK(r.output.find("@ 10 fps") != std::string::npos);
    for (const std::string command :
         {"heap --ops \"1 2 *\" --last-frame", "puzzle \"1 2 3 4 5 6 7 0 8\" --last-frame"}) {
        for (const std::string value : {"0x1E", "1e1", "-5", "30.5"}) {
            const std::string message = run_collide_bad_input(
                command + " --fps " + value + " -o '" + (out.path / "x.png").string() + "'");
            CAPTURE(message);
            CHECK(message.find("--fps: expected a whole number") != std::string::npos);
        }
    }
    for (const std::string value : {"0x1", "01x"}) {
        CHECK(run_collide_bad_input("heap --ops \"1 2 *\" --last-frame --index-base " + value +
                                    " -o '" + (out.path / "x.png").string() + "'")
                  .find("--index-base") != std::string::npos);
    }
}

TEST_CASE("collide heap --code: the pseudocode beside the heap, its line under way on a plate") {
    TempDir dir("heap_code");
    // 320x180 is the compact form; the code needs the lesson's 16:9 frame at its smallest.
    const std::string frame = " --size 854x480 --pace 1 --progress none ";
    const auto still = [&](const std::string& options, const char* name) {
        const fs::path png = dir.path / name;
        const auto r =
            run_collide("heap --ops \"P Q E *\"" + frame + options + " -o " + shell_quoted(png));
        REQUIRE_MESSAGE(r.exit_code == 0, r.output);
        return collide::video::read_png(png);
    };
    // Pixels of the current line's amber plate in the right 40 % of the frame, under the strip.
    const auto plate_pixels = [](const collide::Image& image) {
        int n = 0;
        for (int y = image.height / 6; y < image.height; ++y) {
            for (int x = image.width * 3 / 5; x < image.width; ++x) {
                const std::uint8_t* p = image.pixel(x, y);
                n += p[0] == 240 && p[1] == 170 && p[2] == 40;
            }
        }
        return n;
    };
    // 2 s: the first insert's first step (after the 1.5 s intro) is under way.
    const collide::Image code = still("--code --at 2", "code.png");
    const collide::Image plain = still("--at 2", "plain.png");
    CHECK(code.rgba != plain.rgba);
    CHECK(plate_pixels(code) > 2000);  // a bar across the column, not a speck
    CHECK(plate_pixels(plain) == 0);
    // The last frame: every operation done, no line under way.
    CHECK(plate_pixels(still("--code --last-frame", "last.png")) == 0);
}

TEST_CASE("collide heap --code: where no code can be shown, exit 2 naming --code") {
    TempDir dir("heap_code_bad");
    const std::string out = " -o " + shell_quoted(dir.path / "x.mp4");
    CHECK(contains(
        run_collide_bad_input("heap --ops \"P Q *\" --code --impl unordered" + quick + out),
        "--code: shows the code of one heap"));
    CHECK(contains(
        run_collide_bad_input("heap --ops \"P Q *\" --code --impl binary,dary:3" + quick + out),
        "--code: shows the code of one heap"));
    // 22 keys at once: one panel takes 36, but beside the code only 21.
    const std::string keys = "\"A B C D E F G H I J K L M N O P Q R S T U V\"";
    CHECK(contains(run_collide_bad_input("heap --ops " + keys + " --code" + quick + out),
                   "at most 21 can be drawn legibly with 1 panel side by side"));
    CHECK(fs::is_empty(dir.path));  // nothing written
}

TEST_CASE(
    "collide heap: trees that do not fit the frame at the lesson size exit 2 naming the most "
    "keys that do") {
    // Issue 44: an indexed heap of 11 keys beside two other heaps, or word keys in two heaps,
    // were drawn with nodes on nodes and words out of their nodes; now refused up front.
    TempDir dir("heap_fit");
    const std::string out = " --progress none --last-frame -o " + shell_quoted(dir.path / "x.png");
    const std::string eleven = "\"P Q E X A M L S O R T * *\"";
    const std::string three =
        run_collide_bad_input("heap --ops " + eleven + " --impl binary,dary:3,indexed -q l" + out);
    CHECK(contains(three,
                   "--ops: the queue holds up to 11 keys at once, but at most 8 fit a "
                   "854x480 frame with --impl binary,dary:3,indexed"));
    CHECK(contains(three, "use fewer keys or fewer implementations"));
    const std::string words = run_collide_bad_input(
        "heap --ops \"apple banana cherry damson elder fig grape hazel iris * kiwi *\" --impl "
        "binary,dary:4 --size 1280x720" +
        out);
    CHECK(contains(words, "holds up to 9 keys at once, but at most 6 fit a 1280x720 frame"));
    CHECK(contains(words, "shorter keys"));
    CHECK(!fs::exists(dir.path / "x.png"));
    // The most that fit are drawn.
    const auto eight =
        run_collide("heap --ops \"P Q E X A M L S * *\" --impl binary,dary:3,indexed -q l" + out);
    CHECK_MESSAGE(eight.exit_code == 0, eight.output);
    CHECK(fs::exists(dir.path / "x.png"));
}
