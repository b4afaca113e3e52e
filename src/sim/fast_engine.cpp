// The fast engine in parts (docs/engines.md): this file builds the engine and reads it out;
// fast_cells.cpp chooses the cell grid and places the particles, fast_step.cpp is the event step
// and the prediction, fast_lists.cpp the spheres' neighbour lists, fast_calendar.cpp the event
// queue's tuning and view, fast_engine_internal.hpp what they share.

#include "collide/sim/fast_engine.hpp"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "collide/sim/sphere_check.hpp"
#include "fast_engine_internal.hpp"

namespace collide::sim {

namespace {

using kinematics::never;

}  // namespace

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
        if (i % detail::build_stop_poll_particles == 0) this->check_stop();
        predict(i);
    }
    tune_calendar();
}

template <int D>
std::unique_ptr<EngineOf<D>> BasicFastEngine<D>::clone() const {
    std::unique_ptr<BasicFastEngine> copy(new BasicFastEngine(*this));
    copy->set_collision_listener(nullptr);
    return copy;
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

namespace {

/// The engine's state in the arrays the observables read, kept between calls on one thread: a
/// video measures every frame, and at 10^6 discs fresh arrays (48 MB a frame) cost more in page
/// faults and zeroing than the sums (docs/benchmarks.md, "A big video").
template <int D>
struct MeasureArrays {
    std::vector<typename Space<D>::Vec> positions;
    std::vector<typename Space<D>::Vec> velocities;
    std::vector<double> masses;
    std::vector<double> radii;
};

template <int D>
MeasureArrays<D>& measure_arrays(std::size_t n) {
    thread_local MeasureArrays<D> arrays;
    arrays.positions.resize(n);
    arrays.velocities.resize(n);
    arrays.masses.resize(n);
    arrays.radii.resize(n);
    return arrays;
}

}  // namespace

template <int D>
Measurements BasicFastEngine<D>::measurements() const {
    // In the internal order: the sums come out as they always have, bit for bit.
    const std::size_t n = p_.size();
    MeasureArrays<D>& arrays = measure_arrays<D>(n);
    std::vector<Vec>& positions = arrays.positions;
    std::vector<Vec>& velocities = arrays.velocities;
    std::vector<double>& masses = arrays.masses;
    std::vector<double>& radii = arrays.radii;
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
    total += centre_.capacity() * sizeof(Vec) + (nbr_.capacity() + nbr_count_.capacity()) * u32 +
             wraps_.capacity();
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
