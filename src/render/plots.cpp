#include "plots.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace collide::render {
namespace {

// Beyond this many distinct masses, one curve at the mean mass is a fair summary.
constexpr std::size_t max_mass_groups = 16;

/// The first of `choices` (longest first) no wider than `room`, else the last; "" for none.
const std::string& first_that_fits(const FontAtlas& font, const std::vector<std::string>& choices,
                                   float room) {
    static const std::string none;
    for (const std::string& choice : choices) {
        if (font.text_width(choice) <= room) return choice;
    }
    return choices.empty() ? none : choices.back();
}

struct PlotAxes {
    RectF plot;  // the data area
    float line_width;
};

// Title line above, axes along the bottom and left.
PlotAxes draw_axes(OverlayBatch& batch, OverlayBatch& text, const FontAtlas& font, RectF area,
                   const std::string& title, const PlotColors& colors) {
    const float line = std::max(1.0F, std::round(font.pixel_height() / 12.0F));
    font.add_text(text, area.x0, area.y0 + font.ascent(), title, colors.label);
    RectF plot{area.x0, area.y0 + font.line_height(), area.x1, area.y1};
    if (plot.y1 <= plot.y0 + 2.0F) plot.y0 = plot.y1 - 2.0F;
    batch.add_rect({plot.x0, plot.y1 - line, plot.x1, plot.y1}, colors.axis);
    batch.add_rect({plot.x0, plot.y0, plot.x0 + line, plot.y1}, colors.axis);
    return {plot, line};
}

bool is_finite(const DriftPoint& p) {
    return std::isfinite(p.time) && std::isfinite(p.drift);
}

// Appends the indices to draw of the run [begin, end) of finite points in one pixel column.
void keep_run(const std::vector<DriftPoint>& s, std::size_t begin, std::size_t end,
              std::vector<std::size_t>& keep) {
    constexpr std::size_t all_kept = 4;
    if (end - begin <= all_kept) {
        for (std::size_t i = begin; i < end; ++i) keep.push_back(i);
        return;
    }
    std::size_t low = begin;
    std::size_t high = begin;
    for (std::size_t i = begin + 1; i < end; ++i) {
        if (s[i].drift < s[low].drift) low = i;
        if (s[i].drift > s[high].drift) high = i;
    }
    std::array<std::size_t, 4> picked{begin, low, high, end - 1};
    std::sort(picked.begin(), picked.end());
    const auto last = std::unique(picked.begin(), picked.end());
    keep.insert(keep.end(), picked.begin(), last);
}

}  // namespace

std::vector<std::size_t> drift_points_to_draw(const std::vector<DriftPoint>& series,
                                              const std::function<std::int64_t(double)>& column) {
    std::vector<std::size_t> keep;
    std::size_t i = 0;
    while (i < series.size()) {
        if (!is_finite(series[i])) {
            keep.push_back(i++);
            continue;
        }
        const std::int64_t here = column(series[i].time);
        std::size_t end = i + 1;
        while (end < series.size() && is_finite(series[end]) && column(series[end].time) == here) {
            ++end;
        }
        keep_run(series, i, end, keep);
        i = end;
    }
    return keep;
}

namespace {
bool counted(const DiscState& d, double heavy) noexcept {
    return std::isfinite(d.mass) && d.mass < heavy;
}
}  // namespace

std::vector<double> speed_density(const Snapshot& snapshot, double v_min, double v_max, int bins,
                                  double heavy) {
    std::vector<double> density(static_cast<std::size_t>(std::max(bins, 1)), 0.0);
    if (snapshot.discs.empty() || !(v_max > v_min)) return density;
    const double width = (v_max - v_min) / static_cast<double>(density.size());
    std::size_t discs = 0;
    for (const DiscState& d : snapshot.discs) {
        if (!counted(d, heavy)) continue;
        ++discs;
        const double bin = std::floor((norm(d.velocity) - v_min) / width);
        if (bin >= 0.0 && bin < static_cast<double>(density.size())) {
            density[static_cast<std::size_t>(bin)] += 1.0;
        }
    }
    if (discs == 0) return density;
    const double scale = 1.0 / (static_cast<double>(discs) * width);
    for (double& value : density) value *= scale;
    return density;
}

MaxwellBoltzmann::MaxwellBoltzmann(const Snapshot& snapshot, double heavy) {
    // Masses and their counts: a short list (one or a few masses), searched linearly; beyond
    // max_mass_groups distinct masses one group at the mean mass.
    std::vector<std::pair<double, double>> counts;
    bool many_masses = false;
    double kinetic = 0.0;
    double mass_sum = 0.0;
    std::size_t discs = 0;
    for (const DiscState& d : snapshot.discs) {
        if (!counted(d, heavy)) continue;
        ++discs;
        kinetic += 0.5 * d.mass * norm2(d.velocity);
        mass_sum += d.mass;
        if (many_masses) continue;
        const auto it = std::find_if(counts.begin(), counts.end(),
                                     [&](const auto& c) { return c.first == d.mass; });
        if (it != counts.end()) {
            it->second += 1.0;
        } else if (counts.size() < max_mass_groups) {
            counts.emplace_back(d.mass, 1.0);
        } else {
            many_masses = true;
        }
    }
    if (discs == 0) return;
    const auto n = static_cast<double>(discs);
    dimension_ = snapshot.dimension == 3 ? 3 : 2;
    kT_ = dimension_ == 3 ? 2.0 * kinetic / (3.0 * n) : kinetic / n;
    if (many_masses) {
        groups_.push_back({mass_sum / n, 1.0});
    } else {
        std::sort(counts.begin(), counts.end());
        for (const auto& [mass, count] : counts) groups_.push_back({mass, count / n});
    }
}

double MaxwellBoltzmann::density(double speed) const noexcept {
    if (!(kT_ > 0.0) || speed < 0.0) return 0.0;
    double f = 0.0;
    if (dimension_ == 3) {
        for (const Group& g : groups_) {
            const double a = g.mass / kT_;
            f += g.weight * std::sqrt(2.0 / std::numbers::pi) * a * std::sqrt(a) * speed * speed *
                 std::exp(-0.5 * a * speed * speed);
        }
        return f;
    }
    for (const Group& g : groups_) {
        f += g.weight * (g.mass * speed / kT_) * std::exp(-g.mass * speed * speed / (2.0 * kT_));
    }
    return f;
}

namespace {
/// Series p's colour: its panel's accent (the curve's colour for a series without one).
Rgb8 series_color(const std::vector<Rgb8>& series_colors, std::size_t p, Rgba8 fallback) noexcept {
    return p < series_colors.size() ? series_colors[p] : Rgb8{fallback.r, fallback.g, fallback.b};
}
}  // namespace

void draw_speed_plot(OverlayBatch& batch, OverlayBatch& text, const FontAtlas& font, RectF area,
                     const std::vector<const Snapshot*>& snapshots,
                     const std::vector<Rgb8>& series_colors, double v_min, double v_max,
                     const SpeedPlotWords& words, const PlotColors& colors) {
    // The longest title that leaves room for the range label (narrow frames get the short one).
    const std::string& range = words.range;
    const float room = area.width() - font.text_width(range) - font.pixel_height();
    const std::string& title = first_that_fits(font, words.titles, room);
    const bool show_range = font.text_width(title) <= room;
    const PlotAxes frame = draw_axes(batch, text, font, area, title, colors);
    const RectF plot = frame.plot;
    if (snapshots.empty() || plot.width() < 4.0F) return;
    const int bins = std::clamp(static_cast<int>(plot.width() / 6.0F), 8, 40);
    std::vector<std::vector<double>> histograms;
    double peak = 0.0;
    for (const Snapshot* s : snapshots) {
        // Moving discs only: barriers of still, heavy discs are not part of the gas.
        histograms.push_back(speed_density(*s, v_min, v_max, bins, moving_mass_limit(*s)));
        peak =
            std::max(peak, *std::max_element(histograms.back().begin(), histograms.back().end()));
    }
    const MaxwellBoltzmann curve(*snapshots.back(), moving_mass_limit(*snapshots.back()));
    constexpr int curve_samples = 64;
    std::vector<double> curve_values(curve_samples + 1);
    for (int i = 0; i <= curve_samples; ++i) {
        curve_values[static_cast<std::size_t>(i)] =
            curve.density(v_min + (v_max - v_min) * i / curve_samples);
        peak = std::max(peak, curve_values[static_cast<std::size_t>(i)]);
    }
    if (!(peak > 0.0)) return;
    const double y_scale = static_cast<double>(plot.height() - frame.line_width) / (peak * 1.1);
    const auto to_y = [&](double value) {
        return plot.y1 - frame.line_width - static_cast<float>(value * y_scale);
    };
    const float bin_width = plot.width() / static_cast<float>(bins);
    for (std::size_t p = 0; p < histograms.size(); ++p) {
        const Rgba8 color = with_alpha(series_color(series_colors, p, colors.curve), 230);
        float previous_y = to_y(0.0);
        for (int b = 0; b < bins; ++b) {
            const float x0 = plot.x0 + bin_width * static_cast<float>(b);
            const float y = to_y(histograms[p][static_cast<std::size_t>(b)]);
            batch.add_line({x0, previous_y}, {x0, y}, frame.line_width, color);
            batch.add_line({x0, y}, {x0 + bin_width, y}, frame.line_width, color);
            previous_y = y;
        }
    }
    for (int i = 0; i < curve_samples; ++i) {
        const float x0 = plot.x0 + plot.width() * static_cast<float>(i) / curve_samples;
        const float x1 = plot.x0 + plot.width() * static_cast<float>(i + 1) / curve_samples;
        batch.add_line({x0, to_y(curve_values[static_cast<std::size_t>(i)])},
                       {x1, to_y(curve_values[static_cast<std::size_t>(i) + 1])},
                       frame.line_width * 1.5F, colors.curve);
    }
    if (show_range) {
        font.add_text(text, plot.x1 - font.text_width(range), area.y0 + font.ascent(), range,
                      colors.axis);
    }
}

void draw_drift_plot(OverlayBatch& batch, OverlayBatch& text, const FontAtlas& font, RectF area,
                     const std::vector<std::vector<DriftPoint>>& series,
                     const DriftPlotWords& words, const std::vector<Rgb8>& series_colors,
                     const PlotColors& colors) {
    double t_min = 0.0;
    double t_max = 0.0;
    bool any = false;
    for (const auto& s : series) {
        for (const DriftPoint& p : s) {
            if (!is_finite(p)) continue;
            t_min = any ? std::min(t_min, p.time) : p.time;
            t_max = any ? std::max(t_max, p.time) : p.time;
            any = true;
        }
    }
    const double scale = words.scale;
    const PlotAxes frame = draw_axes(batch, text, font, area, words.title, colors);
    const RectF plot = frame.plot;
    const float mid = 0.5F * (plot.y0 + plot.y1 - frame.line_width);
    batch.add_rect({plot.x0, mid, plot.x1, mid + 1.0F}, colors.zero_line);
    if (!any || !(t_max > t_min) || !(scale > 0.0)) return;
    const auto to_x = [&](double t) {
        return plot.x0 + static_cast<float>((t - t_min) / (t_max - t_min)) * plot.width();
    };
    const float half = 0.5F * (plot.height() - frame.line_width) * 0.9F;
    const auto to_y = [&](double d) { return mid - static_cast<float>(d / scale) * half; };
    const auto column = [&](double t) { return static_cast<std::int64_t>(std::floor(to_x(t))); };
    for (std::size_t p = 0; p < series.size(); ++p) {
        const Rgba8 color = with_alpha(series_color(series_colors, p, colors.curve), 255);
        const auto& s = series[p];
        const std::vector<std::size_t> shown = drift_points_to_draw(s, column);
        for (std::size_t k = 1; k < shown.size(); ++k) {
            const DriftPoint& a = s[shown[k - 1]];
            const DriftPoint& b = s[shown[k]];
            if (!is_finite(a) || !is_finite(b)) continue;
            batch.add_line({to_x(a.time), to_y(a.drift)}, {to_x(b.time), to_y(b.drift)},
                           frame.line_width * 1.5F, color);
        }
    }
}

double moving_mass_limit(const Snapshot& snapshot) noexcept {
    double lightest = std::numeric_limits<double>::infinity();
    for (const DiscState& d : snapshot.discs) lightest = std::min(lightest, d.mass);
    return immovable_mass_ratio * lightest;
}

Snapshot moving_discs(const Snapshot& snapshot) {
    Snapshot out;
    out.time = snapshot.time;
    out.box = snapshot.box;
    const double heavy = moving_mass_limit(snapshot);
    for (const DiscState& d : snapshot.discs) {
        if (counted(d, heavy)) out.discs.push_back(d);
    }
    return out;
}

SpeedPlotLayout speed_plot_layout(const FontAtlas& font, RectF area, const SpeedPlotWords& words) {
    SpeedPlotLayout out;
    const float line = font.line_height();
    out.curve_name = first_that_fits(font, words.curve_names, area.width());
    const float name_width = std::min(font.text_width(out.curve_name), area.width());
    // A title, and the curve's name on its own line, only above a data area of at least four
    // lines: in a narrow column the axis word ("speed") says enough and the name goes inside
    // the data area's top right corner (bins under it are cut there).
    float top = area.y0;
    const bool roomy = area.height() - 3.0F * line >= 4.0F * line;
    if (roomy) {
        out.title_text = first_that_fits(font, words.lesson_titles, area.width());
        out.title = {area.x0, top, area.x1, top + line};
        top += line;
        out.curve_label = {area.x1 - name_width, top, area.x1, top + line};
        top += line;
    }
    out.data = {area.x0, top, area.x1, std::max(top, area.y1 - line)};
    out.axis = {area.x0, out.data.y1, area.x1, area.y1};
    if (!roomy) {
        out.curve_label = {out.data.x1 - name_width, out.data.y0, out.data.x1,
                           std::min(out.data.y1, out.data.y0 + line)};
    }
    return out;
}

void draw_moving_speed_plot(OverlayBatch& batch, OverlayBatch& text, const FontAtlas& font,
                            RectF area, const std::vector<const Snapshot*>& snapshots,
                            const std::vector<Rgb8>& colors, double v_min, double v_max,
                            const SpeedPlotWords& words, const PlotColors& palette,
                            const std::function<Rgb8(double)>& axis_colors) {
    const SpeedPlotLayout parts = speed_plot_layout(font, area, words);
    if (!parts.title_text.empty()) {
        font.add_text(text, parts.title.x0, parts.title.y0 + font.ascent(), parts.title_text,
                      palette.label);
    }
    const RectF plot = parts.data;
    const float line_width = std::max(1.0F, std::round(font.pixel_height() / 12.0F));
    const float axis_height = axis_colors ? 3.0F * line_width : line_width;
    if (axis_colors) {
        // The speed axis as the discs' colour bar: a thicker strip, one segment per speed.
        constexpr int segments = 32;
        for (int k = 0; k < segments; ++k) {
            const float x0 = plot.x0 + plot.width() * static_cast<float>(k) / segments;
            const float x1 = plot.x0 + plot.width() * static_cast<float>(k + 1) / segments;
            batch.add_rect({x0, plot.y1 - axis_height, x1 + 0.5F, plot.y1},
                           with_alpha(axis_colors((k + 0.5) / segments), 255));
        }
    } else {
        batch.add_rect({plot.x0, plot.y1 - line_width, plot.x1, plot.y1}, palette.axis);
    }
    batch.add_rect({plot.x0, plot.y0, plot.x0 + line_width, plot.y1}, palette.axis);
    if (snapshots.empty() || plot.width() < 8.0F || plot.height() < 8.0F) return;
    // The moving discs, counted in place (no copies of 10^4 discs per frame).
    std::vector<double> heavy;
    std::size_t most = 0;
    for (const Snapshot* s : snapshots) {
        heavy.push_back(moving_mass_limit(*s));
        const double limit = heavy.back();
        most = std::max(most, static_cast<std::size_t>(std::count_if(
                                  s->discs.begin(), s->discs.end(),
                                  [&](const DiscState& d) { return counted(d, limit); })));
    }
    // About sqrt(N) bins (a few discs per bin even in a small gas), at least 10 px each.
    const int bins =
        std::clamp(std::min(static_cast<int>(plot.width() / 10.0F),
                            static_cast<int>(std::lround(std::sqrt(static_cast<double>(most))))),
                   5, 30);
    std::vector<std::vector<double>> histograms;
    for (std::size_t p = 0; p < snapshots.size(); ++p) {
        histograms.push_back(speed_density(*snapshots[p], v_min, v_max, bins, heavy[p]));
    }
    const MaxwellBoltzmann curve(*snapshots.back(), heavy.back());
    constexpr int curve_samples = 64;
    std::vector<double> curve_values(curve_samples + 1);
    const auto sample_x = [&](int i) {
        return plot.x0 + plot.width() * static_cast<float>(i) / curve_samples;
    };
    double peak = 0.0;
    double under_label = 0.0;  // the curve's highest value below its name
    for (int i = 0; i <= curve_samples; ++i) {
        const double f = curve.density(v_min + (v_max - v_min) * i / curve_samples);
        curve_values[static_cast<std::size_t>(i)] = f;
        peak = std::max(peak, f);
        if (sample_x(std::min(i + 1, curve_samples)) >= parts.curve_label.x0) {
            under_label = std::max(under_label, f);
        }
    }
    if (!(peak > 0.0)) return;
    // A fixed vertical scale (the curve's peak depends only on the energy, which is conserved):
    // bars do not jump as the histogram fills; taller bins are cut at the top. The scale also
    // keeps the curve below its name.
    const float usable = plot.height() - axis_height;
    // (half the curve's width of margin, so its stroke stays clear of the name too)
    const float below_label = plot.y1 - axis_height - 1.5F * line_width - parts.curve_label.y1;
    double top = peak * 1.6;
    if (below_label > 0.0F && under_label > 0.0) {
        top = std::max(top, 1.05 * under_label * static_cast<double>(usable / below_label));
    }
    const double y_scale = static_cast<double>(usable) / top;
    const auto to_y = [&](double value, float x0, float x1) {
        float y = plot.y1 - axis_height - static_cast<float>(std::min(value, top) * y_scale);
        // Nothing is drawn over the curve's name: bins under it are cut at its bottom.
        if (x1 > parts.curve_label.x0 && x0 < parts.curve_label.x1) {
            y = std::max(y, parts.curve_label.y1);
        }
        return y;
    };
    // The curve first: the histograms' outlines stay visible where they follow it.
    for (int i = 0; i < curve_samples; ++i) {
        const float x0 = sample_x(i);
        const float x1 = sample_x(i + 1);
        const auto y = [&](int k) {
            return plot.y1 - axis_height -
                   static_cast<float>(std::min(curve_values[static_cast<std::size_t>(k)], top) *
                                      y_scale);
        };
        batch.add_line({x0, y(i)}, {x1, y(i + 1)}, 2.0F * line_width, palette.curve);
    }
    const float bin_width = plot.width() / static_cast<float>(bins);
    const float base = plot.y1 - axis_height;
    for (std::size_t p = 0; p < histograms.size(); ++p) {
        const Rgb8 c = series_color(colors, p, palette.curve);
        const bool outlines = histograms.size() > 1;  // two panels: two step outlines
        const Rgba8 color = with_alpha(c, outlines ? 235 : 220);
        const float width = 2.0F * line_width;
        float previous_y = base;
        for (int b = 0; b < bins; ++b) {
            const float x0 = plot.x0 + bin_width * static_cast<float>(b);
            const float y = to_y(histograms[p][static_cast<std::size_t>(b)], x0, x0 + bin_width);
            if (outlines) {
                if (b > 0) batch.add_line({x0, previous_y}, {x0, y}, width, color);
                batch.add_line({x0, y}, {x0 + bin_width, y}, width, color);
                previous_y = y;
            } else {
                batch.add_rect({x0 + 1.0F, y, x0 + bin_width - 1.0F, base}, color);
            }
        }
        if (outlines) {
            const float x = plot.x1 - 0.5F * width;
            batch.add_line({x, previous_y}, {x, base}, width, color);
        }
    }
    font.add_text(text, parts.curve_label.x0, parts.curve_label.y0 + font.ascent(),
                  parts.curve_name, palette.curve);
    // The speed axis: "0  speed  0.5", or "slow ... fast" where the three do not fit apart.
    const float baseline = parts.axis.y0 + font.ascent() + 2.0F;
    const std::string& high = words.axis_high;
    const std::string& axis = words.axis_quantity;
    const float space = font.pixel_height();
    const bool numbers = font.text_width(words.axis_low) + font.text_width(axis) +
                             font.text_width(high) + 2.0F * space <=
                         plot.width();
    const std::string& left = numbers ? words.axis_low : words.axis_slow;
    const std::string& right = numbers ? high : words.axis_fast;
    font.add_text(text, plot.x0, baseline, left, palette.label);
    if (numbers) {
        font.add_text(text, plot.x0 + 0.5F * (plot.width() - font.text_width(axis)), baseline, axis,
                      palette.label);
    }
    font.add_text(text, plot.x1 - font.text_width(right), baseline, right, palette.label);
}

}  // namespace collide::render
