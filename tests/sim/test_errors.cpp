// The error helpers every module uses (collide/error.hpp) and the name tables of the options
// chosen by name (collide/named_values.hpp): the option comes first, then what was expected, then
// the value as typed. And the simulation library's messages name fields ("dt", "pq"), never a
// command-line option ("--dt"): its callers pass the spelling their user knows.

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "../support/files.hpp"
#include "../support/input_error.hpp"
#include "collide/error.hpp"
#include "collide/named_values.hpp"

using namespace collide;
using collide::test::input_error_message;

namespace {

enum class Shade { dark, light, grey };

/// Whether the quote at `i` separates digits (1'000'000) rather than opening a character.
bool digit_separator(const std::string& text, std::size_t i) {
    return i > 0 && std::isalnum(static_cast<unsigned char>(text[i - 1])) != 0;
}

/// The string literals of C++ source text, comments left out (no raw strings: the library has
/// none).
std::vector<std::string> string_literals(const std::string& text) {
    std::vector<std::string> out;
    std::size_t i = 0;
    while (i < text.size()) {
        const char c = text[i];
        if (c == '/' && i + 1 < text.size() && text[i + 1] == '/') {
            i = text.find('\n', i);
            if (i == std::string::npos) break;
        } else if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
            i = text.find("*/", i + 2);
            if (i == std::string::npos) break;
            i += 2;
        } else if (c == '"' || (c == '\'' && !digit_separator(text, i))) {
            std::string literal;
            for (++i; i < text.size() && text[i] != c; ++i) {
                if (text[i] == '\\' && i + 1 < text.size()) literal += text[i++];
                literal += text[i];
            }
            ++i;
            if (c == '"') out.push_back(literal);
        } else {
            ++i;
        }
    }
    return out;
}

/// The literals of `text` that spell a command-line option ("--dt", "use --engine classic").
std::vector<std::string> option_spellings(const std::string& text) {
    static const std::regex option(R"((^|[\s(`'])--[A-Za-z])");
    std::vector<std::string> out;
    for (const std::string& literal : string_literals(text)) {
        if (std::regex_search(literal, option)) out.push_back(literal);
    }
    return out;
}

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

TEST_CASE("the scan for option spellings finds them in literals only") {
    const std::string code =
        "// --dt in a comment\n"
        "/* --pq */ throw_input_error(\"--moves: must be 0..\");\n"
        "f(\"a periodic box (use --engine classic)\", '\"', \"dt\");\n"
        "g(\"ops\", \"increase-key\", \"a -- b\", --i, 1'000'000);\n"
        "h(\"--heuristic: unknown\");\n";
    CHECK(option_spellings(code) ==
          std::vector<std::string>{"--moves: must be 0..", "a periodic box (use --engine classic)",
                                   "--heuristic: unknown"});
}

TEST_CASE("the simulation library's messages name fields, never command-line options") {
    namespace fs = std::filesystem;
    const fs::path root = fs::path(COLLIDE_TESTS_DIR).parent_path();
    std::size_t files = 0;
    for (const fs::path& dir : {root / "src/sim", root / "include/collide/sim"}) {
        REQUIRE(fs::is_directory(dir));
        for (const auto& entry : fs::recursive_directory_iterator(dir)) {
            const fs::path& path = entry.path();
            if (path.extension() != ".cpp" && path.extension() != ".hpp") continue;
            ++files;
            CAPTURE(path.string());
            CHECK(option_spellings(test::read_all(path)).empty());
        }
    }
    CHECK(files > 40);
}
