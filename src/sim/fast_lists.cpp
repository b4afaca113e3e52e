// The fast engine's neighbour lists (3D; see fast_engine.hpp): whether a scene uses them, their
// rebuild, and the scan of one list when a sphere predicts.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <type_traits>

#include "collide/sim/kinematics.hpp"
#include "collide/sim/sphere_check.hpp"
#include "fast_engine_internal.hpp"

namespace collide::sim {

namespace {

using detail::cell_margin;
using detail::fit_cells;
using detail::vec_of;
using kinematics::never;

/// The neighbour lists' shell, as a fraction of the largest diameter (3D, see fast_engine.hpp):
/// thinner shells mean shorter lists but more rebuilds. At packing 0.45, timed against 0.5: 0.6
/// 1.02x at 4000 and at 108,000 spheres, 1.12x at 10^6 (where a rebuild's reads miss the
/// caches); 0.4 0.95x, 0.65 1.02x at 4000 but 1.01x at 108,000, 0.7 1.01x, 0.8 0.99x
/// (docs/benchmarks-history.md, "The 3D engine's margin at N = 4000").
constexpr double list_shell_per_diameter = 0.6;

/// Lists beat cell scans from about packing 0.37 (0.81x at 0.30, 1.05x at 0.38, 1.3x at 0.45,
/// 1.6x at 0.5, N = 4000; docs/benchmarks.md): in a thinner gas a sphere rebuilds its list
/// several times between collisions. Below this packing fraction spheres use cell crossings
/// (0.38, not 0.4: a scene made at 0.4 sums to a hair less).
constexpr double list_min_packing = 0.38;

/// Up to this many bytes of particle records, a list scan finds them in the core's own caches
/// (a typical L2): asking for them first would only cost instructions (docs/benchmarks.md).
constexpr std::size_t records_in_cache = std::size_t{1} << 20;

/// Slots per list to start with; lists that outgrow them double every list's slots.
constexpr std::uint32_t initial_list_slots = 16;

}  // namespace

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
void BasicFastEngine<D>::build_all_lists() {
    list_cap_ = initial_list_slots;
    prefetch_records_ = p_.size() * sizeof(Particle) > records_in_cache;
    nbr_.assign(p_.size() * list_cap_, no_disc);
    nbr_count_.assign(p_.size(), 0);
    wraps_.assign(p_.size(), 0);
    for (std::uint32_t i = 0; i < p_.size(); ++i) {
        if (i % detail::build_stop_poll_particles == 0) this->check_stop();
        gather_neighbours(i, true);
    }
}

template <int D>
void BasicFastEngine<D>::gather_neighbours(std::uint32_t i, bool only_after) {
    const Particle& pi = p_[i];
    const Vec ci = centre_[i];
    // The 3^D cells around i's and the image code of each, from three coordinates and code
    // digits per axis worked out once (for_each_cell and image_code per cell cost ~65
    // instructions a cell, 27 cells a rebuild); every occupied cell's members asked for before any
    // is read, as in scan_cells. The cells come in for_each_cell's order (the last axis outer).
    const Coords home = coords_of(pi.cell);
    std::array<std::array<std::int64_t, 3>, 3> at{};  // -1: no such cell (walled box)
    std::array<std::array<std::uint32_t, 3>, 3> digit{};
    for (int k = 0; k < D; ++k) {
        const auto n = static_cast<std::int64_t>(n_[k]);
        for (int o = -1; o <= 1; ++o) {
            std::int64_t x = home[k] + o;
            std::uint32_t d = 1;  // image_code's digit: 0 wrapped below, 1 none, 2 wrapped above
            if (x < 0 || x >= n) {
                if (periodic_) {
                    d = x < 0 ? 0 : 2;
                    x = x < 0 ? x + n : x - n;
                } else {
                    x = -1;
                }
            }
            at[k][o + 1] = x;
            digit[k][o + 1] = d;
        }
    }
    struct Near {
        std::uint32_t cell;
        std::uint32_t image;
    };
    std::array<Near, D == 2 ? 9 : 27> near;
    std::size_t cells = 0;
    const auto nx = static_cast<std::int64_t>(n_[0]);
    const auto ny = static_cast<std::int64_t>(n_[1]);
    constexpr int layers = D == 3 ? 3 : 1;  // 2D: one layer, z = 0 with digit 0
    for (int z = 0; z < layers; ++z) {
        if (at[2][z] < 0) continue;
        for (int y = 0; y < 3; ++y) {
            if (at[1][y] < 0) continue;
            const std::int64_t row = (at[2][z] * ny + at[1][y]) * nx;
            const std::uint32_t zy = 9 * digit[2][z] + 3 * digit[1][y];
            for (int x = 0; x < 3; ++x) {
                if (at[0][x] < 0) continue;
                const auto cell = static_cast<std::uint32_t>(row + at[0][x]);
                if (member_count_[cell] == 0) continue;
                __builtin_prefetch(&members_[std::size_t{cell} * cell_slots_]);
                near[cells++] = Near{cell, zy + digit[0][x]};
            }
        }
    }
    // Locals: through the members the compiler reloads them after every add_neighbour's stores
    // (the centres' array, i's radius, the reach), once per candidate.
    const Vec* centres = centre_.data();
    const double ri = pi.r;
    const double shell = shell_;
    // Equal radii: the same reach for every candidate, without reading j's record.
    const double reach_equal = ri + ri + shell;
    const double reach2_equal = reach_equal * reach_equal;
    const auto gather = [&](auto equal_radii, auto after) {
        for (std::size_t c = 0; c < cells; ++c) {
            const std::uint32_t image = near[c].image;
            const Vec shift = image_shift_[image];
            // The cell's members are read from one array, not followed link by link: each
            // record read below then waits for no other (the linked lists' chain of reads cost
            // more than the distances).
            const std::uint32_t* members = &members_[std::size_t{near[c].cell} * cell_slots_];
            const std::uint32_t count = member_count_[near[c].cell];
            // j is seen from i through the cell's image, and i from j through the opposite one.
            const auto opposite = static_cast<std::uint32_t>(image_shift_.size() - 1) - image;
            // Most cells are seen through no image: no shift to add (adding a zero one changes
            // no distance), and no image code to set either list's wraps_ by.
            const auto members_within = [&](auto shifted) {
                for (std::uint32_t k = 0; k < count; ++k) {
                    const std::uint32_t j = members[k];
                    if (j == i || (after && j < i)) continue;
                    double reach2 = reach2_equal;
                    if constexpr (!equal_radii) {
                        const double reach = ri + p_[j].r + shell;
                        reach2 = reach * reach;
                    }
                    Vec d = centres[j];
                    if constexpr (shifted) d += shift;
                    if (norm2(d - ci) <= reach2) {
                        add_neighbour(i, j, shifted ? image : no_image_shift);
                        add_neighbour(j, i, shifted ? opposite : no_image_shift);
                    }
                }
            };
            if (image == no_image_shift) {
                members_within(std::false_type{});
            } else {
                members_within(std::true_type{});
            }
        }
    };
    if (equal_radii_) {
        if (only_after) {
            gather(std::true_type{}, std::true_type{});
        } else {
            gather(std::true_type{}, std::false_type{});
        }
    } else {
        if (only_after) {
            gather(std::false_type{}, std::true_type{});
        } else {
            gather(std::false_type{}, std::false_type{});
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
    if (image != no_image_shift) wraps_[i] = 1;
}

template <int D>
void BasicFastEngine<D>::widen_lists() {
    // Rare (a crowd denser than the start): double every list's slots, keeping the entries.
    detail::double_slots(nbr_, nbr_count_, list_cap_);
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
    wraps_[i] = 0;
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
    // are one test that goes the same way for most pairs; the rare rest is exact.
    // Locals, not members or `best`: through references the compiler reloads them per pair.
    const auto scan = [&](auto equal_radii, auto shifted) {
        const double now = now_;
        const Vec vi = pi.v;
        const double ri = pi.r;
        // Equal radii: every pair's contact distance and its square are the same values, worked
        // out once (one load and two operations fewer per pair).
        const double sigma_equal = ri + ri;
        const double sigma2_equal = sigma_equal * sigma_equal;
        Key found = best;
        // cannot_beat's bound as one factor: c > b * (-2 margin) is c > -2 b margin exactly (a
        // factor of -2 only moves the exponent); updated when the best event improves.
        double bound = -2.0 * beat_margin(found.t);
        for (std::uint32_t k = 0; k < count; ++k) {
            const std::uint32_t j = list[k] & list_index_mask;
            const Particle& pj = p_[j];
            // j through the image stored with it (no shift away from the box's faces: adding
            // a zero shift changes no sum but the sign of a zero, which no test below sees).
            Vec dr = pj.x + pj.v * (now - pj.t);
            if constexpr (shifted) dr += image_shift_[list[k] >> list_image_shift];
            dr = dr - xi;
            const Vec dv = pj.v - vi;
            const double sigma = equal_radii ? sigma_equal : ri + pj.r;
            const double b = dot(dv, dr);
            const double c = dot(dr, dr) - (equal_radii ? sigma2_equal : sigma * sigma);
            // Apart (c > 0), the bound is <= 0 for a receding pair (b >= 0), so this one test
            // skips both the receding pairs and those that cannot beat the best so far; touching
            // or overlapping (c <= 0, rare) it never holds, and the receding test follows.
            if (c > b * bound) continue;
            if (b >= 0.0) continue;
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
                bound = -2.0 * beat_margin(found.t);
            }
        }
        best = found;
    };
    if (equal_radii_) {
        if (wraps_[i]) {
            scan(std::true_type{}, std::true_type{});
        } else {
            scan(std::true_type{}, std::false_type{});
        }
    } else {
        scan(std::false_type{}, std::true_type{});
    }
}

template <int D>
inline double BasicFastEngine<D>::time_to_expiry(std::uint32_t i, const Particle& pi,
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
    if (centre_.size() != n || nbr_count_.size() != n || wraps_.size() != n ||
        nbr_.size() != n * list_cap_)
        return false;
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
            if (!wraps_[i] && (list[k] >> list_image_shift) != no_image_shift) return false;
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

}  // namespace collide::sim
