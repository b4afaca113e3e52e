/// `collide render` (a video) and `collide thumbnail` (one frame as PNG), collide-draw's side:
/// the command line checked (render_cli.hpp: scene, options, destination) before anything is
/// rendered, the replays found, the frame pipeline run, one summary line printed on stdout.

#include <fmt/core.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <system_error>

#include "collide/error.hpp"
#include "collide/io/file.hpp"
#include "collide/printable.hpp"
#include "collide/show/collision.hpp"
#include "collide/show/sphere_camera.hpp"
#include "collide/video/output.hpp"
#include "collide/video/video_writer.hpp"
#include "commands.hpp"
#include "interrupt.hpp"
#include "json_output.hpp"
#include "pipeline.hpp"
#include "progress.hpp"
#include "render_cli.hpp"
#include "render_plan.hpp"
#include "replay_plan.hpp"
#include "video_options.hpp"

namespace collide::app {

namespace {

/// The plan `draft` with its frames laid out around the failures it replays: they take
/// simulating (within the work limits validated_plan checked), which a signal stops, and then
/// the signal is what ends the run. Spheres have no replay yet: their flat stand-in's physics
/// is not the video's.
RenderPlan with_replays(RenderPlan draft, const RenderRequest& request, show::SceneView scene,
                        const InterruptGuard& interrupts) {
    if (scene.three_d()) {
        // Nor questions: the engines that answer them run discs.
        if (!draft.lesson.questions.empty()) {
            draft.notices.push_back(
                "render.questions: not asked in a 3D scene yet (the engines answer for discs)");
            draft.lesson.questions.clear();
            draft.lesson.question_cues.clear();
        }
        lay_out_frames(draft, request);
        return draft;
    }
    const ReplayFinder finder = [&](const RenderPlan& plan) {
        try {
            return find_replays(scene.discs(), plan, &interrupts.flag());
        } catch (const Error&) {
            interrupts.throw_if_requested();
            throw;
        }
    };
    lay_out_frames(draft, request, finder);
    try {
        ask_questions(draft, request, scene.discs(), finder, &interrupts.flag());
    } catch (const Error&) {
        interrupts.throw_if_requested();
        throw;
    }
    return draft;
}

/// A file's size in SI units, as `ls --si` and file managers show it: kB = 1000 bytes, MB = 10^6,
/// GB = 10^9 (85,396 bytes is "85.4 kB").
std::string human_size(std::uintmax_t bytes) {
    const auto value = static_cast<double>(bytes);
    if (bytes >= 1'000'000'000) return fmt::format("{:.1f} GB", value / 1e9);
    if (bytes >= 1'000'000) return fmt::format("{:.1f} MB", value / 1e6);
    if (bytes >= 1'000) return fmt::format("{:.1f} kB", value / 1e3);
    return fmt::format("{} B", bytes);
}

std::uintmax_t size_on_disk(const std::filesystem::path& path) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) {
        std::uintmax_t total = 0;
        for (const auto& entry : std::filesystem::directory_iterator(path, error)) {
            if (entry.is_regular_file(error)) total += entry.file_size(error);
        }
        return total;
    }
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    return error ? 0 : size;
}

/// Wall-clock cost of each engine: printed, never drawn (it would break byte-identical output).
std::string engine_costs(const RenderPlan& plan, const PipelineResult& result) {
    std::string out;
    std::size_t i = 0;
    if (plan.mode != RenderMode::event && i < result.engines.size() && plan.time_steps.empty()) {
        const Measurements& m = result.engines[i++];
        out += fmt::format("time-driven {:.2f} s ({})", m.wall_seconds,
                           show::time_driven_work_line(m));
    }
    for (const double dt : plan.time_steps) {
        if (plan.mode == RenderMode::event || i >= result.engines.size()) break;
        const Measurements& m = result.engines[i++];
        if (!out.empty()) out += ", ";
        out += fmt::format("time-driven dt = {:g} {:.2f} s ({}; {} missed)", dt, m.wall_seconds,
                           show::time_driven_work_line(m), m.missed_collisions);
    }
    if (plan.mode != RenderMode::time && i < result.engines.size()) {
        const Measurements& m = result.engines[i];
        if (!out.empty()) out += ", ";
        out += fmt::format(
            "event-driven {:.2f} s ({} collisions)", m.wall_seconds,
            show::short_count(static_cast<double>(m.collisions_pair + m.collisions_wall)));
    }
    return out;
}

/// The video's timeline (--timeline-json): every segment with its video frames and seconds, the
/// simulation times it shows and its caption, in order.
Json timeline_json(const RenderPlan& plan) {
    Json segments = Json::array();
    for (const show::Segment& segment : plan.timeline.segments) {
        segments.push_back(Json{{"kind", show::segment_kind_name(segment.kind)},
                                {"start", segment.start},
                                {"end", segment.end},
                                {"first_frame", segment.first_frame},
                                {"end_frame", segment.end_frame},
                                {"sim_start", plan.clock.time(segment.sim_frame)},
                                {"sim_end", plan.clock.time(segment.last_sim_frame())},
                                {"moves", segment.moves},
                                {"caption", segment.caption}});
    }
    return Json{{"fps", plan.timeline.fps},
                {"frames", plan.timeline.frame_count()},
                {"seconds", static_cast<double>(plan.timeline.frame_count()) / plan.timeline.fps},
                {"speed", plan.speed.speed},
                {"segments", std::move(segments)}};
}

/// The summary as one JSON object (render/thumbnail --json): the same figures as the line.
Json summary_json(const RenderPlan& plan, const PipelineResult& result, double wall_seconds,
                  std::uintmax_t bytes) {
    const bool still = plan.kind == OutputKind::still;
    Json engines = Json::array();
    std::size_t i = 0;
    if (plan.mode != RenderMode::event && i < result.engines.size() && plan.time_steps.empty()) {
        const Measurements& m = result.engines[i++];
        engines.push_back(Json{{"engine", "time-driven"},
                               {"wall_seconds", m.wall_seconds},
                               {"overlap_checks", m.overlap_checks}});
    }
    for (const double dt : plan.time_steps) {
        if (plan.mode == RenderMode::event || i >= result.engines.size()) break;
        const Measurements& m = result.engines[i++];
        engines.push_back(Json{{"engine", "time-driven"},
                               {"dt", dt},
                               {"wall_seconds", m.wall_seconds},
                               {"overlap_checks", m.overlap_checks},
                               {"missed_collisions", m.missed_collisions}});
    }
    if (plan.mode != RenderMode::time && i < result.engines.size()) {
        const Measurements& m = result.engines[i];
        engines.push_back(Json{{"engine", "event-driven"},
                               {"wall_seconds", m.wall_seconds},
                               {"collisions", m.collisions_pair + m.collisions_wall}});
    }
    Json document{{"output", plan.output.string()},
                  {"kind", still ? "png" : std::string(video::to_string(plan.format))},
                  {"width", result.output_width},
                  {"height", result.output_height}};
    if (still) {
        document["frame"] = result.frames - 1;
        document["fps"] = plan.fps;
    } else {
        document["frames"] = result.frames;
        document["fps"] = result.output_fps;
        document["seconds"] = static_cast<double>(result.frames) / plan.fps;
    }
    document["sim_time"] = result.sim_time;
    document["bytes"] = bytes;
    document["wall_seconds"] = wall_seconds;
    document["engines"] = std::move(engines);
    return document;
}

/// The summary line on `out`, or with `json` the JSON object on stdout (--json).
void print_summary(const RenderPlan& plan, const PipelineResult& result, double wall_seconds,
                   std::FILE* out, bool json) {
    const std::uintmax_t bytes = size_on_disk(plan.output);
    if (json) {
        std::fputs(json_text(summary_json(plan, result, wall_seconds, bytes)).c_str(), stdout);
        return;
    }
    if (plan.kind == OutputKind::still) {
        std::fprintf(out, "%s: %dx%d PNG at t = %.6g (%s), %s, in %.1f s; engines: %s\n",
                     printable_text(plan.output.string()).c_str(), result.output_width,
                     result.output_height, result.sim_time,
                     fmt::format("frame {} of a {} fps video", result.frames - 1, plan.fps).c_str(),
                     human_size(bytes).c_str(), wall_seconds, engine_costs(plan, result).c_str());
        return;
    }
    const double seconds = static_cast<double>(result.frames) / plan.fps;
    std::fprintf(
        out,
        "%s: %.2f s of video, %lld frames, %dx%d @ %g fps, %s, rendered in %.1f s (%.1f fps); "
        "simulation time 0..%.6g; engines: %s\n",
        printable_text(plan.output.string()).c_str(), seconds,
        static_cast<long long>(result.frames), result.output_width, result.output_height,
        result.output_fps, human_size(bytes).c_str(), wall_seconds,
        wall_seconds > 0.0 ? static_cast<double>(result.frames) / wall_seconds : 0.0,
        result.sim_time, engine_costs(plan, result).c_str());
}

/// The run's outputs must be files of their own (after links), the layout outside a directory
/// of frames. Throws Error(input) naming both.
void check_distinct_outputs(const RenderPlan& plan, const RenderCli& values,
                            const SubtitleOutput& subtitles, const ChapterOutput& chapters) {
    std::vector<io::NamedOutput> outputs;
    const bool directory =
        plan.kind == OutputKind::video && plan.format == video::VideoFormat::png_sequence;
    outputs.push_back({"-o", plan.output, directory});
    if (!plan.layout_json.empty()) outputs.push_back({"--layout-json", plan.layout_json, false});
    if (!plan.timeline_json.empty())
        outputs.push_back({"--timeline-json", plan.timeline_json, false});
    if (!values.dump_rgba.empty()) outputs.push_back({"--dump-rgba", values.dump_rgba, false});
    if (!subtitles.file.empty()) outputs.push_back({"--subtitles-file", subtitles.file, false});
    if (!chapters.file.empty()) outputs.push_back({"--chapters-file", chapters.file, false});
    if (!chapters.slides.empty()) outputs.push_back({"--slides", chapters.slides, true});
    if (!chapters.handout.empty()) outputs.push_back({"--handout", chapters.handout, false});
    if (outputs.size() > 1) io::check_distinct_outputs(outputs);
}

void run(const RenderCli& values, bool still) {
    // From here a signal is a clean stop with one message (main), even while the scene loads.
    InterruptGuard interrupts;
    // Every check of the command line `collide` made before it became this program, again.
    const CheckedRender checked(values, still, interrupts);
    const show::SceneView view = checked.view();
    const render::Backend backend = checked.backend;
    const RenderRequest& request = checked.request;
    const SubtitleOutput& subtitles = checked.subtitles;
    const ChapterOutput& chapters = checked.chapters;
    const RenderPlan plan = with_replays(checked.draft, request, view, interrupts);
    video::set_libav_verbose(values.video.verbose);
    for (const std::string& line : plan.notices) print_notice(line);
    // Its temporary exists from here on, so an unwritable path fails before any frame.
    check_distinct_outputs(plan, values, subtitles, chapters);
    std::optional<io::OutputFile> layout_file;
    if (!plan.layout_json.empty()) {
        layout_file.emplace(plan.layout_json, io::OutputOptions{"--layout-json", true});
    }
    // Known before any frame: its temporary is filled now and put in place after the video.
    std::optional<io::OutputFile> timeline_file;
    if (!plan.timeline_json.empty()) {
        timeline_file.emplace(plan.timeline_json, io::OutputOptions{"--timeline-json", true});
        if (!timeline_file->is_standard_output())
            timeline_file->write(json_text(timeline_json(plan)));
    }
    // Data on standard output (--layout-json -, --timeline-json -) is the only thing there: the
    // summary moves aside, and only one of them can be there.
    const bool layout_on_stdout = layout_file && layout_file->is_standard_output();
    const bool timeline_on_stdout = timeline_file && timeline_file->is_standard_output();
    if (layout_on_stdout && timeline_on_stdout) {
        throw_option_error("--timeline-json",
                           "it and --layout-json - cannot share standard output; write one of "
                           "them to a file");
    }
    const bool data_on_stdout = layout_on_stdout || timeline_on_stdout;
    if (data_on_stdout && values.json) {
        throw_option_error("--json",
                           fmt::format("the JSON summary and {} - cannot share standard "
                                       "output; write the data to a file",
                                       layout_on_stdout ? "--layout-json" : "--timeline-json"));
    }

    Progress progress(checked.progress, plan.timeline.frame_count());
    JobHooks hooks;
    hooks.interrupts = &interrupts;
    hooks.progress = &progress;
    hooks.preview = values.video.preview;
    hooks.backend = backend;
    hooks.notice = print_notice;
    hooks.dump_rgba = values.dump_rgba;
    // A file is whole before the frames: it goes in place with the video, not after it.
    if (timeline_file && !timeline_file->is_standard_output())
        hooks.commit_with.push_back(&*timeline_file);
    PipelineResult result;
    try {
        result = run_render(view, plan, hooks, layout_file ? &*layout_file : nullptr, subtitles,
                            chapters);
    } catch (...) {
        progress.finish();
        interrupts.throw_if_requested();  // whatever noticed it first: one wording, the signal
        throw;
    }
    progress.finish();
    if (timeline_file && timeline_file->is_standard_output()) {
        // On standard output only once the video is whole.
        timeline_file->write(json_text(timeline_json(plan)));
        timeline_file->commit();
    }
    for (const std::string& line : result.notices) print_notice(line);
    print_summary(plan, result, progress.elapsed_seconds(), data_on_stdout ? stderr : stdout,
                  values.json);
}

}  // namespace

void add_render_command(CLI::App& root) {
    auto values = std::make_shared<RenderCli>();
    add_render_options(root, *values, false)->callback([values] { run(*values, false); });
}

void add_thumbnail_command(CLI::App& root) {
    auto values = std::make_shared<RenderCli>();
    add_render_options(root, *values, true)->callback([values] { run(*values, true); });
}

}  // namespace collide::app
