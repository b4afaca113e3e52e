#pragma once
// The video loop shared by the drawn lessons (`collide heap`, `collide puzzle`): a picture that is
// a function of time, encoded frame by frame through the one video writer.

#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

#include "collide/image.hpp"
#include "progress.hpp"
#include "render_plan.hpp"

namespace collide::app {

/// Frame size and rate of a lesson video (-q, --size, --fps resolved).
struct LessonGeometry {
    int width = 1280;
    int height = 720;
    int fps = 30;
};

/// The video options every drawn lesson takes (-o, --format, -q, --size, --fps, --last-frame,
/// --at, --progress, --verbose), raw as CLI11 stores them.
struct LessonVideoCli {
    std::string output;
    std::string format;
    std::string quality = "m";
    std::string size;
    int fps = 30;
    bool last_frame = false;
    double at = 0.0;
    std::string progress = "auto";
    bool verbose = false;
    std::string font;  ///< --font FILE (empty: find_font's search)

    CLI::Option* output_opt = nullptr;
    CLI::Option* format_opt = nullptr;
    CLI::Option* quality_opt = nullptr;
    CLI::Option* size_opt = nullptr;
    CLI::Option* fps_opt = nullptr;
    CLI::Option* last_frame_opt = nullptr;
    CLI::Option* at_opt = nullptr;
};

/// True when the user gave `option` on the command line.
[[nodiscard]] bool given(const CLI::Option* option);

/// Registers the video options on `cmd`; `stem` names the default outputs (out/STEM.mp4, ...),
/// `size_note` goes into --size's help (e.g. "e.g. 640x360").
void add_lesson_video_options(CLI::App& cmd, LessonVideoCli& v, std::string_view stem,
                              std::string_view size_note);

/// Where and in which format the lesson goes (lesson_output of what was given).
[[nodiscard]] LessonOutput lesson_output_of(const LessonVideoCli& v, std::string_view stem);

/// -q, then --size and --fps when given. A frame smaller than `minimum` (when not 0x0) is
/// refused naming --size or -q, saying it is too small for `what_stays_legible`.
[[nodiscard]] LessonGeometry lesson_geometry_of(const LessonVideoCli& v, FrameSize minimum = {},
                                                std::string_view what_stays_legible = {});

/// What was written, for the command's summary line.
struct LessonVideoSummary {
    std::int64_t frames = 0;
    int width = 0;
    int height = 0;
    double fps = 0.0;
};

/// Encodes `duration` seconds (at least one frame) to `output`: frame k shows time k / fps, drawn
/// into the writer's spare frame by `draw`. Ctrl-C stops it between frames; the destination is
/// only replaced once the video is whole (VideoWriter).
LessonVideoSummary write_lesson_video(const LessonOutput& output, const LessonGeometry& geometry,
                                      ProgressMode progress_mode, double duration,
                                      const std::function<void(double t, Image& frame)>& draw);

}  // namespace collide::app
