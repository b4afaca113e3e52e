// The words of the collision video's plots and of its cost graphic's values
// (collide/show/plot_words.hpp): what the renderer is handed to paint where it fits.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "collide/show/collision.hpp"
#include "collide/show/plot_words.hpp"

using namespace collide;
using namespace collide::show;

namespace {

/// Each choice strictly shorter than the one before it (the painter takes the first that fits).
bool longest_first(const std::vector<std::string>& choices) {
    for (std::size_t i = 1; i < choices.size(); ++i) {
        if (choices[i].size() >= choices[i - 1].size()) return false;
    }
    return !choices.empty();
}

}  // namespace

TEST_CASE("the speed plot's words: titles longest first, the range's top, the axis words") {
    const SpeedPlotWords w = speed_plot_words(1.5);
    CHECK(w.titles.front() == "speed distribution vs Maxwell-Boltzmann");
    CHECK(w.titles.back() == "speeds vs MB");
    CHECK(longest_first(w.titles));
    CHECK(w.range == "v max 1.5");
    CHECK(w.lesson_titles == std::vector<std::string>{"Speeds of moving discs", "Speeds"});
    CHECK(w.curve_names == std::vector<std::string>{"Maxwell-Boltzmann", "Maxwell"});
    CHECK(longest_first(w.lesson_titles));
    CHECK(longest_first(w.curve_names));
    CHECK(w.axis_low == "0");
    CHECK(w.axis_quantity == "speed");
    CHECK(w.axis_high == "1.5");
    CHECK(w.axis_slow == "slow");
    CHECK(w.axis_fast == "fast");
    // The strip says the range in three significant digits, the column's axis in two.
    const SpeedPlotWords narrow = speed_plot_words(0.123456);
    CHECK(narrow.range == "v max 0.123");
    CHECK(narrow.axis_high == "0.12");
    CHECK(speed_plot_words(2500.0).range == "v max 2.5e+03");
}

TEST_CASE("the drift plot's scale is the largest finite |drift| of every series, and its title") {
    const std::vector<std::vector<DriftPoint>> series = {
        {{0.0, 0.0}, {1.0, 0.01}, {2.0, -0.03}},
        {{0.0, 0.0}, {1.0, 0.02}},
    };
    const DriftPlotWords w = drift_plot_words(series);
    CHECK(w.scale == 0.03);
    CHECK(w.title == "energy drift  \u00b10.03");
    // Points without a finite time or drift are left out (they break the line, not the scale).
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const DriftPlotWords broken =
        drift_plot_words({{{0.0, 1e-4}, {1.0, inf}, {2.0, nan}, {inf, 0.5}, {nan, -0.5}}});
    CHECK(broken.scale == 1e-4);
    CHECK(broken.title == "energy drift  \u00b10.0001");
    // Round-off drift, or none at all, never fills the plot: the scale has a floor.
    CHECK(drift_plot_words({{{0.0, 0.0}, {1.0, 1e-16}}}).scale == smallest_drift_scale);
    const DriftPlotWords none = drift_plot_words({});
    CHECK(none.scale == smallest_drift_scale);
    CHECK(none.title == "energy drift  \u00b11e-12");
}

TEST_CASE("the cost graphic's value: digits with separators, or millions and billions in words") {
    CHECK(cost_text(0.0) == "0");
    CHECK(cost_text(1234567.4) == "1,234,567");
    CHECK(cost_text(1234567.5) == "1,234,568");
    CHECK(cost_text(1e20) == "9,000,000,000,000,000,000");  // capped: a long long holds it
    CHECK(cost_in_words(12'345'678.0) == "12.3 million");
    CHECK(cost_in_words(999'000'000.0) == "999 million");
    CHECK(cost_in_words(1e9) == "1 billion");
    CHECK(cost_in_words(11.16e9) == "11.2 billion");
    // Each panel's words carry both, of the same work.
    Measurements m;
    m.overlap_checks = 11'160'000'000ULL;
    const PanelWords td = panel_words(m, true, true, 0.0);
    CHECK(td.cost_text == "11,160,000,000");
    CHECK(td.cost_words == "11.2 billion");
    const PanelWords ed = panel_words(m, false, true, 0.0);
    CHECK(ed.cost_text == "0");
}
