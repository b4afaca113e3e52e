#version 330 core
// A lit sphere: the surface point under the pixel, its normal, a key light (diffuse and a small
// highlight) plus an ambient term, darkened with depth (the depth cue), and the true depth of the
// surface in gl_FragDepth so that spheres that intersect cut each other where they should. The
// outline is antialiased over one pixel; spheres arrive far to near, so a soft edge blends over
// what lies behind it. Orthographic (eye.z = 0): every ray runs straight into depth. Perspective:
// the pixel's ray runs from the eye through the pixel on the screen plane and is intersected with
// the sphere.
in vec2 local_px;
in vec2 plane_px;
flat in float draw_radius;
flat in float frag_depth;
flat in float frag_radius_depth;
flat in vec4 frag_color;
flat in vec4 frag_ball;

uniform vec3 light_dir;    // towards the light: x right, y up, z towards the viewer; unit
uniform float ambient;     // 0..1
uniform float depth_cue;   // share of the colour lost at depth 1
uniform vec3 cue_color;    // what far spheres fade towards (the box's fill)
uniform vec3 eye;          // perspective: the eye, pixels (y down) and height; 0: orthographic

out vec4 out_color;

// Lit and depth-cued colour and depth of the surface point with unit normal n (y up), seen
// along `view` (towards the viewer, y up).
void shade(vec3 n, vec3 view, float alpha) {
    float diffuse = max(dot(n, light_dir), 0.0);
    vec3 h = normalize(light_dir + view);
    float highlight = pow(max(dot(n, h), 0.0), 40.0) * 0.35;
    vec3 lit = frag_color.rgb * (ambient + (1.0 - ambient) * diffuse) + vec3(highlight);
    float depth = frag_depth - frag_radius_depth * n.z;
    lit = mix(lit, cue_color, depth_cue * clamp(depth, 0.0, 1.0));
    gl_FragDepth = clamp(depth, 0.0, 1.0);
    alpha *= frag_color.a;
    out_color = vec4(lit * alpha, alpha);  // premultiplied
}

void main() {
    if (eye.z > 0.0) {
        // Pixels, y down, z towards the viewer; the ray from the eye through the pixel.
        vec3 centre = frag_ball.xyz;
        float r = frag_ball.w;
        vec3 through = vec3(plane_px, 0.0);
        vec3 d = normalize(through - eye);
        float along = dot(centre - eye, d);  // the ray's closest approach to the centre
        vec3 off = eye + along * d - centre;
        float miss = length(off);
        // The miss distance at the sphere, scaled onto the screen plane: pixels of soft edge.
        float magnify = length(through - eye) / along;
        float alpha = clamp((r - miss) * magnify + 0.5, 0.0, 1.0);
        if (alpha <= 0.0) discard;
        vec3 surface = miss < r ? eye + (along - sqrt(r * r - miss * miss)) * d
                                : centre + off * (r / miss);  // the outline's point
        vec3 n = (surface - centre) / r;
        shade(vec3(n.x, -n.y, n.z), vec3(-d.x, d.y, -d.z), alpha);
        return;
    }
    float dist = length(local_px);
    float alpha = clamp(draw_radius - dist + 0.5, 0.0, 1.0);
    if (alpha <= 0.0) discard;
    // The unit normal: screen y runs down, the light's y up.
    vec2 xy = local_px / draw_radius;
    float r2 = min(dot(xy, xy), 1.0);
    vec3 n = vec3(xy.x, -xy.y, sqrt(1.0 - r2));
    shade(n, vec3(0.0, 0.0, 1.0), alpha);
}
