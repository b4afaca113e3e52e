#pragma once
/// \file
/// The drawn lessons' (`collide heap`, `collide puzzle`) video options, registered apart from the
/// video loop (algorithm_video.hpp) so that `collide`, which draws nothing, can parse a lesson's
/// command line too (collide_app_options: no GL, no encoder).

#include <string_view>

#include "cli_fwd.hpp"
#include "video_options.hpp"

namespace collide::app {

/// The lessons' video options are the one set of video options (video_options.hpp).
using AlgorithmVideoCli = VideoCli;

/// Registers the video options of a drawn lesson on `cmd` (video_options.hpp); `stem` names the
/// default outputs (out/STEM.mp4, ...), `size_example` goes into --size's help. Every lesson
/// takes --theme (default dark).
void add_algorithm_video_options(CLI::App& cmd, AlgorithmVideoCli& v, std::string_view stem,
                                 std::string_view size_example);

}  // namespace collide::app
