// `collide render` and `collide thumbnail` checked by `collide` itself (render_cli.hpp): a bad
// command line is refused before collide-draw starts, in collide-draw's own words and with its
// exit status; a good one still becomes collide-draw. Shown with a copy of `collide` that has no
// collide-draw to start, over the option matrix's bad sets (tests/cli_matrix/bad_draw_options.hpp).
#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "../cli_matrix/bad_draw_options.hpp"
#include "../support/input_error.hpp"
#include "../support/temp_dir.hpp"
#include "run_collide.hpp"

using collide::test::Bad;
using collide::test::contains;
using collide::test::run_command;
using collide::test::shell_quoted;
using collide::test::TempDir;
namespace fs = std::filesystem;

namespace {

/// A copy of `collide` with no collide-draw beside it or in ../libexec/collide, reading the
/// source tree's scenes.
struct CollideAlone {
    TempDir dir{"draw_checks"};
    fs::path program = dir.path / "bin" / "collide";

    CollideAlone() {
        fs::create_directories(program.parent_path());
        fs::copy_file(COLLIDE_EXE, program);
    }

    [[nodiscard]] collide::test::RunResult run(const std::string& args) const {
        return run_command("COLLIDE_ASSETS_DIR=" + shell_quoted(COLLIDE_ASSETS_DIR) + " " +
                           shell_quoted(program) + " " + args + " 2>&1");
    }
};

}  // namespace

TEST_CASE("collide refuses every bad render, thumbnail and heap line itself, before collide-draw") {
    // Without collide-draw to start, every bad set of the option matrix is still refused (exit 2,
    // "collide: error: " and the option); the matrix checks the words in full.
    const CollideAlone alone;
    const std::vector<std::pair<std::string, std::vector<Bad>>> commands{
        {"render", collide::test::bad_render_options()},
        {"thumbnail", collide::test::bad_thumbnail_options()},
        {"heap", collide::test::bad_heap_options()}};
    for (const auto& [command, cases] : commands) {
        for (const Bad& c : cases) {
            const std::string args = command + " " + c.args;
            CAPTURE(args);
            const auto here = alone.run(args);
            CHECK(here.exit_code == 2);
            CHECK(contains(here.output,
                           c.usage ? "collide: error: " : "collide: error: " + c.option));
            CHECK(contains(here.output, c.option));
            CHECK(contains(here.output, c.detail));
        }
    }
}

TEST_CASE("collide's refusals are collide-draw's, word for word, at every kind of check") {
    // One line for each place a check lives: CLI11's conversion and its usage errors, the option
    // values, the scene (a 3D scene's own options), the plan, the output path, the GL backend,
    // the work limits and --layout-json.
    const CollideAlone alone;
    const std::string never = collide::test::never;
    for (const std::string& args :
         {"render gas --fps abc" + never + ".mp4", "render gas --at 1" + never + ".mp4",
          "render gas --duration nan" + never + ".mp4", "render gas-3d --slab 0" + never + ".mp4",
          "render gas-3d --queue --code" + never + ".mp4",
          "render gas --queue --code --size 640x360" + never + ".mp4",
          "render gas" + never + ".avi", "render gas --gl vulkan" + never + ".mp4",
          "render gas --dt 1e-9" + never + ".mp4", "render gas --layout-json ''" + never + ".mp4",
          "thumbnail gas --at 1e18" + never + ".png", "thumbnail gas" + never + ".png",
          // heap: CLI11, the lesson, its legibility and its fit at the frame size (the
          // renderer's layout, HeapRenderer::fits), the frame, --at.
          "heap --ops P --fps abc" + never + ".mp4",
          "heap --ops 'P Q' --sort 'S O'" + never + ".mp4",
          "heap --ops 'A B C D E F G H I J K L M N O P Q R S T U V' --code" + never + ".mp4",
          "heap --ops 'P Q E X A M L S O R T * *' --impl binary,dary:3,indexed -q l" + never +
              ".png",
          "heap --ops P --size 10x10" + never + ".mp4", "heap --ops P --at 99" + never + ".png"}) {
        CAPTURE(args);
        const auto here = alone.run(args);
        const auto drawn = run_command(shell_quoted(COLLIDE_DRAW_EXE) + " " + args + " 2>&1");
        CHECK(here.exit_code == drawn.exit_code);
        CHECK(here.output == drawn.output);
    }
}

TEST_CASE("collide hands a good render, thumbnail or heap line to collide-draw") {
    // Here collide-draw is missing: the line passed collide's checks, and only drawing is left.
    const CollideAlone alone;
    for (const std::string command : {"render", "thumbnail", "heap"}) {
        CAPTURE(command);
        const fs::path output = alone.dir.path / (command == "thumbnail" ? "gas.png" : "gas.mp4");
        const std::string options = command == "render"      ? " gas -q l --duration 1"
                                    : command == "thumbnail" ? " gas -q l --at 0.5"
                                                             : " --ops 'P Q E * X' -q l";
        const auto r = alone.run(command + options + " -o " + shell_quoted(output));
        CHECK(r.exit_code == 1);
        CHECK(contains(r.output, "collide-draw for `collide " + command + "`"));
        CHECK_FALSE(fs::exists(output));
    }
}
