#pragma once
/// \file
/// A still's timeline (thumbnail, --last-frame): the simulation frames 0..frames-1 of a still
/// only run (no card, hold or summary over them), each with the caption the video shows with
/// that state, so a thumbnail at simulation time T reads what the video reads at T.

#include <cstdint>
#include <string>

#include "collide/show/timeline.hpp"

namespace collide::show {

/// `video`: the video's timeline; `caption`: the scene's caption (shown with the states the
/// video shows only under its card). Beyond the video's last state, its last run's caption.
[[nodiscard]] Timeline still_timeline(const Timeline& video, std::int64_t frames,
                                      const std::string& caption);

}  // namespace collide::show
