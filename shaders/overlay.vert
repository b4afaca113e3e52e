#version 330 core
// Triangles for everything that is not a disc or text: box, walls, trails, plots. Frame pixels,
// y down, mapped so the readback is top-down (see disc.vert). Text is blended on the CPU after the
// readback (src/render/glyph_blit.hpp).
layout(location = 0) in vec2 position_px;
layout(location = 1) in vec4 color;

uniform vec2 frame_size;

out vec4 frag_color;

void main() {
    frag_color = color;
    gl_Position = vec4(position_px / frame_size * 2.0 - 1.0, 0.0, 1.0);
}
