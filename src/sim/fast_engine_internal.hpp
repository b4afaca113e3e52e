#pragma once
/// \file
/// What the fast engine's source files share (src/sim/fast_*.cpp, one part of the engine each, as
/// docs/engines.md lists them): the cell grid's geometry, the bookkeeping of a particle's clock and
/// cell, and the cell scans. The parts are compiled as one translation unit
/// (src/sim/CMakeLists.txt, fast_engine.cpp last, which instantiates the class), so the compiler
/// sees the whole engine at once and inlines across the parts as it did when the engine was one
/// file.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "collide/sim/fast_engine.hpp"
#include "collide/sim/kinematics.hpp"

namespace collide::sim::detail {

/// Cells are this much wider than the largest small-disc diameter, so that a disc sitting a
/// rounding error outside its cell still only reaches the neighbouring cells.
constexpr double cell_margin = 1e-9;

/// Particles between two looks at the stop flag while the engine is built (a few milliseconds of
/// predictions or list gathering).
constexpr std::uint32_t build_stop_poll_particles = 4096;

/// Cells along one axis: as many as fit with cells at least `min_cell` wide.
std::uint32_t fit_cells(double extent, double min_cell);

/// The linear index of the cell holding x in a grid of n[k] cells of side cw[k] along each axis
/// (the first axis varies fastest), positions outside the grid clamped to its edge cells.
template <std::size_t D, class Vec>
std::uint32_t cell_index(Vec x, Vec cw, const std::array<std::uint32_t, D>& n) noexcept {
    const auto clamp_index = [](double v, std::uint32_t cells) {
        if (!(v > 0.0)) return 0U;
        return static_cast<std::uint32_t>(std::min(v, static_cast<double>(cells - 1)));
    };
    std::uint32_t cell = 0;
    for (int k = static_cast<int>(D) - 1; k >= 0; --k) {
        const auto kk = static_cast<std::size_t>(k);
        cell = cell * n[kk] + clamp_index(axis(x, k) / axis(cw, k), n[kk]);
    }
    return cell;
}

/// Doubles `slots`, the width of each row of `table` (one row per entry of `used`), keeping each
/// row's first used[row] entries (the rest: no_disc).
void double_slots(pq::BigVector<std::uint32_t>& table, const pq::BigVector<std::uint32_t>& used,
                  std::uint32_t& slots);

/// The vector with components s (the cell scan's plain storage of a periodic image shift).
[[nodiscard]] constexpr Vec2 vec_of(const std::array<double, 2>& s) noexcept {
    return Vec2{s[0], s[1]};
}
[[nodiscard]] constexpr Vec3 vec_of(const std::array<double, 3>& s) noexcept {
    return Vec3{s[0], s[1], s[2]};
}

}  // namespace collide::sim::detail

namespace collide::sim {

// ------------------------------------------------------------------------------------------
// The cell grid's geometry.

template <int D>
inline std::uint32_t BasicFastEngine<D>::cell_of(Vec x) const noexcept {
    return detail::cell_index(x, cw_, n_);
}

template <int D>
inline typename BasicFastEngine<D>::Coords BasicFastEngine<D>::coords_of(
    std::uint32_t cell) const noexcept {
    Coords c{};
    if constexpr (D == 2) {
        c[0] = static_cast<std::int64_t>(cell % n_[0]);
        c[1] = static_cast<std::int64_t>(cell / n_[0]);
    } else {
        c[0] = static_cast<std::int64_t>(cell % n_[0]);
        const std::uint32_t rest = cell / n_[0];
        c[1] = static_cast<std::int64_t>(rest % n_[1]);
        c[2] = static_cast<std::int64_t>(rest / n_[1]);
    }
    return c;
}

template <int D>
inline std::uint32_t BasicFastEngine<D>::cell_at(const Coords& c) const noexcept {
    std::int64_t cell = c[D - 1];
    for (int k = D - 2; k >= 0; --k) cell = cell * n_[k] + c[k];
    return static_cast<std::uint32_t>(cell);
}

template <int D>
template <typename Visit>
[[gnu::always_inline]] inline void BasicFastEngine<D>::for_each_cell(const Particle& pi,
                                                                     const Coords& lo_in,
                                                                     const Coords& hi_in,
                                                                     Visit&& visit) const {
    // Local copies: through the references the bounds were reloaded from memory on every
    // iteration (the visitor's stores might alias them).
    const Coords lo = lo_in;
    const Coords hi = hi_in;
    const Coords c = coords_of(pi.cell);
    // One axis: the wrapped coordinate and the image shift of offset o, or false (no such cell).
    const auto along = [&](int k, std::int64_t o, std::int64_t& x, double& shift) {
        x = c[k] + o;
        shift = 0.0;
        const auto n = static_cast<std::int64_t>(n_[k]);
        if (x < 0 || x >= n) {
            if (!periodic_) return false;
            shift = x < 0 ? -axis(extent_, k) : axis(extent_, k);
            x = x < 0 ? x + n : x - n;
        }
        return true;
    };
    const auto nx = static_cast<std::int64_t>(n_[0]);
    if constexpr (D == 2) {
        if (c[0] + lo[0] >= 0 && c[0] + hi[0] < nx && c[1] + lo[1] >= 0 &&
            c[1] + hi[1] < static_cast<std::int64_t>(n_[1])) {
            // Inside the grid (most cells): nothing wraps, every shift is zero; the same cells in
            // the same order as below, without the per-cell wrap tests.
            for (std::int64_t y = c[1] + lo[1]; y <= c[1] + hi[1]; ++y) {
                for (std::int64_t x = c[0] + lo[0]; x <= c[0] + hi[0]; ++x) {
                    const auto cell = static_cast<std::uint32_t>(y * nx + x);
                    if (occupied(cell)) visit(cell, Vec{0.0, 0.0});
                }
            }
            return;
        }
        for (std::int64_t oy = lo[1]; oy <= hi[1]; ++oy) {
            std::int64_t y;
            double shift_y;
            if (!along(1, oy, y, shift_y)) continue;
            for (std::int64_t ox = lo[0]; ox <= hi[0]; ++ox) {
                std::int64_t x;
                double shift_x;
                if (!along(0, ox, x, shift_x)) continue;
                const auto cell = static_cast<std::uint32_t>(y * nx + x);
                if (occupied(cell)) visit(cell, Vec{shift_x, shift_y});
            }
        }
    } else {
        const auto ny = static_cast<std::int64_t>(n_[1]);
        for (std::int64_t oz = lo[2]; oz <= hi[2]; ++oz) {
            std::int64_t z;
            double shift_z;
            if (!along(2, oz, z, shift_z)) continue;
            for (std::int64_t oy = lo[1]; oy <= hi[1]; ++oy) {
                std::int64_t y;
                double shift_y;
                if (!along(1, oy, y, shift_y)) continue;
                const std::int64_t row = (z * ny + y) * nx;
                for (std::int64_t ox = lo[0]; ox <= hi[0]; ++ox) {
                    std::int64_t x;
                    double shift_x;
                    if (!along(0, ox, x, shift_x)) continue;
                    const auto cell = static_cast<std::uint32_t>(row + x);
                    if (occupied(cell)) visit(cell, Vec{shift_x, shift_y, shift_z});
                }
            }
        }
    }
}

template <int D>
template <typename Prefetch>
[[gnu::always_inline]] inline std::size_t BasicFastEngine<D>::occupied_cells(
    const Particle& pi, const Coords& lo, const Coords& hi, CellVisits& visits,
    Prefetch&& prefetch) const {
    std::size_t count = 0;
    for_each_cell(pi, lo, hi, [&](std::uint32_t cell, Vec shift) {
        prefetch(cell);
        CellVisit& visit = visits[count++];
        visit.cell = cell;
        for (int k = 0; k < D; ++k) visit.shift[static_cast<std::size_t>(k)] = axis(shift, k);
    });
    return count;
}

// ------------------------------------------------------------------------------------------
// Bookkeeping.

template <int D>
inline void BasicFastEngine<D>::advance_disc(std::uint32_t i) noexcept {
    Particle& pi = p_[i];
    const double dt = now_ - pi.t;
    pi.x += pi.v * dt;
    pi.t = now_;
}

template <int D>
inline void BasicFastEngine<D>::link(std::uint32_t i, std::uint32_t cell) {
    Particle& pi = p_[i];
    pi.cell = cell;
    if (lists()) {
        if (member_count_[cell] == cell_slots_) widen_cells();
        const std::uint32_t slot = member_count_[cell]++;
        members_[std::size_t{cell} * cell_slots_ + slot] = i;
        cold_[i].prev = slot;
        return;
    }
    pi.next = head_[cell];
    cold_[i].prev = no_disc;
    if (pi.next != no_disc) cold_[pi.next].prev = i;
    head_[cell] = i;
}

template <int D>
inline void BasicFastEngine<D>::unlink(std::uint32_t i) noexcept {
    Particle& pi = p_[i];
    if (lists()) {
        // The cell's last member takes i's slot.
        std::uint32_t* members = &members_[std::size_t{pi.cell} * cell_slots_];
        const std::uint32_t slot = cold_[i].prev;
        const std::uint32_t last = members[--member_count_[pi.cell]];
        members[slot] = last;
        cold_[last].prev = slot;
        cold_[i].prev = no_disc;
        return;
    }
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

template <int D>
inline void BasicFastEngine<D>::widen_cells() {
    // Rare (a crowd denser than the start): double every cell's slots, keeping the members.
    detail::double_slots(members_, member_count_, cell_slots_);
}

template <int D>
inline typename BasicFastEngine<D>::Vec BasicFastEngine<D>::position_at_now(
    std::uint32_t i) const noexcept {
    const Particle& pi = p_[i];
    const double dt = now_ - pi.t;
    return pi.x + pi.v * dt;
}

// ------------------------------------------------------------------------------------------
// Prediction: its always-inline steps (visible wherever the class is instantiated) and the
// margin the step and the list scan share.

template <int D>
inline void BasicFastEngine<D>::remember_pair(std::uint32_t i, const Key& pair) noexcept {
    Cold& ci = cold_[i];
    ci.pair_t = pair.t;
    ci.pair_partner = pair.t == kinematics::never ? no_disc : pair.b();
    ci.pair_count = pair.t == kinematics::never ? 0 : p_[pair.b()].count;
}

template <int D>
inline void BasicFastEngine<D>::enqueue(std::uint32_t i, const Key& best) {
    if (best.t == kinematics::never) {
        if (queue_.contains(i)) {
            queue_.erase(i);
            ++stats().updates;
        }
        return;
    }
    if (queue_.contains(i)) {
        ++stats().updates;
    } else {
        ++stats().pushes;
    }
    queue_.push_or_change(i, best);
    stats().max_size = std::max<std::uint64_t>(stats().max_size, queue_.size());
}

template <int D>
inline double BasicFastEngine<D>::beat_margin(double best_t) const noexcept {
    return (best_t - now_) * (1.0 + 1e-9) + std::abs(best_t) * 1e-14;
}

template <int D>
inline void BasicFastEngine<D>::prefetch_list(std::uint32_t i) const noexcept {
    // What predict(i) reads at the end of the event, asked for at its start: the list's centre,
    // count and first slots, each a miss of its own once the lists outgrow the caches (+14-23 %
    // collisions per second at 108,000 spheres, docs/benchmarks.md).
    __builtin_prefetch(&centre_[i]);
    __builtin_prefetch(&nbr_count_[i]);
    __builtin_prefetch(&nbr_[std::size_t{i} * list_cap_]);
}

}  // namespace collide::sim
