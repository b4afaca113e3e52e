#pragma once
// Internal: CPU-side geometry for everything that is not a disc, in frame pixels with y down:
// triangles for the overlay shader (boxes, walls, trails, plots) and glyphs (text).

#include <cstdint>
#include <vector>

#include "collide/disc.hpp"

namespace collide::render {

struct Rgba8 {
    std::uint8_t r = 0;
    std::uint8_t g = 0;
    std::uint8_t b = 0;
    std::uint8_t a = 255;
};

[[nodiscard]] constexpr Rgba8 with_alpha(Rgb8 c, std::uint8_t a) noexcept {
    return {c.r, c.g, c.b, a};
}

/// A point in frame pixels (y down).
struct PointF {
    float x = 0.0F;
    float y = 0.0F;
};

/// An axis-aligned rectangle in frame pixels.
struct RectF {
    float x0 = 0.0F;
    float y0 = 0.0F;
    float x1 = 0.0F;
    float y1 = 0.0F;
    [[nodiscard]] float width() const noexcept { return x1 - x0; }
    [[nodiscard]] float height() const noexcept { return y1 - y0; }
};

/// The vertex layout of shaders/overlay.vert (12 bytes).
struct OverlayVertex {
    float x, y;  // frame pixels
    Rgba8 color;
};

/// One glyph copied pixel for pixel from the font atlas: the `width` x `height` texels at
/// (`u`, `v`) land on the frame pixels whose top-left one is (`x`, `y`), tinted by `color`.
struct GlyphBox {
    int x, y;  // frame pixels
    std::uint16_t u, v, width, height;
    Rgba8 color;
};

/// Append-only lists: triangles, drawn in order with one GL call, and the glyphs blended over
/// them on the CPU.
class OverlayBatch {
  public:
    void clear() noexcept {
        vertices_.clear();
        glyphs_.clear();
    }
    void add_rect(RectF r, Rgba8 color);
    /// A rectangle outline `width` pixels thick, inside r.
    void add_frame(RectF r, float width, Rgba8 color);
    /// A straight segment as a quad `width` pixels wide.
    void add_line(PointF a, PointF b, float width, Rgba8 color);
    /// A glyph, drawn after every triangle of the batch (see glyph_blit.hpp).
    void add_glyph(const GlyphBox& glyph) { glyphs_.push_back(glyph); }

    [[nodiscard]] const std::vector<OverlayVertex>& vertices() const noexcept { return vertices_; }
    [[nodiscard]] const std::vector<GlyphBox>& glyphs() const noexcept { return glyphs_; }

  private:
    void add_quad(PointF a, PointF b, PointF c, PointF d, Rgba8 color);
    std::vector<OverlayVertex> vertices_;
    std::vector<GlyphBox> glyphs_;
};

}  // namespace collide::render
