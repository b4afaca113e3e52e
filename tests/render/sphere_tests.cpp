// Pixel checks of spheres (3D panels): a sphere is lit at its centre and the box shows around
// it, the nearer of two spheres hides the farther one whatever order they arrive in (the depth
// buffer, through gl_FragDepth), and the orbiting camera gives the same bytes for the same frame.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "../support/skip.hpp"
#include "collide/show/sphere_camera.hpp"
#include "layout.hpp"
#include "render_fixtures.hpp"

namespace collide::render {
namespace {

using test::rgb_at;

constexpr Rgb8 red{230, 40, 40};
constexpr Rgb8 green{40, 220, 60};
constexpr Rgb8 box_fill{34, 36, 46};  // the dark theme's box fill

SphereState sphere_at(Vec3 p, double r, Rgb8 color) {
    SphereState s;
    s.position = p;
    s.radius = r;
    s.mass = 1.0;
    s.color = color;
    return s;
}

struct Drawn {
    Image image;
    PanelLayout layout;
    show::ProjectedPanel panel;
};

/// Renders one panel of spheres (overlays off) through `camera`; `reverse` hands the spheres to
/// the renderer near to far, the wrong order, so that only the depth test can sort them.
Drawn render_spheres(const SphereSnapshot& snapshot, show::Camera camera, bool reverse = false,
                     Backend backend = test::test_backend()) {
    const RenderConfig config = test::small_config(false);
    Renderer renderer(config, backend);
    Drawn out;
    out.panel = show::project(snapshot, camera);
    if (reverse) std::reverse(out.panel.view.spheres.begin(), out.panel.view.spheres.end());
    FrameContent frame;
    frame.panels = {{&out.panel.screen, "", {}}};
    frame.panels[0].spheres = &out.panel.view;
    out.image = renderer.render(frame);
    out.layout = compute_layout(config, {out.panel.screen.box}, 0.0F).panels.at(0);
    return out;
}

PointF centre_px(const Drawn& d, const SphereState& s) {
    for (const SphereSprite& sprite : d.panel.view.spheres) {
        if (sprite.color.r == s.color.r && sprite.color.g == s.color.g)
            return d.layout.to_pixels(sprite.at, d.panel.screen.box);
    }
    FAIL("sphere not in the view");
    return {};
}

int px(float v) {
    return static_cast<int>(std::floor(v));
}

TEST_CASE("a sphere is lit at its centre and shaded towards its rim with the box around it") {
    SphereSnapshot s;
    s.box = Box3{1.0, 1.0, 1.0, Boundary::walls};
    s.spheres = {sphere_at({0.5, 0.5, 0.5}, 0.2, red)};
    const Drawn d = render_spheres(s, show::Camera{0.0, 0.0});
    test::dump_if_requested(d.image, "sphere_one");
    const PointF c = centre_px(d, s.spheres[0]);
    const Rgb8 centre = rgb_at(d.image, px(c.x), px(c.y));
    CHECK(centre.r > 120);
    CHECK(centre.r > centre.g + 60);
    // Lit from the upper left: that side is brighter than the lower right.
    const auto rad = static_cast<float>(0.2 * d.layout.scale);
    const Rgb8 upper_left = rgb_at(d.image, px(c.x - 0.5F * rad), px(c.y - 0.5F * rad));
    const Rgb8 lower_right = rgb_at(d.image, px(c.x + 0.5F * rad), px(c.y + 0.5F * rad));
    CHECK(upper_left.r > lower_right.r + 20);
    // Beyond the rim: the box's fill, untouched.
    CHECK(rgb_at(d.image, px(c.x + 1.4F * rad), px(c.y)) == box_fill);
    CHECK(rgb_at(d.image, px(c.x), px(c.y - 1.4F * rad)) == box_fill);
}

TEST_CASE("the nearer sphere hides the farther one, whatever order they are drawn in") {
    SphereSnapshot s;
    s.box = Box3{1.0, 1.0, 1.0, Boundary::walls};
    // Seen from the front (+z), the green sphere at z = 0.75 is in front of the red one.
    s.spheres = {sphere_at({0.5, 0.5, 0.25}, 0.2, red), sphere_at({0.55, 0.5, 0.75}, 0.2, green)};
    for (const bool reverse : {false, true}) {
        CAPTURE(reverse);
        const Drawn d = render_spheres(s, show::Camera{0.0, 0.0}, reverse);
        test::dump_if_requested(d.image, reverse ? "sphere_depth_reversed" : "sphere_depth");
        const PointF c = centre_px(d, s.spheres[1]);
        const Rgb8 front = rgb_at(d.image, px(c.x), px(c.y));
        CHECK(front.g > front.r + 60);
        // The red sphere shows only where the green one does not cover it (its left side).
        const PointF r = centre_px(d, s.spheres[0]);
        const auto rad = static_cast<float>(0.2 * d.layout.scale);
        const Rgb8 left = rgb_at(d.image, px(r.x - 0.85F * rad), px(r.y));
        CHECK(left.r > left.g + 30);
    }
}

TEST_CASE("intersecting spheres cut each other where their surfaces meet") {
    SphereSnapshot s;
    s.box = Box3{1.0, 1.0, 1.0, Boundary::walls};
    // Side by side at one depth, overlapping in x: each wins on its own side of the overlap.
    s.spheres = {sphere_at({0.4, 0.5, 0.5}, 0.2, red), sphere_at({0.6, 0.5, 0.5}, 0.2, green)};
    for (const bool reverse : {false, true}) {
        CAPTURE(reverse);
        const Drawn d = render_spheres(s, show::Camera{0.0, 0.0}, reverse);
        const PointF a = centre_px(d, s.spheres[0]);
        const PointF b = centre_px(d, s.spheres[1]);
        const float mid = 0.5F * (a.x + b.x);
        const float step = 0.25F * (b.x - a.x);
        const Rgb8 left = rgb_at(d.image, px(mid - step), px(a.y));
        const Rgb8 right = rgb_at(d.image, px(mid + step), px(a.y));
        CHECK(left.r > left.g);
        CHECK(right.g > right.r);
    }
}

TEST_CASE("the orbiting camera draws the same frame the same way twice") {
    SphereSnapshot s;
    s.box = Box3{1.0, 1.0, 1.0, Boundary::walls};
    s.spheres = {sphere_at({0.3, 0.4, 0.2}, 0.12, red), sphere_at({0.7, 0.6, 0.7}, 0.15, green)};
    const show::Camera at = show::camera_at(show::CameraMotion::orbit, 7.25);
    const Drawn a = render_spheres(s, at);
    const Drawn b = render_spheres(s, at);
    CHECK(a.image.rgba == b.image.rgba);
    const Drawn later = render_spheres(s, show::camera_at(show::CameraMotion::orbit, 12.0));
    CHECK(a.image.rgba != later.image.rgba);  // and it does turn
}

show::Camera perspective_front() {
    show::Camera c{0.0, 0.0};
    c.projection = show::Projection::perspective;
    return c;
}

TEST_CASE("under a perspective, the nearer sphere still hides the farther, whatever the order") {
    SphereSnapshot s;
    s.box = Box3{1.0, 1.0, 1.0, Boundary::walls};
    // Seen from the front, the green sphere (z = 0.75) is in front of the red one (z = 0.25),
    // and the two outlines overlap.
    s.spheres = {sphere_at({0.35, 0.5, 0.25}, 0.2, red), sphere_at({0.6, 0.5, 0.75}, 0.2, green)};
    for (const bool reverse : {false, true}) {
        CAPTURE(reverse);
        const Drawn d = render_spheres(s, perspective_front(), reverse);
        test::dump_if_requested(d.image, reverse ? "sphere_persp_reversed" : "sphere_persp");
        const auto sprite = [&](Rgb8 color) {
            for (const SphereSprite& p : d.panel.view.spheres)
                if (p.color.g == color.g) return p;
            FAIL("sphere not in the view");
            return SphereSprite{};
        };
        const SphereSprite near = sprite(green);
        const SphereSprite far = sprite(red);
        // The near sphere looks larger than the far one of the same radius.
        CHECK(near.radius > 1.2 * far.radius);
        const PointF c = centre_px(d, s.spheres[1]);
        const Rgb8 front = rgb_at(d.image, px(c.x), px(c.y));
        CHECK(front.g > front.r + 60);
        // Where the outlines overlap, green; red where only the far one is.
        const double overlap = 0.5 * ((far.at.x + far.radius) + (near.at.x - near.radius));
        const float y = d.layout.to_pixels(far.at, d.panel.screen.box).y;
        const float x = d.layout.to_pixels({overlap, far.at.y}, d.panel.screen.box).x;
        const Rgb8 both = rgb_at(d.image, px(x), px(y));
        CHECK(both.g > both.r + 30);
        const PointF r = centre_px(d, s.spheres[0]);
        const auto rad = static_cast<float>(far.radius * d.layout.scale);
        const Rgb8 left = rgb_at(d.image, px(r.x - 0.6F * rad), px(r.y));
        CHECK(left.r > left.g + 30);
    }
}

TEST_CASE("under a perspective, a sphere off the axis fills the outline its tangent rays give") {
    SphereSnapshot s;
    s.box = Box3{1.0, 1.0, 1.0, Boundary::walls};
    // Right of the axis and near the viewer, on the eye's height (so its outline's widest row
    // is the eye's row).
    constexpr double radius = 0.15;
    s.spheres = {sphere_at({0.85, 0.5, 0.8}, radius, red)};
    const Drawn d = render_spheres(s, perspective_front());
    test::dump_if_requested(d.image, "sphere_persp_outline");
    REQUIRE(d.panel.view.spheres.size() == 1);
    const SphereSprite& sprite = d.panel.view.spheres[0];
    // The two rays from the eye that touch the sphere in the horizontal plane, met with the
    // screen plane: x = eye + D * m, m the slopes of the tangents (box units).
    const double eye = d.panel.view.eye_distance;
    const double a = sprite.plane_at.x - d.panel.view.eye_at.x;
    const double w = eye - sprite.height;
    const double root = radius * std::sqrt(a * a + w * w - radius * radius);
    const double slopes[2] = {(a * w - root) / (w * w - radius * radius),
                              (a * w + root) / (w * w - radius * radius)};
    const Box& screen = d.panel.screen.box;
    const float y = d.layout.to_pixels(d.panel.view.eye_at, screen).y;
    for (int side = 0; side < 2; ++side) {
        const double x = d.panel.view.eye_at.x + eye * slopes[side];
        const float edge = d.layout.to_pixels({x, 0.5 * screen.height}, screen).x;
        const float inward = side == 0 ? 1.5F : -1.5F;
        CAPTURE(side);
        CAPTURE(edge);
        const Rgb8 inside = rgb_at(d.image, px(edge + inward), px(y));
        CHECK(inside.r > inside.g + 40);
        CHECK(rgb_at(d.image, px(edge - inward), px(y)) == box_fill);
    }
    // The outline is wider than the sphere's apparent size at its centre: stretched away from
    // the axis, as a perspective stretches it.
    CHECK(eye * (slopes[1] - slopes[0]) > 2.0 * sprite.radius);
}

TEST_CASE("spheres: EGL surfaceless gives the same pixels as OSMesa, in both projections") {
    if (!is_available(Backend::osmesa) || !is_available(Backend::egl)) {
        COLLIDE_SKIP_TEST("this build lacks OSMesa or EGL");
    }
    {
        const RenderConfig config = test::small_config(false);
        const Renderer probe(config, Backend::egl);
        // On a machine with a GPU, `egl` takes it: different rasteriser, different pixels.
        if (probe.backend() != Backend::egl) {
            COLLIDE_SKIP_TEST("EGL chose a GPU device here, not the surfaceless platform");
        }
    }
    SphereSnapshot s;
    s.box = Box3{1.0, 0.8, 0.6, Boundary::walls};
    s.spheres = {sphere_at({0.3, 0.4, 0.2}, 0.12, red), sphere_at({0.7, 0.6, 0.4}, 0.15, green),
                 sphere_at({0.5, 0.3, 0.45}, 0.1, red)};
    for (const show::Projection projection :
         {show::Projection::orthographic, show::Projection::perspective}) {
        CAPTURE(static_cast<int>(projection));
        show::Camera camera;
        camera.projection = projection;
        const Drawn egl = render_spheres(s, camera, false, Backend::egl);
        const Drawn osmesa = render_spheres(s, camera, false, Backend::osmesa);
        REQUIRE(egl.image.rgba.size() == osmesa.image.rgba.size());
        CHECK(egl.image.rgba == osmesa.image.rgba);
    }
}

}  // namespace
}  // namespace collide::render
