#pragma once
/// \file
/// The words of the collision video's plots and of its cost graphic's values: the titles, the
/// curve's name, the axis words and the scales' labels (the renderer paints them where they fit).

#include <string>
#include <vector>

#include "collide/view/collision.hpp"
#include "collide/view/plots.hpp"

namespace collide::show {

/// The speed plot's words for a video whose fixed speed range tops at `speed_max`: the range as
/// "v max" and three significant digits in the strip, two at the axis's end in the column.
[[nodiscard]] SpeedPlotWords speed_plot_words(double speed_max);

/// The smallest drift scale: round-off drift (1e-15) must not fill the plot.
inline constexpr double smallest_drift_scale = 1e-12;

/// The drift plot's scale, the largest |drift| of the points of `series` with a finite time and
/// drift (at least smallest_drift_scale), and its title "energy drift  ±0.03". O(points).
[[nodiscard]] DriftPlotWords drift_plot_words(const std::vector<std::vector<DriftPoint>>& series);

/// The cost graphic's value: the work rounded to a whole count with thousands separators
/// ("12,345,678"; at most 9e18).
[[nodiscard]] std::string cost_text(double cost);

/// The same in words where its digits do not fit: "12.3 million", "4.56 billion".
[[nodiscard]] std::string cost_in_words(double cost);

/// The time-driven panel's cost label: its work (work_done, collide/show/collision.hpp) is pair
/// tests, the overlap checks and the contact-time computations of its roll-backs. `render` and
/// `thumbnail` print the same figure under the same words (time_driven_work_line,
/// collide/show/collision.hpp).
inline constexpr const char* time_driven_cost_label = "pair tests";

}  // namespace collide::show
