#pragma once
/// \file
/// The offscreen renderer: turns snapshots into RGBA images (rows top-down), two simulations side
/// by side in one frame (time-driven left, event-driven right), with titles, counters, failure
/// markers, trails, a colour legend, and a strip below holding the time, the speed histogram
/// against the 2D Maxwell-Boltzmann curve, the energy drift plot and a notice line.
///
/// Typical use (one Renderer per video, frames in order):
///     RenderConfig config; config.width = 1280; config.height = 720;
///     config.color_mode = ColorMode::speed; config.speed_max = 3.0; config.validate();
///     Renderer renderer(config);                         // OSMesa, no display needed
///     FrameContent frame;
///     frame.panels = {{&td_snapshot, "Time-driven, dt = 0.01", {"collisions 1234", ...}},
///                     {&ed_snapshot, "Event-driven (priority queue)", {"events 1240", ...}}};
///     frame.time_text = "t = 3.25";
///     frame.energy_drift = {td_drift_series, ed_drift_series};
///     Image image = renderer.render(frame);

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "collide/image.hpp"
#include "collide/number_text.hpp"
#include "collide/render/context.hpp"
#include "collide/render_options.hpp"
#include "collide/snapshot.hpp"
#include "collide/view/collision.hpp"

namespace collide::render {

// The typed options live in the types layer (one name table each); the renderer's code names
// them unqualified.
using collide::color_mode_name;
using collide::ColorMode;
using collide::overlay_level_name;
using collide::OverlayLevel;
using collide::parse_color_mode;
using collide::parse_overlay_level;
using collide::parse_theme;
using collide::PlotSize;
using collide::Theme;
using collide::theme_name;

/// The frame sides the renderers accept, in pixels (every frame size option and config is checked
/// against these): below 64 no text is legible; 8192 is well inside every GL implementation's
/// framebuffer limit.
inline constexpr int min_frame_side = 64;
inline constexpr int max_frame_side = 8192;

/// Everything that stays fixed for a whole video.
struct RenderConfig {
    /// Frame width in pixels, min_frame_side..max_frame_side (encoders want it even; not
    /// enforced here).
    int width = 1280;
    int height = 720;  ///< frame height in pixels, min_frame_side..max_frame_side
    ColorMode color_mode = ColorMode::scene;
    /// Speed range of the colormap, the legend and the histogram, in box units per time unit.
    /// Fixed for the whole video so colours mean the same thing in every frame.
    double speed_min = 0.0;
    double speed_max = 1.0;  ///< > speed_min
    /// Mass range of ColorMode::mass (log scale), > 0, mass_max >= mass_min.
    double mass_min = 1.0;
    double mass_max = 1.0;
    bool trails = true;     ///< fading trails behind tagged discs
    int trail_length = 48;  ///< frames of history kept per tagged disc, 2..1024
    /// Past trail_length frames, keep the whole path at a coarser spacing instead of dropping its
    /// start (a few tagged discs whose path is the lesson, as the Brownian tracer's).
    bool trail_whole_path = false;
    OverlayLevel overlays = OverlayLevel::lesson;  ///< what is drawn around the boxes
    Theme theme = Theme::dark;
    /// Font for all text (DejaVu Sans from fonts-dejavu-core). A missing file is a runtime error
    /// when the Renderer is constructed with overlays on.
    std::string font_path = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

    /// Throws collide::Error (input) naming the first bad field ("render.width: must be >= 64").
    void validate() const;
};

// The collision video's views (what the painter takes) live in the types layer, filled by the
// presentation layer (src/show).
using collide::DriftPoint;
using collide::Figure;
using collide::FrameContent;
using collide::PanelContent;

/// Renders frames with a GL context it owns. Keeps per-panel trail history across frames (it
/// sees only snapshots), so feed frames in time order; a snapshot whose disc count changes or
/// whose time goes backwards resets that panel's trails. Not thread-safe; one per thread.
class Renderer {
  public:
    /// Creates the context (see make_context) and all GL resources. Throws collide::Error:
    /// input for an invalid config, runtime when the context, shaders or font cannot be set up.
    explicit Renderer(const RenderConfig& config, Backend backend = Backend::automatic,
                      const NoticeSink& notice = {});
    /// Uses an existing context (tests, other backends). Same throws.
    Renderer(const RenderConfig& config, std::unique_ptr<Context> context);
    ~Renderer();
    Renderer(Renderer&&) noexcept;
    Renderer& operator=(Renderer&&) noexcept;
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    /// Draws and reads back one frame: width x height RGBA8, rows top-down.
    /// O(N) in the number of discs. Throws collide::Error (input) if a panel has no snapshot or
    /// there are not 1 to max_frame_panels panels.
    [[nodiscard]] Image render(const FrameContent& frame);
    /// Same, reusing `out`'s storage (resized as needed): no allocation per frame.
    void render(const FrameContent& frame, Image& out);

    /// The two halves of render(), exposed for benchmarks: draw only (GL commands issued and
    /// finished), then read back the last drawn frame (its text is blended in on the CPU then).
    void draw(const FrameContent& frame);
    void read_pixels(Image& out);

    /// The rectangles `frame` is laid out in (panels, boxes, every text line with its pixel
    /// height) and, once it was drawn (call after render or draw), the strings drawn in each
    /// line, as JSON (`--layout-json`).
    [[nodiscard]] std::string layout_json(const FrameContent& frame) const;

    [[nodiscard]] Backend backend() const noexcept;
    [[nodiscard]] const RenderConfig& config() const noexcept;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

using collide::with_separators;  // collide/number_text.hpp

/// Each engine's colour (title swatch, cost bar, histogram): time-driven orange, event-driven
/// blue, the same in every video; on the light theme darkened until it keeps 3:1 on the page.
[[nodiscard]] Rgb8 panel_accent(bool time_driven, Theme theme = Theme::dark) noexcept;

/// The colour reserved for failures (missed collisions, overlaps, escapes) in a theme.
[[nodiscard]] Rgb8 failure_color(Theme theme) noexcept;
/// True when a disc colour could be mistaken for the failure colour.
[[nodiscard]] bool near_failure_color(Rgb8 color) noexcept;
/// `color` moved away from the failure colour (unchanged when it is not near it).
[[nodiscard]] Rgb8 away_from_failure_color(Rgb8 color) noexcept;
/// WCAG contrast ratio of two sRGB colours, 1..21.
[[nodiscard]] double contrast_ratio(Rgb8 a, Rgb8 b) noexcept;
/// The box fill of a theme (what discs are seen against).
[[nodiscard]] Rgb8 box_fill_color(Theme theme) noexcept;
/// Discs with less contrast than this against the box get an outline.
inline constexpr double min_disc_contrast = 3.0;

/// How a caption fits the lesson level's caption line (one line across the frame).
struct CaptionFit {
    bool fits = true;                ///< also true where no caption is shown (none, full, compact)
    std::size_t max_characters = 0;  ///< when it does not fit: how many of its characters do
};
/// Measures `caption` (UTF-8) with the lesson font of `config`'s frame size against the caption
/// line's width. Throws collide::Error (runtime) when the font cannot be loaded.
[[nodiscard]] CaptionFit fit_caption(const RenderConfig& config, std::string_view caption);

/// The perceptual colormap used for speed and mass (dark blue-violet -> teal -> yellow), t in
/// [0, 1] (clamped). Exposed for tests and for anyone drawing a matching legend.
[[nodiscard]] Rgb8 colormap(double t) noexcept;

}  // namespace collide::render
