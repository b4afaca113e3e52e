#pragma once
/// \file
/// Subcommands of the `collide` CLI. Each `add_*_command` registers one subcommand (options and
/// callback) on the root app; callbacks throw collide::Error, which `main` turns into an exit code.

#include <CLI/CLI.hpp>

namespace collide::app {

// Subcommands register here as their issues land, e.g.
// void add_pq_command(CLI::App& root);

/// `collide pq`: the lecture's priority-queue trace table (text, CSV or Markdown).
void add_pq_command(CLI::App& root);

}  // namespace collide::app
