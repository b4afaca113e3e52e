// `collide simulate` and `collide bench engine` end to end: exit codes, JSON keys, the events
// log (CSV, atomic, unwritable path = exit 2 before simulating).

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../support/input_error.hpp"
#include "../support/temp_dir.hpp"
#include "run_collide.hpp"

using collide::test::run_collide;
using collide::test::run_collide_bad_input;

namespace {

namespace fs = std::filesystem;

using collide::test::contains;
using collide::test::TempDir;

/// Two discs head-on in the unit box: a pair collision at t = 2, both walls at t = 5.
fs::path write_head_on(const fs::path& dir) {
    const fs::path file = dir / "headon.txt";
    std::ofstream(file) << "2\n0.2 0.5 0.1 0 0.1 1 255 0 0\n0.8 0.5 -0.1 0 0.1 1 0 0 255\n";
    return file;
}

std::vector<std::string> lines_of(const fs::path& file) {
    std::ifstream in(file);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

}  // namespace

TEST_CASE("collide simulate --json prints every measurement key") {
    TempDir dir("collide_test_simulate_json");
    const fs::path scene = write_head_on(dir.path);
    for (const char* engine : {"fast", "classic"}) {
        CAPTURE(engine);
        const auto r = run_collide("simulate \"" + scene.string() +
                                   "\" --until 5.5 --json --engine " + engine);
        REQUIRE(r.exit_code == 0);
        for (const char* key :
             {"\"t\": 5.5", "\"events\"", "\"collisions_pair\": 1", "\"collisions_wall\": 2",
              "\"kinetic_energy\"", "\"pressure\"", "\"compressibility\"", "\"packing_fraction\"",
              "\"max_overlap\": 0", "\"collisions_per_second\"", "\"pq_max_size\"",
              "\"pq_updates\"", "\"stale_events\"", "\"overlap_checks\"", "\"missed_collisions\"",
              "\"escaped\"", "\"energy_drift\"", "\"msd\"", "\"temperature\""}) {
            CHECK_MESSAGE(contains(r.output, key), key);
        }
    }
}

TEST_CASE("collide simulate --events-log writes one CSV line per collision") {
    TempDir dir("collide_test_simulate_log");
    const fs::path scene = write_head_on(dir.path);
    const fs::path log = dir.path / "events.csv";
    const auto r = run_collide("simulate \"" + scene.string() +
                               "\" --until 5.5 --pq ordered --engine classic"
                               " --events-log \"" +
                               log.string() + "\"");
    REQUIRE(r.exit_code == 0);
    const auto lines = lines_of(log);
    REQUIRE(lines.size() == 4);
    CHECK(lines[0] == "t,kind,a,b");
    CHECK(lines[1].rfind("2", 0) == 0);  // t = 2 up to rounding
    CHECK(contains(lines[1], ",pair,0,1"));
    CHECK(contains(lines[2], ",xwall,"));
    CHECK(lines[2].back() == ',');  // b is empty for walls
    // nothing but the log itself is left in the directory (no temporary)
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir.path)) ++files;
    CHECK(files == 2);  // headon.txt and events.csv
}

TEST_CASE("collide simulate: bad options and unwritable logs exit 2 without output files") {
    TempDir dir("collide_test_simulate_bad");
    const fs::path scene = write_head_on(dir.path);
    const std::string base = "simulate \"" + scene.string() + "\" --until 1";
    const auto unwritable = run_collide(base + " --events-log /nonexistent-dir/x/events.csv");
    CHECK(unwritable.exit_code == 2);
    CHECK(contains(unwritable.output, "--events-log"));
    CHECK_FALSE(fs::exists("/nonexistent-dir/x/events.csv"));

    const auto engine = run_collide(base + " --engine warp");
    CHECK(engine.exit_code == 2);
    CHECK(contains(engine.output, "--engine"));
    const auto queue = run_collide(base + " --engine classic --pq fibonacci");
    CHECK(queue.exit_code == 2);
    CHECK(contains(queue.output, "--pq"));
    const auto until = run_collide("simulate \"" + scene.string() + "\" --until -1");
    CHECK(until.exit_code == 2);
    CHECK(contains(until.output, "--until"));
    const auto missing =
        run_collide("simulate \"" + (dir.path / "none.txt").string() + "\" --until 1");
    CHECK(missing.exit_code == 2);
}

TEST_CASE("collide bench engine reports throughput and memory on a small fluid") {
    const auto r = run_collide("bench engine --n 400 --eta 0.4 --collisions 20000 --json");
    REQUIRE(r.exit_code == 0);
    for (const char* key :
         {"\"collisions_per_second\"", "\"events_per_cpu_second\"", "\"engine_bytes_per_disc\"",
          "\"rss_delta_bytes_per_disc\"", "\"pq_max_size\": 400", "\"stale_fraction\""}) {
        CHECK_MESSAGE(contains(r.output, key), key);
    }
    CHECK(run_collide("bench engine --n 1 --collisions 10").exit_code == 2);
}

TEST_CASE(
    "collide bench engine: --n in exponent form, and clear errors for fluids it cannot time") {
    const auto exponent = run_collide("bench engine --n 4e2 --eta 0.4 --collisions 1e3");
    CHECK(exponent.exit_code == 0);
    CHECK(contains(exponent.output, "discs: 400"));

    CHECK(contains(run_collide_bad_input("bench engine --n 2.5 --collisions 10"),
                   "--n: expected a whole number of discs from 2 to 1e+09, got '2.5'"));
    // Two discs at packing fraction 0.5 are wider than a quarter of the box.
    CHECK(contains(run_collide_bad_input("bench engine --n 2 --eta 0.5 --collisions 10"),
                   "--n 2 --eta 0.5: no valid fluid"));
    // A disc at rest in a walled box never collides: an error, not an endless search.
    TempDir dir("collide_test_bench_still");
    const fs::path still = dir.path / "still.txt";
    std::ofstream(still) << "1\n0.5 0.5 0 0 0.1 1 0 0 0\n";
    CHECK(contains(
        run_collide_bad_input("bench engine --scene \"" + still.string() + "\" --collisions 10"),
        "no collision happens in this scene"));
}

TEST_CASE("collide simulate of a 3D scene reports kT (3 dof), Z, packing fraction and MSD") {
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / "collide_e2e_spheres.toml";
    std::ofstream(path) << "dimension = 3\n[box]\nboundary = \"periodic\"\n[[fcc]]\ncells = 4\n"
                           "packing_fraction = 0.3\nseed = 2\n";
    const auto r = run_collide("simulate \"" + path.string() + "\" --until 0.5 --json");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(contains(r.output, "\"dimension\": 3,"));
    CHECK(contains(r.output, "\"spheres\": 256,"));
    const auto value = [&](const std::string& key) {
        const std::size_t at = r.output.find("\"" + key + "\": ");
        REQUIRE(at != std::string::npos);
        return std::stod(r.output.substr(at + key.size() + 4));
    };
    CHECK(value("temperature") == doctest::Approx(1.0).epsilon(1e-12));  // 2 KE / 3N
    CHECK(value("packing_fraction") == doctest::Approx(0.3).epsilon(1e-12));
    CHECK(value("compressibility") > 2.0);  // Carnahan-Starling: 3.97 at 0.3
    CHECK(value("msd") > 0.0);
    CHECK(value("max_overlap") < 1e-12);
    // Every engine runs spheres: the classic loop makes as many collisions as the fast engine
    // (not the same ones after some 10^3: chaos amplifies their different rounding), the
    // time-driven one reports its steps and what it missed.
    const auto classic = run_collide("simulate \"" + path.string() +
                                     "\" --until 0.5 --engine classic --pq indexed --json");
    INFO(classic.output);
    REQUIRE(classic.exit_code == 0);
    CHECK(contains(classic.output, "\"pq\": \"indexed:4\","));
    const std::size_t at = classic.output.find("\"collisions_pair\": ");
    REQUIRE(at != std::string::npos);
    CHECK(std::stod(classic.output.substr(at + 19)) ==
          doctest::Approx(value("collisions_pair")).epsilon(0.02));
    const auto timed =
        run_collide("simulate \"" + path.string() +
                    "\" --until 0.5 --engine time --dt 0.005 --td-detect grid --json");
    INFO(timed.output);
    REQUIRE(timed.exit_code == 0);
    CHECK(contains(timed.output, "\"steps\": 100,"));
    CHECK(contains(timed.output, "\"missed_collisions\": "));
    // The work limits hold in 3D: all pairs of 256 spheres for 10^9 steps is refused.
    const auto refused =
        run_collide("simulate \"" + path.string() + "\" --until 1e3 --engine time --dt 1e-6");
    CHECK(refused.exit_code == 2);
    CHECK(contains(refused.output, "256 spheres"));
    // Drawing it (thumbnail, render) is tested in test_render3d_cli.cpp.
}
