#pragma once
/// \file
/// The words of the collision video's plots (the speed histogram against Maxwell-Boltzmann, the
/// energy drift): filled by the presentation layer (show::speed_plot_words,
/// show::drift_plot_words), painted by the renderer. Where a plot offers alternatives, longest
/// first, the painter draws the first that fits its room, else the last. Plain values.

#include <string>
#include <vector>

namespace collide {

/// The speed plot's words at both levels; the plot's range is the video's fixed speed range.
struct SpeedPlotWords {
    // Full level (the strip): a title line, with the range at its right end when both fit.
    std::vector<std::string> titles;  ///< "speed distribution vs Maxwell-Boltzmann", ...
    std::string range;                ///< "v max 1.5"
    // Lesson level (the column): a title over a roomy plot, the curve's name, the speed axis.
    std::vector<std::string> lesson_titles;  ///< "Speeds of moving discs", "Speeds"
    std::vector<std::string> curve_names;    ///< "Maxwell-Boltzmann", "Maxwell"
    std::string axis_low;                    ///< at the axis's left end: "0"
    std::string axis_quantity;               ///< under the axis's middle: "speed"
    std::string axis_high;                   ///< at the axis's right end: the range's top, "0.5"
    /// At the axis's ends instead where the three above do not fit apart: "slow", "fast".
    std::string axis_slow;
    std::string axis_fast;
};

/// The energy drift plot's scale and title, from the frame's drift series.
struct DriftPlotWords {
    /// The largest |relative drift| drawn: the plot's half height (0: nothing to scale by).
    double scale = 0.0;
    std::string title;  ///< "energy drift  ±0.03" (the scale)
};

}  // namespace collide
