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
#include <vector>

#include "collide/image.hpp"
#include "collide/render/context.hpp"
#include "collide/snapshot.hpp"

namespace collide::render {

/// How discs are coloured.
enum class ColorMode {
    scene,  ///< the scene's own colour for each disc
    speed,  ///< |v| through a perceptual colormap over [speed_min, speed_max] (legend shown)
    mass,   ///< mass through the colormap over [mass_min, mass_max] (log scale)
    tag,    ///< tagged discs highlighted, the others grey
};

/// "scene" / "speed" / "mass" / "tag".
[[nodiscard]] std::string_view color_mode_name(ColorMode mode) noexcept;
/// Parses a colour mode name; throws collide::Error (input) naming `field` otherwise.
[[nodiscard]] ColorMode parse_color_mode(std::string_view text,
                                         std::string_view field = "color_mode");

/// Everything that stays fixed for a whole video.
struct RenderConfig {
    int width = 1280;  ///< frame width in pixels, >= 64 (encoders want it even; not enforced here)
    int height = 720;  ///< frame height in pixels, >= 64
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
    bool overlays = true;   ///< titles, counters, legend and the bottom strip; off = discs only
    /// Font for all text (DejaVu Sans from fonts-dejavu-core). A missing file is a runtime error
    /// when the Renderer is constructed with overlays on.
    std::string font_path = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

    /// Throws collide::Error (input) naming the first bad field ("render.width: must be >= 64").
    void validate() const;
};

/// One simulation shown in one panel.
struct PanelContent {
    const Snapshot* snapshot = nullptr;  ///< not owned; must stay valid during render()
    std::string title;                   ///< e.g. "Event-driven (priority queue)"
    std::vector<std::string> counters;   ///< lines shown under the title ("collisions 1234")
};

/// One sample of an energy drift series: relative drift (E(t) - E(0)) / E(0) at time t.
struct DriftPoint {
    double time = 0.0;
    double drift = 0.0;
};

/// Everything drawn in one frame. Panels are laid out left to right in the given order (1 or 2
/// panels; convention: time-driven left, event-driven right). Failure markers are drawn for any
/// panel whose snapshot carries them (overlapping_pairs, missed_collisions, escaped discs).
struct FrameContent {
    std::vector<PanelContent> panels;
    std::string time_text;  ///< e.g. "t = 3.25   (x0.5 speed)"
    /// One series per panel (same order as `panels`; may be empty or shorter), oldest first.
    std::vector<std::vector<DriftPoint>> energy_drift;
    std::vector<std::string> notes;  ///< notice line(s) at the bottom, e.g. what the viewer sees
};

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
    /// there are not 1 or 2 panels.
    [[nodiscard]] Image render(const FrameContent& frame);
    /// Same, reusing `out`'s storage (resized as needed): no allocation per frame.
    void render(const FrameContent& frame, Image& out);

    /// The two halves of render(), exposed for benchmarks: draw only (GL commands issued and
    /// finished), then read back the last drawn frame (its text is blended in on the CPU then).
    void draw(const FrameContent& frame);
    void read_pixels(Image& out);

    /// Forgets all trail history (e.g. after seeking).
    void reset_trails();

    [[nodiscard]] Backend backend() const noexcept;
    [[nodiscard]] const RenderConfig& config() const noexcept;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// The perceptual colormap used for speed and mass (dark blue-violet -> teal -> yellow), t in
/// [0, 1] (clamped). Exposed for tests and for anyone drawing a matching legend.
[[nodiscard]] Rgb8 colormap(double t) noexcept;

}  // namespace collide::render
