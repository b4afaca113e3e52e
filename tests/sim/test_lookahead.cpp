// sim::CollisionLookahead and Engine::clone: the next collision the lesson draws is exactly the
// one the watched engine resolves next, and looking ahead (the engine run a frame early, copies
// run further) leaves the engine's own history bit for bit as if nobody had looked.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "collide/sim/lookahead.hpp"
#include "collide/sim/pq/queue_kind.hpp"
#include "scene_fixtures.hpp"
#include "sphere_fixtures.hpp"

using namespace collide;

namespace {

/// Frame times with holds (every fifth frame repeats the one before), as a video's timeline
/// gives them: the look ahead must take the same calls in the same order, repeats included.
double frame_time(double interval, std::int64_t k) {
    return interval * static_cast<double>(k - k / 5);
}

bool same(const CollisionRecord& x, const CollisionRecord& y) {
    return x.t == y.t && x.kind == y.kind && x.a == y.a && x.b == y.b;
}

/// Exact equality of the discs' motion (bits, not tolerances).
bool same_motion(const Snapshot& x, const Snapshot& y) {
    if (x.time != y.time || x.discs.size() != y.discs.size()) return false;
    for (std::size_t i = 0; i < x.discs.size(); ++i) {
        const DiscState& a = x.discs[i];
        const DiscState& b = y.discs[i];
        if (a.position.x != b.position.x || a.position.y != b.position.y ||
            a.velocity.x != b.velocity.x || a.velocity.y != b.velocity.y)
            return false;
    }
    return true;
}

struct Reference {
    std::vector<CollisionRecord> log;  ///< every collision, frames and look-ahead frames
    std::vector<Snapshot> frames;      ///< the engine at each video frame
};

/// An engine nobody looks ahead of, advanced to every frame time (and `extra` more past the
/// last frame): what it resolves and how it stands at each frame.
Reference reference_run(const Scene& scene, const EngineOptions& options, std::int64_t frames,
                        std::int64_t extra, double interval) {
    Reference ref;
    const std::unique_ptr<Engine> engine = make_engine(scene, options);
    engine->set_collision_listener([&](const CollisionRecord& r) { ref.log.push_back(r); });
    for (std::int64_t k = 0; k < frames + extra; ++k) {
        engine->advance_to(std::max(frame_time(interval, k), engine->time()));
        if (k < frames) ref.frames.push_back(engine->snapshot());
    }
    return ref;
}

/// Runs a video of `frames` frames with a look ahead of `extra` frames past its end, and checks
/// every frame: the engine stands as the reference does, and the look ahead's answer is the
/// reference's first collision after the frame's time. Returns how many frames had an answer.
int check_video(const Scene& scene, const EngineOptions& options, std::int64_t frames,
                std::int64_t extra, double interval) {
    const Reference ref = reference_run(scene, options, frames, extra, interval);
    const std::unique_ptr<Engine> engine = make_engine(scene, options);
    sim::CollisionLookahead lookahead(*engine);
    int answered = 0;
    for (std::int64_t k = 0; k < frames; ++k) {
        CAPTURE(k);
        engine->advance_to(std::max(frame_time(interval, k), engine->time()));
        const Snapshot now = engine->snapshot();
        REQUIRE(same_motion(now, ref.frames[static_cast<std::size_t>(k)]));
        const sim::FramesAhead ahead{
            [interval, k](std::int64_t i) { return frame_time(interval, k + i); }, frames - 1 - k,
            frames + extra - 1 - k};
        const std::optional<CollisionRecord> next = lookahead.next(ahead);
        const auto truth = std::find_if(ref.log.begin(), ref.log.end(),
                                        [&](const CollisionRecord& r) { return r.t > now.time; });
        REQUIRE(next.has_value() == (truth != ref.log.end()));
        if (!next) continue;
        CHECK(same(*next, *truth));
        ++answered;
    }
    return answered;
}

EngineOptions classic_on(const std::string& queue) {
    EngineOptions options;
    options.engine = EngineKind::classic;
    options.pq = pq::parse_queue_kind(queue);
    return options;
}

}  // namespace

TEST_CASE("lookahead: the next collision is the one the engine resolves next, every frame") {
    // Dense: collisions in every frame (the engine itself runs a frame early; a copy only past
    // the last frame). Sparse, fine frames: most frames pass without one (copies run ahead).
    // Small enough for the sanitizer build's time limit (the classic engine on an array queue
    // does O(N) work per event, and every frame is checked against a reference run).
    const Scene dense = test::lattice_fluid(6, 0.4, Boundary::walls, 11);
    const Scene dense_periodic = test::lattice_fluid(6, 0.4, Boundary::periodic, 12);
    const Scene sparse = test::lattice_fluid(3, 0.02, Boundary::walls, 13);
    SUBCASE("fast engine") {
        CHECK(check_video(dense, EngineOptions{}, 30, 20, 1.0 / 30.0) == 30);
        CHECK(check_video(dense_periodic, EngineOptions{}, 30, 20, 1.0 / 30.0) == 30);
        CHECK(check_video(sparse, EngineOptions{}, 60, 30, 1.0 / 240.0) == 60);
    }
    SUBCASE("classic engine on several queues") {
        // Fewer frames: the classic loop's queue holds every stale event, and the sanitizer
        // build checks the whole queue's invariants at each operation.
        const Scene small = test::lattice_fluid(4, 0.4, Boundary::walls, 15);
        for (const std::string queue : {"binary", "ordered", "dary:3", "indexed:4"}) {
            CAPTURE(queue);
            CHECK(check_video(small, classic_on(queue), 10, 5, 1.0 / 30.0) == 10);
            CHECK(check_video(sparse, classic_on(queue), 20, 10, 1.0 / 240.0) == 20);
        }
    }
    SUBCASE("nothing within reach: no answer, and the engine is still where it should be") {
        // One disc at rest: nothing ever happens.
        Scene still = test::lattice_fluid(3, 0.02, Boundary::walls, 14);
        still.discs.resize(1);
        still.discs[0].velocity = {0.0, 0.0};
        CHECK(check_video(still, EngineOptions{}, 20, 10, 1.0 / 30.0) == 0);
    }
}

namespace {

/// The engine's collisions while it is advanced to each time in turn.
template <class E>
std::vector<CollisionRecord> collisions_over(E& engine, const std::vector<double>& times) {
    std::vector<CollisionRecord> log;
    engine.set_collision_listener([&](const CollisionRecord& r) { log.push_back(r); });
    for (double t : times) engine.advance_to(t);
    engine.set_collision_listener(nullptr);
    return log;
}

bool same_logs(const std::vector<CollisionRecord>& x, const std::vector<CollisionRecord>& y) {
    return std::equal(x.begin(), x.end(), y.begin(), y.end(), same);
}

bool same_motion(const SphereSnapshot& x, const SphereSnapshot& y) {
    if (x.time != y.time || x.spheres.size() != y.spheres.size()) return false;
    for (std::size_t i = 0; i < x.spheres.size(); ++i) {
        const SphereState& a = x.spheres[i];
        const SphereState& b = y.spheres[i];
        if (a.position.x != b.position.x || a.position.y != b.position.y ||
            a.position.z != b.position.z || a.velocity.x != b.velocity.x ||
            a.velocity.y != b.velocity.y || a.velocity.z != b.velocity.z)
            return false;
    }
    return true;
}

/// Copies an engine midway and checks that the copy and the engine each go on exactly as an
/// engine never copied does, that the copy does not call the engine's listener, and that their
/// counters are the same.
template <class SceneType>
void check_clone(const SceneType& scene, const EngineOptions& options) {
    const auto never_copied = make_engine(scene, options);
    const auto engine = make_engine(scene, options);
    const std::vector<double> before = {0.01, 0.05, 0.05, 0.1};
    const std::vector<double> after = {0.13, 0.2, 0.2, 0.31};
    CHECK(same_logs(collisions_over(*engine, before), collisions_over(*never_copied, before)));

    int heard_by_engine = 0;
    engine->set_collision_listener([&](const CollisionRecord&) { ++heard_by_engine; });
    const auto copy = engine->clone();
    REQUIRE(copy != nullptr);
    CHECK(copy->time() == engine->time());
    const std::vector<CollisionRecord> truth = collisions_over(*never_copied, after);
    REQUIRE_FALSE(truth.empty());  // the test looks at something
    CHECK(same_logs(collisions_over(*copy, after), truth));
    CHECK(heard_by_engine == 0);  // the copy has a listener of its own (none), not the engine's
    CHECK(same_motion(copy->snapshot(), never_copied->snapshot()));
    // The engine, copied and then left behind, goes on as if it never had been.
    CHECK(engine->time() == before.back());
    CHECK(same_logs(collisions_over(*engine, after), truth));
    CHECK(same_motion(engine->snapshot(), never_copied->snapshot()));
    const Measurements m = engine->measurements();
    const Measurements c = copy->measurements();
    const Measurements n = never_copied->measurements();
    CHECK(m.events == n.events);
    CHECK(c.events == n.events);
    CHECK(m.predictions == n.predictions);
    CHECK(c.queue.pops == n.queue.pops);
}

}  // namespace

TEST_CASE("clone: a copy goes on like the engine, which goes on as if never copied") {
    const Scene discs = test::lattice_fluid(6, 0.4, Boundary::walls, 21);
    const Scene periodic = test::lattice_fluid(6, 0.4, Boundary::periodic, 22);
    SUBCASE("fast engine") {
        check_clone(discs, EngineOptions{});
        check_clone(periodic, EngineOptions{});
    }
    SUBCASE("classic engine, every queue family") {
        // 16 discs, as in the lookahead's classic loop: the classic queue holds every stale
        // event, and the sanitizer build checks all of it at each operation (36 discs took
        // about a minute of CPU there for the seven queues). A copy is a copy at any size.
        const Scene small = test::lattice_fluid(4, 0.4, Boundary::walls, 21);
        for (const std::string queue :
             {"unordered", "ordered", "binary", "dary:3", "dary:4", "dary:5", "indexed:2"}) {
            CAPTURE(queue);
            check_clone(small, classic_on(queue));
        }
    }
    SUBCASE("spheres") {
        const SphereScene spheres =
            test::fcc_fluid(2, 0.3, 23);  // 32: quick in the sanitizer build
        check_clone(spheres, EngineOptions{});
        check_clone(spheres, classic_on("binary"));
    }
    SUBCASE("the time-driven engine has no copy (nothing looks ahead of it)") {
        EngineOptions options;
        options.engine = EngineKind::time;
        CHECK(make_engine(discs, options)->clone() == nullptr);
    }
}
