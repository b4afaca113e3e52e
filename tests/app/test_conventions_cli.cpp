// What users expect of a command-line tool (issue #31), on the real program: JSON that is always
// valid whatever bytes a file name holds, --json on check, scenes, render and thumbnail,
// suggestions for typos, --version's build facts, and --font.

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../support/temp_dir.hpp"
#include "run_collide.hpp"

using collide::test::run_collide;
using collide::test::run_command;
using collide::test::shell_quoted;
using collide::test::TempDir;

namespace {

namespace fs = std::filesystem;

/// `collide ARGS` with stdout alone (stderr dropped): the JSON document.
collide::test::RunResult run_stdout(const std::string& args) {
    return run_command(std::string("\"") + COLLIDE_EXE + "\" " + args + " 2>/dev/null");
}

/// A file name no JSON printer may paste as it is: a control character, a quote, a backslash,
/// a newline and a byte that is not UTF-8.
const std::string hostile_stem = std::string("a\x01q\"b\\n\nx\xff") + "y";

/// hostile_stem as valid JSON must decode: the invalid byte becomes U+FFFD.
const std::string hostile_stem_decoded = std::string("a\x01q\"b\\n\nx\xEF\xBF\xBD") + "y";

fs::path write_two_discs(const fs::path& dir, const std::string& stem) {
    const fs::path file = dir / (stem + ".txt");
    std::ofstream(file) << "2\n0.2 0.5 0.1 0 0.1 1 255 0 0\n0.8 0.5 -0.1 0 0.1 1 0 0 255\n";
    return file;
}

/// Strict JSON: parse() refuses raw control characters in strings and invalid UTF-8.
nlohmann::json parse_json(const std::string& text) {
    INFO(text);
    nlohmann::json value;
    CHECK_NOTHROW(value = nlohmann::json::parse(text));
    return value;
}

}  // namespace

TEST_CASE("simulate --json escapes control characters and replaces invalid UTF-8 of a file name") {
    TempDir dir("conventions_simulate");
    const fs::path scene = write_two_discs(dir.path, hostile_stem);
    const auto r = run_stdout("simulate " + shell_quoted(scene.string()) + " --until 1 --json");
    REQUIRE(r.exit_code == 0);
    const nlohmann::json value = parse_json(r.output);
    CHECK(value.at("scene") == hostile_stem_decoded);
    CHECK(value.at("discs") == 2);
    CHECK(value.at("t") == 1.0);
}

TEST_CASE("check --json: the scene, its name, its discs and the summary, valid for any name") {
    TempDir dir("conventions_check");
    const fs::path scene = write_two_discs(dir.path, hostile_stem);
    const auto r = run_stdout("check " + shell_quoted(scene.string()) + " --json");
    REQUIRE(r.exit_code == 0);
    const nlohmann::json value = parse_json(r.output);
    CHECK(value.at("discs") == 2);
    CHECK(value.at("exported").is_null());
    CHECK(value.at("summary").get<std::string>().find("N = 2") != std::string::npos);
    const auto builtin = run_stdout("check gas --json");
    REQUIRE(builtin.exit_code == 0);
    CHECK(parse_json(builtin.output).at("name") == "gas");
}

TEST_CASE("scenes --json lists every built-in scene with its description") {
    const auto r = run_stdout("scenes --json");
    REQUIRE(r.exit_code == 0);
    const nlohmann::json list = parse_json(r.output);
    REQUIRE(list.is_array());
    CHECK(list.size() >= 8);
    bool gas = false;
    for (const auto& entry : list) {
        CHECK(!entry.at("description").get<std::string>().empty());
        gas = gas || entry.at("name") == "gas";
    }
    CHECK(gas);
}

TEST_CASE("thumbnail --json: the summary as JSON, naming an output path of any bytes") {
    TempDir dir("conventions_thumbnail");
    const fs::path png = dir.path / (hostile_stem + ".png");
    const auto r =
        run_stdout("thumbnail gas --at 0.5 --size 160x90 --json -o " + shell_quoted(png.string()));
    REQUIRE(r.exit_code == 0);
    CHECK(fs::is_regular_file(png));
    const nlohmann::json value = parse_json(r.output);
    CHECK(value.at("kind") == "png");
    CHECK(value.at("width") == 160);
    CHECK(value.at("height") == 90);
    CHECK(value.at("bytes") == fs::file_size(png));
    CHECK(value.at("output") == (dir.path / (hostile_stem_decoded + ".png")).string());
    CHECK(value.at("engines").size() == 2);
}

TEST_CASE("a mistyped subcommand or option gets a suggestion") {
    const auto command = run_collide("rendr gas");
    CHECK(command.exit_code == 2);
    CHECK_MESSAGE(command.output.find("(did you mean 'render'?)") != std::string::npos,
                  command.output);
    const auto option = run_collide("render gas --durration 5");
    CHECK(option.exit_code == 2);
    CHECK_MESSAGE(option.output.find("(did you mean '--duration'?)") != std::string::npos,
                  option.output);
    const auto with_value = run_collide("check gas --jsn");
    CHECK(with_value.exit_code == 2);
    CHECK_MESSAGE(with_value.output.find("(did you mean '--json'?)") != std::string::npos,
                  with_value.output);
    // Nothing close: no suggestion.
    const auto far = run_collide("render gas --zzzzzzzz");
    CHECK(far.exit_code == 2);
    CHECK(far.output.find("did you mean") == std::string::npos);
}

TEST_CASE("--version names the git revision, the GL backends, libav and the data directory") {
    const auto r = run_collide("--version");
    REQUIRE(r.exit_code == 0);
    CHECK(r.output.rfind("collide 0.", 0) == 0);
    CHECK(r.output.find("(git ") != std::string::npos);
    CHECK(r.output.find("\nGL backends: ") != std::string::npos);
    CHECK(r.output.find("glfw") != std::string::npos);
    CHECK(r.output.find("\nlibav (built with): libavcodec ") != std::string::npos);
    CHECK(r.output.find("\ndata: ") != std::string::npos);
}

TEST_CASE("--font and $COLLIDE_FONT: a missing file is exit 2 naming the option") {
    const auto option = run_collide("thumbnail gas --font /nonexistent/font.ttf -o /dev/null");
    CHECK(option.exit_code == 2);
    CHECK(option.output.find("--font: expected a TrueType font file") != std::string::npos);
    const auto variable =
        collide::test::run_collide_env("COLLIDE_FONT=/nonexistent/font.ttf", "heap --ops 'P *'");
    CHECK(variable.exit_code == 2);
    CHECK(variable.output.find("$COLLIDE_FONT: expected") != std::string::npos);
}

TEST_CASE("--font and $COLLIDE_FONT: a file that is not a font is the user's, not the install's") {
    TempDir dir("conventions_font");
    const fs::path text = dir.path / "notes.ttf";
    std::ofstream(text) << "this is not a font, whatever its name says\n";
    const fs::path empty = dir.path / "empty.otf";
    std::ofstream(empty).close();
    // A copy of a real font, cut in half: damaged.
    const fs::path dejavu = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    const fs::path cut = dir.path / "cut.ttf";
    if (fs::exists(dejavu)) {
        fs::copy_file(dejavu, cut);
        fs::resize_file(cut, fs::file_size(dejavu) / 2);
    }
    // Larger than any font (sparse: it costs no disk), refused before it is read.
    const fs::path huge = dir.path / "huge.ttf";
    std::ofstream(huge).close();
    fs::resize_file(huge, 300ULL * 1024 * 1024);
    std::vector<fs::path> files{text, empty, huge};
    if (fs::exists(cut)) files.push_back(cut);
    for (const fs::path& file : files) {
        CAPTURE(file);
        const auto option =
            run_collide("thumbnail gas --font '" + file.string() + "' -o /dev/null");
        CHECK(option.exit_code == 2);
        CHECK(option.output.find("--font: '" + file.string() + "' is not a usable font file") !=
              std::string::npos);
        CHECK(option.output.find("fonts-dejavu-core") == std::string::npos);
        const auto variable = collide::test::run_collide_env(
            "COLLIDE_FONT='" + file.string() + "'",
            "heap --ops 'P *' -o '" + (dir.path / "h.mp4").string() + "'");
        CHECK(variable.exit_code == 2);
        CHECK(variable.output.find("$COLLIDE_FONT: '" + file.string() + "'") != std::string::npos);
        CHECK(variable.output.find("fonts-dejavu-core") == std::string::npos);
    }
    const auto huge_run = run_collide("render gas --font '" + huge.string() + "' -o '" +
                                      (dir.path / "g.mp4").string() + "'");
    CHECK(huge_run.exit_code == 2);
    CHECK(huge_run.output.find("300 MB, more than the 256 MB a font file may have") !=
          std::string::npos);
    // check only warns (it needs no font), in the same words.
    const auto check = run_collide("check gas --font '" + text.string() + "'");
    CHECK(check.exit_code == 0);
    CHECK(check.output.find("--font: '" + text.string() + "' is not a usable font file") !=
          std::string::npos);
}

TEST_CASE("render --progress bar fits COLUMNS=60 and --progress plain writes whole lines") {
    TempDir dir("conventions_progress");
    const std::string video = (dir.path / "g.mp4").string();
    const auto bar = collide::test::run_collide_env(
        "COLUMNS=60", "render gas -q l --size 160x90 --duration 1 --progress bar -o " + video);
    REQUIRE(bar.exit_code == 0);
    int bars = 0;
    std::string line;
    for (const char c : bar.output + "\n") {
        if (c == '\r' || c == '\n') {
            if (line.rfind("[", 0) == 0) {
                ++bars;
                CHECK_MESSAGE(line.size() <= 59, line);
            }
            line.clear();
        } else {
            line += c;
        }
    }
    CHECK(bars >= 1);
    const auto plain =
        run_collide("render gas -q l --size 160x90 --duration 1 --progress plain -o " + video);
    REQUIRE(plain.exit_code == 0);
    CHECK(plain.output.find('\r') == std::string::npos);
    CHECK(plain.output.find("collide: 100% (") != std::string::npos);
}

TEST_CASE("compare: exit 0 on a match, 1 on a mismatch with a difference image, 2 on bad input") {
    TempDir dir("conventions_compare");
    const auto path = [&](const char* name) { return (dir.path / name).string(); };
    REQUIRE(run_collide("thumbnail gas --at 1 --size 160x90 -o " + path("a.png")).exit_code == 0);
    REQUIRE(run_collide("thumbnail gas --at 1 --size 160x90 -o " + path("same.png")).exit_code ==
            0);
    REQUIRE(run_collide("thumbnail gas --at 2 --size 160x90 -o " + path("b.png")).exit_code == 0);
    REQUIRE(run_collide("thumbnail gas --at 1 --size 320x180 -o " + path("big.png")).exit_code ==
            0);

    const auto same = run_collide("compare " + path("a.png") + " " + path("same.png"));
    CHECK_MESSAGE(same.exit_code == 0, same.output);
    CHECK(same.output.rfind("match: 14400 pixels", 0) == 0);
    CHECK(!fs::exists(dir.path / "same.diff.png"));

    const auto differ = run_collide("compare " + path("a.png") + " " + path("b.png"));
    CHECK_MESSAGE(differ.exit_code == 1, differ.output);
    CHECK(differ.output.rfind("differ: ", 0) == 0);
    CHECK(differ.output.find(" of 14400 pixels (") != std::string::npos);
    CHECK(differ.output.find("difference image: " + path("b.diff.png")) != std::string::npos);
    REQUIRE(fs::is_regular_file(dir.path / "b.diff.png"));
    // A tolerance of 255 accepts any difference.
    CHECK(run_collide("compare " + path("a.png") + " " + path("b.png") + " --tolerance 255")
              .exit_code == 0);
    // --diff puts the picture elsewhere.
    CHECK(run_collide("compare " + path("a.png") + " " + path("b.png") + " --diff " + path("d.png"))
              .exit_code == 1);
    CHECK(fs::is_regular_file(dir.path / "d.png"));
    const auto sizes = run_collide("compare " + path("a.png") + " " + path("big.png"));
    CHECK(sizes.exit_code == 1);
    CHECK(sizes.output.find("is 160x90") != std::string::npos);

    std::ofstream(dir.path / "not.png") << "not a png";
    for (const std::string& args :
         {path("a.png") + " " + path("none.png"), path("not.png") + " " + path("a.png"),
          path("a.png") + " " + path("b.png") + " --tolerance 256", path("a.png")}) {
        CAPTURE(args);
        const auto bad = run_collide("compare " + args);
        CHECK_MESSAGE(bad.exit_code == 2, bad.output);
        CHECK(bad.output.find("collide: error: ") != std::string::npos);
    }
}
