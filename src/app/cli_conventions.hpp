#pragma once
// What the command line does around the subcommands: --version's text and suggestions for typos.

#include <CLI/CLI.hpp>
#include <string>

namespace collide::app {

/// `collide --version`: the version, the git revision it was configured from, the GL backends
/// built, the libav versions it was built with and where the built-in data is (all known without
/// loading the renderer or libav).
[[nodiscard]] std::string version_text();

/// For a parse error about an unexpected argument (`collide rendr`, `render gas --durration 5`):
/// " (did you mean 'render'?)" naming the closest subcommand, or option of the subcommand that
/// was given, by edit distance; "" when nothing is close or the error is of another kind.
[[nodiscard]] std::string typo_hint(const CLI::App& root, const CLI::ParseError& error);

}  // namespace collide::app
