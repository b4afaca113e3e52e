/// `collide heap`: animated priority-queue operations for the first half of the lecture (arrays,
/// binary and d-ary heaps, the indexed heap's increase-key, heapsort), several implementations
/// side by side, to MP4, GIF, a PNG sequence or one PNG. Validates everything (operations,
/// options, legibility, destination) before anything is drawn, then renders every frame from
/// the animation model (collide/sim/pq/heap_lesson.hpp) through HeapRenderer into the same
/// VideoWriter as `collide render`.

#include <fmt/core.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "collide/error.hpp"
#include "collide/render/heap_view.hpp"
#include "collide/sim/pq/heap_lesson.hpp"
#include "collide/video/output.hpp"
#include "collide/video/png.hpp"
#include "collide/video/video_writer.hpp"
#include "commands.hpp"
#include "heap_frames.hpp"
#include "lesson_video.hpp"
#include "progress.hpp"
#include "render_plan.hpp"

namespace collide::app {

namespace {

/// Raw option values as CLI11 stores them.
struct HeapCli {
    std::string ops;
    std::string sort;
    std::vector<std::string> impls;
    bool min = false;
    int index_base = 1;
    double pace = 0.8;
    std::string output;
    std::string format;
    std::string quality = "m";
    std::string size;
    int fps = 30;
    bool last_frame = false;
    double at = 0.0;
    std::string progress = "auto";
    std::string theme = "dark";
    bool verbose = false;

    CLI::Option* ops_opt = nullptr;
    CLI::Option* sort_opt = nullptr;
    CLI::Option* impl_opt = nullptr;
    CLI::Option* output_opt = nullptr;
    CLI::Option* format_opt = nullptr;
    CLI::Option* size_opt = nullptr;
    CLI::Option* fps_opt = nullptr;
    CLI::Option* at_opt = nullptr;
};

bool given(const CLI::Option* option) {
    return option != nullptr && option->count() > 0;
}

/// Seconds per step a class can follow: 0.8 s (a slide, then a moment to see where it landed).
pq::LessonPacing pacing_of(double pace) {
    if (!std::isfinite(pace) || pace <= 0.0 || pace > 60.0)
        throw_option_error("--pace", fmt::format("{}", pace), "(0, 60] seconds per step");
    pq::LessonPacing pacing;
    pacing.pace = pace;
    pacing.pause = 0.6 * pace;
    pacing.intro = std::max(1.0, 1.5 * pace);
    pacing.outro = std::max(2.5, 3.0 * pace);
    return pacing;
}

pq::LessonTimeline timeline_of(const HeapCli& v) {
    if (given(v.ops_opt) == given(v.sort_opt))
        throw_option_error("--ops", "give either --ops \"P Q E * ...\" or --sort \"S O R T ...\"");
    if (v.index_base != 0 && v.index_base != 1)
        throw_option_error("--index-base", std::to_string(v.index_base), "0 or 1");
    const auto orientation = v.min ? pq::Orientation::min : pq::Orientation::max;
    const pq::LessonPacing pacing = pacing_of(v.pace);
    if (given(v.sort_opt)) {
        if (given(v.impl_opt))
            throw_option_error("--impl", "--sort is heapsort on a binary heap; leave --impl out");
        const std::vector<pq::TraceKey> keys = pq::parse_sort_keys(v.sort, "--sort");
        return pq::LessonTimeline::heapsort(keys, orientation, v.index_base, pacing);
    }
    const std::vector<pq::LessonOp> ops = pq::parse_lesson_ops(v.ops, "--ops");
    std::vector<pq::QueueKind> kinds;
    for (const std::string& impl : v.impls) kinds.push_back(pq::parse_queue_kind(impl, "--impl"));
    if (kinds.empty()) kinds.push_back({pq::QueueFamily::binary, 2});
    if (kinds.size() > render::max_heap_panels) {
        throw_option_error("--impl", fmt::format("at most {} implementations side by side, got {}",
                                                 render::max_heap_panels, kinds.size()));
    }
    return pq::LessonTimeline::operations(ops, kinds, orientation, v.index_base, pacing);
}

/// Refuses a lesson whose queue holds more keys than the frame can show legibly.
void check_legible(const pq::LessonTimeline& timeline, const HeapCli& v) {
    const std::size_t panels = timeline.panels().size();
    const std::size_t limit = render::max_legible_keys(panels);
    if (timeline.capacity() <= limit) return;
    throw_option_error(
        given(v.sort_opt) ? "--sort" : "--ops",
        fmt::format("the queue holds up to {} keys at once, but at most {} can be drawn "
                    "legibly with {} panel{} side by side (keys over ~14 px tall at "
                    "854x480); use fewer keys{}",
                    timeline.capacity(), limit, panels, panels == 1 ? "" : "s",
                    panels > 1 ? " or fewer implementations" : ""));
}

LessonOutput output_of(const HeapCli& v) {
    const auto if_given = [](const CLI::Option* option, const std::string& value) {
        return given(option) ? std::optional(value) : std::nullopt;
    };
    return lesson_output(if_given(v.format_opt, v.format), if_given(v.output_opt, v.output),
                         v.last_frame || given(v.at_opt), "heap");
}

struct FrameGeometry {
    int width = 1280;
    int height = 720;
    int fps = 30;
};

FrameGeometry geometry_of(const HeapCli& v) {
    const QualityPreset preset = quality_preset(v.quality, "-q");
    FrameGeometry g{preset.width, preset.height, preset.fps};
    if (given(v.size_opt)) {
        const FrameSize size = parse_frame_size(v.size, "--size");
        g.width = size.width;
        g.height = size.height;
    }
    if (given(v.fps_opt)) g.fps = checked_fps(v.fps);
    return g;
}

std::string lesson_name(const pq::LessonTimeline& timeline) {
    std::string out;
    for (const pq::LessonPanel& p : timeline.panels()) out += (out.empty() ? "" : ", ") + p.title;
    return out;
}

void run(const HeapCli& v) {
    // Validation: nothing is drawn, and no file is created, until all of it passes.
    const ProgressMode progress_mode = parse_progress_mode(v.progress);
    const render::Theme theme = render::parse_theme(v.theme, "--theme");
    const pq::LessonTimeline timeline = timeline_of(v);
    check_legible(timeline, v);
    const FrameGeometry geometry = geometry_of(v);
    if (given(v.at_opt) && !(v.at >= 0.0 && v.at <= timeline.duration())) {
        throw_option_error(
            "--at", fmt::format("{}", v.at),
            fmt::format("a time within the video, 0..{:.2f} s", timeline.duration()));
    }
    const LessonOutput output = output_of(v);
    if (output.default_path) std::filesystem::create_directories(output.path.parent_path());
    video::check_output_writable(
        output.path, !output.still && output.format == video::VideoFormat::png_sequence);
    video::set_libav_verbose(v.verbose);

    HeapShow show;
    show.min = v.min;
    show.sort = given(v.sort_opt);
    show.index_base = v.index_base;
    render::HeapViewConfig config;
    config.width = geometry.width;
    config.height = geometry.height;
    config.widest_key = widest_key(timeline);
    config.theme = theme;
    render::HeapRenderer renderer(config, render::Backend::automatic, print_notice);

    if (output.still) {
        const double t = given(v.at_opt) ? v.at : timeline.duration();
        const Image image = renderer.render(heap_frame_at(timeline, show, t));
        video::write_png(image, output.path);
        std::printf("%s: %dx%d PNG at %.2f s of a %.2f s video of %s\n",
                    output.path.string().c_str(), geometry.width, geometry.height, t,
                    timeline.duration(), lesson_name(timeline).c_str());
        return;
    }

    const LessonVideoSummary written = write_lesson_video(
        output, {geometry.width, geometry.height, geometry.fps}, progress_mode, timeline.duration(),
        [&](double t, Image& frame) { renderer.render(heap_frame_at(timeline, show, t), frame); });
    std::printf("%s: %.2f s of video, %lld frames, %dx%d @ %g fps, %s, %zu operations\n",
                output.path.string().c_str(), static_cast<double>(written.frames) / geometry.fps,
                static_cast<long long>(written.frames), written.width, written.height, written.fps,
                lesson_name(timeline).c_str(), timeline.op_labels().size());
}

}  // namespace

void add_heap_command(CLI::App& root) {
    auto v = std::make_shared<HeapCli>();
    CLI::App* cmd = root.add_subcommand(
        "heap",
        "Animate priority-queue operations: heaps as trees over their arrays, step by step");
    v->ops_opt = cmd->add_option(
        "--ops", v->ops,
        "Operations separated by spaces, as in `collide pq`: a key (word or integer) inserts, '*' "
        "removes the max (min), KEY^NEW raises KEY to NEW (increase-key, --impl indexed only)");
    v->sort_opt = cmd->add_option("--sort", v->sort,
                                  "Heapsort these keys instead: heap construction, then sortdown");
    v->impl_opt = cmd->add_option("--impl", v->impls,
                                  "Implementations, one panel each, repeatable or comma-separated: "
                                  "unordered|ordered|binary|dary:D|indexed[:D] (default binary)")
                      ->delimiter(',');
    cmd->add_flag("--min", v->min, "A min-queue ('*' removes the smallest; --sort: descending)");
    cmd->add_option("--index-base", v->index_base,
                    "Index of the first slot: 1 as in the lecture's code, 0 as in its pseudo-code")
        ->capture_default_str();
    cmd->add_option("--pace", v->pace, "Seconds per step (a compare, an exchange, ...)")
        ->capture_default_str();
    v->output_opt = cmd->add_option("-o,--output", v->output,
                                    "Output file (default out/heap.mp4, .gif, _frames/ or .png)");
    v->format_opt = cmd->add_option("--format", v->format,
                                    "mp4 (default), gif, or png (a directory of frames)");
    cmd->add_option("-q,--quality", v->quality,
                    "l 854x480@15, m 1280x720@30 (default), h 1920x1080@60, k 3840x2160@60");
    v->size_opt = cmd->add_option("--size", v->size, "Frame size WxH, overrides -q (e.g. 640x360)");
    v->fps_opt = cmd->add_option("--fps", v->fps, "Frames per second, overrides -q");
    cmd->add_flag("--last-frame", v->last_frame,
                  "Write only the final state, as a PNG (-o FILE.png, default out/heap.png)");
    v->at_opt = cmd->add_option("--at", v->at,
                                "Write only the frame at this many seconds of video, as a PNG "
                                "(a still for slides; -o FILE.png, default out/heap.png)");
    cmd->add_option("--progress", v->progress,
                    "Progress on stderr: auto (bar on a terminal), bar, json or none")
        ->capture_default_str();
    cmd->add_option("--theme", v->theme,
                    "Colours: dark (screens) or light (projectors, print), as in `collide render`")
        ->capture_default_str();
    cmd->add_flag("--verbose", v->verbose, "Show the encoder's own log");
    cmd->footer(
        "Examples:\n"
        "  collide heap --ops \"P Q E * X A M * P L E *\" -o heap.mp4   # the lecture's trace\n"
        "  collide heap --ops \"P Q E * X A M *\" --impl dary:3 --min\n"
        "  collide heap --ops \"P Q E * X A M *\" --impl unordered,ordered,binary\n"
        "  collide heap --ops \"5 9 3 7 * 3^12\" --impl indexed       # increase-key\n"
        "  collide heap --sort \"S O R T E X A M P L E\" -o heapsort.mp4\n"
        "See docs/heap.md for a whole lesson.");
    cmd->callback([v] { run(*v); });
}

}  // namespace collide::app
