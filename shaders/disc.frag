#version 330 core
// Antialiased signed-distance disc: alpha is the pixel's coverage of the edge (1 px ramp).
in vec2 local_px;
flat in float draw_radius;
flat in float half_side;
flat in float coverage;
flat in float frag_style;
flat in vec4 frag_color;

uniform bool as_points;

out vec4 out_color;

void main() {
    // A point sprite has no interpolated offset: gl_PointCoord spans [0, 1] over its square.
    vec2 offset = as_points ? (gl_PointCoord * 2.0 - 1.0) * half_side : local_px;
    float dist = length(offset);
    float alpha = clamp(draw_radius - dist + 0.5, 0.0, 1.0);
    if (frag_style > 0.0) {
        alpha *= clamp(dist - (draw_radius - frag_style) + 0.5, 0.0, 1.0);
    } else if (frag_style < 0.0) {
        float t = clamp(1.0 - dist / draw_radius, 0.0, 1.0);
        alpha = t * t;
    }
    alpha *= coverage * frag_color.a;
    out_color = vec4(frag_color.rgb * alpha, alpha);  // premultiplied
}
