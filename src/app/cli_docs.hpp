#pragma once
/// \file
/// The man page and the bash, zsh and fish completion, written from the command line's own
/// definitions (the CLI11 tree), so that they name every command and option there is. The build
/// runs `collide-draw --generate-docs KIND` (the program that defines every command) and installs
/// what it prints; `json` is the tree itself, for the test that checks the others against it.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace collide::app {

/// One option or positional argument of a command, as the documents show it.
struct OptionDoc {
    std::vector<std::string> names;    ///< "-q", "--quality"; a positional: its name ("scene")
    std::string value;                 ///< "INT", "FLOAT", "PATH", "WxH"...; "" for a flag
    std::vector<std::string> choices;  ///< the values a CLI11 IsMember check lists, else none
    std::string description;
    bool positional = false;
    bool required = false;
    /// Whether its value names a file or folder (completion offers paths).
    [[nodiscard]] bool takes_path() const;
};

/// One command (the root: name ""), its visible options in the order defined.
struct CommandDoc {
    std::string name;
    std::string description;
    std::string footer;
    std::vector<OptionDoc> options;
};

/// The root and every visible subcommand (hidden: group ""), root first.
[[nodiscard]] std::vector<CommandDoc> describe_commands(const CLI::App& root);

[[nodiscard]] std::string man_page(const std::vector<CommandDoc>& commands);
[[nodiscard]] std::string bash_completion(const std::vector<CommandDoc>& commands);
[[nodiscard]] std::string zsh_completion(const std::vector<CommandDoc>& commands);
[[nodiscard]] std::string fish_completion(const std::vector<CommandDoc>& commands);
[[nodiscard]] std::string commands_json(const std::vector<CommandDoc>& commands);

/// The hidden root option `--generate-docs man|bash|zsh|fish|json`: prints that document for
/// `root` as parsed (every command registered) and ends the run with exit 0.
void add_docs_generator(CLI::App& root);

}  // namespace collide::app
