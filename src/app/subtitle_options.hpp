#pragma once
/// \file
/// The subtitle options of a video command (--subtitles, --lang, --subtitles-file) checked
/// against its output. Apart from the options' registration (video_options.hpp) because it asks
/// the encoder (collide_video) which languages and sidecar formats exist: the drawing commands
/// use it, `collide` never links it.

#include "render_plan.hpp"
#include "video_job.hpp"
#include "video_options.hpp"

namespace collide::app {

/// --subtitles, --lang and --subtitles-file checked against the output: embedding is the default
/// for an MP4 (other formats have no subtitle track: asking for one there is refused, as is a
/// sidecar for a still). Throws Error(input) naming the option.
[[nodiscard]] SubtitleOutput subtitle_output_of(const VideoCli& v, const OutputChoice& output);

}  // namespace collide::app
