#pragma once
/// \file
/// What `collide render` / `collide thumbnail` will do, decided before anything is rendered:
/// the options the user typed (RenderRequest) resolved against the scene's [render] hints and the
/// defaults into one RenderPlan. Precedence everywhere: command line > scene hint > default.
/// Pure functions (no GL, no files): unit-tested in collide_render_plan_tests.

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "collide/render/renderer.hpp"
#include "collide/scene.hpp"
#include "collide/show/collision.hpp"
#include "collide/show/collision_program.hpp"
#include "collide/show/questions.hpp"
#include "collide/show/replay.hpp"
#include "collide/show/sphere_camera.hpp"
#include "collide/sim/engine.hpp"
#include "collide/video/video_writer.hpp"

namespace collide::app {

/// Which simulations appear in the video.
enum class RenderMode {
    both,   ///< time-driven left, event-driven right, same scene and simulation time
    event,  ///< the event-driven engine alone
    time,   ///< the time-driven engine alone
};

/// "both" / "event" / "time"; throws Error(input) naming `option` otherwise.
[[nodiscard]] RenderMode parse_render_mode(std::string_view text,
                                           std::string_view option = "--mode");

/// "fixed" / "orbit" (`--camera`, 3D scenes); throws Error(input) naming `option` otherwise.
[[nodiscard]] show::CameraMotion parse_camera_motion(std::string_view text,
                                                     std::string_view option = "--camera");

/// "ortho" / "perspective" (`--projection`, 3D scenes); throws Error(input) naming `option`
/// otherwise.
[[nodiscard]] show::Projection parse_projection(std::string_view text,
                                                std::string_view option = "--projection");

/// A frame size and rate preset, as in manim's -ql/-qm/-qh/-qk.
struct QualityPreset {
    int width = 1280;
    int height = 720;
    int fps = 30;
};

/// `fps` if it is 1..max_fps (video_options.hpp); else throws Error(input) naming `option`.
[[nodiscard]] int checked_fps(int fps, std::string_view option = "--fps");

/// Where the output of `render`, `thumbnail`, `heap` or `puzzle` goes and as what.
struct OutputChoice {
    std::filesystem::path path;
    video::VideoFormat format = video::VideoFormat::mp4;  ///< videos only
    bool still = false;         ///< one PNG (thumbnail, --last-frame, --at)
    bool default_path = false;  ///< derived from the stem under default_output_dir

    /// A video written as MP4: the only output that carries subtitle and chapter tracks.
    [[nodiscard]] bool mp4_video() const noexcept {
        return !still && format == video::VideoFormat::mp4;
    }
};

/// The one output rule of every video command (docs/outputs.md, "Which file, which format"):
/// - a still is a PNG: --format, if given, must be png, and -o, if given, end in .png;
/// - a video: --format decides, and -o may then have any extension but one naming another
///   format (.mp4, .gif, .png); without --format, -o's extension decides (.mp4, .gif), and
///   any other is refused (.png with a word on --last-frame and --format png);
/// - without -o: out/STEM.png, out/STEM.mp4, out/STEM.gif or out/STEM_frames (PNG sequence).
/// Extensions compare case-insensitively. Throws Error(input) naming --format or -o.
[[nodiscard]] OutputChoice resolve_output(const std::optional<std::string>& format,
                                          const std::optional<std::string>& output, bool still,
                                          std::string_view stem);

/// l = 854x480@15, m = 1280x720@30, h = 1920x1080@60, k = 3840x2160@60.
/// Throws Error(input) naming `option` for any other letter.
[[nodiscard]] QualityPreset quality_preset(std::string_view letter, std::string_view option = "-q");

/// Parses "WxH" (e.g. "1280x720"), both in [render::min_frame_side, render::max_frame_side].
/// Throws Error(input) naming `option`.
struct FrameSize {
    int width = 0;
    int height = 0;
};
[[nodiscard]] FrameSize parse_frame_size(std::string_view text, std::string_view option = "--size");

/// Root mean square speed of the scene's discs at t = 0 (all discs, resting ones included, so a
/// few fast discs among many resting ones still set the pace). 0 when nothing moves.
[[nodiscard]] double rms_speed(const Scene& scene) noexcept;
/// Largest disc speed at t = 0.
[[nodiscard]] double max_speed(const Scene& scene) noexcept;

/// Seconds of video in which a typical disc crosses the box when the speed is derived.
inline constexpr double crossing_seconds = 10.0;

/// The playback speed (simulation time units per second of video) and where it came from.
struct SpeedChoice {
    double speed = 1.0;
    std::string source;  ///< "--speed", "scene hint", "derived" or "fallback"
    std::string notice;  ///< non-empty when the user should know (e.g. nothing moves)
};

/// `cli` if given, else the scene's [render] speed hint, else box width / (crossing_seconds *
/// rms speed) so that algs4 files with speeds of 0.01 and molecular-scale fluids both look right;
/// a scene where nothing moves falls back to 1 with a notice. O(N).
[[nodiscard]] SpeedChoice choose_speed(const Scene& scene, std::optional<double> cli);

/// The frame clock and the time-driven steps between frames (collide/show/collision.hpp).
using show::divides;
using show::FrameClock;

/// A video of `duration` seconds at `fps`: round(duration * fps) frames (at least 1), frame k at
/// k * speed / fps. Throws Error(input) if duration, speed or fps is not positive and finite.
[[nodiscard]] FrameClock video_clock(double duration, double speed, int fps);

/// The frames a still image at simulation time `at` goes through: every frame time of the video
/// clock up to `at`, then `at` itself (snapped onto a frame time within 1e-9 of an interval), so
/// the time-driven engine takes exactly the steps the video takes and a thumbnail at the video's
/// last frame time equals that frame. Throws Error(input) naming `option` for a negative `at`.
[[nodiscard]] FrameClock still_clock(double at, double speed, int fps,
                                     std::string_view option = "--at");

/// How messages name a scene hint: its "file:line: render.dt" when known (`where`, from
/// RenderHints), else "scene [render] dt".
[[nodiscard]] std::string hint_option(const std::string& where, std::string_view key);

/// Everything the user may type; unset = take the scene hint or the default.
struct RenderRequest {
    std::string scene;                      ///< file or built-in name
    std::optional<std::string> output;      ///< -o
    std::string mode = "both";              ///< --mode
    std::optional<std::string> camera;      ///< --camera (3D scenes): fixed or orbit
    std::optional<double> slab;             ///< --slab W (3D scenes): a slice W box units thick
    std::optional<std::string> projection;  ///< --projection (3D scenes): ortho or perspective
    std::optional<std::string> quality;     ///< -q
    std::optional<std::string> size;        ///< --size WxH
    std::optional<int> fps;                 ///< --fps
    std::optional<double> duration;         ///< --duration (seconds of video)
    std::optional<double> speed;            ///< --speed (simulation time per second of video)
    std::optional<double> dt;               ///< --dt (time-driven quantum)
    /// --dt A,B[,C[,D]]: the dt trade-off, one time-driven panel per step beside the
    /// event-driven one (parse_dt_list; empty: one step, `dt`).
    std::vector<double> dt_list;
    EngineKind engine = EngineKind::fast;  ///< --engine (the event-driven one: fast or classic)
    pq::QueueKind pq;                      ///< --pq (classic engine's queue)
    OverlapDetection td_detect = OverlapDetection::all_pairs;  ///< --td-detect (time-driven)
    std::optional<std::string> color;                          ///< --color
    std::optional<bool> trails;                                ///< --trails / --no-trails
    std::optional<std::string> overlays;                       ///< --overlays none|lesson|full
    std::optional<std::string> theme;                          ///< --theme dark|light
    std::optional<std::string> layout_json;                    ///< --layout-json FILE
    std::optional<std::string> timeline_json;                  ///< --timeline-json FILE
    std::optional<std::string> format;                         ///< --format mp4|gif|png
    bool last_frame = false;               ///< --last-frame: write only the last frame as a PNG
    std::optional<double> at;              ///< thumbnail --at (simulation time)
    bool still = false;                    ///< true for `collide thumbnail` (PNG output)
    bool no_limits = false;                ///< --no-limits: run even what exceeds WorkLimits
    std::optional<int> queue;              ///< --queue [K]: show the event queue, K events
    std::optional<double> slow_motion;     ///< --slow-motion F: F times slower than the speed
    bool code = false;                     ///< --code: the event-driven loop beside the queue
    std::string font;                      ///< --font FILE (empty: find_font's search)
    bool no_intro = false;                 ///< --no-intro: no title card
    bool no_epilogue = false;              ///< --no-epilogue: no summary card at the end
    std::optional<std::string> replay;     ///< --replay none|first|all
    std::optional<std::string> questions;  ///< --questions on|none
};

/// The most time-driven panels a --dt list puts beside the event-driven one: five boxes in all
/// still leave lesson-size text (lesson_layout's grid).
inline constexpr std::size_t max_dt_steps = 4;

/// `--dt A,B[,C[,D]]`: 2..max_dt_steps distinct positive steps, in the order given. Throws
/// Error(input) naming `option` for too many or too few values, one that is no positive number,
/// or one given twice.
[[nodiscard]] std::vector<double> parse_dt_list(std::string_view text,
                                                std::string_view option = "--dt");

/// Events `--queue` shows without a number.
inline constexpr int default_queue_events = 5;
/// `--code` without `--slow-motion`: slow enough that a pop's walk through the loop's lines
/// (4 x show::code_line_seconds) mostly ends before the next pop (gas: ~0.7 pops a second).
inline constexpr double default_code_slow_motion = 16.0;
/// `--code`: the narrowest frame that holds the loop's lines beside the boxes (-q l).
inline constexpr int min_code_frame_width = 854;
/// The largest --slow-motion factor (a disc crossing the box in ten seconds would take days).
inline constexpr double max_slow_motion = 1000.0;

/// What kind of file comes out.
enum class OutputKind {
    video,  ///< MP4 or GIF or PNG sequence through video::VideoWriter
    still,  ///< one PNG (thumbnail, --last-frame)
};

/// The lesson's timeline: intro card, captions, step indicator (collide/show/collision.hpp).
using show::intro_seconds;
using show::LessonPlan;

/// The default time-driven dt is the simulation time of one 1/30 s video frame at the video's
/// speed (the -q m frame interval), whatever -q or --fps say: presets never change the physics.
inline constexpr double reference_fps = 30.0;

/// The default dt without `[render] dt` or --dt: the time scale of the video (its speed: --speed,
/// the scene's hint or derived from the scene, in simulation time per second of video) divided
/// by reference_fps. Never the frame rate.
[[nodiscard]] double default_dt(double speed);

/// The resolved plan. Every field is valid once plan_render returned.
struct RenderPlan {
    RenderMode mode = RenderMode::both;
    int width = 1280;
    int height = 720;
    int fps = 30;
    double duration = 10.0;  ///< seconds of video (still: the video it is a frame of)
    SpeedChoice speed;
    FrameClock clock;  ///< the simulation frames: frame j at simulation time clock.time(j)
    /// The video frames (show/timeline.hpp): which simulation frame each shows, and why. A still
    /// only runs (video frame k shows simulation frame k).
    show::Timeline timeline;
    EngineOptions event_engine;  ///< engine fast or classic
    EngineOptions time_engine;   ///< engine time, with the dt in use (a --dt list: the smallest)
    /// A --dt list: the step of each time-driven panel, in the order given (2..max_dt_steps);
    /// empty: one time-driven panel, time_engine.dt. The list replays nothing (each panel fails
    /// at its own steps, and a replay zooms every panel onto one failure).
    std::vector<double> time_steps;
    render::RenderConfig render;
    OutputKind kind = OutputKind::video;
    video::VideoFormat format = video::VideoFormat::mp4;
    std::filesystem::path output;
    bool default_output = false;          ///< output derived from the scene name (under out/)
    std::vector<std::string> notices;     ///< one-line remarks to print before rendering
    LessonPlan lesson;                    ///< what the lesson level shows besides the discs
    std::filesystem::path layout_json;    ///< --layout-json (empty: none)
    std::filesystem::path timeline_json;  ///< --timeline-json (empty: none)
    /// --queue: the event-driven panel shows this many upcoming events and its queue (0: off).
    std::size_t queue_events = 0;
    /// --code: the event-driven loop's pseudocode beside the queue, its line under way marked.
    bool code = false;
    /// --slow-motion: speed.speed is the chosen pace divided by this (1: none). The physics (the
    /// default dt) follows the pace before the slow motion.
    double slow_motion = 1.0;
    /// --camera, else the scene's hint: how a 3D scene is seen (a 2D scene ignores it).
    show::CameraMotion camera = show::CameraMotion::fixed;
    /// --projection, else the scene's hint: the 3D camera's projection (2D ignores it).
    show::Projection projection = show::Projection::orthographic;
    /// --slab, else the hint: the thickness of the slice of spheres shown, box units (0: all).
    double slab = 0.0;
    /// Which failures of the time-driven panel are replayed (--replay, the scene's hint, else
    /// first); none where no replay can be shown (no time-driven panel, not the lesson level).
    ReplayChoice replay = ReplayChoice::first;
    /// The failures replayed (plan_render's ReplayFinder), in the order the video shows them.
    std::vector<show::ReplayFailure> replays;
    /// The questions' answers from the engines (answer_plan_questions), indexed like
    /// lesson.questions.
    std::vector<show::QuestionAnswer> questions;
};

/// Default output directory for derived paths.
inline constexpr const char* default_output_dir = "out";

/// Finds the failures a plan's video replays (replay_plan.hpp: it runs the engines), from the
/// plan's choice (RenderPlan::replay) and its simulation frames without replays
/// (RenderPlan::clock).
using ReplayFinder = std::function<std::vector<show::ReplayFailure>(const RenderPlan&)>;

/// Asks the engines the questions of `plan` (laid out by lay_out_frames): each question's answer
/// and words (show/questions.hpp), and the timeline with their captions. A question that cannot
/// be asked on its frame moves to the first later one that can (will-see: before the time-driven
/// engine's next failed step; next-collision: show::next_askable_frame), with a notice naming
/// where it was written when it lands more than show::quiet_move_seconds after its `at`. One
/// that cannot be asked at all (no later moment before the video's end, no room for it before
/// the end, or a how-many question whose next second the video does not show) throws
/// Error(input) naming its file, line and `render.questions.at`; when --duration, --speed,
/// --slow-motion or --dt set the video's length or clock it is left out with a notice instead,
/// and the frames laid out again without it. A still asks nothing. Once `stop` is set throws
/// Error(runtime).
void ask_questions(RenderPlan& plan, const RenderRequest& request, const Scene& scene,
                   const ReplayFinder& find_replays = {}, const std::atomic<bool>* stop = nullptr);

/// Resolves `request` against `scene` (already loaded and validated). Throws Error(input) naming
/// the first bad option. Touches no file: the caller checks that `output` is writable. Without
/// `find_replays` (or with --replay none) the video replays nothing; with it, the timeline and
/// the clock make room for the replays it finds.
[[nodiscard]] RenderPlan plan_render(const RenderRequest& request, const Scene& scene,
                                     const ReplayFinder& find_replays = {});

/// plan_render in two steps, so that a plan can be checked before its replays are looked for
/// (which may simulate for long) without resolving the request twice:
/// everything but the frames (clock, timeline, replays; the output and every option checked) ...
[[nodiscard]] RenderPlan plan_without_frames(const RenderRequest& request, const Scene& scene);
/// ... then the frames: the timeline and the simulation frames it shows, making room for the
/// replays `find_replays` finds (none without it). `plan` comes from plan_without_frames, once:
/// a still's plan loses its card and summary here.
void lay_out_frames(RenderPlan& plan, const RenderRequest& request,
                    const ReplayFinder& find_replays = {});

/// The collision program's settings (collide/show/collision_program.hpp) of a resolved plan.
[[nodiscard]] show::CollisionSettings collision_settings(const RenderPlan& plan);

/// find_font(requested), recorded as one of the run's inputs (io::note_input_file), so that no
/// output of the run may replace the font it draws with (`--font f.ttf --layout-json f.ttf`).
[[nodiscard]] std::string find_drawing_font(const std::string& requested);

}  // namespace collide::app
