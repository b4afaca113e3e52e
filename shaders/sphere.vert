#version 330 core
// One sphere as a ray-cast impostor: a screen-aligned square around its outline (6 consecutive
// vertices with the same attributes, two triangles whose corners come from gl_VertexID, as in
// disc.vert). sphere.frag solves the sphere's surface per pixel. The camera is orthographic, so
// a sphere's outline is a circle of its radius and every pixel's ray runs straight into depth.
// Coordinates are frame pixels with y down, mapped as in disc.vert.
layout(location = 0) in vec2 center_px;
layout(location = 1) in float radius_px;
layout(location = 2) in float center_depth;  // 0 (near) .. 1 (far)
layout(location = 3) in float radius_depth;  // the radius in depth units
layout(location = 4) in vec4 color;

uniform vec2 frame_size;

out vec2 local_px;  // fragment offset from the centre, pixels
flat out float draw_radius;
flat out float frag_depth;
flat out float frag_radius_depth;
flat out vec4 frag_color;

const float min_radius = 0.75;
const float aa_margin = 0.5;  // the soft edge reaches half a pixel beyond the radius

void main() {
    const int quad_corner[6] = int[6](0, 1, 2, 2, 1, 3);
    int k = quad_corner[gl_VertexID % 6];
    vec2 corner = vec2(float(k & 1), float(k >> 1)) * 2.0 - 1.0;
    draw_radius = max(radius_px, min_radius);
    local_px = corner * (draw_radius + aa_margin);
    frag_depth = center_depth;
    frag_radius_depth = radius_depth;
    frag_color = color;
    vec2 p = center_px + local_px;
    gl_Position = vec4(p / frame_size * 2.0 - 1.0, 0.0, 1.0);
}
