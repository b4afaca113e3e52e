#pragma once
// Scenes for the engine tests: small dense fluids on a square lattice with Gaussian velocities
// (zero total momentum, kT = 1), hand-placed few-disc setups, and algs4 files from ../shared.

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <numbers>
#include <optional>
#include <random>
#include <string>

#include "collide/scene.hpp"
#include "collide/sim/algs4.hpp"

namespace collide::test {

/// n_side^2 equal discs (radius r, mass 1) on a square lattice at packing fraction eta,
/// Gaussian velocities with zero total momentum and kT = 1.
inline Scene lattice_fluid(std::size_t n_side, double eta, Boundary boundary, std::uint64_t seed,
                           double radius = 0.01) {
    Scene s;
    s.name = "lattice";
    const double n = static_cast<double>(n_side * n_side);
    const double side = std::sqrt(n * std::numbers::pi * radius * radius / eta);
    s.box = Box{side, side, boundary};
    const double a = side / static_cast<double>(n_side);
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> gauss(0.0, 1.0);
    Vec2 total{};
    for (std::size_t iy = 0; iy < n_side; ++iy) {
        for (std::size_t ix = 0; ix < n_side; ++ix) {
            Disc d;
            d.position = {(static_cast<double>(ix) + 0.5) * a, (static_cast<double>(iy) + 0.5) * a};
            d.velocity = {gauss(rng), gauss(rng)};
            d.radius = radius;
            d.mass = 1.0;
            total += d.velocity;
            s.discs.push_back(d);
        }
    }
    double kinetic = 0.0;
    for (Disc& d : s.discs) {
        d.velocity -= (1.0 / n) * total;
        kinetic += 0.5 * norm2(d.velocity);
    }
    const double scale = std::sqrt(n / kinetic);  // kT = KE / N = 1
    for (Disc& d : s.discs) d.velocity *= scale;
    return s;
}

/// Two discs in the unit box moving head-on along y = 0.5.
inline Scene head_on() {
    Scene s;
    s.box = Box{1.0, 1.0, Boundary::walls};
    Disc a;
    a.position = {0.2, 0.5};
    a.velocity = {0.1, 0.0};
    a.radius = 0.1;
    Disc b = a;
    b.position = {0.8, 0.5};
    b.velocity = {-0.1, 0.0};
    s.discs = {a, b};
    return s;
}

inline std::filesystem::path algs4_dir() {
    return std::filesystem::path(COLLIDE_SHARED_DIR) / "data" / "algs4";
}

/// Reads and validates an algs4 file from ../shared/data/algs4; std::nullopt when it is absent
/// (tests then skip with COLLIDE_SKIP_TEST, support/skip.hpp).
inline std::optional<Scene> read_algs4(const std::string& name) {
    const std::filesystem::path path = algs4_dir() / name;
    if (!std::filesystem::exists(path)) return std::nullopt;
    return read_algs4_file(path).scene;
}

}  // namespace collide::test
