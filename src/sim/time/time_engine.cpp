#include "collide/sim/time_engine.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <tuple>
#include <type_traits>

#include "collide/error.hpp"
#include "collide/sim/kinematics.hpp"
#include "collide/sim/observables.hpp"
#include "time/cell_grid.hpp"
#include "time/pair_sweep.hpp"

namespace collide {

void validate_time_driven_options(const EngineOptions& options, std::string_view dt_field) {
    if (!std::isfinite(options.dt) || options.dt <= 0.0) {
        char value[32];
        std::snprintf(value, sizeof value, "%g", options.dt);
        throw_option_error(dt_field, value, "a finite time step > 0");
    }
}

}  // namespace collide

namespace collide::sim {

namespace {

/// Grid cells are widened by this factor over the reach they must cover, so that a pair exactly
/// `reach` apart cannot land two cells apart through rounding.
constexpr double cell_margin = 1.0 + 1e-9;

/// Clamps a contact time solved in a step of length h to [0, h]: `never` (grazing pairs where
/// rounding makes the discriminant negative) and tiny overshoots mean "at the end of the step".
double within_step(double t_contact, double h) noexcept {
    return std::clamp(t_contact, 0.0, h);
}

/// The wall contact of axis k (0 x, 1 y, 2 z).
constexpr CollisionKind wall_kind(int k) noexcept {
    return static_cast<CollisionKind>(static_cast<int>(CollisionKind::xwall) + k);
}

}  // namespace

template <int D>
BasicTimeEngine<D>::BasicTimeEngine(const SceneType& scene, const EngineOptions& options)
    : core_(scene),
      box_(scene.box),
      extent_(Space::extent(scene.box)),
      dt_(options.dt),
      use_grid_(options.td_detect == OverlapDetection::grid) {
    validate_time_driven_options(options);
    const auto& particles = Space::particles(scene);
    const std::size_t n = particles.size();
    position_.reserve(n);
    velocity_.reserve(n);
    radius_.reserve(n);
    mass_.reserve(n);
    for (const auto& disc : particles) {
        position_.push_back(box_.wrap(disc.position));
        velocity_.push_back(disc.velocity);
        radius_.push_back(disc.radius);
        mass_.push_back(disc.mass);
        max_radius_ = std::max(max_radius_, disc.radius);
    }
    displacement_.assign(n, Vec{});
    escaped_.assign(n, false);
    through_barrier_.assign(n, false);
    double lightest = std::numeric_limits<double>::infinity();
    for (const double m : mass_) lightest = std::min(lightest, m);
    immovable_mass_ = immovable_mass_ratio * lightest;
    grid_ = std::make_unique<detail::BasicCellGrid<D>>();
    sweep_ = std::make_unique<detail::BasicPairSweep<D>>();
    initial_energy_ = kinetic_energy();
    take_census();
}

template <int D>
BasicTimeEngine<D>::~BasicTimeEngine() = default;

template <int D>
void BasicTimeEngine<D>::set_collision_listener(CollisionListener listener) {
    core_.set_listener(std::move(listener));
}

template <int D>
std::uint64_t BasicTimeEngine<D>::whole_steps(double t, double dt) noexcept {
    if (!(t > 0.0) || !(dt > 0.0)) return 0;
    // Beyond 2^62 steps nothing could run them anyway (the work limits refuse far less).
    constexpr double most = 4.6e18;
    const double ratio = t / dt;
    if (!(ratio < most)) return static_cast<std::uint64_t>(most);
    // floor(t / dt), then corrected by the products the engine actually computes, k * dt, so
    // that the division's rounding cannot disagree with the step ends.
    auto k = static_cast<std::uint64_t>(std::floor(ratio));
    const double reach = t + landing_tolerance * dt;
    while (static_cast<double>(k + 1) * dt <= reach) ++k;
    while (k > 0 && static_cast<double>(k) * dt > reach) --k;
    return k;
}

template <int D>
void BasicTimeEngine<D>::advance_to(double t) {
    const WallClock clock = core_.start_advance(clock_, t);
    missed_markers_.clear();  // markers are "missed since the previous frame"
    // Step k ends at k dt from t = 0 whoever calls (a video at any fps, a thumbnail, simulate):
    // the same step gives the same state bit for bit. Only whole steps are taken; the state
    // stays at the latest one at or before t.
    const std::uint64_t target = whole_steps(t, dt_);
    try {
        while (steps_ < target) {
            this->check_stop();  // once per step: a step over many discs can take milliseconds
            const double next = static_cast<double>(steps_ + 1) * dt_;
            step(next - time_);
            time_ = next;
        }
    } catch (...) {
        clock_ = std::max(clock_, time_);  // stopped: the clock is where the state is
        throw;
    }
    clock_ = t;
    take_census();
}

// One quantum, as the lecture lists it: move everyone, check for overlaps, roll back, resolve.
template <int D>
void BasicTimeEngine<D>::step(double h) {
    step_start_ = time_;
    step_failed_ = false;
    step_candidates_.clear();
    drift(h);
    contacts_.clear();
    try {
        detect_pair_contacts(h);  // the long phase (O(N^2) all-pairs): it looks at the stop flag
    } catch (...) {
        drift(-h);  // stopped: back to the start of the step (up to rounding), time_ unchanged
        throw;
    }
    detect_wall_contacts(h);
    resolve_contacts(h);
    wrap_positions();
    finish_failure_record();
    ++steps_;
#ifdef COLLIDE_VALIDATE
    validate_state();
#endif
}

template <int D>
void BasicTimeEngine<D>::drift(double h) {
    for (std::uint32_t i = 0; i < position_.size(); ++i) {
        move(i, h * velocity_[i]);
    }
}

template <int D>
void BasicTimeEngine<D>::move(std::uint32_t i, Vec delta) {
    position_[i] += delta;
    displacement_[i] += delta;
}

template <int D>
template <typename PairVisitor>
void BasicTimeEngine<D>::for_each_candidate_pair(double h, PairVisitor&& visit) {
    // A pair that touches at any moment of the step ends at most 2 r_max + 2 v_max h apart, so a
    // grid with that reach sees every overlap and every miss.
    if (use_grid_ &&
        grid_->build(box_, position_, (2.0 * max_radius_ + 2.0 * max_speed() * h) * cell_margin)) {
        // Cells as wide as the fast discs' reach can hold most of the discs: poll here too.
        grid_->for_each_pair([&](std::uint32_t i, std::uint32_t j) {
            if (++overlap_checks_ % detail::sweep_stop_poll_pairs == 0) this->check_stop();
            visit(i, j);
        });
        return;
    }
    // The lecture's all-pairs loop: N(N-1)/2 checks. The sweep tests every pair against a
    // conservative bound in a vectorised loop; the exact tests (visit) run on the few it keeps,
    // in the same (i, j) order as the plain double loop, so the results are the same.
    if (!sweep_->find(box_, position_, velocity_, radius_, h, candidates_, this->stop_flag())) {
        this->throw_stopped();
    }
    const auto n = static_cast<std::uint64_t>(position_.size());
    overlap_checks_ += n < 2 ? 0 : n * (n - 1) / 2;
    for (const auto& [i, j] : candidates_) {
        visit(i, j);
    }
}

template <int D>
void BasicTimeEngine<D>::detect_pair_contacts(double h) {
    struct Miss {
        std::uint32_t i;
        std::uint32_t j;
        Vec where;
        double t_contact;
    };
    std::vector<Miss> misses;
    std::vector<Miss> grazes;  // missed too, but seen overlapping: no replay record
    const auto contact_point = [&](std::uint32_t i, const Vec& dr0, const Vec& dv, double sigma,
                                   double t_contact) {
        const Vec pi = position_[i] - (h - t_contact) * velocity_[i];
        return box_.wrap(pi + (radius_[i] / sigma) * (dr0 + t_contact * dv));
    };
    for_each_candidate_pair(h, [&](std::uint32_t i, std::uint32_t j) {
        const Vec dr = box_.displacement(position_[i], position_[j]);
        const Vec dv = velocity_[j] - velocity_[i];
        const double sigma = radius_[i] + radius_[j];
        const double dist2 = norm2(dr);
        if (dist2 < sigma * sigma) {
            max_overlap_seen_ = std::max(max_overlap_seen_, sigma - std::sqrt(dist2));
            if (dot(dv, dr) < 0.0) {
                ++core_.counters().predictions;
                const double t_contact =
                    within_step(kinematics::time_to_hit(dr - h * dv, dv, sigma), h);
                contacts_.push_back({t_contact, CollisionKind::pair, i, j});
                return;
            }
            // Reporting only: apart at the start of the step, overlapping and already parting at
            // its end. A glancing pair went in and turned back out between two checks: the check
            // sees a separating overlap, which it never resolves, so the collision is missed
            // although the discs overlap (a cause of "0 missed" beside too few collisions).
            const Vec dr0 = dr - h * dv;
            if (norm2(dr0) >= sigma * sigma) {
                const double t_contact = kinematics::time_to_hit(dr0, dv, sigma);
                if (t_contact < h)
                    grazes.push_back(
                        {i, j, contact_point(i, dr0, dv, sigma, t_contact), t_contact});
            }
            return;
        }
        // Reporting only: did the straight paths of this step touch although the check cannot see
        // it? They did if contact falls inside the step and the pair now separates (it went
        // through); a pair touching exactly at the end still approaches and is seen next step.
        if (dot(dv, dr) < 0.0) {
            return;
        }
        const Vec dr0 = dr - h * dv;
        // Overlapping at the start of the step: a graze counted when it went in, or a pair a
        // resolution pushed together; either way not a collision this step stepped over.
        if (norm2(dr0) < sigma * sigma) return;
        const double t_contact = kinematics::time_to_hit(dr0, dv, sigma);
        if (t_contact < h)
            misses.push_back({i, j, contact_point(i, dr0, dv, sigma, t_contact), t_contact});
    });
    // Grid and all-pairs visit pairs in different orders; report misses in id order either way.
    const auto by_ids = [](const Miss& a, const Miss& b) {
        return std::tie(a.i, a.j) < std::tie(b.i, b.j);
    };
    std::sort(misses.begin(), misses.end(), by_ids);
    std::sort(grazes.begin(), grazes.end(), by_ids);
    missed_ += misses.size() + grazes.size();
    if (!misses.empty() && recording_failures() && !step_failed_) {
        // The step's candidates, in id order, as their paths went during the drift: the record
        // takes the first whose discs no contact of the step moved (finish_failure_record).
        for (const Miss& miss : misses) {
            if (step_candidates_.size() == max_step_candidates) break;
            BasicStepFailure<D> failure;
            failure.kind = StepFailureKind::missed_pair;
            failure.step = steps_;
            failure.a = miss.i;
            failure.b = miss.j;
            failure.motion_a = h * velocity_[miss.i];
            failure.motion_b = h * velocity_[miss.j];
            failure.before_a = position_[miss.i] - failure.motion_a;
            failure.before_b = position_[miss.j] - failure.motion_b;
            failure.radius_a = radius_[miss.i];
            failure.radius_b = radius_[miss.j];
            failure.contact = miss.t_contact;
            const double sigma = radius_[miss.i] + radius_[miss.j];
            const Vec dr0 = box_.displacement(failure.before_a, failure.before_b);
            const Vec dv = velocity_[miss.j] - velocity_[miss.i];
            failure.where = failure.before_a + miss.t_contact * velocity_[miss.i] +
                            (radius_[miss.i] / sigma) * (dr0 + miss.t_contact * dv);
            step_candidates_.push_back(failure);
        }
        step_failed_ = true;
    }
    // A disc that stepped over a piece of a barrier (an immovable disc) went through the barrier.
    // A graze turned back out on the side it came from: not a passage.
    for (const Miss& miss : misses) {
        const bool heavy_i = mass_[miss.i] >= immovable_mass_;
        const bool heavy_j = mass_[miss.j] >= immovable_mass_;
        if (heavy_i != heavy_j) through_barrier_[heavy_i ? miss.j : miss.i] = true;
    }
    for (const std::vector<Miss>* list : {&misses, &grazes}) {
        for (const Miss& miss : *list) {
            if (missed_markers_.size() < max_markers_per_frame) {
                missed_markers_.push_back(miss.where);
            }
        }
    }
}

template <int D>
void BasicTimeEngine<D>::detect_wall_contacts(double h) {
    if (box_.boundary != Boundary::walls) {
        return;
    }
    // A disc touches a wall when it straddles the wall's segment (a sphere: the wall's face);
    // one entirely past it does not.
    auto straddles = [](double p, double line, double r) { return p > line - r && p < line + r; };
    auto alongside = [](double q, double extent, double r) { return q > -r && q < extent + r; };
    const auto hits_wall = [&](Vec p, Vec v, double r, int k) {
        for (int m = 0; m < D; ++m) {
            if (m != k && !alongside(axis(p, m), axis(extent_, m), r)) return false;
        }
        const double vk = axis(v, k);
        return (vk < 0.0 && straddles(axis(p, k), 0.0, r)) ||
               (vk > 0.0 && straddles(axis(p, k), axis(extent_, k), r));
    };
    for (std::uint32_t i = 0; i < position_.size(); ++i) {
        const Vec p = position_[i];
        const Vec v = velocity_[i];
        const double r = radius_[i];
        if (recording_failures() && !step_failed_) record_escape(i, h);
        for (int k = 0; k < D; ++k) {  // x, then y (then z): the contacts' order
            if (!hits_wall(p, v, r, k)) continue;
            ++core_.counters().predictions;
            const double pk = axis(p, k);
            const double vk = axis(v, k);
            const double t_contact =
                within_step(kinematics::time_to_wall(pk - h * vk, vk, r, axis(extent_, k)), h);
            contacts_.push_back({t_contact, wall_kind(k), i, 0});
        }
    }
}

// Reporting only: a disc entirely past a wall line now that was not at the start of the step
// went through the wall during it (the checks never saw it straddle the wall).
template <int D>
void BasicTimeEngine<D>::record_escape(std::uint32_t i, double h) {
    const Vec p = position_[i];
    const Vec motion = h * velocity_[i];
    const double r = radius_[i];
    if (!is_outside(p, r) || is_outside(p - motion, r)) return;
    const Vec before = p - motion;
    // When the centre crossed the wall line it ended beyond (the latest such crossing).
    double crossed = 0.0;
    for (int k = 0; k < D; ++k) {
        const double vk = axis(velocity_[i], k);
        const double line = axis(p, k) > axis(extent_, k) ? axis(extent_, k) : 0.0;
        if (vk == 0.0 || (axis(p, k) >= 0.0 && axis(p, k) <= axis(extent_, k))) continue;
        crossed = std::max(crossed, std::clamp((line - axis(before, k)) / vk, 0.0, h));
    }
    BasicStepFailure<D> failure;
    failure.kind = StepFailureKind::left_box;
    failure.step = steps_;
    failure.a = i;
    failure.b = i;
    failure.motion_a = motion;
    failure.motion_b = motion;
    failure.before_a = before;
    failure.before_b = before;
    failure.radius_a = r;
    failure.radius_b = r;
    failure.contact = crossed;
    failure.where = before + crossed * velocity_[i];
    step_candidates_.push_back(failure);
    step_failed_ = true;
}

template <int D>
void BasicTimeEngine<D>::finish_failure_record() {
    if (!step_failed_) return;
    // The clearest failure of the step: one whose discs no contact of the step moved (their
    // state after the step is where the straight move took them), else the first.
    const auto moved = [&](std::uint32_t i) {
        return std::any_of(contacts_.begin(), contacts_.end(), [&](const Contact& c) {
            return c.a == i || (c.kind == CollisionKind::pair && c.b == i);
        });
    };
    const auto clear =
        std::find_if(step_candidates_.begin(), step_candidates_.end(),
                     [&](const BasicStepFailure<D>& f) { return !moved(f.a) && !moved(f.b); });
    BasicStepFailure<D> failure =
        clear != step_candidates_.end() ? *clear : step_candidates_.front();
    failure.after_a = position_[failure.a];
    failure.after_b = position_[failure.b];
    failures_.push_back(failure);
    step_candidates_.clear();
}

template <int D>
void BasicTimeEngine<D>::resolve_contacts(double h) {
    std::sort(contacts_.begin(), contacts_.end(), [](const Contact& x, const Contact& y) {
        return std::tie(x.t_estimate, x.kind, x.a, x.b) < std::tie(y.t_estimate, y.kind, y.a, y.b);
    });
    for (const Contact& contact : contacts_) {
        if (contact.kind == CollisionKind::pair) {
            resolve_pair_contact(contact, h);
        } else {
            resolve_wall_contact(contact, h);
        }
    }
}

template <int D>
void BasicTimeEngine<D>::resolve_pair_contact(const Contact& contact, double h) {
    const std::uint32_t a = contact.a;
    const std::uint32_t b = contact.b;
    const Vec dr = box_.displacement(position_[a], position_[b]);
    const Vec dv = velocity_[b] - velocity_[a];
    const double sigma = radius_[a] + radius_[b];
    // An earlier contact of this step may have separated the pair already.
    if (norm2(dr) >= sigma * sigma || dot(dv, dr) >= 0.0) {
        return;
    }
    ++core_.counters().predictions;
    const double t_contact = within_step(kinematics::time_to_hit(dr - h * dv, dv, sigma), h);
    const double back = h - t_contact;
    move(a, -back * velocity_[a]);
    move(b, -back * velocity_[b]);
    const Vec contact_dr = box_.displacement(position_[a], position_[b]);
    const Vec impulse =
        kinematics::resolve_pair(velocity_[a], velocity_[b], mass_[a], mass_[b], contact_dr);
    core_.counters().impulses.virial += std::fabs(dot(contact_dr, impulse));
    move(a, back * velocity_[a]);
    move(b, back * velocity_[b]);
    core_.collided({step_start_ + t_contact, CollisionKind::pair, a, b});
}

template <int D>
void BasicTimeEngine<D>::resolve_wall_contact(const Contact& contact, double h) {
    const std::uint32_t i = contact.a;
    const int k = static_cast<int>(contact.kind) - static_cast<int>(CollisionKind::xwall);
    const double p = axis(position_[i], k);
    double& v = axis(velocity_[i], k);
    const double extent = axis(extent_, k);
    const double r = radius_[i];
    // Still touching the wall it moves towards? (a pair collision may have turned it round)
    const bool towards_wall =
        (v < 0.0 && p < r && p > -r) || (v > 0.0 && p > extent - r && p < extent + r);
    if (!towards_wall) {
        return;
    }
    ++core_.counters().predictions;
    const double t_contact = within_step(kinematics::time_to_wall(p - h * v, v, r, extent), h);
    const double back = h - t_contact;
    move(i, -back * velocity_[i]);
    core_.counters().impulses.wall_impulse += 2.0 * mass_[i] * std::fabs(v);
    v = -v;
    move(i, back * velocity_[i]);
    core_.collided({step_start_ + t_contact, contact.kind, i, 0});
}

template <int D>
void BasicTimeEngine<D>::wrap_positions() {
    if (box_.boundary != Boundary::periodic) {
        return;
    }
    for (Vec& p : position_) {
        p = box_.wrap(p);
    }
}

// After each advance_to: which pairs overlap now, how deep, and which discs are out of the box.
// Reporting only, so its pair tests are not counted in overlap_checks: they are not the lecture's
// checks, and whatever the detection, a grid finds the overlapping pairs in about O(N).
template <int D>
void BasicTimeEngine<D>::take_census() {
    overlapping_pairs_.clear();
    max_overlap_ = 0.0;
    const auto census_pair = [&](std::uint32_t i, std::uint32_t j) {
        const double sigma = radius_[i] + radius_[j];
        const double depth = sigma - norm(box_.displacement(position_[i], position_[j]));
        if (depth > contact_slack * sigma) {
            overlapping_pairs_.emplace_back(i, j);
            max_overlap_ = std::max(max_overlap_, depth);
        }
    };
    // Cells no smaller than one disc's share of the box, so that tiny discs do not make a grid of
    // mostly empty cells (larger cells only add candidates).
    const double per_particle =
        Space::measure(box_) / static_cast<double>(std::max<std::size_t>(1, position_.size()));
    const double share = D == 2 ? std::sqrt(per_particle) : std::cbrt(per_particle);
    if (grid_->build(box_, position_, std::max(2.0 * max_radius_, share) * cell_margin)) {
        grid_->for_each_pair(census_pair);
    } else {  // a periodic box under three cells wide
        (void)sweep_->find(box_, position_, velocity_, radius_, 0.0, candidates_);
        for (const auto& [i, j] : candidates_) {
            census_pair(i, j);
        }
    }
    std::sort(overlapping_pairs_.begin(), overlapping_pairs_.end());
    overlapped_.resize(position_.size(), false);
    for (const auto& [i, j] : overlapping_pairs_) {
        for (const std::uint32_t k : {i, j}) {
            if (!overlapped_[k]) {
                overlapped_[k] = true;
                ++overlapped_count_;
            }
        }
    }
    // Escaped = entirely past a wall line. A disc whose centre is outside by less than r still
    // touches the wall and is reflected at the next check, so it is not (yet) an escape.
    escaped_count_ = 0;
    tunnelled_count_ = 0;
    for (std::size_t i = 0; i < position_.size(); ++i) {
        escaped_[i] = box_.boundary == Boundary::walls && is_outside(position_[i], radius_[i]);
        if (escaped_[i]) {
            ++escaped_count_;
        }
        if (escaped_[i] || through_barrier_[i]) ++tunnelled_count_;
    }
}

template <int D>
void BasicTimeEngine<D>::validate_state() const {
    for (std::size_t i = 0; i < position_.size(); ++i) {
        bool finite = true;
        for (int k = 0; k < D; ++k) {
            finite = finite && std::isfinite(axis(position_[i], k)) &&
                     std::isfinite(axis(velocity_[i], k));
        }
        if (!finite) {
            throw_runtime_error("time-driven engine: disc " + std::to_string(i) +
                                " has a non-finite state at t = " + std::to_string(time_));
        }
    }
    // Elastic resolutions conserve energy up to rounding (~1e-16 per collision); 1e-9 leaves
    // room for millions of collisions and still catches a wrong impulse at once.
    constexpr double energy_tolerance = 1e-9;
    const double energy = kinetic_energy();
    if (std::fabs(energy - initial_energy_) > energy_tolerance * initial_energy_) {
        throw_runtime_error("time-driven engine: kinetic energy " + std::to_string(energy) +
                            " departs from " + std::to_string(initial_energy_) +
                            " at t = " + std::to_string(time_));
    }
}

template <int D>
bool BasicTimeEngine<D>::is_outside(Vec p, double r) const noexcept {
    bool outside = false;
    for (int k = 0; k < D; ++k) {
        outside = outside || axis(p, k) <= -r || axis(p, k) >= axis(extent_, k) + r;
    }
    return outside;
}

template <int D>
double BasicTimeEngine<D>::max_speed() const noexcept {
    double v2 = 0.0;
    for (const Vec& v : velocity_) {
        v2 = std::max(v2, norm2(v));
    }
    return std::sqrt(v2);
}

template <int D>
std::uint64_t BasicTimeEngine<D>::bytes() const noexcept {
    auto held = [](const auto& v) {
        return static_cast<std::uint64_t>(v.capacity() *
                                          sizeof(typename std::decay_t<decltype(v)>::value_type));
    };
    return held(position_) + held(velocity_) + held(displacement_) + held(radius_) + held(mass_) +
           (escaped_.capacity() + through_barrier_.capacity()) / 8 + overlapped_.capacity() / 8 +
           held(contacts_) + held(overlapping_pairs_) + held(missed_markers_) + held(candidates_) +
           grid_->bytes() + sweep_->bytes() + core_.bytes();
}

template <int D>
double BasicTimeEngine<D>::kinetic_energy() const noexcept {
    double e = 0.0;
    for (std::size_t i = 0; i < velocity_.size(); ++i) {
        e += 0.5 * mass_[i] * norm2(velocity_[i]);
    }
    return e;
}

template <int D>
SnapshotOf<D> BasicTimeEngine<D>::snapshot() const {
    SnapshotOf<D> snap = core_.start_snapshot(time_);
    for (std::size_t i = 0; i < position_.size(); ++i) {
        auto& d = [&]() -> auto& {
            if constexpr (D == 2) {
                return snap.discs[i];
            } else {
                return snap.spheres[i];
            }
        }
        ();
        BasicEngineCore<D>::set_motion(d, position_[i], velocity_[i], radius_[i], mass_[i]);
        d.escaped = escaped_[i];
        d.tunnelled = through_barrier_[i];
    }
    snap.overlapping_pairs = overlapping_pairs_;
    snap.missed_collisions = missed_markers_;
    return snap;
}

template <int D>
Measurements BasicTimeEngine<D>::measurements() const {
    Measurements m = core_.measurements(time_, velocity_, mass_, radius_, bytes());
    m.max_overlap = max_overlap_;
    m.msd = core_.mean_squared_displacement(displacement_.size(), [this](std::size_t i) {
        return std::pair{i, displacement_[i]};
    });
    m.steps = steps_;
    m.max_overlap_seen = max_overlap_seen_;
    m.seconds_per_time_unit = time_ > 0.0 ? m.wall_seconds / time_ : 0.0;
    m.overlap_checks = overlap_checks_;
    m.missed_collisions = missed_;
    m.escaped = escaped_count_;
    m.tunnelled = tunnelled_count_;
    m.discs_overlapped = overlapped_count_;
    m.overlapping_pairs = overlapping_pairs_.size();
    m.energy_drift =
        initial_energy_ > 0.0 ? (m.kinetic_energy - initial_energy_) / initial_energy_ : 0.0;
    return m;
}

template class BasicTimeEngine<2>;
template class BasicTimeEngine<3>;

}  // namespace collide::sim
