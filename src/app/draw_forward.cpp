// `collide`'s side of the drawing commands: it links no GL and no encoder, so that commands that
// draw nothing start fast; a drawing command becomes `collide-draw` (execv: the same process,
// arguments, signals and exit status), found next to this program (the build tree) or in
// ../libexec/collide (an install). `puzzle` is parsed here whole: --solve and --json print text
// and run here; only its video becomes collide-draw, once its command line has parsed. `render`
// and `thumbnail` are parsed and checked here too (render_cli.hpp), and `heap` (heap_cli.hpp), so
// that a bad command line is refused with collide-draw's own words without starting it.

#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>

#include "commands.hpp"
#include "heap_cli.hpp"
#include "interrupt.hpp"
#include "render_cli.hpp"

namespace collide::app {

namespace {

/// The subcommand argv names: its first word that is not an option (the root takes no values).
std::string_view command_of(int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        if (argv[i][0] != '-') return argv[i];
    }
    return {};
}

std::filesystem::path drawing_program() {
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    const std::filesystem::path beside = exe.parent_path() / "collide-draw";
    if (std::filesystem::is_regular_file(beside, ec)) return beside;
    return exe.parent_path().parent_path() / "libexec" / "collide" / "collide-draw";
}

/// Becomes collide-draw with the same arguments; returns only by exiting 1 when it cannot.
[[noreturn]] void run_drawing_program(char** argv, std::string_view command) {
    const std::filesystem::path program = drawing_program();
    execv(program.c_str(), argv);
    std::fprintf(stderr, "collide: error: cannot run %s for `collide %s`: %s\n", program.c_str(),
                 std::string(command).c_str(), std::strerror(errno));
    std::exit(1);
}

/// `collide puzzle`, whole: --solve and --json run here; a video becomes collide-draw once the
/// command line has parsed, before any search (collide-draw parses it again and draws it).
void add_puzzle_here(CLI::App& root, char** argv) {
    PuzzleVideoMaker video;
    video.check = [argv](const PuzzleVideoCli& /*collide-draw checks them*/) {
        run_drawing_program(argv, "puzzle");
    };
    // No `draw`: `check` never returns.
    add_puzzle_command(root, std::move(video));
}

/// `collide render` (still = false) or `thumbnail`, parsed and checked here with collide-draw's
/// own checks (CheckedRender: the scene, every option, the destinations; nothing drawn or
/// simulated); only a line that passes becomes collide-draw, which checks it again and draws.
void add_render_here(CLI::App& root, char** argv, bool still) {
    auto values = std::make_shared<RenderCli>();
    add_render_options(root, *values, still)->callback([values, argv, still] {
        {
            // (A scene is read from a regular file only, so collide-draw reads it again.)
            const InterruptGuard interrupts;
            const CheckedRender checked(*values, still, interrupts);
        }  // the handlers go before the exec: collide-draw installs its own
        run_drawing_program(argv, still ? "thumbnail" : "render");
    });
}

void add_render_here(CLI::App& root, char** argv) {
    add_render_here(root, argv, false);
}

void add_thumbnail_here(CLI::App& root, char** argv) {
    add_render_here(root, argv, true);
}

/// `collide heap`, parsed and checked here with collide-draw's own checks (CheckedHeap: the
/// lesson, its fit at the frame size, every option, the destinations; nothing drawn); only a line
/// that passes becomes collide-draw, which checks it again and draws.
void add_heap_here(CLI::App& root, char** argv) {
    auto values = std::make_shared<HeapCli>();
    add_heap_options(root, *values)->callback([values, argv] {
        const CheckedHeap checked(*values);  // throws Error(input) for a bad line
        run_drawing_program(argv, "heap");
    });
}

struct DrawingCommand {
    std::string_view name;
    std::string_view description;  ///< for `collide --help`
    /// Registers the whole command here (it execs collide-draw only to draw); null: the command
    /// execs collide-draw as soon as argv names it.
    void (*add_here)(CLI::App& root, char** argv) = nullptr;
};

// The descriptions are the commands' own (cmd_*.cpp), for `collide --help`.
constexpr std::array<DrawingCommand, 4> drawing_commands{{
    {"heap", {}, add_heap_here},            // registered with its own (heap_cli.cpp)
    {"puzzle", {}, add_puzzle_here},        // registered with its own description (cmd_puzzle.cpp)
    {"render", {}, add_render_here},        // registered with its own (render_cli.cpp)
    {"thumbnail", {}, add_thumbnail_here},  // registered with its own (render_cli.cpp)
}};

}  // namespace

void add_drawing_commands(CLI::App& root, int argc, char** argv) {
    const std::string_view command = command_of(argc, argv);
    for (const DrawingCommand& c : drawing_commands) {
        if (command == c.name && c.add_here == nullptr) run_drawing_program(argv, c.name);
    }
    for (const DrawingCommand& c : drawing_commands) {
        if (c.add_here != nullptr) {
            c.add_here(root, argv);
            continue;
        }
        root.add_subcommand(std::string(c.name), std::string(c.description))
            ->prefix_command()
            ->allow_extras();
    }
}

}  // namespace collide::app
