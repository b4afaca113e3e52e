// A fixed amount of work for the fast engine, for instruction counts under callgrind
// (docs/benchmarks.md, "One engine for discs and spheres"): a random periodic fluid of N discs at
// packing 0.5 (seed 0), 2000 collisions of warm-up, then C collisions, advanced in steps sized
// from the observed rate as `collide bench engine` does. Prints the collision count and the
// final time, which must agree bit for bit between builds that claim the same events.
//
// Uses only the fast engine's public interface of 7ab144c onwards, so the same file compiles
// against an older tree's libcollide_sim.a for a side-by-side count.
//
//   fast_engine_run [N = 1000] [C = 2e5]

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <numbers>

#include "collide/scene.hpp"
#include "collide/sim/fast_engine.hpp"
#include "collide/sim/generate.hpp"

int main(int argc, char** argv) {
    // Both namespaces: some names moved between collide and collide::sim since 7ab144c.
    using namespace collide;
    using namespace collide::sim;
    const double n = argc > 1 ? std::atof(argv[1]) : 1000.0;
    const double timed = argc > 2 ? std::atof(argv[2]) : 2e5;
    const double eta = 0.5;
    if (!(n >= 2.0) || !(timed >= 1.0)) {
        std::fprintf(stderr, "usage: fast_engine_run [N >= 2] [collisions >= 1]\n");
        return 2;
    }
    Scene scene;
    scene.box = Box{1.0, 1.0, Boundary::periodic};
    GenerateSpec spec;
    spec.count = static_cast<std::size_t>(n);
    spec.radius = std::sqrt(eta / (std::numbers::pi * n));
    spec.temperature = 1.0;
    spec.seed = 0;
    spec.validate();
    generate_discs(scene, spec);

    FastEngine engine(scene);
    std::uint64_t collisions = 0;
    engine.set_collision_listener([&collisions](const CollisionRecord&) { ++collisions; });
    const auto run = [&](double more) {
        const std::uint64_t goal = collisions + static_cast<std::uint64_t>(more);
        double step = 1e-6;
        while (collisions < goal) {
            const std::uint64_t before = collisions;
            engine.advance_to(engine.time() + step);
            const auto done = static_cast<double>(collisions - before);
            const double wanted =
                std::max(1.0, std::min(static_cast<double>(goal - collisions), more / 8.0));
            step = done > 0.0 ? std::min(step * 8.0, step * wanted / done) : step * 8.0;
        }
    };
    run(2000.0);
    run(timed);
    std::printf("collisions %llu t %.17g\n", static_cast<unsigned long long>(collisions),
                engine.time());
    return 0;
}
