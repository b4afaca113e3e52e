// What the program promises for its outputs (docs/outputs.md), through the real executable:
// never a lost or clobbered user file, no temporary left, symbolic links written through,
// standard output for "-", exit 1 for a full disk and 2 (with the reason) for an unwritable path.

#include <doctest/doctest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "../support/files.hpp"
#include "../support/skip.hpp"
#include "../support/temp_dir.hpp"
#include "run_collide.hpp"

namespace {

namespace fs = std::filesystem;
using collide::test::entries;
using collide::test::read_all;
using collide::test::run_collide;
using collide::test::run_collide_shell;
using collide::test::RunResult;
using collide::test::shell_quoted;
using collide::test::TempDir;
using collide::test::write_file;

bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

/// A short, cheap video: 5 frames at 854x480.
const std::string small_video = " -q l --duration 0.3 --progress none";

/// Runs `collide ARGS` in a child whose pid is known before it starts, so that `prepare(pid)`
/// can plant files at names derived from it (the pid survives exec). Returns the exit code.
template <typename Prepare>
int run_with_pid(const std::vector<std::string>& args, const fs::path& log, Prepare prepare) {
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        prepare(getpid());
        std::vector<std::string> argv{COLLIDE_EXE};
        argv.insert(argv.end(), args.begin(), args.end());
        std::vector<char*> pointers;
        for (std::string& a : argv) pointers.push_back(a.data());
        pointers.push_back(nullptr);
        const std::string log_name = log.string();
        if (std::freopen(log_name.c_str(), "w", stdout) == nullptr) _exit(126);
        dup2(STDOUT_FILENO, STDERR_FILENO);
        execv(pointers[0], pointers.data());
        _exit(127);
    }
    int status = 0;
    waitpid(child, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

TEST_CASE("render --format png -o DIR never deletes what it did not create") {
    TempDir dir("outputs_png_dir");
    const fs::path out = dir.path / "out";
    fs::create_directory(out);
    REQUIRE(run_collide("render gas" + small_video + " -o " + shell_quoted(out / "gas.mp4"))
                .exit_code == 0);
    const std::string video = read_all(out / "gas.mp4");
    // The report: this removed out/gas.mp4.
    const RunResult r =
        run_collide("render gas" + small_video + " --format png -o " + shell_quoted(out));
    CHECK(r.exit_code == 2);
    CHECK(contains(r.output, "holds other files ('gas.mp4')"));
    CHECK(read_all(out / "gas.mp4") == video);
    CHECK(entries(out) == std::vector<std::string>{"gas.mp4"});
    CHECK(entries(dir.path) == std::vector<std::string>{"out"});

    // A new directory, then the same one again: an earlier sequence of the same name is replaced.
    const fs::path frames = dir.path / "frames";
    REQUIRE(run_collide("render gas" + small_video + " --format png -o " + shell_quoted(frames))
                .exit_code == 0);
    CHECK(entries(frames).size() == 5);
    CHECK(run_collide("render gas -q l --duration 0.2 --progress none --format png -o " +
                      shell_quoted(frames))
              .exit_code == 0);
    CHECK(entries(frames).size() == 3);  // the whole earlier sequence replaced
    CHECK(entries(dir.path) == std::vector<std::string>{"frames", "out"});
}

TEST_CASE("render --format png -o . and -o .. are refused before anything is rendered") {
    TempDir dir("outputs_png_dot");
    const fs::path work = dir.path / "work";
    fs::create_directories(work / "inner");
    write_file(work / "notes.txt", "mine");
    write_file(work / "inner" / "notes.txt", "mine too");
    // Run inside work/inner, so that even a broken build could only reach this test's files.
    // --speed 1e300 --no-limits: rendering would never end (timeout fails it), so an answer at
    // all means the refusal came up front.
    for (const char* bad : {".", "..", "./", "inner/..", "../inner", "/"}) {
        CAPTURE(bad);
        const RunResult r = run_collide_shell(
            "cd " + shell_quoted(work / "inner") + " && timeout 60 \"" + COLLIDE_EXE +
            "\" render gas --speed 1e300 --no-limits --format png -o '" + bad +
            "' --progress none");
        CHECK(r.exit_code == 2);
        CHECK((contains(r.output, "give it a name") || contains(r.output, "current directory")));
    }
    CHECK(read_all(work / "notes.txt") == "mine");
    CHECK(read_all(work / "inner" / "notes.txt") == "mine too");
    CHECK(entries(dir.path) == std::vector<std::string>{"work"});
    CHECK(entries(work) == std::vector<std::string>{"inner", "notes.txt"});
}

TEST_CASE("render: a legal 250-byte file name works") {
    TempDir dir("outputs_long_name");
    const fs::path out = dir.path / (std::string(246, 'v') + ".mp4");
    const RunResult r = run_collide("render gas" + small_video + " -o " + shell_quoted(out));
    CHECK(r.exit_code == 0);
    CHECK(fs::file_size(out) > 1000);
    CHECK(entries(dir.path).size() == 1);
}

TEST_CASE("render: a symlinked output is written through, the link kept") {
    TempDir dir("outputs_symlink");
    write_file(dir.path / "v1.mp4", "old");
    fs::create_symlink("v1.mp4", dir.path / "latest.mp4");
    const RunResult r =
        run_collide("render gas" + small_video + " -o " + shell_quoted(dir.path / "latest.mp4"));
    CHECK(r.exit_code == 0);
    CHECK(fs::is_symlink(dir.path / "latest.mp4"));
    CHECK(fs::file_size(dir.path / "v1.mp4") > 1000);
    CHECK(entries(dir.path) == std::vector<std::string>{"latest.mp4", "v1.mp4"});
}

TEST_CASE("render: -o NAME without extension with --format writes that format") {
    TempDir dir("outputs_noext");
    const RunResult r = run_collide("render gas" + small_video + " --format mp4 -o " +
                                    shell_quoted(dir.path / "noext"));
    CHECK(r.exit_code == 0);
    CHECK(read_all(dir.path / "noext").substr(4, 4) == "ftyp");  // an MP4
    const RunResult clash = run_collide("render gas" + small_video + " --format mp4 -o " +
                                        shell_quoted(dir.path / "x.gif"));
    CHECK(clash.exit_code == 2);
    CHECK(contains(clash.output, "ends in .gif, but --format is mp4"));
    CHECK_FALSE(contains(clash.output, "or --format"));
}

TEST_CASE("render: stale temporaries of a dead run are removed, a live run's are kept") {
    TempDir dir("outputs_stale");
    const pid_t dead = fork();
    REQUIRE(dead >= 0);
    if (dead == 0) _exit(0);
    waitpid(dead, nullptr, 0);
    // What a SIGKILLed run leaves on a filesystem without O_TMPFILE.
    const std::string stale = ".out.mp4.collide-" + std::to_string(dead) + "-Ab12Cd";
    const std::string live = ".out.mp4.collide-" + std::to_string(getpid()) + "-Ef34Gh";
    write_file(dir.path / stale, "half a video");
    write_file(dir.path / live, "a video being written");
    write_file(dir.path / ".out.mp4.XXXXXX", "not ours: another pattern");
    const RunResult r =
        run_collide("render gas" + small_video + " -o " + shell_quoted(dir.path / "out.mp4"));
    CHECK(r.exit_code == 0);
    std::vector<std::string> expected{live, ".out.mp4.XXXXXX", "out.mp4"};
    std::sort(expected.begin(), expected.end());
    CHECK(entries(dir.path) == expected);
}

TEST_CASE(
    "simulate --events-log: '-' is standard output, and a symlink at a temporary name is not "
    "followed") {
    TempDir dir("outputs_events");
    const RunResult r = run_collide("simulate gas --until 1 --events-log -");
    CHECK(r.exit_code == 0);
    CHECK(r.output.rfind("t,kind,a,b\n", 0) == 0);
    CHECK_FALSE(fs::exists("-"));

    // The old fixed pattern DEST.tmp-<pid>, planted by someone who guesses the pid.
    write_file(dir.path / "victim.txt", "precious");
    const int code = run_with_pid(
        {"simulate", "gas", "--until", "1", "--events-log", (dir.path / "ev.csv").string()},
        dir.path / "log.txt", [&](pid_t pid) {
            fs::create_symlink(dir.path / "victim.txt",
                               dir.path / ("ev.csv.tmp-" + std::to_string(pid)));
        });
    CHECK(code == 0);
    CHECK(read_all(dir.path / "victim.txt") == "precious");
    CHECK(fs::is_regular_file(fs::symlink_status(dir.path / "ev.csv")));
    CHECK(read_all(dir.path / "ev.csv").rfind("t,kind,a,b\n", 0) == 0);
}

TEST_CASE("simulate --events-log to a full device is exit 1 with the reason") {
    TempDir dir("outputs_full");
    // Through a link, so that nothing can ever replace /dev/full itself.
    fs::create_symlink("/dev/full", dir.path / "full.csv");
    const RunResult r =
        run_collide("simulate gas --until 10 --events-log " + shell_quoted(dir.path / "full.csv"));
    CHECK(r.exit_code == 1);
    CHECK(contains(r.output, "No space left on device"));
    CHECK(fs::is_symlink(dir.path / "full.csv"));
}

TEST_CASE("check --export: an unrelated DEST.partial is left alone") {
    TempDir dir("outputs_partial");
    write_file(dir.path / "x.toml.partial", "the user's own file");
    const RunResult r = run_collide("check gas --export " + shell_quoted(dir.path / "x.toml"));
    CHECK(r.exit_code == 0);
    CHECK(read_all(dir.path / "x.toml.partial") == "the user's own file");
    CHECK(entries(dir.path) == std::vector<std::string>{"x.toml", "x.toml.partial"});
}

TEST_CASE("check --export: concurrent exports to one path each leave a whole file") {
    TempDir dir("outputs_concurrent");
    const fs::path out = dir.path / "x.toml";
    REQUIRE(run_collide("check brownian --export " + shell_quoted(dir.path / "a.toml")).exit_code ==
            0);
    REQUIRE(
        run_collide("check dense-fluid --export " + shell_quoted(dir.path / "b.toml")).exit_code ==
        0);
    const std::string a = read_all(dir.path / "a.toml");
    const std::string b = read_all(dir.path / "b.toml");
    const std::string exe = std::string("\"") + COLLIDE_EXE + "\"";
    for (int round = 0; round < 5; ++round) {
        CAPTURE(round);
        const std::string both = exe + " check brownian --export " + shell_quoted(out) +
                                 " >/dev/null & " + exe + " check dense-fluid --export " +
                                 shell_quoted(out) + " >/dev/null & wait";
        CHECK(std::system(both.c_str()) == 0);
        const std::string result = read_all(out);
        CHECK((result == a || result == b));
    }
    CHECK(entries(dir.path) == std::vector<std::string>{"a.toml", "b.toml", "x.toml"});
}

TEST_CASE("check --export: a full disk is exit 1, not bad input") {
    TempDir dir("outputs_export_full");
    // A file size limit makes writes fail as a full disk does (EFBIG), on any filesystem.
    const std::string command = "trap '' XFSZ; ulimit -f 1; exec \"" + std::string(COLLIDE_EXE) +
                                "\" check dense-fluid --export " +
                                shell_quoted(dir.path / "x.toml");
    const RunResult r = run_collide_shell(command);
    CHECK(r.exit_code == 1);
    CHECK(contains(r.output, "File too large"));
    CHECK(entries(dir.path).empty());
}

TEST_CASE("check --export: a read-only filesystem is exit 2 with the reason") {
    if (geteuid() != 0 || std::system("unshare -m true 2>/dev/null") != 0) {
        COLLIDE_SKIP_TEST("needs root and unshare(1) to mount a read-only filesystem privately");
    }
    // A private mount namespace: the read-only tmpfs exists for this one command only.
    TempDir dir("outputs_read_only");
    const std::string command = "unshare -m sh -c \"mount -t tmpfs -o ro none " +
                                shell_quoted(dir.path) + " && exec '" + COLLIDE_EXE +
                                "' check gas --export " + shell_quoted(dir.path / "x.toml") + "\"";
    const RunResult r = run_collide_shell(command);
    CHECK(r.exit_code == 2);
    CHECK(contains(r.output, "Read-only file system"));
}

TEST_CASE("one output rule for render, thumbnail, heap and puzzle (-o, --format, stills)") {
    // Every destination lies in a directory that does not exist: a request the rule accepts
    // then stops at the path ("directory ... does not exist"), one it refuses names -o or
    // --format; nothing is ever rendered. The same answers for every command.
    const TempDir dir("outputs_rule");
    const std::string m = shell_quoted(dir.path / "missing") + "/";
    const std::vector<std::string> videos = {"render gas", "heap --ops 'P Q *'",
                                             "puzzle '1 2 3 4 5 6 7 0 8'"};
    struct Case {
        std::string options;
        std::string refused;  ///< the option the rule names; empty: accepted
    };
    const std::vector<Case> video_cases = {
        {"-o M/x.MP4", ""},
        {"-o M/x.avi --format mp4", ""},  // with --format, any extension but another format's
        {"-o M/x --format png", ""},
        {"-o M/x.gif --format mp4", "-o"},
        {"-o M/x.gif --format png", "-o"},  // a directory of frames named .gif misleads
        {"-o M/x.mp4 --format png", "-o"},
        {"-o M/x.avi", "-o"},  // without --format, the extension decides
        {"-o M/x", "-o"},
        {"-o M/x.png", "-o"},
        {"-o M/x.mp4 --format avi", "--format"},
        {"-o M/x.png --last-frame --format gif", "--format"},  // a still is a PNG
    };
    // One frame: thumbnail always, the others with --last-frame.
    const std::vector<Case> still_cases = {
        {"-o M/x.PNG", ""}, {"-o M/x.mp4", "-o"}, {"-o M/x", "-o"}};
    const auto check = [&](const std::string& command, const Case& c) {
        std::string options = c.options;
        for (std::size_t at = options.find("M/"); at != std::string::npos;
             at = options.find("M/", at)) {
            options.replace(at, 2, m);
            at += m.size();
        }
        const RunResult r = run_collide(command + " " + options + " --progress none");
        INFO(command << " " << c.options << "\n" << r.output);
        CHECK(r.exit_code == 2);
        if (c.refused.empty()) {
            CHECK(contains(r.output, "does not exist"));
        } else {
            CHECK(contains(r.output, "error: " + c.refused + ":"));
        }
    };
    for (const std::string& command : videos) {
        for (const Case& c : video_cases) check(command, c);
    }
    for (const Case& c : still_cases) {
        check("thumbnail gas", c);
        for (const std::string& command : videos)
            check(command, {c.options + " --last-frame", c.refused});
    }
    CHECK(entries(dir.path).empty());
}

TEST_CASE("render: two outputs that are one file (same name, a link, a hard link) are refused") {
    TempDir dir("outputs_same_file");
    const fs::path video = dir.path / "x.mp4";
    write_file(video, "old");
    fs::create_symlink("x.mp4", dir.path / "link.json");
    fs::create_hard_link(video, dir.path / "hard.json");
    for (const std::string layout : {"x.mp4", "link.json", "hard.json"}) {
        const RunResult r = run_collide("render gas" + small_video + " -o " + shell_quoted(video) +
                                        " --layout-json " + shell_quoted(dir.path / layout));
        INFO(layout << "\n" << r.output);
        CHECK(r.exit_code == 2);
        CHECK(contains(r.output, "is the same file as -o"));
        CHECK(read_all(video) == "old");
    }
    // A layout inside the directory of frames would vanish with the directory it replaces.
    const RunResult r = run_collide("render gas" + small_video + " --format png -o " +
                                    shell_quoted(dir.path / "frames") + " --layout-json " +
                                    shell_quoted(dir.path / "frames" / "l.json"));
    CHECK(r.exit_code == 2);
    CHECK(contains(r.output, "lies inside -o"));
    CHECK(entries(dir.path).size() == 3);  // x.mp4, link.json, hard.json: nothing new
}

TEST_CASE("render: a layout that cannot be written leaves the video untouched") {
    if (!fs::exists("/dev/full")) COLLIDE_SKIP_TEST("no /dev/full");
    TempDir dir("outputs_all_or_nothing");
    const fs::path video = dir.path / "x.mp4";
    write_file(video, "old");
    const RunResult r = run_collide("render gas" + small_video + " -o " + shell_quoted(video) +
                                    " --layout-json /dev/full");
    INFO(r.output);
    CHECK(r.exit_code == 1);
    CHECK(contains(r.output, "No space left on device"));
    CHECK(read_all(video) == "old");  // before: replaced by the new video, then exit 1
    // The same for a still: neither the PNG nor the layout is put in place.
    const fs::path still = dir.path / "x.png";
    const RunResult s = run_collide("thumbnail gas --size 320x180 --progress none -o " +
                                    shell_quoted(still) + " --layout-json /dev/full");
    CHECK(s.exit_code == 1);
    CHECK(!fs::exists(still));
}

TEST_CASE("render --layout-json -: standard output holds the JSON and nothing else") {
    TempDir dir("outputs_stdout_data");
    const RunResult r =
        run_collide_shell(std::string("\"") + COLLIDE_EXE + "\" render gas" + small_video + " -o " +
                          shell_quoted(dir.path / "x.mp4") + " --layout-json - 2>/dev/null");
    INFO(r.output);
    CHECK(r.exit_code == 0);
    REQUIRE(!r.output.empty());
    CHECK(r.output.front() == '{');
    CHECK(r.output.substr(r.output.find_last_not_of('\n')) == "}\n");  // no summary line after
    CHECK(!contains(r.output, "s of video"));
    CHECK(fs::exists(dir.path / "x.mp4"));
}

TEST_CASE("simulate --events-log -: standard output holds the log and nothing else") {
    const RunResult r = run_collide_shell(std::string("\"") + COLLIDE_EXE +
                                          "\" simulate gas --until 1 --events-log - 2>/dev/null");
    CHECK(r.exit_code == 0);
    CHECK(r.output.rfind("t,kind,a,b\n", 0) == 0);
    CHECK(!contains(r.output, "discs"));  // the report went to stderr
    // Two kinds of data on one stream cannot be told apart: refused before anything is written.
    const RunResult both = run_collide("simulate gas --until 1 --events-log - --json");
    CHECK(both.exit_code == 2);
    CHECK(contains(both.output, "--events-log"));
    CHECK(!contains(both.output, "t,kind,a,b"));
}

TEST_CASE("render: destinations that would fail only at the end are refused before rendering") {
    TempDir dir("outputs_up_front");
    const auto refused = [&](const std::string& args, const std::string& reason) {
        const RunResult r = run_collide(args);
        INFO(args << "\n" << r.output);
        CHECK(r.exit_code == 2);  // before: the whole render, then exit 1
        CHECK(contains(r.output, reason));
        CHECK(!contains(r.output, "s of video"));
    };
    // A name longer than the filesystem's NAME_MAX (pathconf): a file, a directory of frames.
    const std::string long_name(252, 'a');
    refused("render gas" + small_video + " -o " + shell_quoted(dir.path / (long_name + ".mp4")),
            "bytes long");
    refused("thumbnail gas --size 320x180 -o " + shell_quoted(dir.path / (long_name + ".png")),
            "bytes long");
    // A link whose target ends in '/' or '/.' names a directory, not a file.
    fs::create_directory(dir.path / "d.mp4");
    fs::create_symlink("d.mp4/", dir.path / "slash.mp4");
    fs::create_symlink("d.mp4/.", dir.path / "dot.mp4");
    refused("render gas" + small_video + " -o " + shell_quoted(dir.path / "slash.mp4"),
            "names no file");
    refused("render gas" + small_video + " -o " + shell_quoted(dir.path / "dot.mp4"),
            "names no file");
    // A bind mount on the same filesystem (same st_dev as its parent): a private mount namespace
    // where the system allows one (root, or unprivileged user namespaces).
    fs::create_directory(dir.path / "src");
    fs::create_directory(dir.path / "frames");
    write_file(dir.path / "file-src.mp4", "old");
    write_file(dir.path / "file.mp4", "old");
    if (run_collide_shell("unshare -m true").exit_code != 0 &&
        run_collide_shell("unshare -r -m true").exit_code != 0) {
        COLLIDE_SKIP_TEST("no mount namespace here (unshare -m)");
    }
    const std::string unshare =
        run_collide_shell("unshare -m true").exit_code == 0 ? "unshare -m" : "unshare -r -m";
    const auto in_namespace = [&](const std::string& source, const std::string& target,
                                  const std::string& args) {
        return run_collide_shell(
            unshare + " sh -c \"mount --bind " + shell_quoted(dir.path / source) + " " +
            shell_quoted(dir.path / target) + " && exec '" + COLLIDE_EXE + "' " + args + "\"");
    };
    for (const auto& [source, target, args] :
         {std::tuple<std::string, std::string, std::string>{
              "src", "frames", "--format png -o " + shell_quoted(dir.path / "frames")},
          {"file-src.mp4", "file.mp4", "-o " + shell_quoted(dir.path / "file.mp4")}}) {
        const RunResult r = in_namespace(source, target, "render gas" + small_video + " " + args);
        INFO(args << "\n" << r.output);
        if (contains(r.output, "mount:")) COLLIDE_SKIP_TEST("mount --bind refused here");
        CHECK(r.exit_code == 2);
        CHECK(contains(r.output, "is a mount point"));
    }
    CHECK(read_all(dir.path / "file.mp4") == "old");
}

TEST_CASE(
    "no output of a run may be one of its inputs: the scene, an include, the font, any name") {
    TempDir dir("outputs_own_inputs");
    const fs::path scene = dir.path / "s.toml";
    const fs::path include = dir.path / "two.txt";
    const std::string scene_text = "title = \"own inputs\"\ninclude = \"two.txt\"\n";
    const std::string include_text = "2\n0.2 0.2 0.1 0 0.05 1 0 0 0\n0.8 0.8 0 0.1 0.05 1 0 0 0\n";
    write_file(scene, scene_text);
    write_file(include, include_text);
    fs::create_symlink("s.toml", dir.path / "soft.json");
    for (const char* name :
         {"hard.json", "hard.mp4", "hard.png", "hard.srt", "hard.vtt", "hard.toml"})
        fs::create_hard_link(scene, dir.path / name);
    const fs::path font = dir.path / "f.ttf";
    const fs::path dejavu = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    if (fs::exists(dejavu)) {
        fs::copy_file(dejavu, font);
    } else {
        write_file(font, "a font");  // refused before it is parsed, but for `heap` below
    }
    const std::string font_bytes = read_all(font);
    fs::create_hard_link(font, dir.path / "font.mp4");
    fs::create_symlink("two.txt", dir.path / "soft.csv");
    fs::create_hard_link(include, dir.path / "hard.csv");
    const std::vector<std::string> before = entries(dir.path);

    const std::string render =
        "render " + shell_quoted(scene) + small_video + " -o " + shell_quoted(dir.path / "x.mp4");
    const std::string simulate = "simulate " + shell_quoted(scene) + " --until 0.1 --events-log ";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {render + " --layout-json " + shell_quoted(scene), "--layout-json"},
        {render + " --timeline-json " + shell_quoted(dir.path / "soft.json"), "--timeline-json"},
        {render + " --layout-json " + shell_quoted(dir.path / "hard.json"), "--layout-json"},
        {render + " --subtitles-file " + shell_quoted(dir.path / "hard.srt"), "--subtitles-file"},
        {render + " --chapters-file " + shell_quoted(dir.path / "hard.vtt"), "--chapters-file"},
        {"render " + shell_quoted(scene) + small_video + " -o " +
             shell_quoted(dir.path / "hard.mp4"),
         "hard.mp4"},
        {"thumbnail " + shell_quoted(scene) + " --size 320x180 --progress none -o " +
             shell_quoted(dir.path / "hard.png"),
         "hard.png"},
        {simulate + shell_quoted(include), "--events-log"},
        {simulate + shell_quoted(dir.path / "soft.csv"), "--events-log"},
        {simulate + shell_quoted(dir.path / "hard.csv"), "--events-log"},
        {render + " --font " + shell_quoted(font) + " --layout-json " + shell_quoted(font),
         "--layout-json"},
        {"heap --ops 'P Q E' --size 320x180 --progress none --font " + shell_quoted(font) + " -o " +
             shell_quoted(dir.path / "font.mp4"),
         "font.mp4"},
        {"check " + shell_quoted(scene) + " --export " + shell_quoted(scene), "s.toml"},
        {"check " + shell_quoted(scene) + " --export " + shell_quoted(dir.path / "hard.toml"),
         "hard.toml"},
    };
    for (const auto& [args, named] : cases) {
        const RunResult r = run_collide(args);
        INFO(args << "\n" << r.output);
        CHECK(r.exit_code == 2);
        CHECK(contains(r.output, named));
        CHECK(contains(r.output, "which this run reads"));
        CHECK(read_all(scene) == scene_text);
        CHECK(read_all(include) == include_text);
        CHECK(read_all(font) == font_bytes);
        CHECK(entries(dir.path) == before);  // nothing new, no temporary left
    }
    // Standard output appended to the scene would write into it (stderr stays on the pipe).
    const RunResult appended = run_collide_shell("'" + std::string(COLLIDE_EXE) + "' " + simulate +
                                                 "- 2>&1 >>" + shell_quoted(scene));
    CHECK_MESSAGE(appended.exit_code == 2, appended.output);
    CHECK(contains(appended.output, "which this run reads"));
    CHECK(read_all(scene) == scene_text);
    // The same outputs elsewhere are fine.
    const RunResult ok = run_collide(simulate + shell_quoted(dir.path / "events.csv"));
    CHECK_MESSAGE(ok.exit_code == 0, ok.output);
}

TEST_CASE("compare never writes its difference image over an image it compares") {
    TempDir dir("outputs_compare_inputs");
    const fs::path golden = dir.path / "golden.png";
    const fs::path fresh = dir.path / "new.png";
    REQUIRE(run_collide("thumbnail gas --size 320x180 --progress none -o " + shell_quoted(golden))
                .exit_code == 0);
    REQUIRE(
        run_collide("thumbnail brownian --size 320x180 --progress none -o " + shell_quoted(fresh))
            .exit_code == 0);
    const std::string golden_bytes = read_all(golden);
    const std::string fresh_bytes = read_all(fresh);
    fs::create_hard_link(golden, dir.path / "hard.png");
    fs::create_symlink("new.png", dir.path / "soft.png");
    // EXPECTED named as ACTUAL's default difference image: ACTUAL.diff.png.
    fs::copy_file(golden, dir.path / "x.diff.png");
    fs::copy_file(fresh, dir.path / "x.png");
    const std::vector<std::string> before = entries(dir.path);
    const std::vector<std::string> cases = {
        shell_quoted(golden) + " " + shell_quoted(fresh) + " --diff " + shell_quoted(golden),
        shell_quoted(golden) + " " + shell_quoted(fresh) + " --diff " + shell_quoted(fresh),
        shell_quoted(golden) + " " + shell_quoted(fresh) + " --diff " +
            shell_quoted(dir.path / "." / "golden.png"),
        shell_quoted(golden) + " " + shell_quoted(fresh) + " --diff " +
            shell_quoted(dir.path / "hard.png"),
        shell_quoted(golden) + " " + shell_quoted(fresh) + " --diff " +
            shell_quoted(dir.path / "soft.png"),
        shell_quoted(dir.path / "x.diff.png") + " " + shell_quoted(dir.path / "x.png"),
    };
    for (const std::string& args : cases) {
        const RunResult r = run_collide("compare " + args);
        INFO(args << "\n" << r.output);
        CHECK(r.exit_code == 2);
        CHECK(contains(r.output, "--diff"));
        CHECK(contains(r.output, "which this run reads"));
        CHECK(read_all(golden) == golden_bytes);
        CHECK(read_all(fresh) == fresh_bytes);
        CHECK(read_all(dir.path / "x.diff.png") == golden_bytes);
        CHECK(entries(dir.path) == before);
    }
    const RunResult r = run_collide("compare " + shell_quoted(golden) + " " + shell_quoted(fresh));
    CHECK_MESSAGE(r.exit_code == 1, r.output);  // they differ: new.diff.png is written
    CHECK(fs::exists(dir.path / "new.diff.png"));
}

TEST_CASE("render: when the slide folder cannot go in place, no output of the run does") {
    TempDir dir("outputs_slides_last");
    const fs::path video = dir.path / "x.mp4";
    const fs::path srt = dir.path / "x.srt";
    const fs::path chapters = dir.path / "x.chapters.vtt";
    const fs::path layout = dir.path / "x.json";
    const fs::path slides = dir.path / "talk";
    const fs::path fifo = dir.path / "frames.fifo";
    for (const fs::path& old : {video, srt, chapters, layout}) write_file(old, "old");
    fs::create_directory(slides);
    write_file(slides / "index.html", "old page");
    // The slide folder changes while the frames are drawn (someone saves notes into it), so it
    // may no longer be replaced: found when the outputs are put in place, after the video, the
    // sidecars and the layout are all written. The frames go to a FIFO this script reads, so
    // the change comes at a known moment: once the first frame is drawn.
    const std::string script =
        "mkfifo " + shell_quoted(fifo) + " || exit 99; exec 3<>" + shell_quoted(fifo) + "; '" +
        COLLIDE_EXE + "' render gas -q l --duration 0.5 --progress none -o " + shell_quoted(video) +
        " --subtitles-file " + shell_quoted(srt) + " --chapters-file " + shell_quoted(chapters) +
        " --layout-json " + shell_quoted(layout) + " --slides " + shell_quoted(slides) +
        " --dump-rgba " + shell_quoted(fifo) +
        " & pid=$!; head -c 1 <&3 >/dev/null; echo notes > " + shell_quoted(slides / "notes.txt") +
        "; cat <&3 >/dev/null & reader=$!; wait $pid; rc=$?; kill $reader; exit $rc";
    const RunResult r = run_collide_shell(script);
    INFO(r.output);
    CHECK(r.exit_code == 1);
    CHECK(contains(r.output, "--slides"));
    CHECK(contains(r.output, "changed while"));
    for (const fs::path& old : {video, srt, chapters, layout}) {
        CAPTURE(old);
        CHECK(read_all(old) == "old");  // before: all four replaced, then exit 1
    }
    CHECK(read_all(slides / "index.html") == "old page");
    std::vector<std::string> names = entries(dir.path);
    std::sort(names.begin(), names.end());
    CHECK(names == std::vector<std::string>{"frames.fifo", "talk", "x.chapters.vtt", "x.json",
                                            "x.mp4", "x.srt"});
}
