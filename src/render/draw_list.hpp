#pragma once
// Internal: a picture described on the CPU for GlTarget (gl_target.hpp): discs (filled, rings,
// glows), triangles under and over them, and text. No GL here, so frame builders and their tests
// need no context.

#include <cstddef>
#include <vector>

#include "font.hpp"
#include "overlay_geometry.hpp"

namespace collide::render {

/// The vertex layout of shaders/disc.vert: one instance per disc or marker (20 bytes).
struct DiscInstance {
    float x, y;    ///< centre, frame pixels
    float radius;  ///< pixels
    float style;   ///< 0 filled, > 0 ring width (px), < 0 glow
    Rgba8 color;
};
static_assert(sizeof(DiscInstance) == 20);

/// The vertex layout of shaders/sphere.vert: one sphere impostor (40 bytes).
struct SphereInstance {
    float x, y;          ///< the centre's projection, frame pixels
    float radius;        ///< pixels: how large it looks there (orthographic: its radius)
    float depth;         ///< the centre's depth, 0 (near) .. 1 (far)
    float radius_depth;  ///< the radius in depth units
    Rgba8 color;
    /// Perspective only (SphereLight::eye_z > 0): the centre in frame pixels over the screen
    /// plane (x, y) and its height above it towards the viewer, and the true radius, pixels.
    float plane_x = 0.0F, plane_y = 0.0F, height = 0.0F, ball_radius = 0.0F;
};
static_assert(sizeof(SphereInstance) == 40);

/// How one panel's spheres are lit (SphereView's light, in the painter's colours).
struct SphereLight {
    float x = -0.45F, y = 0.6F, z = 0.66F;  ///< towards the light, unit
    float ambient = 0.3F;
    float depth_cue = 0.5F;
    Rgba8 cue_color;  ///< far spheres fade towards it
    /// The perspective eye in frame pixels (y down) and its height above the screen plane;
    /// eye_z = 0: orthographic.
    float eye_x = 0.0F, eye_y = 0.0F, eye_z = 0.0F;
};

/// Text of one font: glyphs (OverlayBatch::glyphs) blended over everything after the readback.
struct TextRun {
    const FontAtlas* font = nullptr;
    OverlayBatch glyphs;  ///< only its glyphs are used
};

/// Everything one frame draws, in drawing order: background (and whole-pixel fills cleared to
/// `fill_color`), `under` triangles, spheres (per group, scissored, depth-tested), discs (per
/// group, scissored), `over` triangles, then text.
struct DrawList {
    Rgba8 background{22, 22, 28, 255};
    Rgba8 fill_color{34, 36, 46, 255};
    std::vector<RectF> fill_clears;  ///< whole-pixel rectangles cleared to fill_color first
    OverlayBatch under;              ///< triangles under the discs (must hold no glyphs)
    std::vector<DiscInstance> discs;
    struct DiscGroup {
        std::size_t end = 0;  ///< discs [previous group's end, end)
        RectF clip;           ///< scissor rectangle of the group
    };
    std::vector<DiscGroup> disc_groups;
    /// Spheres (3D panels), drawn after `under` and before the discs, with a depth test, far to
    /// near per group.
    std::vector<SphereInstance> spheres;
    struct SphereGroup {
        std::size_t end = 0;  ///< spheres [previous group's end, end)
        RectF clip;           ///< scissor rectangle of the group
        SphereLight light;
    };
    std::vector<SphereGroup> sphere_groups;
    OverlayBatch over;          ///< triangles over the discs (must hold no glyphs)
    std::vector<TextRun> text;  ///< blended last, run by run

    void clear();
};

}  // namespace collide::render
