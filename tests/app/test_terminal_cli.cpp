// What reaches the terminal: a scene's words and the command line's are anyone's bytes, and an
// escape sequence among them (ESC, the 8-bit CSI U+009B, BEL, a carriage return) must be shown,
// not obeyed: every message, warning and listing prints them escaped (collide/printable.hpp),
// keeping every language's letters.

#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "../support/files.hpp"
#include "../support/temp_dir.hpp"
#include "run_collide.hpp"

namespace {

namespace fs = std::filesystem;
using collide::test::run_collide;
using collide::test::run_collide_env;
using collide::test::RunResult;
using collide::test::TempDir;
using collide::test::write_file;

bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

/// No byte of `output` acts on a terminal: no C0 control but line feed and tab, no DEL, no C1
/// control (U+0080..U+009F, as UTF-8 C2 80..C2 9F), no stray byte a Latin-1 terminal would read
/// as one.
void check_inert(const std::string& output) {
    for (std::size_t i = 0; i < output.size(); ++i) {
        const auto c = static_cast<unsigned char>(output[i]);
        CAPTURE(i);
        CHECK((c >= 0x20 || c == '\n' || c == '\t'));
        CHECK(c != 0x7F);
        if (c == 0xC2 && i + 1 < output.size()) {
            CHECK(static_cast<unsigned char>(output[i + 1]) >= 0xA0);
        }
    }
}

/// A TOML basic string's worth of hostile text: OSC (retitle the window), BEL, a clear screen,
/// a carriage return that would overwrite the line, the 8-bit CSI and NEL, DEL, then letters.
const std::string hostile =
    "a\\u001b]0;pwned\\u0007b\\u001b[2J\\rc\\u009b2Jd\\u0085e\\u007f Zażółć";

}  // namespace

TEST_CASE("collide scenes: a description's control characters are shown escaped") {
    TempDir dir("terminal_scenes");
    fs::create_directory(dir.path / "scenes");
    write_file(dir.path / "scenes" / "evil.toml",
               "title = \"t\"\ndescription = \"" + hostile +
                   "\"\n[[disc]]\nposition = [0.5, 0.5]\nradius = 0.1\n");
    const RunResult r = run_collide_env("COLLIDE_DATA_DIR='" + dir.path.string() + "'", "scenes");
    INFO(r.output);
    CHECK(r.exit_code == 0);
    check_inert(r.output);
    CHECK(contains(r.output, "\\u001b]0;pwned\\u0007b\\u001b[2J\\rc\\u009b2Jd\\u0085e\\u007f"));
    CHECK(contains(r.output, "Zażółć"));
}

TEST_CASE("error messages quoting a scene or the command line show control characters escaped") {
    TempDir dir("terminal_errors");
    const std::string discs = "[[disc]]\nposition = [0.5, 0.5]\nradius = 0.1\n";
    const fs::path key = dir.path / "key.toml";
    write_file(key, "\"k" + hostile + "\" = 1\n" + discs);
    const fs::path tag = dir.path / "tag.toml";
    write_file(tag, "[render]\nreplay_tag = \"" + hostile + "\"\n" + discs);
    const std::vector<std::string> commands = {
        "check '" + key.string() + "'",
        "check '" + tag.string() + "'",
        "render '" + tag.string() + "' --size 320x180",
        "simulate '" + key.string() + "' --until 1",
        // The command line's own words: a scene name, an option's value.
        "check \"$(printf 'no\\033[2Jsuch\\r\\302\\233x')\"",
        "render gas --size \"$(printf '1\\033[2J\\007')\"",
    };
    for (const std::string& command : commands) {
        const RunResult r = run_collide(command);
        INFO(command << "\n" << r.output);
        CHECK(r.exit_code == 2);
        check_inert(r.output);
        CHECK(contains(r.output, "\\u001b"));
    }
    // The letters of any language stay as they are.
    const RunResult polish = run_collide("check '" + tag.string() + "'");
    CHECK(contains(polish.output, "Zażółć"));
}
