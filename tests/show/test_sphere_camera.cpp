// The camera of a panel of spheres (show::project): where spheres land on the screen, in which
// order they are drawn, the box's edges, the stand-in discs, and the orbit's determinism.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "collide/show/sphere_camera.hpp"

namespace collide::show {
namespace {

SphereState sphere_at(Vec3 p, double r, Vec3 v = {}) {
    SphereState s;
    s.position = p;
    s.velocity = v;
    s.radius = r;
    s.mass = 1.0;
    s.color = {200, 40, 40};
    return s;
}

SphereSnapshot two_spheres() {
    SphereSnapshot s;
    s.box = Box3{1.0, 1.0, 1.0, Boundary::walls};
    s.spheres = {sphere_at({0.5, 0.5, 0.2}, 0.1, {0.3, 0.4, 1.2}), sphere_at({0.5, 0.5, 0.8}, 0.1)};
    return s;
}

TEST_CASE("seen from the front, a sphere lands at its (x, y) and nearer means larger z") {
    const ProjectedPanel p = project(two_spheres(), Camera{0.0, 0.0});
    REQUIRE(p.view.spheres.size() == 2);
    // Far to near: the sphere at z = 0.2 (farther from a viewer on the +z side) first.
    CHECK(p.view.spheres[0].depth > p.view.spheres[1].depth);
    CHECK(p.view.spheres[0].speed == doctest::Approx(1.3));
    const Box& screen = p.screen.box;
    for (const SphereSprite& s : p.view.spheres) {
        CHECK(s.at.x == doctest::Approx(0.5 * screen.width));
        CHECK(s.at.y == doctest::Approx(0.5 * screen.height));
        CHECK(s.depth - s.radius_depth > 0.0);  // every surface point inside the depth range
        CHECK(s.depth + s.radius_depth < 1.0);
    }
}

TEST_CASE("the stand-in discs carry the spheres' speeds and the 3D marker") {
    const ProjectedPanel p = project(two_spheres(), Camera{});
    REQUIRE(p.screen.discs.size() == 2);
    CHECK(p.screen.dimension == 3);
    CHECK(norm(p.screen.discs[0].velocity) == doctest::Approx(1.3));
    CHECK(p.screen.discs[0].radius == doctest::Approx(0.1));
    CHECK_FALSE(p.screen.discs[0].tagged);  // no trails of projected paths
}

TEST_CASE("the box has 12 edges, three of them in front") {
    const ProjectedPanel p = project(two_spheres(), Camera{});
    CHECK(p.view.edges.size() == 12);
    CHECK(std::count_if(p.view.edges.begin(), p.view.edges.end(),
                        [](const BoxEdge& e) { return e.front; }) == 3);
    // Every corner lies inside the screen box, whatever the yaw.
    for (const double yaw : {0.0, 0.6, 1.3, 2.9, 4.4}) {
        const ProjectedPanel q = project(two_spheres(), Camera{yaw, 0.42});
        for (const BoxEdge& e : q.view.edges) {
            for (const Vec2 c : {e.from, e.to}) {
                CHECK(c.x >= 0.0);
                CHECK(c.x <= q.screen.box.width);
                CHECK(c.y >= 0.0);
                CHECK(c.y <= q.screen.box.height);
            }
        }
        CHECK(q.screen.box.width == doctest::Approx(p.screen.box.width));  // the layout stays
    }
}

TEST_CASE("the orbit is a function of video time: a turn every orbit_seconds") {
    CHECK(camera_at(CameraMotion::fixed, 12.0).yaw == camera_at(CameraMotion::fixed, 0.0).yaw);
    const Camera a = camera_at(CameraMotion::orbit, 3.5);
    const Camera b = camera_at(CameraMotion::orbit, 3.5);
    CHECK(a.yaw == b.yaw);
    CHECK(a.yaw != camera_at(CameraMotion::orbit, 0.0).yaw);
    CHECK(camera_at(CameraMotion::orbit, orbit_seconds / 4).yaw ==
          doctest::Approx(camera_at(CameraMotion::orbit, 0.0).yaw + std::numbers::pi / 2));
}

TEST_CASE("a stand-in scene keeps the box, the hints and every sphere's speed") {
    SphereScene scene;
    scene.name = "s";
    scene.box = Box3{2.0, 1.0, 3.0, Boundary::periodic};
    Sphere p;
    p.position = {1.0, 0.5, 2.0};
    p.velocity = {0.0, 3.0, 4.0};
    scene.spheres = {p};
    scene.render.duration = 7.0;
    const Scene s = stand_in_scene(scene);
    CHECK(s.box.width == 2.0);
    CHECK(s.box.boundary == Boundary::periodic);
    REQUIRE(s.discs.size() == 1);
    CHECK(norm(s.discs[0].velocity) == doctest::Approx(5.0));
    CHECK(s.render.duration == 7.0);
}

}  // namespace
}  // namespace collide::show

namespace collide::show {
namespace {

TEST_CASE("a slab keeps the spheres within half its thickness of the centre plane, all the discs") {
    SphereSnapshot s;
    s.box = Box3{1.0, 1.0, 1.0, Boundary::walls};
    // Seen from the front, depth runs along z: 0.5 is on the centre plane, 0.2 and 0.85 are not.
    s.spheres = {sphere_at({0.5, 0.5, 0.2}, 0.05), sphere_at({0.3, 0.5, 0.55}, 0.05),
                 sphere_at({0.7, 0.5, 0.85}, 0.05)};
    const ProjectedPanel all = project(s, Camera{0.0, 0.0, 0.0});
    CHECK(all.view.spheres.size() == 3);
    const ProjectedPanel slab = project(s, Camera{0.0, 0.0, 0.2});
    REQUIRE(slab.view.spheres.size() == 1);
    CHECK(slab.view.spheres[0].at.x == doctest::Approx(all.view.spheres[1].at.x));
    CHECK(slab.screen.discs.size() == 3);  // the figures and the plot still count every sphere
    CHECK(camera_at(CameraMotion::orbit, 2.0, 0.3).slab == 0.3);
}

}  // namespace
}  // namespace collide::show
