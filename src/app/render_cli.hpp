#pragma once
/// \file
/// The command lines of `collide render` and `collide thumbnail`, and every check of them that
/// needs no GL, no encoder and no simulating. Both programs register these commands from here:
/// `collide` checks a line before it becomes collide-draw (so a bad one is refused without
/// starting the drawing program: the same message, exit 2), and collide-draw checks it again
/// and draws (cmd_render.cpp).

#include <cstdint>
#include <optional>
#include <string>

#include "cli_fwd.hpp"
#include "collide/render/context.hpp"
#include "collide/scene/load.hpp"
#include "collide/show/scene_view.hpp"
#include "progress.hpp"
#include "render_plan.hpp"
#include "video_job.hpp"
#include "video_options.hpp"

namespace collide::app {

class InterruptGuard;

/// Raw option values as CLI11 stores them; CheckedRender turns them into a RenderRequest.
struct RenderCli {
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

/// Registers `render` (still = false) or `thumbnail` (still = true) on `root` with every option
/// bound to `values`, its description, help and examples; the caller sets its callback.
CLI::App* add_render_options(CLI::App& root, RenderCli& values, bool still);

/// A command line of `render` or `thumbnail` that passed every check that needs no GL, no encoder
/// and no simulating: the scene loaded (a 3D one with its stand-in discs), the options resolved
/// against it, the plan laid out without replays, the destinations writable. The constructor
/// throws Error(input) naming the first bad option (a signal while the scene loads ends the run:
/// interrupt.hpp), in one order for both programs. Refers to nothing of `values` once built; not
/// copied or moved, since view() refers to the scene it holds.
class CheckedRender {
  public:
    CheckedRender(const RenderCli& values, bool still, const InterruptGuard& interrupts);
    CheckedRender(const CheckedRender&) = delete;
    CheckedRender& operator=(const CheckedRender&) = delete;

    /// The scene as the engines run it (its discs, or its spheres and their stand-in).
    [[nodiscard]] show::SceneView view() const;

    ProgressMode progress = ProgressMode::automatic;
    render::Backend backend = render::Backend::automatic;
    RenderRequest request;
    RenderPlan draft;  ///< plan_without_frames: its frames are laid out with the replays later
    SubtitleOutput subtitles;
    ChapterOutput chapters;

  private:
    AnyScene scene_;
    std::optional<Scene> stand_in_;  ///< a 3D scene's discs for planning
};

}  // namespace collide::app
