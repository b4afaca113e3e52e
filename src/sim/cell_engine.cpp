#include "collide/sim/cell_engine.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <utility>

#include "collide/error.hpp"
#include "collide/sim/kinematics.hpp"

namespace collide::sim {

namespace {

using kinematics::never;

/// Same grid rules as the fast engine (see fast_engine.cpp).
constexpr double cell_margin = 1e-9;
constexpr double max_cells_per_disc = 2.0;

std::uint32_t fit_cells(double extent, double min_cell) {
    if (!(min_cell > 0.0)) return 1;
    const double n = std::floor(extent / min_cell);
    if (!(n >= 1.0)) return 1;
    return static_cast<std::uint32_t>(std::min(n, 65536.0));
}

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

bool CellEngine::KeyLess::tie_break(const Key& x, const Key& y) const noexcept {
    if (x.kind() != y.kind()) return x.kind() < y.kind();
    const auto ids = [this](const Key& k) {
        const std::uint32_t a = (*scene_index)[k.a];
        if (k.kind() != EventKind::pair) return std::pair{a, k.b()};
        const std::uint32_t b = (*scene_index)[k.b()];
        return std::pair{std::min(a, b), std::max(a, b)};
    };
    return ids(x) < ids(y);
}

CellEngine::CellEngine(const Scene& scene)
    : box_(scene.box), periodic_(scene.box.boundary == Boundary::periodic), appearance_(scene) {
    choose_grid(scene);
    place_discs(scene);
    instant_limit_ = instant_collision_limit(loc_.size());
    for (std::uint32_t i = 0; i < loc_.size(); ++i) predict(i);
}

bool CellEngine::can_simulate(const Scene& scene) {
    if (scene.box.boundary != Boundary::periodic) return true;
    const double min_cell = 2.0 * split_radii(scene).second * (1.0 + cell_margin);
    return fit_cells(scene.box.width, min_cell) >= 3 && fit_cells(scene.box.height, min_cell) >= 3;
}

void CellEngine::choose_grid(const Scene& scene) {
    std::tie(big_threshold_, small_radius_max_) = split_radii(scene);
    const double min_cell = 2.0 * small_radius_max_ * (1.0 + cell_margin);
    std::uint32_t nx = fit_cells(box_.width, min_cell);
    std::uint32_t ny = fit_cells(box_.height, min_cell);
    if (periodic_ && (nx < 3 || ny < 3)) {
        throw_input_error("", 0, nx < 3 ? "box.width" : "box.height",
                          "a periodic box must be at least three disc diameters wide and tall for "
                          "the fast engine (use --engine classic)");
    }
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
    tiles_x_ = (nx_ + tile - 1) / tile;
    const std::uint32_t tiles_y = (ny_ + tile - 1) / tile;
    const std::size_t stored =
        static_cast<std::size_t>(tiles_x_) * tiles_y * tile * tile * slots_per_cell;
    slots_.reserve(stored);
    slots_.assign(stored, Slot{});
}

std::uint32_t CellEngine::cell_of(double x, double y) const noexcept {
    const auto clamp_index = [](double v, std::uint32_t n) {
        if (!(v > 0.0)) return 0U;
        return static_cast<std::uint32_t>(std::min(v, static_cast<double>(n - 1)));
    };
    return clamp_index(y / ch_, ny_) * nx_ + clamp_index(x / cw_, nx_);
}

std::vector<std::uint32_t> CellEngine::locality_order(const Scene& scene) const {
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

void CellEngine::place_discs(const Scene& scene) {
    const std::size_t n = scene.discs.size();
    if (n >= Key::index_mask)
        throw_input_error("", 0, "discs", "too many discs for the fast engine (at most 2^30 - 2)");
    scene_index_ = locality_order(scene);
    loc_.assign(n, Loc{0, 0, 0});
    cold_.assign(n, Cold{});
    image_.assign(n, Image{});
    start_.resize(n);
    heap_.reserve_handles(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        const Disc& d = scene.discs[scene_index_[i]];
        const Vec2 pos = box_.wrap(d.position);
        const Body b{pos.x, pos.y, d.velocity.x, d.velocity.y, 0.0, d.radius, i, no_disc};
        cold_[i].m = d.mass;
        start_[i] = d.position;
        if (periodic_) {
            image_[i].x = static_cast<std::int32_t>(std::floor(d.position.x / box_.width));
            image_[i].y = static_cast<std::int32_t>(std::floor(d.position.y / box_.height));
        }
        const std::uint32_t cell = cell_of(pos.x, pos.y);
        const auto cx = static_cast<std::uint16_t>(cell % nx_);
        const auto cy = static_cast<std::uint16_t>(cell / nx_);
        if (d.radius > big_threshold_) {
            loc_[i] = Loc{cx, cy, big_bit | static_cast<std::uint32_t>(bigs_.size())};
            bigs_.push_back(b);
            big_.push_back(i);
        } else {
            insert(b, cx, cy);
        }
    }
}

// ------------------------------------------------------------------------------------------
// Cell storage: inline slots in tile order, overflow regions in a pool.

inline std::size_t CellEngine::first_slot(std::uint32_t cx, std::uint32_t cy) const noexcept {
    const std::size_t tile_index = static_cast<std::size_t>(cy / tile) * tiles_x_ + cx / tile;
    return ((tile_index * tile + cy % tile) * tile + cx % tile) * slots_per_cell;
}

inline CellEngine::Slot& CellEngine::slot_at(std::uint32_t cx, std::uint32_t cy,
                                             std::uint32_t pos) noexcept {
    const std::size_t first = first_slot(cx, cy);
    if (pos < slots_per_cell) return slots_[first + pos];
    return pool_[slots_[first].overflow + pos - slots_per_cell];
}

inline const CellEngine::Slot& CellEngine::slot_at(std::uint32_t cx, std::uint32_t cy,
                                                   std::uint32_t pos) const noexcept {
    const std::size_t first = first_slot(cx, cy);
    if (pos < slots_per_cell) return slots_[first + pos];
    return pool_[slots_[first].overflow + pos - slots_per_cell];
}

inline CellEngine::Body& CellEngine::body(std::uint32_t i) noexcept {
    const Loc l = loc_[i];
    if (l.pos & big_bit) return bigs_[l.pos & ~big_bit];
    return slot_at(l.cx, l.cy, l.pos).b;
}

inline const CellEngine::Body& CellEngine::body(std::uint32_t i) const noexcept {
    const Loc l = loc_[i];
    if (l.pos & big_bit) return bigs_[l.pos & ~big_bit];
    return slot_at(l.cx, l.cy, l.pos).b;
}

std::uint32_t CellEngine::take_region(std::uint32_t size_class) {
    if (free_regions_.size() <= size_class) free_regions_.resize(size_class + 1);
    auto& free = free_regions_[size_class];
    if (!free.empty()) {
        const std::uint32_t offset = free.back();
        free.pop_back();
        return offset;
    }
    const auto offset = static_cast<std::uint32_t>(pool_.size());
    pool_.resize(pool_.size() + (std::size_t{1} << size_class));
    return offset;
}

void CellEngine::give_region(std::uint32_t offset, std::uint32_t size_class) {
    free_regions_[size_class].push_back(offset);
}

void CellEngine::insert(const Body& b, std::uint32_t cx, std::uint32_t cy) {
    const std::size_t first = first_slot(cx, cy);
    const std::uint32_t pos = slots_[first].fill;
    if (pos < slots_per_cell) {
        slots_[first + pos].b = b;
    } else {
        // Overflow: regions grow by powers of two (a region's class is kept in its first slot's
        // fill field, so shrinking happens only when it empties).
        const std::uint32_t n = pos - slots_per_cell;  // records already in the region
        if (n == 0) {
            const std::uint32_t offset = take_region(0);
            pool_[offset].fill = 0;
            slots_[first].overflow = offset;
        } else if (n == (1U << pool_[slots_[first].overflow].fill)) {
            const std::uint32_t old = slots_[first].overflow;
            const std::uint32_t old_class = pool_[old].fill;
            const std::uint32_t offset = take_region(old_class + 1);
            for (std::uint32_t k = 0; k < n; ++k) pool_[offset + k].b = pool_[old + k].b;
            pool_[offset].fill = old_class + 1;
            give_region(old, old_class);
            slots_[first].overflow = offset;
        }
        pool_[slots_[first].overflow + n].b = b;
        ++overflow_discs_;
    }
    ++slots_[first].fill;
    loc_[b.id] = Loc{static_cast<std::uint16_t>(cx), static_cast<std::uint16_t>(cy), pos};
}

void CellEngine::remove(std::uint32_t i) noexcept {
    const Loc l = loc_[i];
    const std::size_t first = first_slot(l.cx, l.cy);
    const std::uint32_t last = slots_[first].fill - 1;
    if (l.pos != last) {
        const Body& moved = slot_at(l.cx, l.cy, last).b;
        slot_at(l.cx, l.cy, l.pos).b = moved;
        loc_[moved.id].pos = l.pos;
    }
    if (last >= slots_per_cell) {
        --overflow_discs_;
        if (last == slots_per_cell) {
            const std::uint32_t offset = slots_[first].overflow;
            give_region(offset, pool_[offset].fill);
        }
    }
    slots_[first].fill = last;
}

std::size_t CellEngine::overflow_discs() const noexcept {
    return overflow_discs_;
}

// ------------------------------------------------------------------------------------------
// The main loop.

void CellEngine::advance_to(double t) {
    require_forward(now_, t);
    WallClock clock(wall_seconds_);
    while (!heap_.empty() && heap_.top_key().t <= t) {
        poll_stop();
        const std::uint32_t i = heap_.top();
        const Key key = heap_.top_key();
        // The event's discs are reached through loc_ (id -> slot): ask for both discs' index
        // entries and cold records at once, so that those misses overlap.
        __builtin_prefetch(&loc_[i]);
        __builtin_prefetch(&cold_[i]);
        if (key.kind() == EventKind::pair) {
            __builtin_prefetch(&loc_[key.b()]);
            __builtin_prefetch(&cold_[key.b()]);
        }
        ++stats_.pops;
        now_ = key.t;
        process(i, key);
    }
    now_ = t;
}

void CellEngine::process(std::uint32_t i, const Key& key) {
    switch (key.kind()) {
        case EventKind::pair: {
            const std::uint32_t j = key.b();
            if (cold_[j].count != cold_[i].pair_count) {
                ++stats_.stale_pops;
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

void CellEngine::count_collision_now(std::uint32_t i, const Body& bi) {
    std::uint32_t& count = cold_[i].instant_collisions;
    if (!same_instant(now_ - bi.t, {bi.vx, bi.vy}, bi.r)) count = 0;
    if (++count > instant_limit_) throw_jammed(scene_index_[i], now_, instant_limit_);
}

void CellEngine::process_pair(std::uint32_t i, std::uint32_t j, double t) {
    Body& bi = body(i);
    Body& bj = body(j);
    __builtin_prefetch(&bj);
    count_collision_now(i, bi);
    count_collision_now(j, bj);
    advance_disc(bi);
    advance_disc(bj);
    const Vec2 dr = box_.displacement({bi.x, bi.y}, {bj.x, bj.y});
    Vec2 vi{bi.vx, bi.vy};
    Vec2 vj{bj.vx, bj.vy};
    const Vec2 impulse = kinematics::resolve_pair(vi, vj, cold_[i].m, cold_[j].m, dr);
    bi.vx = vi.x;
    bi.vy = vi.y;
    bj.vx = vj.x;
    bj.vy = vj.y;
    tally_.virial += std::abs(dot(dr, impulse));
    ++cold_[i].count;
    ++cold_[j].count;
    bi.last_partner = j;
    bj.last_partner = i;
    ++collisions_pair_;
    if (listener_) listener_(to_record(t, EventKind::pair, scene_index_[i], scene_index_[j]));
    predict(i);
    predict(j);
}

void CellEngine::process_wall(std::uint32_t i, EventKind kind, double t) {
    Body& bi = body(i);
    count_collision_now(i, bi);
    advance_disc(bi);
    if (kind == EventKind::xwall) {
        tally_.wall_impulse += 2.0 * cold_[i].m * std::abs(bi.vx);
        bi.vx = -bi.vx;
        ++collisions_xwall_;
    } else {
        tally_.wall_impulse += 2.0 * cold_[i].m * std::abs(bi.vy);
        bi.vy = -bi.vy;
        ++collisions_ywall_;
    }
    ++cold_[i].count;
    bi.last_partner = no_disc;
    if (listener_) listener_(to_record(t, kind, scene_index_[i], no_disc));
    predict(i);
}

void CellEngine::process_cell(std::uint32_t i, std::uint32_t axis) {
    Body& bi = body(i);
    if (!same_instant(now_ - bi.t, {bi.vx, bi.vy}, bi.r)) cold_[i].instant_collisions = 0;
    advance_disc(bi);
    auto cx = static_cast<std::int64_t>(loc_[i].cx);
    auto cy = static_cast<std::int64_t>(loc_[i].cy);
    if (axis == 0) {
        cx += bi.vx > 0.0 ? 1 : -1;
        if (cx == nx_) {
            cx = 0;
            bi.x -= box_.width;
            ++image_[i].x;
        } else if (cx < 0) {
            cx = nx_ - 1;
            bi.x += box_.width;
            --image_[i].x;
        }
    } else {
        cy += bi.vy > 0.0 ? 1 : -1;
        if (cy == ny_) {
            cy = 0;
            bi.y -= box_.height;
            ++image_[i].y;
        } else if (cy < 0) {
            cy = ny_ - 1;
            bi.y += box_.height;
            --image_[i].y;
        }
    }
    if (is_big(i)) {
        loc_[i].cx = static_cast<std::uint16_t>(cx);
        loc_[i].cy = static_cast<std::uint16_t>(cy);
    } else {
        const Body moving = bi;  // bi's slot is reused by remove
        remove(i);
        insert(moving, static_cast<std::uint32_t>(cx), static_cast<std::uint32_t>(cy));
    }
    ++cell_crossings_;
    predict_after_crossing(i, axis);
}

// ------------------------------------------------------------------------------------------
// Prediction.

void CellEngine::predict(std::uint32_t i) {
    const Body& bi = body(i);
    const Loc cell = loc_[i];
    const double dt = now_ - bi.t;
    const double xi = bi.x + bi.vx * dt;
    const double yi = bi.y + bi.vy * dt;
    Key pair = Key::make(never, i, no_disc, EventKind::pair);
    if (is_big(i)) {
        scan_ring(bi, cell, xi, yi, pair);
    } else {
        scan_cells(bi, cell, xi, yi, -1, 1, -1, 1, pair);
    }
    for (std::uint32_t b : big_) {
        if (b != i) consider_pair_images(bi, xi, yi, body(b), pair);
    }
    schedule(i, bi, cell, xi, yi, pair);
}

void CellEngine::predict_after_crossing(std::uint32_t i, std::uint32_t axis) {
    const Cold& ci = cold_[i];
    if (is_big(i) || (ci.pair_t != never && cold_[ci.pair_partner].count != ci.pair_count)) {
        predict(i);
        return;
    }
    const Body& bi = body(i);
    const Loc cell = loc_[i];
    Key pair = Key::make(ci.pair_t, i, ci.pair_partner, EventKind::pair);
    if (axis == 0) {
        const std::int64_t dx = bi.vx > 0.0 ? 1 : -1;
        scan_cells(bi, cell, bi.x, bi.y, dx, dx, -1, 1, pair);
    } else {
        const std::int64_t dy = bi.vy > 0.0 ? 1 : -1;
        scan_cells(bi, cell, bi.x, bi.y, -1, 1, dy, dy, pair);
    }
    schedule(i, bi, cell, bi.x, bi.y, pair);
}

void CellEngine::schedule(std::uint32_t i, const Body& bi, Loc cell, double xi, double yi,
                          const Key& pair) {
    Cold& ci = cold_[i];
    ci.pair_t = pair.t;
    ci.pair_partner = pair.t == never ? no_disc : pair.b();
    ci.pair_count = pair.t == never ? 0 : cold_[pair.b()].count;
    Key best = pair;
    consider_walls_and_cells(i, bi, cell, xi, yi, best);
    if (best.t == never) {
        if (heap_.contains(i)) heap_.erase(i);
        return;
    }
    if (!heap_.contains(i)) ++stats_.pushes;
    heap_.push_or_change(i, best);
    stats_.max_size = std::max<std::uint64_t>(stats_.max_size, heap_.size());
}

void CellEngine::consider_walls_and_cells(std::uint32_t i, const Body& bi, Loc cell, double xi,
                                          double yi, Key& best) {
    const auto offer = [&](double dt, EventKind kind, std::uint32_t b) {
        if (dt == never) return;
        const Key k = Key::make(now_ + dt, i, b, kind);
        if (key_less_(k, best)) best = k;
    };
    if (!periodic_) {
        offer(kinematics::time_to_wall(xi, bi.vx, bi.r, box_.width), EventKind::xwall, no_disc);
        offer(kinematics::time_to_wall(yi, bi.vy, bi.r, box_.height), EventKind::ywall, no_disc);
        predictions_ += 2;
    }
    const std::uint32_t cx = cell.cx;
    const std::uint32_t cy = cell.cy;
    if (bi.vx > 0.0 && (periodic_ || cx + 1 < nx_)) {
        offer(std::max(0.0, ((cx + 1) * cw_ - xi) / bi.vx), EventKind::cell, 0);
    } else if (bi.vx < 0.0 && (periodic_ || cx > 0)) {
        offer(std::max(0.0, (cx * cw_ - xi) / bi.vx), EventKind::cell, 0);
    }
    if (bi.vy > 0.0 && (periodic_ || cy + 1 < ny_)) {
        offer(std::max(0.0, ((cy + 1) * ch_ - yi) / bi.vy), EventKind::cell, 1);
    } else if (bi.vy < 0.0 && (periodic_ || cy > 0)) {
        offer(std::max(0.0, (cy * ch_ - yi) / bi.vy), EventKind::cell, 1);
    }
}

inline bool CellEngine::cannot_beat(Vec2 dr, Vec2 dv, double sigma, double best_t) const noexcept {
    // See FastEngine::cannot_beat.
    const double b = dot(dv, dr);
    if (b >= 0.0) return true;
    const double c = dot(dr, dr) - sigma * sigma;
    if (!(c > 0.0)) return false;
    const double interval = best_t - now_;
    return c > -2.0 * b * (interval * (1.0 + 1e-9) + std::abs(best_t) * 1e-14);
}

inline void CellEngine::consider_pair(const Body& bi, double xi, double yi, const Body& bj,
                                      double shift_x, double shift_y, Key& best) {
    const double dtj = now_ - bj.t;
    const Vec2 dr{bj.x + bj.vx * dtj + shift_x - xi, bj.y + bj.vy * dtj + shift_y - yi};
    const Vec2 dv{bj.vx - bi.vx, bj.vy - bi.vy};
    const double sigma = bi.r + bj.r;
    ++predictions_;
    if (bi.last_partner == bj.id && bj.last_partner == bi.id) {
        const double reach = sigma * (1.0 + just_collided_slack);
        if (norm2(dr) < reach * reach) return;
    }
    if (cannot_beat(dr, dv, sigma, best.t)) return;
    const double dt = kinematics::time_to_hit(dr, dv, sigma);
    if (dt == never) return;
    const double t = now_ + dt;
    if (t > best.t) return;
    const Key k = Key::make(t, bi.id, bj.id, EventKind::pair);
    if (key_less_(k, best)) best = k;
}

void CellEngine::consider_pair_images(const Body& bi, double xi, double yi, const Body& bj,
                                      Key& best) {
    if (!periodic_) {
        consider_pair(bi, xi, yi, bj, 0.0, 0.0, best);
        return;
    }
    const double dtj = now_ - bj.t;
    const Vec2 base = box_.displacement({xi, yi}, {bj.x + bj.vx * dtj, bj.y + bj.vy * dtj});
    const double sx = base.x - (bj.x + bj.vx * dtj - xi);
    const double sy = base.y - (bj.y + bj.vy * dtj - yi);
    for (int ky = -1; ky <= 1; ++ky) {
        for (int kx = -1; kx <= 1; ++kx) {
            consider_pair(bi, xi, yi, bj, sx + kx * box_.width, sy + ky * box_.height, best);
        }
    }
}

void CellEngine::scan_cells(const Body& bi, Loc cell, double xi, double yi, std::int64_t x0,
                            std::int64_t x1, std::int64_t y0, std::int64_t y1, Key& best) {
    // Two passes: first every cell's first slot is located and requested (its address needs no
    // load, unlike a list head), then the cells are scanned. Scanning at once would stall on each
    // cell's first line in turn: whether a cell is empty is a branch the CPU cannot guess, so
    // the misses would not overlap.
    struct Visit {
        const Slot* first;
        double shift_x, shift_y;
    };
    constexpr std::size_t batch = 9;  // a 3 x 3 neighbourhood; rings go through in batches
    std::array<Visit, batch> visits;
    std::size_t count = 0;
    const auto scan = [&] {
        for (std::size_t v = 0; v < count; ++v)
            scan_cell(bi, xi, yi, visits[v].first, visits[v].shift_x, visits[v].shift_y, best);
        count = 0;
    };
    const auto cx = static_cast<std::int64_t>(cell.cx);
    const auto cy = static_cast<std::int64_t>(cell.cy);
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
            const Slot* first =
                &slots_[first_slot(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y))];
            __builtin_prefetch(first);
            visits[count++] = {first, shift_x, shift_y};
            if (count == batch) scan();
        }
    }
    scan();
}

inline void CellEngine::scan_cell(const Body& bi, double xi, double yi, const Slot* first,
                                  double shift_x, double shift_y, Key& best) {
    const std::uint32_t fill = first->fill;
    const std::uint32_t in_line = std::min(fill, slots_per_cell);
    for (std::uint32_t k = 0; k < in_line; ++k) {
        const Body& bj = first[k].b;
        if (bj.id != bi.id) consider_pair(bi, xi, yi, bj, shift_x, shift_y, best);
    }
    if (fill > slots_per_cell) {
        const Slot* region = &pool_[first->overflow];
        for (std::uint32_t k = 0; k < fill - slots_per_cell; ++k) {
            const Body& bj = region[k].b;
            if (bj.id != bi.id) consider_pair(bi, xi, yi, bj, shift_x, shift_y, best);
        }
    }
}

void CellEngine::scan_ring(const Body& bi, Loc cell, double xi, double yi, Key& best) {
    const double reach = (bi.r + small_radius_max_) * (1.0 + cell_margin);
    const auto kx = static_cast<std::int64_t>(1 + std::ceil(reach / cw_));
    const auto ky = static_cast<std::int64_t>(1 + std::ceil(reach / ch_));
    if (periodic_ && (2 * kx + 1 > nx_ || 2 * ky + 1 > ny_)) {
        for (std::uint32_t j = 0; j < loc_.size(); ++j) {
            if (j != bi.id && !is_big(j)) consider_pair_images(bi, xi, yi, body(j), best);
        }
        return;
    }
    scan_cells(bi, cell, xi, yi, -kx, kx, -ky, ky, best);
}

// ------------------------------------------------------------------------------------------
// Bookkeeping and outputs.

void CellEngine::advance_disc(Body& b) const noexcept {
    const double dt = now_ - b.t;
    b.x += b.vx * dt;
    b.y += b.vy * dt;
    b.t = now_;
}

Vec2 CellEngine::position_at_now(const Body& b) const noexcept {
    const double dt = now_ - b.t;
    return {b.x + b.vx * dt, b.y + b.vy * dt};
}

Snapshot CellEngine::snapshot() const {
    Snapshot s;
    s.time = now_;
    s.box = box_;
    s.discs.resize(loc_.size());
    for (std::uint32_t i = 0; i < loc_.size(); ++i) {
        const Body& b = body(i);
        const std::uint32_t k = scene_index_[i];
        DiscState& d = s.discs[k];
        d.position = box_.wrap(position_at_now(b));
        d.velocity = {b.vx, b.vy};
        d.radius = b.r;
        d.mass = cold_[i].m;
        d.color = appearance_.colors[k];
        d.tagged = appearance_.tagged[k] != 0;
    }
    return s;
}

Measurements CellEngine::measurements() const {
    Measurements m;
    m.t = now_;
    m.collisions_pair = collisions_pair_;
    m.collisions_xwall = collisions_xwall_;
    m.collisions_ywall = collisions_ywall_;
    m.collisions_wall = collisions_xwall_ + collisions_ywall_;
    m.cell_crossings = cell_crossings_;
    m.events = m.collisions_pair + m.collisions_wall + cell_crossings_;
    m.predictions = predictions_;
    m.queue = stats_;

    const std::size_t n = loc_.size();
    std::vector<Vec2> positions(n);
    std::vector<Vec2> velocities(n);
    std::vector<double> masses(n);
    std::vector<double> radii(n);
    double msd_sum = 0.0;
    std::size_t msd_count = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
        const Body& b = body(i);
        positions[i] = position_at_now(b);
        velocities[i] = {b.vx, b.vy};
        masses[i] = cold_[i].m;
        radii[i] = b.r;
        if (appearance_.in_msd(scene_index_[i])) {
            const Vec2 unwrapped{positions[i].x + image_[i].x * box_.width,
                                 positions[i].y + image_[i].y * box_.height};
            msd_sum += norm2(unwrapped - start_[i]);
            ++msd_count;
        }
    }
    fill_thermodynamics(m, velocities, masses, radii, box_, tally_);
    m.max_overlap = max_overlap(positions, radii, box_);
    m.msd = msd_count > 0 ? msd_sum / static_cast<double>(msd_count) : 0.0;
    m.wall_seconds = wall_seconds_;
    if (wall_seconds_ > 0.0) {
        m.collisions_per_second =
            static_cast<double>(m.collisions_pair + m.collisions_wall) / wall_seconds_;
    }
    m.engine_bytes = bytes();
    return m;
}

std::uint64_t CellEngine::bytes() const noexcept {
    constexpr std::size_t u32 = sizeof(std::uint32_t);
    std::size_t total = (slots_.capacity() + pool_.capacity()) * sizeof(Slot);
    for (const auto& f : free_regions_) total += f.capacity() * u32;
    total += loc_.capacity() * sizeof(Loc) + bigs_.capacity() * sizeof(Body);
    total += cold_.capacity() * sizeof(Cold);
    total += (big_.capacity() + scene_index_.capacity()) * u32;
    total += image_.capacity() * sizeof(Image) + start_.capacity() * sizeof(Vec2);
    total += heap_.bytes();
    total += appearance_.bytes();
    return total;
}

bool CellEngine::check_invariants() const {
    if (!heap_.check_invariants()) return false;
    std::vector<std::uint8_t> seen(loc_.size(), 0);
    std::uint64_t overflowing = 0;
    for (std::uint32_t cy = 0; cy < ny_; ++cy) {
        for (std::uint32_t cx = 0; cx < nx_; ++cx) {
            const std::uint32_t fill = slots_[first_slot(cx, cy)].fill;
            if (fill > slots_per_cell) overflowing += fill - slots_per_cell;
            for (std::uint32_t k = 0; k < fill; ++k) {
                const Body& b = slot_at(cx, cy, k).b;
                if (b.id >= loc_.size() || seen[b.id] || loc_[b.id].cx != cx ||
                    loc_[b.id].cy != cy || loc_[b.id].pos != k || is_big(b.id))
                    return false;
                seen[b.id] = 1;
            }
        }
    }
    if (overflowing != overflow_discs_) return false;
    for (std::uint32_t i = 0; i < loc_.size(); ++i) {
        if (!is_big(i) && !seen[i]) return false;
        const Body& b = body(i);
        if (b.id != i || b.t > now_) return false;
        if (heap_.contains(i) && heap_.key(i).t < now_) return false;
        const Cold& ci = cold_[i];
        if (ci.pair_t != never && (!heap_.contains(i) || heap_.key(i).t > ci.pair_t)) return false;
        if (heap_.contains(i) && heap_.key(i).kind() == EventKind::pair &&
            (heap_.key(i).t != ci.pair_t || heap_.key(i).b() != ci.pair_partner)) {
            return false;
        }
        const Vec2 pos = position_at_now(b);
        const double cx = static_cast<double>(loc_[i].cx);
        const double cy = static_cast<double>(loc_[i].cy);
        const double slack = 1e-9 * (cw_ + ch_);
        if (pos.x < cx * cw_ - slack || pos.x > (cx + 1) * cw_ + slack) return false;
        if (pos.y < cy * ch_ - slack || pos.y > (cy + 1) * ch_ + slack) return false;
    }
    return true;
}

}  // namespace collide::sim
