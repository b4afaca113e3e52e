// `collide`'s side of the drawing commands: it links no GL and no encoder, so that commands that
// draw nothing start fast; a drawing command becomes `collide-draw` (execv: the same process,
// arguments, signals and exit status), found next to this program (the build tree) or in
// ../libexec/collide (an install).

#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

#include "commands.hpp"

namespace collide::app {

namespace {

struct DrawingCommand {
    std::string_view name;
    std::string_view description;
};

// The descriptions are the commands' own (cmd_*.cpp), for `collide --help`.
constexpr std::array<DrawingCommand, 5> drawing_commands{{
    {"heap", "Animate priority-queue operations: heaps as trees over their arrays, step by step"},
    {"puzzle", "Breadth-first search against A* on the 8-puzzle (n x n up to 4x4), side by side"},
    {"render", "Render a teaching video: time-driven (left) and event-driven (right) side by side"},
    {"thumbnail", "Render one frame as a PNG (fast, no video): for READMEs and CI"},
    {"compare",
     "Compare two PNG images: exit 0 if they match, 1 if not (writing a difference image), 2 on "
     "bad input"},
}};

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

}  // namespace

void add_drawing_commands(CLI::App& root, int argc, char** argv) {
    const std::string_view command = command_of(argc, argv);
    for (const DrawingCommand& c : drawing_commands) {
        if (command == c.name) {
            const std::filesystem::path program = drawing_program();
            execv(program.c_str(), argv);
            std::fprintf(stderr, "collide: error: cannot run %s for `collide %s`: %s\n",
                         program.c_str(), std::string(c.name).c_str(), std::strerror(errno));
            std::exit(1);
        }
    }
    for (const DrawingCommand& c : drawing_commands) {
        root.add_subcommand(std::string(c.name), std::string(c.description))
            ->prefix_command()
            ->allow_extras();
    }
}

}  // namespace collide::app
