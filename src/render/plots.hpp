#pragma once
// Internal: the strip's small plots (speed histogram vs 2D Maxwell-Boltzmann, energy drift),
// built as overlay triangles, and the statistics behind them (pure, tested directly).

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "collide/render/renderer.hpp"
#include "collide/snapshot.hpp"
#include "font.hpp"
#include "overlay_geometry.hpp"

namespace collide::render {

/// Histogram of |v| as a probability density over [v_min, v_max] with `bins` bins (speeds
/// outside the range are counted in no bin, so the area is the fraction inside). O(N).
/// Discs of mass `heavy` or more (and non-finite masses) are left out when `heavy` is given
/// (moving_mass_limit: the moving discs only, without copying them).
[[nodiscard]] std::vector<double> speed_density(
    const Snapshot& snapshot, double v_min, double v_max, int bins,
    double heavy = std::numeric_limits<double>::infinity());

/// The 2D Maxwell-Boltzmann speed density of a snapshot's temperature, kT = mean kinetic
/// energy per disc (k_B = 1): with several masses a mixture, one term per mass weighted by its
/// share of discs: f(v) = sum_g (n_g/N) (m_g v / kT) exp(-m_g v^2 / 2kT). For discs standing in
/// for spheres (Snapshot::dimension 3) the 3D law: kT = 2/3 of the mean kinetic energy and
/// f(v) = sum_g (n_g/N) sqrt(2/pi) (m_g/kT)^(3/2) v^2 exp(-m_g v^2 / 2kT).
class MaxwellBoltzmann {
  public:
    /// Over the discs lighter than `heavy` (all finite-mass discs by default).
    explicit MaxwellBoltzmann(const Snapshot& snapshot,
                              double heavy = std::numeric_limits<double>::infinity());
    [[nodiscard]] double kT() const noexcept { return kT_; }
    [[nodiscard]] double density(double speed) const noexcept;

  private:
    struct Group {
        double mass;
        double weight;  // share of discs with this mass
    };
    double kT_ = 0.0;
    int dimension_ = 2;
    std::vector<Group> groups_;
};

/// Colours of a plot's text, axes and reference curve: the theme's (theme.hpp: plot_colors).
struct PlotColors {
    Rgba8 label;
    Rgba8 axis;
    Rgba8 curve;
    Rgba8 zero_line;  ///< the drift plot's zero
};

/// Shapes go to `batch`, text to `text`.
/// Draws the histograms of every snapshot's moving discs (step outlines in `series_colors`, one
/// per snapshot: each panel's engine accent) and the Maxwell-Boltzmann curve of the last one's
/// inside `area`, under the first of `words.titles` that leaves room for `words.range` (the
/// range only when it fits).
void draw_speed_plot(OverlayBatch& batch, OverlayBatch& text, const FontAtlas& font, RectF area,
                     const std::vector<const Snapshot*>& snapshots,
                     const std::vector<Rgb8>& series_colors, double v_min, double v_max,
                     const SpeedPlotWords& words, const PlotColors& colors = {});

/// The indices (increasing) of the points of `series` worth drawing, `column` mapping a time to
/// its pixel column: of each run of consecutive points in one column, the first, the lowest, the
/// highest and the last (every point of a run of at most four). A polyline through them covers
/// the same pixels as one through every point, so the plot of a long video costs O(plot width)
/// segments per frame instead of one more segment per frame for ever. Points with a non-finite
/// time or drift are kept (they break the line) and end a run.
[[nodiscard]] std::vector<std::size_t> drift_points_to_draw(
    const std::vector<DriftPoint>& series, const std::function<std::int64_t(double)>& column);

/// Draws relative energy drift against time, one polyline per series in `series_colors` (one per
/// series: each panel's engine accent), +-`words.scale` over the plot's height, under
/// `words.title`, with the zero line (no polylines for a scale that is not positive).
void draw_drift_plot(OverlayBatch& batch, OverlayBatch& text, const FontAtlas& font, RectF area,
                     const std::vector<std::vector<DriftPoint>>& series,
                     const DriftPlotWords& words, const std::vector<Rgb8>& series_colors,
                     const PlotColors& colors = {});

/// The snapshot's discs that can move (finite mass below immovable_mass_ratio x the lightest,
/// collide/disc.hpp: barriers and walls of heavy discs are not part of the speed distribution).
[[nodiscard]] Snapshot moving_discs(const Snapshot& snapshot);
/// The mass from which a disc of `snapshot` counts as immovable: immovable_mass_ratio x the
/// lightest (infinity for no discs). O(N), no copy.
[[nodiscard]] double moving_mass_limit(const Snapshot& snapshot) noexcept;

/// Where the lesson speed plot puts its parts inside its area (pure, tested): where the area is
/// tall enough, a title line and the curve's name on a line of its own above the data area;
/// otherwise the name inside the data area's top right corner (bars and curve stay below it);
/// the axis labels' line under the data area. The title and the name are the first of `words`'
/// lesson_titles and curve_names as wide as the area at most (else the last).
struct SpeedPlotLayout {
    RectF title;        ///< empty when there is no room for a title line
    RectF data;         ///< histogram bars and the curve
    RectF curve_label;  ///< the curve's name (nothing else is drawn there)
    RectF axis;         ///< "0", "speed" and the top speed
    std::string title_text;
    std::string curve_name;  ///< "Maxwell-Boltzmann", or "Maxwell" where that does not fit
};
[[nodiscard]] SpeedPlotLayout speed_plot_layout(const FontAtlas& font, RectF area,
                                                const SpeedPlotWords& words);

/// Lesson plot: histograms of the moving discs' speeds (one per snapshot, in `colors`) on the
/// fixed range [v_min, v_max] and a fixed height, with the labelled Maxwell-Boltzmann curve of
/// the last snapshot's moving discs and the axis labelled. Shapes go to `batch`, text to `text`.
/// With `axis_colors` (t in [0, 1] from v_min to v_max to a colour) the speed axis is drawn as a
/// colour bar: the discs' speed colours, so no separate colour legend is needed. The words are
/// `words`' lesson ones; the axis says "0  speed  v_max", or "slow .. fast" where that does not
/// fit.
void draw_moving_speed_plot(OverlayBatch& batch, OverlayBatch& text, const FontAtlas& font,
                            RectF area, const std::vector<const Snapshot*>& snapshots,
                            const std::vector<Rgb8>& colors, double v_min, double v_max,
                            const SpeedPlotWords& words, const PlotColors& palette,
                            const std::function<Rgb8(double)>& axis_colors = {});

}  // namespace collide::render
