// The camera of a panel of spheres: projection onto the screen, the box's edges, and the discs
// that stand in for the spheres everywhere a video reads a Snapshot.
#include "collide/show/sphere_camera.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <numeric>

namespace collide::show {

namespace {

/// A point relative to the box's centre, in camera space: x right, y up, z towards the viewer.
struct Rotation {
    double cy, sy, cp, sp;
    explicit Rotation(Camera c) noexcept
        : cy(std::cos(c.yaw)), sy(std::sin(c.yaw)), cp(std::cos(c.pitch)), sp(std::sin(c.pitch)) {}
    [[nodiscard]] Vec3 apply(Vec3 q) const noexcept {
        const double x1 = cy * q.x + sy * q.z;
        const double z1 = -sy * q.x + cy * q.z;
        return {x1, cp * q.y - sp * z1, sp * q.y + cp * z1};
    }
};

double largest_radius(const SphereSnapshot& s) noexcept {
    double r = 0.0;
    for (const SphereState& p : s.spheres) r = std::max(r, p.radius);
    return r;
}

/// Half the depth range: the box's half diagonal and a sphere radius, so every surface point of a
/// sphere inside the box has a depth in [0, 1].
double depth_half_range(const Box3& box, double radius) noexcept {
    return 0.5 *
               std::sqrt(box.width * box.width + box.height * box.height + box.depth * box.depth) +
           radius;
}

}  // namespace

Camera camera_at(CameraMotion motion, double video_seconds, double slab) noexcept {
    Camera c;
    c.slab = slab;
    if (motion == CameraMotion::orbit)
        c.yaw += 2.0 * std::numbers::pi * std::fmod(video_seconds / orbit_seconds, 1.0);
    return c;
}

Box screen_box(const Box3& box, double largest_radius, Camera camera) noexcept {
    // Any yaw: the footprint's half diagonal; the pitch tilts the height and the footprint.
    const double footprint = 0.5 * std::sqrt(box.width * box.width + box.depth * box.depth);
    const double half_w = footprint + largest_radius;
    const double half_h = 0.5 * box.height * std::cos(camera.pitch) +
                          footprint * std::sin(camera.pitch) + largest_radius;
    return Box{2.0 * half_w, 2.0 * half_h, box.boundary};
}

ProjectedPanel project(const SphereSnapshot& snapshot, Camera camera) {
    ProjectedPanel out;
    project(snapshot, camera, out);
    return out;
}

void project(const SphereSnapshot& snapshot, Camera camera, ProjectedPanel& out) {
    const Box3& box = snapshot.box;
    const double radius = largest_radius(snapshot);
    const Box screen = screen_box(box, radius, camera);
    const Rotation rotate(camera);
    const Vec3 centre{0.5 * box.width, 0.5 * box.height, 0.5 * box.depth};
    const double half_depth = depth_half_range(box, radius);
    const auto to_screen = [&](Vec3 p, double& depth) {
        const Vec3 c = rotate.apply(p - centre);
        depth = 0.5 - c.z / (2.0 * half_depth);
        return Vec2{c.x + 0.5 * screen.width, c.y + 0.5 * screen.height};
    };

    Snapshot& s = out.screen;
    s.time = snapshot.time;
    s.box = screen;
    s.dimension = 3;
    s.discs.resize(snapshot.spheres.size());
    SphereView& view = out.view;
    view.spheres.clear();
    view.spheres.reserve(snapshot.spheres.size());
    // The slab: a depth range about the centre (depth 0.5) of half width slab / 2.
    const double slab_half_depth = camera.slab > 0.0 ? camera.slab / (4.0 * half_depth) : 1.0;
    for (std::size_t i = 0; i < snapshot.spheres.size(); ++i) {
        const SphereState& p = snapshot.spheres[i];
        SphereSprite sprite;
        sprite.at = to_screen(p.position, sprite.depth);
        sprite.radius = p.radius;
        sprite.radius_depth = p.radius / (2.0 * half_depth);
        sprite.speed = norm(p.velocity);
        sprite.mass = p.mass;
        sprite.color = p.color;
        sprite.tagged = p.tagged;
        if (std::abs(sprite.depth - 0.5) <= slab_half_depth) view.spheres.push_back(sprite);
        DiscState& d = s.discs[i];
        d.position = sprite.at;
        d.velocity = {p.velocity.x, std::hypot(p.velocity.y, p.velocity.z)};
        d.radius = p.radius;
        d.mass = p.mass;
        d.color = p.color;
        d.tagged = false;  // no trails: a path projected from 3D reads as a tangle
        d.escaped = p.escaped;
    }
    // Far to near, ties in scene order: the same order on every run.
    std::stable_sort(
        view.spheres.begin(), view.spheres.end(),
        [](const SphereSprite& a, const SphereSprite& b) { return a.depth > b.depth; });

    // A pair that overlaps across a periodic box's edge has its spheres on opposite sides of the
    // screen: no point between them is where they meet, so only pairs that touch directly are
    // handed on (the figures still count every pair: they come from the measurements).
    s.overlapping_pairs.clear();
    for (const auto& [i, j] : snapshot.overlapping_pairs) {
        const Vec3 a = snapshot.spheres[i].position;
        const Vec3 b = snapshot.spheres[j].position;
        if (norm2(box.displacement(a, b)) == norm2(b - a)) s.overlapping_pairs.emplace_back(i, j);
    }
    s.missed_collisions.clear();
    for (const Vec3& m : snapshot.missed_collisions) {
        double depth = 0.0;
        s.missed_collisions.push_back(to_screen(m, depth));
    }
    s.queue.reset();

    // The 12 edges; the three that meet at the corner nearest the viewer are drawn over the
    // spheres (the box's front), the others behind them.
    std::array<Vec2, 8> corner{};
    std::array<double, 8> corner_depth{};
    for (int k = 0; k < 8; ++k) {
        const Vec3 p{(k & 1) != 0 ? box.width : 0.0, (k & 2) != 0 ? box.height : 0.0,
                     (k & 4) != 0 ? box.depth : 0.0};
        corner[static_cast<std::size_t>(k)] =
            to_screen(p, corner_depth[static_cast<std::size_t>(k)]);
    }
    const auto nearest = static_cast<int>(
        std::min_element(corner_depth.begin(), corner_depth.end()) - corner_depth.begin());
    view.edges.clear();
    for (int a = 0; a < 8; ++a) {
        for (const int bit : {1, 2, 4}) {
            if ((a & bit) != 0) continue;
            const int b = a | bit;
            view.edges.push_back({corner[static_cast<std::size_t>(a)],
                                  corner[static_cast<std::size_t>(b)],
                                  a == nearest || b == nearest});
        }
    }
}

Scene stand_in_scene(const SphereScene& scene) {
    Scene out;
    out.name = scene.name;
    out.title = scene.title;
    out.description = scene.description;
    out.box = Box{scene.box.width, scene.box.height, scene.box.boundary};
    out.render = scene.render;
    out.discs.reserve(scene.spheres.size());
    for (const Sphere& p : scene.spheres) {
        Disc d;
        d.position = {p.position.x, p.position.y};
        d.velocity = {p.velocity.x, std::hypot(p.velocity.y, p.velocity.z)};
        d.radius = p.radius;
        d.mass = p.mass;
        d.color = p.color;
        d.tag = p.tag;
        out.discs.push_back(std::move(d));
    }
    return out;
}

}  // namespace collide::show
