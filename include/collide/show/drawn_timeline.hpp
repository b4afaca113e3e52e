#pragma once
/// \file
/// The timeline of a drawn lesson (`collide heap`, `collide puzzle`) for `--timeline-json`: the
/// lesson runs, except where it asks (`--questions on`): a question segment while the class
/// thinks, a reveal segment while the answer shows. The same segment kinds and frame arithmetic
/// as a collision video's timeline (timeline.hpp), without a simulation clock.

#include <string>
#include <vector>

#include "collide/show/heap_program.hpp"
#include "collide/show/puzzle_program.hpp"
#include "collide/show/timeline.hpp"

namespace collide::show {

/// Where a drawn lesson asks: from `start` seconds of video, `think` seconds on the question,
/// then `reveal` seconds on its answer.
struct AskedStretch {
    double start = 0.0;
    double think = 0.0;
    double reveal = 0.0;
    std::string question;  ///< the question segment's caption
    std::string answer;    ///< the reveal segment's caption
};

/// The segments of a lesson of `duration` seconds at `fps` (frame k shows k / fps; the frames
/// as the video writes them, at least one): run, question, reveal, run, ... in order, each
/// stretch's segments from the first frame at or after its times, none empty. Stretches in time
/// order; one past the end is cut there. Every segment's sim_frame is 0 and `moves` false (a
/// drawn lesson has no simulation clock; run segments move).
[[nodiscard]] Timeline drawn_lesson_timeline(double duration, int fps,
                                             const std::vector<AskedStretch>& asked);

/// Where a heap lesson asks (HeapProgram::questions) and where a puzzle lesson asks
/// (PuzzleProgram::questions), in time order.
[[nodiscard]] std::vector<AskedStretch> asked_stretches(const HeapProgram& lesson);
[[nodiscard]] std::vector<AskedStretch> asked_stretches(const PuzzleProgram& lesson);

}  // namespace collide::show
