#include <doctest/doctest.h>

#include "run_collide.hpp"

using collide::test::run_collide;

TEST_CASE("--version prints the version and exits 0") {
    const auto r = run_collide("--version");
    CHECK(r.exit_code == 0);
    CHECK(r.output.find("collide 0.") != std::string::npos);
}

TEST_CASE("--help lists usage and exits 0") {
    const auto r = run_collide("--help");
    CHECK(r.exit_code == 0);
    CHECK(r.output.find("Usage") != std::string::npos);
}

TEST_CASE("an unknown option is a usage error: exit 2 with a reason naming it") {
    const auto r = run_collide("--no-such-option");
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("--no-such-option") != std::string::npos);
}

TEST_CASE("usage errors read like every other error, with the hint to --help") {
    const auto r = run_collide("render gas --duration x");
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("collide: error: Could not convert: --duration = x") != std::string::npos);
    CHECK(r.output.find("Run with --help for more information.") != std::string::npos);
    // Whole-number options parse strictly, and their errors read the same way.
    const auto seed = run_collide("render gas --seed x");
    CHECK(seed.exit_code == 2);
    CHECK(seed.output.find("collide: error: --seed: expected a whole number") != std::string::npos);
    CHECK(seed.output.find("Run with --help for more information.") != std::string::npos);
}

TEST_CASE("an unknown subcommand is a usage error: exit 2") {
    const auto r = run_collide("frobnicate");
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("frobnicate") != std::string::npos);
}
