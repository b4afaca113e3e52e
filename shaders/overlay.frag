#version 330 core
in vec2 frag_uv;
in vec4 frag_color;

uniform sampler2D glyph_atlas;  // single channel: glyph coverage

out vec4 out_color;

void main() {
    float alpha = frag_color.a;
    if (frag_uv.x >= 0.0) alpha *= texture(glyph_atlas, frag_uv).r;
    out_color = vec4(frag_color.rgb * alpha, alpha);  // premultiplied
}
