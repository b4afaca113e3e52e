#include "render_cli.hpp"

#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "cli_numbers.hpp"
#include "cli_types.hpp"
#include "collide/error.hpp"
#include "collide/show/sphere_camera.hpp"
#include "collide/sim/pq/queue_kind.hpp"
#include "collide/sim/queue_view.hpp"
#include "collide/video/output.hpp"
#include "interrupt.hpp"
#include "subtitle_options.hpp"
#include "work_limits.hpp"

namespace collide::app {

namespace {

template <typename T>
std::optional<T> if_given(const CLI::Option* option, const T& value) {
    if (option == nullptr || option->count() == 0) return std::nullopt;
    return value;
}

/// The --gl backend, checked against this build and against --preview (which renders through
/// GLFW: one GL implementation per process, docs/renderer.md "Preview"). Throws Error (input).
render::Backend gl_backend_of(const RenderCli& v) {
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
RenderRequest request_of(const RenderCli& v, bool still) {
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
void add_shared_options(CLI::App& cmd, RenderCli& v, bool video) {
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

/// Options of one dimension's scenes only, given for a scene of the other: refused (exit 2), as
/// the same settings are as the scene's hints, rather than ignored.
void check_dimension_options(const RenderCli& values, bool spheres, const std::string& scene) {
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

}  // namespace

CLI::App* add_render_options(CLI::App& root, RenderCli& values, bool still) {
    if (still) {
        CLI::App* cmd = root.add_subcommand(
            "thumbnail", "Render one frame as a PNG (fast, no video): for READMEs and CI");
        add_shared_options(*cmd, values, false);
        cmd->footer(
            "Examples:\n"
            "  collide thumbnail gas --at 2.5 -o gas.png --size 480x270\n"
            "  collide thumbnail tunnelling --mode time     # out/tunnelling.png");
        return cmd;
    }
    CLI::App* cmd = root.add_subcommand(
        "render",
        "Render a teaching video: time-driven (left) and event-driven (right) side by side");
    add_shared_options(*cmd, values, true);
    // Benchmarks only (scripts/bench_pipeline.sh): the frames as raw RGBA for ffmpeg alone.
    cmd->add_option("--dump-rgba", values.dump_rgba, "")->group("");
    cmd->add_flag("--no-intro", values.no_intro,
                  "No title card: the simulation runs from the first frame (for those who cut "
                  "their own)");
    cmd->add_flag("--no-epilogue", values.no_epilogue,
                  "No summary card at the end: the last frame runs to the end of the video");
    values.replay_opt = cmd->add_option("--replay", values.replay,
                                        "Replay the time-driven panel's failures, zoomed in and "
                                        "slowly: none, first (the default "
                                        "at the lesson level, when the scene fails) or all (each "
                                        "failed step it records, as long "
                                        "as they fit)")
                            ->type_name("{none,first,all}");
    values.questions_opt =
        cmd->add_option("--questions", values.questions,
                        "Ask the scene's questions ([[render.questions]]: the picture stops, the "
                        "class thinks, the engine's answer shows): on (the default, at the "
                        "lesson level) or none")
            ->type_name("{on,none}");
    values.timeline_json_opt =
        cmd->add_option(
               "--timeline-json", values.timeline_json,
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
    return cmd;
}

CheckedRender::CheckedRender(const RenderCli& values, bool still,
                             const InterruptGuard& interrupts) {
    // Nothing is rendered, and no output file is created, until all of it passes.
    progress = parse_progress_mode(values.video.progress);
    SceneOptions scene_options;
    if (values.seed_opt != nullptr && values.seed_opt->count() > 0)
        scene_options.seed = values.seed;
    {
        // A signal is a clean stop with one message (main), even while the scene loads.
        const StopAtOnce nothing_written_yet(interrupts);
        scene_ = load_any_scene(values.scene, scene_options);
    }
    // A 3D scene is planned through discs standing in for its spheres (the same pace, speeds
    // and hints) and drawn as spheres (show::SphereCamera).
    const SphereScene* spheres = std::get_if<SphereScene>(&scene_);
    if (spheres != nullptr) stand_in_ = show::stand_in_scene(*spheres);
    check_dimension_options(values, spheres != nullptr, values.scene);
    if (spheres != nullptr && values.code)
        throw_option_error("--code",
                           "not for 3D scenes yet: the loop is shown beside the queue "
                           "picture, drawn in 2D");
    if (spheres != nullptr && values.queue_opt != nullptr && values.queue_opt->count() > 0)
        throw_option_error("--queue", "not for 3D scenes yet: the queue picture is drawn in 2D");
    interrupts.throw_if_requested();
    backend = gl_backend_of(values);
    request = request_of(values, still);
    draft = plan_without_frames(request, view().discs());
    const RenderPlan checked = validated_plan(draft, request, view());
    const OutputChoice output{checked.output, checked.format, checked.kind == OutputKind::still,
                              false};
    subtitles = subtitle_output_of(values.video, output);
    chapters = chapter_output_of(values.video, output, view().discs().title);
}

show::SceneView CheckedRender::view() const {
    if (const SphereScene* spheres = std::get_if<SphereScene>(&scene_); spheres != nullptr)
        return show::SceneView{*spheres, *stand_in_};
    return show::SceneView{std::get<Scene>(scene_)};
}

}  // namespace collide::app
