#version 330 core
// One sphere as a ray-cast impostor: a screen-aligned square around its outline (6 consecutive
// vertices with the same attributes, two triangles whose corners come from gl_VertexID, as in
// disc.vert). sphere.frag solves the sphere's surface per pixel. Orthographic camera (eye.z = 0):
// a sphere's outline is a circle of its radius round its projected centre and every pixel's ray
// runs straight into depth. Perspective camera: the rays start at the eye, and the square is the
// bounding box of the outline (an ellipse), found from the planes through the eye that touch the
// sphere. Coordinates are frame pixels with y down, mapped as in disc.vert.
layout(location = 0) in vec2 center_px;
layout(location = 1) in float radius_px;
layout(location = 2) in float center_depth;  // 0 (near) .. 1 (far)
layout(location = 3) in float radius_depth;  // the radius in depth units
layout(location = 4) in vec4 color;
layout(location = 5) in vec4 ball;  // perspective: centre over the screen plane, height, radius

uniform vec2 frame_size;
uniform vec3 eye;  // perspective: the eye, pixels (y down), its height above the plane; 0: ortho

out vec2 local_px;  // orthographic: fragment offset from the centre, pixels
out vec2 plane_px;  // perspective: the fragment on the screen plane, pixels
flat out float draw_radius;
flat out float frag_depth;
flat out float frag_radius_depth;
flat out vec4 frag_color;
flat out vec4 frag_ball;

const float min_radius = 0.75;
const float aa_margin = 0.5;  // the soft edge reaches half a pixel beyond the radius

// Perspective: where the outline's two tangents along one axis meet the screen plane. `a` is the
// centre's offset from the eye along the axis, `w` its distance below the eye (> r).
vec2 outline_span(float a, float w, float r) {
    float root = r * sqrt(max(a * a + w * w - r * r, 0.0));
    return vec2(a * w - root, a * w + root) / (w * w - r * r) * eye.z;
}

void main() {
    const int quad_corner[6] = int[6](0, 1, 2, 2, 1, 3);
    int k = quad_corner[gl_VertexID % 6];
    vec2 corner = vec2(float(k & 1), float(k >> 1)) * 2.0 - 1.0;
    frag_depth = center_depth;
    frag_radius_depth = radius_depth;
    frag_color = color;
    frag_ball = ball;
    vec2 p;
    if (eye.z > 0.0) {
        float w = eye.z - ball.z;
        vec2 span_x = outline_span(ball.x - eye.x, w, ball.w) + eye.x;
        vec2 span_y = outline_span(ball.y - eye.y, w, ball.w) + eye.y;
        // One pixel of margin for the soft edge.
        vec2 lo = vec2(span_x.x, span_y.x) - 1.0;
        vec2 hi = vec2(span_x.y, span_y.y) + 1.0;
        p = mix(lo, hi, corner * 0.5 + 0.5);
        plane_px = p;
        local_px = vec2(0.0);
        draw_radius = ball.w;
    } else {
        draw_radius = max(radius_px, min_radius);
        local_px = corner * (draw_radius + aa_margin);
        plane_px = vec2(0.0);
        p = center_px + local_px;
    }
    gl_Position = vec4(p / frame_size * 2.0 - 1.0, 0.0, 1.0);
}
