#pragma once
// Internal: CPU-side triangle lists for everything drawn with the overlay shader (boxes, walls,
// trails, plots, text), in frame pixels with y down.

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

/// The vertex layout of shaders/overlay.vert (20 bytes).
struct OverlayVertex {
    float x, y;  // frame pixels
    float u, v;  // glyph atlas coordinates; u < 0: solid fill
    Rgba8 color;
};

/// An append-only list of triangles, drawn in order with one call.
class OverlayBatch {
  public:
    void clear() noexcept { vertices_.clear(); }
    void add_rect(RectF r, Rgba8 color);
    /// A rectangle outline `width` pixels thick, inside r.
    void add_frame(RectF r, float width, Rgba8 color);
    /// A straight segment as a quad `width` pixels wide.
    void add_line(PointF a, PointF b, float width, Rgba8 color);
    /// A textured quad (a glyph).
    void add_glyph(RectF r, RectF uv, Rgba8 color);

    [[nodiscard]] const std::vector<OverlayVertex>& vertices() const noexcept { return vertices_; }

  private:
    void add_quad(PointF a, PointF b, PointF c, PointF d, RectF uv, Rgba8 color);
    std::vector<OverlayVertex> vertices_;
};

}  // namespace collide::render
