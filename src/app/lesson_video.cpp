#include "lesson_video.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "cli_numbers.hpp"
#include "collide/error.hpp"
#include "collide/video/video_writer.hpp"
#include "interrupt.hpp"
#include "render_plan.hpp"

namespace collide::app {

bool given(const CLI::Option* option) {
    return option != nullptr && option->count() > 0;
}

void add_lesson_video_options(CLI::App& cmd, LessonVideoCli& v, std::string_view stem,
                              std::string_view size_note) {
    v.output_opt = cmd.add_option(
        "-o,--output", v.output,
        fmt::format("Output file (default out/{}.mp4, .gif, _frames/ or .png)", stem));
    v.format_opt =
        cmd.add_option("--format", v.format, "mp4 (default), gif, or png (a directory of frames)");
    v.quality_opt =
        cmd.add_option("-q,--quality", v.quality,
                       "l 854x480@15, m 1280x720@30 (default), h 1920x1080@60, k 3840x2160@60");
    v.size_opt = cmd.add_option("--size", v.size,
                                fmt::format("Frame size WxH, overrides -q ({})", size_note));
    // Decimal digits only, as `render --fps` (CLI11 alone reads 010 as octal, 0x1E as hex).
    v.fps_opt =
        add_whole_option(cmd, "--fps", v.fps, 1, max_fps, "Frames per second, overrides -q");
    v.last_frame_opt = cmd.add_flag(
        "--last-frame", v.last_frame,
        fmt::format("Write only the final frame, as a PNG (-o FILE.png, default out/{}.png)",
                    stem));
    v.at_opt = cmd.add_option("--at", v.at,
                              fmt::format("Write only the frame at this many seconds of video, as "
                                          "a PNG (a still for slides; -o FILE.png, default "
                                          "out/{}.png)",
                                          stem));
    cmd.add_option("--progress", v.progress,
                   "Progress on stderr: auto (bar on a terminal), bar, json or none")
        ->capture_default_str();
    cmd.add_flag("--verbose", v.verbose, "Show the encoder's own log");
}

LessonOutput lesson_output_of(const LessonVideoCli& v, std::string_view stem) {
    const auto if_given = [](const CLI::Option* option, const std::string& value) {
        return given(option) ? std::optional(value) : std::nullopt;
    };
    return lesson_output(if_given(v.format_opt, v.format), if_given(v.output_opt, v.output),
                         v.last_frame || given(v.at_opt), stem);
}

LessonGeometry lesson_geometry_of(const LessonVideoCli& v, FrameSize minimum,
                                  std::string_view what_stays_legible) {
    const QualityPreset preset = quality_preset(v.quality, "-q");
    LessonGeometry g{preset.width, preset.height, preset.fps};
    if (given(v.size_opt)) {
        const FrameSize size = parse_frame_size(v.size, "--size");
        g.width = size.width;
        g.height = size.height;
    }
    if (g.width < minimum.width || g.height < minimum.height) {
        throw_option_error(
            given(v.size_opt) ? "--size" : "-q",
            fmt::format("{}x{} is too small for {}; at least {}x{}", g.width, g.height,
                        what_stays_legible, minimum.width, minimum.height));
    }
    if (given(v.fps_opt)) g.fps = checked_fps(v.fps);
    return g;
}

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
