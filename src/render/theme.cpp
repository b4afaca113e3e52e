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

HeapPalette heap_palette(Theme theme) noexcept {
    if (theme == Theme::light) {
        return {{236, 236, 240, 255}, {255, 255, 255, 255}, {10, 10, 15, 255},
                {55, 55, 65, 255},    {20, 20, 25, 255},    {150, 152, 170, 255},
                {226, 229, 238, 255}, {85, 88, 105, 255},   {195, 197, 210, 255},
                {214, 218, 230, 255}, {80, 82, 98, 255},    {40, 40, 50, 255},
                {205, 207, 216, 255}, {10, 10, 15, 255},    {35, 35, 45, 255},
                {150, 152, 165, 255}, {75, 77, 95, 255}};
    }
    return {{22, 22, 28, 255},    {32, 34, 44, 255},    {245, 245, 245, 255}, {190, 190, 200, 255},
            {255, 255, 255, 255}, {105, 108, 128, 255}, {52, 56, 74, 255},    {150, 152, 170, 255},
            {70, 72, 90, 255},    {58, 62, 84, 255},    {165, 168, 185, 255}, {215, 215, 225, 255},
            {40, 43, 55, 255},    {245, 245, 245, 255}, {200, 200, 210, 255}, {110, 112, 128, 255},
            {170, 172, 190, 255}};
}

MarkStyle heap_mark_style(view::SlotMark mark, const HeapPalette& palette) noexcept {
    constexpr Rgba8 white{255, 255, 255, 255};
    switch (mark) {
        case view::SlotMark::plain:
            return {palette.slot, palette.title};
        case view::SlotMark::compared:
            return {{240, 170, 40, 255}, highlight_dark_text};
        case view::SlotMark::moving:
            return {{70, 145, 240, 255}, white};
        case view::SlotMark::inserted:
            return {{70, 185, 100, 255}, highlight_dark_text};
        case view::SlotMark::changed:
            return {{175, 110, 230, 255}, white};
        case view::SlotMark::best:
            return {{40, 175, 175, 255}, highlight_dark_text};
        case view::SlotMark::leaving:
            return {{225, 70, 70, 255}, white};
        case view::SlotMark::sinking:
            return {{240, 170, 40, 255}, highlight_dark_text};
    }
    return {palette.slot, palette.title};
}

PuzzlePalette puzzle_palette(Theme theme) noexcept {
    if (theme == Theme::light) {
        // The collision video's light page; boards keep light tiles in a dark frame (a board
        // reads the same in both themes), marks and amber text darkened to stand out on white.
        return {
            {236, 236, 240, 255}, {255, 255, 255, 255}, {10, 10, 15, 255},    {55, 55, 65, 255},
            {150, 95, 0, 255},    {80, 82, 98, 255},    {130, 132, 150, 255}, {185, 187, 200, 255},
            {240, 241, 246, 255}, {222, 224, 232, 255}, {24, 24, 30, 255},    {70, 72, 88, 255},
            {240, 170, 40, 255},  {205, 125, 0, 255},   {30, 140, 60, 255},   {40, 105, 210, 255}};
    }
    // The collision video's dark theme.
    return {{22, 22, 28, 255},   {32, 34, 44, 255},    {245, 245, 245, 255}, {200, 200, 210, 255},
            {240, 190, 80, 255}, {175, 178, 195, 255}, {105, 108, 128, 255}, {70, 72, 90, 255},
            {38, 40, 52, 255},   {222, 224, 232, 255}, {24, 24, 30, 255},    {48, 50, 64, 255},
            {240, 170, 40, 255}, {240, 170, 40, 255},  {80, 200, 110, 255},  {90, 160, 245, 255}};
}

Rgba8 puzzle_mark_color(view::PuzzleMark mark, const PuzzlePalette& palette) noexcept {
    switch (mark) {
        case view::PuzzleMark::current:
            return palette.current;
        case view::PuzzleMark::goal:
            return palette.goal;
        case view::PuzzleMark::solution:
            return palette.solution;
        case view::PuzzleMark::plain:
            break;
    }
    return palette.edge;
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
