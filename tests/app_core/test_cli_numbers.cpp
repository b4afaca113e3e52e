// Whole-number options: decimal digits in a stated range, nothing CLI11's strtoull would bend.
#include <doctest/doctest.h>

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

#include "../support/input_error.hpp"
#include "cli_numbers.hpp"

using namespace collide::app;
using collide::test::contains;
using collide::test::input_error_message;

TEST_CASE("whole numbers: decimal digits within the range are taken as they read") {
    CHECK(parse_whole_number("0", "--seed", 0, UINT64_MAX) == 0);
    CHECK(parse_whole_number("+42", "--seed", 0, UINT64_MAX) == 42);
    CHECK(parse_whole_number("010", "--seed", 0, UINT64_MAX) == 10);  // not octal 8
    CHECK(parse_whole_number("18446744073709551615", "--seed", 0, UINT64_MAX) == UINT64_MAX);
}

TEST_CASE("whole numbers: signs, fractions, exponents, hex and overflow name the option") {
    for (const char* bad : {"-1", "18446744073709551616", "1e23", "1.5", "0x10", "", "+", "+-1",
                            " 1", "1 ", "seven"}) {
        CAPTURE(bad);
        const std::string message =
            input_error_message([&] { (void)parse_whole_number(bad, "--seed", 0, UINT64_MAX); });
        CHECK(contains(message, "--seed: "));
        CHECK(contains(message, "from 0 to 18446744073709551615"));
    }
    CHECK(contains(input_error_message([] { (void)parse_whole_number("241", "--fps", 1, 240); }),
                   "--fps: expected a whole number from 1 to 240, got '241'"));
    CHECK(contains(input_error_message([] { (void)parse_whole_number("0", "--fps", 1, 240); }),
                   "--fps: expected a whole number from 1 to 240, got '0'"));
}

TEST_CASE("whole numbers: an option registered with CLI11 is a usage error when bad") {
    CLI::App app;
    std::uint64_t seed = 7;
    int fps = 0;
    add_whole_option(app, "--seed", seed, 0, UINT64_MAX, "");
    add_whole_option(app, "--fps", fps, 1, 240, "");
    app.parse(std::string("--seed 123 --fps 60"), false);
    CHECK(seed == 123);
    CHECK(fps == 60);
    try {
        app.parse(std::string("--seed -1"), false);
        FAIL("no error");
    } catch (const CLI::ValidationError& e) {
        CHECK(contains(e.what(),
                       "--seed: expected a whole number from 0 to 18446744073709551615, got '-1'"));
    }
}
