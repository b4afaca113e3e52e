#pragma once
/// \file
/// The video of `collide puzzle` (collide-draw only): its options' validation, and the render loop
/// from show::PuzzleProgram through PuzzleRenderer into the VideoWriter. The options themselves
/// are registered by puzzle_options.hpp.

#include <vector>

#include "algorithm_video.hpp"
#include "collide/sim/puzzle/board.hpp"
#include "collide/sim/puzzle/search.hpp"
#include "puzzle_options.hpp"

namespace collide::app {

/// Checks every video option and the destination before any search or drawing. Throws
/// Error(input) naming the option.
void validate_puzzle_video(const PuzzleVideoCli& v);

/// Renders the video (or its last frame) of `results` (one or two solved searches of `start`).
void render_puzzle_video(const puzzle::Board& start,
                         const std::vector<puzzle::SearchResult>& results, const PuzzleVideoCli& v);

/// The two above, as `collide puzzle` takes them.
[[nodiscard]] PuzzleVideoMaker drawn_puzzle_video();

}  // namespace collide::app
