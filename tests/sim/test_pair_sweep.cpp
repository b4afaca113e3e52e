// The time-driven engine's vectorised all-pairs sweep (src/sim/time/pair_sweep.*) against a
// straightforward double loop, and against the engine's exact tests: every pair those tests can
// flag (overlap, missed contact, census overlap) must be among the sweep's candidates, including
// exactly touching and near-tangent pairs, where rounding decides.

#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "collide/box.hpp"
#include "collide/sim/kinematics.hpp"
#include "time/pair_sweep.hpp"

using namespace collide;
using sim::detail::DiscPair;

namespace {

struct Discs {
    std::vector<Vec2> positions;
    std::vector<Vec2> velocities;
    std::vector<double> radii;

    void add(Vec2 p, Vec2 v, double r) {
        positions.push_back(p);
        velocities.push_back(v);
        radii.push_back(r);
    }
};

/// The sweep's bound written plainly: minimum-image distance by Box::displacement.
std::vector<DiscPair> plain_candidates(const Box& box, const Discs& d, double h) {
    const double slack = sim::detail::sweep_absolute_margin * std::max(box.width, box.height);
    auto reach = [&](std::size_t i) {
        return (d.radii[i] + norm(d.velocities[i]) * h) *
                   (1.0 + sim::detail::sweep_relative_margin) +
               slack;
    };
    std::vector<DiscPair> out;
    const auto n = static_cast<std::uint32_t>(d.positions.size());
    for (std::uint32_t i = 0; i < n; ++i) {
        for (std::uint32_t j = i + 1; j < n; ++j) {
            const double r = reach(i) + reach(j);
            if (norm2(box.displacement(d.positions[i], d.positions[j])) < r * r) {
                out.emplace_back(i, j);
            }
        }
    }
    return out;
}

/// The engine's exact tests (time_engine.hpp), for a step of length h that ended at d: the pair
/// overlaps now (a contact, or with h = 0 a census overlap), or it separates although its straight
/// paths touched inside the step (a missed collision).
bool flagged_exactly(const Box& box, const Discs& d, std::uint32_t i, std::uint32_t j, double h) {
    const Vec2 dr = box.displacement(d.positions[i], d.positions[j]);
    const Vec2 dv = d.velocities[j] - d.velocities[i];
    const double sigma = d.radii[i] + d.radii[j];
    if (norm2(dr) < sigma * sigma) {
        return true;
    }
    if (dot(dv, dr) < 0.0) {
        return false;
    }
    return kinematics::time_to_hit(dr - h * dv, dv, sigma) < h;
}

void check_sweep(const Box& box, const Discs& d, double h) {
    sim::detail::PairSweep sweep;
    std::vector<DiscPair> found;
    sweep.find(box, d.positions, d.velocities, d.radii, h, found);
    CHECK(found == plain_candidates(box, d, h));
    std::size_t flagged = 0;
    const auto n = static_cast<std::uint32_t>(d.positions.size());
    for (std::uint32_t i = 0; i < n; ++i) {
        for (std::uint32_t j = i + 1; j < n; ++j) {
            if (flagged_exactly(box, d, i, j, h)) {
                ++flagged;
                CAPTURE(i);
                CAPTURE(j);
                CHECK(std::binary_search(found.begin(), found.end(), DiscPair{i, j}));
            }
        }
    }
    CHECK(found.size() >= flagged);
}

/// n discs scattered over (and for periodic boxes a little beyond, as mid-step positions are
/// unwrapped) the box, overlapping freely.
Discs random_discs(std::size_t n, const Box& box, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Discs d;
    for (std::size_t k = 0; k < n; ++k) {
        const Vec2 p{box.width * (1.1 * unit(rng) - 0.05), box.height * (1.1 * unit(rng) - 0.05)};
        const Vec2 v{4.0 * unit(rng) - 2.0, 4.0 * unit(rng) - 2.0};
        d.add(p, v, 0.005 + 0.03 * unit(rng));
    }
    return d;
}

/// Pairs where rounding decides: exactly touching (at rest, approaching, separating), a hair
/// apart or overlapping, and straight paths that graze at exactly sigma inside the step.
Discs near_tangent_discs(const Box& box, double h) {
    Discs d;
    const double r = 0.00390625;  // 2^-8: sigma = 2r is exact
    const double sigma = 2.0 * r;
    double y = 0.05;
    auto row = [&](double gap, Vec2 va, Vec2 vb) {
        const Vec2 a{0.3, y};
        d.add(a, va, r);
        d.add({a.x + gap, y}, vb, r);
        y += 4.0 * sigma;
    };
    const double eps = std::numeric_limits<double>::epsilon();
    for (double gap : {sigma, std::nextafter(sigma, 0.0), std::nextafter(sigma, 1.0),
                       sigma * (1.0 + 8.0 * eps), sigma * (1.0 - 8.0 * eps)}) {
        row(gap, {0.0, 0.0}, {0.0, 0.0});
        row(gap, {1.0, 0.0}, {-1.0, 0.0});
        row(gap, {-1.0, 0.0}, {1.0, 0.0});
    }
    // Grazing: b passes a at closest distance sigma (1 + k eps) half-way through the step, moving
    // along y; at the end of the step it is |v| h / 2 past the closest point and separating.
    for (double k : {-4.0, -1.0, 0.0, 1.0, 4.0}) {
        const double speed = 0.5;
        const Vec2 a{0.7, y};
        d.add(a, {0.0, 0.0}, r);
        d.add({a.x + sigma * (1.0 + k * eps), a.y + 0.5 * speed * h}, {0.0, speed}, r);
        y += 4.0 * sigma + speed * h;
    }
    // Across the periodic seam: a touching pair split by the x = 0 edge.
    if (box.boundary == Boundary::periodic) {
        d.add({box.width - r, 0.9}, {1.0, 0.0}, r);
        d.add({r, 0.9}, {-1.0, 0.0}, r);
    }
    return d;
}

}  // namespace

TEST_CASE("pair sweep: equals a plain double loop on random discs, and keeps every exact hit") {
    for (Boundary boundary : {Boundary::walls, Boundary::periodic}) {
        const Box box{1.0, 0.75, boundary};
        // 203 discs: rows end mid-block, so the block tails are exercised.
        const Discs d = random_discs(203, box, boundary == Boundary::walls ? 1 : 2);
        for (double h : {0.0, 1e-3, 0.02}) {
            CAPTURE(h);
            CAPTURE(boundary == Boundary::periodic);
            check_sweep(box, d, h);
        }
    }
}

TEST_CASE("pair sweep: exactly touching and near-tangent pairs are candidates") {
    for (Boundary boundary : {Boundary::walls, Boundary::periodic}) {
        const Box box{1.0, 1.0, boundary};
        for (double h : {0.0, 1e-3, 0.05}) {
            CAPTURE(h);
            CAPTURE(boundary == Boundary::periodic);
            check_sweep(box, near_tangent_discs(box, h), h);
        }
    }
}

TEST_CASE("pair sweep: near-tangent pairs far outside a walled box are candidates too") {
    // Escaped discs fly on; far from the origin, float rounding of positions (the counting
    // pass's) is coarse, and the pass's padding must grow with it.
    const Box box{1.0, 1.0, Boundary::walls};
    for (double offset : {-37.3, 1000.3, 1.0e5 + 0.3}) {
        for (double h : {0.0, 1e-3}) {
            CAPTURE(offset);
            CAPTURE(h);
            Discs d = near_tangent_discs(box, h);
            for (Vec2& p : d.positions) p = p + Vec2{offset, 0.5 * offset};
            d.add({0.5, 0.5}, {0.0, 0.0}, 0.01);  // one disc stays home
            check_sweep(box, d, h);
        }
    }
}

TEST_CASE("pair sweep: no discs, one disc") {
    sim::detail::PairSweep sweep;
    std::vector<DiscPair> found{{0, 1}};
    sweep.find(Box{}, {}, {}, {}, 0.1, found);
    CHECK(found.empty());
    sweep.find(Box{}, {{0.5, 0.5}}, {{1.0, 0.0}}, {0.1}, 0.1, found);
    CHECK(found.empty());
}

// Ctrl-C during one all-pairs step over 10^6 discs (a minute of sweeping) must not wait for the
// end of the step: the sweep looks at the stop flag before a row once 4096 pairs have passed.
TEST_CASE("pair sweep: a set stop flag ends the sweep after a few thousand pairs") {
    const Box box{1.0, 1.0, Boundary::walls};
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> coord(0.0, 1.0);
    Discs d;
    for (int k = 0; k < 3000; ++k) d.add({coord(rng), coord(rng)}, {0.0, 0.0}, 0.05);
    sim::detail::PairSweep sweep;
    std::vector<DiscPair> out;
    const std::atomic<bool> stop{true};
    CHECK_FALSE(sweep.find(box, d.positions, d.velocities, d.radii, 0.01, out, &stop));
    // Rows 0 and 1 (2999 + 2998 pairs) ran before the first look; nothing after them.
    REQUIRE_FALSE(out.empty());
    CHECK(std::all_of(out.begin(), out.end(), [](const DiscPair& p) { return p.first <= 1; }));
    // A clear flag changes nothing: every candidate, as without a flag.
    const std::atomic<bool> go{false};
    CHECK(sweep.find(box, d.positions, d.velocities, d.radii, 0.01, out, &go));
    CHECK(out == plain_candidates(box, d, 0.01));
}
