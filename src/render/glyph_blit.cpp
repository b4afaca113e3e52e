#include "glyph_blit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace collide::render {
namespace {

// x / 255 rounded to nearest for x in [0, 255 * 255], without a division.
std::uint32_t div255(std::uint32_t x) {
    x += 128;
    return (x + (x >> 8)) >> 8;
}

// Float to unorm8 as the GL pipeline converts a fragment's output: clamp, scale, round.
std::uint32_t to_unorm8(float value) {
    return static_cast<std::uint32_t>(std::lrint(std::clamp(value, 0.0F, 1.0F) * 255.0F));
}

void blend_pixel(std::uint8_t* dst, Rgba8 color, std::uint8_t coverage) {
    // What a fragment shader sampling the coverage would output, in float:
    // alpha = a * coverage; out = (rgb * alpha, alpha).
    const float alpha =
        (static_cast<float>(color.a) / 255.0F) * (static_cast<float>(coverage) / 255.0F);
    const std::uint32_t src_a = to_unorm8(alpha);
    const std::uint32_t keep = 255 - src_a;
    const auto channel = [&](std::uint8_t c, std::uint8_t d) {
        const std::uint32_t src = to_unorm8(static_cast<float>(c) / 255.0F * alpha);
        return static_cast<std::uint8_t>(std::min<std::uint32_t>(255, src + div255(d * keep)));
    };
    dst[0] = channel(color.r, dst[0]);
    dst[1] = channel(color.g, dst[1]);
    dst[2] = channel(color.b, dst[2]);
    dst[3] = static_cast<std::uint8_t>(std::min<std::uint32_t>(255, src_a + div255(dst[3] * keep)));
}

}  // namespace

void blend_glyphs(Image& image, std::span<const GlyphBox> glyphs,
                  std::span<const std::uint8_t> atlas, int atlas_size) {
    for (const GlyphBox& g : glyphs) {
        const int x0 = std::max(g.x, 0);
        const int y0 = std::max(g.y, 0);
        const int x1 = std::min(g.x + g.width, image.width);
        const int y1 = std::min(g.y + g.height, image.height);
        for (int y = y0; y < y1; ++y) {
            const std::uint8_t* coverage =
                atlas.data() + static_cast<std::size_t>(g.v + (y - g.y)) * atlas_size + g.u;
            std::uint8_t* row = image.pixel(0, y);
            for (int x = x0; x < x1; ++x) {
                const std::uint8_t c = coverage[x - g.x];
                if (c != 0) blend_pixel(row + 4 * x, g.color, c);
            }
        }
    }
}

}  // namespace collide::render
