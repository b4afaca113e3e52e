#pragma once
/// \file
/// The lecture's event-driven main loop, written as taught (algs4's CollisionSystem, with its
/// faults fixed): fill a priority queue with every potential event; pop the earliest; skip it if
/// a disc involved has collided since it was predicted (lazy invalidation by collision counts);
/// advance every disc to its time; resolve; predict the colliding discs against all others.
/// O(N) per event and a queue that fills with stale events: it exists for teaching and as the
/// test oracle of the fast engine. A template over the queue type, so that every queue of the
/// priority-queue lecture can drive it (the strict event order makes them all agree exactly).

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "collide/scene.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/engine_support.hpp"
#include "collide/sim/event.hpp"
#include "collide/sim/kinematics.hpp"
#include "collide/sim/observables.hpp"
#include "collide/sim/queue_view.hpp"

namespace collide::sim {

/// Queue: a min-queue of sim::Event ordered by sim::EventLess with push(Event), pop() -> Event,
/// top(), empty() and size() (e.g. pq::DaryHeap<Event, Orientation::min, 2, EventLess>).
template <class Queue>
class ClassicEngine final : public Engine {
  public:
    /// Copies the scene (validated by the caller): O(N). The first advance_to() predicts every
    /// initial event: O(N^2) time, O(number of predicted events) memory.
    explicit ClassicEngine(const Scene& scene, Queue queue = Queue{})
        : box_(scene.box), appearance_(scene), queue_(std::move(queue)) {
        const std::size_t n = scene.discs.size();
        px_.reserve(n);
        py_.reserve(n);
        vx_.reserve(n);
        vy_.reserve(n);
        start_.reserve(n);
        radius_.reserve(n);
        mass_.reserve(n);
        for (const Disc& d : scene.discs) {
            px_.push_back(d.position.x);
            py_.push_back(d.position.y);
            vx_.push_back(d.velocity.x);
            vy_.push_back(d.velocity.y);
            start_.push_back(d.position);
            radius_.push_back(d.radius);
            mass_.push_back(d.mass);
        }
        count_.assign(n, 0);
        last_partner_.assign(n, no_disc);
        instant_t_.assign(n, 0.0);
        instant_collisions_.assign(n, 0);
        instant_limit_ = instant_collision_limit(n);
    }

    void advance_to(double t) override {
        require_forward(now_, t);
        WallClock clock(wall_seconds_);
        predict_initial_events();
        while (!queue_.empty() && queue_.top().t <= t) {
            poll_stop();
            const Event e = queue_.pop();
            ++stats_.pops;
            const bool valid = is_valid(e);
            if (watch_.on()) watch_.record_pop(queued(e, !valid));
            if (!valid) {
                ++stats_.stale_pops;
                continue;
            }
            move_all_to(e.t);
            resolve(e);
            predict(e.a, 0);
            if (e.kind == EventKind::pair) predict(e.b, 0);
        }
        move_all_to(t);
    }

    [[nodiscard]] double time() const noexcept override { return now_; }

    [[nodiscard]] Snapshot snapshot() const override {
        Snapshot s;
        s.time = now_;
        s.box = box_;
        s.discs.reserve(px_.size());
        for (std::size_t i = 0; i < px_.size(); ++i) {
            DiscState d;
            d.position = box_.wrap(position(i));
            d.velocity = velocity(i);
            d.radius = radius_[i];
            d.mass = mass_[i];
            d.color = appearance_.colors[i];
            d.tagged = appearance_.tagged[i] != 0;
            s.discs.push_back(d);
        }
        if (watch_.on()) s.queue = queue_view();
        return s;
    }

    bool watch_queue(std::size_t next_events) override {
        watch_.start(next_events);
        return true;
    }

    [[nodiscard]] Measurements measurements() const override {
        Measurements m;
        m.t = now_;
        m.events = collisions_pair_ + collisions_xwall_ + collisions_ywall_;
        m.collisions_pair = collisions_pair_;
        m.collisions_xwall = collisions_xwall_;
        m.collisions_ywall = collisions_ywall_;
        m.collisions_wall = collisions_xwall_ + collisions_ywall_;
        m.predictions = predictions_;
        m.queue = stats_;
        std::vector<Vec2> positions(px_.size());
        std::vector<Vec2> velocities(px_.size());
        for (std::size_t i = 0; i < px_.size(); ++i) {
            positions[i] = position(i);
            velocities[i] = velocity(i);
        }
        fill_thermodynamics(m, velocities, mass_, radius_, box_, tally_);
        m.max_overlap = max_overlap(positions, radius_, box_);
        m.msd = mean_squared_displacement();
        m.wall_seconds = wall_seconds_;
        if (wall_seconds_ > 0.0) {
            m.collisions_per_second =
                static_cast<double>(m.collisions_pair + m.collisions_wall) / wall_seconds_;
        }
        m.engine_bytes = bytes();
        return m;
    }

    void set_collision_listener(CollisionListener listener) override {
        listener_ = std::move(listener);
    }

    /// The queue, for teaching traces and queue statistics.
    [[nodiscard]] const Queue& queue() const noexcept { return queue_; }

  private:
    [[nodiscard]] Vec2 position(std::size_t i) const noexcept { return {px_[i], py_[i]}; }
    [[nodiscard]] Vec2 velocity(std::size_t i) const noexcept { return {vx_[i], vy_[i]}; }
    void set_velocity(std::size_t i, Vec2 v) noexcept {
        vx_[i] = v.x;
        vy_[i] = v.y;
    }

    /// The queue as it stands (see Engine::watch_queue): O(entries).
    [[nodiscard]] QueueView queue_view() const {
        QueueView view;
        describe_queue(
            queue_, watch_.next_events(), [this](const Event& e) { return !is_valid(e); }, view);
        view.popped = watch_.popped();
        view.pops = stats_.pops;
        view.stale_pops = stats_.stale_pops;
        return view;
    }

    /// Predicts each pair once (j > i), row by row, looking at the stop flag before each row.
    /// Why here and not in the constructor: the flag is set after construction, and at 10^6 discs
    /// this is 5 10^11 pair tests (hours), which Ctrl-C must still stop. A stopped run resumes at
    /// the row it stopped before, so the queue ends up the same.
    void predict_initial_events() {
        const auto n = static_cast<std::uint32_t>(px_.size());
        for (; initial_rows_ < n; ++initial_rows_) {
            check_stop();  // one look per row of n - i tests: nothing next to the row's cost
            predict(initial_rows_, initial_rows_ + 1);
        }
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
            const std::size_t n = px_.size();
            for (std::size_t i = 0; i < n; ++i) px_[i] += dt * vx_[i];
            for (std::size_t i = 0; i < n; ++i) py_[i] += dt * vy_[i];
        }
        now_ = t;
    }

    void push(Event e) {
        queue_.push(e);
        ++stats_.pushes;
        stats_.max_size = std::max<std::uint64_t>(stats_.max_size, queue_.size());
    }

    /// Predicts disc i against the walls and against discs first..N-1 (except itself).
    void predict(std::uint32_t i, std::uint32_t first) {
        const auto n = static_cast<std::uint32_t>(px_.size());
        const Vec2 pi = position(i);
        const Vec2 vi = velocity(i);
        const double ri = radius_[i];
        const bool periodic = box_.boundary == Boundary::periodic;
        predictions_ += n - first - (first <= i ? 1 : 0);
        if (periodic) {
            for (std::uint32_t j = first; j < n; ++j) {
                if (j != i) offer_pair(i, j, time_to_hit(i, j));
            }
        } else {
            // Pass 1, branch-free so the compiler vectorises it: which pairs can meet at all
            // (approaching, and either overlapping or with d >= 0). Most pairs cannot; pass 2
            // runs the lecture's kernel on the few that can, so the times are exactly the kernel's.
            may_hit_.resize(n);
            // Plain pointers and flags stored as doubles: a byte store could alias the doubles,
            // and a double select vectorises where a bool-to-integer conversion does not.
            const double* x = px_.data();
            const double* y = py_.data();
            const double* vx = vx_.data();
            const double* vy = vy_.data();
            const double* r = radius_.data();
            double* flag = may_hit_.data();
            for (std::size_t j = first; j < n; ++j) {
                const double dx = x[j] - pi.x;
                const double dy = y[j] - pi.y;
                const double dvx = vx[j] - vi.x;
                const double dvy = vy[j] - vi.y;
                const double b = dx * dvx + dy * dvy;
                const double sigma = ri + r[j];
                const double c = dx * dx + dy * dy - sigma * sigma;
                const double d = b * b - (dvx * dvx + dvy * dvy) * c;
                flag[j] = (b < 0.0) & ((c <= 0.0) | (d >= 0.0)) ? 1.0 : 0.0;
            }
            may_hit_[i] = 0.0;
            for (std::uint32_t j = first; j < n; ++j) {
                if (may_hit_[j] == 0.0) continue;
                const Vec2 dr = position(j) - pi;
                const double sigma = ri + radius_[j];
                if (just_collided(i, j, dr, sigma)) continue;
                offer_pair(i, j, kinematics::time_to_hit(dr, velocity(j) - vi, sigma));
            }
        }
        if (periodic) return;
        const double tx = kinematics::time_to_wall(pi.x, vi.x, ri, box_.width);
        const double ty = kinematics::time_to_wall(pi.y, vi.y, ri, box_.height);
        predictions_ += 2;
        if (tx != kinematics::never)
            push(Event{now_ + tx, EventKind::xwall, i, no_disc, count_[i], 0});
        if (ty != kinematics::never)
            push(Event{now_ + ty, EventKind::ywall, i, no_disc, count_[i], 0});
    }

    void offer_pair(std::uint32_t i, std::uint32_t j, double dt) {
        if (dt == kinematics::never) return;
        const std::uint32_t a = std::min(i, j);
        const std::uint32_t b = std::max(i, j);
        push(Event{now_ + dt, EventKind::pair, a, b, count_[a], count_[b]});
    }

    /// Time until i and j touch. Periodic boxes try the nine nearest images of j, so a pair
    /// meeting across the seam is found even when another image is nearer now.
    [[nodiscard]] double time_to_hit(std::uint32_t i, std::uint32_t j) const noexcept {
        const double sigma = radius_[i] + radius_[j];
        const Vec2 dr = box_.displacement(position(i), position(j));
        const Vec2 dv = velocity(j) - velocity(i);
        if (just_collided(i, j, dr, sigma)) return kinematics::never;
        if (box_.boundary != Boundary::periodic) return kinematics::time_to_hit(dr, dv, sigma);
        double best = kinematics::never;
        for (int ky = -1; ky <= 1; ++ky) {
            for (int kx = -1; kx <= 1; ++kx) {
                const Vec2 image{dr.x + kx * box_.width, dr.y + ky * box_.height};
                best = std::min(best, kinematics::time_to_hit(image, dv, sigma));
            }
        }
        return best;
    }

    /// See sim::just_collided_slack: a pair still touching after colliding with each other.
    [[nodiscard]] bool just_collided(std::uint32_t i, std::uint32_t j, Vec2 dr,
                                     double sigma) const noexcept {
        if (last_partner_[i] != j || last_partner_[j] != i) return false;
        const double reach = sigma * (1.0 + just_collided_slack);
        return norm2(dr) < reach * reach;
    }

    /// Counts a collision of disc i at now_ and throws when i is jammed (see
    /// sim::instant_collision_limit): a wedged disc would otherwise collide at this instant
    /// forever while the queue grows by N events per collision.
    void count_collision_now(std::uint32_t i) {
        if (!same_instant(now_ - instant_t_[i], velocity(i), radius_[i]))
            instant_collisions_[i] = 0;
        instant_t_[i] = now_;
        if (++instant_collisions_[i] > instant_limit_) throw_jammed(i, now_, instant_limit_);
    }

    void resolve(const Event& e) {
        const std::uint32_t a = e.a;
        count_collision_now(a);
        if (e.kind == EventKind::pair) count_collision_now(e.b);
        switch (e.kind) {
            case EventKind::pair: {
                const std::uint32_t b = e.b;
                const Vec2 dr = box_.displacement(position(a), position(b));
                Vec2 va = velocity(a);
                Vec2 vb = velocity(b);
                const Vec2 impulse = kinematics::resolve_pair(va, vb, mass_[a], mass_[b], dr);
                set_velocity(a, va);
                set_velocity(b, vb);
                tally_.virial += std::abs(dot(dr, impulse));
                ++count_[b];
                last_partner_[a] = b;
                last_partner_[b] = a;
                ++collisions_pair_;
                break;
            }
            case EventKind::xwall:
                tally_.wall_impulse += 2.0 * mass_[a] * std::abs(vx_[a]);
                vx_[a] = -vx_[a];
                last_partner_[a] = no_disc;
                ++collisions_xwall_;
                break;
            case EventKind::ywall:
                tally_.wall_impulse += 2.0 * mass_[a] * std::abs(vy_[a]);
                vy_[a] = -vy_[a];
                last_partner_[a] = no_disc;
                ++collisions_ywall_;
                break;
            case EventKind::cell:
                break;
        }
        ++count_[a];
        if (listener_) listener_(to_record(e.t, e.kind, e.a, e.b));
    }

    [[nodiscard]] double mean_squared_displacement() const {
        double sum = 0.0;
        std::size_t counted = 0;
        for (std::size_t i = 0; i < px_.size(); ++i) {
            if (!appearance_.in_msd(i)) continue;
            sum += norm2(position(i) - start_[i]);
            ++counted;
        }
        return counted > 0 ? sum / static_cast<double>(counted) : 0.0;
    }

    [[nodiscard]] std::uint64_t bytes() const noexcept {
        const std::size_t vecs =
            (px_.capacity() + py_.capacity() + vx_.capacity() + vy_.capacity()) * sizeof(double) +
            start_.capacity() * sizeof(Vec2);
        const std::size_t scalars =
            (radius_.capacity() + mass_.capacity()) * sizeof(double) +
            (count_.capacity() + last_partner_.capacity() + instant_collisions_.capacity()) *
                sizeof(std::uint32_t) +
            instant_t_.capacity() * sizeof(double);
        // The queue's own storage is not visible through its interface; count its entries.
        return vecs + scalars + appearance_.bytes() + stats_.max_size * sizeof(Event);
    }

    Box box_;
    Appearance appearance_;
    Queue queue_;
    double now_ = 0.0;
    // Positions (unwrapped in periodic boxes, for the displacement) and velocities, one array
    // per component so that the O(N) loops over partners vectorise.
    std::vector<double> px_, py_;
    std::vector<double> vx_, vy_;
    std::vector<double> radius_;
    std::vector<double> mass_;
    std::vector<Vec2> start_;                  ///< positions at t = 0 (mean squared displacement)
    std::vector<std::uint32_t> count_;         ///< collisions per disc (lazy invalidation)
    std::vector<std::uint32_t> last_partner_;  ///< see just_collided
    std::vector<double> may_hit_;              ///< scratch of predict (no allocation per event)
    std::vector<double> instant_t_;            ///< time of each disc's latest collision
    std::vector<std::uint32_t> instant_collisions_;  ///< collisions of each disc in its instant
    std::uint64_t instant_limit_ = 0;                ///< see count_collision_now
    std::uint32_t initial_rows_ = 0;                 ///< see predict_initial_events
    QueueStats stats_;
    ImpulseTally tally_;
    std::uint64_t collisions_pair_ = 0;
    std::uint64_t collisions_xwall_ = 0;
    std::uint64_t collisions_ywall_ = 0;
    std::uint64_t predictions_ = 0;
    double wall_seconds_ = 0.0;
    CollisionListener listener_;
    QueueWatch watch_;  ///< off unless a teaching video asked for the queue (watch_queue)
};

}  // namespace collide::sim
