// Work estimates: the kinetic-theory collision rate against the engine's own count, steps and
// overlap checks, dt below the clock's resolution, and which limit a run exceeds.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "collide/sim/engine.hpp"
#include "collide/sim/work_estimate.hpp"
#include "scene_fixtures.hpp"

using namespace collide;

namespace {

Scene one_disc(Vec2 velocity) {
    Scene s;
    s.box = Box{1.0, 1.0, Boundary::walls};
    s.discs.push_back(Disc{{0.5, 0.5}, velocity, 0.01, 1.0, {}, ""});
    return s;
}

}  // namespace

TEST_CASE("work: collision and crossing rates are within 15 % of a melted gas's actual counts") {
    for (const Boundary boundary : {Boundary::walls, Boundary::periodic}) {
        for (const double eta : {0.05, 0.3, 0.5}) {
            CAPTURE(eta);
            CAPTURE(static_cast<int>(boundary));
            const Scene gas = test::lattice_fluid(16, eta, boundary, 7);
            EngineOptions options;
            std::unique_ptr<Engine> engine = make_engine(gas, options);
            engine->advance_to(0.5);  // the lattice melts first
            const Measurements before = engine->measurements();
            engine->advance_to(1.5);
            const Measurements after = engine->measurements();
            const CollisionRate rate = collision_rate(gas);
            const auto pairs = static_cast<double>(after.collisions_pair - before.collisions_pair);
            const auto walls = static_cast<double>(after.collisions_wall - before.collisions_wall);
            CHECK(rate.pairs == doctest::Approx(pairs).epsilon(0.15));
            CHECK(rate.walls == doctest::Approx(walls).epsilon(0.15));
            const auto crossings =
                static_cast<double>(after.cell_crossings - before.cell_crossings);
            CHECK(cell_crossing_rate(gas) == doctest::Approx(crossings).epsilon(0.15));
        }
    }
}

TEST_CASE("work: a single fast disc's wall hits and no pairs, and nothing moving is no work") {
    const CollisionRate rate = collision_rate(one_disc({1e50, 0.0}));
    CHECK(rate.pairs == 0.0);
    CHECK(rate.walls > 1e50);
    RunShape run;
    run.span = 10.0;
    run.event_driven = true;
    CHECK(estimate_work(one_disc({1e50, 0.0}), run).collisions > 1e50);
    CHECK(estimate_work(one_disc({0.0, 0.0}), run).collisions == 0.0);
    // An ordinary disc: about (2/pi) (1 + 1) = 1.27 hits per time unit at speed 1, against the
    // true 1 / 0.98 = 1.02 (it moves along x only): the right order of magnitude.
    CHECK(collision_rate(one_disc({1.0, 0.0})).walls ==
          doctest::Approx(4.0 / std::numbers::pi).epsilon(0.01));
}

TEST_CASE("work: time-driven steps are span / dt, checks N(N-1)/2 per step or ~10 N with a grid") {
    Scene s = test::lattice_fluid(10, 0.2, Boundary::walls, 1);
    RunShape run;
    run.span = 10.0;
    run.time_driven = true;
    run.dt = 0.01;
    const WorkEstimate all = estimate_work(s, run);
    CHECK(all.steps == doctest::Approx(1000.0));
    CHECK(all.pair_checks == doctest::Approx(1000.0 * 100.0 * 99.0 / 2.0));
    CHECK_FALSE(all.dt_below_resolution);
    CHECK(all.collisions == 0.0);  // no event-driven engine in this run
    run.all_pairs = false;
    CHECK(estimate_work(s, run).pair_checks ==
          doctest::Approx(1000.0 * 100.0 * grid_checks_per_disc));
}

TEST_CASE("work: a dt with t + dt == t at the run's end is flagged, a tiny but usable one is not") {
    const Scene s = one_disc({1.0, 0.0});
    RunShape run;
    run.span = 10.0;
    run.time_driven = true;
    run.dt = 1e-300;
    const WorkEstimate hopeless = estimate_work(s, run);
    CHECK(hopeless.dt_below_resolution);
    CHECK(hopeless.steps == doctest::Approx(1e301));
    run.dt = 1e-13;  // about 50 ulps of 10: slow, but the clock moves
    CHECK_FALSE(estimate_work(s, run).dt_below_resolution);
}

TEST_CASE("work: first_excess names the limit exceeded the most, or none") {
    WorkEstimate work;
    CHECK(first_excess(work).what.empty());
    work.collisions = 5e9;
    work.steps = 1e8;
    CHECK(first_excess(work).what.empty());  // within every limit
    work.collisions = 3e10;
    work.steps = 1e11;  // 100 x its limit beats 3 x
    const WorkExcess e = first_excess(work);
    CHECK(e.what == "time-driven steps");
    work.crossings = 1e12;  // events: collisions and crossings, 103 x the limit
    CHECK(first_excess(work).what == "events");
    work.crossings = 0.0;
    CHECK(e.estimate == 1e11);
    CHECK(e.fitting_fraction() == doctest::Approx(1e-2));
    work.frames = std::numeric_limits<double>::infinity();
    CHECK(first_excess(work).what == "frames");
}

TEST_CASE("work: rough_number is short and exact for small counts") {
    CHECK(rough_number(4500.0) == "4500");
    CHECK(rough_number(0.0123456) == "0.0123");
    CHECK(rough_number(3.21e12) == "3.2e+12");
    CHECK(rough_number(std::numeric_limits<double>::infinity()) == "infinitely many");
}

TEST_CASE("work: cell crossings of the fast engine: a lone disc in a periodic box never rests") {
    Scene s;
    s.box = Box{1.0, 1.0, Boundary::periodic};
    s.discs.push_back(Disc{{0.5, 0.5}, {1.0, 0.3}, 0.01, 1.0, {}, ""});
    EngineOptions options;
    std::unique_ptr<Engine> engine = make_engine(s, options);
    engine->advance_to(1000.0);
    const auto actual = static_cast<double>(engine->measurements().cell_crossings) / 1000.0;
    CHECK(cell_crossing_rate(s) == doctest::Approx(actual).epsilon(0.1));
    RunShape run;
    run.span = 1e300;
    run.event_driven = true;
    CHECK(estimate_work(s, run).crossings == 0.0);  // the classic engine has no cells
    run.cell_grid = true;
    CHECK(first_excess(estimate_work(s, run)).what == "events");
}

TEST_CASE("work: the classic engine costs 2 N predictions an event, an array queue its length") {
    // Before, the limits counted events only: 200,000 discs with --engine classic (each event
    // predicted against every disc) or an unordered queue (each removal scans the whole array)
    // were accepted and would have run for days.
    const Scene s = test::lattice_fluid(30, 0.3, Boundary::walls, 1);
    const double n = static_cast<double>(s.discs.size());
    RunShape run;
    run.span = 5.0;
    run.event_driven = true;
    const WorkEstimate fast = estimate_work(s, run);
    CHECK(fast.predictions == 0.0);
    CHECK(fast.queue_steps == 0.0);
    run.classic = true;
    const WorkEstimate classic = estimate_work(s, run);
    CHECK(classic.collisions == doctest::Approx(fast.collisions));
    CHECK(classic.predictions == doctest::Approx(n * (n - 1.0) / 2.0 + fast.collisions * 2.0 * n));
    CHECK(classic.queue_steps == 0.0);  // a heap: O(log) per operation
    run.array_queue = true;
    const WorkEstimate array = estimate_work(s, run);
    const double pushed = std::max(2.0, classic_finite_fraction * 2.0 * n);
    CHECK(array.queue_steps ==
          doctest::Approx(fast.collisions * n + pushed * fast.collisions * fast.collisions / 2.0));
    // Each is a limit of its own, named when it is the one exceeded.
    WorkEstimate work;
    work.predictions = 2e11;
    CHECK(first_excess(work).what == "pair predictions");
    work.queue_steps = 1e13;
    CHECK(first_excess(work).what == "queue steps");
}
