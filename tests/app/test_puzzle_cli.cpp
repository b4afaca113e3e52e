// `collide puzzle` end to end: the text and JSON reports (answered by `collide` itself, without
// collide-draw), the video (byte-identical from run to run; its last frame equal to
// --last-frame), and bad boards and options refused with exit 2.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "../support/temp_dir.hpp"
#include "collide/video/png.hpp"
#include "run_collide.hpp"

using collide::test::run_collide;
using collide::test::run_collide_bad_input;
using collide::test::run_command;
using collide::test::shell_quoted;
using collide::test::TempDir;
namespace fs = std::filesystem;

namespace {

// The smallest frame collide puzzle draws, at 4 frames per second: a few dozen frames.
const std::string quick = " --size 854x480 --fps 4 --progress none ";

bool contains(const std::string& haystack, const std::string& needle) {
    return haystack.find(needle) != std::string::npos;
}

std::size_t occurrences(const std::string& haystack, const std::string& needle) {
    std::size_t n = 0;
    for (auto at = haystack.find(needle); at != std::string::npos;
         at = haystack.find(needle, at + 1))
        ++n;
    return n;
}

std::string bytes_of(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("collide puzzle --solve and --json: both methods find the 31 moves of a hardest board") {
    const auto text = run_collide("puzzle \"8 6 7 2 5 4 3 0 1\" --solve");
    REQUIRE_MESSAGE(text.exit_code == 0, text.output);
    CHECK(contains(text.output, "BFS (FIFO queue)"));
    CHECK(contains(text.output, "A* (manhattan, binary)"));
    CHECK(contains(text.output, "181,439"));  // BFS expands all but one of the 181,440 boards
    CHECK(occurrences(text.output, "     31\n") == 2);

    const auto json = run_collide(
        "puzzle \"6 4 7 8 5 0 3 2 1\" --json --pq dary:3 --heuristic "
        "hamming");
    REQUIRE_MESSAGE(json.exit_code == 0, json.output);
    CHECK(occurrences(json.output, "\"solution_length\": 31") == 2);
    CHECK(contains(json.output, "\"pq\": \"dary:3\""));
    CHECK(contains(json.output, "\"heuristic\": \"hamming\""));
    CHECK(occurrences(json.output, "\"tile\": ") == 62);

    const auto a = run_collide("puzzle random --moves 20 --seed 3 --json --method astar");
    const auto b = run_collide("puzzle random --moves 20 --seed 3 --json --method astar");
    REQUIRE(a.exit_code == 0);
    CHECK(a.output == b.output);
    CHECK_FALSE(contains(a.output, "\"bfs\""));
}

TEST_CASE("collide puzzle --solve and --json run in `collide` alone: no collide-draw, no GL") {
    // A copy of `collide` with no collide-draw beside it or in ../libexec/collide: the text modes
    // answer as the build tree's program does, and only a video asks for the drawing program.
    TempDir dir("puzzle_alone");
    const fs::path alone = dir.path / "bin" / "collide";
    fs::create_directories(alone.parent_path());
    fs::copy_file(COLLIDE_EXE, alone);
    const auto run_alone = [&](const std::string& args) {
        return run_command(shell_quoted(alone) + " " + args + " 2>&1");
    };
    for (const std::string args : {"puzzle \"8 1 3 4 0 2 7 6 5\" --solve",
                                   "puzzle random --moves 20 --seed 3 --json --pq dary:3"}) {
        CAPTURE(args);
        const auto here = run_alone(args);
        REQUIRE_MESSAGE(here.exit_code == 0, here.output);
        CHECK(here.output == run_collide(args).output);
    }
    CHECK(contains(run_alone("puzzle \"8 1 3 4 0 2 7 6 5\" --solve").output, "A*: "));
    // Bad options of the text modes are refused by `collide` itself (exit 2, the usual words).
    const auto refused = run_alone("puzzle \"1 2 3 4 0 6 7 5 8\" --json -o x.mp4");
    CHECK(refused.exit_code == 2);
    CHECK(contains(refused.output, "--json prints text instead of a video"));
    // A video is collide-draw's: here it is missing, and the message says so.
    const auto video =
        run_alone("puzzle \"1 2 3 4 0 6 7 5 8\" -o " + shell_quoted(dir.path / "p.mp4"));
    CHECK(video.exit_code == 1);
    CHECK(contains(video.output, "collide-draw for `collide puzzle`"));
    CHECK_FALSE(fs::exists(dir.path / "p.mp4"));
}

TEST_CASE("collide puzzle renders byte-identical videos whose last frame is --last-frame's") {
    TempDir dir("puzzle_video");
    const std::string board = "puzzle \"1 2 3 4 0 6 7 5 8\"" + quick;
    const auto first = run_collide(board + "-o " + shell_quoted(dir.path / "a.mp4"));
    REQUIRE_MESSAGE(first.exit_code == 0, first.output);
    REQUIRE(run_collide(board + "-o " + shell_quoted(dir.path / "b.mp4")).exit_code == 0);
    CHECK(fs::file_size(dir.path / "a.mp4") > 1000);
    CHECK(bytes_of(dir.path / "a.mp4") == bytes_of(dir.path / "b.mp4"));

    const auto frames = run_collide(board + "--format png -o " + shell_quoted(dir.path / "frames"));
    REQUIRE_MESSAGE(frames.exit_code == 0, frames.output);
    std::vector<fs::path> pngs;
    for (const auto& entry : fs::directory_iterator(dir.path / "frames")) {
        if (entry.path().extension() == ".png") pngs.push_back(entry.path());
    }
    std::sort(pngs.begin(), pngs.end());
    CHECK(contains(frames.output, std::to_string(pngs.size()) + " frames"));
    REQUIRE(pngs.size() > 20);

    const fs::path last = dir.path / "last.png";
    const auto still = run_collide(board + "--last-frame -o " + shell_quoted(last));
    REQUIRE_MESSAGE(still.exit_code == 0, still.output);
    const collide::Image image = collide::video::read_png(last);
    CHECK(image.width == 854);
    CHECK(image.height == 480);
    // The video ends on a hold: its last frame is the final state.
    CHECK(collide::video::read_png(pngs.back()).rgba == image.rgba);
    CHECK(collide::video::read_png(pngs.front()).rgba != image.rgba);
}

TEST_CASE("collide puzzle: bad boards name the token and unsolvable boards and budgets say why") {
    TempDir dir("puzzle_bad");
    const std::string out = " -o " + shell_quoted(dir.path / "x.mp4");
    CHECK(contains(run_collide_bad_input("puzzle \"1 2 3 4 x 6 7 5 8\"" + out),
                   "board: 'x' (token 5) is not a tile"));
    CHECK(contains(run_collide_bad_input("puzzle \"1 2 3 4 0 6 7 5 5\"" + out),
                   "'5' (token 9) is tile 5 again (first at token 8); tile 8 is missing"));
    const std::string unsolvable = run_collide_bad_input("puzzle \"1 2 3 4 5 6 8 7 0\"" + out);
    CHECK(contains(unsolvable, "cannot be solved: it has 1 inversion"));
    const std::string budget =
        run_collide_bad_input("puzzle random --side 4 --moves 60 --seed 5 --max-nodes 20000" + out);
    CHECK(contains(budget, "--max-nodes: BFS stopped after storing 20,000 boards"));
    CHECK(contains(budget, "--method astar"));
    CHECK(run_collide("puzzle random --side 4 --moves 60 --seed 5 --solve --method astar")
              .exit_code == 0);
    const std::string png = " -o " + shell_quoted(dir.path / "x.png");
    for (const char* at : {"-1", "1e9", "nan"}) {
        CHECK(contains(run_collide_bad_input("puzzle random --at " + std::string(at) + png),
                       "--at: expected a time within the video"));
    }
    CHECK_FALSE(fs::exists(dir.path / "x.mp4"));
    CHECK_FALSE(fs::exists(dir.path / "x.png"));
}

TEST_CASE(
    "collide puzzle --theme light draws a light page, dark is the default, a bad one exit 2") {
    TempDir dir("puzzle_theme");
    const std::string board = "puzzle \"1 2 3 4 0 6 7 5 8\"" + quick;
    const auto mean_brightness = [&](const std::string& theme, const char* name) {
        const fs::path png = dir.path / name;
        const auto r = run_collide(board + "--last-frame " + theme + " -o " + shell_quoted(png));
        REQUIRE_MESSAGE(r.exit_code == 0, r.output);
        const collide::Image image = collide::video::read_png(png);
        double sum = 0.0;
        for (std::size_t i = 0; i + 3 < image.rgba.size(); i += 4)
            sum += image.rgba[i] + image.rgba[i + 1] + image.rgba[i + 2];
        return sum / (3.0 * static_cast<double>(image.rgba.size() / 4));
    };
    // The last frame: two large boards of light tiles on the page.
    const double dark = mean_brightness("", "dark.png");
    const double light = mean_brightness("--theme light", "light.png");
    CHECK(dark < 110.0);
    CHECK(light > 180.0);
    CHECK(light - dark > 80.0);
    CHECK(mean_brightness("--theme dark", "dark2.png") == doctest::Approx(dark));
    CHECK(contains(
        run_collide_bad_input(board + "--theme sepia -o " + shell_quoted(dir.path / "x.mp4")),
        "--theme: expected a theme (dark or light), got 'sepia'"));
    CHECK(contains(run_collide_bad_input("puzzle \"1 2 3 4 0 6 7 5 8\" --solve --theme light"),
                   "--theme"));
    CHECK_FALSE(fs::exists(dir.path / "x.mp4"));
}

TEST_CASE("collide puzzle --code: A* beside its loop and both searches or a text mode exit 2") {
    TempDir dir("puzzle_code");
    const std::string board = "puzzle \"5 2 8 1 0 4 7 6 3\"" + quick;
    // The start's expansion, mid-walk: one search (A* by default) with the listing beside it.
    const fs::path code = dir.path / "code.png";
    const auto r = run_collide(board + "--code --at 4 -o " + shell_quoted(code));
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    const fs::path plain = dir.path / "plain.png";
    REQUIRE(run_collide(board + "--method astar --at 4 -o " + shell_quoted(plain)).exit_code == 0);
    CHECK(bytes_of(code) != bytes_of(plain));
    CHECK(run_collide(board + "--code --method bfs --at 4 -o " + shell_quoted(dir.path / "bfs.png"))
              .exit_code == 0);
    // Refused before any search or drawing, with words that say what to do.
    const std::string both = run_collide_bad_input(board + "--code --method both -o " +
                                                   shell_quoted(dir.path / "x.mp4"));
    CHECK(contains(both, "--code"));
    CHECK(contains(both, "--method astar"));
    for (const char* mode : {"--solve", "--json"}) {
        const std::string text =
            run_collide_bad_input("puzzle \"5 2 8 1 0 4 7 6 3\" --code " + std::string(mode));
        CHECK(contains(text, std::string(mode) + " prints text instead of a video"));
        CHECK(contains(text, "--code"));
    }
    CHECK_FALSE(fs::exists(dir.path / "x.mp4"));
}
