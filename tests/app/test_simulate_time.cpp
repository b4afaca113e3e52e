// `collide simulate --engine time` end to end: the time-driven figures in the JSON, the failures
// it reports for a large dt, and the option errors.
#include <doctest/doctest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "run_collide.hpp"

using collide::test::run_collide;
using collide::test::shell_quoted;

namespace {

/// An algs4 scene (unit box, walls): two discs closing head-on at speed 2 with a gap of 0.08, and
/// one disc 0.04 from the right wall moving at speed 1. With dt = 0.1 the pair tunnels and the
/// lone disc escapes; with dt = 0.001 the pair collides at t = 0.04 and the wall at t = 0.04.
class TunnelScene {
  public:
    TunnelScene()
        : path_(std::filesystem::temp_directory_path() /
                ("collide-timed-" + std::to_string(::getpid()) + ".txt")) {
        std::ofstream out(path_);
        out << "3\n"
            << "0.45 0.5 1 0 0.01 1 255 0 0\n"
            << "0.55 0.5 -1 0 0.01 1 0 0 255\n"
            << "0.95 0.2 1 0 0.01 1 0 128 0\n";
    }
    TunnelScene(const TunnelScene&) = delete;
    TunnelScene& operator=(const TunnelScene&) = delete;
    ~TunnelScene() {
        std::error_code ignored;
        std::filesystem::remove(path_, ignored);
    }
    [[nodiscard]] std::string path() const { return shell_quoted(path_.string()); }

  private:
    std::filesystem::path path_;
};

bool has(const std::string& text, const std::string& needle) {
    return text.find(needle) != std::string::npos;
}

}  // namespace

TEST_CASE("simulate --engine time with a large dt reports the missed collision and the escape") {
    const TunnelScene scene;
    const auto r =
        run_collide("simulate " + scene.path() + " --until 0.1 --engine time --dt 0.1 --json");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(has(r.output, "\"engine\": \"time\""));
    CHECK(has(r.output, "\"missed_collisions\": 1,"));
    CHECK(has(r.output, "\"escaped\": 1,"));
    CHECK(has(r.output, "\"collisions_pair\": 0,"));
    CHECK(has(r.output, "\"overlap_checks\": 3,"));  // one step, 3 discs: 3 pairs
    CHECK(has(r.output, "\"energy_drift\": "));
}

TEST_CASE("simulate --engine time with a small dt resolves the same collisions") {
    const TunnelScene scene;
    for (const char* detect : {"all-pairs", "grid"}) {
        CAPTURE(detect);
        const auto r =
            run_collide("simulate " + scene.path() +
                        " --until 0.1 --engine time --dt 0.001 --td-detect " + detect + " --json");
        INFO(r.output);
        REQUIRE(r.exit_code == 0);
        CHECK(has(r.output, "\"missed_collisions\": 0,"));
        CHECK(has(r.output, "\"escaped\": 0,"));
        CHECK(has(r.output, "\"collisions_pair\": 1,"));
        CHECK(has(r.output, "\"collisions_wall\": 1,"));
        if (std::string(detect) == "all-pairs") {
            CHECK(has(r.output, "\"overlap_checks\": 300,"));  // 100 steps, 3 pairs
        }
    }
}

TEST_CASE("simulate --engine time: a bad --dt or --td-detect is a one-line input error") {
    const TunnelScene scene;
    for (const char* dt : {"0", "-1", "nan"}) {
        CAPTURE(dt);
        const auto r =
            run_collide("simulate " + scene.path() + " --until 0.1 --engine time --dt " + dt);
        CHECK(r.exit_code == 2);
        CHECK(has(r.output, "--dt"));
    }
    const auto r =
        run_collide("simulate " + scene.path() + " --until 0.1 --engine time --td-detect octree");
    CHECK(r.exit_code == 2);
    CHECK(has(r.output, "--td-detect"));
}
