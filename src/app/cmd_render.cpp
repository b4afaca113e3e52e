/// `collide render` (a video) and `collide thumbnail` (one frame as PNG): read the options,
/// validate everything (scene, options, destination) before anything is rendered, run the frame
/// pipeline, print one summary line on stdout.

#include <fmt/core.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <variant>

#include "cli_numbers.hpp"
#include "cli_types.hpp"
#include "collide/error.hpp"
#include "collide/io/file.hpp"
#include "collide/printable.hpp"
#include "collide/scene/load.hpp"
#include "collide/show/sphere_camera.hpp"
#include "collide/sim/queue_view.hpp"
#include "collide/video/output.hpp"
#include "collide/video/video_writer.hpp"
#include "commands.hpp"
#include "font_search.hpp"
#include "interrupt.hpp"
#include "json_output.hpp"
#include "pipeline.hpp"
#include "progress.hpp"
#include "render_plan.hpp"
#include "replay_plan.hpp"
#include "subtitle_options.hpp"
#include "video_options.hpp"
#include "work_limits.hpp"

namespace collide::app {

namespace {

/// Raw option values as CLI11 stores them; `resolve` turns the ones given into a RenderRequest.
struct CliValues {
    std::string scene;
    VideoCli video;  ///< -o, --format, -q, --size, --fps, --at, --last-frame, --theme, ...
    std::string mode = "both";
    std::string camera = "fixed";
    CLI::Option* camera_opt = nullptr;
    std::string projection = "ortho";
    CLI::Option* projection_opt = nullptr;
    double slab = 0.0;
    CLI::Option* slab_opt = nullptr;
    double duration = 0.0;
    double speed = 0.0;
    std::string dt;  ///< --dt: one step, or a list (parse_dt_list)
    std::string engine = "fast";
    std::string pq = "binary";
    std::string td_detect = "all-pairs";
    std::string color;
    std::string overlays;
    std::string layout_json;
    std::string timeline_json;
    std::string replay;
    std::string questions;
    bool no_intro = false;
    bool no_epilogue = false;
    bool code = false;
    bool trails = true;
    std::string gl = "auto";
    std::string dump_rgba;
    bool no_limits = false;
    std::string queue;  ///< --queue [K]: the K, or empty for the default
    double slow_motion = 1.0;
    bool json = false;  ///< --json: the summary as JSON
    std::uint64_t seed = 0;
    CLI::Option* seed_opt = nullptr;

    // Options whose absence means "take the scene hint or the default".
    CLI::Option* duration_opt = nullptr;
    CLI::Option* speed_opt = nullptr;
    CLI::Option* dt_opt = nullptr;
    CLI::Option* color_opt = nullptr;
    CLI::Option* overlays_opt = nullptr;
    CLI::Option* layout_json_opt = nullptr;
    CLI::Option* timeline_json_opt = nullptr;
    CLI::Option* replay_opt = nullptr;
    CLI::Option* questions_opt = nullptr;
    CLI::Option* trails_opt = nullptr;
    CLI::Option* queue_opt = nullptr;
    CLI::Option* slow_motion_opt = nullptr;
};

template <typename T>
std::optional<T> if_given(const CLI::Option* option, const T& value) {
    if (option == nullptr || option->count() == 0) return std::nullopt;
    return value;
}

/// The --gl backend, checked against this build and against --preview (which renders through
/// GLFW: one GL implementation per process, docs/renderer.md "Preview"). Throws Error (input).
render::Backend gl_backend_of(const CliValues& v) {
    const render::Backend backend = render::parse_backend(v.gl, "--gl");
    if (!render::is_available(backend)) {
        std::string available;
        for (const render::Backend b : render::available_backends()) {
            available += (available.empty() ? "" : ", ") + std::string(render::backend_name(b));
        }
        throw_option_error("--gl", v.gl,
                           "a backend this collide was built with (" + available + ")");
    }
    if (v.video.preview && backend != render::Backend::automatic &&
        backend != render::Backend::glfw) {
        throw_option_error("--gl", "'" + v.gl +
                                       "' beside --preview: --preview renders the frames through "
                                       "glfw (one GL implementation for the frames and the "
                                       "window); drop --gl or --preview");
    }
    return backend;
}

/// The request as typed, with the names (--engine, --pq, --td-detect) parsed into their types.
/// Throws Error(input) naming the first bad one.
RenderRequest request_of(const CliValues& v, bool still) {
    RenderRequest r;
    r.scene = v.scene;
    r.output = if_given(v.video.output_opt, v.video.output);
    r.mode = v.mode;
    r.camera = if_given(v.camera_opt, v.camera);
    r.slab = if_given(v.slab_opt, v.slab);
    r.projection = if_given(v.projection_opt, v.projection);
    r.quality = if_given(v.video.quality_opt, v.video.quality);
    r.size = if_given(v.video.size_opt, v.video.size);
    r.fps = if_given(v.video.fps_opt, v.video.fps);
    r.duration = if_given(v.duration_opt, v.duration);
    r.speed = if_given(v.speed_opt, v.speed);
    if (v.dt_opt != nullptr && v.dt_opt->count() > 0) {
        if (v.dt.empty()) {
            r.dt = 0.0;  // as a number option reads "" (refused below as no positive step)
        } else if (v.dt.find(',') == std::string::npos) {
            // One step, converted (and refused) exactly as a number option is.
            double dt = 0.0;
            if (!CLI::detail::lexical_cast(v.dt, dt))
                throw CLI::ConversionError("--dt", std::vector<std::string>{v.dt});
            r.dt = dt;
        } else {
            r.dt_list = parse_dt_list(v.dt, "--dt");
        }
    }
    r.at = if_given(v.video.at_opt, v.video.at);
    r.engine = parse_event_engine_kind(v.engine, "--engine");
    r.pq = pq::parse_queue_kind(v.pq, "--pq");  // a bad --pq is refused even for the fast engine
    r.td_detect = parse_overlap_detection(v.td_detect, "--td-detect");
    r.color = if_given(v.color_opt, v.color);
    r.trails = if_given(v.trails_opt, v.trails);
    r.overlays = if_given(v.overlays_opt, v.overlays);
    r.theme = if_given(v.video.theme_opt, v.video.theme);
    r.layout_json = if_given(v.layout_json_opt, v.layout_json);
    r.timeline_json = if_given(v.timeline_json_opt, v.timeline_json);
    r.replay = if_given(v.replay_opt, v.replay);
    r.questions = if_given(v.questions_opt, v.questions);
    r.no_intro = v.no_intro;
    r.no_epilogue = v.no_epilogue;
    r.format = if_given(v.video.format_opt, v.video.format);
    r.last_frame = v.video.last_frame;
    r.still = still;
    r.no_limits = v.no_limits;
    if (v.queue_opt != nullptr && v.queue_opt->count() > 0) {
        r.queue = v.queue.empty() ? default_queue_events
                                  : static_cast<int>(parse_whole_number(v.queue, "--queue", 1,
                                                                        sim::max_watched_events));
    }
    r.slow_motion = if_given(v.slow_motion_opt, v.slow_motion);
    r.code = v.code;
    r.font = v.video.font;
    return r;
}

/// The options `render` and `thumbnail` share.
void add_shared_options(CLI::App& cmd, CliValues& v, bool video) {
    v.seed_opt = add_whole_option(cmd, "--seed", v.seed, 0, UINT64_MAX,
                                  "Seed for the scene's random discs ([[generate]] block i gets "
                                  "N + i; default: the scene's)");
    cmd.add_option("scene", v.scene,
                   "Scene: a built-in name (see `collide scenes`), a .toml or an algs4 .txt file")
        ->required()
        ->type_name("SCENE");
    VideoOptionSet set;
    set.stem = "<scene>";
    set.size_example = "e.g. 640x360";
    set.video = video;
    if (!video) set.at_help = "Simulation time of the frame (default: the video's last frame)";
    set.preview = true;
    set.theme_help = "default: scene hint, else dark";
    set.subtitles = true;
    add_video_options(cmd, v.video, set);
    cmd.add_option("--mode", v.mode, "both (time-driven left, event-driven right), event or time")
        ->capture_default_str()
        ->type_name("{both,event,time}");
    v.camera_opt = cmd.add_option("--camera", v.camera,
                                  "3D scenes: fixed, or orbit (the view turns slowly round the "
                                  "box, once every 40 s of video; default: scene hint, else fixed)")
                       ->type_name("{fixed,orbit}");
    v.projection_opt =
        cmd.add_option("--projection", v.projection,
                       "3D scenes: ortho (parallel rays: every sphere as large as it is) or "
                       "perspective (an eye near the box: near spheres larger, edges converge; "
                       "default: scene hint, else ortho)")
            ->type_name("{ortho,perspective}");
    v.slab_opt = cmd.add_option("--slab", v.slab,
                                "3D scenes: show only a slice W box units thick through the box's "
                                "centre, facing the camera (the inside of a dense system; default: "
                                "scene hint, else every sphere)");
    v.duration_opt =
        cmd.add_option("--duration", v.duration, "Seconds of video (default: scene hint, else 10)");
    v.speed_opt = cmd.add_option(
        "--speed", v.speed,
        "Simulation time per second of video (default: scene hint, else a typical disc "
        "crosses the box in 10 s)");
    v.dt_opt =
        cmd.add_option("--dt", v.dt,
                       "Time-driven time step (default: scene hint, else the video's speed "
                       "/ 30, the same at every -q); a list of 2 to 4 steps (0.01,0.02,0.04) "
                       "puts one time-driven panel per step beside the event-driven one")
            ->type_name("FLOAT");
    cmd.add_option("--engine", v.engine, "Event-driven engine: fast or classic")
        ->capture_default_str()
        ->type_name("{fast,classic}");
    cmd.add_option("--pq", v.pq,
                   "Classic engine's queue: unordered, ordered, binary, dary:D or indexed")
        ->capture_default_str()
        ->type_name(queue_kind_type);
    cmd.add_option("--td-detect", v.td_detect, "Time-driven overlap checks: all-pairs or grid")
        ->capture_default_str()
        ->type_name("{all-pairs,grid}");
    v.color_opt =
        cmd.add_option("--color", v.color,
                       "Disc colours: scene, speed, mass or tag (default: scene hint, else scene)")
            ->type_name("{scene,speed,mass,tag}");
    v.overlays_opt =
        cmd.add_option(
               "--overlays", v.overlays,
               "Text around the boxes: lesson (titles, a few figures, the cost graphic, captions; "
               "default), full (every counter and plot) or none (discs only)")
            ->type_name("{lesson,full,none}");
    v.layout_json_opt = cmd.add_option("--layout-json", v.layout_json,
                                       "Also write the frame's rectangles (panels, boxes, text "
                                       "lines with pixel heights) as JSON")
                            ->type_name("PATH");
    v.queue_opt = cmd.add_option("--queue", v.queue,
                                 "Show the event-driven engine's queue: its next K (default 5, "
                                 "at most 20) collisions in the box, its top levels under it "
                                 "(after the scene: `render gas --queue`)")
                      ->expected(0, 1)
                      ->type_name("[K]");
    cmd.add_flag(
        "--code", v.code,
        "With --queue: the event-driven loop's pseudocode beside the boxes, the line under "
        "way marked; each pop walks its lines (default --slow-motion 16)");
    v.slow_motion_opt = cmd.add_option(
        "--slow-motion", v.slow_motion,
        "Play F times slower than --speed (or the scene's pace), e.g. 4 to follow single events");
    v.trails_opt = cmd.add_flag("--trails,!--no-trails", v.trails,
                                "Trails behind tagged discs (default: scene hint, else on)");
    cmd.add_option("--gl", v.gl,
                   "GL backend: auto (OSMesa where built, else EGL), osmesa, egl (surfaceless, or "
                   "the GPU), egl-device or glfw (needs a display)")
        ->capture_default_str()
        ->type_name("{auto,osmesa,egl,egl-device,glfw}");
    cmd.add_flag("--json", v.json,
                 "Print the summary on stdout as JSON (output, kind, frames, size, fps, bytes, "
                 "times, engines)");
    cmd.add_flag(insist_option, v.no_limits,
                 "Run even when the estimated work (collisions and cell crossings, time-driven "
                 "steps and checks, frames) is beyond the limits of docs/limits.md");
}

/// Everything that can be wrong with the request, found before any frame is drawn (and before
/// the replay search, which may simulate for long: a bad output path is refused at once): the
/// plan `draft` (plan_without_frames) with its frames laid out without replays.
RenderPlan validated_plan(RenderPlan draft, const RenderRequest& request, show::SceneView scene) {
    lay_out_frames(draft, request);
    check_render_work(draft, request, scene);
    // The default directory is ours to create; a user-given one must exist already.
    if (draft.default_output) std::filesystem::create_directories(draft.output.parent_path());
    const bool directory =
        draft.kind == OutputKind::video && draft.format == video::VideoFormat::png_sequence;
    video::check_output_writable(draft.output, directory);
    return draft;
}

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
        out += fmt::format("time-driven {:.2f} s ({} overlap checks)", m.wall_seconds,
                           show::short_count(static_cast<double>(m.overlap_checks)));
    }
    for (const double dt : plan.time_steps) {
        if (plan.mode == RenderMode::event || i >= result.engines.size()) break;
        const Measurements& m = result.engines[i++];
        if (!out.empty()) out += ", ";
        out += fmt::format("time-driven dt = {:g} {:.2f} s ({} overlap checks, {} missed)", dt,
                           m.wall_seconds, show::short_count(static_cast<double>(m.overlap_checks)),
                           m.missed_collisions);
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
void check_distinct_outputs(const RenderPlan& plan, const CliValues& values,
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

/// Options of one dimension's scenes only, given for a scene of the other: refused (exit 2), as
/// the same settings are as the scene's hints, rather than ignored.
void check_dimension_options(const CliValues& values, bool spheres, const std::string& scene) {
    if (!spheres) {
        for (const CLI::Option* option :
             {values.camera_opt, values.projection_opt, values.slab_opt}) {
            if (!given(option)) continue;
            throw_option_error(option->get_name(),
                               fmt::format("for 3D scenes only (the camera of spheres), and '{}' "
                                           "is a 2D scene of discs",
                                           scene));
        }
        return;
    }
    for (const CLI::Option* option : {values.trails_opt, values.replay_opt}) {
        if (!given(option)) continue;
        throw_option_error(
            option == values.trails_opt ? "--trails/--no-trails" : option->get_name(),
            fmt::format("for 2D scenes only, and '{}' is a 3D scene (spheres are "
                        "drawn without trails and their failures are not "
                        "replayed yet)",
                        scene));
    }
}

void run(const CliValues& values, bool still) {
    // Validation: nothing is rendered, and no output file is created, until all of it passes.
    const ProgressMode progress_mode = parse_progress_mode(values.video.progress);
    // From here a signal is a clean stop with one message (main), even while the scene loads.
    InterruptGuard interrupts;
    SceneOptions scene_options;
    if (values.seed_opt != nullptr && values.seed_opt->count() > 0)
        scene_options.seed = values.seed;
    const AnyScene any_scene = [&] {
        const StopAtOnce nothing_written_yet(interrupts);
        return load_any_scene(values.scene, scene_options);
    }();
    // A 3D scene is planned through discs standing in for its spheres (the same pace, speeds
    // and hints) and drawn as spheres (show::SphereCamera).
    const SphereScene* spheres = std::get_if<SphereScene>(&any_scene);
    std::optional<Scene> stand_in;
    if (spheres != nullptr) stand_in = show::stand_in_scene(*spheres);
    const Scene& scene = spheres != nullptr ? *stand_in : std::get<Scene>(any_scene);
    const show::SceneView view =
        spheres != nullptr ? show::SceneView{*spheres, scene} : show::SceneView{scene};
    check_dimension_options(values, spheres != nullptr, values.scene);
    if (spheres != nullptr && values.code)
        throw_option_error("--code",
                           "not for 3D scenes yet: the loop is shown beside the queue "
                           "picture, drawn in 2D");
    if (spheres != nullptr && values.queue_opt != nullptr && values.queue_opt->count() > 0)
        throw_option_error("--queue", "not for 3D scenes yet: the queue picture is drawn in 2D");
    interrupts.throw_if_requested();
    const render::Backend backend = gl_backend_of(values);
    const RenderRequest request = request_of(values, still);
    const RenderPlan draft = plan_without_frames(request, scene);
    const RenderPlan checked = validated_plan(draft, request, view);
    const OutputChoice output{checked.output, checked.format, checked.kind == OutputKind::still,
                              false};
    const SubtitleOutput subtitles = subtitle_output_of(values.video, output);
    const ChapterOutput chapters = chapter_output_of(values.video, output, scene.title);
    const RenderPlan plan = with_replays(draft, request, view, interrupts);
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

    Progress progress(progress_mode, plan.timeline.frame_count());
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
    auto values = std::make_shared<CliValues>();
    CLI::App* cmd = root.add_subcommand(
        "render",
        "Render a teaching video: time-driven (left) and event-driven (right) side by side");
    add_shared_options(*cmd, *values, true);
    // Benchmarks only (scripts/bench_pipeline.sh): the frames as raw RGBA for ffmpeg alone.
    cmd->add_option("--dump-rgba", values->dump_rgba, "")->group("");
    cmd->add_flag("--no-intro", values->no_intro,
                  "No title card: the simulation runs from the first frame (for those who cut "
                  "their own)");
    cmd->add_flag("--no-epilogue", values->no_epilogue,
                  "No summary card at the end: the last frame runs to the end of the video");
    values->replay_opt = cmd->add_option("--replay", values->replay,
                                         "Replay the time-driven panel's failures, zoomed in and "
                                         "slowly: none, first (the default "
                                         "at the lesson level, when the scene fails) or all (each "
                                         "failed step it records, as long "
                                         "as they fit)")
                             ->type_name("{none,first,all}");
    values->questions_opt =
        cmd->add_option("--questions", values->questions,
                        "Ask the scene's questions ([[render.questions]]: the picture stops, the "
                        "class thinks, the engine's answer shows): on (the default, at the "
                        "lesson level) or none")
            ->type_name("{on,none}");
    values->timeline_json_opt =
        cmd->add_option(
               "--timeline-json", values->timeline_json,
               "Also write the video's timeline as JSON: its segments (card, run, hold, replay, "
               "question, reveal, epilogue) with their video and simulation times and captions")
            ->type_name("PATH");
    cmd->footer(
        "Examples:\n"
        "  collide render tunnelling                      # out/tunnelling.mp4, 720p30, side by "
        "side\n"
        "  collide render gas -q l --duration 5 -o gas.mp4\n"
        "  collide render brownian --mode event --color speed --format gif\n"
        "  collide render tunnelling --last-frame         # out/tunnelling.png");
    cmd->callback([values] { run(*values, false); });
}

void add_thumbnail_command(CLI::App& root) {
    auto values = std::make_shared<CliValues>();
    CLI::App* cmd = root.add_subcommand(
        "thumbnail", "Render one frame as a PNG (fast, no video): for READMEs and CI");
    add_shared_options(*cmd, *values, false);
    cmd->footer(
        "Examples:\n"
        "  collide thumbnail gas --at 2.5 -o gas.png --size 480x270\n"
        "  collide thumbnail tunnelling --mode time     # out/tunnelling.png");
    cmd->callback([values] { run(*values, true); });
}

}  // namespace collide::app
