// The renderer's colours in one place: the themes' palettes, the engines' accents, the colour
// reserved for failures and the contrast rule, and the colour helpers every painter shares.
#include "theme.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace collide::render {

namespace {

double linear_channel(int c) {
    const double v = c / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

// sRGB to linear light, tabulated: the contrast rule runs per disc in colour-mapped scenes.
double channel_luminance(std::uint8_t c) {
    static const std::array<double, 256> table = [] {
        std::array<double, 256> t{};
        for (int i = 0; i < 256; ++i) t[static_cast<std::size_t>(i)] = linear_channel(i);
        return t;
    }();
    return table[c];
}

double luminance(Rgb8 c) {
    return 0.2126 * channel_luminance(c.r) + 0.7152 * channel_luminance(c.g) +
           0.0722 * channel_luminance(c.b);
}

}  // namespace

Rgba8 faded(Rgba8 c, float opacity) noexcept {
    c.a = static_cast<std::uint8_t>(std::lround(std::clamp(opacity, 0.0F, 1.0F) * c.a));
    return c;
}

Rgb8 rgb(Rgba8 c) noexcept {
    return {c.r, c.g, c.b};
}

Palette palette(Theme theme) noexcept {
    if (theme == Theme::light) {
        return {{236, 236, 240, 255}, {255, 255, 255, 255}, {40, 40, 48, 255},
                {150, 150, 170, 255}, {10, 10, 15, 255},    {35, 35, 45, 255},
                {95, 95, 105, 255},   {215, 0, 170, 255},   {30, 30, 36, 255}};
    }
    return {{22, 22, 28, 255},    {34, 36, 46, 255},    {205, 205, 215, 255},
            {95, 95, 120, 255},   {245, 245, 245, 255}, {215, 215, 222, 255},
            {150, 150, 160, 255}, {255, 40, 220, 255},  {225, 225, 232, 255}};
}

PlotColors plot_colors(Theme theme) noexcept {
    if (theme == Theme::dark) return {};  // the plots' own defaults are the dark theme's
    const Palette p = palette(theme);
    // The zero line: halfway between the axis grey and the page, quieter than the axes.
    const auto mix = [](std::uint8_t a, std::uint8_t b) {
        return static_cast<std::uint8_t>((static_cast<int>(a) + static_cast<int>(b)) / 2);
    };
    const Rgba8 zero{mix(p.muted.r, p.background.r), mix(p.muted.g, p.background.g),
                     mix(p.muted.b, p.background.b), 255};
    return {p.text, p.muted, p.title, zero};
}

Rgb8 panel_accent(bool time_driven) noexcept {
    return time_driven ? Rgb8{240, 150, 60} : Rgb8{90, 175, 245};
}

Rgb8 failure_color(Theme theme) noexcept {
    return rgb(palette(theme).failure);
}

Rgb8 box_fill_color(Theme theme) noexcept {
    return rgb(palette(theme).box_fill);
}

bool near_failure_color(Rgb8 c) noexcept {
    // Magenta family: red and blue both well above green. Both themes' failure colours are in it.
    const int r = c.r;
    const int g = c.g;
    const int b = c.b;
    return r > 150 && b > 120 && g < std::min(r, b) - 70;
}

Rgb8 away_from_failure_color(Rgb8 c) noexcept {
    if (!near_failure_color(c)) return c;
    // Towards violet: keep the brightness, pull red down until the colour leaves the family.
    Rgb8 out = c;
    while (near_failure_color(out) && out.r > 0) out.r = static_cast<std::uint8_t>(out.r - 5);
    return out;
}

double contrast_ratio(Rgb8 a, Rgb8 b) noexcept {
    const double la = luminance(a);
    const double lb = luminance(b);
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

}  // namespace collide::render
