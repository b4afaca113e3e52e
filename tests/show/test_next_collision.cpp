// The event-driven panel's next collision line (show::next_collision_view over what
// sim::CollisionLookahead says comes next): the drawn pair and time to go are those of the
// collision the engine resolves next, found independently by stepping a fresh engine to it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "../sim/scene_fixtures.hpp"
#include "collide/show/collision.hpp"
#include "collide/sim/lookahead.hpp"
#include "frame_clock_fixture.hpp"

using namespace collide;
using namespace collide::show;

namespace {

using test::clock_of;

/// The first collision a fresh engine resolves after frame k, stepped to it the way a video
/// steps it: to each frame time up to k, then on in small steps.
std::optional<CollisionRecord> stepped_next(const Scene& scene, const EngineOptions& options,
                                            const FrameClock& clock, std::int64_t k) {
    const std::unique_ptr<Engine> engine = make_engine(scene, options);
    for (std::int64_t j = 0; j <= k; ++j) engine->advance_to(clock.time(j));
    std::optional<CollisionRecord> first;
    engine->set_collision_listener([&](const CollisionRecord& r) {
        if (!first) first = r;
    });
    const double now = engine->time();
    for (int step = 1; step <= 4000 && !first; ++step) engine->advance_to(now + step * 1e-3);
    return first;
}

/// The times a video's frames advance its engine to, then on past the last frame (as the app's
/// FrameSource gives them to the look ahead).
double frame_time(const FrameClock& clock, std::int64_t j) {
    return j < clock.count
               ? clock.time(j)
               : clock.last_time + static_cast<double>(j - clock.count + 1) * clock.interval;
}

/// What the look ahead sees past frame k: the video's remaining frames, then 300 more.
sim::FramesAhead frames_after(const FrameClock& clock, std::int64_t k) {
    return {[clock, k](std::int64_t i) { return frame_time(clock, k + i); }, clock.count - 1 - k,
            clock.count + 300 - 1 - k};
}

void check_matches_engine(const Scene& scene, EngineKind kind) {
    EngineOptions options;
    options.engine = kind;
    const FrameClock clock = clock_of(40, 1.0 / 30.0);
    const std::unique_ptr<Engine> engine = make_engine(scene, options);
    sim::CollisionLookahead lookahead(*engine);
    int drawn = 0;
    for (std::int64_t k = 0; k < clock.count; ++k) {
        engine->advance_to(std::max(clock.time(k), engine->time()));
        const Snapshot now = engine->snapshot();
        const std::optional<CollisionRecord> next = lookahead.next(frames_after(clock, k));
        if (k % 7 != 0) continue;
        CAPTURE(k);
        const std::optional<CollisionRecord> truth = stepped_next(scene, options, clock, k);
        REQUIRE(truth.has_value());
        REQUIRE(next.has_value());
        CHECK(next->kind == truth->kind);
        CHECK(next->a == truth->a);
        CHECK(next->b == truth->b);
        CHECK(next->t == doctest::Approx(truth->t).epsilon(1e-9));
        const NextCollisionView view = next_collision_view(*next, now, clock);
        REQUIRE_FALSE(view.lines.empty());
        // The line starts at the first disc's centre now and points at what it will hit.
        const DiscState& a = now.discs[truth->a];
        CHECK(view.lines[0].from.x == a.position.x);
        CHECK(view.lines[0].from.y == a.position.y);
        if (truth->kind == CollisionKind::pair) {
            const DiscState& b = now.discs[truth->b];
            const Vec2 d = now.box.displacement(a.position, b.position);
            const Vec2 to = view.lines[0].to - a.position;
            // At most one box width away from the partner's nearest image now (periodic boxes:
            // the image they meet may be another).
            CHECK(std::abs(std::remainder(to.x - d.x, now.box.width)) < 1e-9);
            CHECK(std::abs(std::remainder(to.y - d.y, now.box.height)) < 1e-9);
        }
        CHECK(view.text == next_collision_words(truth->t - now.time, clock));
        ++drawn;
    }
    CHECK(drawn == 6);
}

}  // namespace

TEST_CASE("next collision: the drawn pair and time are the engine's next collision") {
    SUBCASE("fast engine, walls") {
        check_matches_engine(test::lattice_fluid(10, 0.3, Boundary::walls, 7), EngineKind::fast);
    }
    SUBCASE("fast engine, periodic") {
        check_matches_engine(test::lattice_fluid(10, 0.3, Boundary::periodic, 8), EngineKind::fast);
    }
    SUBCASE("classic engine, walls") {
        check_matches_engine(test::lattice_fluid(8, 0.2, Boundary::walls, 9), EngineKind::classic);
    }
}

TEST_CASE("next collision: a wall hit is drawn to the point the disc will touch") {
    Scene scene;
    scene.box = Box{1.0, 1.0, Boundary::walls};
    Disc disc;
    disc.position = {0.5, 0.3};
    disc.velocity = {1.0, 0.25};
    disc.radius = 0.1;
    disc.mass = 1.0;
    scene.discs = {disc};
    const std::unique_ptr<Engine> engine = make_engine(scene, EngineOptions{});
    sim::CollisionLookahead lookahead(*engine);
    // A one-frame video of 1 s frames: only a copy of the engine looks past it.
    const std::optional<CollisionRecord> next =
        lookahead.next({[](std::int64_t i) { return static_cast<double>(i); }, 0, 1});
    REQUIRE(next.has_value());
    CHECK(next->kind == CollisionKind::xwall);
    CHECK(next->t == doctest::Approx(0.4));
    CHECK(engine->time() == 0.0);  // the engine itself stayed at the frame shown
    const NextCollisionView view =
        next_collision_view(*next, engine->snapshot(), clock_of(60, 1.0 / 30.0));
    REQUIRE(view.lines.size() == 1);
    CHECK(view.lines[0].to.x == doctest::Approx(1.0));  // on the wall
    CHECK(view.lines[0].to.y == doctest::Approx(0.4));  // where the centre will be then
    CHECK(view.text == "next hit in 0.40");
    CHECK(view.keep_clear.size() == 1);
}

TEST_CASE("next collision: in a periodic box the line crosses the edge in two pieces") {
    Scene scene;
    scene.box = Box{1.0, 1.0, Boundary::periodic};
    Disc a;
    a.position = {0.05, 0.5};
    a.velocity = {-0.5, 0.0};
    a.radius = 0.01;
    a.mass = 1.0;
    Disc b = a;
    b.position = {0.95, 0.5};
    b.velocity = {0.5, 0.0};
    scene.discs = {a, b};
    const std::unique_ptr<Engine> engine = make_engine(scene, EngineOptions{});
    const CollisionRecord next{0.08, CollisionKind::pair, 0, 1};
    const NextCollisionView view =
        next_collision_view(next, engine->snapshot(), clock_of(60, 1.0 / 30.0));
    REQUIRE(view.lines.size() == 2);
    // From a leftwards over the edge, and from b rightwards over the other: not across the box.
    CHECK(view.lines[0].to.x == doctest::Approx(-0.05));
    CHECK(view.lines[1].from.x == doctest::Approx(0.95));
    CHECK(view.lines[1].to.x == doctest::Approx(1.05));
    CHECK(view.label_at.x == doctest::Approx(0.0).epsilon(1e-12));
    CHECK(view.keep_clear.size() == 2);
}

TEST_CASE("next collision: its words use the lesson clock's decimals") {
    const FrameClock clock = clock_of(300, 1.0 / 30.0);  // the clock shows two decimals
    CHECK(next_collision_words(0.4213, clock) == "next hit in 0.42");
    CHECK(next_collision_words(12.0, clock) == "next hit in 12.00");
    CHECK(next_collision_words(0.001, clock) == "next hit in < 0.01");
    CHECK(next_collision_words(0.0, clock) == "next hit in < 0.01");
    CHECK(next_collision_words(0.4213, clock, true) == "in 0.42");  // a narrow box's
    CHECK(next_collision_words(0.0, clock, true) == "in < 0.01");
    const FrameClock slow = clock_of(300, 0.2);  // one decimal
    CHECK(next_collision_words(0.37, slow) == "next hit in 0.4");
}
