// The fast engine's event step: pop the earliest pending event, check it, resolve it, and
// predict the next event of the particles it moved (docs/engines.md).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

#include "collide/error.hpp"
#include "collide/sim/kinematics.hpp"
#include "fast_engine_internal.hpp"

namespace collide::sim {

namespace {

using detail::cell_margin;
using detail::vec_of;
using kinematics::never;

}  // namespace

template <int D>
bool BasicFastEngine<D>::KeyLess::tie_break(const Key& x, const Key& y) const noexcept {
    if (x.kind() != y.kind()) return x.kind() < y.kind();
    const auto ids = [this](const Key& k) {
        const std::uint32_t a = (*scene_index)[k.a];
        if (k.kind() != EventKind::pair) return std::pair{a, k.b()};
        const std::uint32_t b = (*scene_index)[k.b()];
        return std::pair{std::min(a, b), std::max(a, b)};
    };
    return ids(x) < ids(y);
}

// ------------------------------------------------------------------------------------------
// The main loop: pop the earliest pending event, check it, resolve it, predict again.

template <int D>
void BasicFastEngine<D>::advance_to(double t) {
    const WallClock clock = core_.start_advance(now_, t);
    while (settle_queue() && queue_.top_key().t <= t) {
        this->poll_stop();
        const std::uint32_t i = queue_.top();
        const Key key = queue_.top_key();
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

template <int D>
bool BasicFastEngine<D>::settle_queue() {
    // Past the caches, the events of the calendar's next block ask for their records (and the
    // partner's) about a block of events before their turn, as the calendar walks that block's
    // list ahead. Hints only: the events are the same.
    return queue_.settle([this](std::uint32_t i, const Key& key) {
        __builtin_prefetch(&p_[i]);
        __builtin_prefetch(&cold_[i]);
        if (key.kind() == EventKind::pair) __builtin_prefetch(&p_[key.b()]);
    });
}

template <int D>
void BasicFastEngine<D>::process(std::uint32_t i, const Key& key) {
    // Every kind of event ends in predict(i).
    if (prefetch_records_) prefetch_list(i);
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
        case EventKind::zwall:
            process_wall(i, key.kind(), key.t);
            return;
        case EventKind::cell:
            if (lists()) {
                process_rebuild(i);
            } else {
                process_cell(i, key.b());
            }
            return;
    }
}

template <int D>
void BasicFastEngine<D>::count_collision_now(std::uint32_t i) {
    // The local clock is the time of the particle's latest event (collision or crossing).
    const Particle& pi = p_[i];
    std::uint32_t& count = cold_[i].instant_collisions;
    if (!same_instant(now_ - pi.t, pi.v, pi.r)) count = 0;
    if (++count > instant_limit_) throw_jammed(scene_index(i), now_, instant_limit_);
}

template <int D>
void BasicFastEngine<D>::process_pair(std::uint32_t i, std::uint32_t j, double t) {
    if (prefetch_records_) prefetch_list(j);
    queue_.prefetch_handle(j);
    count_collision_now(i);
    count_collision_now(j);
    advance_disc(i);
    advance_disc(j);
    Particle& pi = p_[i];
    Particle& pj = p_[j];
    // At contact the true image is the nearest one (boxes are wider than 2 sigma).
    const Vec dr = box_.displacement(pi.x, pj.x);
    const Vec impulse = kinematics::resolve_pair(pi.v, pj.v, cold_[i].m, cold_[j].m, dr);
    core_.counters().impulses.virial += std::abs(dot(dr, impulse));
    ++pi.count;
    ++pj.count;
    pi.last_partner = j;
    pj.last_partner = i;
    core_.collided(to_record(t, EventKind::pair, scene_index(i), scene_index(j)));
    // i's event is filed after j's scan, not before it: the calendar's bucket of it (a miss past
    // the caches) is asked for as soon as its time is known, and arrives while j is scanned.
    // Same events: j's scan reads no queue, and the queue sees the same calls in the same order.
    const Key ki = next_event(i);
    queue_.prefetch_place(i, ki.t);
    queue_.prefetch_unlink(j);
    const Key kj = next_event(j);
    enqueue(i, ki);
    enqueue(j, kj);
}

template <int D>
void BasicFastEngine<D>::process_wall(std::uint32_t i, EventKind kind, double t) {
    count_collision_now(i);
    advance_disc(i);
    Particle& pi = p_[i];
    const int k = static_cast<int>(kind) - static_cast<int>(EventKind::xwall);
    double& v = axis(pi.v, k);
    core_.counters().impulses.wall_impulse += 2.0 * cold_[i].m * std::abs(v);
    v = -v;
    ++pi.count;
    pi.last_partner = no_disc;
    core_.collided(to_record(t, kind, scene_index(i), no_disc));
    predict(i);
}

template <int D>
void BasicFastEngine<D>::process_cell(std::uint32_t i, std::uint32_t axis_index) {
    // A crossing far from the particle's latest event starts a new instant for the jam count.
    if (!same_instant(now_ - p_[i].t, p_[i].v, p_[i].r)) cold_[i].instant_collisions = 0;
    advance_disc(i);
    Particle& pi = p_[i];
    Coords c = coords_of(pi.cell);
    const auto k = static_cast<int>(axis_index);
    const std::int64_t n = n_[k];
    std::int64_t& ck = c[k];
    ck += axis(pi.v, k) > 0.0 ? 1 : -1;
    if (ck == n) {
        ck = 0;
        axis(pi.x, k) -= axis(extent_, k);
        ++image_[i][k];
    } else if (ck < 0) {
        ck = n - 1;
        axis(pi.x, k) += axis(extent_, k);
        --image_[i][k];
    }
    const std::uint32_t cell = cell_at(c);
    if (is_big(i)) {
        pi.cell = cell;
    } else {
        unlink(i);
        link(i, cell);
    }
    ++core_.counters().cell_crossings;
    predict_after_crossing(i, axis_index);
}

// ------------------------------------------------------------------------------------------
// Prediction: the earliest of i's wall, cell-crossing and pair events, as i's one heap entry.

template <int D>
void BasicFastEngine<D>::predict(std::uint32_t i) {
    enqueue(i, next_event(i));
}

template <int D>
typename BasicFastEngine<D>::Key BasicFastEngine<D>::next_event(std::uint32_t i) {
    const Particle& pi = p_[i];
    const double dt = now_ - pi.t;
    const Vec xi = pi.x + pi.v * dt;
    if (lists()) return predict_listed(i, pi, xi);
    // Pairs first, bounded only by each other (not by the wall and crossing times): the earliest
    // pair is remembered for the crossings to come, so it must be exact.
    Key pair = Key::make(never, i, no_disc, EventKind::pair);
    if (is_big(i)) {
        scan_ring(i, pi, xi, pair);
    } else {
        scan_small_neighbours(i, pi, xi, pair);
    }
    for (std::uint32_t b : big_) {
        if (b != i) consider_pair_images(i, pi, xi, b, pair);
    }
    return schedule(i, pi, xi, pair);
}

template <int D>
void BasicFastEngine<D>::predict_after_crossing(std::uint32_t i, std::uint32_t axis_index) {
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
    Coords lo = neighbourhood_lo();
    Coords hi = neighbourhood_hi();
    const auto k = static_cast<int>(axis_index);
    lo[k] = hi[k] = axis(pi.v, k) > 0.0 ? 1 : -1;
    scan_cells(i, pi, pi.x, lo, hi, pair);
    enqueue(i, schedule(i, pi, pi.x, pair));
}

template <int D>
typename BasicFastEngine<D>::Key BasicFastEngine<D>::predict_listed(std::uint32_t i,
                                                                    const Particle& pi, Vec xi) {
    // Nothing remembers a pair between predictions here (no crossings), so the list's expiry and
    // the walls go first: a pair that cannot beat them is skipped before its square root. The
    // earliest of all by KeyLess is the same whatever the order: the expiry first, which beats
    // "never" without a compare, then the walls of a walled box.
    Key best = Key::make(never, i, no_disc, EventKind::pair);
    const double dt = time_to_expiry(i, pi, xi);
    if (dt != never) best = Key::make(now_ + dt, i, 0, EventKind::cell);
    if (!periodic_) consider_walls_and_cells(i, pi, xi, best);
    scan_neighbour_list(i, pi, xi, best);
    remember_pair(
        i, best.kind() == EventKind::pair ? best : Key::make(never, i, no_disc, EventKind::pair));
    return best;
}

template <int D>
typename BasicFastEngine<D>::Key BasicFastEngine<D>::schedule(std::uint32_t i, const Particle& pi,
                                                              Vec xi, const Key& pair) {
    remember_pair(i, pair);
    Key best = pair;
    consider_walls_and_cells(i, pi, xi, best);
    return best;
}

template <int D>
void BasicFastEngine<D>::consider_walls_and_cells(std::uint32_t i, const Particle& pi, Vec xi,
                                                  Key& best) {
    const auto offer = [&](double dt, EventKind kind, std::uint32_t b) {
        if (dt == never) return;
        const Key k = Key::make(now_ + dt, i, b, kind);
        if (key_less_(k, best)) best = k;
    };
    if (!periodic_) {
        for (int k = 0; k < D; ++k) {
            offer(kinematics::time_to_wall(axis(xi, k), axis(pi.v, k), pi.r, axis(extent_, k)),
                  static_cast<EventKind>(static_cast<int>(EventKind::xwall) + k), no_disc);
        }
        core_.counters().predictions += D;
    }
    if (lists()) return;  // no crossings: predict_listed offers the list's expiry
    const Coords c = coords_of(pi.cell);
    // Walled boxes have no crossing out of the outer cells (the wall comes first).
    for (int k = 0; k < D; ++k) {
        const auto ck = static_cast<std::uint32_t>(c[k]);
        const double v = axis(pi.v, k);
        const double w = axis(cw_, k);
        if (v > 0.0 && (periodic_ || ck + 1 < n_[k])) {
            offer(std::max(0.0, ((ck + 1) * w - axis(xi, k)) / v), EventKind::cell,
                  static_cast<std::uint32_t>(k));
        } else if (v < 0.0 && (periodic_ || ck > 0)) {
            offer(std::max(0.0, (ck * w - axis(xi, k)) / v), EventKind::cell,
                  static_cast<std::uint32_t>(k));
        }
    }
}

template <int D>
inline bool BasicFastEngine<D>::cannot_beat(Vec dr, Vec dv, double sigma,
                                            double best_t) const noexcept {
    // Without the square root and the division of time_to_hit: for approaching discs apart,
    // sqrt(b^2 - ac) <= -b, so the contact time is at least c / (-2b). When even that bound is
    // later than the best event so far (by more than any rounding of time_to_hit and of now + dt:
    // relative 1e-9 of the interval plus 1e-14 of the time, vs. errors of ~1e-15), the pair's
    // event would have lost `t > best.t`, so skipping it changes nothing.
    const double b = dot(dv, dr);
    if (b >= 0.0) return true;  // receding: time_to_hit says never
    const double c = dot(dr, dr) - sigma * sigma;
    if (!(c > 0.0)) return false;
    return c > -2.0 * b * beat_margin(best_t);
}

template <int D>
inline void BasicFastEngine<D>::consider_pair(std::uint32_t i, const Particle& pi, Vec xi,
                                              std::uint32_t j, Vec shift, Key& best) {
    ++core_.counters().predictions;
    const Particle& pj = p_[j];
    const double dtj = now_ - pj.t;
    const Vec dr = pj.x + pj.v * dtj + shift - xi;
    const Vec dv = pj.v - pi.v;
    const double sigma = pi.r + pj.r;
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

template <int D>
void BasicFastEngine<D>::consider_pair_images(std::uint32_t i, const Particle& pi, Vec xi,
                                              std::uint32_t j, Key& best) {
    if (!periodic_) {
        consider_pair(i, pi, xi, j, Vec{}, best);
        return;
    }
    // Pairs with a big particle are not tied to neighbouring cells: try the 3^D nearest images.
    const Particle& pj = p_[j];
    const double dtj = now_ - pj.t;
    const Vec base = box_.displacement(xi, pj.x + pj.v * dtj);
    const Vec s = base - (pj.x + pj.v * dtj - xi);
    if constexpr (D == 2) {
        for (int ky = -1; ky <= 1; ++ky) {
            for (int kx = -1; kx <= 1; ++kx) {
                consider_pair(i, pi, xi, j, Vec{s.x + kx * box_.width, s.y + ky * box_.height},
                              best);
            }
        }
    } else {
        for (int kz = -1; kz <= 1; ++kz) {
            for (int ky = -1; ky <= 1; ++ky) {
                for (int kx = -1; kx <= 1; ++kx) {
                    consider_pair(
                        i, pi, xi, j,
                        Vec{s.x + kx * box_.width, s.y + ky * box_.height, s.z + kz * box_.depth},
                        best);
                }
            }
        }
    }
}

template <int D>
void BasicFastEngine<D>::scan_small_neighbours(std::uint32_t i, const Particle& pi, Vec xi,
                                               Key& best) {
    scan_cells(i, pi, xi, neighbourhood_lo(), neighbourhood_hi(), best);
}

template <int D>
[[gnu::always_inline]] inline void BasicFastEngine<D>::scan_list(std::uint32_t i,
                                                                 const Particle& pi, Vec xi,
                                                                 std::uint32_t first, Vec shift,
                                                                 Key& best) {
    for (std::uint32_t j = first; j != no_disc; j = p_[j].next) {
        if (j != i) consider_pair(i, pi, xi, j, shift, best);
    }
}

// Beyond the caches every cell's first disc is a miss, and following the lists one after the
// other makes those misses wait for each other: asking for all of them before reading any
// overlaps them (docs/benchmarks.md). The scans and their order are the same either way.
template <int D>
inline void BasicFastEngine<D>::scan_cells(std::uint32_t i, const Particle& pi, Vec xi,
                                           const Coords& lo, const Coords& hi, Key& best) {
    CellVisits visits;
    const std::size_t count = occupied_cells(
        pi, lo, hi, visits, [&](std::uint32_t cell) { __builtin_prefetch(&p_[head_[cell]]); });
    for (std::size_t k = 0; k < count; ++k) {
        scan_list(i, pi, xi, head_[visits[k].cell], vec_of(visits[k].shift), best);
    }
}

template <int D>
void BasicFastEngine<D>::scan_ring(std::uint32_t i, const Particle& pi, Vec xi, Key& best) {
    // Small particles that can touch big particle i before either leaves its cell lie within
    // 1 + (R + r_small) / cell cells of i's centre cell.
    const double reach = (pi.r + small_radius_max_) * (1.0 + cell_margin);
    Coords lo;
    Coords hi;
    bool wraps = false;
    for (int k = 0; k < D; ++k) {
        hi[k] = static_cast<std::int64_t>(1 + std::ceil(reach / axis(cw_, k)));
        lo[k] = -hi[k];
        wraps = wraps || 2 * hi[k] + 1 > n_[k];
    }
    if (periodic_ && wraps) {
        // The ring wraps onto itself: check every small particle (3^D images each).
        for (std::uint32_t j = 0; j < p_.size(); ++j) {
            if (j != i && !is_big(j)) consider_pair_images(i, pi, xi, j, best);
        }
        return;
    }
    // Big particles are in no cell list, so scan_list's skip of i never applies here.
    for_each_cell(pi, lo, hi, [&](std::uint32_t cell, Vec shift) {
        scan_list(i, pi, xi, head_[cell], shift, best);
    });
}

}  // namespace collide::sim
