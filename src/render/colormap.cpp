#include <algorithm>
#include <array>
#include <cmath>

#include "collide/render/renderer.hpp"

namespace collide::render {
namespace {

// Our own perceptual ramp: six hand-picked sRGB anchors, evenly spaced in t, whose lightness
// rises steadily (deep violet -> indigo -> teal -> green -> yellow) so faster reads brighter
// even in greyscale, and which stays distinguishable for red-green colour blindness.
constexpr std::array<Rgb8, 6> anchors = {{
    {46, 16, 84},
    {58, 66, 140},
    {38, 120, 150},
    {32, 168, 128},
    {120, 205, 80},
    {246, 228, 48},
}};

}  // namespace

Rgb8 colormap(double t) noexcept {
    if (!(t > 0.0)) t = 0.0;  // also maps NaN to the bottom of the scale
    if (t > 1.0) t = 1.0;
    const double scaled = t * static_cast<double>(anchors.size() - 1);
    const auto index = std::min(static_cast<std::size_t>(scaled), anchors.size() - 2);
    const double f = scaled - static_cast<double>(index);
    const Rgb8 a = anchors[index];
    const Rgb8 b = anchors[index + 1];
    const auto mix = [f](std::uint8_t x, std::uint8_t y) {
        return static_cast<std::uint8_t>(std::lround(x + (y - x) * f));
    };
    return {mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b)};
}

}  // namespace collide::render
