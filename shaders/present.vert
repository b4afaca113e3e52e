#version 330 core
// Preview window: one full-window triangle showing the frame texture. Image row 0 is the top,
// so v runs downwards.
out vec2 uv;

void main() {
    vec2 p = vec2(float((gl_VertexID & 1) * 4 - 1), float((gl_VertexID >> 1) * 4 - 1));
    uv = vec2((p.x + 1.0) * 0.5, (1.0 - p.y) * 0.5);
    gl_Position = vec4(p, 0.0, 1.0);
}
