#pragma once
/// \file
/// The subtitle and chapter options of a video command (--subtitles, --lang, --subtitles-file,
/// --chapters, --chapters-file, --slides, --handout) checked
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

/// --chapters, --chapters-file, --slides and --handout checked against the output: chapters go
/// into an MP4 by default; --chapters embed needs an MP4, a chapters file a video and a .vtt name,
/// the slide folder an MP4 and a DIR that is new, empty or an earlier slide folder (checked here,
/// before anything is drawn), a handout a video and a .pdf name. `title`: the slide page's title.
/// Throws Error(input) naming the option.
[[nodiscard]] ChapterOutput chapter_output_of(const VideoCli& v, const OutputChoice& output,
                                              std::string title);

}  // namespace collide::app
