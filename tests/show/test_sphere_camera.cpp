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

#include "collide/show/failure_marks.hpp"

namespace collide::show {
namespace {

Camera perspective(double yaw, double pitch) {
    Camera c{yaw, pitch};
    c.projection = Projection::perspective;
    return c;
}

TEST_CASE("a perspective camera: the centre plane keeps its scale, near spheres look larger") {
    SphereSnapshot s;
    s.box = Box3{1.0, 1.0, 1.0, Boundary::walls};
    // Seen from the front (+z towards the viewer): one sphere on the centre plane, one nearer and
    // one farther, both off the axis.
    s.spheres = {sphere_at({0.5, 0.5, 0.5}, 0.1), sphere_at({0.8, 0.5, 0.9}, 0.1),
                 sphere_at({0.8, 0.5, 0.1}, 0.1)};
    const ProjectedPanel p = project(s, perspective(0.0, 0.0));
    REQUIRE(p.view.spheres.size() == 3);
    CHECK(p.view.eye_distance > 0.0);
    const Box& screen = p.screen.box;
    // Far to near: the sphere at z = 0.1 first, then the centre, then z = 0.9.
    const SphereSprite& far = p.view.spheres[0];
    const SphereSprite& mid = p.view.spheres[1];
    const SphereSprite& near = p.view.spheres[2];
    CHECK(mid.at.x == doctest::Approx(0.5 * screen.width));
    CHECK(mid.radius == doctest::Approx(0.1));
    CHECK(near.radius > 0.1);
    CHECK(far.radius < 0.1);
    // The near one is pushed away from the centre, the far one drawn towards it, by the
    // perspective's scale: eye / (eye - height).
    const double eye = p.view.eye_distance;
    CHECK(near.at.x - 0.5 * screen.width == doctest::Approx(0.3 * eye / (eye - 0.4)));
    CHECK(far.at.x - 0.5 * screen.width == doctest::Approx(0.3 * eye / (eye + 0.4)));
    CHECK(near.radius == doctest::Approx(0.1 * eye / (eye - 0.4)));
    // What the ray cast needs: the sphere itself over the screen plane.
    CHECK(near.plane_at.x - 0.5 * screen.width == doctest::Approx(0.3));
    CHECK(near.height == doctest::Approx(0.4));
    CHECK(near.ball_radius == 0.1);
    // The stand-in discs are where the spheres look to be, as large as they look.
    CHECK(p.screen.discs[1].position.x == doctest::Approx(near.at.x));
    CHECK(p.screen.discs[1].radius == doctest::Approx(near.radius));
    // Orthographic: no eye, and the radius is the sphere's.
    const ProjectedPanel o = project(s, Camera{0.0, 0.0});
    CHECK(o.view.eye_distance == 0.0);
    CHECK(o.view.spheres[2].radius == 0.1);
}

TEST_CASE("a perspective camera keeps the whole box on the screen at every yaw, the box still") {
    const SphereSnapshot s = two_spheres();
    const ProjectedPanel first = project(s, perspective(0.0, 0.42));
    for (const double yaw : {0.0, 0.6, 0.785398, 1.3, 2.9, 3.93, 4.4}) {
        CAPTURE(yaw);
        const ProjectedPanel q = project(s, perspective(yaw, 0.42));
        CHECK(q.screen.box.width == doctest::Approx(first.screen.box.width));
        CHECK(q.screen.box.height == doctest::Approx(first.screen.box.height));
        for (const BoxEdge& e : q.view.edges) {
            for (const Vec2 c : {e.from, e.to}) {
                CHECK(c.x >= 0.0);
                CHECK(c.x <= q.screen.box.width);
                CHECK(c.y >= 0.0);
                CHECK(c.y <= q.screen.box.height);
            }
        }
        for (const SphereSprite& sp : q.view.spheres) {
            CHECK(sp.at.x - sp.radius >= 0.0);
            CHECK(sp.at.x + sp.radius <= q.screen.box.width);
        }
    }
    // The perspective box needs more room than the orthographic one: its near corners grow.
    CHECK(first.screen.box.width > project(s, Camera{0.0, 0.42}).screen.box.width);
}

TEST_CASE("a sphere that reaches the eye is left out of the view, its disc stays") {
    SphereSnapshot s = two_spheres();
    const ProjectedPanel p = project(s, perspective(0.0, 0.0));
    s.spheres[0].position = {0.5, 0.5, 0.5 + p.view.eye_distance};  // escaped far towards us
    s.spheres[0].escaped = true;
    const ProjectedPanel q = project(s, perspective(0.0, 0.0));
    CHECK(q.view.spheres.size() == 1);
    CHECK(q.screen.discs.size() == 2);
}

/// Where the camera puts a point: a small sphere there, projected with the same snapshot's box.
Vec2 seen_at(SphereSnapshot s, Vec3 point, Camera camera) {
    s.spheres.push_back(sphere_at(point, 0.0));
    s.spheres.back().escaped = false;
    const ProjectedPanel p = project(s, camera);
    return p.screen.discs.back().position;
}

TEST_CASE("marks of spheres sit where the camera shows the failure: an escape where it left") {
    SphereSnapshot s;
    s.box = Box3{1.0, 1.0, 1.0, Boundary::walls};
    // Left through the face x = 1 at (1, 0.4, 0.7) a while ago: now at x = 1.3, still moving.
    SphereState out = sphere_at({1.3, 0.4 + 0.3 * 0.5, 0.7 - 0.3 * 0.25}, 0.05, {1.0, 0.5, -0.25});
    out.escaped = true;
    s.spheres = {sphere_at({0.3, 0.3, 0.3}, 0.05), out};
    s.missed_collisions = {Vec3{0.2, 0.8, 0.6}};
    for (const Camera camera :
         {Camera{}, Camera{2.0, 0.3}, perspective(0.6, 0.42), perspective(4.0, 0.42)}) {
        CAPTURE(camera.yaw);
        CAPTURE(static_cast<int>(camera.projection));
        const ProjectedPanel p = project(s, camera);
        FailureMarks marks(10);
        marks.update(p.screen, 0.0);
        int left = 0;
        int missed = 0;
        for (const FailureMark& m : marks.marks()) {
            if (m.kind == FailureKind::left_box) {
                ++left;
                const Vec2 expected = seen_at(s, {1.0, 0.4, 0.7}, camera);
                CHECK(m.where.x == doctest::Approx(expected.x));
                CHECK(m.where.y == doctest::Approx(expected.y));
                // Pointing out of the face x = 1: along the projected +x axis from there.
                const Vec2 ahead = seen_at(s, {1.01, 0.4, 0.7}, camera) - expected;
                CHECK(dot(m.out, ahead) / norm(ahead) == doctest::Approx(1.0));
            } else if (m.kind == FailureKind::missed) {
                ++missed;
                const Vec2 expected = seen_at(s, {0.2, 0.8, 0.6}, camera);
                CHECK(m.where.x == doctest::Approx(expected.x));
                CHECK(m.where.y == doctest::Approx(expected.y));
            }
        }
        CHECK(left == 1);
        CHECK(missed == 1);
    }
}

TEST_CASE("an escape mark turns with an orbiting camera") {
    SphereSnapshot s;
    s.box = Box3{1.0, 1.0, 1.0, Boundary::walls};
    SphereState out = sphere_at({0.5, 0.5, 1.2}, 0.05, {0.0, 0.0, 1.0});
    out.escaped = true;
    s.spheres = {out};
    FailureMarks marks(10);
    marks.update(project(s, Camera{0.0, 0.42}).screen, 0.0);
    REQUIRE(marks.marks().size() == 1);
    const Vec2 before = marks.marks()[0].where;
    s.time = 0.1;
    s.spheres[0].position.z += 0.1;
    const Camera turned{1.0, 0.42};
    marks.update(project(s, turned).screen, 0.1);
    REQUIRE(marks.marks().size() == 1);
    const Vec2 after = marks.marks()[0].where;
    CHECK(after.x != doctest::Approx(before.x));
    CHECK(after.x == doctest::Approx(seen_at(s, {0.5, 0.5, 1.0}, turned).x));
}

}  // namespace
}  // namespace collide::show

namespace collide::show {
namespace {

TEST_CASE("with a slab, only the failures inside the slice are handed on to be marked") {
    SphereSnapshot s;
    s.box = Box3{1.0, 1.0, 1.0, Boundary::walls};
    // Seen from the front: an overlapping pair in the centre plane, one near the front; a missed
    // collision at the centre plane and one at the back.
    s.spheres = {sphere_at({0.3, 0.5, 0.5}, 0.05), sphere_at({0.38, 0.5, 0.5}, 0.05),
                 sphere_at({0.7, 0.5, 0.9}, 0.05), sphere_at({0.78, 0.5, 0.9}, 0.05)};
    s.overlapping_pairs = {{0, 1}, {2, 3}};
    s.missed_collisions = {Vec3{0.5, 0.3, 0.5}, Vec3{0.5, 0.3, 0.1}};
    const ProjectedPanel all = project(s, Camera{0.0, 0.0});
    CHECK(all.screen.overlapping_pairs.size() == 2);
    CHECK(all.screen.missed_collisions.size() == 2);
    const ProjectedPanel slab = project(s, Camera{0.0, 0.0, 0.2});
    REQUIRE(slab.screen.overlapping_pairs.size() == 1);
    CHECK(slab.screen.overlapping_pairs[0] == std::pair<std::uint32_t, std::uint32_t>{0, 1});
    REQUIRE(slab.screen.missed_collisions.size() == 1);
    CHECK(slab.screen.missed_collisions[0].x == doctest::Approx(all.screen.missed_collisions[0].x));
}

}  // namespace
}  // namespace collide::show
