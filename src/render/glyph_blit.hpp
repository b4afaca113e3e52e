#pragma once
// Internal: text drawn on the CPU over a frame read back from GL. llvmpipe's cost grows with the
// pixels it shades (per 4x4 block), and as textured quads the ~600 glyphs of a 720p frame's
// titles, counters and labels cost it ~0.7 ms of CPU per frame; blending their coverage here
// costs a fraction of that and gives the same bytes (docs/benchmarks.md, Whole pipeline).

#include <span>

#include "collide/image.hpp"
#include "overlay_geometry.hpp"

namespace collide::render {

/// Blends each glyph (coverage from the single-channel `atlas` of side `atlas_size`, tinted by its
/// colour) into `image`, in order, clipped to the image, with the arithmetic of a GL fragment
/// shader writing premultiplied (rgb * a * coverage, a * coverage) in float, rounded to 8 bits and
/// blended with GL_ONE, GL_ONE_MINUS_SRC_ALPHA into an RGBA8 target (dst * (255 - a) / 255,
/// rounded): byte for byte what llvmpipe gave for glyph quads with nearest sampling, on every
/// built-in scene at 720p, 1080p and 4K.
void blend_glyphs(Image& image, std::span<const GlyphBox> glyphs,
                  std::span<const std::uint8_t> atlas, int atlas_size);

}  // namespace collide::render
