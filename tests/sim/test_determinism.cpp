// The pinned determinism hash (Box2D's habit): the first 10^4 collision records of the built-in
// `gas` scene, per engine, folded into one 64-bit hash that is written down here. Same scene,
// seed and options -> the same events to the last bit, across refactors: a change that moves a
// single collision time by one ulp (an operation reordered, a tally moved, a queue tie broken
// differently) fails here. A change that is meant to alter the events (new physics, another
// tie-break) re-pins the hash in the same commit and says why.

#include <doctest/doctest.h>

#include <bit>
#include <cstdint>
#include <cstdio>
#include <string>

#include "collide/scene.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/generate.hpp"

using namespace collide;

namespace {

/// The built-in `gas` scene (assets/scenes/gas.toml) as the scene loader builds it from its one
/// [[generate]] block: 20 discs of radius 0.03 at kT = 0.02 in a walled unit box, seed 10.
/// Rebuilt here because the simulation library's tests see no TOML (COLLIDE_SIM_ONLY builds);
/// colours are left out (they do not move a disc).
Scene gas_scene() {
    Scene scene;
    scene.box = Box{1.0, 1.0, Boundary::walls};
    GenerateSpec spec;
    spec.count = 20;
    spec.radius = 0.03;
    spec.mass = 1.0;
    spec.temperature = 0.02;
    spec.seed = 10;
    generate_discs(scene, spec, "generate[0]");
    return scene;
}

/// FNV-1a over each record's time (its bits), kind and discs, in the order they happen.
class RecordHash {
  public:
    void add(const CollisionRecord& r) {
        mix(std::bit_cast<std::uint64_t>(r.t));
        mix(static_cast<std::uint64_t>(r.kind));
        mix(r.a);
        mix(r.b);
        ++count_;
    }
    [[nodiscard]] std::uint64_t value() const noexcept { return hash_; }
    [[nodiscard]] std::size_t count() const noexcept { return count_; }

  private:
    void mix(std::uint64_t word) {
        for (int byte = 0; byte < 8; ++byte) {
            hash_ ^= (word >> (8 * byte)) & 0xFFU;
            hash_ *= 0x100000001B3ULL;
        }
    }
    std::uint64_t hash_ = 0xCBF29CE484222325ULL;
    std::size_t count_ = 0;
};

constexpr std::size_t pinned_records = 10000;

/// Hash of the first pinned_records collisions of `engine` on the gas scene, advanced in steps of
/// 1/fps (frame times: the way the videos drive the engines).
std::string first_records_hash(EngineKind engine, int fps = 30) {
    EngineOptions options;
    options.engine = engine;
    auto sim = make_engine(gas_scene(), options);
    RecordHash hash;
    sim->set_collision_listener([&](const CollisionRecord& r) {
        if (hash.count() < pinned_records) hash.add(r);
    });
    for (int frame = 1; hash.count() < pinned_records && frame < 1'000'000; ++frame)
        sim->advance_to(frame / static_cast<double>(fps));
    REQUIRE(hash.count() == pinned_records);
    char text[19];
    std::snprintf(text, sizeof text, "0x%016llx", static_cast<unsigned long long>(hash.value()));
    return text;
}

}  // namespace

TEST_CASE("determinism: the first 10^4 collisions of the gas scene hash as pinned, per engine") {
    SUBCASE("fast (event-driven, cell grid)") {
        CHECK(first_records_hash(EngineKind::fast) == "0x121a1451ca3955f4");
    }
    SUBCASE("classic (the lecture's loop)") {
        CHECK(first_records_hash(EngineKind::classic) == "0xb680243f21d8a984");
    }
    SUBCASE("time-driven (dt = 0.01)") {
        // Re-pinned when step k came to end at k * dt from t = 0 for every caller (issue #28):
        // the frame times no longer change the physics, so any frame rate gives this hash.
        CHECK(first_records_hash(EngineKind::time) == "0xc75b4cd5ea4149f9");
        CHECK(first_records_hash(EngineKind::time, 24) == "0xc75b4cd5ea4149f9");
    }
}
