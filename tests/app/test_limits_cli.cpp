// End-to-end: runs that could never finish are refused before they start (exit 2, naming the
// option or the scene hint, with the estimate and what would fit), and `check` agrees with
// `render` about a scene's [render] hints.

#include <doctest/doctest.h>
#include <sys/stat.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "../support/input_error.hpp"
#include "../support/skip.hpp"
#include "../support/temp_dir.hpp"
#include "run_collide.hpp"

using collide::test::contains;
using collide::test::run_collide;
using collide::test::run_collide_bad_input;
using collide::test::run_collide_env;
using collide::test::TempDir;
namespace fs = std::filesystem;

namespace {

std::string write_file(const TempDir& dir, const std::string& name, const std::string& text) {
    const std::filesystem::path path = dir.path / name;
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
}

std::string toml_with_render(const std::string& render_lines) {
    return "[box]\nwidth = 1.0\nheight = 1.0\n\n[[disc]]\nposition = [0.3, 0.5]\n"
           "velocity = [0.1, 0.05]\nradius = 0.05\n\n[render]\n" +
           render_lines;
}

}  // namespace

TEST_CASE("limits: simulate --until 1e300 is refused with the collision estimate and the way out") {
    const std::string out = run_collide_bad_input("simulate gas --until 1e300");
    CHECK(contains(out, "--until"));
    CHECK(contains(out, "collisions"));
    CHECK(contains(out, "--no-limits"));
}

TEST_CASE("limits: a dt below the clock's resolution is refused, even with --no-limits") {
    for (const std::string args :
         {"simulate gas --until 10 --engine time --dt 1e-300",
          "simulate gas --until 10 --engine time --dt 1e-300 --no-limits",
          "render gas --dt 1e-300 -o never.mp4", "render gas --dt 1e-300 --no-limits -o never.mp4",
          "thumbnail gas --dt 1e-300 -o never.png"}) {
        CAPTURE(args);
        const std::string out = run_collide_bad_input(args);
        CHECK(contains(out, "--dt"));
        CHECK(contains(out, "t + dt == t"));
    }
    CHECK_FALSE(std::filesystem::exists("never.mp4"));
    CHECK_FALSE(std::filesystem::exists("never.png"));
}

TEST_CASE("limits: too many time-driven steps name --dt and the dt that would fit") {
    const std::string out =
        run_collide_bad_input("simulate gas --until 10 --engine time --dt 1e-9");
    CHECK(contains(out, "--dt"));
    CHECK(contains(out, "steps"));
    CHECK(contains(out, "at least 1e-08"));
}

TEST_CASE("limits: render --speed 1e300 and thumbnail --at 1e6 are refused naming the option") {
    CHECK(contains(run_collide_bad_input("render gas --speed 1e300 -o never.mp4"), "--speed"));
    CHECK(contains(run_collide_bad_input("render gas --speed 1e308 --no-limits -o never.mp4"),
                   "beyond the range of double precision"));
    const std::string at = run_collide_bad_input("thumbnail gas --at 1e6 -o never.png");
    CHECK(contains(at, "--at"));
    CHECK(contains(at, "frames"));
}

TEST_CASE("limits: a disc at 1e50 units per time unit is refused for --until 10") {
    TempDir dir("limits_fast");
    const std::string scene = write_file(dir, "fast.txt", "1\n0.5 0.5 1e50 0 0.01 1 0 0 0\n");
    const std::string out = run_collide_bad_input("simulate '" + scene + "' --until 10");
    CHECK(contains(out, "--until"));
    CHECK(contains(out, "collisions"));
}

TEST_CASE("limits (UBSan): thumbnail --at beyond the countable frames is exit 2 naming --at") {
    for (const std::string args :
         {"thumbnail gas --at 1e18 -o never.png", "thumbnail gas --at 1e15 -o never.png",
          "thumbnail gas --at 1 --speed 1e-300 -o never.png",
          "thumbnail gas --at 1e18 --no-limits -o never.png"}) {
        CAPTURE(args);
        const std::string out = run_collide_bad_input(args);
        CHECK(contains(out, "collide: error: --at"));
        CHECK_FALSE(contains(out, "runtime error"));
    }
}

TEST_CASE("limits: check and render agree on [render] hints, naming file, line and field") {
    TempDir dir("limits_hints");
    struct Case {
        const char* render;
        const char* field;
    };
    for (const Case c :
         {Case{"dt = 1e-300\n", "render.dt"}, Case{"duration = 1e300\n", "render.duration"},
          Case{"speed = 1e300\n", "render.speed"}}) {
        CAPTURE(c.render);
        const std::string scene = write_file(dir, "hint.toml", toml_with_render(c.render));
        const std::string where = scene + ":11: " + c.field;
        const std::string checked = run_collide_bad_input("check '" + scene + "'");
        CHECK(contains(checked, where));
        const std::string rendered = run_collide_bad_input("render '" + scene + "' -o '" +
                                                           (dir.path / "x.mp4").string() + "'");
        CHECK(contains(rendered, where));
        CHECK_FALSE(std::filesystem::exists(dir.path / "x.mp4"));
    }
    // A command-line value replaces the hint, and then the hint is no longer in the way.
    const std::string scene = write_file(dir, "hint.toml", toml_with_render("speed = 1e300\n"));
    CHECK(run_collide("simulate '" + scene + "' --until 1").exit_code == 0);
}

TEST_CASE("options: --seed, --fps and bench's counts refuse what strtoull would bend") {
    for (const std::string args :
         {"render gas --seed -1", "render gas --seed 18446744073709551616",
          "render gas --seed 1e23", "thumbnail gas --seed 0x10", "bench engine --seed -1",
          "render gas --fps 1e3", "thumbnail gas --fps 99999999999", "render gas --fps 30.5"}) {
        CAPTURE(args);
        const std::string out = run_collide_bad_input(args + " -o never.mp4");
        const std::size_t from = args.find(" --") + 1;
        const std::string option = args.substr(from, args.find(' ', from) - from);
        CHECK(contains(out, "collide: error: " + option + ": "));
    }
    CHECK(contains(run_collide_bad_input("bench engine --collisions 1e30"), "--collisions"));
    CHECK(contains(run_collide_bad_input("bench engine --collisions 2e10"), "--no-limits"));
    CHECK(contains(run_collide_bad_input("bench engine --warmup 1e300"), "--warmup"));
    CHECK_FALSE(std::filesystem::exists("never.mp4"));
}

TEST_CASE("inputs: a FIFO, /dev/zero or an oversized file as a scene is exit 2 naming it") {
    TempDir dir("limits_inputs");
    const std::filesystem::path fifo = dir.path / "pipe.toml";
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    std::filesystem::create_symlink("/dev/zero", dir.path / "zero.txt");
    const std::filesystem::path big = dir.path / "big.txt";
    std::ofstream(big).close();
    std::filesystem::resize_file(big, (std::uintmax_t{512} << 20) + 1);  // sparse
    // The old reader blocked forever on a FIFO and read /dev/zero until memory ran out: under
    // `timeout`, that is exit 124, a failure rather than a hung test.
    const auto bounded = [](const std::string& args) {
        const auto r = run_collide_env("timeout 60", args);
        CHECK_MESSAGE(r.exit_code == 2, args);
        return r.output;
    };
    CHECK(contains(bounded("check '" + fifo.string() + "'"),
                   "pipe.toml: a FIFO (named pipe), not a regular file"));
    CHECK(contains(bounded("simulate '" + (dir.path / "zero.txt").string() + "' --until 1"),
                   "zero.txt: a character device, not a regular file"));
    CHECK(contains(bounded("check '" + big.string() + "'"), "larger than 512 MiB"));
    // `collide scenes` over an assets directory holding a FIFO.
    std::filesystem::create_directories(dir.path / "assets" / "scenes");
    REQUIRE(mkfifo((dir.path / "assets" / "scenes" / "stuck.toml").c_str(), 0600) == 0);
    const auto r = run_collide_env(
        "COLLIDE_ASSETS_DIR='" + (dir.path / "assets").string() + "' timeout 60", "scenes");
    CHECK(r.exit_code == 2);
    CHECK(contains(r.output, "stuck.toml: a FIFO"));
}

TEST_CASE("inputs: an algs4 file with a UTF-8 BOM, and a 1e-400 in it, check fine") {
    TempDir dir("limits_bom");
    const std::string scene = write_file(dir, "bom.txt",
                                         "\xEF\xBB\xBF"
                                         "1\n0.5 0.5 1e-400 0 0.1 1 0 0 0\n");
    const auto r = run_collide("check '" + scene + "'");
    CHECK(r.exit_code == 0);
    CHECK(contains(r.output, "ok: "));
    CHECK(contains(
        run_collide_bad_input(
            "check '" + write_file(dir, "huge.txt", "1\n0.5 0.5 1e400 0 0.1 1 0 0 0\n") + "'"),
        "huge.txt:2: vx: '1e400' is too large for a double"));
}

TEST_CASE("memory: running out says what ran out and what to lower, exit 1") {
    // AddressSanitizer reserves terabytes of address space: it cannot start under `ulimit -v`.
    if (collide::test::address_sanitizer)
        COLLIDE_SKIP_TEST("the address-space cap cannot apply under AddressSanitizer");
    TempDir dir("limits_memory");
    const std::string scene = write_file(dir, "many.toml",
                                         "[box]\nwidth = 100.0\nheight = 100.0\n\n[[generate]]\n"
                                         "count = 20000000\nradius = 0.001\nspeed = 1.0\n");
    // 20 million discs need about 2 GB; the address space is capped at 1 GB for this run.
    const auto r = run_collide_env("ulimit -v 1000000;", "check '" + scene + "'");
    CHECK(r.exit_code == 1);
    CHECK(contains(r.output, "collide: error: out of memory in `collide check` with the scene '" +
                                 scene + "'"));
    CHECK(contains(r.output, "use fewer discs"));
    CHECK_FALSE(contains(r.output, "std::bad_alloc"));
}

TEST_CASE("limits: the classic engine and the array queues are refused where they cannot finish") {
    TempDir dir("limits_classic");
    const std::string scene = (dir.path / "big.toml").string();
    std::ofstream(scene) << "[box]\nwidth = 500\nheight = 500\n[[generate]]\ncount = 200000\n"
                            "radius = 0.4\n";
    const std::string classic =
        run_collide_bad_input("simulate '" + scene + "' --engine classic --until 100");
    CHECK(contains(classic, "--until: the classic engine predicts"));
    CHECK(contains(classic, "--engine fast"));
    CHECK(contains(run_collide_bad_input("simulate '" + scene +
                                         "' --engine classic --until 100 "
                                         "--pq unordered"),
                   "--until: "));
    const std::string array = run_collide_bad_input(
        "render dense-fluid --engine classic --pq unordered --duration 60 -o '" +
        (dir.path / "x.mp4").string() + "'");
    CHECK(contains(array, "render.speed: an array queue"));
    CHECK(contains(array, "--pq binary"));
    // The fast engine runs the same scene and span.
    CHECK(run_collide("simulate '" + scene + "' --until 0.001").exit_code == 0);
}

TEST_CASE("limits: under an address-space limit, running out is exit 1 'out of memory', no crash") {
    // `ulimit -v` near what a run needs: the software GL's shader compiler (LLVM) crashed
    // (SIGSEGV, abort) at half the limits tried, x264's failure read "Generic error in an
    // external library", a thread's "Resource temporarily unavailable". Every limit ends in
    // success or in the one message, and leaves nothing in the output's directory.
    if (collide::test::address_sanitizer) COLLIDE_SKIP_TEST("ASan reserves terabytes");
    TempDir dir("limits_memory");
    const std::string video = (dir.path / "v.mp4").string();
    const std::string still = (dir.path / "s.png").string();
    const fs::path big = dir.path / "big.toml";
    std::ofstream(big) << "[box]\nwidth = 100\nheight = 100\n[[generate]]\ncount = 1000000\n"
                          "radius = 0.02\n";
    // Each command at limits around what it needs: the drawing commands (llvmpipe's headroom,
    // x264) from 420 to 760 MiB; `simulate` of a million discs (about 360 MiB, 4 s of CPU a run)
    // from 300 to 420 MiB: above that it takes the path it takes without a limit.
    const std::string draw_args[] = {"render gas -q l --duration 1 --chapters-file '" +
                                         (dir.path / "c.vtt").string() + "' -o '" + video + "'",
                                     "thumbnail gas --size 320x180 -o '" + still + "'"};
    const std::string simulate_args = "simulate '" + big.string() + "' --until 0.001";
    std::vector<std::pair<long, std::string>> runs;
    for (const long mib : {420L, 480L, 540L, 560L, 600L, 650L, 700L, 760L})
        for (const std::string& args : draw_args) runs.emplace_back(mib, args);
    for (const long mib : {300L, 340L, 380L, 420L}) runs.emplace_back(mib, simulate_args);
    int failed = 0;
    for (const auto& run : runs) {
        const long mib = run.first;
        const std::string& args = run.second;
        CAPTURE(mib);
        CAPTURE(args);
        const auto r = collide::test::run_collide_measured(args, mib);
        CHECK((r.exit_code == 0 || r.exit_code == 1));  // -1: killed by a signal
        if (r.exit_code != 0) {
            ++failed;
            CHECK(contains(r.output, "collide: error: out of memory"));
        }
        for (const auto& entry : fs::directory_iterator(dir.path)) {
            const std::string name = entry.path().filename().string();
            CHECK_MESSAGE(name.front() != '.', name);  // no temporary left
        }
    }
    CHECK(failed > 0);  // the limits tried do reach the memory the runs need
}

TEST_CASE("limits: an empty number is refused naming the option, never read as 0") {
    for (const std::string& args :
         {std::string("thumbnail gas --at ''"), std::string("simulate gas --until ''"),
          std::string("render gas --duration ''"), std::string("render gas --speed ''"),
          std::string("render gas --dt ''"), std::string("render gas --slow-motion ''"),
          std::string("thumbnail gas-3d --slab ''"), std::string("heap --ops 'P *' --pace ''"),
          std::string("simulate gas --until 1 --engine time --dt ''"),
          std::string("bench engine --eta ''")}) {
        CAPTURE(args);
        const std::string option = args.substr(
            args.rfind("--"), args.find_first_of(" =", args.rfind("--")) - args.rfind("--"));
        const bool draws = args.rfind("simulate", 0) != 0 && args.rfind("bench", 0) != 0;
        const std::string out =
            run_collide_bad_input(args + (draws ? " -o /tmp/collide_never.mp4" : ""));
        CHECK(contains(out, option + ": expected a number, got an empty value"));
    }
    CHECK_FALSE(fs::exists("/tmp/collide_never.mp4"));
}
