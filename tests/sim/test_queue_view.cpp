// The engines' queue view (Engine::watch_queue -> Snapshot::queue, sim/queue_view.hpp): what
// `collide render --queue` draws must be what the engine will do next, for every queue kind of
// the classic loop and for the fast engine, and watching must not change the simulation.
#include <doctest/doctest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "collide/error.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/queue_view.hpp"
#include "scene_fixtures.hpp"

namespace collide {
namespace {

using test::lattice_fluid;

/// A picture budget for these tests (a video's is show::queue_picture): the next `k` events,
/// a heap down to the deepest level of at most 8 nodes and at most 3 levels, 10 array slots.
QueueViewLimits picture(std::size_t k) {
    return {k, 8, 3, 10};
}

EngineOptions classic_with(const std::string& pq) {
    EngineOptions o;
    o.engine = EngineKind::classic;
    o.pq = pq::parse_queue_kind(pq);
    return o;
}

EngineOptions fast() {
    EngineOptions o;
    o.engine = EngineKind::fast;
    return o;
}

/// A walled box of 36 discs: walls and pairs both happen often.
Scene walled_gas() {
    return lattice_fluid(6, 0.2, Boundary::walls, 7, 0.05);
}

std::vector<CollisionRecord> events_until(Engine& engine, double t) {
    std::vector<CollisionRecord> log;
    engine.set_collision_listener([&](const CollisionRecord& r) { log.push_back(r); });
    engine.advance_to(t);
    engine.set_collision_listener({});
    return log;
}

bool same_collision(const QueuedEvent& e, const CollisionRecord& r) {
    const bool kind = (e.kind == EventKind::pair && r.kind == CollisionKind::pair) ||
                      (e.kind == EventKind::xwall && r.kind == CollisionKind::xwall) ||
                      (e.kind == EventKind::ywall && r.kind == CollisionKind::ywall);
    return kind && e.t == r.t && e.a == r.a && (e.kind != EventKind::pair || e.b == r.b);
}

const std::vector<EngineOptions> every_queue = {classic_with("binary"),
                                                classic_with("dary:3"),
                                                classic_with("dary:4"),
                                                classic_with("indexed"),
                                                classic_with("ordered"),
                                                classic_with("unordered"),
                                                fast()};

TEST_CASE("queue view: no view unless asked for, and the time-driven engine has no queue") {
    const Scene scene = walled_gas();
    for (const EngineOptions& o : every_queue) {
        auto engine = make_engine(scene, o);
        engine->advance_to(0.01);
        CHECK_FALSE(engine->snapshot().queue.has_value());
    }
    EngineOptions time;
    time.engine = EngineKind::time;
    auto engine = make_engine(scene, time);
    CHECK_FALSE(engine->watch_queue(picture(5)));
    engine->advance_to(0.01);
    CHECK_FALSE(engine->snapshot().queue.has_value());
}

TEST_CASE("queue view: K out of range is refused naming the field queue") {
    auto engine = make_engine(walled_gas(), classic_with("binary"));
    for (const std::size_t k : {std::size_t{0}, sim::max_watched_events + 1}) {
        try {
            (void)engine->watch_queue(picture(k));
            FAIL("accepted " << k << " upcoming events");
        } catch (const Error& e) {
            CHECK(e.kind() == ErrorKind::input);
            CHECK(std::string(e.what()).starts_with("queue: shows 1 to "));
        }
    }
}

TEST_CASE("queue view: the next events shown are the collisions that happen next, in order") {
    const Scene scene = walled_gas();
    for (const EngineOptions& o : every_queue) {
        CAPTURE(to_string(o.engine));
        CAPTURE(pq::to_string(o.pq));
        auto engine = make_engine(scene, o);
        REQUIRE(engine->watch_queue(picture(4)));
        double t = 0.0;
        int checked = 0;
        for (int frame = 0; frame < 40; ++frame) {
            engine->advance_to(t);
            const Snapshot s = engine->snapshot();
            REQUIRE(s.queue.has_value());
            const QueueView& q = *s.queue;
            REQUIRE_FALSE(q.next.empty());
            CHECK(q.next.size() <= 4);
            for (std::size_t k = 0; k < q.next.size(); ++k) {
                CHECK_FALSE(q.next[k].stale);
                CHECK(q.next[k].kind != EventKind::cell);
                CHECK(q.next[k].t >= s.time);
                if (k > 0) CHECK(q.next[k - 1].t <= q.next[k].t);
            }
            // The classic loop holds every valid prediction: the first one shown is the very
            // next collision. The fast engine predicts lazily (a disc whose event turns out
            // stale, or that crosses into a new cell, predicts again), so the first one shown is
            // a real prediction that something may still come before.
            const double next_t = q.next.front().t;
            const auto log = events_until(*engine, next_t);
            REQUIRE_FALSE(log.empty());
            if (o.engine == EngineKind::classic) {
                CHECK(same_collision(q.next.front(), log.front()));
            } else {
                CHECK(log.front().t <= next_t);
            }
            ++checked;
            t = next_t + 0.003;
        }
        CHECK(checked == 40);
    }
}

TEST_CASE("queue view: the shown slots are the queue's own, root first, and the counts match") {
    const Scene scene = walled_gas();
    for (const EngineOptions& o : every_queue) {
        CAPTURE(to_string(o.engine));
        CAPTURE(pq::to_string(o.pq));
        auto engine = make_engine(scene, o);
        REQUIRE(engine->watch_queue(picture(5)));
        engine->advance_to(0.2);
        const Measurements m = engine->measurements();
        const QueueView q = *engine->snapshot().queue;
        CHECK(q.pops == m.queue.pops);
        CHECK(q.stale_pops == m.queue.stale_pops);
        CHECK(q.stale_entries <= q.size);
        REQUIRE_FALSE(q.slots.empty());
        CHECK(q.slots.size() <= q.size);
        if (q.shape == QueueShape::heap) {
            CHECK(q.levels >= 1);
            CHECK(q.levels <= picture(5).tree_levels);
            CHECK(q.slots.size() == sim::shown_tree_slots(q.arity, q.levels, q.size));
            // Heap order: no child comes before its parent.
            for (std::size_t i = 1; i < q.slots.size(); ++i)
                CHECK(q.slots[(i - 1) / q.arity].t <= q.slots[i].t);
        }
        if (q.shape == QueueShape::ordered_array) {
            for (std::size_t i = 1; i < q.slots.size(); ++i)
                CHECK(q.slots[i - 1].t <= q.slots[i].t);
        }
        if (o.engine == EngineKind::fast) {
            CHECK(q.one_per_disc);
            CHECK(q.size <= scene.discs.size());
            CHECK(q.name == "indexed 4-ary heap");
        } else {
            CHECK_FALSE(q.one_per_disc);
            CHECK(q.name == sim::detail::queue_name(q.shape, q.arity,
                                                    o.pq.family == pq::QueueFamily::indexed));
        }
    }
}

TEST_CASE("queue view: pops are recorded in order, the latest last, stale ones flagged") {
    const Scene scene = walled_gas();
    auto engine = make_engine(scene, classic_with("binary"));
    REQUIRE(engine->watch_queue(picture(5)));
    const auto log = events_until(*engine, 0.5);
    const QueueView q = *engine->snapshot().queue;
    REQUIRE(q.pops > sim::watched_pops);
    REQUIRE(q.popped.size() == sim::watched_pops);
    for (std::size_t k = 1; k < q.popped.size(); ++k) CHECK(q.popped[k - 1].t <= q.popped[k].t);
    // The valid pops are the latest resolved collisions, in the same order.
    std::vector<QueuedEvent> valid;
    for (const QueuedEvent& e : q.popped) {
        if (!e.stale) valid.push_back(e);
    }
    REQUIRE_FALSE(valid.empty());
    REQUIRE(log.size() >= valid.size());
    for (std::size_t k = 0; k < valid.size(); ++k) {
        CHECK(same_collision(valid[valid.size() - 1 - k], log[log.size() - 1 - k]));
    }
    // The lecture's lazy invalidation: a dense gas throws away many stale events.
    CHECK(q.stale_pops > 0);
    CHECK(q.stale_entries > 0);
}

TEST_CASE("queue view: watching does not change a single event") {
    const Scene scene = walled_gas();
    for (const EngineOptions& o : every_queue) {
        CAPTURE(to_string(o.engine));
        CAPTURE(pq::to_string(o.pq));
        auto plain = make_engine(scene, o);
        auto watched = make_engine(scene, o);
        REQUIRE(watched->watch_queue(picture(sim::max_watched_events)));
        std::vector<CollisionRecord> a;
        std::vector<CollisionRecord> b;
        for (int frame = 1; frame <= 10; ++frame) {
            const double t = 0.05 * frame;
            for (const CollisionRecord& r : events_until(*plain, t)) a.push_back(r);
            for (const CollisionRecord& r : events_until(*watched, t)) b.push_back(r);
            (void)watched->snapshot();
        }
        REQUIRE(a.size() == b.size());
        for (std::size_t k = 0; k < a.size(); ++k) {
            CHECK(a[k].t == b[k].t);
            CHECK(a[k].a == b[k].a);
            CHECK(a[k].b == b[k].b);
        }
    }
}

TEST_CASE("queue view: tree levels keep the deepest level legible") {
    CHECK(sim::shown_tree_levels(2, 0, picture(5)) == 0);
    CHECK(sim::shown_tree_levels(2, 1, picture(5)) == 1);
    CHECK(sim::shown_tree_levels(2, 3, picture(5)) == 2);
    CHECK(sim::shown_tree_levels(2, 1000, picture(5)) == 3);  // 1 + 2 + 4
    CHECK(sim::shown_tree_slots(2, 3, 1000) == 7);
    CHECK(sim::shown_tree_levels(4, 1000, picture(5)) == 2);  // 16 in the third level: too many
    CHECK(sim::shown_tree_slots(4, 2, 1000) == 5);
    CHECK(sim::shown_tree_levels(8, 1000, picture(5)) == 2);
    CHECK(sim::shown_tree_slots(8, 2, 6) == 6);  // a partial last level
}

TEST_CASE("queue view: the next collisions drop stale entries, cell crossings and repeats") {
    std::vector<QueuedEvent> events = {
        {0.5, EventKind::pair, 1, 2, false},       {0.1, EventKind::pair, 3, 4, true},
        {0.2, EventKind::cell, 5, 0, false},       {0.3, EventKind::xwall, 6, 0, false},
        {0.5000001, EventKind::pair, 1, 2, false}, {0.4, EventKind::ywall, 7, 0, false},
    };
    sim::keep_next_collisions(events, 5);
    REQUIRE(events.size() == 3);
    CHECK(events[0].a == 6);
    CHECK(events[1].a == 7);
    CHECK(events[2].t == 0.5);
    std::vector<QueuedEvent> again = events;
    sim::keep_next_collisions(again, 2);
    CHECK(again.size() == 2);
}

}  // namespace
}  // namespace collide
