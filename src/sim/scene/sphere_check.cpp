#include "collide/sim/sphere_check.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace collide {

double packing_fraction(const SphereScene& scene) noexcept {
    double covered = 0.0;
    for (const Sphere& s : scene.spheres)
        covered += 4.0 / 3.0 * std::numbers::pi * s.radius * s.radius * s.radius;
    return covered / scene.box.volume();
}

namespace {

struct Means {
    double diameter = 0.0;
    double mass = 0.0;
    double kt = 0.0;
};

Means means(const SphereScene& scene) {
    Means m;
    const auto n = static_cast<double>(scene.spheres.size());
    if (n == 0) return m;
    double kinetic = 0.0;
    for (const Sphere& s : scene.spheres) {
        m.diameter += 2.0 * s.radius;
        m.mass += s.mass;
        kinetic += 0.5 * s.mass * norm2(s.velocity);
    }
    m.diameter /= n;
    m.mass /= n;
    m.kt = 2.0 * kinetic / (3.0 * n);
    return m;
}

}  // namespace

double collisions_per_time_unit(const SphereScene& scene) noexcept {
    const Means m = means(scene);
    if (!(m.kt > 0.0)) return 0.0;
    const double n = static_cast<double>(scene.spheres.size());
    const double density = n / scene.box.volume();
    const double eta = std::min(packing_fraction(scene), 0.7);
    const double contact = (1.0 - 0.5 * eta) / std::pow(1.0 - eta, 3.0);
    const double per_sphere = 4.0 * density * m.diameter * m.diameter * contact *
                              std::sqrt(std::numbers::pi * m.kt / m.mass);
    return 0.5 * n * per_sphere;
}

double sphere_crossing_rate(const SphereScene& scene) noexcept {
    const std::size_t n = scene.spheres.size();
    if (n == 0) return 0.0;
    double crossing_speed = 0.0;
    for (const Sphere& s : scene.spheres) {
        crossing_speed += std::abs(s.velocity.x) + std::abs(s.velocity.y) + std::abs(s.velocity.z);
    }
    const double diameter = means(scene).diameter;
    const double volume = scene.box.volume();
    const double cells = std::min(volume / (diameter * diameter * diameter),
                                  std::max(27.0, 2.0 * static_cast<double>(n)));
    return crossing_speed / std::cbrt(volume / std::max(1.0, cells));
}

WorkEstimate estimate_work(const SphereScene& scene, const RunShape& run) noexcept {
    return estimate_work_at_rates(collisions_per_time_unit(scene),
                                  run.cell_grid ? sphere_crossing_rate(scene) : 0.0,
                                  scene.spheres.size(), run);
}

std::string sphere_scene_summary(const SphereScene& scene) {
    std::ostringstream s;
    s.precision(4);
    s << "N = " << scene.spheres.size() << " spheres (3D), eta = " << packing_fraction(scene)
      << ", box " << scene.box.width << " x " << scene.box.height << " x " << scene.box.depth
      << ", " << (scene.box.boundary == Boundary::periodic ? "periodic" : "walls")
      << ", kT = " << means(scene).kt << ", about " << collisions_per_time_unit(scene)
      << " collisions per time unit";
    return s.str();
}

}  // namespace collide
