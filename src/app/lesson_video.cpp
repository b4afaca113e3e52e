#include "lesson_video.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "collide/video/video_writer.hpp"
#include "interrupt.hpp"

namespace collide::app {

LessonVideoSummary write_lesson_video(const LessonOutput& output, const LessonGeometry& geometry,
                                      ProgressMode progress_mode, double duration,
                                      const std::function<void(double t, Image& frame)>& draw) {
    InterruptGuard interrupts;
    video::VideoOptions options;
    options.path = output.path;
    options.format = output.format;
    options.width = geometry.width;
    options.height = geometry.height;
    options.fps = geometry.fps;
    options.cancel = &interrupts.flag();
    video::VideoWriter writer(options);
    for (const std::string& line : writer.notices()) print_notice(line);

    const auto frames =
        std::max<std::int64_t>(1, std::llround(duration * static_cast<double>(geometry.fps)));
    Progress progress(progress_mode, frames);
    try {
        for (std::int64_t k = 0; k < frames; ++k) {
            interrupts.throw_if_requested();
            const double t = static_cast<double>(k) / geometry.fps;
            Image frame = writer.spare_frame();
            draw(t, frame);
            writer.write(std::move(frame));
            progress.frame_done(t);
        }
        writer.finish();
    } catch (...) {
        progress.finish();
        throw;
    }
    progress.finish();
    return {frames, writer.output_width(), writer.output_height(), writer.output_fps()};
}

}  // namespace collide::app
