#pragma once
/// \file
/// Subcommands of the `collide` CLI. Each `add_*_command` registers one subcommand (options and
/// callback) on the root app; callbacks throw collide::Error, which `main` turns into an exit code.

#include <CLI/CLI.hpp>

#include "puzzle_options.hpp"

namespace collide::app {

// Subcommands register here as their issues land, e.g.
// void add_pq_command(CLI::App& root);

/// `collide check SCENE`: validate a scene; exit 0 with a one-line summary, 2 with the problem.
void add_check_command(CLI::App& root);

/// `collide scenes`: list the built-in scenes with a one-line description each.
void add_scenes_command(CLI::App& root);

/// `collide pq`: the lecture's priority-queue trace table (text, CSV or Markdown).
void add_pq_command(CLI::App& root);

/// `collide heap`: animated priority-queue operations (heaps as trees over their arrays).
void add_heap_command(CLI::App& root);

/// `collide puzzle`: BFS against A* on the sliding puzzle (text, JSON or a video); `video` makes
/// the video (collide-draw: draws it; collide: hands the command line to collide-draw).
void add_puzzle_command(CLI::App& root, PuzzleVideoMaker video);

/// `collide simulate`: run an engine to a time, print measurements, optionally log collisions.
void add_simulate_command(CLI::App& root);

/// `collide bench`: engine throughput and memory on a random periodic fluid or a scene.
void add_bench_command(CLI::App& root);

/// `collide render SCENE`: a side-by-side teaching video (time-driven | event-driven) to
/// MP4/GIF/PNG.
void add_render_command(CLI::App& root);

/// `collide compare A.png B.png [--tolerance T] [--max-diff-pixels N] [--max-diff-percent P]
/// [--json]`: exit 0 if they match, 1 (with a difference image) if not, 2 on bad input. PNG
/// files only (no GL, no encoder): registered by main in both programs.
void add_compare_command(CLI::App& root);

/// The commands that draw (heap, puzzle, render, thumbnail). In `collide-draw`
/// (draw_commands.cpp) they are registered. In `collide` (draw_forward.cpp), which links no GL
/// and no encoder, the process becomes collide-draw (execv, same arguments) when argv names one
/// of them, and they are registered for --help and suggestions otherwise; `puzzle` is registered
/// whole, answers --solve and --json itself and becomes collide-draw for a video only.
void add_drawing_commands(CLI::App& root, int argc, char** argv);

/// Thrown by a command whose answer is its exit status (`compare`: 1 = the images differ), after
/// it has said so on stdout; `main` returns `code` and prints nothing more.
struct ExitStatus {
    int code = 1;
};

/// `collide thumbnail SCENE --at T`: one frame of that video as a PNG, without encoding a video.
void add_thumbnail_command(CLI::App& root);

}  // namespace collide::app
