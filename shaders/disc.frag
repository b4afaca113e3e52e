#version 330 core
// Antialiased signed-distance disc: alpha is the pixel's coverage of the edge (1 px ramp).
in vec2 local_px;
flat in float draw_radius;
flat in float coverage;
flat in float frag_style;
flat in vec4 frag_color;

out vec4 out_color;

void main() {
    float dist = length(local_px);
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
