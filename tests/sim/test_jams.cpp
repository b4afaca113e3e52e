// Touching and jammed discs (issue 15, item 6): every engine makes progress on touching contacts
// (billiard racks, rows, lattices) and refuses a jam (a disc that cannot move along an axis but
// moves along it) instead of colliding forever at one instant; validation refuses the jams it can
// see, naming file, line and disc. Every run here ends at a finite time: a regression would hang
// until ctest's TIMEOUT on this suite (the classic engine's queue grew by ~0.5 GB/s meanwhile).

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "../support/input_error.hpp"
#include "collide/error.hpp"
#include "collide/sim/algs4.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/scene_check.hpp"

using namespace collide;
using collide::test::contains;
using collide::test::input_error_message;

namespace {

Disc disc(double x, double y, double vx, double vy, double r, double m = 1.0) {
    Disc d;
    d.position = {x, y};
    d.velocity = {vx, vy};
    d.radius = r;
    d.mass = m;
    return d;
}

Scene unit_box(std::vector<Disc> discs, Boundary boundary = Boundary::walls) {
    Scene s;
    s.box = Box{1.0, 1.0, boundary};
    s.discs = std::move(discs);
    return s;
}

struct Shape {
    const char* name;
    Scene scene;
};

// The campaign's shapes, with positions as a user would type them (1/6 + 1/3 is a rounding error
// away from 1/2, so "touching" discs are 1e-17 apart or overlap by as much).
std::vector<Shape> jammed_shapes() {
    const double sixth = 1.0 / 6.0;
    std::vector<Shape> shapes;
    shapes.push_back({"one disc as wide as the box", unit_box({disc(0.5, 0.5, 1.0, 0.0, 0.5)})});
    shapes.push_back({"three discs of radius 1/6 wall to wall",
                      unit_box({disc(sixth, 0.5, 1.0, 0.0, sixth), disc(0.5, 0.5, 0.0, 0.0, sixth),
                                disc(5.0 * sixth, 0.5, 0.0, 0.0, sixth)})});
    std::vector<Disc> row;
    for (int k = 0; k < 5; ++k)
        row.push_back(disc(0.1 + 0.2 * k, 0.5, k == 2 ? -0.7 : 0.0, 0.3, 0.1));
    shapes.push_back({"a touching row wall to wall", unit_box(row)});
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> speed(-1.0, 1.0);
    std::vector<Disc> lattice;
    // 2 x 2 only: the array queues are O(size) per operation (validated after each in the
    // sanitizer build), and the classic queue holds N events per collision up to the bound.
    for (int iy = 0; iy < 2; ++iy) {
        for (int ix = 0; ix < 2; ++ix) {
            lattice.push_back(disc(0.25 + 0.5 * ix, 0.25 + 0.5 * iy, speed(rng), speed(rng), 0.25));
        }
    }
    shapes.push_back({"a touching lattice filling the box", unit_box(lattice)});
    std::vector<Disc> ring;
    for (int k = 0; k < 5; ++k)
        ring.push_back(disc(0.1 + 0.2 * k, 0.5, k == 0 ? 1.0 : 0.0, 0.0, 0.1));
    shapes.push_back({"a touching ring around a periodic box", unit_box(ring, Boundary::periodic)});
    return shapes;
}

// Touching but free to move: the engines must simulate these, not refuse them.
std::vector<Shape> touching_free_shapes() {
    const double sixth = 1.0 / 6.0;
    std::vector<Shape> shapes;
    std::vector<Disc> cradle;  // a disc runs into a touching row (Newton's cradle, a rack)
    for (int k = 0; k < 6; ++k)
        cradle.push_back(disc(0.2 + 0.1 * k, 0.5, k == 0 ? 1.0 : 0.0, 0.0, 0.05));
    cradle[0].position.x = 0.1;
    shapes.push_back({"a disc into a touching row", unit_box(cradle)});
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> speed(-1.0, 1.0);
    std::vector<Disc> lattice;  // touching, random velocities, not wall to wall
    for (int iy = 0; iy < 4; ++iy) {
        for (int ix = 0; ix < 4; ++ix) {
            lattice.push_back(
                disc(0.25 + 0.05 + 0.1 * ix, 0.2 + 0.05 + 0.1 * iy, speed(rng), speed(rng), 0.05));
        }
    }
    shapes.push_back({"a touching lattice with random velocities", unit_box(lattice)});
    std::vector<Disc> masses;  // a long cascade at t = 0: masses from 0.1 to 10
    std::uniform_real_distribution<double> mass(0.1, 10.0);
    for (int k = 0; k < 25; ++k)
        masses.push_back(disc(0.1 + 0.02 * k, 0.5, speed(rng), 0.0, 0.01, mass(rng)));
    shapes.push_back({"a touching row of unequal masses", unit_box(masses)});
    // Jammed along x, moving along y only: they slide.
    shapes.push_back({"three wedged discs sliding along the walls",
                      unit_box({disc(sixth, 0.5, 0.0, 1.0, sixth), disc(0.5, 0.5, 0.0, -1.0, sixth),
                                disc(5.0 * sixth, 0.5, 0.0, 0.3, sixth)})});
    Scene tall = unit_box({disc(0.5, 0.5, 0.0, 1.0, 0.5)});
    tall.box.height = 2.0;
    shapes.push_back({"a disc as wide as a tall box moving along it", tall});
    std::vector<Disc> ring;  // a ring may move along itself as a whole
    for (int k = 0; k < 5; ++k) ring.push_back(disc(0.1 + 0.2 * k, 0.5, 0.5, 0.2, 0.1));
    shapes.push_back({"a touching ring moving as a whole", unit_box(ring, Boundary::periodic)});
    // Galperin's billiard: a light disc between a heavy one and the wall, all touching (~314
    // collisions at t = 0 for a mass ratio of 10^4).
    shapes.push_back({"a light disc between a heavy one and a wall",
                      unit_box({disc(0.125, 0.5, 0.0, 0.0, 0.125, 1.0),
                                disc(0.375, 0.5, -1.0, 0.0, 0.125, 1e4)})});
    return shapes;
}

struct EngineChoice {
    const char* engine;
    const char* pq;
    const char* td_detect;
};

// Every engine, the time-driven one with both detections. The classic engine's queues pop the
// same sequence (test_engines.cpp); each of them has its own test case below.
constexpr EngineChoice all_engines[] = {{"fast", "binary", "all-pairs"},
                                        {"classic", "binary", "all-pairs"},
                                        {"time", "binary", "all-pairs"},
                                        {"time", "binary", "grid"}};

std::unique_ptr<Engine> make(const EngineChoice& kind, const Scene& scene) {
    EngineOptions options;
    options.engine = parse_engine_kind(kind.engine);
    options.pq = pq::parse_queue_kind(kind.pq);
    options.dt = 1e-3;
    options.td_detect = parse_overlap_detection(kind.td_detect);
    return make_engine(scene, options);
}

bool is_time_driven(const EngineChoice& kind) {
    return std::string(kind.engine) == "time";
}

/// The most the classic engine can have pushed when its jam bound stops it: the initial
/// predictions, then at most 2 (N + 1) per collision, at most N bound's worth of collisions.
std::uint64_t classic_push_bound(std::size_t n) {
    const std::uint64_t limit = 1000 + 16 * n;
    return n * (n + 1) / 2 + 2 * n + 2 * (n + 1) * n * limit;
}

}  // namespace

TEST_CASE("validation refuses a jammed scene, naming the file, line, disc and why") {
    for (const Shape& shape : jammed_shapes()) {
        CAPTURE(std::string(shape.name));
        const std::string message = input_error_message([&] { validate_scene(shape.scene); });
        CHECK(contains(message, "velocity"));
        CHECK(contains(message, "forever"));
    }
    // Through the algs4 reader: file and line of the offending disc.
    std::istringstream text(
        "3\n"
        "0.16666666666666666 0.5 0 0 0.16666666666666666 1 0 0 0\n"
        "0.5 0.5 0.25 0 0.16666666666666666 1 0 0 0\n"
        "0.8333333333333334 0.5 0 0 0.16666666666666666 1 0 0 0\n");
    const ParsedScene parsed = parse_algs4(text, "rack.txt");
    const std::string message =
        input_error_message([&] { validate_scene(parsed.scene, parsed.origin); });
    CHECK(contains(message, "rack.txt:3: disc 2 velocity: moves along x (0.25)"));
    CHECK(contains(message, "wedged between the walls x = 0 and x = 1"));
    CHECK(contains(message, "straight row of 3 touching discs"));

    const std::string wide =
        input_error_message([&] { validate_scene(unit_box({disc(0.5, 0.5, 0.0, -2.0, 0.5)})); });
    CHECK(
        contains(wide, "disc 1 velocity: moves along y (-2), but the disc is as wide as the box"));
}

TEST_CASE("validation accepts touching discs that can move, and a bend in a row") {
    for (const Shape& shape : touching_free_shapes()) {
        CAPTURE(std::string(shape.name));
        CHECK(input_error_message([&] { validate_scene(shape.scene); }).empty());
    }
    // A row from wall to wall that is not straight (the middle disc 0.01 higher, the row shorter
    // than the box) can buckle: not a jam.
    const double r = 0.1;
    const double dx = std::sqrt(4 * r * r - 0.01 * 0.01);
    const Scene bent = unit_box({disc(r, 0.5, 1.0, 0.0, r), disc(r + dx, 0.51, 0.0, 0.0, r),
                                 disc(r + 2 * dx, 0.5, 0.0, 0.0, r)});
    CHECK(input_error_message([&] { validate_scene(bent); }).empty());
}

// The engines' own guard (sim::instant_collision_limit), for jams that validation does not see
// (here: the scenes reach the engines unvalidated). Each event engine throws an input error
// naming a jammed disc within about 1000 + 16 N collisions per disc; the time-driven engine has
// no instants to get stuck at and simply steps to the end.
TEST_CASE("every engine refuses or steps through a jam, in finite time") {
    for (const Shape& shape : jammed_shapes()) {
        for (const EngineChoice& kind : all_engines) {
            CAPTURE(std::string(shape.name));
            CAPTURE(std::string(kind.engine));
            CAPTURE(std::string(kind.td_detect));
            auto engine = make(kind, shape.scene);
            const std::string message = input_error_message([&] { engine->advance_to(1.0); });
            if (is_time_driven(kind)) {
                CHECK(message.empty());
                CHECK(engine->time() == 1.0);
            } else {
                CHECK(contains(message, "jammed at t = 0"));
                CHECK(contains(message, "collisions at one instant"));
                const Measurements m = engine->measurements();
                const std::size_t n = shape.scene.discs.size();
                // Stopped by the bound, not by running out of memory.
                CHECK(m.collisions_pair + m.collisions_wall <= n * (1000 + 16 * n));
                CHECK(m.queue.pushes <= classic_push_bound(n));
            }
        }
    }
}

// The classic engine's queue grew by ~0.5 GB/s on these shapes (N events pushed per collision,
// stale ones never popped): with every queue kind it now stops at the bound. The three wedged
// discs only: the array queues cost O(size) per operation, validated after each in the sanitizer
// build.
TEST_CASE("the classic engine's queue stays bounded on a jam, whatever the queue") {
    const Shape three = jammed_shapes()[1];
    for (const char* pq : {"unordered", "ordered", "binary", "dary:4", "indexed", "indexed:8"}) {
        CAPTURE(std::string(pq));
        auto engine = make({"classic", pq, "all-pairs"}, three.scene);
        const std::string message = input_error_message([&] { engine->advance_to(1.0); });
        CHECK(contains(message, "jammed at t = 0"));
        const Measurements m = engine->measurements();
        CHECK(m.queue.pushes > m.queue.pops);  // stale events pile up while jammed...
        CHECK(m.queue.max_size <= classic_push_bound(three.scene.discs.size()));  // ...boundedly
    }
}

TEST_CASE("every engine simulates touching discs that can move, conserving energy") {
    for (const Shape& shape : touching_free_shapes()) {
        for (const EngineChoice& kind : all_engines) {
            CAPTURE(std::string(shape.name));
            CAPTURE(std::string(kind.engine));
            CAPTURE(std::string(kind.td_detect));
            auto engine = make(kind, shape.scene);
            const double energy = kinetic_energy(shape.scene);
            CHECK(input_error_message([&] { engine->advance_to(0.1); }).empty());
            CHECK(engine->time() == 0.1);
            const Measurements m = engine->measurements();
            CHECK(m.kinetic_energy == doctest::Approx(energy).epsilon(1e-9));
            if (!is_time_driven(kind)) CHECK(m.max_overlap <= 1e-9);
        }
    }
}
