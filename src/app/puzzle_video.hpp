#pragma once
/// \file
/// The video of `collide puzzle`: its options (the same as `collide heap`'s: -o, --format, -q,
/// --size, --fps, --last-frame, --theme, --progress, --verbose), their validation, and the render
/// loop from show::PuzzleLesson through PuzzleRenderer into the VideoWriter.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "collide/sim/puzzle/board.hpp"
#include "collide/sim/puzzle/search.hpp"
#include "lesson_video.hpp"

namespace collide::app {

/// The puzzle video's options are the drawn lessons' own (lesson_video.hpp).
using PuzzleVideoCli = LessonVideoCli;

/// Registers the video options on `cmd`.
void add_puzzle_video_options(CLI::App& cmd, PuzzleVideoCli& v);

/// Throws Error(input) naming the first video option given although `mode` (--solve, --json)
/// prints text instead.
void refuse_video_options(const PuzzleVideoCli& v, const std::string& mode);

/// Checks every video option and the destination before any search or drawing. Throws
/// Error(input) naming the option.
void validate_puzzle_video(const PuzzleVideoCli& v);

/// Renders the video (or its last frame) of `results` (one or two solved searches of `start`).
void render_puzzle_video(const puzzle::Board& start,
                         const std::vector<puzzle::SearchResult>& results, const PuzzleVideoCli& v);

}  // namespace collide::app
