#pragma once
/// \file
/// The typed render options every module shares: how discs are coloured, how much is drawn
/// around the boxes, the theme and the size of a lesson plot. One name table each: the command
/// line (`--color`, `--overlays`, `--theme`), the scene's `[render]` table and the renderer parse
/// and print them through these tables only. Std-only (types layer).

#include <array>
#include <cstdint>
#include <string_view>

#include "collide/named_values.hpp"

namespace collide {

/// How discs are coloured.
enum class ColorMode {
    scene,  ///< the scene's own colour for each disc
    speed,  ///< |v| through a perceptual colormap over [speed_min, speed_max] (legend shown)
    mass,   ///< mass through the colormap over [mass_min, mass_max] (log scale)
    tag,    ///< tagged discs highlighted, the others grey
};

/// How much is drawn around the boxes (docs/renderer.md, "Layout levels").
enum class OverlayLevel {
    none,    ///< discs only: the boxes fill the frame
    lesson,  ///< the default: titles, two or three figures per panel, the cost graphic, a caption
    full,    ///< every counter and the plot strip (for experts)
};

/// Colours of the background, panels and text.
enum class Theme {
    dark,   ///< light discs on dark panels (screens)
    light,  ///< dark text on white panels (projectors, print)
};

/// Size of a lesson-level plot.
enum class PlotSize { none, small, large };

/// Which failures of the time-driven panel a lesson replays (zoomed in, slowly).
enum class ReplayChoice {
    none,   ///< no replay
    first,  ///< the default: the first failure, if the video shows one
    all,    ///< every failure the engine records (one per step, a few), as long as they fit
};

/// What a question in a collision video asks (`[[render.questions]] kind`); the engines answer.
enum class QuestionKind : std::uint8_t {
    next_collision,  ///< which of two to four marked pairs collides next (event-driven panel)
    how_many,        ///< how many collisions in the next second of video (event-driven panel)
    will_see,        ///< will the next check see this collision? (time-driven panel)
};

/// How a 3D scene's camera moves (`--camera`, `[render] camera`): a fixed view, or one that turns
/// slowly about the box's vertical axis (show::camera_at).
enum class CameraMotion : std::uint8_t { fixed, orbit };

/// A 3D scene's projection (`--projection`, `[render] projection`): parallel rays (every sphere
/// as large as it is, the box's edges parallel), or a perspective from an eye at a finite
/// distance (near spheres larger, the edges converge).
enum class Projection : std::uint8_t { orthographic, perspective };

/// The names, in the order messages list them.
inline constexpr std::array<NamedValue<ColorMode>, 4> color_mode_names{{{"scene", ColorMode::scene},
                                                                        {"speed", ColorMode::speed},
                                                                        {"mass", ColorMode::mass},
                                                                        {"tag", ColorMode::tag}}};
inline constexpr std::array<NamedValue<OverlayLevel>, 3> overlay_level_names{
    {{"none", OverlayLevel::none}, {"lesson", OverlayLevel::lesson}, {"full", OverlayLevel::full}}};
inline constexpr std::array<NamedValue<Theme>, 2> theme_names{
    {{"dark", Theme::dark}, {"light", Theme::light}}};
inline constexpr std::array<NamedValue<PlotSize>, 3> plot_size_names{
    {{"none", PlotSize::none}, {"small", PlotSize::small}, {"large", PlotSize::large}}};
inline constexpr std::array<NamedValue<ReplayChoice>, 3> replay_choice_names{
    {{"none", ReplayChoice::none}, {"first", ReplayChoice::first}, {"all", ReplayChoice::all}}};
inline constexpr std::array<NamedValue<QuestionKind>, 3> question_kind_names{
    {{"next-collision", QuestionKind::next_collision},
     {"how-many", QuestionKind::how_many},
     {"will-see", QuestionKind::will_see}}};
inline constexpr std::array<NamedValue<CameraMotion>, 2> camera_motion_names{
    {{"fixed", CameraMotion::fixed}, {"orbit", CameraMotion::orbit}}};
inline constexpr std::array<NamedValue<Projection>, 2> projection_names{
    {{"ortho", Projection::orthographic}, {"perspective", Projection::perspective}}};

/// "scene" / "speed" / "mass" / "tag".
[[nodiscard]] constexpr std::string_view color_mode_name(ColorMode mode) noexcept {
    return name_of(mode, color_mode_names, "scene");
}
/// Parses a colour mode name; throws collide::Error (input) naming `field` otherwise.
[[nodiscard]] inline ColorMode parse_color_mode(std::string_view text,
                                                std::string_view field = "color_mode") {
    return parse_named(text, field, color_mode_names, "a colour mode");
}

/// "none" / "lesson" / "full".
[[nodiscard]] constexpr std::string_view overlay_level_name(OverlayLevel level) noexcept {
    return name_of(level, overlay_level_names, "lesson");
}
/// Parses an overlay level; throws collide::Error (input) naming `field` otherwise.
[[nodiscard]] inline OverlayLevel parse_overlay_level(std::string_view text,
                                                      std::string_view field = "overlays") {
    return parse_named(text, field, overlay_level_names, "an overlay level");
}

/// "dark" / "light".
[[nodiscard]] constexpr std::string_view theme_name(Theme theme) noexcept {
    return name_of(theme, theme_names, "dark");
}
/// Parses a theme; throws collide::Error (input) naming `field` otherwise.
[[nodiscard]] inline Theme parse_theme(std::string_view text, std::string_view field = "theme") {
    return parse_named(text, field, theme_names, "a theme");
}

/// "none" / "small" / "large".
[[nodiscard]] constexpr std::string_view plot_size_name(PlotSize size) noexcept {
    return name_of(size, plot_size_names, "none");
}

/// "none" / "first" / "all".
[[nodiscard]] constexpr std::string_view replay_choice_name(ReplayChoice choice) noexcept {
    return name_of(choice, replay_choice_names, "first");
}
/// Parses a replay choice; throws collide::Error (input) naming `field` otherwise.
[[nodiscard]] inline ReplayChoice parse_replay_choice(std::string_view text,
                                                      std::string_view field = "replay") {
    return parse_named(text, field, replay_choice_names, "a replay choice");
}

/// "next-collision" / "how-many".
[[nodiscard]] constexpr std::string_view question_kind_name(QuestionKind kind) noexcept {
    return name_of(kind, question_kind_names, "next-collision");
}
/// Parses a question kind; throws collide::Error (input) naming `field` otherwise.
[[nodiscard]] inline QuestionKind parse_question_kind(std::string_view text,
                                                      std::string_view field = "kind") {
    return parse_named(text, field, question_kind_names, "a question kind");
}

}  // namespace collide
