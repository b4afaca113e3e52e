#pragma once
// The video loop shared by the drawn lessons (`collide heap`, `collide puzzle`): a picture that is
// a function of time, encoded frame by frame through the one video writer.

#include <cstdint>
#include <functional>

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
