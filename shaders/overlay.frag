#version 330 core
in vec4 frag_color;

out vec4 out_color;

void main() {
    out_color = vec4(frag_color.rgb * frag_color.a, frag_color.a);  // premultiplied
}
