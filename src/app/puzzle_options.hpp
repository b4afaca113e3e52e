#pragma once
/// \file
/// `collide puzzle`'s video options (the drawn lessons' own: -o, --format, -q, --size, --fps,
/// --at, --last-frame, --theme, --subtitles, --progress, --verbose, --font), apart from the video
/// (puzzle_video.hpp): `collide`, which draws nothing, parses the whole command line and answers
/// --solve and --json itself (collide_app_options: no GL, no encoder).

#include <functional>
#include <string>
#include <vector>

#include "algorithm_options.hpp"
#include "cli_fwd.hpp"
#include "collide/sim/puzzle/board.hpp"
#include "collide/sim/puzzle/search.hpp"

namespace collide::app {

/// The puzzle video's options: the drawn lessons' own (algorithm_options.hpp), --code and
/// --questions.
struct PuzzleVideoCli : AlgorithmVideoCli {
    bool code = false;  ///< --code: the search loop beside one search
    CLI::Option* code_opt = nullptr;
    std::string questions = "none";  ///< --questions on|none
    CLI::Option* questions_opt = nullptr;
    std::string timeline_json;  ///< --timeline-json PATH; empty: none
    CLI::Option* timeline_json_opt = nullptr;
};

/// --questions: on or none; anything else throws Error(input) naming it.
[[nodiscard]] bool puzzle_questions_of(const PuzzleVideoCli& v);

/// Registers the video options on `cmd`.
void add_puzzle_video_options(CLI::App& cmd, PuzzleVideoCli& v);

/// Throws Error(input) naming the first video option given although `mode` (--solve, --json)
/// prints text instead.
void refuse_video_options(const PuzzleVideoCli& v, const std::string& mode);

/// How `collide puzzle` makes its video when neither --solve nor --json is given. collide-draw
/// draws it (puzzle_video.hpp); `collide`, which links no renderer, hands the command line to
/// collide-draw in `check`, before any search runs.
struct PuzzleVideoMaker {
    /// Checks every video option and the destination before any search. Throws Error(input)
    /// naming the option.
    std::function<void(const PuzzleVideoCli&)> check;
    /// Draws the video of `results` (one or two solved searches of `start`).
    std::function<void(const puzzle::Board& start, const std::vector<puzzle::SearchResult>& results,
                       const PuzzleVideoCli&)>
        draw;
};

}  // namespace collide::app
