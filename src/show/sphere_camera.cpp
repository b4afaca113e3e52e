// The camera of a panel of spheres: projection onto the screen, the box's edges, and the discs
// that stand in for the spheres everywhere a video reads a Snapshot.
#include "collide/show/sphere_camera.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <numeric>
#include <vector>

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

/// The perspective eye's distance from the box's centre (box units); 0: orthographic.
double eye_distance(const Box3& box, Projection projection) noexcept {
    if (projection == Projection::orthographic) return 0.0;
    return eye_distance_in_half_diagonals * depth_half_range(box, 0.0);
}

/// Camera space to the screen plane (the plane through the box's centre facing the camera): the
/// scale of a point at height z towards the viewer (1 everywhere when orthographic).
struct Lens {
    double eye = 0.0;  ///< the eye's distance from the screen plane; 0: orthographic
    [[nodiscard]] double scale(double z) const noexcept {
        return eye > 0.0 ? eye / (eye - z) : 1.0;
    }
    /// Whether a sphere of radius r at height z lies wholly in front of the eye.
    [[nodiscard]] bool sees(double z, double r) const noexcept { return eye <= 0.0 || z + r < eye; }
    /// The screen direction of a step along `n` (camera space) from the point c: the derivative
    /// of the projection, so that under a perspective it points along the projected line.
    [[nodiscard]] Vec2 direction(Vec3 c, Vec3 n) const noexcept {
        if (eye <= 0.0) return {n.x, n.y};
        const double s = scale(c.z);
        const double pull = n.z / (eye - c.z);  // the step's change of the scale, relative
        return {s * (n.x + c.x * pull), s * (n.y + c.y * pull)};
    }
};

/// The largest distance of the box's projected corners from the screen's centre along x and
/// along y, over a whole turn of the yaw, and the largest scale of a point of the box. Sampled
/// every quarter degree (the corners move smoothly with the yaw).
struct Reach {
    double x = 0.0;
    double y = 0.0;
    double scale = 1.0;
};

Reach perspective_reach(const Box3& box, double largest_radius, Camera camera, Lens lens) {
    constexpr int samples = 1440;
    Reach reach;
    for (int k = 0; k < samples; ++k) {
        Camera turned = camera;
        turned.yaw = 2.0 * std::numbers::pi * k / samples;
        const Rotation rotate(turned);
        for (int corner = 0; corner < 8; ++corner) {
            const Vec3 q{((corner & 1) != 0 ? 0.5 : -0.5) * box.width,
                         ((corner & 2) != 0 ? 0.5 : -0.5) * box.height,
                         ((corner & 4) != 0 ? 0.5 : -0.5) * box.depth};
            const Vec3 c = rotate.apply(q);
            const double s = lens.scale(c.z);
            const double near = lens.scale(std::min(c.z + largest_radius, 0.5 * lens.eye));
            reach.x = std::max(reach.x, std::abs(c.x) * s + largest_radius * near);
            reach.y = std::max(reach.y, std::abs(c.y) * s + largest_radius * near);
            reach.scale = std::max(reach.scale, near);
        }
    }
    // The samples may miss a maximum by a relative 1e-5: a little margin covers it.
    reach.x *= 1.001;
    reach.y *= 1.001;
    return reach;
}

/// Where a sphere outside a walled box crossed its wall (the face crossed last, going back along
/// its velocity) and the face's outward normal: show::exit_point in three dimensions.
struct Exit3 {
    Vec3 where;
    Vec3 out;
};

Exit3 exit_point3(const SphereState& sphere, const Box3& box) noexcept {
    const Vec3 p = sphere.position;
    const Vec3 v = sphere.velocity;
    const std::array<double, 3> pos{p.x, p.y, p.z};
    const std::array<double, 3> vel{v.x, v.y, v.z};
    const std::array<double, 3> extent{box.width, box.height, box.depth};
    double back = -1.0;
    int axis = -1;
    double sign = 0.0;
    for (int k = 0; k < 3; ++k) {
        const auto i = static_cast<std::size_t>(k);
        double t = -1.0;
        double s = 0.0;
        if (pos[i] > extent[i] && vel[i] > 0.0) {
            t = (pos[i] - extent[i]) / vel[i];
            s = 1.0;
        } else if (pos[i] < 0.0 && vel[i] < 0.0) {
            t = pos[i] / vel[i];
            s = -1.0;
        }
        if (t > back) {
            back = t;
            axis = k;
            sign = s;
        }
    }
    std::array<double, 3> where = pos;
    if (back >= 0.0) {
        for (std::size_t i = 0; i < 3; ++i) where[i] -= back * vel[i];
    } else {
        // Not moving away (turned round outside): the face it is farthest beyond.
        double over = -1.0;
        for (int k = 0; k < 3; ++k) {
            const auto i = static_cast<std::size_t>(k);
            const double beyond = std::max(-pos[i], pos[i] - extent[i]);
            if (beyond > over) {
                over = beyond;
                axis = k;
                sign = pos[i] < 0.0 ? -1.0 : 1.0;
            }
        }
    }
    std::array<double, 3> out{0.0, 0.0, 0.0};
    for (std::size_t i = 0; i < 3; ++i) where[i] = std::clamp(where[i], 0.0, extent[i]);
    const auto a = static_cast<std::size_t>(axis);
    where[a] = sign > 0.0 ? extent[a] : 0.0;  // on the face crossed, exactly
    out[a] = sign;
    return {{where[0], where[1], where[2]}, {out[0], out[1], out[2]}};
}

}  // namespace

Camera camera_at(CameraMotion motion, double video_seconds, double slab,
                 Projection projection) noexcept {
    Camera c;
    c.slab = slab;
    c.projection = projection;
    if (motion == CameraMotion::orbit)
        c.yaw += 2.0 * std::numbers::pi * std::fmod(video_seconds / orbit_seconds, 1.0);
    return c;
}

Box screen_box(const Box3& box, double largest_radius, Camera camera) noexcept {
    if (camera.projection == Projection::perspective) {
        const Reach reach = perspective_reach(box, largest_radius, camera,
                                              Lens{eye_distance(box, camera.projection)});
        return Box{2.0 * reach.x, 2.0 * reach.y, box.boundary};
    }
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
    const Lens lens{eye_distance(box, camera.projection)};
    const Vec3 centre{0.5 * box.width, 0.5 * box.height, 0.5 * box.depth};
    const double half_depth = depth_half_range(box, radius);
    const Vec2 screen_centre{0.5 * screen.width, 0.5 * screen.height};
    const auto on_plane = [&](Vec3 c) {
        return Vec2{c.x + screen_centre.x, c.y + screen_centre.y};
    };
    const auto projected = [&](Vec3 c) {
        const double s = lens.scale(c.z);
        return Vec2{c.x * s + screen_centre.x, c.y * s + screen_centre.y};
    };
    const auto to_screen = [&](Vec3 p, double& depth) {
        const Vec3 c = rotate.apply(p - centre);
        depth = 0.5 - c.z / (2.0 * half_depth);
        return projected(c);
    };

    Snapshot& s = out.screen;
    s.time = snapshot.time;
    s.box = screen;
    s.dimension = 3;
    s.discs.resize(snapshot.spheres.size());
    SphereView& view = out.view;
    view.eye_distance = lens.eye;
    view.eye_at = screen_centre;
    view.spheres.clear();
    view.spheres.reserve(snapshot.spheres.size());
    // The slab: a depth range about the centre (depth 0.5) of half width slab / 2.
    const double slab_half_depth = camera.slab > 0.0 ? camera.slab / (4.0 * half_depth) : 1.0;
    const auto in_slab = [&](double depth) { return std::abs(depth - 0.5) <= slab_half_depth; };
    // Which spheres the picture shows: a failure is marked only where its spheres are seen (the
    // figures still count every failure: they come from the measurements).
    std::vector<bool> shown(snapshot.spheres.size(), false);
    for (std::size_t i = 0; i < snapshot.spheres.size(); ++i) {
        const SphereState& p = snapshot.spheres[i];
        const Vec3 c = rotate.apply(p.position - centre);
        SphereSprite sprite;
        sprite.at = projected(c);
        sprite.depth = 0.5 - c.z / (2.0 * half_depth);
        sprite.radius = p.radius * lens.scale(c.z);
        sprite.radius_depth = p.radius / (2.0 * half_depth);
        sprite.plane_at = on_plane(c);
        sprite.height = c.z;
        sprite.ball_radius = p.radius;
        sprite.speed = norm(p.velocity);
        sprite.mass = p.mass;
        sprite.color = p.color;
        sprite.tagged = p.tagged;
        if (in_slab(sprite.depth) && lens.sees(c.z, p.radius)) {
            view.spheres.push_back(sprite);
            shown[i] = true;
        }
        DiscState& d = s.discs[i];
        d.position = sprite.at;
        d.velocity = {p.velocity.x, std::hypot(p.velocity.y, p.velocity.z)};
        d.radius = lens.sees(c.z, p.radius) ? sprite.radius : p.radius;
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
        if (norm2(box.displacement(a, b)) == norm2(b - a) && shown[i] && shown[j])
            s.overlapping_pairs.emplace_back(i, j);
    }
    s.missed_collisions.clear();
    for (const Vec3& m : snapshot.missed_collisions) {
        double depth = 0.0;
        const Vec2 where = to_screen(m, depth);
        if (in_slab(depth)) s.missed_collisions.push_back(where);
    }
    // An escaped sphere's mark sits where it crossed the wall, on the screen, pointing out of the
    // face it crossed; recomputed every frame, so that it turns with an orbiting camera.
    s.exits.clear();
    for (std::size_t i = 0; i < snapshot.spheres.size(); ++i) {
        if (!snapshot.spheres[i].escaped) continue;
        const Exit3 exit = exit_point3(snapshot.spheres[i], box);
        const Vec3 c = rotate.apply(exit.where - centre);
        const Vec2 along = lens.direction(c, rotate.apply(exit.out));
        const double length = norm(along);
        s.exits.push_back({static_cast<std::uint32_t>(i), projected(c),
                           length > 0.0 ? (1.0 / length) * along : Vec2{0.0, 1.0}});
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
