#version 330 core
// One disc (or marker) drawn as a tight screen-aligned square around it, in one of two ways:
//  - as_points: one vertex per disc, a point sprite of side 2 * half_size. llvmpipe sets up a
//    point as one primitive, about 3x cheaper than the two triangles of a quad for the small
//    discs that dominate (measured in bench_render); sprites are capped at the implementation's
//    maximum point size and vanish when their centre leaves the frame, so the renderer only
//    sends discs that fit and lie fully inside;
//  - otherwise 6 consecutive vertices with the same attributes: two triangles whose corners come
//    from gl_VertexID (huge discs, discs crossing the frame edge). Coordinates are frame pixels with y down; we map y = 0 to
// NDC -1 (the first row glReadPixels returns), so the readback is already top-down.
layout(location = 0) in vec2 center_px;
layout(location = 1) in float radius_px;
layout(location = 2) in float style;   // 0: filled disc, > 0: ring of that width (px), < 0: glow
layout(location = 3) in vec4 color;

uniform vec2 frame_size;
uniform bool as_points;

out vec2 local_px;        // fragment offset from the centre, pixels
flat out float draw_radius;
flat out float half_side;  // half the square's side (px): point sprites rebuild local_px from it
flat out float coverage;  // < 1 for sub-pixel discs: keeps them visible at a fair brightness
flat out float frag_style;
flat out vec4 frag_color;

const float min_radius = 0.75;  // a disc never shrinks below ~1.5 px across
// Room for the antialiased edge: disc.frag's coverage reaches zero half a pixel beyond the radius,
// so no pixel centre farther out is touched. llvmpipe's cost per disc grows with the square's area
// (a margin of 1 cost 4 % more CPU per 720p frame of 2 x 2000 small discs, docs/benchmarks.md).
const float aa_margin = 0.5;

void main() {
    // Corners 0..5 of the triangles (0,1,2) and (2,1,3) of the quad with corners
    // 0 = (-1,-1), 1 = (1,-1), 2 = (-1,1), 3 = (1,1).
    const int quad_corner[6] = int[6](0, 1, 2, 2, 1, 3);
    int k = quad_corner[gl_VertexID % 6];
    vec2 corner = vec2(float(k & 1), float(k >> 1)) * 2.0 - 1.0;
    draw_radius = max(radius_px, min_radius);
    coverage = min(1.0, (radius_px * radius_px) / (min_radius * min_radius));
    float half_size = draw_radius + aa_margin;
    local_px = corner * half_size;
    frag_style = style;
    frag_color = color;
    half_side = half_size;
    vec2 p = center_px + local_px;
    if (as_points) {
        gl_PointSize = 2.0 * half_size;
        p = center_px;
    }
    gl_Position = vec4(p / frame_size * 2.0 - 1.0, 0.0, 1.0);
}
