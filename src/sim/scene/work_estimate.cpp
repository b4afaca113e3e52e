// Work estimates: kinetic theory for collisions, span / dt for steps. Orders of magnitude only.

#include "collide/sim/work_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "collide/sim/scene_check.hpp"

namespace collide {

namespace {

/// Henderson's contact value is fitted up to the freezing range; beyond it, a cap keeps the
/// estimate finite for a jammed scene (which the engines treat separately).
constexpr double max_packing_for_rate = 0.9;

double contact_correlation(double eta) noexcept {
    const double e = std::clamp(eta, 0.0, max_packing_for_rate);
    return (1.0 - 7.0 * e / 16.0) / ((1.0 - e) * (1.0 - e));
}

}  // namespace

CollisionRate collision_rate(const Scene& scene) noexcept {
    CollisionRate rate;
    const std::size_t n = scene.discs.size();
    if (n == 0) return rate;
    double speed_sum = 0.0;
    double radius_sum = 0.0;
    for (const Disc& d : scene.discs) {
        speed_sum += norm(d.velocity);
        radius_sum += d.radius;
    }
    const double area = scene.box.area();
    const double eta = packing_fraction(scene);
    const double g = contact_correlation(eta);
    if (n >= 2) {
        const double density = static_cast<double>(n - 1) / area;
        // Two discs meet when their centres pass within d = r_i + r_j: the swept width is 2 d.
        const double width = 4.0 * radius_sum / static_cast<double>(n);
        rate.pairs = g * density * width * speed_sum / std::numbers::sqrt2;
    }
    if (scene.box.boundary == Boundary::walls) {
        // Discs crowd at a wall as they do at a disc: the density there is n (1 + 2 eta g), the
        // compressibility factor of the 2D hard-disc gas.
        rate.walls = (1.0 + 2.0 * eta * g) * 2.0 / std::numbers::pi * speed_sum *
                     (1.0 / scene.box.width + 1.0 / scene.box.height);
    }
    return rate;
}

double cell_crossing_rate(const Scene& scene) noexcept {
    const std::size_t n = scene.discs.size();
    if (n == 0) return 0.0;
    double radius_sum = 0.0;
    double crossing_speed = 0.0;  // sum of |v_x| + |v_y|
    for (const Disc& d : scene.discs) {
        radius_sum += d.radius;
        crossing_speed += std::abs(d.velocity.x) + std::abs(d.velocity.y);
    }
    const double diameter = 2.0 * radius_sum / static_cast<double>(n);
    const double area = scene.box.area();
    const double cells =
        std::min(area / (diameter * diameter), std::max(9.0, 2.0 * static_cast<double>(n)));
    return crossing_speed / std::sqrt(area / std::max(1.0, cells));
}

WorkEstimate estimate_work(const Scene& scene, const RunShape& run) noexcept {
    return estimate_work_at_rates(collision_rate(scene).total(),
                                  run.cell_grid ? cell_crossing_rate(scene) : 0.0,
                                  scene.discs.size(), run);
}

WorkEstimate estimate_work_at_rates(double collisions_per_time, double crossings_per_time,
                                    std::size_t particles, const RunShape& run) noexcept {
    WorkEstimate work;
    const double span = std::max(0.0, run.span);
    if (run.event_driven && span > 0.0) {
        work.collisions = collisions_per_time * span;
        if (run.cell_grid) work.crossings = crossings_per_time * span;
        const auto n = static_cast<double>(particles);
        if (run.classic) work.predictions = n * (n - 1.0) / 2.0 + work.collisions * 2.0 * n;
        if (run.classic && run.array_queue) {
            const double pushed = std::max(2.0, classic_finite_fraction * 2.0 * n);
            work.queue_steps =
                work.collisions * n + pushed * work.collisions * work.collisions / 2.0;
        }
    }
    if (run.time_driven && span > 0.0) {
        work.steps = span / run.dt;
        work.dt_below_resolution = !(span + run.dt > span);
        const auto n = static_cast<double>(particles);
        const double per_step = run.all_pairs ? n * (n - 1.0) / 2.0 : n * grid_checks_per_disc;
        work.pair_checks = work.steps * per_step;
    }
    work.frames = std::max(0.0, run.frames);
    // 0 * inf (no discs, infinite span) is no work, not NaN.
    for (double* v : {&work.collisions, &work.crossings, &work.steps, &work.pair_checks,
                      &work.predictions, &work.queue_steps}) {
        if (std::isnan(*v)) *v = 0.0;
    }
    return work;
}

WorkExcess first_excess(const WorkEstimate& work, const WorkLimits& limits) {
    WorkExcess worst;
    double worst_ratio = 1.0;
    const auto consider = [&](const char* what, double estimate, double limit) {
        const double ratio = estimate / limit;
        if (ratio > worst_ratio) {
            worst_ratio = ratio;
            worst = {what, estimate, limit};
        }
    };
    consider("events", work.collisions + work.crossings, limits.events);
    consider("time-driven steps", work.steps, limits.steps);
    consider("overlap checks", work.pair_checks, limits.pair_checks);
    consider("frames", work.frames, limits.frames);
    consider("pair predictions", work.predictions, limits.predictions);
    consider("queue steps", work.queue_steps, limits.queue_steps);
    return worst;
}

std::string rough_number(double value) {
    char buf[32];
    if (std::isinf(value)) return value > 0 ? "infinitely many" : "-inf";
    if (std::abs(value) < 1e6 && value == std::floor(value)) {
        std::snprintf(buf, sizeof buf, "%.0f", value);
    } else if (std::abs(value) < 1e6) {
        std::snprintf(buf, sizeof buf, "%.3g", value);
    } else {
        std::snprintf(buf, sizeof buf, "%.2g", value);
    }
    return buf;
}

}  // namespace collide
