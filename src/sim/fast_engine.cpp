#include "collide/sim/fast_engine.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <tuple>
#include <utility>

#include "collide/error.hpp"
#include "collide/sim/kinematics.hpp"

namespace collide::sim {

namespace {

using kinematics::never;

/// Cells are this much wider than the largest small-disc diameter, so that a disc sitting a
/// rounding error outside its cell still only reaches the neighbouring cells.
constexpr double cell_margin = 1e-9;

/// Upper bound on grid cells per disc: enough for dense fluids (pi / (4 eta) cells per disc at
/// cells one diameter wide), and it stops dilute scenes from allocating millions of empty cells.
constexpr double max_cells_per_disc = 2.0;

/// Cells along one axis: as many as fit with cells at least `min_cell` wide.
std::uint32_t fit_cells(double extent, double min_cell) {
    if (!(min_cell > 0.0)) return 1;
    const double n = std::floor(extent / min_cell);
    if (!(n >= 1.0)) return 1;
    return static_cast<std::uint32_t>(std::min(n, 65536.0));
}

}  // namespace

bool FastEngine::KeyLess::tie_break(const Key& x, const Key& y) const noexcept {
    if (x.kind() != y.kind()) return x.kind() < y.kind();
    const auto ids = [this](const Key& k) {
        const std::uint32_t a = (*scene_index)[k.a];
        if (k.kind() != EventKind::pair) return std::pair{a, k.b()};
        const std::uint32_t b = (*scene_index)[k.b()];
        return std::pair{std::min(a, b), std::max(a, b)};
    };
    return ids(x) < ids(y);
}

FastEngine::FastEngine(const Scene& scene)
    : core_(scene), box_(scene.box), periodic_(scene.box.boundary == Boundary::periodic) {
    choose_grid(scene);
    place_discs(scene);
    instant_limit_ = instant_collision_limit(p_.size());
    for (std::uint32_t i = 0; i < p_.size(); ++i) predict(i);
}

namespace {

/// The big-disc threshold and the largest small radius of a scene.
std::pair<double, double> split_radii(const Scene& scene) {
    std::vector<double> radii;
    radii.reserve(scene.discs.size());
    for (const Disc& d : scene.discs) radii.push_back(d.radius);
    const double big = big_radius_threshold(radii);
    double small_max = 0.0;
    for (double r : radii) {
        if (r <= big) small_max = std::max(small_max, r);
    }
    return {big, small_max};
}

}  // namespace

bool FastEngine::can_simulate(const Scene& scene) {
    if (scene.box.boundary != Boundary::periodic) return true;
    const double min_cell = 2.0 * split_radii(scene).second * (1.0 + cell_margin);
    return fit_cells(scene.box.width, min_cell) >= 3 && fit_cells(scene.box.height, min_cell) >= 3;
}

void FastEngine::choose_grid(const Scene& scene) {
    std::tie(big_threshold_, small_radius_max_) = split_radii(scene);
    const double min_cell = 2.0 * small_radius_max_ * (1.0 + cell_margin);
    std::uint32_t nx = fit_cells(box_.width, min_cell);
    std::uint32_t ny = fit_cells(box_.height, min_cell);
    if (periodic_ && (nx < 3 || ny < 3)) {
        throw_scene_error("", 0, nx < 3 ? "box.width" : "box.height",
                          "a periodic box must be at least three disc diameters wide and tall for "
                          "the fast engine (the classic engine has no such limit)");
    }
    // Dilute scenes: fewer, larger cells (each must stay at least min_cell wide, so only shrink).
    const double cap = std::max(9.0, max_cells_per_disc * static_cast<double>(scene.discs.size()));
    const double cells = static_cast<double>(nx) * static_cast<double>(ny);
    if (cells > cap) {
        const double shrink = std::sqrt(cap / cells);
        const std::uint32_t floor_n = periodic_ ? 3U : 1U;
        nx = std::max(floor_n, static_cast<std::uint32_t>(static_cast<double>(nx) * shrink));
        ny = std::max(floor_n, static_cast<std::uint32_t>(static_cast<double>(ny) * shrink));
    }
    nx_ = nx;
    ny_ = ny;
    cw_ = box_.width / nx_;
    ch_ = box_.height / ny_;
    head_.assign(static_cast<std::size_t>(nx_) * ny_, no_disc);
}

std::uint32_t FastEngine::cell_of(double x, double y) const noexcept {
    const auto clamp_index = [](double v, std::uint32_t n) {
        if (!(v > 0.0)) return 0U;
        const auto k = static_cast<std::uint32_t>(std::min(v, static_cast<double>(n - 1)));
        return k;
    };
    return clamp_index(y / ch_, ny_) * nx_ + clamp_index(x / cw_, nx_);
}

namespace {

/// Interleaves the bits of x and y (Z-order / Morton code).
std::uint64_t morton(std::uint32_t x, std::uint32_t y) noexcept {
    const auto spread = [](std::uint64_t v) {
        v &= 0xffffffffULL;
        v = (v | (v << 16)) & 0x0000ffff0000ffffULL;
        v = (v | (v << 8)) & 0x00ff00ff00ff00ffULL;
        v = (v | (v << 4)) & 0x0f0f0f0f0f0f0f0fULL;
        v = (v | (v << 2)) & 0x3333333333333333ULL;
        v = (v | (v << 1)) & 0x5555555555555555ULL;
        return v;
    };
    return spread(x) | (spread(y) << 1);
}

}  // namespace

std::vector<std::uint32_t> FastEngine::locality_order(const Scene& scene) const {
    const std::size_t n = scene.discs.size();
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(n);
    for (std::uint32_t k = 0; k < n; ++k) {
        const Vec2 pos = box_.wrap(scene.discs[k].position);
        const std::uint32_t cell = cell_of(pos.x, pos.y);
        keyed[k] = {morton(cell % nx_, cell / nx_), k};
    }
    std::sort(keyed.begin(), keyed.end());
    std::vector<std::uint32_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = keyed[i].second;
    return order;
}

void FastEngine::place_discs(const Scene& scene) {
    const std::size_t n = scene.discs.size();
    if (n >= Key::index_mask)
        throw_scene_error("", 0, "discs", "too many discs for the fast engine (at most 2^30 - 2)");
    scene_index_ = locality_order(scene);
    p_.resize(n);
    cold_.assign(n, Cold{});
    image_.assign(n, Image{});
    start_.resize(n);
    heap_.reserve_handles(n);
    // The key and handle arrays are reserved but untouched yet (the position map is not).
    for (std::uint32_t i = 0; i < n; ++i) {
        const Disc& d = scene.discs[scene_index_[i]];
        const Vec2 pos = box_.wrap(d.position);
        p_[i] = Particle{pos.x, pos.y, d.velocity.x, d.velocity.y, 0.0, d.radius, no_disc,
                         0,     0,     no_disc};
        cold_[i].m = d.mass;
        start_[i] = d.position;
        if (periodic_) {
            // Keep the unwrapped start: image counts measure wrapping from the wrapped position.
            image_[i].x = static_cast<std::int32_t>(std::floor(d.position.x / box_.width));
            image_[i].y = static_cast<std::int32_t>(std::floor(d.position.y / box_.height));
        }
        const std::uint32_t cell = cell_of(pos.x, pos.y);
        p_[i].cell = cell;
        if (is_big(i)) {
            big_.push_back(i);
        } else {
            link(i, cell);
        }
    }
}

// ------------------------------------------------------------------------------------------
// The main loop: pop the earliest pending event, check it, resolve it, predict again.

void FastEngine::advance_to(double t) {
    const WallClock clock = core_.start_advance(now_, t);
    while (!heap_.empty() && heap_.top_key().t <= t) {
        poll_stop();
        const std::uint32_t i = heap_.top();
        const Key key = heap_.top_key();
        ++stats().pops;
        if (watch_.on()) watch_.record_pop(queued_event(i, key));
        now_ = key.t;
        process(i, key);
    }
    now_ = t;
#ifdef COLLIDE_VALIDATE
    // The O(N) whole-structure check (cells, heap, one pending event per disc), once per call.
    if (!check_invariants()) {
        throw_runtime_error("fast engine: invariants violated at t = " + std::to_string(now_));
    }
#endif
}

void FastEngine::process(std::uint32_t i, const Key& key) {
    switch (key.kind()) {
        case EventKind::pair: {
            const std::uint32_t j = key.b();
            if (p_[j].count != cold_[i].pair_count) {
                // j collided after i predicted this; i's trajectory is unchanged, predict it anew.
                ++stats().stale_pops;
                predict(i);
                return;
            }
            process_pair(i, j, key.t);
            return;
        }
        case EventKind::xwall:
        case EventKind::ywall:
            process_wall(i, key.kind(), key.t);
            return;
        case EventKind::cell:
            process_cell(i, key.b());
            return;
    }
}

void FastEngine::count_collision_now(std::uint32_t i) {
    // The local clock is the time of the disc's latest event (collision or crossing).
    const Particle& pi = p_[i];
    std::uint32_t& count = cold_[i].instant_collisions;
    if (!same_instant(now_ - pi.t, {pi.vx, pi.vy}, pi.r)) count = 0;
    if (++count > instant_limit_) throw_jammed(scene_index_[i], now_, instant_limit_);
}

void FastEngine::process_pair(std::uint32_t i, std::uint32_t j, double t) {
    count_collision_now(i);
    count_collision_now(j);
    advance_disc(i);
    advance_disc(j);
    Particle& pi = p_[i];
    Particle& pj = p_[j];
    // At contact the true image is the nearest one (boxes are wider than 2 sigma).
    const Vec2 dr = box_.displacement({pi.x, pi.y}, {pj.x, pj.y});
    Vec2 vi{pi.vx, pi.vy};
    Vec2 vj{pj.vx, pj.vy};
    const Vec2 impulse = kinematics::resolve_pair(vi, vj, cold_[i].m, cold_[j].m, dr);
    pi.vx = vi.x;
    pi.vy = vi.y;
    pj.vx = vj.x;
    pj.vy = vj.y;
    core_.counters().impulses.virial += std::abs(dot(dr, impulse));
    ++pi.count;
    ++pj.count;
    pi.last_partner = j;
    pj.last_partner = i;
    core_.collided(to_record(t, EventKind::pair, scene_index_[i], scene_index_[j]));
    predict(i);
    predict(j);
}

void FastEngine::process_wall(std::uint32_t i, EventKind kind, double t) {
    count_collision_now(i);
    advance_disc(i);
    Particle& pi = p_[i];
    if (kind == EventKind::xwall) {
        core_.counters().impulses.wall_impulse += 2.0 * cold_[i].m * std::abs(pi.vx);
        pi.vx = -pi.vx;
    } else {
        core_.counters().impulses.wall_impulse += 2.0 * cold_[i].m * std::abs(pi.vy);
        pi.vy = -pi.vy;
    }
    ++pi.count;
    pi.last_partner = no_disc;
    core_.collided(to_record(t, kind, scene_index_[i], no_disc));
    predict(i);
}

void FastEngine::process_cell(std::uint32_t i, std::uint32_t axis) {
    // A crossing far from the disc's latest event starts a new instant for the jam count.
    if (!same_instant(now_ - p_[i].t, {p_[i].vx, p_[i].vy}, p_[i].r))
        cold_[i].instant_collisions = 0;
    advance_disc(i);
    Particle& pi = p_[i];
    auto cx = static_cast<std::int64_t>(pi.cell % nx_);
    auto cy = static_cast<std::int64_t>(pi.cell / nx_);
    if (axis == 0) {
        cx += pi.vx > 0.0 ? 1 : -1;
        if (cx == nx_) {
            cx = 0;
            pi.x -= box_.width;
            ++image_[i].x;
        } else if (cx < 0) {
            cx = nx_ - 1;
            pi.x += box_.width;
            --image_[i].x;
        }
    } else {
        cy += pi.vy > 0.0 ? 1 : -1;
        if (cy == ny_) {
            cy = 0;
            pi.y -= box_.height;
            ++image_[i].y;
        } else if (cy < 0) {
            cy = ny_ - 1;
            pi.y += box_.height;
            --image_[i].y;
        }
    }
    const auto cell = static_cast<std::uint32_t>(cy * nx_ + cx);
    if (is_big(i)) {
        pi.cell = cell;
    } else {
        unlink(i);
        link(i, cell);
    }
    ++core_.counters().cell_crossings;
    predict_after_crossing(i, axis);
}

// ------------------------------------------------------------------------------------------
// Prediction: the earliest of i's wall, cell-crossing and pair events, as i's one heap entry.

void FastEngine::predict(std::uint32_t i) {
    const Particle& pi = p_[i];
    const double dt = now_ - pi.t;
    const double xi = pi.x + pi.vx * dt;
    const double yi = pi.y + pi.vy * dt;
    // Pairs first, bounded only by each other (not by the wall and crossing times): the earliest
    // pair is remembered for the crossings to come, so it must be exact.
    Key pair = Key::make(never, i, no_disc, EventKind::pair);
    if (is_big(i)) {
        scan_ring(i, pi, xi, yi, pair);
    } else {
        scan_small_neighbours(i, pi, xi, yi, pair);
    }
    for (std::uint32_t b : big_) {
        if (b != i) consider_pair_images(i, pi, xi, yi, b, pair);
    }
    schedule(i, pi, xi, yi, pair);
}

void FastEngine::predict_after_crossing(std::uint32_t i, std::uint32_t axis) {
    const Particle& pi = p_[i];
    const Cold& ci = cold_[i];
    // A big disc reaches a whole ring of cells; and once the remembered pair's partner has
    // collided, the pairs that lost to it may be the earliest: both need the full scan.
    if (is_big(i) || (ci.pair_t != never && p_[ci.pair_partner].count != ci.pair_count)) {
        predict(i);
        return;
    }
    // Crossings move nothing (pi.t == now_). The remembered pair covers every disc scanned since
    // the last full prediction: discs that came near i since then scanned i when they crossed
    // (and hold the pair themselves if it is their earliest); discs that collided since predicted
    // again against i. What is new to i is the row or column of cells it now borders.
    Key pair = Key::make(ci.pair_t, i, ci.pair_partner, EventKind::pair);
    if (axis == 0) {
        const std::int64_t dx = pi.vx > 0.0 ? 1 : -1;
        scan_cells(i, pi, pi.x, pi.y, dx, dx, -1, 1, pair);
    } else {
        const std::int64_t dy = pi.vy > 0.0 ? 1 : -1;
        scan_cells(i, pi, pi.x, pi.y, -1, 1, dy, dy, pair);
    }
    schedule(i, pi, pi.x, pi.y, pair);
}

void FastEngine::schedule(std::uint32_t i, const Particle& pi, double xi, double yi,
                          const Key& pair) {
    Cold& ci = cold_[i];
    ci.pair_t = pair.t;
    ci.pair_partner = pair.t == never ? no_disc : pair.b();
    ci.pair_count = pair.t == never ? 0 : p_[pair.b()].count;
    Key best = pair;
    consider_walls_and_cells(i, pi, xi, yi, best);
    if (best.t == never) {
        if (heap_.contains(i)) heap_.erase(i);
        return;
    }
    if (!heap_.contains(i)) {
        ++stats().pushes;
    }
    heap_.push_or_change(i, best);
    stats().max_size = std::max<std::uint64_t>(stats().max_size, heap_.size());
}

void FastEngine::consider_walls_and_cells(std::uint32_t i, const Particle& pi, double xi, double yi,
                                          Key& best) {
    const auto offer = [&](double dt, EventKind kind, std::uint32_t b) {
        if (dt == never) return;
        const Key k = Key::make(now_ + dt, i, b, kind);
        if (key_less_(k, best)) best = k;
    };
    if (!periodic_) {
        offer(kinematics::time_to_wall(xi, pi.vx, pi.r, box_.width), EventKind::xwall, no_disc);
        offer(kinematics::time_to_wall(yi, pi.vy, pi.r, box_.height), EventKind::ywall, no_disc);
        core_.counters().predictions += 2;
    }
    const std::uint32_t cx = pi.cell % nx_;
    const std::uint32_t cy = pi.cell / nx_;
    // Walled boxes have no crossing out of the outer cells (the wall comes first).
    if (pi.vx > 0.0 && (periodic_ || cx + 1 < nx_)) {
        offer(std::max(0.0, ((cx + 1) * cw_ - xi) / pi.vx), EventKind::cell, 0);
    } else if (pi.vx < 0.0 && (periodic_ || cx > 0)) {
        offer(std::max(0.0, (cx * cw_ - xi) / pi.vx), EventKind::cell, 0);
    }
    if (pi.vy > 0.0 && (periodic_ || cy + 1 < ny_)) {
        offer(std::max(0.0, ((cy + 1) * ch_ - yi) / pi.vy), EventKind::cell, 1);
    } else if (pi.vy < 0.0 && (periodic_ || cy > 0)) {
        offer(std::max(0.0, (cy * ch_ - yi) / pi.vy), EventKind::cell, 1);
    }
}

inline bool FastEngine::cannot_beat(Vec2 dr, Vec2 dv, double sigma, double best_t) const noexcept {
    // Without the square root and the division of time_to_hit: for approaching discs apart,
    // sqrt(b^2 - ac) <= -b, so the contact time is at least c / (-2b). When even that bound is
    // later than the best event so far (by more than any rounding of time_to_hit and of now + dt:
    // relative 1e-9 of the interval plus 1e-14 of the time, vs. errors of ~1e-15), the pair's
    // event would have lost `t > best.t`, so skipping it changes nothing.
    const double b = dot(dv, dr);
    if (b >= 0.0) return true;  // receding: time_to_hit says never
    const double c = dot(dr, dr) - sigma * sigma;
    if (!(c > 0.0)) return false;
    const double interval = best_t - now_;
    return c > -2.0 * b * (interval * (1.0 + 1e-9) + std::abs(best_t) * 1e-14);
}

inline void FastEngine::consider_pair(std::uint32_t i, const Particle& pi, double xi, double yi,
                                      std::uint32_t j, double shift_x, double shift_y, Key& best) {
    const Particle& pj = p_[j];
    const double dtj = now_ - pj.t;
    const Vec2 dr{pj.x + pj.vx * dtj + shift_x - xi, pj.y + pj.vy * dtj + shift_y - yi};
    const Vec2 dv{pj.vx - pi.vx, pj.vy - pi.vy};
    const double sigma = pi.r + pj.r;
    ++core_.counters().predictions;
    if (pi.last_partner == j && pj.last_partner == i) {
        const double reach = sigma * (1.0 + just_collided_slack);
        if (norm2(dr) < reach * reach) return;
    }
    if (cannot_beat(dr, dv, sigma, best.t)) return;
    const double dt = kinematics::time_to_hit(dr, dv, sigma);
    if (dt == never) return;
    const double t = now_ + dt;
    if (t > best.t) return;
    const Key k = Key::make(t, i, j, EventKind::pair);
    if (key_less_(k, best)) best = k;
}

void FastEngine::consider_pair_images(std::uint32_t i, const Particle& pi, double xi, double yi,
                                      std::uint32_t j, Key& best) {
    if (!periodic_) {
        consider_pair(i, pi, xi, yi, j, 0.0, 0.0, best);
        return;
    }
    // Pairs with a big disc are not tied to neighbouring cells: try the nine nearest images.
    const Particle& pj = p_[j];
    const double dtj = now_ - pj.t;
    const Vec2 base = box_.displacement({xi, yi}, {pj.x + pj.vx * dtj, pj.y + pj.vy * dtj});
    const double sx = base.x - (pj.x + pj.vx * dtj - xi);
    const double sy = base.y - (pj.y + pj.vy * dtj - yi);
    for (int ky = -1; ky <= 1; ++ky) {
        for (int kx = -1; kx <= 1; ++kx) {
            consider_pair(i, pi, xi, yi, j, sx + kx * box_.width, sy + ky * box_.height, best);
        }
    }
}

void FastEngine::scan_small_neighbours(std::uint32_t i, const Particle& pi, double xi, double yi,
                                       Key& best) {
    scan_cells(i, pi, xi, yi, -1, 1, -1, 1, best);
}

template <typename Visit>
[[gnu::always_inline]] inline void FastEngine::for_each_cell(const Particle& pi, std::int64_t x0,
                                                             std::int64_t x1, std::int64_t y0,
                                                             std::int64_t y1, Visit&& visit) const {
    const auto cx = static_cast<std::int64_t>(pi.cell % nx_);
    const auto cy = static_cast<std::int64_t>(pi.cell / nx_);
    for (std::int64_t oy = y0; oy <= y1; ++oy) {
        std::int64_t y = cy + oy;
        double shift_y = 0.0;
        if (y < 0 || y >= ny_) {
            if (!periodic_) continue;
            shift_y = y < 0 ? -box_.height : box_.height;
            y = y < 0 ? y + ny_ : y - ny_;
        }
        for (std::int64_t ox = x0; ox <= x1; ++ox) {
            std::int64_t x = cx + ox;
            double shift_x = 0.0;
            if (x < 0 || x >= nx_) {
                if (!periodic_) continue;
                shift_x = x < 0 ? -box_.width : box_.width;
                x = x < 0 ? x + nx_ : x - nx_;
            }
            const std::uint32_t first = head_[static_cast<std::size_t>(y * nx_ + x)];
            if (first != no_disc) visit(first, shift_x, shift_y);
        }
    }
}

[[gnu::always_inline]] inline void FastEngine::scan_list(std::uint32_t i, const Particle& pi,
                                                         double xi, double yi, std::uint32_t first,
                                                         double shift_x, double shift_y,
                                                         Key& best) {
    for (std::uint32_t j = first; j != no_disc; j = p_[j].next) {
        if (j != i) consider_pair(i, pi, xi, yi, j, shift_x, shift_y, best);
    }
}

// Beyond the caches every cell's first disc is a miss, and following the lists one after the
// other makes those misses wait for each other: asking for all of them before reading any
// overlaps them (docs/benchmarks.md). The scans and their order are the same either way.
inline void FastEngine::scan_cells(std::uint32_t i, const Particle& pi, double xi, double yi,
                                   std::int64_t x0, std::int64_t x1, std::int64_t y0,
                                   std::int64_t y1, Key& best) {
    struct CellVisit {
        std::uint32_t first;
        double shift_x, shift_y;
    };
    std::array<CellVisit, 9> visits;  // callers scan at most 3 x 3 cells
    std::size_t count = 0;
    for_each_cell(pi, x0, x1, y0, y1, [&](std::uint32_t first, double sx, double sy) {
        __builtin_prefetch(&p_[first]);
        visits[count++] = {first, sx, sy};
    });
    for (std::size_t k = 0; k < count; ++k) {
        scan_list(i, pi, xi, yi, visits[k].first, visits[k].shift_x, visits[k].shift_y, best);
    }
}

void FastEngine::scan_ring(std::uint32_t i, const Particle& pi, double xi, double yi, Key& best) {
    // Small discs that can touch big disc i before either leaves its cell lie within
    // 1 + (R + r_small) / cell cells of i's centre cell.
    const double reach = (pi.r + small_radius_max_) * (1.0 + cell_margin);
    const auto kx = static_cast<std::int64_t>(1 + std::ceil(reach / cw_));
    const auto ky = static_cast<std::int64_t>(1 + std::ceil(reach / ch_));
    if (periodic_ && (2 * kx + 1 > nx_ || 2 * ky + 1 > ny_)) {
        // The ring wraps onto itself: check every small disc (nine images each).
        for (std::uint32_t j = 0; j < p_.size(); ++j) {
            if (j != i && !is_big(j)) consider_pair_images(i, pi, xi, yi, j, best);
        }
        return;
    }
    // Big discs are in no cell list, so scan_list's skip of i never applies here.
    for_each_cell(pi, -kx, kx, -ky, ky, [&](std::uint32_t first, double sx, double sy) {
        scan_list(i, pi, xi, yi, first, sx, sy, best);
    });
}

// ------------------------------------------------------------------------------------------
// Bookkeeping.

void FastEngine::advance_disc(std::uint32_t i) noexcept {
    Particle& pi = p_[i];
    const double dt = now_ - pi.t;
    pi.x += pi.vx * dt;
    pi.y += pi.vy * dt;
    pi.t = now_;
}

void FastEngine::link(std::uint32_t i, std::uint32_t cell) noexcept {
    Particle& pi = p_[i];
    pi.cell = cell;
    pi.next = head_[cell];
    cold_[i].prev = no_disc;
    if (pi.next != no_disc) cold_[pi.next].prev = i;
    head_[cell] = i;
}

void FastEngine::unlink(std::uint32_t i) noexcept {
    Particle& pi = p_[i];
    const std::uint32_t prev = cold_[i].prev;
    if (prev == no_disc) {
        head_[pi.cell] = pi.next;
    } else {
        p_[prev].next = pi.next;
    }
    if (pi.next != no_disc) cold_[pi.next].prev = prev;
    pi.next = no_disc;
    cold_[i].prev = no_disc;
}

Vec2 FastEngine::position_at_now(std::uint32_t i) const noexcept {
    const Particle& pi = p_[i];
    const double dt = now_ - pi.t;
    return {pi.x + pi.vx * dt, pi.y + pi.vy * dt};
}

// ------------------------------------------------------------------------------------------
// Outputs.

Snapshot FastEngine::snapshot() const {
    Snapshot s = core_.start_snapshot(now_);
    for (std::uint32_t i = 0; i < p_.size(); ++i) {
        EngineCore::set_motion(s.discs[scene_index_[i]], box_.wrap(position_at_now(i)),
                               {p_[i].vx, p_[i].vy}, p_[i].r, cold_[i].m);
    }
    if (watch_.on()) s.queue = queue_view();
    return s;
}

QueuedEvent FastEngine::queued_event(std::uint32_t i, const Key& key) const noexcept {
    QueuedEvent e;
    e.t = key.t;
    e.kind = queued_kind(key.kind());
    e.a = scene_index_[i];
    if (key.kind() == EventKind::pair) {
        const std::uint32_t j = key.b();
        e.b = scene_index_[j];
        if (e.b < e.a) std::swap(e.a, e.b);
        e.stale = p_[j].count != cold_[i].pair_count;
    }
    return e;
}

// The indexed 4-ary heap holding one pending event per disc: its top levels, its next
// collisions. O(N), only for watched engines.
QueueView FastEngine::queue_view() const {
    QueueView view;
    view.shape = QueueShape::heap;
    view.arity = 4;
    view.name = "indexed 4-ary heap";
    view.one_per_disc = true;
    const std::size_t n = heap_.size();
    view.size = n;
    std::vector<QueuedEvent> all;
    all.reserve(n);
    for (std::size_t k = 0; k < n; ++k) {
        const Key& key = heap_.key_at(k);
        all.push_back(queued_event(key.a, key));
    }
    view.stale_entries = static_cast<std::uint64_t>(
        std::count_if(all.begin(), all.end(), [](const QueuedEvent& e) { return e.stale; }));
    view.levels = shown_tree_levels(view.arity, n, watch_.limits());
    view.slots.assign(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(
                                                     shown_tree_slots(view.arity, view.levels, n)));
    keep_next_collisions(all, watch_.next_events());
    view.next = std::move(all);
    view.popped = watch_.popped();
    view.pops = core_.counters().queue.pops;
    view.stale_pops = core_.counters().queue.stale_pops;
    return view;
}

Measurements FastEngine::measurements() const {
    // In the internal order: the sums come out as they always have, bit for bit.
    const std::size_t n = p_.size();
    std::vector<Vec2> positions(n);
    std::vector<Vec2> velocities(n);
    std::vector<double> masses(n);
    std::vector<double> radii(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        positions[i] = position_at_now(i);
        velocities[i] = {p_[i].vx, p_[i].vy};
        masses[i] = cold_[i].m;
        radii[i] = p_[i].r;
    }
    Measurements m = core_.measurements(now_, velocities, masses, radii, bytes());
    m.max_overlap = max_overlap(positions, radii, box_);
    m.msd = core_.mean_squared_displacement(n, [&](std::size_t i) {
        const Vec2 unwrapped{positions[i].x + image_[i].x * box_.width,
                             positions[i].y + image_[i].y * box_.height};
        return std::pair{std::size_t{scene_index_[i]}, unwrapped - start_[i]};
    });
    return m;
}

std::uint64_t FastEngine::bytes() const noexcept {
    constexpr std::size_t u32 = sizeof(std::uint32_t);
    std::size_t total = p_.capacity() * sizeof(Particle);
    total += cold_.capacity() * sizeof(Cold);
    total += (big_.capacity() + head_.capacity() + scene_index_.capacity()) * u32;
    total += image_.capacity() * sizeof(Image) + start_.capacity() * sizeof(Vec2);
    total += heap_.bytes();
    total += core_.bytes();
    return total;
}

bool FastEngine::check_invariants() const {
    if (!heap_.check_invariants()) return false;
    std::vector<std::uint8_t> seen(p_.size(), 0);
    for (std::size_t c = 0; c < head_.size(); ++c) {
        std::uint32_t before = no_disc;
        for (std::uint32_t j = head_[c]; j != no_disc; j = p_[j].next) {
            if (j >= p_.size() || seen[j] || p_[j].cell != c || cold_[j].prev != before ||
                is_big(j))
                return false;
            seen[j] = 1;
            before = j;
        }
    }
    for (std::uint32_t i = 0; i < p_.size(); ++i) {
        if (!is_big(i) && !seen[i]) return false;
        if (p_[i].t > now_) return false;
        if (heap_.contains(i) && heap_.key(i).t < now_) return false;
        // The pending event is the remembered pair or comes no later than it; a pending pair is
        // the remembered one.
        const Cold& ci = cold_[i];
        if (ci.pair_t != never && (!heap_.contains(i) || heap_.key(i).t > ci.pair_t)) return false;
        if (heap_.contains(i) && heap_.key(i).kind() == EventKind::pair &&
            (heap_.key(i).t != ci.pair_t || heap_.key(i).b() != ci.pair_partner)) {
            return false;
        }
        // The centre lies in its cell, up to the rounding of the crossing times.
        const Vec2 pos = position_at_now(i);
        const double cx = static_cast<double>(p_[i].cell % nx_);
        const double cy = static_cast<double>(p_[i].cell / nx_);
        const double slack = 1e-9 * (cw_ + ch_);
        if (pos.x < cx * cw_ - slack || pos.x > (cx + 1) * cw_ + slack) return false;
        if (pos.y < cy * ch_ - slack || pos.y > (cy + 1) * ch_ + slack) return false;
    }
    return true;
}

}  // namespace collide::sim
