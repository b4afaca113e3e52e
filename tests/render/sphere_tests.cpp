// Pixel checks of spheres (3D panels): a sphere is lit at its centre and the box shows around
// it, the nearer of two spheres hides the farther one whatever order they arrive in (the depth
// buffer, through gl_FragDepth), and the orbiting camera gives the same bytes for the same frame.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

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
Drawn render_spheres(const SphereSnapshot& snapshot, show::Camera camera, bool reverse = false) {
    const RenderConfig config = test::small_config(false);
    Renderer renderer(config, test::test_backend());
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

}  // namespace
}  // namespace collide::render
