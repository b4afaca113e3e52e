#version 330 core
in vec2 uv;
uniform sampler2D frame;
out vec4 out_color;

void main() { out_color = vec4(texture(frame, uv).rgb, 1.0); }
