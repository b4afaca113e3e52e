// The time-driven engine against analytic results, its failure reports (misses, escapes,
// overlaps), its cost counter, grid vs all-pairs, and determinism.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "collide/error.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/time_engine.hpp"
#include "scene_fixtures.hpp"

using namespace collide;
using sim::TimeEngine;

namespace {

Disc make_disc(Vec2 p, Vec2 v, double r, double m = 1.0) {
    Disc d;
    d.position = p;
    d.velocity = v;
    d.radius = r;
    d.mass = m;
    return d;
}

Scene make_scene(double width, double height, std::vector<Disc> discs,
                 Boundary boundary = Boundary::walls) {
    Scene s;
    s.name = "test";
    s.box = Box{width, height, boundary};
    s.discs = std::move(discs);
    return s;
}

EngineOptions time_options(double dt, OverlapDetection detect = OverlapDetection::all_pairs) {
    EngineOptions o;
    o.engine = EngineKind::time;
    o.dt = dt;
    o.td_detect = detect;
    return o;
}

/// A gas of n discs on a jittered lattice (no overlaps) with random velocities; fixed seed.
Scene random_gas(std::size_t side, double r, double speed, std::uint64_t seed, Boundary boundary) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const double spacing = 1.0 / static_cast<double>(side);
    const double jitter = 0.5 * (spacing - 2.0 * r) * 0.9;
    std::vector<Disc> discs;
    for (std::size_t ix = 0; ix < side; ++ix) {
        for (std::size_t iy = 0; iy < side; ++iy) {
            const Vec2 centre{(static_cast<double>(ix) + 0.5) * spacing,
                              (static_cast<double>(iy) + 0.5) * spacing};
            const Vec2 p = centre + Vec2{jitter * unit(rng), jitter * unit(rng)};
            const Vec2 v{speed * unit(rng), speed * unit(rng)};
            discs.push_back(make_disc(p, v, r, 1.0 + 0.5 * (unit(rng) + 1.0)));
        }
    }
    return make_scene(1.0, 1.0, std::move(discs), boundary);
}

bool same_snapshots(const Snapshot& a, const Snapshot& b) {
    if (a.time != b.time || a.discs.size() != b.discs.size()) {
        return false;
    }
    for (std::size_t i = 0; i < a.discs.size(); ++i) {
        if (a.discs[i].position != b.discs[i].position) {
            return false;
        }
        if (a.discs[i].velocity != b.discs[i].velocity) {
            return false;
        }
        if (a.discs[i].escaped != b.discs[i].escaped) {
            return false;
        }
    }
    return a.overlapping_pairs == b.overlapping_pairs && a.missed_collisions == b.missed_collisions;
}

}  // namespace

TEST_CASE("options: a bad dt is an input error naming the field, as its caller spells it") {
    EngineOptions options = time_options(0.0);
    try {
        options.validate("--dt");
        FAIL("accepted a bad dt");
    } catch (const Error& e) {
        CHECK(std::string(e.what()) == "--dt: expected a finite time step > 0, got '0'");
    }
}

TEST_CASE("options: a bad dt is an input error naming the option and the value") {
    const Scene scene = make_scene(1.0, 1.0, {make_disc({0.5, 0.5}, {0.1, 0.0}, 0.05)});
    for (double dt : {0.0, -0.01, std::nan(""), static_cast<double>(INFINITY)}) {
        CAPTURE(dt);
        try {
            TimeEngine engine(scene, time_options(dt));
            FAIL("accepted a bad dt");
        } catch (const Error& e) {
            CHECK(e.kind() == ErrorKind::input);
            CHECK(std::string(e.what()).rfind("dt: expected a finite time step > 0, got '", 0) ==
                  0);
        }
    }
    CHECK_NOTHROW(validate_time_driven_options(time_options(0.01, OverlapDetection::grid)));
}

TEST_CASE("make_engine builds the time-driven engine for engine = time") {
    const Scene scene = make_scene(1.0, 1.0, {make_disc({0.5, 0.5}, {0.1, 0.0}, 0.05)});
    auto engine = make_engine(scene, time_options(0.01));
    engine->advance_to(1.0);
    CHECK(engine->time() == 1.0);
    CHECK(engine->snapshot().discs[0].position.x == doctest::Approx(0.6));
}

TEST_CASE("advance_to takes the whole steps up to t, step k ending at k dt from t = 0") {
    const Scene scene = make_scene(1.0, 1.0, {make_disc({0.2, 0.5}, {0.1, 0.0}, 0.05)});
    TimeEngine engine(scene, time_options(0.01));
    engine.advance_to(1.0 / 30.0);  // 3 whole steps; the state stays at 0.03
    CHECK(engine.time() == 1.0 / 30.0);
    CHECK(engine.measurements().steps == 3);
    CHECK(engine.snapshot().time == 3 * 0.01);
    CHECK(engine.measurements().t == 3 * 0.01);
    engine.advance_to(2.0 / 30.0);  // steps 4..6, not restarted from 1/30
    CHECK(engine.time() == 2.0 / 30.0);
    CHECK(engine.measurements().steps == 6);
    CHECK(engine.snapshot().time == 6 * 0.01);
    CHECK(engine.snapshot().discs[0].position.x == doctest::Approx(0.2 + 0.1 * 0.06));
    engine.advance_to(engine.time());  // no step at all
    CHECK(engine.measurements().steps == 6);
    engine.advance_to(0.069);  // still before step 7 ends
    CHECK(engine.measurements().steps == 6);
    CHECK_THROWS_AS(engine.advance_to(0.0), Error);
}

TEST_CASE("whole_steps counts the steps k * dt at or before t, up to rounding") {
    CHECK(TimeEngine::whole_steps(0.0, 0.04) == 0);
    CHECK(TimeEngine::whole_steps(-1.0, 0.04) == 0);
    CHECK(TimeEngine::whole_steps(0.03, 0.04) == 0);
    CHECK(TimeEngine::whole_steps(0.05, 0.04) == 1);
    CHECK(TimeEngine::whole_steps(0.12, 0.04) == 3);  // 3 * 0.04 = 0.12000000000000001 > 0.12
    CHECK(TimeEngine::whole_steps(1.0, 0.1) == 10);
    std::uint64_t previous = 0;
    for (int k = 0; k < 300; ++k) {  // never backwards, and step ends never after the frame
        const double t = k / 75.0;
        const std::uint64_t steps = TimeEngine::whole_steps(t, 0.04);
        CHECK(steps >= previous);
        CHECK(static_cast<double>(steps) * 0.04 <= t + TimeEngine::landing_tolerance * 0.04);
        CHECK(static_cast<double>(steps + 1) * 0.04 > t + TimeEngine::landing_tolerance * 0.04);
        previous = steps;
    }
    CHECK(TimeEngine::whole_steps(1e300, 1e-300) > 1'000'000'000'000'000'000u);  // no overflow
}

TEST_CASE("a run in many small calls and one long call take the same steps, bit for bit") {
    const Scene scene = test::lattice_fluid(12, 0.5, Boundary::periodic, 3, 0.02);
    TimeEngine once(scene, time_options(0.003));
    TimeEngine framed(scene, time_options(0.003));
    once.advance_to(0.5);
    for (int k = 1; k <= 37; ++k) framed.advance_to(0.5 * k / 37.0);
    CHECK(once.measurements().steps == framed.measurements().steps);
    CHECK(once.measurements().collisions_pair == framed.measurements().collisions_pair);
    CHECK(once.measurements().collisions_pair > 50);
    const Snapshot a = once.snapshot();
    const Snapshot b = framed.snapshot();
    for (std::size_t i = 0; i < a.discs.size(); ++i) {
        CHECK(a.discs[i].position == b.discs[i].position);
        CHECK(a.discs[i].velocity == b.discs[i].velocity);
    }
}

TEST_CASE("head-on collision of unequal masses matches the analytic result") {
    // m1 = 1 at x = 0.25 moving right at 1, m2 = 3 at x = 0.75 moving left at 0.5; r = 0.05.
    // Gap 0.4 closes at 1.5: contact at t_c = 0.4/1.5. 1D elastic: v1' = -1.25, v2' = 0.25.
    const double r = 0.05;
    const Scene scene = make_scene(
        2.0, 1.0,
        {make_disc({0.25, 0.5}, {1.0, 0.0}, r, 1.0), make_disc({0.75, 0.5}, {-0.5, 0.0}, r, 3.0)});
    const double t_c = 0.4 / 1.5;
    const double t_end = 0.35;
    for (double dt : {0.001, 0.003, 0.007}) {
        CAPTURE(dt);
        TimeEngine engine(scene, time_options(dt));
        std::vector<CollisionRecord> records;
        engine.set_collision_listener([&](const CollisionRecord& c) { records.push_back(c); });
        engine.advance_to(t_end);
        const Snapshot s = engine.snapshot();
        // The state is at the latest whole step: 0.35 itself, or 0.348 for dt = 0.003.
        CHECK(s.time == static_cast<double>(TimeEngine::whole_steps(t_end, dt)) * dt);
        CHECK(s.time > t_end - dt);
        const double x1 = 0.25 + t_c - 1.25 * (s.time - t_c);
        const double x2 = 0.75 - 0.5 * t_c + 0.25 * (s.time - t_c);
        // Between checks the paths are straight, so the rollback finds the exact contact: the
        // time-driven error for one isolated pair is rounding, far below any multiple of dt.
        const double tol = 1e-9 * dt;
        CHECK(s.discs[0].velocity.x == doctest::Approx(-1.25).epsilon(1e-12));
        CHECK(s.discs[1].velocity.x == doctest::Approx(0.25).epsilon(1e-12));
        CHECK(std::fabs(s.discs[0].position.x - x1) < tol);
        CHECK(std::fabs(s.discs[1].position.x - x2) < tol);
        REQUIRE(records.size() == 1);
        CHECK(records[0].kind == CollisionKind::pair);
        CHECK(records[0].t == doctest::Approx(t_c).epsilon(1e-12));
        const Measurements m = engine.measurements();
        CHECK(m.collisions_pair == 1);
        CHECK(m.missed_collisions == 0);
        CHECK(m.momentum.x == doctest::Approx(1.0 - 1.5).epsilon(1e-12));
        CHECK(std::fabs(m.energy_drift) < 1e-12);
    }
}

TEST_CASE("Newton's cradle: the motion passes down a row of resting discs") {
    // Disc 0 (v = 1) hits 1 at t = 0.16, 1 hits 2 at 0.22, 2 hits 3 at 0.28 (gaps 0.16, 0.06,
    // 0.06).
    const double r = 0.02;
    const Scene scene =
        make_scene(2.0, 1.0,
                   {make_disc({0.2, 0.5}, {1.0, 0.0}, r), make_disc({0.4, 0.5}, {}, r),
                    make_disc({0.5, 0.5}, {}, r), make_disc({0.6, 0.5}, {}, r)});
    const std::vector<double> expected_x{0.36, 0.46, 0.56, 0.6 + (0.5 - 0.28)};
    for (double dt : {0.0005, 0.004}) {
        CAPTURE(dt);
        TimeEngine engine(scene, time_options(dt));
        engine.advance_to(0.5);
        const Snapshot s = engine.snapshot();
        for (std::size_t i = 0; i < 4; ++i) {
            CAPTURE(i);
            CHECK(std::fabs(s.discs[i].position.x - expected_x[i]) < dt);
            CHECK(s.discs[i].velocity.x == doctest::Approx(i == 3 ? 1.0 : 0.0).epsilon(1e-9));
        }
        CHECK(engine.measurements().collisions_pair == 3);
    }
}

TEST_CASE("the event-driven classic engine agrees with the time-driven one for small dt") {
    const Scene scene = random_gas(4, 0.03, 0.5, 7, Boundary::walls);
    EngineOptions classic_options;
    classic_options.engine = EngineKind::classic;
    const std::unique_ptr<Engine> classic = make_engine(scene, classic_options);
    const double dt = 1e-4;
    TimeEngine timed(scene, time_options(dt));
    const double t_end = 0.3;  // short: chaos amplifies the O(dt) differences later on
    classic->advance_to(t_end);
    timed.advance_to(t_end);
    const Snapshot a = classic->snapshot();
    const Snapshot b = timed.snapshot();
    CHECK(timed.measurements().missed_collisions == 0);
    CHECK(classic->measurements().collisions_pair == timed.measurements().collisions_pair);
    CHECK(classic->measurements().collisions_wall == timed.measurements().collisions_wall);
    for (std::size_t i = 0; i < a.discs.size(); ++i) {
        CAPTURE(i);
        CHECK(norm(a.discs[i].position - b.discs[i].position) < 10.0 * dt);
        CHECK(norm(a.discs[i].velocity - b.discs[i].velocity) < 10.0 * dt);
    }
}

TEST_CASE("rollback puts a detected pair back at contact: no residual overlap") {
    // sigma = 0.1, closing speed 2, contact at 0.15: with dt = 0.04 the check at 0.12 sees a gap
    // of 0.06 and the one at 0.16 an overlap of 0.02.
    const Scene scene = make_scene(
        1.0, 1.0,
        {make_disc({0.3, 0.5}, {1.0, 0.0}, 0.05), make_disc({0.7, 0.5}, {-1.0, 0.0}, 0.05)});
    TimeEngine engine(scene, time_options(0.04));
    std::vector<CollisionRecord> records;
    engine.set_collision_listener([&](const CollisionRecord& c) { records.push_back(c); });
    engine.advance_to(0.16);
    REQUIRE(records.size() == 1);
    CHECK(records[0].t == doctest::Approx(0.15).epsilon(1e-12));
    const Measurements m = engine.measurements();
    CHECK(m.max_overlap_seen == doctest::Approx(0.02).epsilon(1e-9));
    CHECK(m.max_overlap == 0.0);
    CHECK(m.overlapping_pairs == 0);
    const Snapshot s = engine.snapshot();
    CHECK(s.overlapping_pairs.empty());
    // back to contact at 0.15, then apart for 0.01 at closing speed 2
    CHECK(s.discs[1].position.x - s.discs[0].position.x ==
          doctest::Approx(0.1 + 0.02).epsilon(1e-12));
}

TEST_CASE("tunnelling: discs passing through each other in one step are a missed collision") {
    // v dt = 0.1 each way > 2 sigma: the pair swaps sides between two checks.
    const Scene scene = make_scene(
        1.0, 1.0,
        {make_disc({0.45, 0.5}, {1.0, 0.0}, 0.01), make_disc({0.55, 0.5}, {-1.0, 0.0}, 0.01)});
    TimeEngine engine(scene, time_options(0.1));
    std::vector<CollisionRecord> records;
    engine.set_collision_listener([&](const CollisionRecord& c) { records.push_back(c); });
    engine.advance_to(0.1);
    const Measurements m = engine.measurements();
    CHECK(m.missed_collisions == 1);
    CHECK(m.collisions_pair == 0);
    CHECK(records.empty());
    const Snapshot s = engine.snapshot();
    REQUIRE(s.missed_collisions.size() == 1);
    CHECK(s.missed_collisions[0].x == doctest::Approx(0.5));  // the contact point
    CHECK(s.missed_collisions[0].y == doctest::Approx(0.5));
    CHECK(s.discs[0].velocity.x == 1.0);  // passed through: velocities untouched
    // markers are per frame: the next advance clears them, the count stays
    engine.advance_to(0.11);
    CHECK(engine.snapshot().missed_collisions.empty());
    CHECK(engine.measurements().missed_collisions == 1);

    // the same pair with a small dt collides
    TimeEngine careful(scene, time_options(0.001));
    careful.advance_to(0.1);
    CHECK(careful.measurements().collisions_pair == 1);
    CHECK(careful.measurements().missed_collisions == 0);
}

TEST_CASE("tunnelling through a wall: the disc escapes and keeps flying outside") {
    const Scene scene = make_scene(1.0, 1.0, {make_disc({0.95, 0.5}, {1.0, 0.0}, 0.01)});
    TimeEngine engine(scene, time_options(0.1));
    engine.advance_to(0.1);
    CHECK(engine.measurements().escaped == 1);
    CHECK(engine.measurements().collisions_wall == 0);
    CHECK(engine.snapshot().discs[0].escaped);
    engine.advance_to(0.3);
    CHECK(engine.snapshot().discs[0].position.x == doctest::Approx(1.25));
    CHECK(engine.measurements().escaped == 1);

    // a disc that ends a step straddling the wall is reflected at its contact time
    // (dt = 0.025: the check at 0.05 finds it 0.01 into the wall, contact at 0.04)
    TimeEngine careful(scene, time_options(0.025));
    std::vector<CollisionRecord> records;
    careful.set_collision_listener([&](const CollisionRecord& c) { records.push_back(c); });
    careful.advance_to(0.09);  // three steps: the state is at 0.075
    CHECK(careful.measurements().escaped == 0);
    REQUIRE(records.size() == 1);
    CHECK(records[0].kind == CollisionKind::xwall);
    CHECK(records[0].t == doctest::Approx(0.04));
    CHECK(careful.snapshot().time == doctest::Approx(0.075));
    CHECK(careful.snapshot().discs[0].position.x == doctest::Approx(0.99 - 0.035));
    CHECK(careful.snapshot().discs[0].velocity.x == -1.0);
}

TEST_CASE("tunnelling through a barrier: a disc that steps over an immovable disc is counted") {
    // A barrier piece (1e5 times the lightest: immovable) at (0.5, 0.5); a light disc steps over
    // it (0.1 in one step across 0.04 of contact). Lower down a light disc steps over another
    // light one at rest: a missed collision, but no barrier to go through.
    const Scene scene = make_scene(
        1.0, 1.0,
        {make_disc({0.5, 0.5}, {0.0, 0.0}, 0.01, 1e5), make_disc({0.44, 0.5}, {1.0, 0.0}, 0.01),
         make_disc({0.44, 0.2}, {1.0, 0.0}, 0.01), make_disc({0.5, 0.2}, {0.0, 0.0}, 0.01)});
    TimeEngine engine(scene, time_options(0.1));
    engine.advance_to(0.1);
    CHECK(engine.measurements().missed_collisions == 2);
    CHECK(engine.measurements().escaped == 0);
    CHECK(engine.measurements().tunnelled == 1);
    Snapshot s = engine.snapshot();
    CHECK_FALSE(s.discs[0].tunnelled);  // the barrier stays put
    CHECK(s.discs[1].tunnelled);
    CHECK_FALSE(s.discs[2].tunnelled);
    CHECK_FALSE(s.discs[3].tunnelled);
    // It stays flagged once past. Both moving discs then step through the right wall (0.94 to
    // 1.04): two escaped, two tunnelled, the one through the barrier and the wall counted once.
    engine.advance_to(0.8);
    CHECK(engine.measurements().escaped == 2);
    CHECK(engine.measurements().tunnelled == 2);
    s = engine.snapshot();
    CHECK(s.discs[1].tunnelled);
    CHECK(s.discs[1].escaped);
    CHECK_FALSE(s.discs[2].tunnelled);

    // A periodic box has no wall to leave, the barrier is still there to go through.
    Scene periodic = scene;
    periodic.box.boundary = Boundary::periodic;
    TimeEngine wrapped(periodic, time_options(0.1));
    wrapped.advance_to(0.1);
    CHECK(wrapped.measurements().tunnelled == 1);

    // Small steps: the disc bounces off the barrier, nothing tunnels.
    TimeEngine careful(scene, time_options(0.001));
    careful.advance_to(0.1);
    CHECK(careful.measurements().tunnelled == 0);
    CHECK(careful.snapshot().discs[1].velocity.x < 0.0);
}

TEST_CASE("tunnelling through a wall counts among the discs that tunnelled") {
    const Scene scene = make_scene(
        1.0, 1.0,
        {make_disc({0.95, 0.5}, {1.0, 0.0}, 0.01), make_disc({0.5, 0.5}, {0.0, 0.3}, 0.01)});
    TimeEngine engine(scene, time_options(0.1));
    engine.advance_to(0.1);
    CHECK(engine.measurements().escaped == 1);
    CHECK(engine.measurements().tunnelled == 1);
    CHECK_FALSE(engine.snapshot().discs[0].tunnelled);  // its own flag: escaped
}

TEST_CASE("failure records: the first failing step, its pair and their states before and after") {
    // Rests first: step 0 (0..0.1) ends with the pair 0.1 apart; step 1 swaps them (missed).
    const Scene scene = make_scene(
        1.0, 1.0,
        {make_disc({0.35, 0.5}, {1.0, 0.0}, 0.01), make_disc({0.65, 0.5}, {-1.0, 0.0}, 0.01),
         make_disc({0.1, 0.1}, {0.0, 0.0}, 0.01)});
    TimeEngine engine(scene, time_options(0.1));
    engine.advance_to(0.1);
    const Snapshot before = engine.snapshot();
    CHECK(engine.failures().empty());
    engine.advance_to(0.2);
    const Snapshot after = engine.snapshot();
    REQUIRE(engine.failures().size() == 1);
    const sim::StepFailure& f = engine.failures().front();
    CHECK(f.kind == sim::StepFailureKind::missed_pair);
    CHECK(f.step == 1);
    CHECK(f.a == 0);
    CHECK(f.b == 1);
    // The states at k dt and (k + 1) dt, as the engine showed them.
    CHECK(f.before_a.x == doctest::Approx(before.discs[0].position.x).epsilon(1e-12));
    CHECK(f.before_b.x == doctest::Approx(before.discs[1].position.x).epsilon(1e-12));
    CHECK(f.after_a == after.discs[0].position);
    CHECK(f.after_b == after.discs[1].position);
    CHECK(f.motion_a.x == doctest::Approx(0.1));
    CHECK(f.radius_a == 0.01);
    CHECK(f.contact == doctest::Approx(0.04));  // 0.1 apart, closing at 2, touching at 0.02
    CHECK(f.where.x == doctest::Approx(0.5));
    CHECK(f.where.y == doctest::Approx(0.5));
    CHECK(engine.measurements().missed_collisions == 1);
}

TEST_CASE("failure records: a disc through a wall, and at most max_failure_records steps") {
    const Scene scene = make_scene(1.0, 1.0, {make_disc({0.95, 0.5}, {1.0, 0.0}, 0.01)});
    TimeEngine engine(scene, time_options(0.1));
    engine.advance_to(0.5);
    REQUIRE(engine.failures().size() == 1);  // once outside, it fails no more
    const sim::StepFailure& f = engine.failures().front();
    CHECK(f.kind == sim::StepFailureKind::left_box);
    CHECK(f.step == 0);
    CHECK(f.a == 0);
    CHECK(f.before_a.x == doctest::Approx(0.95));
    CHECK(f.after_a.x == doctest::Approx(1.05));
    CHECK(f.contact == doctest::Approx(0.05));  // the centre crosses x = 1
    CHECK(f.where.x == doctest::Approx(1.0));

    // Many discs leaving one per step: only the first few steps are recorded.
    std::vector<Disc> discs;
    for (int i = 0; i < 20; ++i)
        discs.push_back(make_disc({0.95 - 0.1 * (i % 9), 0.04 + 0.045 * i}, {1.0, 0.0}, 0.01));
    TimeEngine many(make_scene(1.0, 1.0, discs), time_options(0.1));
    many.advance_to(1.0);
    CHECK(many.failures().size() == TimeEngine::max_failure_records);
    for (std::size_t i = 1; i < many.failures().size(); ++i)
        CHECK(many.failures()[i].step > many.failures()[i - 1].step);
}

TEST_CASE("all-pairs performs N(N-1)/2 overlap checks per step") {
    const Scene scene = random_gas(3, 0.02, 1.0, 11, Boundary::walls);  // N = 9
    TimeEngine engine(scene, time_options(0.01));
    engine.advance_to(0.105);  // 10 whole steps (the 11th would end after 0.105)
    const Measurements m = engine.measurements();
    CHECK(m.steps == 10);
    CHECK(m.overlap_checks == 10 * (9 * 8 / 2));
}

TEST_CASE("grid and all-pairs give identical results on a random gas") {
    for (Boundary boundary : {Boundary::walls, Boundary::periodic}) {
        for (double dt : {0.005, 0.05}) {  // careful, and sloppy enough to miss collisions
            CAPTURE(dt);
            CAPTURE(boundary == Boundary::periodic);
            const Scene scene = random_gas(16, 0.005, 1.0, 3, boundary);  // N = 256
            TimeEngine all(scene, time_options(dt, OverlapDetection::all_pairs));
            TimeEngine grid(scene, time_options(dt, OverlapDetection::grid));
            for (int frame = 1; frame <= 6; ++frame) {
                const double t = frame * 0.05;
                all.advance_to(t);
                grid.advance_to(t);
                REQUIRE(same_snapshots(all.snapshot(), grid.snapshot()));
            }
            const Measurements a = all.measurements();
            const Measurements g = grid.measurements();
            CHECK(a.collisions_pair > 0);
            CHECK(a.collisions_pair == g.collisions_pair);
            CHECK(a.collisions_wall == g.collisions_wall);
            CHECK(a.missed_collisions == g.missed_collisions);
            CHECK(a.overlapping_pairs == g.overlapping_pairs);
            CHECK(g.overlap_checks < a.overlap_checks);
            if (dt == 0.05) {
                CHECK(a.missed_collisions > 0);
            }
        }
    }
}

TEST_CASE("grid and all-pairs agree when every neighbour touches exactly") {
    // A square lattice at contact (r = 2^-6, so positions and sigma are exact): the first checks
    // see distances equal to sigma, where the all-pairs sweep's bound and the exact test meet.
    for (Boundary boundary : {Boundary::walls, Boundary::periodic}) {
        CAPTURE(boundary == Boundary::periodic);
        const double r = 0.015625;
        std::mt19937_64 rng(17);
        std::uniform_real_distribution<double> unit(-1.0, 1.0);
        std::vector<Disc> discs;
        for (int ix = 0; ix < 32; ++ix) {
            for (int iy = 0; iy < 32; iy += 3) {
                const Vec2 p{(2 * ix + 1) * r, (2 * iy + 1) * r};
                discs.push_back(make_disc(p, {unit(rng), unit(rng)}, r));
            }
        }
        const Scene scene = make_scene(1.0, 1.0, std::move(discs), boundary);
        TimeEngine all(scene, time_options(0.01, OverlapDetection::all_pairs));
        TimeEngine grid(scene, time_options(0.01, OverlapDetection::grid));
        REQUIRE(same_snapshots(all.snapshot(), grid.snapshot()));
        for (int frame = 1; frame <= 5; ++frame) {
            all.advance_to(frame * 0.02);
            grid.advance_to(frame * 0.02);
            REQUIRE(same_snapshots(all.snapshot(), grid.snapshot()));
        }
        CHECK(all.measurements().collisions_pair > 0);
        CHECK(all.measurements().collisions_pair == grid.measurements().collisions_pair);
        CHECK(all.measurements().missed_collisions == grid.measurements().missed_collisions);
    }
}

TEST_CASE("a periodic box wraps discs around") {
    const Scene scene =
        make_scene(1.0, 1.0, {make_disc({0.95, 0.5}, {1.0, 0.0}, 0.01)}, Boundary::periodic);
    TimeEngine engine(scene, time_options(0.01));
    engine.advance_to(0.1);
    CHECK(engine.snapshot().discs[0].position.x == doctest::Approx(0.05));
    CHECK(engine.measurements().escaped == 0);
    CHECK(engine.measurements().msd == doctest::Approx(0.01));  // unwrapped displacement 0.1
}

TEST_CASE("determinism: the same scene twice gives identical snapshots and collisions") {
    const Scene scene = random_gas(8, 0.015, 1.0, 5, Boundary::walls);
    std::vector<CollisionRecord> first;
    std::vector<CollisionRecord> second;
    TimeEngine a(scene, time_options(0.02));
    TimeEngine b(scene, time_options(0.02));
    a.set_collision_listener([&](const CollisionRecord& c) { first.push_back(c); });
    b.set_collision_listener([&](const CollisionRecord& c) { second.push_back(c); });
    for (int frame = 1; frame <= 15; ++frame) {
        a.advance_to(frame / 30.0);
        b.advance_to(frame / 30.0);
        REQUIRE(same_snapshots(a.snapshot(), b.snapshot()));
    }
    REQUIRE(first.size() == second.size());
    CHECK(!first.empty());
    for (std::size_t i = 0; i < first.size(); ++i) {
        CHECK(first[i].t == second[i].t);
        CHECK(first[i].a == second[i].a);
        CHECK(first[i].b == second[i].b);
    }
}

TEST_CASE("energy is conserved by resolutions, the drift stays at rounding level") {
    const Scene scene = random_gas(8, 0.015, 1.0, 9, Boundary::walls);
    TimeEngine engine(scene, time_options(0.005));
    engine.advance_to(1.0);
    const Measurements m = engine.measurements();
    CHECK(m.collisions_pair + m.collisions_wall > 10);
    CHECK(std::fabs(m.energy_drift) < 1e-12);
    CHECK(m.kinetic_energy > 0.0);
    CHECK(m.pressure > 0.0);
    CHECK(m.packing_fraction == doctest::Approx(64 * 3.14159265358979 * 0.015 * 0.015));
}

TEST_CASE("grid: a periodic box too small for 3 cells per axis falls back to all pairs") {
    // reach = 2 r + 2 v_max dt is about 0.6 here: fewer than 3 cells fit across the unit box.
    const Scene scene = random_gas(4, 0.03, 1.0, 13, Boundary::periodic);  // N = 16
    TimeEngine all(scene, time_options(0.2, OverlapDetection::all_pairs));
    TimeEngine grid(scene, time_options(0.2, OverlapDetection::grid));
    all.advance_to(1.0);
    grid.advance_to(1.0);
    CHECK(grid.measurements().overlap_checks == 5 * (16 * 15 / 2));
    CHECK(same_snapshots(all.snapshot(), grid.snapshot()));
}

TEST_CASE("discs that overlapped in any frame stay counted after their overlap ends") {
    // A dense gas with long steps: resolutions push discs into others, seen at a frame's end
    // and parted a few steps later.
    const Scene scene = random_gas(10, 0.03, 1.0, 17, Boundary::walls);
    TimeEngine engine(scene, time_options(0.01, OverlapDetection::grid));
    std::vector<bool> seen(scene.discs.size(), false);
    std::size_t seen_count = 0;
    for (int frame = 1; frame <= 90; ++frame) {
        engine.advance_to(0.01 * frame);
        for (const auto& [i, j] : engine.snapshot().overlapping_pairs) {
            for (const std::uint32_t k : {i, j}) {
                if (!seen[k]) ++seen_count;
                seen[k] = true;
            }
        }
        CHECK(engine.measurements().discs_overlapped == seen_count);
    }
    const Measurements m = engine.measurements();
    REQUIRE(seen_count > 0);
    // More discs overlapped over the run than overlap at its end: the count kept them.
    std::vector<bool> now(scene.discs.size(), false);
    for (const auto& [i, j] : engine.snapshot().overlapping_pairs) now[i] = now[j] = true;
    CHECK(m.discs_overlapped >
          static_cast<std::uint64_t>(std::count(now.begin(), now.end(), true)));
    CHECK(m.discs_overlapped <= scene.discs.size());
}

TEST_CASE("a glancing pair found parting while it overlaps slides through: missed once") {
    // sigma = 0.1, impact parameter 0.09: the discs overlap while |x gap| < 0.0436, from
    // t = 0.156 to 0.244 (closest at 0.2). The check at 0.22 finds them overlapping but parting,
    // which nothing resolves; the event-driven engine bounces them at 0.156.
    const Scene scene = make_scene(
        1.0, 1.0,
        {make_disc({0.3, 0.5}, {1.0, 0.0}, 0.05), make_disc({0.5, 0.59}, {0.0, 0.0}, 0.05)});
    for (const double dt : {0.22, 0.2}) {
        CAPTURE(dt);
        TimeEngine engine(scene, time_options(dt));
        engine.advance_to(dt);
        CHECK(engine.measurements().collisions_pair == 0);
        CHECK(engine.measurements().overlapping_pairs == 1);  // the overlap is there to see
        CHECK(engine.measurements().missed_collisions == 1);
        REQUIRE(engine.snapshot().missed_collisions.size() == 1);
        // Marked where they touched: x = 0.3 + 0.156 plus half the contact vector.
        CHECK(engine.snapshot().missed_collisions[0].x ==
              doctest::Approx(0.3 + (0.2 - 0.04359) + 0.5 * 0.04359).epsilon(1e-3));
        engine.advance_to(2.0 * dt);
        // Gone through: one missed collision, counted once, and one disc pair that overlapped.
        const Measurements m = engine.measurements();
        CHECK(m.collisions_pair == 0);
        CHECK(m.missed_collisions == 1);
        CHECK(m.overlapping_pairs == 0);
        CHECK(m.discs_overlapped == 2);
        engine.advance_to(3.0 * dt);
        CHECK(engine.measurements().missed_collisions == 1);
    }
    const std::unique_ptr<Engine> event = make_engine(scene, EngineOptions{});
    event->advance_to(0.22);
    CHECK(event->measurements().collisions_pair == 1);
}
