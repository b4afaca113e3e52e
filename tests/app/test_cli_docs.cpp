// The documents generated from the command line (issue #46): the man page and the bash, zsh and
// fish completion name every command and every option that the program defines (its CLI11 tree,
// walked by `collide-draw --generate-docs json`); `collide help [COMMAND]`, `-V`, and help that
// fits 80 columns when it does not go to a terminal.

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "run_collide.hpp"

using collide::test::run_collide;
using collide::test::run_command;

namespace {

namespace fs = std::filesystem;

std::string read_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    REQUIRE_MESSAGE(in.good(), "cannot read " << path);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string generated(const std::string& file) {
    return read_file(fs::path(COLLIDE_DOCS_DIR) / file);
}

/// The command line's tree: every command (the root first, name "") and its options.
nlohmann::json command_tree() {
    const auto r =
        run_command(std::string("\"") + COLLIDE_DRAW_EXE + "\" --generate-docs json 2>/dev/null");
    REQUIRE(r.exit_code == 0);
    return nlohmann::json::parse(r.output)["commands"];
}

/// The text of `doc` from the line that starts with `start` to the next line starting with
/// `next` ("" when `start` is not there).
std::string section(const std::string& doc, const std::string& start, const std::string& next) {
    const std::size_t from = doc.find(start);
    if (from == std::string::npos) return {};
    const std::size_t to = doc.find(next, from + start.size());
    return doc.substr(from, to == std::string::npos ? std::string::npos : to - from);
}

/// An option name as roff writes it: every dash a minus sign.
std::string roff_name(const std::string& name) {
    std::string out;
    for (const char c : name) out += c == '-' ? std::string("\\-") : std::string(1, c);
    return out;
}

bool has_word(const std::string& line, const std::string& word) {
    std::istringstream words(line);
    std::string w;
    while (words >> w) {
        // options='--a ... --z' and commands='a ... z': the quotes are not part of the words.
        while (!w.empty() && (w.back() == '\'' || w.back() == ';')) w.pop_back();
        if (const std::size_t quote = w.find('\''); quote != std::string::npos)
            w = w.substr(quote + 1);
        if (w == word) return true;
    }
    return false;
}

}  // namespace

TEST_CASE("the command tree holds every command, and the options added lately") {
    const nlohmann::json tree = command_tree();
    std::vector<std::string> names;
    for (const auto& c : tree) names.push_back(c["name"]);
    for (const char* expected : {"", "check", "scenes", "pq", "heap", "puzzle", "render",
                                 "thumbnail", "compare", "simulate", "bench", "help"}) {
        CHECK_MESSAGE(std::find(names.begin(), names.end(), expected) != names.end(), expected);
    }
    const auto has_option = [&](const std::string& command, const std::string& option) {
        for (const auto& c : tree) {
            if (c["name"] != command) continue;
            for (const auto& o : c["options"]) {
                for (const auto& n : o["names"])
                    if (n == option) return true;
            }
        }
        return false;
    };
    CHECK(has_option("render", "--chapters"));
    CHECK(has_option("render", "--slides"));
    CHECK(has_option("render", "--subtitles"));
    CHECK(has_option("render", "--questions"));
    CHECK(has_option("heap", "--questions"));
    CHECK(has_option("puzzle", "--questions"));
    CHECK(has_option("heap", "--timeline-json"));
    CHECK(has_option("puzzle", "--timeline-json"));
    CHECK(has_option("compare", "--max-diff-percent"));
    CHECK(has_option("", "-V"));
    CHECK(!has_option("", "--generate-docs"));  // hidden: for the build only
    CHECK(!has_option("render", "--dump-rgba"));
}

TEST_CASE("the man page and the bash, zsh and fish completion name every command and option") {
    const nlohmann::json tree = command_tree();
    const std::string man = generated("collide.1");
    const std::string bash = generated("collide.bash");
    const std::string zsh = generated("_collide");
    const std::string fish = generated("collide.fish");
    // The files installed are the ones this program writes now (not left from an older build).
    for (const auto& [kind, text] : {std::pair<std::string, const std::string*>{"man", &man},
                                     {"bash", &bash},
                                     {"zsh", &zsh},
                                     {"fish", &fish}}) {
        const auto r = run_command(std::string("\"") + COLLIDE_DRAW_EXE + "\" --generate-docs " +
                                   kind + " 2>/dev/null");
        CHECK_MESSAGE(r.output == *text, kind);
    }
    for (const auto& c : tree) {
        const std::string name = c["name"];
        CAPTURE(name);
        const std::string man_part = name.empty() ? section(man, ".SH OPTIONS", ".SH")
                                                  : section(man, ".SS \"collide " + name, "\n.S");
        const std::string bash_line = section(
            bash, "        " + (name.empty() ? std::string("''") : name) + ") options=", "\n");
        const std::string zsh_part = name.empty() ? section(zsh, "_arguments -C", "'1:command")
                                                  : section(zsh, "        (" + name + ")\n", ";;");
        CHECK(!man_part.empty());
        CHECK(!bash_line.empty());
        CHECK(!zsh_part.empty());
        if (!name.empty()) {
            CHECK(has_word(section(bash, "    local commands=", "\n"), name));
            CHECK(zsh.find("'" + name + ":") != std::string::npos);
            CHECK(fish.find("-a " + name + " -d") != std::string::npos);
        }
        const std::string fish_condition = name.empty()
                                               ? "-n '__fish_use_subcommand'"
                                               : "__fish_seen_subcommand_from " + name + "'";
        for (const auto& o : c["options"]) {
            for (const auto& n : o["names"]) {
                const std::string option = n;
                CAPTURE(option);
                if (o["positional"]) {
                    CHECK(man_part.find("\\fI" + option + "\\fR") != std::string::npos);
                    continue;
                }
                CHECK(man_part.find(roff_name(option)) != std::string::npos);
                CHECK(has_word(bash_line, option));
                CHECK(zsh_part.find(option + "[") != std::string::npos);
                const std::string fish_flag =
                    option.size() == 2 ? " -s " + option.substr(1) : " -l " + option.substr(2);
                bool in_fish = false;
                std::istringstream lines(fish);
                for (std::string line; std::getline(lines, line);) {
                    in_fish = in_fish || (line.find(fish_condition) != std::string::npos &&
                                          (line + " ").find(fish_flag + " ") != std::string::npos);
                }
                CHECK(in_fish);
            }
        }
    }
    // The man page has the sections a packager expects, and exit codes and environment.
    for (const char* heading : {".SH NAME", ".SH SYNOPSIS", ".SH OPTIONS", ".SH COMMANDS",
                                ".SH EXIT STATUS", ".SH ENVIRONMENT", ".SH FILES"}) {
        CHECK(man.find(heading) != std::string::npos);
    }
    CHECK(man.find("COLLIDE_FONT") != std::string::npos);
    CHECK(man.find("COLLIDE_DATA_DIR") != std::string::npos);
    // The compressed copy that is installed.
    const fs::path gz = fs::path(COLLIDE_DOCS_DIR) / "collide.1.gz";
    REQUIRE(fs::exists(gz));
    CHECK(fs::file_size(gz) > 100);
}

TEST_CASE("bash completion works in plain bash (no bash-completion package)") {
    const std::string file = (fs::path(COLLIDE_DOCS_DIR) / "collide.bash").string();
    const auto complete = [&](const std::string& words, int cword) {
        return run_command("bash --norc --noprofile -c 'source \"" + file + "\"; COMP_WORDS=(" +
                           words + "); COMP_CWORD=" + std::to_string(cword) +
                           "; _collide; echo \"${COMPREPLY[*]}\"' 2>&1");
    };
    const auto commands = complete("collide ren", 1);
    CHECK(commands.exit_code == 0);
    CHECK(commands.output == "render\n");
    CHECK(complete("collide render --chap", 2).output.find("--chapters") != std::string::npos);
    CHECK(complete("collide compare --max", 2).output == "--max-diff-pixels --max-diff-percent\n");
    CHECK(complete("collide pq --format \"\"", 3).output == "text csv markdown\n");
    CHECK(complete("collide -", 1).output.find("--version") != std::string::npos);
    CHECK(complete("collide -", 1).output.find("_init_completion") == std::string::npos);
}

TEST_CASE("the man page renders without a warning from groff") {
    if (run_command("command -v groff >/dev/null 2>&1").exit_code != 0) {
        MESSAGE("groff is not installed: skipped");
        return;
    }
    const auto r = run_command("groff -man -Tutf8 -ww -z \"" +
                               (fs::path(COLLIDE_DOCS_DIR) / "collide.1").string() + "\" 2>&1");
    CHECK(r.exit_code == 0);
    CHECK_MESSAGE(r.output.empty(), r.output);
}

TEST_CASE("collide help [COMMAND], -V, and help that fits 80 columns off a terminal") {
    const auto help = run_collide("help");
    CHECK(help.exit_code == 0);
    CHECK(help.output == run_collide("--help").output);
    for (const char* command : {"render", "compare", "check", "puzzle", "heap", "simulate"}) {
        CAPTURE(command);
        const auto h = run_collide(std::string("help ") + command);
        CHECK(h.exit_code == 0);
        CHECK(h.output == run_collide(std::string(command) + " --help").output);
        CHECK(h.output.find("did you mean") == std::string::npos);
    }
    const auto unknown = run_collide("help rendr");
    CHECK(unknown.exit_code == 2);
    CHECK(unknown.output.find("did you mean 'render'") != std::string::npos);
    const auto v = run_collide("-V");
    CHECK(v.exit_code == 0);
    CHECK(v.output == run_collide("--version").output);
    // Every command's help, with COLUMNS unset and stdout a pipe: no line over 80 columns.
    for (const char* command : {"", "render", "thumbnail", "compare", "heap", "puzzle", "check",
                                "scenes", "pq", "simulate", "bench"}) {
        CAPTURE(command);
        const auto h =
            collide::test::run_collide_env("env -u COLUMNS", std::string(command) + " --help");
        CHECK(h.exit_code == 0);
        std::istringstream lines(h.output);
        for (std::string line; std::getline(lines, line);) {
            CHECK_MESSAGE(line.size() <= 80, line);
        }
    }
}

TEST_CASE("help shows what each option takes: INT, FLOAT, PATH, WxH, and the choices") {
    const auto compare = run_collide("compare --help").output;
    CHECK(compare.find("--tolerance INT") != std::string::npos);
    CHECK(compare.find("--max-diff-percent FLOAT") != std::string::npos);
    CHECK(compare.find("--diff PATH") != std::string::npos);
    CHECK(run_collide("pq --help").output.find("{text,csv,markdown}") != std::string::npos);
}

TEST_CASE("no option's value shows as TEXT: queues, operations, boards and methods are named") {
    for (const char* command : {"", "render", "thumbnail", "compare", "heap", "puzzle", "check",
                                "scenes", "pq", "simulate", "bench engine"}) {
        CAPTURE(command);
        const std::string help = run_collide(std::string(command) + " --help").output;
        CHECK(!help.empty());
        CHECK(help.find(" TEXT") == std::string::npos);
    }
    const std::string queues = "{unordered,ordered,binary,dary:D,indexed[:D]}";
    CHECK(run_collide("heap --help").output.find("--impl " + queues) != std::string::npos);
    CHECK(run_collide("heap --help").output.find("--ops OPS") != std::string::npos);
    CHECK(run_collide("heap --help").output.find("--sort KEYS") != std::string::npos);
    CHECK(run_collide("pq --help").output.find("--ops OPS") != std::string::npos);
    const std::string puzzle = run_collide("puzzle --help").output;
    CHECK(puzzle.find("board BOARD") != std::string::npos);
    CHECK(puzzle.find("--heuristic {manhattan,hamming}") != std::string::npos);
    CHECK(puzzle.find("--method {both,bfs,astar}") != std::string::npos);
    CHECK(puzzle.find("--pq " + queues) != std::string::npos);
    CHECK(run_collide("simulate --help").output.find("--pq " + queues) != std::string::npos);
    CHECK(run_collide("bench engine --help").output.find("--engine {fast,classic}") !=
          std::string::npos);
    // The man page lists the queue's forms; completion offers those typed as they are (dary:D
    // needs its arity, so the user types it).
    const std::string man = generated("collide.1");
    CHECK(man.find("(one of: unordered, ordered, binary, dary:D, indexed[:D])") !=
          std::string::npos);
    const std::string file = (fs::path(COLLIDE_DOCS_DIR) / "collide.bash").string();
    const auto r = run_command("bash --norc --noprofile -c 'source \"" + file +
                               "\"; COMP_WORDS=(collide heap --impl \"\"); COMP_CWORD=3; "
                               "_collide; echo \"${COMPREPLY[*]}\"' 2>&1");
    CHECK(r.output == "unordered ordered binary indexed\n");
}
