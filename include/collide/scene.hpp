#pragma once
/// \file
/// A scene: the box, the discs at t = 0, and optional rendering hints. Produced by the scene
/// loaders (algs4 text, TOML, generators), consumed by the engines and the CLI.

#include <optional>
#include <string>
#include <vector>

#include "collide/box.hpp"
#include "collide/disc.hpp"
#include "collide/render_options.hpp"

namespace collide {

/// A caption shown from `at` seconds of video until the next one (`[[render.captions]]`).
struct CaptionCue {
    double at = 0.0;   ///< seconds of video
    std::string text;  ///< at most max_caption_chars characters
    std::string file;  ///< where it was written, for errors found later (beyond the video)
    int line = 0;
    double hold = 0.0;  ///< seconds of video the picture stays frozen from `at` (0: none)
    /// The words for a video of one panel (`--mode event`, `--mode time`), where `text` speaks
    /// of both ("Left tests every pair..."); unset: `text` suits that video too.
    std::optional<std::string> event_text = std::nullopt;
    std::optional<std::string> time_text = std::nullopt;
};

/// A question asked from `at` seconds of video (`[[render.questions]]`): the picture freezes while
/// the class thinks `think` seconds, then the engine's answer shows (show/questions.hpp).
struct QuestionCue {
    double at = 0.0;  ///< seconds of video
    QuestionKind kind = QuestionKind::next_collision;
    std::string text;    ///< the question's words ("": the kind's own)
    double think = 3.0;  ///< seconds of video frozen on the question, >= 2
    std::string file;    ///< where it was written, for errors and notices found later
    int line = 0;
};

/// Longest caption: one line across a 16:9 frame at the lesson text size (docs/scenes.md).
inline constexpr std::size_t max_caption_chars = 64;
/// Longest title: a file name's length (a scene without a title is titled after its file, and
/// `check --export` writes that title, which must read back) (docs/scenes.md).
inline constexpr std::size_t max_title_chars = 255;
/// Longest description: a short paragraph on the intro card, which shows it whole on every
/// frame of the intro (docs/scenes.md).
inline constexpr std::size_t max_description_chars = 600;
/// Longest tag: a label, never drawn as text (docs/scenes.md).
inline constexpr std::size_t max_tag_chars = 64;

/// Rendering defaults a scene may carry in `[render]`; the CLI overrides every one of them.
struct RenderHints {
    std::optional<ColorMode> color_mode;  ///< "scene", "speed", "mass" (or "tag")
    std::optional<bool> trails;           ///< draw trails for tagged discs
    /// "none", "lesson" or "full" (true in a file means lesson, false none)
    std::optional<OverlayLevel> overlays;
    std::optional<Theme> theme;          ///< "dark" or "light"
    std::optional<std::string> caption;  ///< the caption line for the whole video
    std::vector<CaptionCue> captions;    ///< scripted captions, `at` increasing
    std::vector<QuestionCue> questions;  ///< questions asked, `at` increasing
    /// "none", "small" or "large"; unset (or "auto" in a file): where it teaches
    std::optional<PlotSize> histogram;
    std::optional<double> duration;      ///< seconds of video
    std::optional<double> speed;         ///< simulation time units per second of video
    std::optional<double> dt;            ///< time-driven quantum
    std::optional<ReplayChoice> replay;  ///< "none", "first" or "all": failures replayed
    /// Only failures involving a disc with this tag are replayed (a barrier's, the scene's
    /// subject); unset: any failure.
    std::optional<std::string> replay_tag;
    // 3D scenes only (a 2D scene file that names them is refused):
    std::optional<CameraMotion> camera;    ///< "fixed" or "orbit"
    std::optional<Projection> projection;  ///< "ortho" or "perspective"
    std::optional<double> slab;            ///< the slice shown, box units thick
    /// Where each numeric hint was written, "file:line: render.dt", so that a hint the CLI
    /// refuses (too long, too much work) is named where the user can fix it; empty = unknown.
    std::string duration_at;
    std::string speed_at;
    std::string dt_at;
    std::string caption_at;  ///< "file:line: render.caption", for a caption too wide for a frame
    std::string slab_at;
};

struct Scene {
    std::string name;         ///< short name (file stem or built-in name), used for default outputs
    std::string title;        ///< human title shown on screen
    std::string description;  ///< one or two sentences: what the scene shows (the intro card)
    Box box;
    std::vector<Disc> discs;
    RenderHints render;
};

}  // namespace collide
