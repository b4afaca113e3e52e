// load_scene: dispatch on .txt / .toml / built-in names, and the built-in library itself.

#include <doctest/doctest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <variant>

#include "../support/input_error.hpp"
#include "../support/temp_dir.hpp"
#include "collide/error.hpp"
#include "collide/scene/load.hpp"
#include "collide/sim/algs4.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/scene_check.hpp"

using namespace collide;

namespace {

std::string load_error(const std::string& what) {
    return test::input_error_message([&] { (void)load_scene(what, COLLIDE_ASSETS_DIR); });
}

using collide::test::contains;

}  // namespace

TEST_CASE("load_scene: algs4 .txt and .toml files by path, named after the file") {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "collide_test_load";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "pair.txt") << "2\n0.2 0.2 0 0 0.05 1 0 0 0\n0.8 0.8 0 0 0.05 1 0 0 0\n";
    std::ofstream(dir / "one.toml") << "[[disc]]\nposition = [0.5, 0.5]\nradius = 0.1\n";
    std::ofstream(dir / "notes.csv") << "x\n";
    const Scene a = load_scene((dir / "pair.txt").string());
    CHECK(a.name == "pair");
    CHECK(a.discs.size() == 2);
    const Scene b = load_scene((dir / "one.toml").string());
    CHECK(b.name == "one");
    CHECK(b.title == "one");
    CHECK(b.discs.size() == 1);
    CHECK(contains(load_error((dir / "notes.csv").string()), "unknown scene format '.csv'"));
    CHECK(contains(load_error(dir.string()), "is a directory"));
    CHECK(contains(load_error((dir / "absent.txt").string()), "cannot open"));
    CHECK(contains(load_error(""), "empty scene path"));
    std::filesystem::remove_all(dir);
}

TEST_CASE("load_scene: unknown names suggest a built-in scene") {
    CHECK(contains(
        load_error("brownain"),
        "'brownain': not a scene file and not a built-in scene (did you mean 'brownian'?)"));
    CHECK(contains(load_error("zzzzzzzz"), "`collide scenes` lists them"));
}

TEST_CASE("built-in library: the required scenes exist, each described and valid") {
    const std::vector<BuiltinScene> scenes = builtin_scenes(COLLIDE_ASSETS_DIR);
    std::vector<std::string> names;
    for (const BuiltinScene& s : scenes) names.push_back(s.name);
    for (const char* required :
         {"gas", "brownian", "diffusion", "billiards", "newtons-cradle", "maxwell-boltzmann",
          "tunnelling", "dense-fluid", "gas-3d", "alder-wainwright", "spheres-freeze"}) {
        CAPTURE(required);
        CHECK(std::find(names.begin(), names.end(), required) != names.end());
    }
    for (const BuiltinScene& b : scenes) {
        CAPTURE(b.name);
        CHECK(!b.description.empty());
        CHECK(b.description.find('\n') == std::string::npos);
        const std::filesystem::path file =
            std::filesystem::path(COLLIDE_ASSETS_DIR) / "scenes" / (b.name + ".toml");
        std::ifstream in(file);
        const std::string text{std::istreambuf_iterator<char>(in),
                               std::istreambuf_iterator<char>()};
        // Either dimension; throws if invalid.
        const AnyScene any = parse_any_toml_scene(text, file.string(), file.parent_path());
        if (const auto* spheres = std::get_if<SphereScene>(&any)) {
            CHECK(!spheres->title.empty());
            CHECK(!spheres->spheres.empty());
            continue;
        }
        const Scene s = load_scene(b.name, COLLIDE_ASSETS_DIR);
        CHECK(s.name == b.name);
        CHECK(!s.title.empty());
        CHECK(!s.discs.empty());
    }
}

TEST_CASE("built-in library: the tunnelling demo is built to make the time-driven method fail") {
    const Scene s = load_scene("tunnelling", COLLIDE_ASSETS_DIR);
    REQUIRE(s.render.dt.has_value());
    CHECK(s.discs.size() <= 400);
    // some disc moves more than a barrier disc's diameter per time step
    double fastest = 0.0;
    double smallest = 1e300;
    for (const Disc& d : s.discs) {
        fastest = std::max(fastest, norm(d.velocity));
        smallest = std::min(smallest, d.radius);
    }
    CHECK(fastest * *s.render.dt > 2.0 * smallest);
}

TEST_CASE("built-in library: the dense fluid is dense and the gas is not") {
    CHECK(packing_fraction(load_scene("dense-fluid", COLLIDE_ASSETS_DIR)) ==
          doctest::Approx(0.7).epsilon(0.03));
    CHECK(packing_fraction(load_scene("gas", COLLIDE_ASSETS_DIR)) < 0.1);
}

namespace {

// Projectiles (radius 0.008) outside the chamber between the barriers at x = 0.3 and x = 0.7.
int escaped_from_chamber(const collide::Snapshot& snapshot) {
    int out = 0;
    for (const collide::DiscState& d : snapshot.discs) {
        if (d.radius > 0.006 && (d.position.x < 0.3 || d.position.x > 0.7)) ++out;
    }
    return out;
}

}  // namespace

TEST_CASE(
    "built-in library: in the tunnelling demo the time-driven method fails at the scene's dt "
    "only") {
    const Scene s = load_scene("tunnelling", COLLIDE_ASSETS_DIR);
    EngineOptions options;
    options.engine = EngineKind::time;
    options.td_detect = OverlapDetection::grid;
    options.dt = *s.render.dt;
    auto coarse = make_engine(s, options);
    coarse->advance_to(1.0);  // 5 s of video at the scene's speed
    CHECK(escaped_from_chamber(coarse->snapshot()) >= 3);
    CHECK(coarse->measurements().missed_collisions > 0);
    options.dt = 1e-3;
    auto fine = make_engine(s, options);
    fine->advance_to(1.0);
    CHECK(escaped_from_chamber(fine->snapshot()) == 0);
    options.engine = EngineKind::fast;
    auto exact = make_engine(s, options);
    exact->advance_to(1.0);
    CHECK(escaped_from_chamber(exact->snapshot()) == 0);
}

TEST_CASE("built-in library: the dense fluid overwhelms the time-driven method at the scene's dt") {
    const Scene s = load_scene("dense-fluid", COLLIDE_ASSETS_DIR);
    EngineOptions options;
    options.engine = EngineKind::time;
    options.td_detect = OverlapDetection::grid;
    options.dt = *s.render.dt;
    auto coarse = make_engine(s, options);
    coarse->advance_to(0.2);
    CHECK(coarse->snapshot().overlapping_pairs.size() > 100);  // of 2228 discs
}

TEST_CASE("load_scene: a seed override re-draws every [[generate]] block, reproducibly") {
    const std::filesystem::path assets = COLLIDE_ASSETS_DIR;
    const Scene own = load_scene("maxwell-boltzmann", assets);
    const Scene seeded = load_scene("maxwell-boltzmann", assets, SceneOptions{7});
    const Scene again = load_scene("maxwell-boltzmann", assets, SceneOptions{7});
    const Scene other = load_scene("maxwell-boltzmann", assets, SceneOptions{8});
    REQUIRE(seeded.discs.size() == own.discs.size());
    const auto same_positions = [](const Scene& a, const Scene& b) {
        for (std::size_t i = 0; i < a.discs.size(); ++i) {
            if (!(a.discs[i].position == b.discs[i].position)) return false;
        }
        return true;
    };
    CHECK(same_positions(seeded, again));
    CHECK_FALSE(same_positions(seeded, other));
    CHECK_FALSE(same_positions(seeded, own));
}

namespace {

/// A FIFO (named pipe) in a fresh directory. Reading it the old way blocks forever in open():
/// the alarm turns that hang into a failure (SIGALRM ends the test process).
struct FifoGuard {
    FifoGuard() { alarm(20); }
    ~FifoGuard() { alarm(0); }
};

}  // namespace

TEST_CASE("read_scene_file: a FIFO, a device, a directory are refused by name without blocking") {
    test::TempDir dir("scene_file");
    const std::filesystem::path fifo = dir.path / "pipe.toml";
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    const FifoGuard guard;
    const std::string message = load_error(fifo.string());
    CHECK(contains(message, fifo.string() + ": a FIFO (named pipe), not a regular file"));
    std::filesystem::create_symlink(fifo, dir.path / "linked.txt");
    CHECK(contains(load_error((dir.path / "linked.txt").string()), "a FIFO (named pipe)"));
    std::filesystem::create_symlink("/dev/zero", dir.path / "zero.txt");
    CHECK(contains(load_error((dir.path / "zero.txt").string()),
                   "zero.txt: a character device, not a regular file"));
    CHECK(contains(test::input_error_message([&] { (void)read_scene_file(dir.path); }),
                   "a directory, not a regular file"));
}

TEST_CASE("read_scene_file: a file beyond the size cap is refused naming the cap, unread") {
    test::TempDir dir("scene_file_big");
    const std::filesystem::path big = dir.path / "big.txt";
    std::ofstream(big).close();
    std::filesystem::resize_file(big, max_scene_file_bytes + 1);  // sparse: no disk used
    CHECK(
        contains(load_error(big.string()), "big.txt: larger than 512 MiB, the most a scene file"));
    std::filesystem::resize_file(big, 0);
    std::ofstream(big) << "1\n0.5 0.5 0 0 0.1 1 0 0 0\n";
    CHECK(read_scene_file(big).size() == 26);
}

TEST_CASE("toml include: a FIFO or an oversized include is refused at the include's line") {
    test::TempDir dir("scene_file_include");
    REQUIRE(mkfifo((dir.path / "pipe.txt").c_str(), 0600) == 0);
    std::ofstream(dir.path / "s.toml") << "title = \"x\"\ninclude = \"pipe.txt\"\n";
    const FifoGuard guard;
    const std::string message = load_error((dir.path / "s.toml").string());
    CHECK(contains(message, "s.toml:2: include: "));
    CHECK(contains(message, "pipe.txt: a FIFO (named pipe), not a regular file"));
}

TEST_CASE("builtin_scenes: a FIFO among the assets is refused by name instead of hanging") {
    test::TempDir dir("scene_file_assets");
    std::filesystem::create_directories(dir.path / "scenes");
    std::ofstream(dir.path / "scenes" / "good.toml") << "description = \"fine\"\n";
    REQUIRE(mkfifo((dir.path / "scenes" / "stuck.toml").c_str(), 0600) == 0);
    const FifoGuard guard;
    CHECK(contains(test::input_error_message([&] { (void)builtin_scenes(dir.path); }),
                   "stuck.toml: a FIFO (named pipe), not a regular file"));
    CHECK(contains(test::input_error_message([&] { (void)load_scene("stuck", dir.path); }),
                   "stuck.toml: a FIFO"));
}
