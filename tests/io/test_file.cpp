// src/io: the safe-output rules every writer goes through (collide/io/file.hpp,
// docs/outputs.md): exclusive temporaries beside the destination, atomic commit, names within
// NAME_MAX, symbolic links, streams, directories of frames, and the sweep of abandoned temporaries.

#include <doctest/doctest.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "../support/files.hpp"
#include "../support/input_error.hpp"
#include "../support/skip.hpp"
#include "../support/temp_dir.hpp"
#include "collide/error.hpp"
#include "collide/io/file.hpp"

namespace {

namespace fs = std::filesystem;
using collide::test::contains;
using collide::test::entries;
using collide::test::input_error_message;
using collide::test::read_all;
using collide::test::TempDir;
using collide::test::write_file;
using namespace collide::io;

/// Both kinds of temporary: unnamed (O_TMPFILE) where the filesystem has it, and the hidden
/// named one every other filesystem gets.
const bool temporary_kinds[] = {true, false};

/// A process id that was in use a moment ago and is not any more.
pid_t dead_pid() {
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) _exit(0);
    waitpid(child, nullptr, 0);
    return child;
}

bool is_frame(std::string_view name) {
    return name.size() > 4 && name.substr(0, 2) == "f_" && name.substr(name.size() - 4) == ".png";
}

}  // namespace

TEST_CASE("temporary names: hidden, carry the pid, and stay within NAME_MAX for any legal name") {
    const std::string short_name = detail::temporary_template("gas.mp4", 4242);
    CHECK(short_name == ".gas.mp4.collide-4242-XXXXXX");
    CHECK(detail::temporary_owner(".gas.mp4.collide-4242-a1B2c3") == 4242);
    for (const std::size_t length : {200u, 240u, 250u, 255u}) {
        CAPTURE(length);
        const std::string name(length, 'x');
        const std::string temporary = detail::temporary_template(name, 2147483647);
        CHECK(temporary.size() <= 255);
        CHECK(temporary.front() == '.');
        CHECK(detail::temporary_owner(temporary.substr(0, temporary.size() - 6) + "abcdef") ==
              2147483647);
    }
    // A shortened name never ends in half a UTF-8 character.
    std::string accents;
    for (int i = 0; i < 127; ++i) accents += "\xc3\xa9";  // "é" x 127: 254 bytes
    const std::string temporary = detail::temporary_template(accents, 12345);
    const std::size_t kept = temporary.find(".collide-") - 1;
    CHECK(kept % 2 == 0);
    // Nothing else is taken for a temporary of ours.
    for (const char* other :
         {"gas.mp4", ".gas.mp4.partial", "gas.mp4.tmp-123", ".gas.mp4.collide-12-abcde",
          ".gas.mp4.collide-12-abcdefg", ".gas.mp4.collide-x2-abcdef", "x.collide-12-abcdef",
          ".gas.mp4.collide--abcdef", ".gas.mp4.collide-12-abc/ef"}) {
        CAPTURE(other);
        CHECK_FALSE(detail::temporary_owner(other).has_value());
    }
}

TEST_CASE("an output file appears whole at commit, and the old file stays until then") {
    for (const bool unnamed : temporary_kinds) {
        CAPTURE(unnamed);
        TempDir dir("io_commit");
        const fs::path destination = dir.path / "out.txt";
        write_file(destination, "old");
        OutputOptions options;
        options.unnamed_temporary = unnamed;
        OutputFile file(destination, options);
        file.write("new ");
        file.write("content");
        CHECK(read_all(destination) == "old");
        CHECK(entries(dir.path).size() == (unnamed ? 1u : 2u));
        file.commit();
        CHECK(read_all(destination) == "new content");
        CHECK(entries(dir.path) == std::vector<std::string>{"out.txt"});
    }
}

TEST_CASE("an output file dropped without commit leaves the directory as it was") {
    for (const bool unnamed : temporary_kinds) {
        CAPTURE(unnamed);
        TempDir dir("io_discard");
        write_file(dir.path / "out.txt", "old");
        write_file(dir.path / "out.txt.partial", "someone else's");
        {
            OutputOptions options;
            options.unnamed_temporary = unnamed;
            OutputFile file(dir.path / "out.txt", options);
            file.write("half");
        }
        CHECK(entries(dir.path) == std::vector<std::string>{"out.txt", "out.txt.partial"});
        CHECK(read_all(dir.path / "out.txt") == "old");
        CHECK(read_all(dir.path / "out.txt.partial") == "someone else's");
    }
}

TEST_CASE("a finished file gets ordinary permissions, or those of the file it replaces") {
    TempDir dir("io_mode");
    OutputOptions named;
    named.unnamed_temporary = false;
    OutputFile fresh(dir.path / "fresh.txt", named);
    fresh.commit();
    const mode_t mask = umask(022);
    umask(mask);
    CHECK((fs::status(dir.path / "fresh.txt").permissions() & fs::perms::all) ==
          static_cast<fs::perms>(0666 & ~mask));
    write_file(dir.path / "kept.txt", "old");
    fs::permissions(dir.path / "kept.txt", static_cast<fs::perms>(0640));
    OutputFile replacing(dir.path / "kept.txt");
    replacing.commit();
    CHECK((fs::status(dir.path / "kept.txt").permissions() & fs::perms::all) ==
          static_cast<fs::perms>(0640));
}

TEST_CASE("a legal 250-byte file name can be written") {
    for (const bool unnamed : temporary_kinds) {
        CAPTURE(unnamed);
        TempDir dir("io_long");
        const fs::path destination = dir.path / (std::string(246, 'n') + ".txt");
        OutputOptions options;
        options.unnamed_temporary = unnamed;
        OutputFile file(destination, options);
        file.write("long");
        file.commit();
        CHECK(read_all(destination) == "long");
        CHECK(entries(dir.path).size() == 1);
    }
}

TEST_CASE("symlinks planted at predictable temporary names are never followed") {
    TempDir dir("io_planted");
    const fs::path victim = dir.path / "victim.txt";
    write_file(victim, "precious");
    // The fixed names earlier versions used, and ours with the pid filled in the obvious ways.
    for (const std::string& name :
         {std::string("out.txt.partial"), "out.txt.tmp-" + std::to_string(getpid()),
          ".out.txt.collide-" + std::to_string(getpid()) + "-XXXXXX"}) {
        fs::create_symlink(victim, dir.path / name);
    }
    for (const bool unnamed : temporary_kinds) {
        OutputOptions options;
        options.unnamed_temporary = unnamed;
        OutputFile file(dir.path / "out.txt", options);
        file.write("mine");
        file.commit();
    }
    CHECK(read_all(victim) == "precious");
    CHECK(read_all(dir.path / "out.txt") == "mine");
    CHECK(fs::is_symlink(dir.path / "out.txt.partial"));
    // libav opens the temporary by name: that name must lead to our file, not a planted one.
    OutputOptions named;
    named.unnamed_temporary = false;
    OutputFile file(dir.path / "other.txt", named);
    CHECK(fs::equivalent(file.reopen_path(), "/proc/self/fd/" + std::to_string(file.fd())));
}

TEST_CASE("a symlinked destination is written through: the link stays, its target is replaced") {
    TempDir dir("io_symlink");
    fs::create_directory(dir.path / "renders");
    write_file(dir.path / "renders" / "v3.txt", "old");
    fs::create_symlink("renders/v3.txt", dir.path / "latest.txt");
    OutputFile file(dir.path / "latest.txt");
    file.write("new");
    file.commit();
    CHECK(fs::is_symlink(dir.path / "latest.txt"));
    CHECK(read_all(dir.path / "renders" / "v3.txt") == "new");
    CHECK(entries(dir.path / "renders") == std::vector<std::string>{"v3.txt"});

    // A dangling link creates its target, as the shell's `>` does.
    fs::create_symlink("renders/v4.txt", dir.path / "next.txt");
    OutputFile next(dir.path / "next.txt");
    next.commit();
    CHECK(fs::is_regular_file(dir.path / "renders" / "v4.txt"));
    CHECK(fs::is_symlink(dir.path / "next.txt"));

    // A link loop is bad input, not a hang.
    fs::create_symlink("loop-b", dir.path / "loop-a");
    fs::create_symlink("loop-a", dir.path / "loop-b");
    CHECK(contains(input_error_message([&] { OutputFile loop(dir.path / "loop-a"); }),
                   "symbolic links"));
}

TEST_CASE(
    "in a shared sticky directory, another user's link is not followed (protected_symlinks)") {
    if (geteuid() != 0) COLLIDE_SKIP_TEST("needs root to give a link another owner");
    TempDir dir("io_sticky");
    const fs::path shared = dir.path / "tmp";
    fs::create_directory(shared);
    fs::permissions(shared, static_cast<fs::perms>(01777));
    write_file(dir.path / "victim.txt", "precious");
    fs::create_symlink(dir.path / "victim.txt", shared / "out.txt");
    REQUIRE(lchown((shared / "out.txt").c_str(), 12345, 12345) == 0);
    CHECK(contains(input_error_message([&] { OutputFile file(shared / "out.txt"); }),
                   "refusing to follow"));
    CHECK(read_all(dir.path / "victim.txt") == "precious");
}

TEST_CASE("another user's link to a directory in a sticky directory is not followed either") {
    // Before, the rule applied to the last component only: /tmp/dirlink/notes.csv, with
    // dirlink someone else's link to a directory, replaced a file in that directory.
    if (geteuid() != 0) COLLIDE_SKIP_TEST("needs root to give a link another owner");
    TempDir dir("io_sticky_dir");
    const fs::path shared = dir.path / "tmp";
    fs::create_directory(shared);
    fs::permissions(shared, static_cast<fs::perms>(01777));
    fs::create_directory(dir.path / "victims");
    write_file(dir.path / "victims" / "notes.csv", "precious");
    fs::create_symlink(dir.path / "victims", shared / "dirlink");
    REQUIRE(lchown((shared / "dirlink").c_str(), 12345, 12345) == 0);
    // A link of our own on the way to it changes nothing.
    fs::create_symlink(shared / "dirlink", dir.path / "mine");
    for (const fs::path& path : {shared / "dirlink" / "notes.csv", dir.path / "mine" / "notes.csv",
                                 shared / "dirlink" / "." / "new.csv"}) {
        CAPTURE(path);
        CHECK(contains(input_error_message([&] { OutputFile file(path); }),
                       "refusing to follow the link"));
    }
    CHECK(read_all(dir.path / "victims" / "notes.csv") == "precious");
    // Our own link in the same place is followed.
    fs::create_symlink(dir.path / "victims", shared / "ours");
    OutputFile ours(shared / "ours" / "notes.csv");
    ours.write("new");
    ours.commit();
    CHECK(read_all(dir.path / "victims" / "notes.csv") == "new");
}

TEST_CASE("unwritable destinations are input errors with the system's reason") {
    TempDir dir("io_errors");
    CHECK(contains(input_error_message([&] { OutputFile f(dir.path / "missing" / "x.txt"); }),
                   "does not exist"));
    fs::create_directory(dir.path / "sub");
    CHECK(contains(input_error_message([&] { OutputFile f(dir.path / "sub"); }),
                   "is an existing directory"));
    CHECK(contains(input_error_message([&] { OutputFile f(dir.path / "sub/"); }), "names no file"));
    CHECK(contains(input_error_message([&] { OutputFile f("/dev/null"); }), "not a regular file"));
    CHECK(contains(input_error_message([&] { OutputFile f("-"); }), "open streams"));
    OutputOptions labelled;
    labelled.label = "--events-log";
    CHECK(contains(input_error_message([&] { OutputFile f(dir.path / "no" / "x", labelled); }),
                   "--events-log '"));
    if (geteuid() != 0) {  // root writes through permission bits
        fs::create_directory(dir.path / "locked");
        fs::permissions(dir.path / "locked", fs::perms::owner_read | fs::perms::owner_exec);
        CHECK(contains(input_error_message([&] { OutputFile f(dir.path / "locked" / "x.txt"); }),
                       "Permission denied"));
        fs::permissions(dir.path / "locked", fs::perms::owner_all);
    }
}

TEST_CASE("streams: standard output and devices are written in place, a FIFO nobody reads fails") {
    OutputOptions stream;
    stream.allow_stream = true;
    OutputFile null("/dev/null", stream);
    CHECK(null.is_stream());
    null.write("discarded");
    null.commit();

    TempDir dir("io_fifo");
    REQUIRE(mkfifo((dir.path / "fifo").c_str(), 0600) == 0);
    CHECK(contains(input_error_message([&] { OutputFile f(dir.path / "fifo", stream); }),
                   "nobody reads this FIFO"));

    // /dev/full: the write fails like a full disk, a runtime error (exit 1) with the reason.
    OutputFile full("/dev/full", stream);
    try {
        full.write(std::string(1 << 16, 'x'));
        FAIL("no error");
    } catch (const collide::Error& e) {
        CHECK(e.kind() == collide::ErrorKind::runtime);
        CHECK(contains(e.what(), "No space left on device"));
    }
}

TEST_CASE("stale temporaries: those of a dead process go, anything not provably ours stays") {
    TempDir dir("io_sweep");
    const std::string dead = std::to_string(dead_pid());
    const std::string alive = std::to_string(getppid());
    const std::string stale = ".old.mp4.collide-" + dead + "-a1b2c3";
    const std::string live = ".old.mp4.collide-" + alive + "-a1b2c3";
    const std::string locked = ".locked.mp4.collide-" + dead + "-d4e5f6";
    const std::string stale_directory = ".seq.collide-" + dead + "-g7h8i9";
    const std::string foreign_directory = ".other.collide-" + dead + "-j1k2l3";
    const std::string link = ".link.mp4.collide-" + dead + "-m4n5o6";
    for (const std::string& name : {stale, live, locked}) write_file(dir.path / name, "x");
    fs::create_directory(dir.path / stale_directory);
    write_file(dir.path / stale_directory / "f_00000.png", "frame");
    fs::create_directory(dir.path / foreign_directory);
    write_file(dir.path / foreign_directory / "notes.txt", "not a frame");
    write_file(dir.path / "target.txt", "t");
    fs::create_symlink("target.txt", dir.path / link);
    for (const char* user : {"old.mp4", ".old.mp4.partial", "old.mp4.tmp-1"}) {
        write_file(dir.path / user, "user");
    }
    // A live writer elsewhere (another pid namespace, another NFS client) holds the lock.
    const int held = open((dir.path / locked).c_str(), O_RDONLY);
    REQUIRE(flock(held, LOCK_EX) == 0);

    OutputDirectory::NamePredicate frames = is_frame;
    CHECK(detail::sweep_stale_temporaries(dir.path, frames) == 2);
    close(held);
    const std::vector<std::string> left = entries(dir.path);
    CHECK(std::find(left.begin(), left.end(), stale) == left.end());
    CHECK(std::find(left.begin(), left.end(), stale_directory) == left.end());
    for (const std::string& kept : {live, locked, foreign_directory, link, std::string("old.mp4"),
                                    std::string(".old.mp4.partial"), std::string("target.txt")}) {
        CAPTURE(kept);
        CHECK(std::find(left.begin(), left.end(), kept) != left.end());
    }
    // Every new output sweeps its directory.
    write_file(dir.path / stale, "x");
    OutputFile next(dir.path / "new.mp4");
    CHECK_FALSE(fs::exists(dir.path / stale));
}

TEST_CASE("a directory output: new, empty or an earlier sequence is replaced, nothing else") {
    TempDir dir("io_directory");
    const fs::path frames = dir.path / "seq";
    const auto write_sequence = [&](int count) {
        OutputDirectory output(frames, is_frame);
        for (int i = 0; i < count; ++i) {
            File file = output.create_file("f_0000" + std::to_string(i) + ".png");
            file.write_all("png", 3, "frame");
        }
        output.commit();
    };
    write_sequence(5);
    CHECK(entries(frames).size() == 5);
    write_sequence(3);  // replaces the earlier sequence whole: no frame 3 or 4 left over
    CHECK(entries(frames) == std::vector<std::string>{"f_00000.png", "f_00001.png", "f_00002.png"});
    CHECK(entries(dir.path) == std::vector<std::string>{"seq"});

    write_file(frames / "notes.txt", "mine");
    const std::string refused = input_error_message([&] { OutputDirectory d(frames, is_frame); });
    CHECK(contains(refused, "holds other files ('notes.txt')"));
    CHECK(entries(frames).size() == 4);

    for (const char* bad : {".", "..", "/", "./", "sub/.."}) {
        CAPTURE(bad);
        CHECK(contains(input_error_message([&] { check_output_directory(bad, is_frame); }),
                       "give it a name"));
    }
    // The current directory (and its parents) are never replaced, even when empty.
    fs::create_directory(dir.path / "here");
    const fs::path before = fs::current_path();
    fs::current_path(dir.path / "here");
    const std::string cwd =
        input_error_message([&] { check_output_directory(dir.path / "here", is_frame); });
    fs::current_path(before);
    CHECK(contains(cwd, "current directory"));

    // Dropped without commit: the temporary and its frames go, the destination stays.
    {
        OutputDirectory output(dir.path / "fresh", is_frame);
        (void)output.create_file("f_00000.png");
    }
    CHECK(entries(dir.path) == std::vector<std::string>{"here", "seq"});
}

TEST_CASE("a scratch file has no name from the start") {
    TempDir dir("io_scratch");
    {
        const File scratch = open_scratch_file(dir.path);
        scratch.write_all("spill", 5, "scratch");
        CHECK(entries(dir.path).empty());
    }
    CHECK(entries(dir.path).empty());
}

TEST_CASE("check_distinct_outputs: one file under two names is refused, distinct files pass") {
    TempDir dir("io_distinct");
    const fs::path video = dir.path / "x.mp4";
    write_file(video, "old");
    fs::create_symlink("x.mp4", dir.path / "soft.json");
    fs::create_hard_link(video, dir.path / "hard.json");
    fs::create_symlink("new.json", dir.path / "dangling.json");
    const auto refused = [](const std::vector<NamedOutput>& outputs) {
        return input_error_message([&] { check_distinct_outputs(outputs); });
    };
    CHECK(contains(refused({{"-o", video}, {"--layout-json", video}}), "the same file as -o"));
    CHECK(contains(refused({{"-o", video}, {"--layout-json", dir.path / "soft.json"}}),
                   "the same file"));
    CHECK(contains(refused({{"-o", video}, {"--layout-json", dir.path / "hard.json"}}),
                   "the same file"));
    CHECK(contains(
        refused({{"-o", dir.path / "new.json"}, {"--layout-json", dir.path / "dangling.json"}}),
        "the same file"));
    CHECK(
        contains(refused({{"-o", dir.path / "y.mp4"}, {"--layout-json", dir.path / "." / "y.mp4"}}),
                 "the same file"));
    CHECK(contains(refused({{"--layout-json", "-"}, {"--dump-rgba", "/dev/stdout"}}),
                   "the same file"));
    CHECK(contains(refused({{"-o", dir.path / "frames", true},
                            {"--layout-json", dir.path / "frames" / "l.json"}}),
                   "lies inside -o"));
    CHECK_NOTHROW(check_distinct_outputs({{"-o", video}, {"--layout-json", dir.path / "l.json"}}));
    CHECK_NOTHROW(check_distinct_outputs(
        {{"-o", dir.path / "frames", true}, {"--layout-json", dir.path / "frames.json"}}));
    CHECK(entries(dir.path).size() == 4);  // nothing created
}

TEST_CASE("OutputFile refuses up front a name over NAME_MAX and a link ending in '/' or '/.'") {
    TempDir dir("io_up_front");
    const std::string long_name(256, 'n');
    CHECK(contains(input_error_message([&] { OutputFile f(dir.path / long_name); }), "bytes long"));
    CHECK(contains(input_error_message([&] { OutputDirectory d(dir.path / long_name, {}); }),
                   "bytes long"));
    fs::create_directory(dir.path / "d");
    fs::create_symlink("d/", dir.path / "slash");
    fs::create_symlink("d/.", dir.path / "dot");
    CHECK(
        contains(input_error_message([&] { OutputFile f(dir.path / "slash"); }), "names no file"));
    CHECK(contains(input_error_message([&] { OutputFile f(dir.path / "dot"); }), "names no file"));
    CHECK(entries(dir.path).size() == 3);
    CHECK(entries(dir.path / "d").empty());
}

namespace {

/// Writes `text` into `file`'s temporary.
void fill(const OutputFile& file, const std::string& text) {
    file.write(text);
}

/// The error message of `f`, which must throw a collide::Error (of any kind).
template <class F>
std::string error_message(F&& f) {
    try {
        std::forward<F>(f)();
    } catch (const collide::Error& e) {
        return e.what();
    }
    FAIL("no error");
    return "";
}

bool is_txt(std::string_view name) {
    return name.size() > 4 && name.substr(name.size() - 4) == ".txt";
}

/// The scenarios of the CommitGroup test, each in a fresh directory.
enum class CommitScenario { all_ready, folder_changed, injected_failure, stop_requested };

void run_commit_scenario(CommitScenario scenario, bool unnamed) {
    TempDir dir("io_commit_group");
    const fs::path video = dir.path / "v.mp4";
    const fs::path sidecar = dir.path / "v.srt";
    const fs::path folder = dir.path / "slides";
    write_file(video, "old video");
    write_file(sidecar, "old srt");
    fs::create_directory(folder);
    write_file(folder / "a.txt", "old slide");
    std::atomic<bool> stop{false};
    set_stop_flag(&stop);
    {
        OutputFile a(video, {"-o", false, unnamed});
        OutputFile b(sidecar, {"--subtitles-file", false, unnamed});
        OutputDirectory d(folder, is_txt, "--slides");
        fill(a, "new video");
        fill(b, "new srt");
        (void)d.create_file("b.txt");
        CommitGroup group;
        group.add(&a);
        if (scenario == CommitScenario::stop_requested) {
            group.add([&] { stop = true; }, [] {});  // the signal comes while preparing
        }
        group.add(&b);
        if (scenario == CommitScenario::injected_failure) {
            group.add([] { collide::throw_runtime_error("cannot write 'x': No space left"); },
                      [] { FAIL("renamed after a failed preparation"); });
        }
        group.add(&d);  // the last: a commit one by one would have replaced a and b before it
        switch (scenario) {
            case CommitScenario::all_ready:
                group.commit();
                break;
            case CommitScenario::folder_changed:
                write_file(folder / "notes.md", "someone's");  // may not be replaced
                CHECK(contains(error_message([&] { group.commit(); }), "changed while"));
                break;
            case CommitScenario::injected_failure:
                CHECK(contains(error_message([&] { group.commit(); }), "No space left"));
                break;
            case CommitScenario::stop_requested:
                CHECK(contains(error_message([&] { group.commit(); }), "interrupted"));
                break;
        }
    }
    set_stop_flag(nullptr);
    if (scenario == CommitScenario::all_ready) {
        CHECK(read_all(video) == "new video");
        CHECK(read_all(sidecar) == "new srt");
        CHECK(entries(folder) == std::vector<std::string>{"b.txt"});
    } else {
        CHECK(read_all(video) == "old video");
        CHECK(read_all(sidecar) == "old srt");
        CHECK(read_all(folder / "a.txt") == "old slide");
    }
    // No temporary is left behind in any case.
    std::vector<std::string> names = entries(dir.path);
    std::sort(names.begin(), names.end());
    CHECK(names == std::vector<std::string>{"slides", "v.mp4", "v.srt"});
}

}  // namespace

TEST_CASE("CommitGroup: every output goes in place, or none when one cannot be prepared") {
    for (const bool unnamed : temporary_kinds) {
        for (const CommitScenario scenario :
             {CommitScenario::all_ready, CommitScenario::folder_changed,
              CommitScenario::injected_failure, CommitScenario::stop_requested}) {
            CAPTURE(unnamed);
            CAPTURE(static_cast<int>(scenario));
            run_commit_scenario(scenario, unnamed);
        }
    }
}

TEST_CASE("an output never replaces a file the process read as an input") {
    TempDir dir("io_inputs");
    const fs::path scene = dir.path / "s.toml";
    const fs::path late = dir.path / "late.txt";
    write_file(scene, "scene");
    write_file(late, "include");
    fs::create_symlink("s.toml", dir.path / "soft.json");
    fs::create_hard_link(scene, dir.path / "hard.json");
    {
        // An output created before its destination was read: refused when it is committed.
        OutputFile early(late, {"--events-log"});
        fill(early, "log");
        const File input(::open(late.c_str(), O_RDONLY | O_CLOEXEC));
        note_input_file(input.get(), late);
        CHECK(contains(input_error_message([&] { early.commit(); }), "which this run reads"));
    }
    const File input(::open(scene.c_str(), O_RDONLY | O_CLOEXEC));
    note_input_file(input.get(), scene);
    for (const char* name : {"s.toml", "soft.json", "hard.json"}) {
        CAPTURE(name);
        const std::string message = input_error_message([&] {
            OutputFile f(dir.path / name, {"--layout-json", true});
        });
        CHECK(contains(message, "--layout-json '"));
        CHECK(contains(message, "which this run reads"));
    }
    CHECK_NOTHROW(OutputFile(dir.path / "other.json"));
    CHECK(read_all(scene) == "scene");
    CHECK(read_all(late) == "include");
    detail::forget_input_files();  // their inodes may be reused once the directory goes
}

TEST_CASE("check_outputs_not_inputs: an output that is an input is refused, others pass") {
    TempDir dir("io_not_inputs");
    const fs::path golden = dir.path / "golden.png";
    write_file(golden, "png");
    fs::create_symlink("golden.png", dir.path / "soft.png");
    fs::create_hard_link(golden, dir.path / "hard.png");
    const std::vector<NamedInput> inputs{{"EXPECTED", golden}, {"ACTUAL", dir.path / "new.png"}};
    for (const char* name : {"golden.png", "soft.png", "hard.png", "new.png", "./new.png"}) {
        CAPTURE(name);
        const std::string message = input_error_message([&] {
            check_outputs_not_inputs({{"--diff", dir.path / name}}, inputs);
        });
        CHECK(contains(message, "--diff '"));
        CHECK(contains(message, "which this run reads"));
    }
    CHECK_NOTHROW(check_outputs_not_inputs({{"--diff", dir.path / "d.png"}}, inputs));
    CHECK(entries(dir.path).size() == 3);
}
