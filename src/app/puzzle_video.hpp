#pragma once
/// \file
/// The video of `collide puzzle`: its options (the same as `collide heap`'s: -o, --format, -q,
/// --size, --fps, --last-frame, --progress, --verbose), their validation, and the render loop
/// from PuzzleFrames through PuzzleRenderer into the VideoWriter.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "collide/sim/puzzle/board.hpp"
#include "collide/sim/puzzle/search.hpp"

namespace collide::app {

/// Raw video option values as CLI11 stores them.
struct PuzzleVideoCli {
    std::string output;
    std::string format;
    std::string quality = "m";
    std::string size;
    int fps = 30;
    bool last_frame = false;
    double at = 0.0;
    std::string progress = "auto";
    bool verbose = false;

    CLI::Option* output_opt = nullptr;
    CLI::Option* format_opt = nullptr;
    CLI::Option* quality_opt = nullptr;
    CLI::Option* size_opt = nullptr;
    CLI::Option* fps_opt = nullptr;
    CLI::Option* last_frame_opt = nullptr;
    CLI::Option* at_opt = nullptr;
};

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
