#pragma once
// The video loop shared by the drawn lessons (`collide heap`, `collide puzzle`): a picture that is
// a function of time, encoded frame by frame through the one video writer.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "algorithm_options.hpp"
#include "collide/cue.hpp"
#include "collide/image.hpp"
#include "collide/io/file.hpp"
#include "collide/show/timeline.hpp"
#include "progress.hpp"
#include "render_plan.hpp"
#include "subtitle_options.hpp"
#include "video_options.hpp"

namespace collide::app {

/// Frame size and rate of a lesson video (-q, --size, --fps resolved).
struct AlgorithmVideoGeometry {
    int width = 1280;
    int height = 720;
    int fps = 30;
};

/// Where and in which format the lesson goes (resolve_output of what was given).
[[nodiscard]] OutputChoice algorithm_video_output_of(const AlgorithmVideoCli& v,
                                                     std::string_view stem);

/// -q, then --size and --fps when given. A frame smaller than `minimum` (when not 0x0) is
/// refused naming --size or -q, saying it is too small for `what_stays_legible`.
[[nodiscard]] AlgorithmVideoGeometry algorithm_video_geometry_of(
    const AlgorithmVideoCli& v, FrameSize minimum = {}, std::string_view what_stays_legible = {});

/// Where a drawn lesson of a known duration goes, resolved and checked before anything is drawn.
struct AlgorithmVideoDestination {
    OutputChoice output;
    SubtitleOutput subtitles;
    ChapterOutput chapters;
    double still_time = 0.0;  ///< the time a still shows: --at, else the end
};

/// The set-up `collide heap` and `collide puzzle` share, in this order: --at refused outside
/// 0..duration; the output (default path under out/, named after `stem`), its subtitles and
/// chapters (`title`: the chapters' title); the default path's folder created, the destination
/// checked writable. (libav's verbosity is the drawing program's to set: `collide` runs this
/// and links no encoder.)
[[nodiscard]] AlgorithmVideoDestination algorithm_video_destination_of(const AlgorithmVideoCli& v,
                                                                       std::string_view stem,
                                                                       double duration,
                                                                       const std::string& title);

/// The checks of `--timeline-json PATH` (open_timeline_json's, without opening it): refused
/// (Error(input) naming --timeline-json) for a still, for standard output, and for a path that
/// is also another output of the run; nothing to check when `path` is empty.
void check_timeline_json(const std::string& path, const AlgorithmVideoDestination& destination);

/// `--timeline-json PATH` of a drawn lesson: the file opened (its temporary beside PATH) and
/// filled with `timeline` as JSON (drawn_timeline_json), to be committed with the video
/// (write_algorithm_video's `commit_with`); none when `path` is empty. Refused (Error(input)
/// naming --timeline-json) for a still, for standard output, and for a path that is also
/// another output of the run.
[[nodiscard]] std::optional<io::OutputFile> open_timeline_json(
    const std::string& path, const AlgorithmVideoDestination& destination,
    const show::Timeline& timeline);

/// A drawn lesson's timeline as JSON text: fps, frames, seconds and its segments (kind, start,
/// end, first_frame, end_frame, caption).
[[nodiscard]] std::string drawn_timeline_json(const show::Timeline& timeline);

/// What was written, for the command's summary line.
struct AlgorithmVideoSummary {
    std::int64_t frames = 0;
    int width = 0;
    int height = 0;
    double fps = 0.0;
};

/// A drawn lesson's picture at `t` seconds of video, drawn into `frame` (sized by the drawing).
using AlgorithmFrameDraw = std::function<void(double t, Image& frame)>;

/// Writes the lesson through the video job (video_job.hpp): a video of `duration` seconds (at
/// least one frame, frame k showing time k / fps) or, for output.still, the one frame showing
/// `still_time` as a PNG. Ctrl-C stops it between frames; the destination is only replaced once
/// the output is whole.
/// `subtitles` and `cues` (videos only): the lesson's step captions as a subtitle track and/or
/// a sidecar file (video_job.hpp); `chapters`: where the chapters go (the MP4, a chapters file
/// and/or a slide folder): `chapter_list` when given (a heap video's, one per operation), else
/// one per step caption (show::chapters_from_cues). `commit_with`: a file that goes in place
/// with the video (--timeline-json), or is discarded with it.
AlgorithmVideoSummary write_algorithm_video(
    const OutputChoice& output, const AlgorithmVideoGeometry& geometry, ProgressMode progress_mode,
    double duration, double still_time, const AlgorithmFrameDraw& draw,
    const SubtitleOutput& subtitles = {}, const Cues& cues = {}, const ChapterOutput& chapters = {},
    const std::optional<Chapters>& chapter_list = std::nullopt,
    io::OutputFile* commit_with = nullptr);

}  // namespace collide::app
