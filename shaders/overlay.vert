#version 330 core
// Triangles for everything that is not a disc: box, walls, trails, plots, text. Frame pixels,
// y down, mapped so the readback is top-down (see disc.vert).
layout(location = 0) in vec2 position_px;
layout(location = 1) in vec2 uv;  // glyph atlas coordinates; u < 0 means a solid fill
layout(location = 2) in vec4 color;

uniform vec2 frame_size;

out vec2 frag_uv;
out vec4 frag_color;

void main() {
    frag_uv = uv;
    frag_color = color;
    gl_Position = vec4(position_px / frame_size * 2.0 - 1.0, 0.0, 1.0);
}
