// The error helpers every module uses (collide/error.hpp) and the name tables of the options
// chosen by name (collide/named_values.hpp): the option comes first, then what was expected, then
// the value as typed.

#include <doctest/doctest.h>

#include <array>
#include <string>

#include "../support/input_error.hpp"
#include "collide/error.hpp"
#include "collide/named_values.hpp"

using namespace collide;
using collide::test::input_error_message;

namespace {

enum class Shade { dark, light, grey };

constexpr std::array<NamedValue<Shade>, 4> shade_names{
    {{"dark", Shade::dark}, {"light", Shade::light}, {"grey", Shade::grey}, {"gray", Shade::grey}}};

}  // namespace

TEST_CASE("option errors name the option first, then what was expected, then the value") {
    CHECK(input_error_message([] {
              throw_option_error("--fps", "0", "1..240 frames per second");
          }) == "--fps: expected 1..240 frames per second, got '0'");
    CHECK(input_error_message([] {
              throw_option_error("demo.toml:7: render.dt", "-1", "a time > 0");
          }) == "demo.toml:7: render.dt: expected a time > 0, got '-1'");
    CHECK(input_error_message([] { throw_option_error("--at", "only for `collide thumbnail`"); }) ==
          "--at: only for `collide thumbnail`");
}

TEST_CASE("scene errors say file:line: field: reason, leaving out what is unknown") {
    CHECK(input_error_message([] {
              throw_scene_error("s.toml", 3, "disc[0].radius", "must be > 0");
          }) == "s.toml:3: disc[0].radius: must be > 0");
    CHECK(input_error_message([] { throw_scene_error("s.toml", 0, "", "no such file"); }) ==
          "s.toml: no such file");
    CHECK(input_error_message([] { throw_scene_error("", 0, "", "empty scene path"); }) ==
          "empty scene path");
}

TEST_CASE("named values: every name parses, aliases included, and each value prints its own name") {
    for (const NamedValue<Shade>& entry : shade_names) {
        CHECK(parse_named(entry.name, "--shade", shade_names) == entry.value);
    }
    CHECK(name_of(Shade::grey, shade_names) == "grey");
    CHECK(list_names(shade_names) == "dark, light or grey");  // aliases accepted, not listed
}

TEST_CASE("named values: a bad name names the option, lists the own names and echoes the text") {
    CHECK(input_error_message([] { (void)parse_named("Dark", "--shade", shade_names); }) ==
          "--shade: expected dark, light or grey, got 'Dark'");
    CHECK(input_error_message([] { (void)parse_named("", "--shade", shade_names, "a shade"); }) ==
          "--shade: expected a shade (dark, light or grey), got ''");
    CHECK(parse_named("LIGHT", "--shade", shade_names, "", NameCase::ignore) == Shade::light);
    CHECK(input_error_message([] {
              (void)parse_named("lights", "--shade", shade_names, "", NameCase::ignore);
          }) == "--shade: expected dark, light or grey, got 'lights'");
}
