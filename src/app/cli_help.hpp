#pragma once
/// \file
/// Help that reads well: `collide help [COMMAND]`, and help text wrapped to the terminal's width
/// (80 columns when standard output is not a terminal) instead of lines of hundreds of characters.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace collide::app {

/// Sets a formatter on `root` that wraps descriptions, footers and option lists to `width`
/// columns. Call before adding subcommands: each copies its parent's formatter when created.
void use_wrapping_help(CLI::App& root, int width);

/// Registers `collide help [COMMAND]` (for --help's list, the man page and completion); the
/// command itself never runs: main rewrites it with help_as_flag first.
void add_help_command(CLI::App& root);

/// argv with `help [COMMAND]` as the first argument rewritten to `[COMMAND] --help`, so that the
/// help of a command drawn by collide-draw comes from the program that defines it. `storage`
/// owns the new array (null-terminated, as execv wants); argc and argv are updated in place.
void help_as_flag(int& argc, char**& argv, std::vector<char*>& storage);

/// `text` wrapped at spaces to lines of at most `width` characters (longer words stay whole);
/// lines that fit are kept as they are; a longer line that starts with spaces (an example) is
/// wrapped under its indent, its continuation lines two spaces further in.
[[nodiscard]] std::string wrap_text(const std::string& text, std::size_t width);

}  // namespace collide::app
