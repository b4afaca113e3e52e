#include "render_plan.hpp"

#include <fcntl.h>
#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

#include "collide/error.hpp"
#include "collide/io/file.hpp"
#include "collide/named_values.hpp"
#include "collide/show/collision_program.hpp"
#include "collide/show/still_timeline.hpp"
#include "collide/sim/pq/queue_kind.hpp"
#include "collide/sim/queue_view.hpp"
#include "font_search.hpp"
#include "replay_plan.hpp"
#include "video_options.hpp"

namespace collide::app {

namespace {

constexpr double max_duration = 3600.0;         // an hour of video is far beyond any lesson
constexpr double default_video_seconds = 10.0;  // a scene that names no [render] duration
/// Colour and histogram range in units of the RMS speed: a 2D Maxwell-Boltzmann gas has
/// P(v > 2.5 v_rms) = exp(-6.25) ~ 0.2 %, so almost every disc gets a distinct colour.
constexpr double speed_range_in_rms = 2.5;
/// Relative tolerance for snapping a still's time onto a frame time: far above rounding (1e-16)
/// and far below anything a viewer could see ("dt divides the frame interval":
/// show::divide_tolerance).
constexpr double snap_tolerance = 1e-9;
using show::divide_tolerance;
/// Frames are counted in int64 and their times computed as k * interval: beyond 2^53 neither the
/// index nor the double k is exact (and an unchecked conversion overflows).
constexpr double max_countable_frames = 9007199254740992.0;  // 2^53

bool positive_finite(double x) {
    return std::isfinite(x) && x > 0.0;
}

void require_positive(double value, std::string_view option, std::string_view what) {
    if (!positive_finite(value))
        throw_option_error(option, fmt::format("{}", value), fmt::format("a positive {}", what));
}

std::string lowercase_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

std::string output_stem(const Scene& scene) {
    return scene.name.empty() ? std::string("scene") : scene.name;
}

int choose_fps(const RenderRequest& request, const QualityPreset& preset) {
    return request.fps ? checked_fps(*request.fps) : preset.fps;
}

double choose_duration(const RenderRequest& request, const Scene& scene) {
    const bool from_cli = request.duration.has_value();
    const double duration =
        request.duration.value_or(scene.render.duration.value_or(default_video_seconds));
    const std::string option =
        from_cli ? std::string("--duration") : hint_option(scene.render.duration_at, "duration");
    require_positive(duration, option, "number of seconds");
    if (duration > max_duration)
        throw_option_error(option, fmt::format("{}", duration),
                           fmt::format("at most {} seconds", max_duration));
    return duration;
}

EngineOptions event_engine_options(const RenderRequest& request) {
    EngineOptions options;
    // The event panel's engine: a request built in code could still name the time-driven one.
    options.engine = parse_event_engine_kind(to_string(request.engine), "--engine");
    options.pq = request.pq;
    return options;
}

/// --slow-motion F: the video plays F times slower (frames F times closer in simulation time).
void apply_slow_motion(const RenderRequest& request, RenderPlan& plan) {
    // --code walks each pop through the loop's lines: it needs pops further apart.
    const std::optional<double> factor =
        request.slow_motion
            ? request.slow_motion
            : (request.code ? std::optional<double>(default_code_slow_motion) : std::nullopt);
    if (!factor) return;
    const double f = *factor;
    if (!std::isfinite(f) || f < 1.0 || f > max_slow_motion) {
        throw_option_error("--slow-motion", fmt::format("{}", f),
                           fmt::format("a factor from 1 to {:g} (times slower)", max_slow_motion));
    }
    plan.slow_motion = f;
    plan.speed.speed /= f;
    plan.speed.source += fmt::format(", {:g}x slow motion", f);
}

/// --queue [K]: K upcoming events of the event-driven engine, its queue in a strip (lesson level).
std::size_t queue_events(const RenderRequest& request, const RenderPlan& plan) {
    if (!request.queue) return 0;
    const int k = *request.queue;
    if (k < 1 || k > static_cast<int>(sim::max_watched_events)) {
        throw_option_error("--queue", std::to_string(k),
                           fmt::format("1 to {} upcoming events", sim::max_watched_events));
    }
    if (plan.mode == RenderMode::time) {
        throw_option_error(
            "--queue",
            "the time-driven engine has no event queue to show; use --mode both or event");
    }
    if (!show::level_shows(plan.render.overlays).queue) {
        throw_option_error("--queue",
                           fmt::format("the queue is drawn at the lesson level only, not with "
                                       "--overlays {}",
                                       render::overlay_level_name(plan.render.overlays)));
    }
    return static_cast<std::size_t>(k);
}

/// --code: the event-driven loop beside the queue picture; the lesson level, --queue and a
/// frame of at least min_code_frame_width pixels (checked before --queue, so that the message
/// names the option given).
bool code_of(const RenderRequest& request, const RenderPlan& plan) {
    if (!request.code) return false;
    if (!show::level_shows(plan.render.overlays).queue) {
        throw_option_error("--code",
                           fmt::format("the code is drawn at the lesson level only, not with "
                                       "--overlays {}",
                                       render::overlay_level_name(plan.render.overlays)));
    }
    if (!request.queue) {
        throw_option_error("--code", "shows the event-driven loop beside its queue; add --queue");
    }
    if (plan.width < min_code_frame_width) {
        throw_option_error("--code", fmt::format("needs a frame at least {} pixels wide (-q l or "
                                                 "larger), got {}x{}",
                                                 min_code_frame_width, plan.width, plan.height));
    }
    return true;
}

EngineOptions time_engine_options(const RenderRequest& request, const Scene& scene, double speed,
                                  double interval, std::vector<std::string>& notices) {
    EngineOptions options;
    options.engine = EngineKind::time;
    options.td_detect = request.td_detect;
    const bool from_cli = request.dt.has_value();
    // Without a dt anywhere: the scene's own time scale, so -q and --fps never change the physics.
    options.dt = request.dt.value_or(scene.render.dt.value_or(default_dt(speed)));
    if (!from_cli && !scene.render.dt && !positive_finite(options.dt)) {
        // A speed so small (5e-324) that the step derived from it is 0: name the speed where
        // the user wrote it, not a dt they never gave.
        const std::string speed_option =
            request.speed ? std::string("--speed") : hint_option(scene.render.speed_at, "speed");
        throw_option_error(speed_option,
                           fmt::format("{:g} is too small: the time-driven step it implies "
                                       "(speed / {:g}) is 0; give a larger speed, or a dt",
                                       speed, reference_fps));
    }
    require_positive(options.dt,
                     from_cli ? std::string("--dt") : hint_option(scene.render.dt_at, "dt"),
                     "time step");
    if (options.dt > interval * (1.0 + divide_tolerance)) {
        notices.push_back(
            fmt::format("dt = {:g} is longer than the frame interval {:g}: the time-driven "
                        "panel shows its latest step and changes every {:.3g} frames",
                        options.dt, interval, options.dt / interval));
    } else if (!divides(options.dt, interval)) {
        notices.push_back(
            fmt::format("warning: dt = {:g} does not divide the frame interval {:g}: the "
                        "time-driven panel shows its latest step, up to dt behind the frame time",
                        options.dt, interval));
    }
    return options;
}

/// A --dt list: each step checked (and its notices said) as a single --dt would be; the plan's
/// time_engine takes the smallest (the work limits' estimate is the costliest panel's).
void choose_time_steps(const RenderRequest& request, const Scene& scene, double pace,
                       double interval, RenderPlan& plan, std::vector<std::string>& notices) {
    if (request.dt_list.empty()) return;
    if (plan.mode == RenderMode::event) {
        throw_option_error("--dt",
                           "a list of steps compares time-driven panels, and --mode event shows "
                           "none; drop --mode, or give one --dt");
    }
    RenderRequest one = request;
    for (const double dt : request.dt_list) {
        one.dt = dt;
        const EngineOptions options = time_engine_options(one, scene, pace, interval, notices);
        if (plan.time_steps.empty() || options.dt < plan.time_engine.dt) plan.time_engine = options;
        plan.time_steps.push_back(options.dt);
    }
}

/// Options that cannot be shown beside a --dt list's panels: the queue strip (and the code
/// beside it) needs the frame's width under one event-driven box.
void check_time_steps_shown(const RenderPlan& plan) {
    if (plan.time_steps.empty()) return;
    if (plan.queue_events > 0) {
        throw_option_error("--dt",
                           "a list of steps cannot be shown with --queue (the queue strip "
                           "takes the room of the extra panels); give one --dt");
    }
}

render::RenderConfig render_config(const RenderRequest& request, const Scene& scene, int width,
                                   int height) {
    render::RenderConfig config;
    config.font_path = find_drawing_font(request.font);
    config.width = width;
    config.height = height;
    if (request.color) {
        config.color_mode = render::parse_color_mode(*request.color, "--color");
    } else if (scene.render.color_mode) {
        config.color_mode = *scene.render.color_mode;
    }
    // Fixed ranges for the whole video, so colours and histogram bins mean the same in every frame.
    const double top = std::max(max_speed(scene), speed_range_in_rms * rms_speed(scene));
    config.speed_min = 0.0;
    config.speed_max = top > 0.0 ? top : 1.0;
    if (!scene.discs.empty()) {
        const auto [lightest, heaviest] =
            std::minmax_element(scene.discs.begin(), scene.discs.end(),
                                [](const Disc& a, const Disc& b) { return a.mass < b.mass; });
        config.mass_min = lightest->mass;
        config.mass_max = heaviest->mass;
    }
    config.trails = request.trails.value_or(scene.render.trails.value_or(true));
    if (request.overlays) {
        config.overlays = render::parse_overlay_level(*request.overlays, "--overlays");
    } else if (scene.render.overlays) {
        config.overlays = *scene.render.overlays;
    }
    if (request.theme) {
        config.theme = render::parse_theme(*request.theme, "--theme");
    } else if (scene.render.theme) {
        config.theme = *scene.render.theme;
    }
    config.validate();
    return config;
}

/// What the lesson plan is made of besides the scene, from the options (show::lesson_plan).
show::LessonRequest lesson_request(const RenderRequest& request, const Scene& scene,
                                   const RenderPlan& plan) {
    show::LessonRequest out;
    // The scene's captions are written for its own pace; --speed, --slow-motion and --code's
    // slow motion move them to the moments they describe.
    out.slower = choose_speed(scene, std::nullopt).speed / plan.speed.speed;
    out.scene_duration = scene.render.duration.value_or(default_video_seconds);
    out.level = plan.render.overlays;
    out.duration = plan.duration;
    out.duration_from_cli = request.duration.has_value();
    out.intro = !request.no_intro;
    out.epilogue = !request.no_epilogue;
    out.step_list = !plan.time_steps.empty();
    out.dt = plan.time_engine.dt;
    out.frame_interval = plan.speed.speed / plan.fps;
    out.time_panel = plan.mode != RenderMode::event;
    out.event_panel = plan.mode != RenderMode::time;
    if (request.questions) {
        if (*request.questions != "on" && *request.questions != "none")
            throw_option_error("--questions", *request.questions, "on or none");
        out.questions = *request.questions == "on";
    }
    return out;
}

/// Which failures are replayed: --replay, else the scene's hint, else the first. None where the
/// video cannot show one: no time-driven panel, or not the lesson level (the replay's words and
/// marks are the lesson's).
ReplayChoice replay_choice(const RenderRequest& request, const Scene& scene,
                           const RenderPlan& plan) {
    ReplayChoice choice = scene.render.replay.value_or(ReplayChoice::first);
    if (request.replay) choice = parse_replay_choice(*request.replay, "--replay");
    if (!plan.time_steps.empty() && choice != ReplayChoice::none) {
        // A replay zooms every panel onto one failure: with several steps, each panel fails at
        // its own steps, and the first of one is no moment of the others.
        if (request.replay) {
            throw_option_error("--replay", *request.replay,
                               "none beside a --dt list (each time-driven panel fails at its own "
                               "steps; give one --dt to replay its first failure)");
        }
        return ReplayChoice::none;
    }
    return show::shown_replays(choice, plan.mode != RenderMode::event, plan.render.overlays);
}

/// The simulation frames a video of `video`'s frames shows on `timeline`.
FrameClock simulation_clock(const FrameClock& video, const show::Timeline& timeline) {
    FrameClock simulation = video;
    simulation.count = timeline.sim_frame_count();
    simulation.last_time = static_cast<double>(simulation.count - 1) * simulation.interval;
    return simulation;
}

bool has_replay(const show::Timeline& timeline, std::int64_t sim_frame) {
    return std::any_of(
        timeline.segments.begin(), timeline.segments.end(), [&](const show::Segment& segment) {
            return segment.kind == show::SegmentKind::replay && segment.sim_frame == sim_frame;
        });
}

/// Scene colours too close to the reserved failure colour are shifted (by the renderer); say so.
void check_failure_colors(const Scene& scene, const render::RenderConfig& config,
                          std::vector<std::string>& notices) {
    if (config.color_mode != render::ColorMode::scene) return;
    for (const Disc& disc : scene.discs) {
        if (render::near_failure_color(disc.color)) {
            const Rgb8 c = disc.color;
            const Rgb8 shifted = render::away_from_failure_color(c);
            notices.push_back(fmt::format(
                "disc colour #{:02x}{:02x}{:02x} is too close to the colour reserved for "
                "failures: drawn as #{:02x}{:02x}{:02x}",
                c.r, c.g, c.b, shifted.r, shifted.g, shifted.b));
            return;
        }
    }
}

}  // namespace

int checked_fps(int fps, std::string_view option) {
    if (fps < 1 || fps > max_fps)
        throw_option_error(option, std::to_string(fps),
                           fmt::format("1..{} frames per second", max_fps));
    return fps;
}

OutputChoice resolve_output(const std::optional<std::string>& format,
                            const std::optional<std::string>& output, bool still,
                            std::string_view stem) {
    OutputChoice out;
    const std::filesystem::path dir = default_output_dir;
    out.still = still;
    out.default_path = !output;
    const std::string ext = output ? lowercase_extension(*output) : "";
    if (still) {
        if (format && *format != "png")
            throw_option_error("--format", *format, "png (a single frame is written as png)");
        if (output && ext != ".png")
            throw_option_error("-o", *output, "a .png path (a single frame is a PNG image)");
        out.path = output ? std::filesystem::path(*output) : dir / (std::string(stem) + ".png");
        return out;
    }
    if (format) {
        out.format = video::parse_video_format(*format, "--format");
        // With --format, the path's extension is the user's business, unless it names another
        // format (a .gif written as MP4, or a directory of frames named .mp4, misleads).
        const bool names_a_format = ext == ".mp4" || ext == ".gif" || ext == ".png";
        if (names_a_format && ext != "." + std::string(video::to_string(out.format))) {
            throw_option_error(
                "-o", fmt::format("'{}' ends in {}, but --format is {}", *output, ext, *format));
        }
    } else if (ext == ".mp4") {
        out.format = video::VideoFormat::mp4;
    } else if (ext == ".gif") {
        out.format = video::VideoFormat::gif;
    } else if (ext == ".png") {
        throw_option_error(
            "-o", fmt::format("'{}' is a single image: use --last-frame (or `collide thumbnail`, "
                              "--at) for one frame, or --format png for a directory of frames",
                              *output));
    } else if (output) {
        throw_option_error("-o", *output, "a .mp4 or .gif path (or --format to name the format)");
    }
    // The lean build writes PNG frames only: an MP4 or a GIF is refused before anything is made.
    video::require_format_built(out.format, format ? "--format" : "-o");
    if (output) {
        out.path = *output;
        return out;
    }
    const std::string name(stem);
    switch (out.format) {
        case video::VideoFormat::mp4:
            out.path = dir / (name + ".mp4");
            break;
        case video::VideoFormat::gif:
            out.path = dir / (name + ".gif");
            break;
        case video::VideoFormat::png_sequence:
            out.path = dir / (name + "_frames");
            break;
    }
    return out;
}

std::string hint_option(const std::string& where, std::string_view key) {
    return where.empty() ? fmt::format("scene [render] {}", key) : where;
}

RenderMode parse_render_mode(std::string_view text, std::string_view option) {
    static constexpr std::array<NamedValue<RenderMode>, 3> names{
        {{"both", RenderMode::both}, {"event", RenderMode::event}, {"time", RenderMode::time}}};
    return parse_named(text, option, names);
}

show::CameraMotion parse_camera_motion(std::string_view text, std::string_view option) {
    return parse_named(text, option, camera_motion_names);
}

show::Projection parse_projection(std::string_view text, std::string_view option) {
    static constexpr std::array<NamedValue<show::Projection>, 2> names{
        {{"ortho", show::Projection::orthographic},
         {"perspective", show::Projection::perspective}}};
    return parse_named(text, option, names);
}

QualityPreset quality_preset(std::string_view letter, std::string_view option) {
    if (letter == "l") return {854, 480, 15};
    if (letter == "m") return {1280, 720, 30};
    if (letter == "h") return {1920, 1080, 60};
    if (letter == "k") return {3840, 2160, 60};
    throw_option_error(option, letter, "l (480p15), m (720p30), h (1080p60) or k (2160p60)");
}

FrameSize parse_frame_size(std::string_view text, std::string_view option) {
    const auto bad = [&] {
        throw_option_error(option, text,
                           fmt::format("WIDTHxHEIGHT with each in {}..{}, e.g. 1280x720",
                                       render::min_frame_side, render::max_frame_side));
    };
    const std::size_t x = text.find('x');
    if (x == std::string_view::npos) bad();
    FrameSize size;
    const auto parse = [&](std::string_view part, int& out) {
        const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), out);
        if (part.empty() || error != std::errc{} || end != part.data() + part.size()) bad();
        if (out < render::min_frame_side || out > render::max_frame_side) bad();
    };
    parse(text.substr(0, x), size.width);
    parse(text.substr(x + 1), size.height);
    return size;
}

double rms_speed(const Scene& scene) noexcept {
    if (scene.discs.empty()) return 0.0;
    double sum = 0.0;
    for (const Disc& disc : scene.discs) sum += dot(disc.velocity, disc.velocity);
    return std::sqrt(sum / static_cast<double>(scene.discs.size()));
}

double max_speed(const Scene& scene) noexcept {
    double top = 0.0;
    for (const Disc& disc : scene.discs) top = std::max(top, norm(disc.velocity));
    return top;
}

SpeedChoice choose_speed(const Scene& scene, std::optional<double> cli) {
    if (cli) {
        require_positive(*cli, "--speed", "number of simulation time units per second");
        return {*cli, "--speed", ""};
    }
    if (scene.render.speed) {
        require_positive(*scene.render.speed, hint_option(scene.render.speed_at, "speed"),
                         "number of time units per second");
        return {*scene.render.speed, "scene hint", ""};
    }
    const double typical = rms_speed(scene);
    const double speed = scene.box.width / (crossing_seconds * typical);
    if (!positive_finite(speed)) {
        return {
            1.0, "fallback",
            "nothing moves in this scene: showing 1 simulation time unit per second (set --speed)"};
    }
    return {speed, "derived", ""};
}

FrameClock video_clock(double duration, double speed, int fps) {
    require_positive(duration, "--duration", "number of seconds");
    require_positive(speed, "--speed", "number of simulation time units per second");
    if (fps < 1) throw_option_error("--fps", std::to_string(fps), "at least 1 frame per second");
    if (!(duration * fps < max_countable_frames))
        throw_option_error(
            "--duration",
            fmt::format("{:g} s at {} fps is more frames than can be counted", duration, fps));
    FrameClock clock;
    clock.interval = speed / fps;
    clock.count = std::max<std::int64_t>(1, std::llround(duration * fps));
    clock.last_time = static_cast<double>(clock.count - 1) * clock.interval;
    return clock;
}

FrameClock still_clock(double at, double speed, int fps, std::string_view option) {
    if (!std::isfinite(at) || at < 0.0)
        throw_option_error(option, fmt::format("{}", at), "a time >= 0");
    require_positive(speed, "--speed", "number of simulation time units per second");
    FrameClock clock;
    clock.interval = speed / fps;
    const double steps = at / clock.interval;
    // Frame indices are int64 and are counted one by one: beyond 2^53 neither holds.
    if (!(steps < max_countable_frames)) {
        throw_option_error(option,
                           fmt::format("t = {:g} is {:.3g} frame intervals ({:g} / {} fps) into "
                                       "the video, more than can be counted ({:.3g}): give an "
                                       "earlier time, or a larger --speed",
                                       at, steps, speed, fps, max_countable_frames));
    }
    auto whole = static_cast<std::int64_t>(std::floor(steps));
    if (steps - static_cast<double>(whole) > 1.0 - snap_tolerance)
        ++whole;  // just under a frame time
    const double on_grid = static_cast<double>(whole) * clock.interval;
    if (std::abs(at - on_grid) <= snap_tolerance * clock.interval) {
        clock.count = whole + 1;  // `at` is (within rounding) frame `whole`: take the video's time
        clock.last_time = on_grid;
    } else {
        clock.count = whole + 2;  // frames 0..whole, then `at` itself
        clock.last_time = at;
    }
    return clock;
}

/// A 3D scene's camera: the options, else the scene's [render] hints, else a fixed orthographic
/// view of every sphere.
void choose_camera(const RenderRequest& request, const Scene& scene, RenderPlan& plan) {
    const RenderHints& hints = scene.render;
    if (request.camera) {
        plan.camera = parse_camera_motion(*request.camera);
    } else if (hints.camera) {
        plan.camera = *hints.camera;
    }
    if (request.projection) {
        plan.projection = parse_projection(*request.projection);
    } else if (hints.projection) {
        plan.projection = *hints.projection;
    }
    if (request.slab) {
        require_positive(*request.slab, "--slab", "thickness in box units");
        plan.slab = *request.slab;
    } else if (hints.slab) {
        require_positive(*hints.slab, hint_option(hints.slab_at, "slab"), "thickness in box units");
        plan.slab = *hints.slab;
    }
}

RenderPlan plan_without_frames(const RenderRequest& request, const Scene& scene) {
    RenderPlan plan;
    plan.mode = parse_render_mode(request.mode);
    choose_camera(request, scene, plan);
    const QualityPreset preset =
        request.quality ? quality_preset(*request.quality) : QualityPreset{};
    const FrameSize size =
        request.size ? parse_frame_size(*request.size) : FrameSize{preset.width, preset.height};
    plan.width = size.width;
    plan.height = size.height;
    plan.fps = choose_fps(request, preset);
    plan.duration = choose_duration(request, scene);
    plan.speed = choose_speed(scene, request.speed);
    if (!plan.speed.notice.empty()) plan.notices.push_back(plan.speed.notice);
    const double pace = plan.speed.speed;  // the physics' time scale (default dt)
    apply_slow_motion(request, plan);
    const FrameClock video = video_clock(plan.duration, plan.speed.speed, plan.fps);
    plan.event_engine = event_engine_options(request);
    std::vector<std::string> dt_notices;
    if (request.dt_list.empty()) {
        plan.time_engine = time_engine_options(request, scene, pace, video.interval, dt_notices);
    } else {
        choose_time_steps(request, scene, pace, video.interval, plan, dt_notices);
    }
    if (plan.mode != RenderMode::event) {
        plan.notices.insert(plan.notices.end(), dt_notices.begin(), dt_notices.end());
    }
    plan.render = render_config(request, scene, plan.width, plan.height);
    plan.code = code_of(request, plan);
    plan.queue_events = queue_events(request, plan);
    check_time_steps_shown(plan);
    plan.render.trail_length = show::trail_length(scene, video.count);
    plan.render.trail_whole_path = show::few_tagged_discs(scene);
    check_failure_colors(scene, plan.render, plan.notices);
    plan.lesson = show::lesson_plan(scene, lesson_request(request, scene, plan), plan.notices);
    if (request.layout_json) {
        if (request.layout_json->empty()) throw_option_error("--layout-json", "needs a file name");
        plan.layout_json = *request.layout_json;
    }
    const bool still = request.still || request.last_frame;
    if (request.at && !request.still) throw_option_error("--at", "only for `collide thumbnail`");
    const OutputChoice output =
        resolve_output(request.format, request.output, still, output_stem(scene));
    plan.kind = still ? OutputKind::still : OutputKind::video;
    plan.format = output.format;
    plan.output = output.path;
    plan.default_output = output.default_path;
    if (request.timeline_json) {
        if (request.timeline_json->empty())
            throw_option_error("--timeline-json", "needs a file name");
        if (still)
            throw_option_error("--timeline-json", "only for videos (a still has no timeline)");
        plan.timeline_json = *request.timeline_json;
    }
    plan.replay = replay_choice(request, scene, plan);
    return plan;
}

void lay_out_frames(RenderPlan& plan, const RenderRequest& request,
                    const ReplayFinder& find_replays) {
    const FrameClock video = video_clock(plan.duration, plan.speed.speed, plan.fps);
    const bool still = plan.kind == OutputKind::still;
    // The video's frames, and the simulation frames they show: fewer than the video's when a
    // card, a hold, a replay or the epilogue freezes the simulation.
    show::Timeline video_timeline = show::lesson_timeline(plan.lesson, plan.fps, video.count);
    FrameClock simulation = simulation_clock(video, video_timeline);
    if (find_replays && plan.replay != ReplayChoice::none) {
        // The failures of the simulation the video would show without them; each replay then
        // freezes the simulation a while, so the video shows fewer simulation frames.
        plan.clock = simulation;
        plan.replays = find_replays(plan);
        plan.lesson.replays = show::replay_cues(plan.replays);
        video_timeline = show::lesson_timeline(plan.lesson, plan.fps, video.count);
        simulation = simulation_clock(video, video_timeline);
        // Only the replays the timeline holds (one past the video's end is none).
        std::erase_if(plan.replays, [&](const show::ReplayFailure& failure) {
            return !has_replay(video_timeline, failure.sim_frame);
        });
        plan.lesson.replays = show::replay_cues(plan.replays);
    }
    if (still) {
        // A still is the simulation at one time: no card, no hold, no replay, no summary over it.
        // Without --at it shows the video's last simulation frame.
        plan.clock = request.at ? still_clock(*request.at, plan.speed.speed, plan.fps) : simulation;
        plan.timeline = show::still_timeline(video_timeline, plan.clock.count, plan.lesson.caption);
        plan.lesson.intro_seconds = 0.0;
        plan.lesson.epilogue_seconds = 0.0;
        plan.replays.clear();
    } else {
        plan.clock = simulation;
        plan.timeline = video_timeline;
    }
}

namespace {

/// Where each question asked stands on the timeline, by question index.
struct AskedAt {
    std::int64_t sim_frame = -1;    ///< the simulation frame it freezes on (-1: not asked)
    std::int64_t video_frame = -1;  ///< its first video frame
};
std::vector<AskedAt> asked_at(const show::Timeline& timeline, std::size_t questions) {
    std::vector<AskedAt> out(questions);
    for (const show::Segment& segment : timeline.segments) {
        if (segment.kind == show::SegmentKind::question && segment.question >= 0 &&
            static_cast<std::size_t>(segment.question) < questions)
            out[static_cast<std::size_t>(segment.question)] = {segment.sim_frame,
                                                               segment.first_frame};
    }
    return out;
}

/// A will-see question asked on simulation frame `frozen`: answered when the time-driven
/// engine's next step fails there; else `moved` says how many simulation frames later its next
/// failure is (0 and not askable: none fails before the video's end).
show::QuestionAnswer answer_will_see_at(const Scene& scene, const RenderPlan& plan,
                                        std::int64_t frozen, std::int64_t& moved,
                                        const std::atomic<bool>* stop) {
    moved = 0;
    const std::optional<show::ReplayFailure> failure = failure_after(scene, plan, frozen, stop);
    if (!failure) return {};
    moved = failure->sim_frame - 1 - frozen;
    return show::answer_will_see(*failure, frozen, plan.clock.time(frozen));
}

/// Where a question not askable on its frame `frozen` moves, in simulation frames after it:
/// a will-see question to the frame before the time-driven engine's next failed step (its
/// answer in `answer`), a next-collision one to the first frame the event-driven engine answers
/// (show::next_askable_frame), both up to the video's last frame. 0: nowhere (how-many is
/// askable wherever it is, or nowhere: its engine cannot be copied).
std::int64_t frames_to_askable(const Scene& scene, const RenderPlan& plan, QuestionKind kind,
                               std::int64_t frozen, show::QuestionAnswer& answer,
                               const std::atomic<bool>* stop) {
    std::int64_t later = 0;
    if (kind == QuestionKind::will_see) {
        answer = answer_will_see_at(scene, plan, frozen, later, stop);
        return later;
    }
    if (kind != QuestionKind::next_collision || answer.askable) return 0;
    const std::optional<std::int64_t> at = show::next_askable_frame(
        scene, plan.event_engine, plan.clock, frozen, plan.timeline.last_sim_frame(), stop);
    return at ? *at - frozen : 0;
}

/// What moves a question of `kind`, in a notice's words.
std::string moved_to_words(QuestionKind kind) {
    if (kind == QuestionKind::will_see)
        return "the moment before the time-driven engine's next check misses a collision";
    return fmt::format(
        "the first moment the event-driven engine resolves a collision in the {} frames after it",
        show::look_ahead_frames);
}

/// "at 12 s" or "at 12 s, moved to 14.20 s (the first moment ...)": where a question is.
std::string question_moment(const QuestionCue& cue, const show::TimelineQuestion& question) {
    if (question.at == cue.at) return fmt::format("at {:g} s", cue.at);
    return fmt::format("at {:g} s, moved to {:.2f} s ({})", cue.at, question.at,
                       moved_to_words(cue.kind));
}

/// Why question `i` cannot be asked where the timeline put it (empty: it can). `asked`: where
/// it stands (sim_frame -1: nowhere, no room); `answer`: the engine's answer there.
std::string cannot_ask_reason(const RenderPlan& plan, const QuestionCue& cue,
                              const show::TimelineQuestion& question, const AskedAt& asked,
                              const show::QuestionAnswer& answer) {
    const std::string moment = question_moment(cue, question);
    const std::string lengthen = "ask earlier, or set [render] duration";
    if (asked.sim_frame < 0) {
        return fmt::format(
            "no room {}, for {:g} s of question and answer before the video's end; {}", moment,
            cue.think + question.reveal, lengthen);
    }
    if (!answer.askable) {
        if (cue.kind == QuestionKind::will_see) {
            return fmt::format(
                "nothing to ask {}: the time-driven engine misses no collision after "
                "it before the video's end",
                moment);
        }
        if (cue.kind == QuestionKind::next_collision) {
            return fmt::format(
                "nothing to ask {}: the event-driven engine resolves no collision in "
                "the {} frames after it, nor after any later moment before the "
                "video's end",
                moment, show::look_ahead_frames);
        }
        return fmt::format("nothing to ask {}: the event-driven engine cannot be run ahead",
                           moment);
    }
    // How many collisions in the next second: the video shows that second after the answer
    // (runs at one simulation frame a video frame), else the class cannot count it.
    const std::int64_t shown_after = plan.timeline.last_sim_frame() - asked.sim_frame;
    if (cue.kind == QuestionKind::how_many && shown_after < plan.fps) {
        const double latest =
            static_cast<double>(asked.video_frame - (plan.fps - shown_after)) / plan.fps;
        const std::string fix =
            latest >= 0.0 ? fmt::format("ask by {:.2f} s, or set [render] duration", latest)
                          : std::string("set [render] duration");
        return fmt::format(
            "a how-many question {}: its answer counts the collisions of the next "
            "second, and the video runs {:.2f} s after it; {}",
            moment, static_cast<double>(shown_after) / plan.fps, fix);
    }
    return {};
}

/// A question that cannot be asked: refused naming its `at` (`refuse`: the video runs as the
/// scene says, its author moves it or lengthens the video), else left out with a notice.
void cannot_ask(const QuestionCue& cue, const std::string& reason, bool refuse,
                std::vector<std::string>& notices) {
    if (refuse) throw_scene_error(cue.file, cue.line, "render.questions.at", reason);
    notices.push_back(fmt::format("{}: render.questions.at: {}; not asked in this video",
                                  show::question_place(cue), reason));
}

}  // namespace

void ask_questions(RenderPlan& plan, const RenderRequest& request, const Scene& scene,
                   const ReplayFinder& find_replays, const std::atomic<bool>* stop) {
    plan.questions.clear();
    if (plan.kind == OutputKind::still || plan.lesson.questions.empty()) return;
    show::LessonPlan& lesson = plan.lesson;
    // The scene's own length and clock: a question it cannot ask is its author's to move. One
    // made unaskable by the command line's (a shorter video, another speed or step) is left out
    // with a notice, as a caption past a --duration's end is.
    const bool refuse = !request.duration && !request.speed && !request.slow_motion &&
                        !request.dt && request.dt_list.empty();
    std::vector<show::QuestionAnswer> answers;
    // Each round lays the frames out again: a question moved or left out changes the frames the
    // later ones freeze on. Moves first (a question moved may make room for another, or take
    // it); only a layout in which nothing moves judges what cannot be asked. A will-see question
    // moving onto its failure converges in a few.
    constexpr int max_rounds = 32;
    for (int round = 0;; ++round) {
        std::vector<QuestionKind> kinds;
        for (const QuestionCue& cue : lesson.question_cues) kinds.push_back(cue.kind);
        answers = show::answer_questions(scene, plan.event_engine, plan.clock, plan.timeline, kinds,
                                         stop);
        const std::vector<AskedAt> where_asked = asked_at(plan.timeline, kinds.size());
        bool moved_any = false;
        for (std::size_t i = 0; i < kinds.size(); ++i) {
            const AskedAt asked = where_asked[i];
            if (asked.sim_frame < 0) continue;
            const std::int64_t later =
                frames_to_askable(scene, plan, kinds[i], asked.sim_frame, answers[i], stop);
            if (later <= 0 || round >= max_rounds) continue;
            // The picture freezes `later` frames on: the frames between run first (one video
            // frame each while running; a whole frame's time, so that no rounding puts it a
            // frame later).
            lesson.questions[i].at = static_cast<double>(asked.video_frame + later) / plan.fps;
            moved_any = true;
        }
        if (!moved_any) {
            std::vector<show::TimelineQuestion> questions;
            std::vector<QuestionCue> cues;
            for (std::size_t i = 0; i < kinds.size(); ++i) {
                const std::string reason = cannot_ask_reason(
                    plan, lesson.question_cues[i], lesson.questions[i], where_asked[i], answers[i]);
                if (!reason.empty()) {
                    cannot_ask(lesson.question_cues[i], reason, refuse, plan.notices);
                    continue;
                }
                questions.push_back(lesson.questions[i]);
                cues.push_back(lesson.question_cues[i]);
            }
            if (questions.size() == kinds.size()) break;
            // Without the questions left out, the later ones freeze other frames: ask again.
            lesson.questions = std::move(questions);
            lesson.question_cues = std::move(cues);
        }
        lay_out_frames(plan, request, find_replays);
    }
    for (std::size_t i = 0; i < answers.size(); ++i) {
        const QuestionCue& cue = lesson.question_cues[i];
        if (lesson.questions[i].at - cue.at > show::quiet_move_seconds) {
            plan.notices.push_back(
                fmt::format("{}: render.questions.at: moved from {:g} s to {:.2f} "
                            "s, {}",
                            show::question_place(cue), cue.at, lesson.questions[i].at,
                            moved_to_words(cue.kind)));
        }
        lesson.questions[i].question = show::question_words(answers[i], cue.text);
        lesson.questions[i].answer = show::answer_words(answers[i], plan.clock);
    }
    plan.questions = std::move(answers);
    // The words do not move a frame: the same segments, now with the questions' captions.
    plan.timeline = show::lesson_timeline(lesson, plan.fps, plan.timeline.frame_count());
}

RenderPlan plan_render(const RenderRequest& request, const Scene& scene,
                       const ReplayFinder& find_replays) {
    RenderPlan plan = plan_without_frames(request, scene);
    lay_out_frames(plan, request, find_replays);
    ask_questions(plan, request, scene, find_replays);
    return plan;
}

std::vector<double> parse_dt_list(std::string_view text, std::string_view option) {
    std::vector<double> steps;
    std::size_t from = 0;
    while (true) {
        const std::size_t comma = text.find(',', from);
        const std::string value(
            text.substr(from, comma == std::string_view::npos ? comma : comma - from));
        char* end = nullptr;
        const double dt = std::strtod(value.c_str(), &end);
        if (value.empty() || end != value.c_str() + value.size() || !positive_finite(dt))
            throw_option_error(option, value, "a positive time step in the list");
        if (std::find(steps.begin(), steps.end(), dt) != steps.end()) {
            throw_option_error(option, fmt::format("{} is given twice in '{}': each time-driven "
                                                   "panel needs a step of its own",
                                                   value, text));
        }
        steps.push_back(dt);
        if (comma == std::string_view::npos) break;
        from = comma + 1;
    }
    if (steps.size() < 2 || steps.size() > max_dt_steps) {
        throw_option_error(option,
                           fmt::format("'{}' has {} steps: a list compares 2 to {} steps side by "
                                       "side (e.g. 0.01,0.02,0.04), or give one step",
                                       text, steps.size(), max_dt_steps));
    }
    return steps;
}

double default_dt(double speed) {
    return speed / reference_fps;
}

show::CollisionSettings collision_settings(const RenderPlan& plan) {
    show::CollisionSettings out;
    out.level = plan.render.overlays;
    out.time_panels = plan.mode != RenderMode::event;
    out.event_panel = plan.mode != RenderMode::time;
    out.event_engine = plan.event_engine;
    out.time_engine = plan.time_engine;
    out.time_steps = plan.time_steps;
    out.queue_events = plan.queue_events;
    out.code = plan.code;
    out.fps = plan.fps;
    out.speed = plan.speed.speed;
    out.clock = plan.clock;
    out.timeline = plan.timeline;
    out.lesson = plan.lesson;
    out.replays = plan.replays;
    out.questions = plan.questions;
    const render::RenderConfig& r = plan.render;
    out.color_mode = r.color_mode;
    out.speed_min = r.speed_min;
    out.speed_max = r.speed_max;
    out.mass_min = r.mass_min;
    out.mass_max = r.mass_max;
    out.camera = plan.camera;
    out.projection = plan.projection;
    out.slab = plan.slab;
    return out;
}

std::string find_drawing_font(const std::string& requested) {
    std::string path = find_font(requested);
    const io::File font(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY));
    if (font) io::note_input_file(font.get(), path);  // one that cannot be opened fails later
    return path;
}

}  // namespace collide::app
