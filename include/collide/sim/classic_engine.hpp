#pragma once
/// \file
/// The lecture's event-driven main loop, written as taught (algs4's CollisionSystem, with its
/// faults fixed): fill a priority queue with every potential event; pop the earliest; skip it if
/// a disc involved has collided since it was predicted (lazy invalidation by collision counts);
/// advance every disc to its time; resolve; predict the colliding discs against all others.
/// O(N) per event and a queue that fills with stale events: it exists for teaching and as the
/// test oracle of the fast engine. A template over the queue type, so that every queue of the
/// priority-queue lecture can drive it (the strict event order makes them all agree exactly).
///
/// One code for discs and spheres: BasicClassicEngine<D, Queue> is a template over the dimension
/// (its Space: vector, box, scene); a wall event per axis (zwall in 3D) and, in a periodic box,
/// the 3^D nearest images of a partner. ClassicEngine<Queue> is the 2D engine (discs),
/// ClassicSphereEngine<Queue> the 3D one.

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "collide/scene.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/engine_core.hpp"
#include "collide/sim/engine_support.hpp"
#include "collide/sim/event.hpp"
#include "collide/sim/kinematics.hpp"
#include "collide/sim/observables.hpp"
#include "collide/sim/queue_view.hpp"
#include "collide/space.hpp"

namespace collide::sim {

/// Queue: a min-queue of sim::Event ordered by sim::EventLess with push(Event), pop() -> Event,
/// top(), empty() and size() (e.g. pq::DaryHeap<Event, Orientation::min, 2, EventLess>).
template <int D, class Queue>
class BasicClassicEngine final : public EngineOf<D> {
  public:
    using Space = collide::Space<D>;
    using Vec = typename Space::Vec;
    using BoxType = typename Space::Box;
    using SceneType = typename Space::Scene;

    /// Copies the scene (validated by the caller): O(N). The first advance_to() predicts every
    /// initial event: O(N^2) time, O(number of predicted events) memory.
    explicit BasicClassicEngine(const SceneType& scene, Queue queue = Queue{})
        : core_(scene),
          box_(scene.box),
          extent_(Space::extent(scene.box)),
          queue_(std::move(queue)) {
        const auto& particles = Space::particles(scene);
        const std::size_t n = particles.size();
        position_.reserve(n);
        velocity_.reserve(n);
        radius_.reserve(n);
        mass_.reserve(n);
        for (const auto& d : particles) {
            position_.push_back(d.position);
            velocity_.push_back(d.velocity);
            radius_.push_back(d.radius);
            mass_.push_back(d.mass);
        }
        start_ = position_;
        count_.assign(n, 0);
        last_partner_.assign(n, no_disc);
        instant_t_.assign(n, 0.0);
        instant_collisions_.assign(n, 0);
        instant_limit_ = instant_collision_limit(n);
    }

    /// The lecture's loop: take the earliest event; skip it if stale; move everyone to its time;
    /// bounce; predict the discs that bounced anew.
    void advance_to(double t) override {
        const WallClock clock = core_.start_advance(now_, t);
        predict_initial_events();
        while (!queue_.empty() && queue_.top().t <= t) {
            this->poll_stop();
            const Event e = queue_.pop();
            if (!accept(e)) continue;
            move_all_to(e.t);
            if (e.kind == EventKind::pair) {
                bounce_off(e.a, e.b);
                predict(e.a);
                predict(e.b);
            } else {
                bounce_off_wall(e.a, wall_axis(e.kind));
                predict(e.a);
            }
        }
        move_all_to(t);
    }

    [[nodiscard]] double time() const noexcept override { return now_; }

    [[nodiscard]] SnapshotOf<D> snapshot() const override {
        SnapshotOf<D> s = core_.start_snapshot(now_);
        for (std::size_t i = 0; i < position_.size(); ++i) {
            auto& out = [&]() -> auto& {
                if constexpr (D == 2) {
                    return s.discs[i];
                } else {
                    return s.spheres[i];
                }
            }
            ();
            BasicEngineCore<D>::set_motion(out, box_.wrap(position_[i]), velocity_[i], radius_[i],
                                           mass_[i]);
        }
        if constexpr (D == 2) {
            if (watch_.on()) s.queue = queue_view();
        }
        return s;
    }

    bool watch_queue(const QueueViewLimits& limits) override {
        watch_.start(limits);
        return true;
    }

    [[nodiscard]] Measurements measurements() const override {
        Measurements m = core_.measurements(now_, velocity_, mass_, radius_, bytes());
        m.max_overlap = max_overlap(position_, radius_, box_);
        m.msd = core_.mean_squared_displacement(position_.size(), [this](std::size_t i) {
            return std::pair{i, position_[i] - start_[i]};
        });
        return m;
    }

    void set_collision_listener(CollisionListener listener) override {
        core_.set_listener(std::move(listener));
    }

    /// See Engine::clone: every member is a value (the queue included), so a member-wise copy
    /// is the engine as it stands; only the listener is dropped.
    [[nodiscard]] std::unique_ptr<EngineOf<D>> clone() const override {
        std::unique_ptr<BasicClassicEngine> copy(new BasicClassicEngine(*this));
        copy->set_collision_listener(nullptr);
        return copy;
    }

    /// The queue, for teaching traces and queue statistics.
    [[nodiscard]] const Queue& queue() const noexcept { return queue_; }

  private:
    /// Through clone() only (it drops the listener a plain copy would share).
    BasicClassicEngine(const BasicClassicEngine&) = default;

    [[nodiscard]] QueueStats& stats() noexcept { return core_.counters().queue; }

    /// The queue as it stands (see Engine::watch_queue): O(entries).
    [[nodiscard]] QueueView queue_view() const {
        QueueView view;
        describe_queue(
            queue_, watch_.limits(), [this](const Event& e) { return !is_valid(e); }, view);
        view.popped = watch_.popped();
        view.pops = core_.counters().queue.pops;
        view.stale_pops = core_.counters().queue.stale_pops;
        return view;
    }

    /// Predicts each pair once (j > i), row by row, looking at the stop flag before each row.
    /// Why here and not in the constructor: the flag is set after construction, and at 10^6 discs
    /// this is 5 10^11 pair tests (hours), which Ctrl-C must still stop. A stopped run resumes at
    /// the row it stopped before, so the queue ends up the same.
    void predict_initial_events() {
        const auto n = static_cast<std::uint32_t>(position_.size());
        for (; initial_rows_ < n; ++initial_rows_) {
            this->check_stop();  // one look per row of n - i tests: nothing next to the row's cost
            predict_row(initial_rows_);
        }
    }

    /// The stale check of a popped event and its bookkeeping: counts the pop (and the stale
    /// ones), shows it to a watching queue picture, and says whether the event still holds.
    [[nodiscard]] bool accept(const Event& e) {
        ++stats().pops;
        const bool valid = is_valid(e);
        if (watch_.on()) watch_.record_pop(queued(e, !valid));
        if (!valid) ++stats().stale_pops;
        return valid;
    }

    /// Valid when neither disc has collided since the event was predicted.
    [[nodiscard]] bool is_valid(const Event& e) const noexcept {
        if (count_[e.a] != e.count_a) return false;
        return e.kind != EventKind::pair || count_[e.b] == e.count_b;
    }

    /// "Advance every disc to t": the O(N) step the fast engine's local clocks avoid.
    void move_all_to(double t) {
        const double dt = t - now_;
        if (dt > 0.0) {
            for (std::size_t i = 0; i < position_.size(); ++i) position_[i] += dt * velocity_[i];
        }
        now_ = t;
    }

    void push(Event e) {
        queue_.push(e);
        ++stats().pushes;
        stats().max_size = std::max<std::uint64_t>(stats().max_size, queue_.size());
    }

    /// The lecture's prediction: disc i against every other disc, then against the walls; every
    /// event that will happen goes into the queue. O(N).
    void predict(std::uint32_t i) {
        predict_pairs(i, 0);
        predict_walls(i);
    }

    /// Row i of the initial triangle: disc i against the discs after it (so that each pair is
    /// predicted once), then against the walls.
    void predict_row(std::uint32_t i) {
        predict_pairs(i, i + 1);
        predict_walls(i);
    }

    /// Disc i against every disc j from `first` on, except itself.
    void predict_pairs(std::uint32_t i, std::uint32_t first) {
        const auto n = static_cast<std::uint32_t>(position_.size());
        core_.counters().predictions += n - first - (first <= i ? 1 : 0);
        const bool periodic = box_.boundary == Boundary::periodic;
        for (std::uint32_t j = first; j < n; ++j) {
            if (j == i) continue;
            const double dt = periodic ? time_to_hit_nearest_image(i, j) : time_to_hit(i, j);
            if (dt == kinematics::never) continue;
            const std::uint32_t a = std::min(i, j);
            const std::uint32_t b = std::max(i, j);
            push(Event{now_ + dt, EventKind::pair, a, b, count_[a], count_[b]});
        }
    }

    /// The wall event of each axis (0 x, 1 y, 2 z) and back.
    [[nodiscard]] static constexpr EventKind wall_kind(int axis) noexcept {
        return static_cast<EventKind>(static_cast<int>(EventKind::xwall) + axis);
    }
    [[nodiscard]] static constexpr int wall_axis(EventKind kind) noexcept {
        return static_cast<int>(kind) - static_cast<int>(EventKind::xwall);
    }

    /// Disc i against the walls of each axis in turn (none in a periodic box).
    void predict_walls(std::uint32_t i) {
        if (box_.boundary == Boundary::periodic) return;
        std::array<double, D> t{};
        for (int k = 0; k < D; ++k) {
            t[k] = kinematics::time_to_wall(axis(position_[i], k), axis(velocity_[i], k),
                                            radius_[i], axis(extent_, k));
        }
        core_.counters().predictions += D;
        for (int k = 0; k < D; ++k) {
            if (t[k] != kinematics::never)
                push(Event{now_ + t[k], wall_kind(k), i, no_disc, count_[i], 0});
        }
    }

    /// Time until i and j touch in a walled box (kinematics::time_to_hit), or never for a pair
    /// that has just collided with each other.
    [[nodiscard]] double time_to_hit(std::uint32_t i, std::uint32_t j) const noexcept {
        const Vec dr = position_[j] - position_[i];
        const double sigma = radius_[i] + radius_[j];
        if (just_collided(i, j, dr, sigma)) return kinematics::never;
        return kinematics::time_to_hit(dr, velocity_[j] - velocity_[i], sigma);
    }

    /// time_to_hit in a periodic box: the earliest of the 3^D nearest images of j, so that a
    /// pair meeting across the seam is found even when another image is nearer now. A pair that
    /// has just collided skips only the image it still touches: in a small box (a few diameters
    /// across) it can meet again through another image before either hits anything else, and
    /// nothing would predict that meeting later (the classic loop predicts a disc only after its
    /// own collisions).
    [[nodiscard]] double time_to_hit_nearest_image(std::uint32_t i,
                                                   std::uint32_t j) const noexcept {
        const double sigma = radius_[i] + radius_[j];
        const Vec dr = box_.displacement(position_[i], position_[j]);
        const bool after_contact = just_collided(i, j, dr, sigma);
        const Vec dv = velocity_[j] - velocity_[i];
        double best = kinematics::never;
        const auto consider = [&](Vec image) {
            if (after_contact && just_collided(i, j, image, sigma)) return;
            best = std::min(best, kinematics::time_to_hit(image, dv, sigma));
        };
        if constexpr (D == 2) {
            for (int ky = -1; ky <= 1; ++ky) {
                for (int kx = -1; kx <= 1; ++kx) {
                    consider(Vec2{dr.x + kx * box_.width, dr.y + ky * box_.height});
                }
            }
        } else {
            for (int kz = -1; kz <= 1; ++kz) {
                for (int ky = -1; ky <= 1; ++ky) {
                    for (int kx = -1; kx <= 1; ++kx) {
                        consider(Vec3{dr.x + kx * box_.width, dr.y + ky * box_.height,
                                      dr.z + kz * box_.depth});
                    }
                }
            }
        }
        return best;
    }

    /// See sim::just_collided_slack: a pair still touching after colliding with each other.
    [[nodiscard]] bool just_collided(std::uint32_t i, std::uint32_t j, Vec dr,
                                     double sigma) const noexcept {
        if (last_partner_[i] != j || last_partner_[j] != i) return false;
        const double reach = sigma * (1.0 + just_collided_slack);
        return norm2(dr) < reach * reach;
    }

    /// Counts a collision of disc i at now_ and throws when i is jammed (see
    /// sim::instant_collision_limit): a wedged disc would otherwise collide at this instant
    /// forever while the queue grows by N events per collision.
    void count_collision_now(std::uint32_t i) {
        if (!same_instant(now_ - instant_t_[i], velocity_[i], radius_[i]))
            instant_collisions_[i] = 0;
        instant_t_[i] = now_;
        if (++instant_collisions_[i] > instant_limit_) throw_jammed(i, now_, instant_limit_);
    }

    /// Discs a and b touch: an elastic collision along the line of centres (nearest image).
    void bounce_off(std::uint32_t a, std::uint32_t b) {
        count_collision_now(a);
        count_collision_now(b);
        const Vec dr = box_.displacement(position_[a], position_[b]);
        const Vec impulse =
            kinematics::resolve_pair(velocity_[a], velocity_[b], mass_[a], mass_[b], dr);
        last_partner_[a] = b;
        last_partner_[b] = a;
        collided(EventKind::pair, a, b, std::abs(dot(dr, impulse)));
    }

    /// Disc a touches a wall across axis k (0: left or right, 1: bottom or top, 2: front or
    /// back): that velocity component reverses.
    void bounce_off_wall(std::uint32_t a, int k) {
        count_collision_now(a);
        double& v = axis(velocity_[a], k);
        const double impulse = 2.0 * mass_[a] * std::abs(v);
        v = -v;
        last_partner_[a] = no_disc;
        collided(wall_kind(k), a, no_disc, impulse);
    }

    /// The bookkeeping of every collision at now_, in one place: the pressure tally (pairs: the
    /// virial |dr . J|; walls: the impulse 2 m |v| the wall takes), the collision counts that make
    /// older predictions stale, and the record for the counters and the listener.
    void collided(EventKind kind, std::uint32_t a, std::uint32_t b, double impulse) {
        ImpulseTally& impulses = core_.counters().impulses;
        if (kind == EventKind::pair) {
            impulses.virial += impulse;
            ++count_[b];
        } else {
            impulses.wall_impulse += impulse;
        }
        ++count_[a];
        core_.collided(to_record(now_, kind, a, b));
    }

    [[nodiscard]] std::uint64_t bytes() const noexcept {
        const std::size_t vecs =
            (position_.capacity() + velocity_.capacity() + start_.capacity()) * sizeof(Vec);
        const std::size_t scalars =
            (radius_.capacity() + mass_.capacity() + instant_t_.capacity()) * sizeof(double) +
            (count_.capacity() + last_partner_.capacity() + instant_collisions_.capacity()) *
                sizeof(std::uint32_t);
        // The queue's own storage is not visible through its interface; count its entries.
        return vecs + scalars + core_.bytes() + core_.counters().queue.max_size * sizeof(Event);
    }

    BasicEngineCore<D> core_;
    BoxType box_;
    Vec extent_;  ///< the box's sides (width, height[, depth])
    Queue queue_;
    double now_ = 0.0;
    // Positions (unwrapped in periodic boxes, for the displacement) and velocities.
    std::vector<Vec> position_;
    std::vector<Vec> velocity_;
    std::vector<double> radius_;
    std::vector<double> mass_;
    std::vector<Vec> start_;                   ///< positions at t = 0 (mean squared displacement)
    std::vector<std::uint32_t> count_;         ///< collisions per disc (lazy invalidation)
    std::vector<std::uint32_t> last_partner_;  ///< see just_collided
    std::vector<double> instant_t_;            ///< time of each disc's latest collision
    std::vector<std::uint32_t> instant_collisions_;  ///< collisions of each disc in its instant
    std::uint64_t instant_limit_ = 0;                ///< see count_collision_now
    std::uint32_t initial_rows_ = 0;                 ///< see predict_initial_events
    QueueWatch watch_;  ///< off unless a teaching video asked for the queue (watch_queue)
};

/// The lecture's loop on discs (`--engine classic`).
template <class Queue>
using ClassicEngine = BasicClassicEngine<2, Queue>;
/// The lecture's loop on spheres (3D scenes).
template <class Queue>
using ClassicSphereEngine = BasicClassicEngine<3, Queue>;

}  // namespace collide::sim
