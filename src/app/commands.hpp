#pragma once
/// \file
/// Subcommands of the `collide` CLI. Each `add_*_command` registers one subcommand (options and
/// callback) on the root app; callbacks throw collide::Error, which `main` turns into an exit code.

#include <CLI/CLI.hpp>

namespace collide::app {

// Subcommands register here as their issues land, e.g.
// void add_pq_command(CLI::App& root);

/// `collide render SCENE`: a side-by-side teaching video (time-driven | event-driven) to MP4/GIF/PNG.
void add_render_command(CLI::App& root);

/// `collide thumbnail SCENE --at T`: one frame of that video as a PNG, without encoding a video.
void add_thumbnail_command(CLI::App& root);

/// `collide pq`: the lecture's priority-queue trace table (text, CSV or Markdown).
void add_pq_command(CLI::App& root);

/// `collide render SCENE`: a side-by-side teaching video (time-driven | event-driven) to MP4/GIF/PNG.
void add_render_command(CLI::App& root);

/// `collide thumbnail SCENE --at T`: one frame of that video as a PNG, without encoding a video.
void add_thumbnail_command(CLI::App& root);

}  // namespace collide::app
