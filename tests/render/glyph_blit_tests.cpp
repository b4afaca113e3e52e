// Text blended on the CPU after the readback: GL's arithmetic for a premultiplied fragment blended
// with GL_ONE, GL_ONE_MINUS_SRC_ALPHA into RGBA8, clipping at the frame's edges, and order.
#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "glyph_blit.hpp"

namespace collide::render {
namespace {

constexpr int atlas_size = 8;

/// An 8x8 atlas whose texel (u, v) holds `coverage(u, v)`.
template <typename F>
std::vector<std::uint8_t> atlas_of(F coverage) {
    std::vector<std::uint8_t> atlas(atlas_size * atlas_size);
    for (int v = 0; v < atlas_size; ++v) {
        for (int u = 0; u < atlas_size; ++u) atlas[v * atlas_size + u] = coverage(u, v);
    }
    return atlas;
}

Image filled(int width, int height, std::array<std::uint8_t, 4> rgba) {
    Image image(width, height);
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        for (std::size_t c = 0; c < 4; ++c) image.rgba[i + c] = rgba[c];
    }
    return image;
}

std::array<std::uint8_t, 4> at(const Image& image, int x, int y) {
    const std::uint8_t* p = image.pixel(x, y);
    return {p[0], p[1], p[2], p[3]};
}

TEST_CASE("full coverage paints the glyph colour, zero coverage leaves the frame alone") {
    // Texels of the left half are covered, of the right half not.
    const auto atlas = atlas_of([](int u, int) { return u < 4 ? 255 : 0; });
    Image image = filled(10, 10, {10, 20, 30, 255});
    const GlyphBox glyph{1, 2, 0, 0, 8, 8, {200, 100, 50, 255}};
    blend_glyphs(image, {&glyph, 1}, atlas, atlas_size);
    CHECK(at(image, 1, 2) == std::array<std::uint8_t, 4>{200, 100, 50, 255});
    CHECK(at(image, 4, 9) == std::array<std::uint8_t, 4>{200, 100, 50, 255});
    CHECK(at(image, 5, 2) == std::array<std::uint8_t, 4>{10, 20, 30, 255});  // u = 4: uncovered
    CHECK(at(image, 0, 2) == std::array<std::uint8_t, 4>{10, 20, 30, 255});  // left of the glyph
    CHECK(at(image, 1, 1) == std::array<std::uint8_t, 4>{10, 20, 30, 255});  // above it
}

TEST_CASE("partial coverage rounds the premultiplied source, then adds dst * (255 - a) / 255") {
    const auto atlas = atlas_of([](int, int) { return 128; });
    Image image = filled(1, 1, {10, 20, 30, 255});
    const GlyphBox glyph{0, 0, 0, 0, 1, 1, {200, 100, 50, 255}};
    blend_glyphs(image, {&glyph, 1}, atlas, atlas_size);
    // a = 128/255: source round(200 a) = 100, round(100 a) = 50, round(50 a) = 25, alpha 128;
    // destination round(10 * 127/255) = 5, round(20 * 127/255) = 10, round(30 * 127/255) = 15.
    CHECK(at(image, 0, 0) == std::array<std::uint8_t, 4>{105, 60, 40, 255});
}

TEST_CASE("a translucent colour scales the coverage") {
    const auto atlas = atlas_of([](int, int) { return 255; });
    Image image = filled(1, 1, {0, 0, 0, 0});
    const GlyphBox glyph{0, 0, 0, 0, 1, 1, {255, 255, 255, 51}};  // 20 % opaque white
    blend_glyphs(image, {&glyph, 1}, atlas, atlas_size);
    CHECK(at(image, 0, 0) == std::array<std::uint8_t, 4>{51, 51, 51, 51});
}

TEST_CASE("glyphs crossing any edge of the frame are clipped to it") {
    const auto atlas =
        atlas_of([](int u, int v) { return static_cast<std::uint8_t>(1 + u + 8 * v); });
    const std::array<std::uint8_t, 4> background{0, 0, 0, 255};
    Image image = filled(12, 10, background);
    const std::array<GlyphBox, 4> glyphs{{
        {-3, -2, 0, 0, 8, 8, {255, 255, 255, 255}},  // top-left corner
        {9, 7, 0, 0, 8, 8, {255, 255, 255, 255}},    // bottom-right corner
        {-20, 0, 0, 0, 8, 8, {255, 255, 255, 255}},  // wholly left of the frame
        {0, 9, 0, 0, 8, 8, {255, 255, 255, 255}},    // wholly below it
    }};
    blend_glyphs(image, glyphs, atlas, atlas_size);
    // Pixel (x, y) of the first glyph shows texel (x + 3, y + 2); of the second, (x - 9, y - 7).
    CHECK(at(image, 0, 0)[0] == 1 + 3 + 8 * 2);
    CHECK(at(image, 4, 5)[0] == 1 + 7 + 8 * 7);
    CHECK(at(image, 9, 7)[0] == 1 + 0 + 8 * 0);
    CHECK(at(image, 11, 9)[0] == 1 + 2 + 8 * 2);
    // Outside both glyphs: untouched.
    CHECK(at(image, 5, 0) == background);
    CHECK(at(image, 0, 6) == background);
    CHECK(at(image, 8, 9) == background);
}

TEST_CASE("later glyphs are blended over earlier ones") {
    const auto atlas = atlas_of([](int, int) { return 255; });
    Image image = filled(1, 1, {0, 0, 0, 255});
    const std::array<GlyphBox, 2> glyphs{{
        {0, 0, 0, 0, 1, 1, {255, 0, 0, 255}},
        {0, 0, 0, 0, 1, 1, {0, 0, 255, 255}},
    }};
    blend_glyphs(image, glyphs, atlas, atlas_size);
    CHECK(at(image, 0, 0) == std::array<std::uint8_t, 4>{0, 0, 255, 255});
}

}  // namespace
}  // namespace collide::render
