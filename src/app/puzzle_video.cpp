/// `collide puzzle`'s video: options resolved as `collide heap` resolves them (the extension
/// decides the format unless --format says it; --last-frame writes one PNG; default paths under
/// out/; --theme dark or light), then every frame from show::PuzzleProgram drawn by PuzzleRenderer
/// into the VideoWriter.

#include "puzzle_video.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "algorithm_video.hpp"
#include "collide/error.hpp"
#include "collide/render/puzzle_view.hpp"
#include "collide/show/drawn_timeline.hpp"
#include "collide/show/puzzle_program.hpp"
#include "collide/show/subtitles.hpp"
#include "collide/video/output.hpp"
#include "collide/video/video_writer.hpp"
#include "font_search.hpp"
#include "progress.hpp"
#include "render_plan.hpp"

namespace collide::app {

namespace {

/// The smallest frame whose text stays legible (the design is laid out for 1280x720).
constexpr FrameSize min_frame{854, 480};

OutputChoice output_of(const PuzzleVideoCli& v) {
    return algorithm_video_output_of(v, "puzzle");
}

AlgorithmVideoGeometry geometry_of(const PuzzleVideoCli& v) {
    return algorithm_video_geometry_of(v, min_frame, "legible boards and counters");
}

}  // namespace

void validate_puzzle_video(const PuzzleVideoCli& v) {
    (void)parse_progress_mode(v.progress);
    (void)puzzle_questions_of(v);
    (void)render::parse_theme(v.theme, "--theme");
    (void)geometry_of(v);
    const OutputChoice output = output_of(v);
    (void)subtitle_output_of(v, output);
    (void)chapter_output_of(v, output, "");
    if (!v.timeline_json.empty() && output.still)
        throw_option_error("--timeline-json", "only for videos (a still has no timeline)");
    if (!output.default_path) {
        video::check_output_writable(
            output.path, !output.still && output.format == video::VideoFormat::png_sequence);
    }
}

void render_puzzle_video(const puzzle::Board& start,
                         const std::vector<puzzle::SearchResult>& results,
                         const PuzzleVideoCli& v) {
    const ProgressMode progress_mode = parse_progress_mode(v.progress);
    const AlgorithmVideoGeometry geometry = geometry_of(v);
    show::PuzzleProgram frames(start, results, v.code);
    frames.ask_questions(puzzle_questions_of(v));
    const AlgorithmVideoDestination destination =
        algorithm_video_destination_of(v, "puzzle", frames.duration(), frames.name());
    video::set_libav_verbose(v.verbose);
    const OutputChoice& output = destination.output;
    std::optional<io::OutputFile> timeline_file =
        open_timeline_json(v.timeline_json, destination,
                           show::drawn_lesson_timeline(frames.duration(), geometry.fps,
                                                       show::asked_stretches(frames)));

    render::PuzzleViewConfig config;
    config.font_path = find_drawing_font(v.font);
    config.width = geometry.width;
    config.height = geometry.height;
    config.theme = render::parse_theme(v.theme, "--theme");
    render::PuzzleRenderer renderer(config, render::Backend::automatic, print_notice);

    const double still_time = destination.still_time;
    const AlgorithmVideoSummary written = write_algorithm_video(
        output, geometry, progress_mode, frames.duration(), still_time,
        [&](double t, Image& frame) { renderer.render(frames.frame_at(t), frame); },
        destination.subtitles,
        output.still ? Cues{} : show::puzzle_subtitle_cues(frames, geometry.fps),
        destination.chapters, std::nullopt, timeline_file ? &*timeline_file : nullptr);
    if (output.still) {
        std::printf("%s: %dx%d PNG at %.2f s of a %.2f s video\n", output.path.string().c_str(),
                    geometry.width, geometry.height, still_time, frames.duration());
        return;
    }
    std::printf("%s: %.2f s of video, %lld frames, %dx%d @ %g fps\n", output.path.string().c_str(),
                static_cast<double>(written.frames) / geometry.fps,
                static_cast<long long>(written.frames), written.width, written.height, written.fps);
}

PuzzleVideoMaker drawn_puzzle_video() {
    return {validate_puzzle_video, render_puzzle_video};
}

}  // namespace collide::app
