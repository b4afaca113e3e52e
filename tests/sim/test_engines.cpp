// The event-driven engines (classic and fast): analytic cases, corner cases that trap naive
// loops, conservation, no overlaps, and event-by-event agreement of the two engines.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "../support/skip.hpp"
#include "collide/error.hpp"
#include "collide/sim/classic_engine.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/event.hpp"
#include "collide/sim/fast_engine.hpp"
#include "collide/sim/observables.hpp"
#include "collide/sim/pq/dary_heap.hpp"
#include "collide/sim/scene_check.hpp"
#include "same_events.hpp"
#include "scene_fixtures.hpp"

using namespace collide;
using collide::test::head_on;
using collide::test::lattice_fluid;
using collide::test::require_same_events;

namespace {

using BinaryQueue = pq::DaryHeap<sim::Event, pq::Orientation::min, 2, sim::EventLess>;

std::unique_ptr<Engine> engine_named(const std::string& name, const Scene& scene) {
    EngineOptions options;
    options.engine = parse_engine_kind(name);
    return make_engine(scene, options);
}

/// Runs until `count` collisions have been recorded (or t_max), returning them.
std::vector<CollisionRecord> first_collisions(Engine& engine, std::size_t count, double step,
                                              double t_max) {
    std::vector<CollisionRecord> log;
    engine.set_collision_listener([&](const CollisionRecord& r) { log.push_back(r); });
    while (log.size() < count && engine.time() < t_max) engine.advance_to(engine.time() + step);
    if (log.size() > count) log.resize(count);
    return log;
}

double largest_sigma(const Scene& s) {
    double r = 0.0;
    for (const Disc& d : s.discs) r = std::max(r, d.radius);
    return 2.0 * r;
}

}  // namespace

TEST_CASE("both engines: head-on discs collide at the analytic time and exchange velocities") {
    for (const char* name : {"classic", "fast"}) {
        CAPTURE(name);
        auto engine = engine_named(name, head_on());
        std::vector<CollisionRecord> log;
        engine->set_collision_listener([&](const CollisionRecord& r) { log.push_back(r); });
        engine->advance_to(2.5);
        // gap 0.4 closes at 0.2 per time unit: contact at t = 2
        REQUIRE(log.size() == 1);
        CHECK(log[0].kind == CollisionKind::pair);
        CHECK(log[0].t == doctest::Approx(2.0).epsilon(1e-14));
        const Snapshot s = engine->snapshot();
        CHECK(s.time == 2.5);
        CHECK(s.discs[0].velocity.x == doctest::Approx(-0.1));
        CHECK(s.discs[1].velocity.x == doctest::Approx(0.1));
        // contact at x = 0.4 and 0.6, then 0.5 time units back out at 0.1
        CHECK(s.discs[0].position.x == doctest::Approx(0.35));
        CHECK(s.discs[1].position.x == doctest::Approx(0.65));
        // then each reaches its wall (x = 0.1 and 0.9) after (0.4 - 0.1)/0.1 = 3 more
        engine->advance_to(5.5);
        REQUIRE(log.size() == 3);
        CHECK(log[1].t == doctest::Approx(5.0));
        CHECK(log[2].t == doctest::Approx(5.0));
        CHECK(engine->measurements().collisions_wall == 2);
    }
}

// validate_scene admits lengths, speeds and masses up to 1e50 (radii and masses down to 1e-50):
// at every corner of that range the head-on collision must still happen, on time, with the
// velocities exchanged and nothing overflowing or underflowing (no NaN, no passing through).
TEST_CASE("every engine: head-on collision at the corners of the admitted range of magnitudes") {
    for (const double length : {1e-49, 1.0, 1e50}) {
        for (const double speed : {1e-50, 1.0, 1e50}) {
            for (const double mass : {min_scene_magnitude, 1.0, max_scene_magnitude}) {
                CAPTURE(length);
                CAPTURE(speed);
                CAPTURE(mass);
                Scene scene = head_on();  // unit box, radius 0.1, speeds 0.1: contact at t = 2
                scene.box = Box{length, length, Boundary::walls};
                for (Disc& d : scene.discs) {
                    d.position = length * d.position;
                    d.radius *= length;
                    d.velocity = speed * d.velocity;
                    d.mass = mass;
                }
                REQUIRE_NOTHROW(validate_scene(scene));
                const double unit_time = length / speed;
                for (const std::string name : {"classic", "fast", "time", "time-grid"}) {
                    CAPTURE(name);
                    EngineOptions options;
                    options.engine = parse_engine_kind(name == "time-grid" ? "time" : name);
                    if (name == "time-grid") options.td_detect = OverlapDetection::grid;
                    options.dt = 0.01 * unit_time;
                    auto engine = make_engine(scene, options);
                    const double energy = engine->measurements().kinetic_energy;
                    engine->advance_to(2.5 * unit_time);
                    const Snapshot s = engine->snapshot();
                    CHECK(s.discs[0].velocity.x == doctest::Approx(-0.1 * speed));
                    CHECK(s.discs[1].velocity.x == doctest::Approx(0.1 * speed));
                    CHECK(s.discs[0].position.x == doctest::Approx(0.35 * length).epsilon(1e-3));
                    const Measurements m = engine->measurements();
                    CHECK(m.collisions_pair == 1);
                    CHECK(m.kinetic_energy == doctest::Approx(energy).epsilon(1e-12));
                    CHECK(m.max_overlap <= 1e-9 * length);
                }
            }
        }
    }
}

TEST_CASE("both engines stop exactly at the frame time and refuse to go backwards") {
    for (const char* name : {"classic", "fast"}) {
        CAPTURE(name);
        auto engine = engine_named(name, head_on());
        engine->advance_to(0.75);
        CHECK(engine->time() == 0.75);
        CHECK(engine->snapshot().discs[0].position.x == doctest::Approx(0.2 + 0.075));
        CHECK_THROWS_AS(engine->advance_to(0.5), Error);
        engine->advance_to(0.75);  // same time: allowed, nothing happens
        CHECK(engine->time() == 0.75);
    }
}

TEST_CASE(
    "every engine refuses to go backwards, or to a time that is not finite, with an input "
    "error") {
    for (const char* name : {"classic", "fast", "time"}) {
        CAPTURE(name);
        auto engine = engine_named(name, head_on());
        engine->advance_to(0.75);
        for (const double t : {0.5, std::nan(""), HUGE_VAL}) {
            CAPTURE(t);
            try {
                engine->advance_to(t);
                FAIL("advance_to accepted t");
            } catch (const Error& e) {
                CHECK(e.kind() == ErrorKind::input);
            }
        }
        CHECK(engine->time() == 0.75);
    }
}

TEST_CASE("a disc wedged in a corner bounces out without a zero-time loop") {
    Scene s;
    s.box = Box{1.0, 1.0, Boundary::walls};
    Disc d;
    d.radius = 0.05;
    d.position = {0.05, 0.05};  // touching both walls
    d.velocity = {-1.0, -1.0};  // moving into the corner
    s.discs = {d};
    for (const char* name : {"classic", "fast"}) {
        CAPTURE(name);
        auto engine = engine_named(name, s);
        engine->advance_to(0.5);
        const Measurements m = engine->measurements();
        CHECK(m.collisions_xwall == 1);
        CHECK(m.collisions_ywall == 1);
        const Snapshot snap = engine->snapshot();
        CHECK(snap.discs[0].velocity.x == 1.0);
        CHECK(snap.discs[0].position.x == doctest::Approx(0.55));
    }
}

TEST_CASE("three discs in a row in contact (Newton's cradle) pass the momentum along and stop") {
    Scene s;
    s.box = Box{2.0, 1.0, Boundary::walls};
    for (int k = 0; k < 3; ++k) {
        Disc d;
        d.radius = 0.1;
        d.position = {0.5 + 0.2 * k, 0.5};  // exactly touching
        s.discs.push_back(d);
    }
    s.discs[0].position.x = 0.3;
    s.discs[0].velocity = {1.0, 0.0};
    for (const char* name : {"classic", "fast"}) {
        CAPTURE(name);
        auto engine = engine_named(name, s);
        engine->advance_to(0.25);  // 0 hits 1 at t = 0.1, passes through 1 to 2 at once
        const Measurements m = engine->measurements();
        CHECK(m.collisions_pair == 2);
        const Snapshot snap = engine->snapshot();
        CHECK(snap.discs[0].velocity.x == doctest::Approx(0.0).epsilon(1e-12));
        CHECK(snap.discs[1].velocity.x == doctest::Approx(0.0).epsilon(1e-12));
        CHECK(snap.discs[2].velocity.x == doctest::Approx(1.0));
        CHECK(m.max_overlap <= sim::overlap_tolerance * 0.2);
    }
}

TEST_CASE("overlapping and approaching discs collide at once instead of passing through") {
    Scene s = head_on();
    s.discs[0].position.x = 0.45;
    s.discs[1].position.x = 0.6;  // overlap 0.05, approaching
    for (const char* name : {"classic", "fast"}) {
        CAPTURE(name);
        auto engine = engine_named(name, s);
        engine->advance_to(0.1);
        CHECK(engine->measurements().collisions_pair == 1);
        CHECK(engine->snapshot().discs[0].velocity.x < 0.0);
    }
}

// The engines round differently (the classic loop advances every disc at every event, the fast
// one keeps local clocks), and hard-disc dynamics amplify a difference by roughly 2 per collision
// per disc in a dense fluid. Agreement to 1e-9 therefore holds for ~20 collisions per disc; the
// physics suite compares 3000 collisions of 400 discs.
TEST_CASE("classic and fast agree event by event on a dense periodic fluid") {
    const Scene scene = lattice_fluid(8, 0.5, Boundary::periodic, 7);
    auto classic = engine_named("classic", scene);
    auto fast = engine_named("fast", scene);
    const auto a = first_collisions(*classic, 400, 0.005, 100.0);
    const auto b = first_collisions(*fast, 400, 0.005, 100.0);
    REQUIRE(a.size() == 400);
    require_same_events(a, b, 1e-9);
}

TEST_CASE("classic and fast agree event by event in a walled box") {
    const Scene scene = lattice_fluid(8, 0.4, Boundary::walls, 11);
    auto classic = engine_named("classic", scene);
    auto fast = engine_named("fast", scene);
    const auto a = first_collisions(*classic, 600, 0.01, 100.0);
    const auto b = first_collisions(*fast, 600, 0.01, 100.0);
    REQUIRE(a.size() == 600);
    CHECK(classic->measurements().collisions_wall > 0);
    require_same_events(a, b, 1e-9);
}

// In a dilute gas a disc crosses several cells between collisions; each crossing scans only the
// cells it newly borders and keeps the pair event remembered from the earlier scans. Long free
// paths amplify rounding faster than in the dense fluid (~10x per collision), hence fewer events.
TEST_CASE("classic and fast agree event by event in a dilute gas (many crossings per collision)") {
    for (Boundary boundary : {Boundary::periodic, Boundary::walls}) {
        CAPTURE(static_cast<int>(boundary));
        const Scene scene = lattice_fluid(8, 0.05, boundary, 13);
        sim::ClassicEngine<BinaryQueue> classic(scene);
        sim::FastEngine fast(scene);
        const auto a = first_collisions(classic, 100, 0.01, 100.0);
        std::vector<CollisionRecord> b;
        fast.set_collision_listener([&](const CollisionRecord& r) { b.push_back(r); });
        while (b.size() < a.size() && fast.time() < 100.0) {
            fast.advance_to(fast.time() + 0.01);
            REQUIRE(fast.check_invariants());
        }
        b.resize(std::min(b.size(), a.size()));
        REQUIRE(a.size() == 100);
        require_same_events(a, b, 1e-9);
        const Measurements m = fast.measurements();
        CHECK(static_cast<double>(m.cell_crossings) >
              2.0 * static_cast<double>(m.collisions_pair + m.collisions_wall));
    }
}

TEST_CASE("classic and fast agree with one big disc among small ones (the big-disc list)") {
    for (Boundary boundary : {Boundary::walls, Boundary::periodic}) {
        CAPTURE(static_cast<int>(boundary));
        Scene scene = lattice_fluid(10, 0.3, boundary, 5, 0.005);
        // Turn the central disc into a heavy big one and clear the discs it would overlap.
        const Vec2 centre{scene.box.width / 2, scene.box.height / 2};
        std::vector<Disc> kept;
        for (const Disc& d : scene.discs) {
            if (norm(d.position - centre) > 0.03) kept.push_back(d);
        }
        Disc big;
        big.position = centre;
        big.velocity = {0.2, 0.1};
        big.radius = 0.02;
        big.mass = 10.0;
        kept.push_back(big);
        scene.discs = kept;
        sim::FastEngine fast(scene);
        CHECK(fast.big_disc_count() == 1);
        sim::ClassicEngine<BinaryQueue> classic(scene);
        const auto a = first_collisions(classic, 400, 0.01, 100.0);
        const auto b = first_collisions(fast, 400, 0.01, 100.0);
        REQUIRE(a.size() == 400);
        require_same_events(a, b, 1e-9);
        CHECK(fast.check_invariants());
        // the big disc took part
        CHECK(std::any_of(a.begin(), a.end(), [&](const CollisionRecord& r) {
            return r.kind == CollisionKind::pair && r.b == scene.discs.size() - 1;
        }));
    }
}

TEST_CASE("the classic engine pops the identical event sequence whatever the queue") {
    // Small on purpose: the array queues are O(size) per operation and the sanitizer build
    // validates every heap after every mutation.
    const Scene scene = lattice_fluid(5, 0.5, Boundary::walls, 3);
    sim::ClassicEngine<BinaryQueue> binary(scene);
    const auto reference = first_collisions(binary, 400, 0.01, 100.0);
    REQUIRE(reference.size() == 400);
    const Measurements reference_m = binary.measurements();
    for (const char* kind : {"unordered", "ordered", "binary", "dary:3", "dary:4", "dary:8",
                             "dary:5", "indexed", "indexed:2", "indexed:8"}) {
        CAPTURE(kind);
        EngineOptions options;
        options.engine = EngineKind::classic;
        options.pq = pq::parse_queue_kind(kind);
        auto engine = make_engine(scene, options);
        const auto events = first_collisions(*engine, 400, 0.01, 100.0);
        require_same_events(reference, events, 0.0);
        const Measurements m = engine->measurements();
        CHECK(m.queue.pops == reference_m.queue.pops);
        CHECK(m.queue.stale_pops == reference_m.queue.stale_pops);
        CHECK(m.queue.max_size == reference_m.queue.max_size);
    }
}

TEST_CASE("engine names parse into kinds and back, and a bad name is an input error listing them") {
    for (const EngineKind kind : {EngineKind::fast, EngineKind::classic, EngineKind::time})
        CHECK(parse_engine_kind(to_string(kind)) == kind);
    CHECK(parse_event_engine_kind("classic") == EngineKind::classic);
    for (const auto d : {OverlapDetection::all_pairs, OverlapDetection::grid})
        CHECK(parse_overlap_detection(to_string(d)) == d);
    const auto message = [](auto&& parse) {
        try {
            parse();
        } catch (const Error& e) {
            CHECK(e.kind() == ErrorKind::input);
            return std::string(e.what());
        }
        FAIL("accepted a bad name");
        return std::string();
    };
    CHECK(message([] { (void)parse_engine_kind("warp"); }) ==
          "engine: expected fast, classic or time, got 'warp'");
    CHECK(message([] { (void)parse_event_engine_kind("time", "--engine"); }) ==
          "--engine: expected an event-driven engine (fast or classic), got 'time'");
    CHECK(message([] { (void)parse_overlap_detection("octree"); }) ==
          "td_detect: expected all-pairs or grid, got 'octree'");
    CHECK(message([] { (void)parse_overlap_detection("octree", "--td-detect"); }) ==
          "--td-detect: expected all-pairs or grid, got 'octree'");
    CHECK(message([] { (void)parse_engine_kind("Fast", "scene.toml:3: engine"); }) ==
          "scene.toml:3: engine: expected fast, classic or time, got 'Fast'");
}

TEST_CASE("fast engine: energy and momentum conserved, no overlap, one queue entry per disc") {
    for (Boundary boundary : {Boundary::periodic, Boundary::walls}) {
        const Scene scene = lattice_fluid(10, 0.55, boundary, 21);
        sim::FastEngine engine(scene);
        const Measurements m0 = engine.measurements();
        double last_t = 0.0;
        bool monotonic = true;
        engine.set_collision_listener([&](const CollisionRecord& r) {
            monotonic = monotonic && r.t >= last_t;
            last_t = r.t;
        });
        for (int frame = 1; frame <= 20; ++frame) {
            engine.advance_to(0.02 * frame);
            REQUIRE(engine.check_invariants());
        }
        const Measurements m = engine.measurements();
        CHECK(monotonic);
        CHECK(m.collisions_pair > 5000);
        CHECK(std::abs(m.kinetic_energy - m0.kinetic_energy) <= 1e-12 * m0.kinetic_energy);
        if (boundary == Boundary::periodic) {
            // Rounding only: each collision moves momentum by ~1e-16 of a disc's momentum.
            CHECK(norm(m.momentum - m0.momentum) <= 1e-11);
            CHECK(m.collisions_wall == 0);
        }
        CHECK(m.max_overlap <= sim::overlap_tolerance * largest_sigma(scene));
        CHECK(m.queue.max_size <= scene.discs.size());
        CHECK(m.packing_fraction == doctest::Approx(0.55));
        CHECK(m.temperature == doctest::Approx(1.0));
    }
}

TEST_CASE("fast engine refuses a periodic box narrower than three diameters") {
    Scene s;
    s.box = Box{0.05, 1.0, Boundary::periodic};
    Disc d;
    d.radius = 0.01;
    d.position = {0.025, 0.5};
    s.discs = {d};
    CHECK_THROWS_AS(sim::FastEngine{s}, Error);
}

TEST_CASE("mean squared displacement follows ballistic flight before any collision") {
    Scene s;
    s.box = Box{1.0, 1.0, Boundary::periodic};
    Disc d;
    d.radius = 0.01;
    d.position = {0.5, 0.5};
    d.velocity = {0.3, 0.4};  // speed 0.5
    s.discs = {d};
    for (const char* name : {"classic", "fast"}) {
        CAPTURE(name);
        auto engine = engine_named(name, s);
        engine->advance_to(4.0);  // wraps around twice; unwrapped displacement is 2.0
        CHECK(engine->measurements().msd == doctest::Approx(4.0));
        CHECK(engine->snapshot().discs[0].position.x == doctest::Approx(0.7));
    }
}

TEST_CASE("queue statistics: the fast engine pops no more stale events than it has pair events") {
    const Scene scene = lattice_fluid(6, 0.5, Boundary::periodic, 9);
    auto classic = engine_named("classic", scene);
    auto fast = engine_named("fast", scene);
    classic->advance_to(0.03);
    fast->advance_to(0.03);
    const Measurements c = classic->measurements();
    const Measurements f = fast->measurements();
    CHECK(f.collisions_pair > 100);
    CHECK(c.queue.max_size > scene.discs.size());  // the lecture's queue fills with stale events
    CHECK(f.queue.max_size <= scene.discs.size());
    CHECK(c.queue.stale_pops > 0);
    CHECK(f.queue.pops == f.events + f.queue.stale_pops);
    // The fast engine re-keys the popped disc in place after every event (a sift, counted as an
    // update); the lecture's queue only pushes and pops.
    CHECK(f.queue.updates >= f.queue.pops);
    CHECK(c.queue.updates == 0);
}

// p10 is dilute: mean free path ~30 diameters, so rounding differences grow ~50x per collision
// and the engines agree to 1e-9 for the first few dozen collisions only.
TEST_CASE("p10.txt: both engines agree and never run time backwards") {
    const auto scene = collide::test::read_algs4("p10.txt");
    if (!scene) {
        COLLIDE_SKIP_TEST(collide::test::algs4_dir() / "p10.txt"
                          << " is absent");
    }
    auto classic = engine_named("classic", *scene);
    auto fast = engine_named("fast", *scene);
    const auto a = first_collisions(*classic, 500, 1.0, 1e6);
    const auto b = first_collisions(*fast, 500, 1.0, 1e6);
    REQUIRE(a.size() == 500);
    REQUIRE(b.size() == 500);
    for (std::size_t k = 1; k < a.size(); ++k) {
        REQUIRE(a[k].t >= a[k - 1].t);
        REQUIRE(b[k].t >= b[k - 1].t);
    }
    require_same_events({a.begin(), a.begin() + 20}, {b.begin(), b.begin() + 20}, 1e-9);
    CHECK(fast->measurements().max_overlap <= sim::overlap_tolerance * 0.04);
}

// A pair that has just collided still touches, so its next prediction skips the image it touches;
// in a box a few diameters across the same pair meets again through another image before either
// hits anything else, and that meeting must be predicted (nothing would predict it later).
TEST_CASE("classic loop in a tiny periodic box: a pair meets again across the seam") {
    Scene scene;
    scene.box = Box{1.0, 1.0, Boundary::periodic};
    Disc a;
    a.position = {0.3, 0.5};
    a.velocity = {1.0, 0.2};
    a.radius = 0.2;
    Disc b = a;
    b.position = {0.75, 0.5};
    b.velocity = {-1.0, 0.2};
    scene.discs = {a, b};
    sim::ClassicEngine<BinaryQueue> classic(scene);
    classic.advance_to(5.0);
    const Measurements m = classic.measurements();
    // Gaps of 0.05 and then 0.2 at a closing speed of 2: a collision every 0.1 time units.
    CHECK(m.collisions_pair == 50);
    CHECK(m.max_overlap <= 1e-9);
}
