#version 330 core
// One instance per disc (or marker): a tight screen-aligned quad around it, 4 vertices from
// gl_VertexID as a triangle strip. Coordinates are frame pixels with y down; we map y = 0 to
// NDC -1 (the first row glReadPixels returns), so the readback is already top-down.
layout(location = 0) in vec2 center_px;
layout(location = 1) in float radius_px;
layout(location = 2) in float style;   // 0: filled disc, > 0: ring of that width (px), < 0: glow
layout(location = 3) in vec4 color;

uniform vec2 frame_size;

out vec2 local_px;        // fragment offset from the centre, pixels
flat out float draw_radius;
flat out float coverage;  // < 1 for sub-pixel discs: keeps them visible at a fair brightness
flat out float frag_style;
flat out vec4 frag_color;

const float min_radius = 0.75;  // a disc never shrinks below ~1.5 px across
const float aa_margin = 1.0;    // room for the antialiased edge

void main() {
    vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1)) * 2.0 - 1.0;
    draw_radius = max(radius_px, min_radius);
    coverage = min(1.0, (radius_px * radius_px) / (min_radius * min_radius));
    float half_size = draw_radius + aa_margin;
    local_px = corner * half_size;
    frag_style = style;
    frag_color = color;
    vec2 p = center_px + local_px;
    gl_Position = vec4(p / frame_size * 2.0 - 1.0, 0.0, 1.0);
}
