// Engine::set_stop_flag: a long advance_to() stops between two events once the flag is set (how
// Ctrl-C reaches a run with a huge --until or --speed), and the engine stays usable.

#include <doctest/doctest.h>

#include <atomic>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "collide/error.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/fast_engine.hpp"
#include "scene_fixtures.hpp"
#include "sphere_fixtures.hpp"

using namespace collide;
using collide::test::lattice_fluid;

namespace {

struct StopChoice {
    const char* engine;
    const char* pq;
};

std::unique_ptr<Engine> make_stopping(const std::string& engine, const std::string& queue,
                                      const Scene& scene) {
    EngineOptions options;
    options.engine = parse_engine_kind(engine);
    options.pq = pq::parse_queue_kind(queue);
    options.dt = 1e-3;
    return make_engine(scene, options);
}

/// An engine that polls `stop`.
std::unique_ptr<Engine> make_flagged(const StopChoice& kind, const Scene& scene,
                                     const std::atomic<bool>& stop) {
    auto engine = make_stopping(kind.engine, kind.pq, scene);
    engine->set_stop_flag(&stop);
    return engine;
}

/// Runs advance_to(t) and returns the message of the Error(runtime) it throws ("" if none).
std::string stop_message(Engine& engine, double t) {
    try {
        engine.advance_to(t);
    } catch (const Error& e) {
        CHECK(e.kind() == ErrorKind::runtime);
        return e.what();
    }
    return "";
}

/// The stop is polled in each engine's own loop, whatever the classic engine's queue.
constexpr StopChoice all_kinds[] = {{"fast", "binary"}, {"classic", "binary"}, {"time", "binary"}};

}  // namespace

TEST_CASE("a set stop flag ends an endless advance_to with an error, between two events") {
    for (const StopChoice kind : all_kinds) {
        CAPTURE(kind.engine);
        CAPTURE(kind.pq);
        const std::atomic<bool> stop{true};
        auto engine = make_flagged(kind, lattice_fluid(8, 0.4, Boundary::walls, 3), stop);
        // Millions of events or steps ahead: seconds of work if the flag were ignored (and then
        // no error), a few microseconds when it is seen.
        const bool stepped = std::strcmp(kind.engine, "time") == 0;
        CHECK(stop_message(*engine, stepped ? 1e3 : 1e4) == "simulation stopped");
        CHECK(engine->time() >= 0.0);
        CHECK(engine->time() < 1.0);
        CHECK(engine->measurements().max_overlap <= 1e-9);
    }
}

// Scenes are small: the sanitizer build validates every queue after every change, and the
// classic engine's queue holds dozens of events per disc.
TEST_CASE("an unset or absent stop flag changes nothing") {
    for (const StopChoice kind : all_kinds) {
        CAPTURE(kind.engine);
        CAPTURE(kind.pq);
        const Scene scene = lattice_fluid(5, 0.4, Boundary::walls, 5);
        const std::atomic<bool> stop{false};
        auto flagged = make_flagged(kind, scene, stop);
        auto plain = make_stopping(kind.engine, kind.pq, scene);
        // The same frames for both (the time-driven engine's steps restart at each call), far
        // enough for the flag to be looked at twice (every 1024 events, or every step).
        double t = 0.0;
        while (plain->measurements().events < 2 * 1024 && t < 100.0) {
            t += 0.05;
            plain->advance_to(t);
            CHECK(stop_message(*flagged, t).empty());
        }
        const Measurements a = flagged->measurements();
        const Measurements b = plain->measurements();
        CHECK((a.events >= 2 * 1024 || a.steps >= 2));
        CHECK(a.collisions_pair == b.collisions_pair);
        CHECK(a.kinetic_energy == b.kinetic_energy);
        flagged->set_stop_flag(nullptr);
        CHECK(stop_message(*flagged, t + 0.1).empty());
    }
}

// The stop lands between two events, so an engine stopped in the middle of a run and then run
// on (flag cleared) produces the very same collisions as one that was never stopped.
TEST_CASE("event-driven engines stopped mid-run and resumed give the identical event sequence") {
    for (const StopChoice kind : {StopChoice{"fast", "binary"}, StopChoice{"classic", "binary"}}) {
        CAPTURE(kind.engine);
        const Scene scene = lattice_fluid(5, 0.5, Boundary::walls, 9);
        const double end = 0.6;
        auto reference = make_stopping(kind.engine, kind.pq, scene);
        std::vector<CollisionRecord> expected;
        reference->set_collision_listener([&](const CollisionRecord& r) { expected.push_back(r); });
        reference->advance_to(end);
        REQUIRE(reference->measurements().events > 2 * 1024 + 200);

        auto engine = make_stopping(kind.engine, kind.pq, scene);
        std::atomic<bool> stop{false};
        std::vector<CollisionRecord> got;
        engine->set_collision_listener([&](const CollisionRecord& r) {
            got.push_back(r);
            if (got.size() == 100 || got.size() == 1400) stop = true;  // twice, mid-frame
        });
        engine->set_stop_flag(&stop);
        int stops = 0;
        for (;;) {
            const std::string message = stop_message(*engine, end);
            if (message.empty()) break;
            CHECK(message == "simulation stopped");
            CHECK(engine->time() < end);
            ++stops;
            stop = false;
        }
        CHECK(stops == 2);
        REQUIRE(got.size() == expected.size());
        for (std::size_t k = 0; k < got.size(); ++k) {
            INFO("collision #" << k);
            REQUIRE(got[k].t == expected[k].t);
            REQUIRE(got[k].kind == expected[k].kind);
            REQUIRE(got[k].a == expected[k].a);
            REQUIRE(got[k].b == expected[k].b);
        }
        CHECK(engine->time() == end);
    }
}

TEST_CASE("the fast engine's invariants hold after a stop") {
    const Scene scene = lattice_fluid(10, 0.5, Boundary::periodic, 21);
    sim::FastEngine engine(scene);
    std::atomic<bool> stop{false};
    std::size_t collisions = 0;
    engine.set_collision_listener([&](const CollisionRecord&) {
        if (++collisions == 3000) stop = true;
    });
    engine.set_stop_flag(&stop);
    CHECK(stop_message(engine, 10.0) == "simulation stopped");
    CHECK(engine.check_invariants());
    // Stopped within one polling interval of the request.
    CHECK(collisions >= 3000);
    CHECK(collisions < 3000 + 1024);
}

// Ctrl-C during one long step (issue 15, item 9). Each scene is large enough that finishing the
// step would take seconds (minutes in the sanitizer build): the flag is set beforehand, so the
// step must throw instead of completing, and the test cannot hang.
TEST_CASE("the classic engine's initial O(N^2) prediction stops when the flag is set") {
    const Scene scene = lattice_fluid(142, 0.3, Boundary::walls, 3);  // 20164 discs: 2e8 pairs
    const std::atomic<bool> stop{true};
    auto engine = make_flagged({"classic", "binary"}, scene, stop);
    CHECK(stop_message(*engine, 1.0) == "simulation stopped");
    // Not one row predicted (the constructor used to predict them all before the flag was set).
    CHECK(engine->measurements().predictions == 0);
    CHECK(engine->measurements().queue.pushes == 0);
    CHECK(engine->time() == 0.0);
}

TEST_CASE("a stopped classic engine resumes its initial prediction and gives the same events") {
    const Scene scene = lattice_fluid(5, 0.5, Boundary::walls, 9);
    auto reference = make_stopping("classic", "binary", scene);
    std::vector<CollisionRecord> expected;
    reference->set_collision_listener([&](const CollisionRecord& r) { expected.push_back(r); });
    reference->advance_to(0.05);
    std::atomic<bool> stop{true};
    auto engine = make_flagged({"classic", "binary"}, scene, stop);
    std::vector<CollisionRecord> got;
    engine->set_collision_listener([&](const CollisionRecord& r) { got.push_back(r); });
    CHECK(stop_message(*engine, 0.05) == "simulation stopped");
    stop = false;
    CHECK(stop_message(*engine, 0.05).empty());
    REQUIRE(got.size() > 10);
    REQUIRE(got.size() == expected.size());
    for (std::size_t k = 0; k < got.size(); ++k) {
        REQUIRE(got[k].t == expected[k].t);
        REQUIRE(got[k].a == expected[k].a);
        REQUIRE(got[k].b == expected[k].b);
    }
}

TEST_CASE("a time-driven step over many discs stops, and leaves the discs where they were") {
    for (const char* detect : {"all-pairs", "grid"}) {
        CAPTURE(std::string(detect));
        const Scene scene = lattice_fluid(142, 0.3, Boundary::walls, 3);
        EngineOptions options;
        options.engine = EngineKind::time;
        options.dt = 1.0;  // one step over 20164 discs
        options.td_detect = parse_overlap_detection(detect);
        auto engine = make_engine(scene, options);
        const Snapshot before = engine->snapshot();
        const std::atomic<bool> stop{true};
        engine->set_stop_flag(&stop);
        CHECK(stop_message(*engine, 1.0) == "simulation stopped");
        CHECK(engine->time() == 0.0);
        const Snapshot after = engine->snapshot();
        REQUIRE(after.discs.size() == before.discs.size());
        for (std::size_t i = 0; i < after.discs.size(); ++i) {
            REQUIRE(norm(after.discs[i].position - before.discs[i].position) < 1e-12);
        }
    }
}

// A signal while a large scene's engine is built (issue 48, item 9): the fast engine predicts
// every particle's first event in its constructor (4 M spheres: seconds), so make_engine takes
// the flag in EngineOptions and looks at it while building.
TEST_CASE("a set stop flag ends the building of every engine, and the flag stays with it") {
    const SphereScene spheres = collide::test::fcc_fluid(12, 0.45);     // 6912 spheres, with lists
    const Scene discs = lattice_fluid(90, 0.3, Boundary::periodic, 5);  // 8100 discs
    for (const StopChoice& kind : all_kinds) {
        CAPTURE(kind.engine);
        std::atomic<bool> stop{true};
        EngineOptions options;
        options.engine = parse_engine_kind(kind.engine);
        options.dt = 1e-3;
        options.stop = &stop;
        const auto built = [&](const auto& scene) -> std::string {
            try {
                (void)make_engine(scene, options);
            } catch (const Error& e) {
                CHECK(e.kind() == ErrorKind::runtime);
                return e.what();
            }
            return "";
        };
        const bool fast = kind.engine == std::string("fast");
        // The classic and time-driven engines only copy the scene (O(N)) and stop in their loops.
        CHECK(built(spheres) == (fast ? "simulation stopped" : ""));
        CHECK(built(discs) == (fast ? "simulation stopped" : ""));
        // Unset, the engine is built and keeps the flag: setting it stops the first advance.
        stop = false;
        std::unique_ptr<SphereEngine> engine = make_engine(spheres, options);
        stop = true;
        try {
            engine->advance_to(10.0);
            FAIL("advance_to ran to its end with the stop flag set");
        } catch (const Error& e) {
            CHECK(std::string(e.what()) == "simulation stopped");
        }
    }
}

TEST_CASE("the fast engine's constructor stops within a few thousand predictions of the flag") {
    // Set before: the constructor throws before its predictions, whatever the scene's size;
    // unset, it predicts every sphere's first event.
    const SphereScene scene = collide::test::fcc_fluid(16, 0.3);  // 16384 spheres, no lists
    const std::atomic<bool> stop{true};
    CHECK_THROWS_WITH_AS(sim::BasicFastEngine<3>(scene, &stop), "simulation stopped", Error);
    const std::atomic<bool> go{false};
    const sim::BasicFastEngine<3> built(scene, &go);
    CHECK(built.measurements().predictions >= scene.spheres.size());
}
