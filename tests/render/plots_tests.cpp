// The strip's plot statistics and the drift plot's thinning, tested as pure functions; how the
// plots place and choose the words they are handed (the words themselves are collide_show's,
// tested in tests/show/test_plot_words.cpp).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include "../support/skip.hpp"
#include "collide/show/plot_words.hpp"
#include "layout.hpp"
#include "plots.hpp"
#include "theme.hpp"

namespace collide::render {
namespace {

// Pixel columns of width `per_column` time units starting at t = 0.
auto columns_of_width(double per_column) {
    return [per_column](double t) { return static_cast<std::int64_t>(std::floor(t / per_column)); };
}

std::vector<DriftPoint> random_walk(std::size_t count, double dt, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> step(0.0, 1e-3);
    std::vector<DriftPoint> series;
    double drift = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        series.push_back({static_cast<double>(i) * dt, drift});
        drift += step(rng);
    }
    return series;
}

bool strictly_increasing(const std::vector<std::size_t>& v) {
    return std::adjacent_find(v.begin(), v.end(), std::greater_equal<>()) == v.end();
}

TEST_CASE("a drift series with at most four points per pixel column is drawn point for point") {
    const std::vector<DriftPoint> series = random_walk(400, 0.25, 1);  // 4 points per column
    const std::vector<std::size_t> kept = drift_points_to_draw(series, columns_of_width(1.0));
    std::vector<std::size_t> all(series.size());
    std::iota(all.begin(), all.end(), std::size_t{0});
    CHECK(kept == all);
}

TEST_CASE("a long drift series keeps per column its first, lowest, highest and last points") {
    const std::size_t per_column = 50;
    const std::size_t columns = 300;
    const std::vector<DriftPoint> series = random_walk(per_column * columns, 0.02, 2);
    const std::vector<std::size_t> kept = drift_points_to_draw(series, columns_of_width(1.0));
    REQUIRE(strictly_increasing(kept));
    CHECK(kept.size() <= 4 * columns);
    CHECK(kept.front() == 0);
    CHECK(kept.back() == series.size() - 1);

    for (std::size_t c = 0; c < columns; ++c) {
        const std::size_t begin = c * per_column;
        const std::size_t end = begin + per_column;
        const auto by_drift = [&](std::size_t a, std::size_t b) {
            return series[a].drift < series[b].drift;
        };
        std::vector<std::size_t> in_column(per_column);
        std::iota(in_column.begin(), in_column.end(), begin);
        const std::size_t low = *std::min_element(in_column.begin(), in_column.end(), by_drift);
        const std::size_t high = *std::max_element(in_column.begin(), in_column.end(), by_drift);
        const auto kept_here = [&](std::size_t i) {
            return std::binary_search(kept.begin(), kept.end(), i);
        };
        CHECK(kept_here(begin));
        CHECK(kept_here(end - 1));
        CHECK(kept_here(low));
        CHECK(kept_here(high));
        const auto count = std::count_if(kept.begin(), kept.end(),
                                         [&](std::size_t i) { return i >= begin && i < end; });
        CHECK(count <= 4);
    }
}

TEST_CASE("non-finite drift points are kept and split the run of their column") {
    std::vector<DriftPoint> series = random_walk(100, 0.01, 3);  // all in column 0
    series[50].drift = std::numeric_limits<double>::quiet_NaN();
    const std::vector<std::size_t> kept = drift_points_to_draw(series, columns_of_width(1.0));
    REQUIRE(strictly_increasing(kept));
    CHECK(std::binary_search(kept.begin(), kept.end(), std::size_t{50}));
    // Both halves end and start at the gap: the line stops at the last point before the NaN.
    CHECK(std::binary_search(kept.begin(), kept.end(), std::size_t{49}));
    CHECK(std::binary_search(kept.begin(), kept.end(), std::size_t{51}));
    CHECK(kept.size() <= 9);
}

TEST_CASE("an empty drift series draws nothing") {
    CHECK(drift_points_to_draw({}, columns_of_width(1.0)).empty());
}

Snapshot discs_with_speeds(const std::vector<double>& speeds, double mass = 1.0) {
    Snapshot s;
    s.box = {1.0, 1.0, Boundary::periodic};
    for (const double v : speeds) {
        DiscState d;
        d.velocity = {v, 0.0};
        d.mass = mass;
        d.radius = 0.01;
        s.discs.push_back(d);
    }
    return s;
}

TEST_CASE("the speed histogram is a density: counts / (N x bin width), speeds outside skipped") {
    const Snapshot s = discs_with_speeds({0.1, 0.2, 0.6, 0.7, 0.8, 5.0});
    const std::vector<double> density = speed_density(s, 0.0, 1.0, 2);
    REQUIRE(density.size() == 2);
    CHECK(density[0] == doctest::Approx(2.0 / (6.0 * 0.5)));
    CHECK(density[1] == doctest::Approx(3.0 / (6.0 * 0.5)));
    CHECK(speed_density(Snapshot{}, 0.0, 1.0, 4) == std::vector<double>(4, 0.0));
}

TEST_CASE("the 2D Maxwell-Boltzmann density uses kT = mean kinetic energy and integrates to 1") {
    const Snapshot s = discs_with_speeds({1.0, 2.0, 3.0}, 2.0);  // kT = (1 + 4 + 9) / 3
    const MaxwellBoltzmann mb(s);
    CHECK(mb.kT() == doctest::Approx(14.0 / 3.0));
    const double kT = mb.kT();
    CHECK(mb.density(1.5) == doctest::Approx(2.0 * 1.5 / kT * std::exp(-2.0 * 2.25 / (2.0 * kT))));
    double area = 0.0;
    const double dv = 1e-3;
    for (double v = 0.5 * dv; v < 20.0; v += dv) area += mb.density(v) * dv;
    CHECK(area == doctest::Approx(1.0).epsilon(1e-4));
}

/// A gas of `count` unit-mass discs with speeds drawn from the 2D Maxwell-Boltzmann law.
Snapshot maxwellian_gas(std::size_t count, double kT, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> component(0.0, std::sqrt(kT));
    Snapshot s;
    s.box = {1.0, 1.0, Boundary::walls};
    for (std::size_t i = 0; i < count; ++i) {
        DiscState d;
        d.position = {0.5, 0.5};
        d.velocity = {component(rng), component(rng)};
        d.radius = 0.01;
        d.mass = 1.0;
        s.discs.push_back(d);
    }
    return s;
}

RectF triangle_bounds(const std::vector<OverlayVertex>& v, std::size_t first) {
    RectF r{v[first].x, v[first].y, v[first].x, v[first].y};
    for (std::size_t k = first; k < first + 3; ++k) {
        r.x0 = std::min(r.x0, v[k].x);
        r.y0 = std::min(r.y0, v[k].y);
        r.x1 = std::max(r.x1, v[k].x);
        r.y1 = std::max(r.y1, v[k].y);
    }
    return r;
}

TEST_CASE("the lesson speed plot in a narrow column: labelled curve, nothing drawn over its name") {
    const RenderConfig config;
    if (!std::filesystem::exists(config.font_path)) {
        COLLIDE_SKIP_TEST("no DejaVu Sans at " << config.font_path);
    }
    // The column of a 720p lesson frame with a small plot, and a large plot's area.
    for (const RectF area :
         {RectF{532.0F, 420.0F, 747.0F, 575.0F}, RectF{800.0F, 100.0F, 1184.0F, 420.0F}}) {
        INFO("plot " << area.width() << " x " << area.height());
        const FontAtlas font(config.font_path, lesson_pixel_height(1280, 720));
        const SpeedPlotWords words = show::speed_plot_words(0.35);
        const SpeedPlotLayout parts = speed_plot_layout(font, area, words);
        CHECK(parts.title_text.empty() == (area.height() < 200.0F));  // no room for a title
        CHECK(parts.curve_label.width() <= area.width());
        CHECK(std::count(words.curve_names.begin(), words.curve_names.end(), parts.curve_name) ==
              1);
        CHECK(parts.data.height() >= 2.0F * font.line_height());
        // Two panels' histograms, one hotter (its bins pile up under the name if not cut).
        const Snapshot cool = maxwellian_gas(800, 0.01, 1);
        const Snapshot hot = maxwellian_gas(800, 0.04, 2);
        OverlayBatch shapes;
        OverlayBatch text;
        draw_moving_speed_plot(shapes, text, font, area, {&hot, &cool},
                               {{240, 150, 60}, {90, 175, 245}}, 0.0, 0.35, words,
                               dark_plot_colors);
        const std::vector<OverlayVertex>& v = shapes.vertices();
        REQUIRE(v.size() % 3 == 0);
        REQUIRE(v.size() > 100);  // bars and curve were drawn
        const RectF name{parts.curve_label.x0 + 1.0F, parts.curve_label.y0 + 1.0F,
                         parts.curve_label.x1 - 1.0F, parts.curve_label.y1 - 1.0F};
        // Strokes may reach half the curve's width (2.5 line widths) past the plot's edge.
        const float spill = 1.25F * std::max(1.0F, std::round(font.pixel_height() / 12.0F)) + 1.0F;
        int over_name = 0;
        for (std::size_t k = 0; k < v.size(); k += 3) {
            const RectF t = triangle_bounds(v, k);
            if (overlaps(t, name)) ++over_name;
            CHECK(t.x0 >= area.x0 - spill);
            CHECK(t.x1 <= area.x1 + spill);
            CHECK(t.y0 >= area.y0 - spill);
            CHECK(t.y1 <= area.y1);
        }
        CHECK(over_name == 0);
        // Every glyph (name, axis labels, title) is inside the area.
        REQUIRE_FALSE(text.glyphs().empty());
        for (const GlyphBox& g : text.glyphs()) {
            CHECK(static_cast<float>(g.x) >= area.x0 - 1.0F);
            CHECK(static_cast<float>(g.x + g.width) <= area.x1 + 1.0F);
            CHECK(static_cast<float>(g.y + g.height) <= area.y1 + 1.0F);
        }
    }
}

}  // namespace
}  // namespace collide::render

namespace collide::render {
namespace {

TEST_CASE("the drift plot draws each series in the colour given for it") {
    const RenderConfig config;
    if (!std::filesystem::exists(config.font_path)) {
        COLLIDE_SKIP_TEST("no DejaVu Sans at " << config.font_path);
    }
    const FontAtlas font(config.font_path, 14);
    const Rgb8 blue{90, 175, 245};
    const Rgb8 orange{240, 150, 60};
    const auto count_of = [](const OverlayBatch& batch, Rgb8 c) {
        return std::count_if(batch.vertices().begin(), batch.vertices().end(),
                             [&](const OverlayVertex& v) {
                                 return v.color.r == c.r && v.color.g == c.g && v.color.b == c.b;
                             });
    };
    const std::vector<std::vector<DriftPoint>> one = {{{0.0, 0.0}, {1.0, 1e-3}, {2.0, -1e-3}}};
    OverlayBatch shapes;
    OverlayBatch text;
    const DriftPlotWords words{1e-3, "drift"};
    draw_drift_plot(shapes, text, font, {0.0F, 0.0F, 300.0F, 120.0F}, one, words, {blue});
    CHECK(count_of(shapes, blue) > 0);
    CHECK(count_of(shapes, orange) == 0);
    OverlayBatch two_shapes;
    draw_drift_plot(two_shapes, text, font, {0.0F, 0.0F, 300.0F, 120.0F}, {one[0], one[0]}, words,
                    {orange, blue});
    CHECK(count_of(two_shapes, orange) > 0);
    CHECK(count_of(two_shapes, blue) > 0);
}

}  // namespace
}  // namespace collide::render

namespace collide::render {
namespace {

/// The glyphs' horizontal extent, or an empty box for none.
RectF glyph_extent(const OverlayBatch& text) {
    if (text.glyphs().empty()) return {};
    RectF r{1e9F, 1e9F, -1e9F, -1e9F};
    for (const GlyphBox& g : text.glyphs()) {
        r.x0 = std::min(r.x0, static_cast<float>(g.x));
        r.y0 = std::min(r.y0, static_cast<float>(g.y));
        r.x1 = std::max(r.x1, static_cast<float>(g.x + g.width));
        r.y1 = std::max(r.y1, static_cast<float>(g.y + g.height));
    }
    return r;
}

TEST_CASE("the speed plot layout takes the first of the words handed that fits, else the last") {
    const RenderConfig config;
    if (!std::filesystem::exists(config.font_path)) {
        COLLIDE_SKIP_TEST("no DejaVu Sans at " << config.font_path);
    }
    const FontAtlas font(config.font_path, 14);
    SpeedPlotWords words;
    words.lesson_titles = {"A title far too long for any plot column of this frame", "Short", "S"};
    words.curve_names = {"A curve name far too long for the column", "Curve"};
    const RectF narrow{0.0F, 0.0F, 160.0F, 400.0F};
    SpeedPlotLayout parts = speed_plot_layout(font, narrow, words);
    CHECK(parts.title_text == "Short");
    CHECK(parts.curve_name == "Curve");
    const RectF wide{0.0F, 0.0F, 2000.0F, 400.0F};
    parts = speed_plot_layout(font, wide, words);
    CHECK(parts.title_text == words.lesson_titles.front());
    CHECK(parts.curve_name == words.curve_names.front());
    // Nothing fits a sliver: the last (shortest) one, never nothing.
    parts = speed_plot_layout(font, {0.0F, 0.0F, 4.0F, 400.0F}, words);
    CHECK(parts.title_text == "S");
    CHECK(parts.curve_name == "Curve");
}

TEST_CASE("the drift plot scales its series by the scale it is handed and writes its title") {
    const RenderConfig config;
    if (!std::filesystem::exists(config.font_path)) {
        COLLIDE_SKIP_TEST("no DejaVu Sans at " << config.font_path);
    }
    const FontAtlas font(config.font_path, 14);
    const Rgb8 blue{90, 175, 245};
    const std::vector<std::vector<DriftPoint>> one = {{{0.0, 0.0}, {1.0, 1e-3}, {2.0, -1e-3}}};
    const RectF area{0.0F, 0.0F, 300.0F, 120.0F};
    // The vertical extent of the series' strokes at a scale.
    const auto extent = [&](double scale) {
        OverlayBatch shapes;
        OverlayBatch text;
        draw_drift_plot(shapes, text, font, area, one, {scale, "energy drift"}, {blue});
        float y0 = 1e9F;
        float y1 = -1e9F;
        for (const OverlayVertex& v : shapes.vertices()) {
            if (v.color.r != blue.r || v.color.g != blue.g || v.color.b != blue.b) continue;
            y0 = std::min(y0, v.y);
            y1 = std::max(y1, v.y);
        }
        return y1 > y0 ? y1 - y0 : 0.0F;
    };
    // The series spans the plot at its own largest |drift|, half of it at twice that.
    const float full = extent(1e-3);
    CHECK(full > 60.0F);
    CHECK(extent(2e-3) == doctest::Approx(0.5F * full).epsilon(0.1));
    // No scale (0): the frame and the title, no series.
    CHECK(extent(0.0) == 0.0F);
    OverlayBatch shapes;
    OverlayBatch with_title;
    draw_drift_plot(shapes, with_title, font, area, one, {1e-3, "energy drift"}, {blue});
    OverlayBatch without_title;
    draw_drift_plot(shapes, without_title, font, area, one, {1e-3, ""}, {blue});
    CHECK(with_title.glyphs().size() > without_title.glyphs().size());
    CHECK(glyph_extent(with_title).y1 <= area.y0 + font.line_height() + 1.0F);  // a title line
}

}  // namespace
}  // namespace collide::render
