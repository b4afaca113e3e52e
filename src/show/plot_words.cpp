// The plots' words (collide/show/plot_words.hpp): what the speed histogram, the energy drift plot
// and the cost graphic's values say, in the numbers' printf formats the renderer once used.
#include "collide/show/plot_words.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "collide/number_text.hpp"

namespace collide::show {
namespace {

std::string format_number(const char* format, double value) {
    char text[48];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

}  // namespace

SpeedPlotWords speed_plot_words(double speed_max) {
    SpeedPlotWords out;
    out.titles = {"speed distribution vs Maxwell-Boltzmann", "speeds vs Maxwell-Boltzmann",
                  "speeds vs MB"};
    out.range = format_number("v max %.3g", speed_max);
    out.lesson_titles = {"Speeds of moving discs", "Speeds"};
    out.curve_names = {"Maxwell-Boltzmann", "Maxwell"};
    out.axis_low = "0";
    out.axis_quantity = "speed";
    out.axis_high = format_number("%.2g", speed_max);
    out.axis_slow = "slow";
    out.axis_fast = "fast";
    return out;
}

DriftPlotWords drift_plot_words(const std::vector<std::vector<DriftPoint>>& series) {
    double largest = 0.0;
    for (const std::vector<DriftPoint>& s : series) {
        for (const DriftPoint& p : s) {
            if (!std::isfinite(p.drift) || !std::isfinite(p.time)) continue;
            largest = std::max(largest, std::abs(p.drift));
        }
    }
    DriftPlotWords out;
    out.scale = std::max(largest, smallest_drift_scale);
    out.title = "energy drift  " + format_number("\xC2\xB1%.2g", out.scale);
    return out;
}

std::string cost_text(double cost) {
    return with_separators(static_cast<long long>(std::llround(std::min(cost, 9.0e18))));
}

std::string cost_in_words(double cost) {
    return cost >= 1e9 ? format_number("%.3g billion", cost / 1e9)
                       : format_number("%.3g million", cost / 1e6);
}

}  // namespace collide::show
