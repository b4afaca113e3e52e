#include "collide/sim/fast_engine.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "collide/error.hpp"
#include "collide/sim/kinematics.hpp"
#include "collide/sim/sphere_check.hpp"

namespace collide::sim {

namespace {

using kinematics::never;

/// Cells are this much wider than the largest small-disc diameter, so that a disc sitting a
/// rounding error outside its cell still only reaches the neighbouring cells.
constexpr double cell_margin = 1e-9;

/// Upper bound on grid cells per disc: enough for dense fluids (pi / (4 eta) cells per disc at
/// cells one diameter wide), and it stops dilute scenes from allocating millions of empty cells.
constexpr double max_cells_per_disc = 2.0;

/// A grid capped by max_cells_per_disc is refined while a particle's cell holds more than this
/// many particles on average (itself included): a crowd in a large box, such as a gas released
/// from one corner, would otherwise put hundreds in each cell, and every scan reads 3^D cells.
constexpr double crowded_cellmates = 8.0;

/// The refinement stops at this many cells (4 MiB of list heads), or at 16 per particle.
constexpr double crowded_max_cells = 1 << 20;

/// The neighbour lists' shell, as a fraction of the largest diameter (3D, see fast_engine.hpp):
/// thinner shells mean shorter lists but more rebuilds. 0.5 was the fastest of 0.2 ... 0.8 at
/// packing 0.45 (docs/benchmarks.md, spheres).
constexpr double list_shell_per_diameter = 0.5;

/// Lists beat cell scans from about packing 0.37 (0.81x at 0.30, 1.05x at 0.38, 1.3x at 0.45,
/// 1.6x at 0.5, N = 4000; docs/benchmarks.md): in a thinner gas a sphere rebuilds its list
/// several times between collisions. Below this packing fraction spheres use cell crossings
/// (0.38, not 0.4: a scene made at 0.4 sums to a hair less).
constexpr double list_min_packing = 0.38;

/// Up to this many bytes of particle records, a list scan finds them in the core's own caches
/// (a typical L2): asking for them first would only cost instructions (docs/benchmarks.md).
constexpr std::size_t records_in_cache = std::size_t{1} << 20;

/// Slots per cell of list centres to start with (about three centres per cell at packing
/// 0.45); a cell that outgrows them doubles every cell's slots.
constexpr std::uint32_t initial_cell_slots = 8;

/// Slots per list to start with; lists that outgrow them double every list's slots.
constexpr std::uint32_t initial_list_slots = 16;

/// Particles between two looks at the stop flag while the engine is built (a few milliseconds of
/// predictions or list gathering).
constexpr std::uint32_t build_stop_poll_particles = 4096;

/// The spheres' event calendar (pq::CalendarQueue): blocks that hold this many events on
/// average (the heap of the current block stays small), and a ring of buckets reaching this
/// many mean event intervals ahead (later events wait in the overflow list).
constexpr double calendar_events_per_block = 8.0;
constexpr double calendar_horizon = 8.0;

/// Cells along one axis: as many as fit with cells at least `min_cell` wide.
std::uint32_t fit_cells(double extent, double min_cell) {
    if (!(min_cell > 0.0)) return 1;
    const double n = std::floor(extent / min_cell);
    if (!(n >= 1.0)) return 1;
    return static_cast<std::uint32_t>(std::min(n, 65536.0));
}

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
                  std::uint32_t& slots) {
    const std::uint32_t wider_slots = 2 * slots;
    pq::BigVector<std::uint32_t> wider(used.size() * wider_slots, no_disc);
    for (std::size_t row = 0; row < used.size(); ++row) {
        std::copy_n(table.begin() + static_cast<std::ptrdiff_t>(row * slots), used[row],
                    wider.begin() + static_cast<std::ptrdiff_t>(row * wider_slots));
    }
    table = std::move(wider);
    slots = wider_slots;
}

template <std::size_t D>
double cell_count(const std::array<std::uint32_t, D>& n) {
    double cells = 1.0;
    for (const std::uint32_t c : n) cells *= static_cast<double>(c);
    return cells;
}

/// `full` (cells per axis) scaled down alike on every axis to at most `cap` cells in all, each
/// axis keeping at least `floor_n`.
template <std::size_t D>
std::array<std::uint32_t, D> shrink_grid(const std::array<std::uint32_t, D>& full, double cap,
                                         std::uint32_t floor_n) {
    const double cells = cell_count(full);
    if (cells <= cap) return full;
    const double shrink = D == 2 ? std::sqrt(cap / cells) : std::cbrt(cap / cells);
    std::array<std::uint32_t, D> n{};
    for (std::size_t k = 0; k < D; ++k) {
        n[k] = std::max(floor_n, static_cast<std::uint32_t>(static_cast<double>(full[k]) * shrink));
    }
    return n;
}

/// The number of particles in a particle's cell (itself included), averaged over the particles
/// of radius at most `small_max` (bigger ones are in no cell), for `n` cells per axis over
/// `extent`.
template <class Particles, class Vec, std::size_t D>
double mean_cellmates(const Particles& particles, const Vec& extent,
                      const std::array<std::uint32_t, D>& n, double small_max) {
    Vec cw = extent;
    for (std::size_t k = 0; k < D; ++k) axis(cw, static_cast<int>(k)) /= n[k];
    std::vector<std::uint32_t> occupancy(static_cast<std::size_t>(cell_count(n)), 0);
    std::uint64_t placed = 0;
    for (const auto& p : particles) {
        if (p.radius > small_max) continue;
        ++occupancy[cell_index(p.position, cw, n)];
        ++placed;
    }
    if (placed == 0) return 0.0;
    double pairs = 0.0;  // sum over cells of occupancy^2 = sum over particles of their cell's
    for (const std::uint32_t c : occupancy) pairs += static_cast<double>(c) * c;
    return pairs / static_cast<double>(placed);
}

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

template <int D>
BasicFastEngine<D>::BasicFastEngine(const SceneType& scene, const std::atomic<bool>* stop)
    : core_(scene),
      box_(scene.box),
      extent_(Space::extent(scene.box)),
      periodic_(scene.box.boundary == Boundary::periodic) {
    this->set_stop_flag(stop);
    choose_grid(scene);
    this->check_stop();
    place_discs(scene);
    this->check_stop();
    if (lists()) build_all_lists();
    instant_limit_ = instant_collision_limit(p_.size());
    for (std::uint32_t i = 0; i < p_.size(); ++i) {
        if (i % build_stop_poll_particles == 0) this->check_stop();
        predict(i);
    }
    tune_calendar();
}

namespace {

/// The big-particle threshold and the largest small radius of a scene's particles.
template <class Particles>
std::pair<double, double> split_radii(const Particles& particles) {
    std::vector<double> radii;
    radii.reserve(particles.size());
    for (const auto& d : particles) radii.push_back(d.radius);
    const double big = big_radius_threshold(radii);
    double small_max = 0.0;
    for (double r : radii) {
        if (r <= big) small_max = std::max(small_max, r);
    }
    return {big, small_max};
}

}  // namespace

template <int D>
bool BasicFastEngine<D>::can_simulate(const SceneType& scene) {
    if (scene.box.boundary != Boundary::periodic) return true;
    const double min_cell = 2.0 * split_radii(Space::particles(scene)).second * (1.0 + cell_margin);
    const Vec extent = Space::extent(scene.box);
    for (int k = 0; k < D; ++k) {
        if (fit_cells(axis(extent, k), min_cell) < 3) return false;
    }
    return true;
}

namespace {

constexpr const char* box_side_names[] = {"box.width", "box.height", "box.depth"};

}  // namespace

template <int D>
void BasicFastEngine<D>::choose_grid(const SceneType& scene) {
    const auto& particles = Space::particles(scene);
    std::tie(big_threshold_, small_radius_max_) = split_radii(particles);
    choose_lists(scene);
    // Lists mode: the grid holds list centres, which pairs within r_i + r_j + shell may have.
    const double min_cell = (2.0 * small_radius_max_ + shell_) * (1.0 + cell_margin);
    std::array<std::uint32_t, D> n{};
    for (int k = 0; k < D; ++k) {
        n[k] = fit_cells(axis(extent_, k), min_cell);
        if (periodic_ && n[k] < 3) {
            throw_scene_error("", 0, box_side_names[k],
                              D == 2 ? "a periodic box must be at least three disc diameters wide "
                                       "and tall for the fast engine (the classic engine has no "
                                       "such limit)"
                                     : "a periodic box must be at least three sphere diameters "
                                       "wide, tall and deep");
        }
    }
    // Dilute scenes: fewer, larger cells (each must stay at least min_cell wide, so only shrink).
    const auto count = static_cast<double>(particles.size());
    double cap = std::max(D == 2 ? 9.0 : 27.0, max_cells_per_disc * count);
    const std::uint32_t floor_n = periodic_ ? 3U : 1U;
    std::array<std::uint32_t, D> grid = shrink_grid(n, cap, floor_n);
    // Unless the particles crowd into a part of the box: then finer cells, within a budget.
    const double budget = std::max(crowded_max_cells, 16.0 * count);
    while (cell_count(grid) < cell_count(n) && 2.0 * cap <= budget &&
           mean_cellmates(particles, extent_, grid, big_threshold_) > crowded_cellmates) {
        cap *= 2.0;
        grid = shrink_grid(n, cap, floor_n);
    }
    n_ = grid;
    std::size_t total = 1;
    for (int k = 0; k < D; ++k) {
        axis(cw_, k) = axis(extent_, k) / n_[k];
        total *= n_[k];
    }
    if (lists()) {
        cell_slots_ = initial_cell_slots;
        members_.assign(total * cell_slots_, no_disc);
        member_count_.assign(total, 0);
    } else {
        head_.assign(total, no_disc);
    }
}

template <int D>
void BasicFastEngine<D>::choose_lists(const SceneType& scene) {
    lists_ = false;
    shell_ = 0.0;
    if constexpr (D == 3) {
        if (!std::isinf(big_threshold_) || !(small_radius_max_ > 0.0)) return;
        if (packing_fraction(scene) < list_min_packing) return;
        // A list entry keeps its image code above the index (a scene this big, 50 GB of
        // spheres, would use cell crossings).
        if (Space::particles(scene).size() > list_index_mask) return;
        const double shell = list_shell_per_diameter * 2.0 * small_radius_max_;
        if (periodic_) {
            // Three cells of centres per axis, and so the nearest image of a listed pair is
            // unambiguous (the box is wider than twice the 2 r + 2 shell a pair spans).
            const double min_cell = (2.0 * small_radius_max_ + shell) * (1.0 + cell_margin);
            const Vec extent = Space::extent(scene.box);
            for (int k = 0; k < D; ++k) {
                if (fit_cells(axis(extent, k), min_cell) < 3) return;
            }
        }
        lists_ = true;
        shell_ = shell;
        const auto& particles = Space::particles(scene);
        equal_radii_ = std::all_of(particles.begin(), particles.end(), [&](const auto& p) {
            return p.radius == particles.front().radius;
        });
        for (std::uint32_t code = 0; code < image_shift_.size(); ++code) {
            Vec shift{};
            std::uint32_t rest = code;
            for (int k = 0; k < D; ++k, rest /= 3) {
                axis(shift, k) = (static_cast<double>(rest % 3) - 1.0) * axis(extent_, k);
            }
            image_shift_[code] = shift;
        }
        // A hair inside shell / 2: a list still holds every pair that can touch when the
        // rebuild's time is rounded a little late.
        expiry_ = 0.5 * shell * (1.0 - 1e-9);
    }
}

template <int D>
std::uint32_t BasicFastEngine<D>::cell_of(Vec x) const noexcept {
    return cell_index(x, cw_, n_);
}

template <int D>
typename BasicFastEngine<D>::Coords BasicFastEngine<D>::coords_of(
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
std::uint32_t BasicFastEngine<D>::cell_at(const Coords& c) const noexcept {
    std::int64_t cell = c[D - 1];
    for (int k = D - 2; k >= 0; --k) cell = cell * n_[k] + c[k];
    return static_cast<std::uint32_t>(cell);
}

namespace {

/// The vector with components s (the cell scan's plain storage of a periodic image shift).
[[nodiscard]] constexpr Vec2 vec_of(const std::array<double, 2>& s) noexcept {
    return Vec2{s[0], s[1]};
}
[[nodiscard]] constexpr Vec3 vec_of(const std::array<double, 3>& s) noexcept {
    return Vec3{s[0], s[1], s[2]};
}

/// Interleaves the bits of x and y (Z-order / Morton code).
std::uint64_t morton2(std::uint32_t x, std::uint32_t y) noexcept {
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

/// Interleaves the low 21 bits of x, y and z (3D Morton code).
std::uint64_t morton3(std::uint32_t x, std::uint32_t y, std::uint32_t z) noexcept {
    const auto spread = [](std::uint64_t v) {
        v &= 0x1fffffULL;
        v = (v | (v << 32)) & 0x001f00000000ffffULL;
        v = (v | (v << 16)) & 0x001f0000ff0000ffULL;
        v = (v | (v << 8)) & 0x100f00f00f00f00fULL;
        v = (v | (v << 4)) & 0x10c30c30c30c30c3ULL;
        v = (v | (v << 2)) & 0x1249249249249249ULL;
        return v;
    };
    return spread(x) | (spread(y) << 1) | (spread(z) << 2);
}

}  // namespace

template <int D>
std::vector<std::uint32_t> BasicFastEngine<D>::locality_order(const SceneType& scene) const {
    const auto& particles = Space::particles(scene);
    const std::size_t n = particles.size();
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(n);
    for (std::uint32_t k = 0; k < n; ++k) {
        const Coords c = coords_of(cell_of(box_.wrap(particles[k].position)));
        if constexpr (D == 2) {
            keyed[k] = {morton2(static_cast<std::uint32_t>(c[0]), static_cast<std::uint32_t>(c[1])),
                        k};
        } else {
            keyed[k] = {morton3(static_cast<std::uint32_t>(c[0]), static_cast<std::uint32_t>(c[1]),
                                static_cast<std::uint32_t>(c[2])),
                        k};
        }
    }
    std::sort(keyed.begin(), keyed.end());
    std::vector<std::uint32_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = keyed[i].second;
    return order;
}

template <int D>
void BasicFastEngine<D>::place_discs(const SceneType& scene) {
    const auto& particles = Space::particles(scene);
    const std::size_t n = particles.size();
    if (n >= Key::index_mask)
        throw_scene_error("", 0, D == 2 ? "discs" : "spheres",
                          D == 2 ? "too many discs for the fast engine (at most 2^29 - 2)"
                                 : "too many spheres for the fast engine (at most 2^29 - 2)");
    *scene_index_ = locality_order(scene);
    p_.resize(n);
    cold_.assign(n, Cold{});
    image_.assign(n, Image{});
    if (lists()) centre_.resize(n);
    start_.resize(n);
    queue_.reserve_handles(n);
    // The key and handle arrays are reserved but untouched yet (the position map is not).
    for (std::uint32_t i = 0; i < n; ++i) {
        const auto& d = particles[scene_index(i)];
        const Vec pos = box_.wrap(d.position);
        p_[i] = Particle{pos, d.velocity, 0.0, d.radius, no_disc, 0, 0, no_disc};
        cold_[i].m = d.mass;
        start_[i] = d.position;
        if (periodic_) {
            // Keep the unwrapped start: image counts measure wrapping from the wrapped position.
            for (int k = 0; k < D; ++k) {
                image_[i][k] =
                    static_cast<std::int32_t>(std::floor(axis(d.position, k) / axis(extent_, k)));
            }
        }
        const std::uint32_t cell = cell_of(pos);
        p_[i].cell = cell;
        if (lists()) centre_[i] = pos;
        if (is_big(i)) {
            big_.push_back(i);
        } else {
            link(i, cell);
        }
    }
}

template <int D>
std::unique_ptr<EngineOf<D>> BasicFastEngine<D>::clone() const {
    std::unique_ptr<BasicFastEngine> copy(new BasicFastEngine(*this));
    copy->set_collision_listener(nullptr);
    return copy;
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
    if constexpr (D == 3) {
        return queue_.settle();
    } else {
        return !queue_.empty();
    }
}

template <int D>
void BasicFastEngine<D>::tune_calendar() {
    if constexpr (D == 3) {
        // Each particle's next event is on average `mean` ahead, so the whole system has about
        // n / mean events per unit time.
        double sum = 0.0;
        std::size_t n = 0;
        queue_.for_each([&](std::uint32_t, const Key& k) {
            sum += k.t - now_;
            ++n;
        });
        if (n == 0 || !(sum > 0.0)) return;  // nothing moves: one block
        const double mean = sum / static_cast<double>(n);
        const double width = calendar_events_per_block * mean / static_cast<double>(n);
        const auto buckets = std::bit_ceil(std::max<std::size_t>(
            64, static_cast<std::size_t>(calendar_horizon * static_cast<double>(n) /
                                         calendar_events_per_block)));
        queue_.tune(width, buckets, now_);
    }
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
    predict(i);
    predict(j);
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
    const Particle& pi = p_[i];
    const double dt = now_ - pi.t;
    const Vec xi = pi.x + pi.v * dt;
    if (lists()) {
        predict_listed(i, pi, xi);
        return;
    }
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
    schedule(i, pi, xi, pair);
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
    schedule(i, pi, pi.x, pair);
}

template <int D>
void BasicFastEngine<D>::predict_listed(std::uint32_t i, const Particle& pi, Vec xi) {
    // Nothing remembers a pair between predictions here (no crossings), so the walls and the
    // list's expiry go first: a pair that cannot beat them is skipped before its square root.
    // The earliest of all by KeyLess is the same whatever the order.
    Key best = Key::make(never, i, no_disc, EventKind::pair);
    consider_walls_and_cells(i, pi, xi, best);
    scan_neighbour_list(i, pi, xi, best);
    remember_pair(
        i, best.kind() == EventKind::pair ? best : Key::make(never, i, no_disc, EventKind::pair));
    enqueue(i, best);
}

template <int D>
inline void BasicFastEngine<D>::remember_pair(std::uint32_t i, const Key& pair) noexcept {
    Cold& ci = cold_[i];
    ci.pair_t = pair.t;
    ci.pair_partner = pair.t == never ? no_disc : pair.b();
    ci.pair_count = pair.t == never ? 0 : p_[pair.b()].count;
}

template <int D>
void BasicFastEngine<D>::schedule(std::uint32_t i, const Particle& pi, Vec xi, const Key& pair) {
    remember_pair(i, pair);
    Key best = pair;
    consider_walls_and_cells(i, pi, xi, best);
    enqueue(i, best);
}

template <int D>
inline void BasicFastEngine<D>::enqueue(std::uint32_t i, const Key& best) {
    if (best.t == never) {
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
    if (lists()) {
        offer(time_to_expiry(i, pi, xi), EventKind::cell, 0);
        return;
    }
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
inline double BasicFastEngine<D>::beat_margin(double best_t) const noexcept {
    return (best_t - now_) * (1.0 + 1e-9) + std::abs(best_t) * 1e-14;
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

// ------------------------------------------------------------------------------------------
// Neighbour lists (3D; see fast_engine.hpp).

template <int D>
void BasicFastEngine<D>::build_all_lists() {
    list_cap_ = initial_list_slots;
    prefetch_records_ = p_.size() * sizeof(Particle) > records_in_cache;
    nbr_.assign(p_.size() * list_cap_, no_disc);
    nbr_count_.assign(p_.size(), 0);
    for (std::uint32_t i = 0; i < p_.size(); ++i) {
        if (i % build_stop_poll_particles == 0) this->check_stop();
        gather_neighbours(i, true);
    }
}

template <int D>
void BasicFastEngine<D>::gather_neighbours(std::uint32_t i, bool only_after) {
    const Particle& pi = p_[i];
    const Vec ci = centre_[i];
    // As in scan_cells: every cell's members asked for before any is read.
    CellVisits visits;
    const std::size_t cells =
        occupied_cells(pi, neighbourhood_lo(), neighbourhood_hi(), visits, [&](std::uint32_t cell) {
            __builtin_prefetch(&members_[std::size_t{cell} * cell_slots_]);
        });
    for (std::size_t c = 0; c < cells; ++c) {
        const Vec shift = vec_of(visits[c].shift);
        // The cell's members are read from one array, not followed link by link: each record
        // read below then waits for no other (the linked lists' chain of reads cost more than
        // the distances).
        const std::uint32_t* members = &members_[std::size_t{visits[c].cell} * cell_slots_];
        const std::uint32_t count = member_count_[visits[c].cell];
        // j is seen from i through the cell's image, and i from j through the opposite one.
        const std::uint32_t image = image_code(visits[c].shift);
        const auto opposite = static_cast<std::uint32_t>(image_shift_.size() - 1) - image;
        const auto gather = [&](auto equal_radii) {
            for (std::uint32_t k = 0; k < count; ++k) {
                const std::uint32_t j = members[k];
                if (j == i || (only_after && j < i)) continue;
                // Equal radii: the same sum without reading j's record.
                const double rj = equal_radii ? pi.r : p_[j].r;
                const double reach = pi.r + rj + shell_;
                if (norm2(centre_[j] + shift - ci) <= reach * reach) {
                    add_neighbour(i, j, image);
                    add_neighbour(j, i, opposite);
                }
            }
        };
        if (equal_radii_) {
            gather(std::true_type{});
        } else {
            gather(std::false_type{});
        }
    }
}

template <int D>
std::uint32_t BasicFastEngine<D>::image_code(const std::array<double, D>& shift) noexcept {
    std::uint32_t code = 0;
    for (int k = D - 1; k >= 0; --k) {
        const double s = shift[static_cast<std::size_t>(k)];
        code = 3 * code + (s > 0.0 ? 2U : s < 0.0 ? 0U : 1U);
    }
    return code;
}

template <int D>
std::uint32_t BasicFastEngine<D>::nearest_image_code(std::uint32_t i,
                                                     std::uint32_t j) const noexcept {
    std::array<double, D> shift{};
    for (int k = 0; k < D; ++k) {
        const double d = axis(centre_[j], k) - axis(centre_[i], k);
        const double side = axis(extent_, k);
        if (periodic_)
            shift[static_cast<std::size_t>(k)] = d > 0.5 * side    ? -side
                                                 : d < -0.5 * side ? side
                                                                   : 0.0;
    }
    return image_code(shift);
}

template <int D>
inline void BasicFastEngine<D>::add_neighbour(std::uint32_t i, std::uint32_t j,
                                              std::uint32_t image) {
    if (nbr_count_[i] == list_cap_) widen_lists();
    nbr_[std::size_t{i} * list_cap_ + nbr_count_[i]++] = j | (image << list_image_shift);
}

template <int D>
void BasicFastEngine<D>::widen_lists() {
    // Rare (a crowd denser than the start): double every list's slots, keeping the entries.
    double_slots(nbr_, nbr_count_, list_cap_);
}

template <int D>
void BasicFastEngine<D>::remove_neighbour(std::uint32_t i, std::uint32_t j) noexcept {
    std::uint32_t* list = &nbr_[std::size_t{i} * list_cap_];
    std::uint32_t& count = nbr_count_[i];
    for (std::uint32_t k = 0; k < count; ++k) {
        if ((list[k] & list_index_mask) == j) {
            list[k] = list[--count];  // order does not matter: a scan's result is order-free
            return;
        }
    }
}

template <int D>
void BasicFastEngine<D>::process_rebuild(std::uint32_t i) {
    // A rebuild far from the particle's latest event starts a new instant for the jam count.
    if (!same_instant(now_ - p_[i].t, p_[i].v, p_[i].r)) cold_[i].instant_collisions = 0;
    advance_disc(i);
    Particle& pi = p_[i];
    const std::uint32_t* list = &nbr_[std::size_t{i} * list_cap_];
    for (std::uint32_t k = 0; k < nbr_count_[i]; ++k) {
        remove_neighbour(list[k] & list_index_mask, i);
    }
    nbr_count_[i] = 0;
    if (periodic_) {
        // The centre goes back into the box: the particle never strays more than shell / 2.
        for (int k = 0; k < D; ++k) {
            double& x = axis(pi.x, k);
            if (x < 0.0) {
                x += axis(extent_, k);
                --image_[i][k];
            } else if (x >= axis(extent_, k)) {
                x -= axis(extent_, k);
                ++image_[i][k];
            }
        }
    }
    centre_[i] = pi.x;
    unlink(i);
    link(i, cell_of(pi.x));
    gather_neighbours(i, false);
    ++core_.counters().list_rebuilds;
    predict(i);
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

template <int D>
void BasicFastEngine<D>::scan_neighbour_list(std::uint32_t i, const Particle& pi, Vec xi,
                                             Key& best) {
    const std::uint32_t* list = &nbr_[std::size_t{i} * list_cap_];
    const std::uint32_t count = nbr_count_[i];
    for (std::uint32_t k = 0; prefetch_records_ && k < count; ++k) {
        // A sphere's 80-byte record starts a cache line only every fourth sphere: ask for the
        // line that holds its last byte too (x, v, t and r, all a scan reads, span both).
        const auto* record = reinterpret_cast<const char*>(&p_[list[k] & list_index_mask]);
        __builtin_prefetch(record);
        __builtin_prefetch(record + sizeof(Particle) - 1);
    }
    core_.counters().predictions += count;
    // test_pair's tests in another order, for fewer mispredicted branches: half of all pairs
    // recede, and most of the others cannot beat the best event so far (cannot_beat), so both
    // are one combined test that goes the same way for most pairs; the rare rest is exact.
    // Locals, not members or `best`: through references the compiler reloads them per pair.
    const double now = now_;
    const Vec vi = pi.v;
    const double ri = pi.r;
    Key found = best;
    // cannot_beat's margin on the interval to the best event, updated when that improves.
    double reach = beat_margin(found.t);
    for (std::uint32_t k = 0; k < count; ++k) {
        const std::uint32_t j = list[k] & list_index_mask;
        const Particle& pj = p_[j];
        // j through the image stored with it (no shift away from the box's faces).
        const Vec dr = pj.x + pj.v * (now - pj.t) + image_shift_[list[k] >> list_image_shift] - xi;
        const Vec dv = pj.v - vi;
        const double sigma = ri + pj.r;
        const double b = dot(dv, dr);
        const double c = dot(dr, dr) - sigma * sigma;
        if ((b >= 0.0) | ((c > 0.0) & (c > -2.0 * b * reach))) continue;
        if (pi.last_partner == j && pj.last_partner == i) {
            const double touch = sigma * (1.0 + just_collided_slack);
            if (norm2(dr) < touch * touch) continue;
        }
        const double dt = kinematics::time_to_hit(dr, dv, sigma);
        if (dt == never) continue;
        const double t = now + dt;
        if (t > found.t) continue;
        const Key key = Key::make(t, i, j, EventKind::pair);
        if (key_less_(key, found)) {
            found = key;
            reach = beat_margin(found.t);
        }
    }
    best = found;
}

template <int D>
double BasicFastEngine<D>::time_to_expiry(std::uint32_t i, const Particle& pi,
                                          Vec xi) const noexcept {
    const Vec d = xi - centre_[i];
    const double a = dot(pi.v, pi.v);
    if (!(a > 0.0)) return never;
    const double b = dot(d, pi.v);
    const double c = dot(d, d) - expiry_ * expiry_;
    if (!(c < 0.0)) return 0.0;  // at the edge already (rounding): rebuild now
    const double root = std::sqrt(b * b - a * c);
    // The positive root of a t^2 + 2 b t + c = 0, without cancellation when b > 0.
    return b > 0.0 ? -c / (b + root) : (root - b) / a;
}

template <int D>
bool BasicFastEngine<D>::check_lists() const {
    const std::size_t n = p_.size();
    if (centre_.size() != n || nbr_count_.size() != n || nbr_.size() != n * list_cap_) return false;
    // j is in i's list, seen through its nearest image (the centres of a listed pair are
    // within 2 r + shell, far less than half the box).
    const auto listed = [&](std::uint32_t i, std::uint32_t j) {
        const std::uint32_t* list = &nbr_[std::size_t{i} * list_cap_];
        return std::find(list, list + nbr_count_[i],
                         j | (nearest_image_code(i, j) << list_image_shift)) !=
               list + nbr_count_[i];
    };
    for (std::uint32_t i = 0; i < n; ++i) {
        // Within shell / 2 of its centre, up to rounding.
        if (norm(position_at_now(i) - centre_[i]) > expiry_ * (1.0 + 1e-6)) return false;
        const std::uint32_t* list = &nbr_[std::size_t{i} * list_cap_];
        for (std::uint32_t k = 0; k < nbr_count_[i]; ++k) {
            const std::uint32_t j = list[k] & list_index_mask;
            if (j >= n || j == i || !listed(i, j) || !listed(j, i)) return false;  // symmetric
            if (std::count_if(list, list + nbr_count_[i],
                              [&](std::uint32_t e) { return (e & list_index_mask) == j; }) != 1)
                return false;
        }
        // Every pair whose centres are near is listed (the cells of centres hold them all).
        bool complete = true;
        for_each_cell(
            p_[i], neighbourhood_lo(), neighbourhood_hi(), [&](std::uint32_t cell, Vec shift) {
                for (std::uint32_t k = 0; k < member_count_[cell]; ++k) {
                    const std::uint32_t j = members_[std::size_t{cell} * cell_slots_ + k];
                    const double reach = (p_[i].r + p_[j].r + shell_) * (1.0 - 1e-9);
                    if (j != i && norm2(centre_[j] + shift - centre_[i]) <= reach * reach &&
                        !listed(i, j))
                        complete = false;
                }
            });
        if (!complete) return false;
    }
    return true;
}

// ------------------------------------------------------------------------------------------
// Bookkeeping.

template <int D>
void BasicFastEngine<D>::advance_disc(std::uint32_t i) noexcept {
    Particle& pi = p_[i];
    const double dt = now_ - pi.t;
    pi.x += pi.v * dt;
    pi.t = now_;
}

template <int D>
void BasicFastEngine<D>::link(std::uint32_t i, std::uint32_t cell) {
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
void BasicFastEngine<D>::unlink(std::uint32_t i) noexcept {
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
void BasicFastEngine<D>::widen_cells() {
    // Rare (a crowd denser than the start): double every cell's slots, keeping the members.
    double_slots(members_, member_count_, cell_slots_);
}

template <int D>
typename BasicFastEngine<D>::Vec BasicFastEngine<D>::position_at_now(
    std::uint32_t i) const noexcept {
    const Particle& pi = p_[i];
    const double dt = now_ - pi.t;
    return pi.x + pi.v * dt;
}

// ------------------------------------------------------------------------------------------
// Outputs.

template <int D>
SnapshotOf<D> BasicFastEngine<D>::snapshot() const {
    SnapshotOf<D> s = core_.start_snapshot(now_);
    for (std::uint32_t i = 0; i < p_.size(); ++i) {
        auto& out = [&]() -> auto& {
            if constexpr (D == 2) {
                return s.discs[scene_index(i)];
            } else {
                return s.spheres[scene_index(i)];
            }
        }
        ();
        BasicEngineCore<D>::set_motion(out, box_.wrap(position_at_now(i)), p_[i].v, p_[i].r,
                                       cold_[i].m);
    }
    if constexpr (D == 2) {
        if (watch_.on()) s.queue = queue_view();
    }
    return s;
}

template <int D>
QueuedEvent BasicFastEngine<D>::queued_event(std::uint32_t i, const Key& key) const noexcept {
    QueuedEvent e;
    e.t = key.t;
    e.kind = queued_kind(key.kind());
    e.a = scene_index(i);
    if (key.kind() == EventKind::pair) {
        const std::uint32_t j = key.b();
        e.b = scene_index(j);
        if (e.b < e.a) std::swap(e.a, e.b);
        e.stale = p_[j].count != cold_[i].pair_count;
    }
    return e;
}

// The indexed 4-ary heap holding one pending event per disc: its top levels, its next
// collisions. O(N), only for watched engines.
template <int D>
QueueView BasicFastEngine<D>::queue_view() const {
    QueueView view;
    view.shape = QueueShape::heap;
    view.arity = 4;
    view.one_per_disc = true;
    const std::size_t n = queue_.size();
    view.size = n;
    std::vector<QueuedEvent> all;
    all.reserve(n);
    std::size_t tree = n;  // entries in heap order at the front of `all`
    if constexpr (D == 3) {
        // The calendar's heap holds its next events; the tree shows that heap.
        view.name = "event calendar (next events: indexed 4-ary heap)";
        tree = queue_.near().size();
        queue_.for_each(
            [&](std::uint32_t i, const Key& key) { all.push_back(queued_event(i, key)); });
    } else {
        view.name = "indexed 4-ary heap";
        for (std::size_t k = 0; k < n; ++k) {
            const Key& key = queue_.key_at(k);
            all.push_back(queued_event(key.a, key));
        }
    }
    view.stale_entries = static_cast<std::uint64_t>(
        std::count_if(all.begin(), all.end(), [](const QueuedEvent& e) { return e.stale; }));
    view.levels = shown_tree_levels(view.arity, tree, watch_.limits());
    view.slots.assign(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(shown_tree_slots(
                                                     view.arity, view.levels, tree)));
    keep_next_collisions(all, watch_.next_events());
    view.next = std::move(all);
    view.popped = watch_.popped();
    view.pops = core_.counters().queue.pops;
    view.stale_pops = core_.counters().queue.stale_pops;
    return view;
}

template <int D>
Measurements BasicFastEngine<D>::measurements() const {
    // In the internal order: the sums come out as they always have, bit for bit.
    const std::size_t n = p_.size();
    std::vector<Vec> positions(n);
    std::vector<Vec> velocities(n);
    std::vector<double> masses(n);
    std::vector<double> radii(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        positions[i] = position_at_now(i);
        velocities[i] = p_[i].v;
        masses[i] = cold_[i].m;
        radii[i] = p_[i].r;
    }
    Measurements m = core_.measurements(now_, velocities, masses, radii, bytes());
    m.max_overlap = max_overlap(positions, radii, box_);
    m.msd = core_.mean_squared_displacement(n, [&](std::size_t i) {
        Vec unwrapped = positions[i];
        for (int k = 0; k < D; ++k) axis(unwrapped, k) += image_[i][k] * axis(extent_, k);
        return std::pair{std::size_t{scene_index(i)}, unwrapped - start_[i]};
    });
    return m;
}

template <int D>
std::uint64_t BasicFastEngine<D>::bytes() const noexcept {
    constexpr std::size_t u32 = sizeof(std::uint32_t);
    std::size_t total = p_.capacity() * sizeof(Particle);
    total += cold_.capacity() * sizeof(Cold);
    total += (big_.capacity() + head_.capacity() + scene_index_->capacity()) * u32;
    total += (members_.capacity() + member_count_.capacity()) * u32;
    total += image_.capacity() * sizeof(Image) + start_.capacity() * sizeof(Vec);
    total += centre_.capacity() * sizeof(Vec) + (nbr_.capacity() + nbr_count_.capacity()) * u32;
    total += queue_.bytes();
    total += core_.bytes();
    return total;
}

template <int D>
bool BasicFastEngine<D>::check_invariants() const {
    if (!queue_.check_invariants()) return false;
    std::vector<std::uint8_t> seen(p_.size(), 0);
    for (std::size_t c = 0; c < member_count_.size(); ++c) {
        if (member_count_[c] > cell_slots_) return false;
        for (std::uint32_t k = 0; k < member_count_[c]; ++k) {
            const std::uint32_t j = members_[c * cell_slots_ + k];
            if (j >= p_.size() || seen[j] || p_[j].cell != c || cold_[j].prev != k || is_big(j))
                return false;
            seen[j] = 1;
        }
    }
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
        if (queue_.contains(i) && queue_.key(i).t < now_) return false;
        // The pending event is the remembered pair or comes no later than it; a pending pair is
        // the remembered one.
        const Cold& ci = cold_[i];
        if (ci.pair_t != never && (!queue_.contains(i) || queue_.key(i).t > ci.pair_t))
            return false;
        if (queue_.contains(i) && queue_.key(i).kind() == EventKind::pair &&
            (queue_.key(i).t != ci.pair_t || queue_.key(i).b() != ci.pair_partner)) {
            return false;
        }
        // The centre (lists: the list's centre) lies in its cell, up to the rounding of the
        // crossing times.
        const Vec pos = lists() ? centre_[i] : position_at_now(i);
        const Coords c = coords_of(p_[i].cell);
        double slack = 0.0;
        for (int k = 0; k < D; ++k) slack += axis(cw_, k);
        slack *= 1e-9;
        for (int k = 0; k < D; ++k) {
            const double lo = static_cast<double>(c[k]) * axis(cw_, k);
            const double hi = static_cast<double>(c[k] + 1) * axis(cw_, k);
            if (axis(pos, k) < lo - slack || axis(pos, k) > hi + slack) return false;
        }
    }
    return !lists() || check_lists();
}

template class BasicFastEngine<2>;
template class BasicFastEngine<3>;

}  // namespace collide::sim
