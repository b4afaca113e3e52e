// `collide compare` for CI (issue #46), on the real program: allowances beside the tolerance,
// --json, the difference image, clear messages for what is not a PNG, inputs bounded like the
// renderer's frames (#48), and a program that runs without the drawing half.

#include <doctest/doctest.h>
#include <sys/stat.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>

#include "../support/png_bytes.hpp"
#include "../support/temp_dir.hpp"
#include "collide/image.hpp"
#include "collide/video/png.hpp"
#include "run_collide.hpp"

using collide::test::run_collide;
using collide::test::run_command;
using collide::test::TempDir;

namespace {

namespace fs = std::filesystem;

/// A 100 x 50 picture (5000 pixels) with a gradient, so that no two pixels are alike.
collide::Image base_image() {
    collide::Image image(100, 50);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            std::uint8_t* p = image.pixel(x, y);
            p[0] = static_cast<std::uint8_t>(2 * x);
            p[1] = static_cast<std::uint8_t>(4 * y);
            p[2] = 100;
            p[3] = 255;
        }
    }
    return image;
}

/// base_image with the green channel of the pixels (x0 + i, y0 + i), i < count, raised by `by`.
collide::Image changed(int x0, int y0, int count, int by) {
    collide::Image image = base_image();
    for (int i = 0; i < count; ++i) image.pixel(x0 + i, y0 + i)[1] += static_cast<std::uint8_t>(by);
    return image;
}

std::string read_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// `collide compare ARGS` with stdout alone (stderr dropped): the JSON document.
collide::test::RunResult run_stdout(const std::string& args) {
    return run_command(std::string("\"") + COLLIDE_EXE + "\" compare " + args + " 2>/dev/null");
}

struct Fixture {
    TempDir dir{"compare_cli"};
    std::string a = (dir.path / "a.png").string();
    std::string b = (dir.path / "b.png").string();
    Fixture() {
        collide::video::write_png(base_image(), a);
        // Five pixels on a diagonal from (10, 20), each green channel 30 higher.
        collide::video::write_png(changed(10, 20, 5, 30), b);
    }
    [[nodiscard]] std::string path(const char* name) const { return (dir.path / name).string(); }
};

}  // namespace

TEST_CASE("compare: --max-diff-pixels and --max-diff-percent let a few differing pixels pass") {
    Fixture f;
    const std::string pair = f.a + " " + f.b;
    CHECK(run_collide("compare " + pair).exit_code == 1);
    CHECK(run_collide("compare " + pair + " --max-diff-pixels 5").exit_code == 0);
    CHECK(run_collide("compare " + pair + " --max-diff-pixels 4").exit_code == 1);
    // 5 of 5000 pixels: 0.1 %.
    CHECK(run_collide("compare " + pair + " --max-diff-percent 0.1").exit_code == 0);
    CHECK(run_collide("compare " + pair + " --max-diff-percent 0.099").exit_code == 1);
    // Both given: both must hold.
    CHECK(run_collide("compare " + pair + " --max-diff-pixels 100 --max-diff-percent 0.05")
              .exit_code == 1);
    CHECK(run_collide("compare " + pair + " --max-diff-pixels 4 --max-diff-percent 50").exit_code ==
          1);
    CHECK(
        run_collide("compare " + pair + " --max-diff-pixels 5 --max-diff-percent 0.1").exit_code ==
        0);
    // The tolerance decides which pixels count as differing at all.
    CHECK(run_collide("compare " + pair + " --tolerance 30").exit_code == 0);
    CHECK(run_collide("compare " + pair + " --tolerance 29").exit_code == 1);
    fs::remove(f.dir.path / "b.diff.png");  // from the runs that differed above
    const auto allowed = run_collide("compare " + pair + " --max-diff-pixels 5");
    CHECK(allowed.output.rfind("match: 5000 pixels, 5 differ by more than 0 (within "
                               "--max-diff-pixels 5)",
                               0) == 0);
    CHECK(!fs::exists(f.dir.path / "b.diff.png"));  // a pass leaves no picture
    const auto beyond = run_collide("compare " + pair + " --max-diff-pixels 4");
    CHECK(beyond.output.find("more than --max-diff-pixels 4 allow") != std::string::npos);
    CHECK(beyond.output.find("within 5x5 at (10, 20)") != std::string::npos);
    // Bad allowances are usage errors naming the option.
    for (const char* bad :
         {"--max-diff-percent 101", "--max-diff-percent -1", "--max-diff-percent nan",
          "--max-diff-percent ''", "--max-diff-percent 5x", "--max-diff-pixels -1",
          "--max-diff-pixels 1.5"}) {
        CAPTURE(bad);
        const auto r = run_collide("compare " + pair + " " + bad);
        CHECK(r.exit_code == 2);
        CHECK(r.output.find(std::string(bad).substr(0, 17)) != std::string::npos);
    }
}

TEST_CASE("compare --json: pixels, differences, largest difference and their bounding box") {
    Fixture f;
    const auto r = run_stdout(f.a + " " + f.b + " --json");
    CHECK(r.exit_code == 1);
    const nlohmann::json j = nlohmann::json::parse(r.output);
    CHECK(j["result"] == "differ");
    CHECK(j["expected"] == f.a);
    CHECK(j["actual"] == f.b);
    CHECK(j["pixels"] == 5000);
    CHECK(j["differing"] == 5);
    CHECK(j["touched"] == 5);
    CHECK(j["differing_percent"].get<double>() == doctest::Approx(0.1));
    CHECK(j["largest_difference"] == 30);
    CHECK(j["bounding_box"] == nlohmann::json{{"x", 10}, {"y", 20}, {"width", 5}, {"height", 5}});
    CHECK(j["max_diff_pixels"].is_null());
    CHECK(j["diff_image"] == f.path("b.diff.png"));
    CHECK(fs::is_regular_file(f.path("b.diff.png")));

    // Within the tolerance: a match, the pixels that moved still counted, no box, no picture.
    const auto within =
        run_stdout(f.a + " " + f.b + " --json --tolerance 40 --diff " + f.path("none.png"));
    CHECK(within.exit_code == 0);
    const nlohmann::json m = nlohmann::json::parse(within.output);
    CHECK(m["result"] == "match");
    CHECK(m["differing"] == 0);
    CHECK(m["touched"] == 5);
    CHECK(m["bounding_box"].is_null());
    CHECK(m["diff_image"].is_null());
    CHECK(!fs::exists(f.path("none.png")));

    // Another variant: one changed pixel in a corner, allowed by a percentage.
    collide::video::write_png(changed(99, 49, 1, 7), f.path("c.png"));
    const auto corner = run_stdout(f.a + " " + f.path("c.png") + " --json --max-diff-percent 1");
    CHECK(corner.exit_code == 0);
    const nlohmann::json c = nlohmann::json::parse(corner.output);
    CHECK(c["bounding_box"] == nlohmann::json{{"x", 99}, {"y", 49}, {"width", 1}, {"height", 1}});
    CHECK(c["max_diff_percent"] == 1.0);
    CHECK(c["largest_difference"] == 7);

    // Sizes that differ: JSON too, exit 1.
    collide::video::write_png(collide::Image(20, 10), f.path("small.png"));
    const auto sizes = run_stdout(f.a + " " + f.path("small.png") + " --json");
    CHECK(sizes.exit_code == 1);
    const nlohmann::json s = nlohmann::json::parse(sizes.output);
    CHECK(s["result"] == "size");
    CHECK(s["actual_size"] == nlohmann::json{{"width", 20}, {"height", 10}});
}

TEST_CASE("compare: the difference image is an RGB PNG, red where pixels differ") {
    Fixture f;
    REQUIRE(run_collide("compare " + f.a + " " + f.b + " --diff " + f.path("d.png")).exit_code ==
            1);
    const std::string bytes = read_file(f.path("d.png"));
    REQUIRE(bytes.size() > 25);
    CHECK(static_cast<unsigned char>(bytes[25]) == 2);  // colour type 2: RGB, no alpha
    const collide::Image d = collide::video::read_png(f.path("d.png"));
    CHECK(d.pixel(12, 22)[0] > 150);
    CHECK(d.pixel(12, 22)[1] == 0);
    CHECK(d.pixel(13, 22)[0] < 100);  // a pixel that did not change: dim grey
}

TEST_CASE("compare: clear messages for what is not a readable PNG, at once for FIFOs and devices") {
    Fixture f;
    REQUIRE(::mkfifo(f.path("fifo.png").c_str(), 0600) == 0);
    std::ofstream(f.path("text.png")) << "hello\n";
    std::ofstream(f.path("photo.png"), std::ios::binary) << std::string("\xff\xd8\xff\xe0", 4);
    std::ofstream(f.path("empty.png")).close();
    fs::create_directory(f.path("dir.png"));
    const struct {
        std::string file;
        std::string says;
    } cases[] = {{f.path("fifo.png"), "a FIFO (named pipe), not a regular file"},
                 {"/dev/zero", "a character device, not a regular file"},
                 {f.path("dir.png"), "a directory"},
                 {f.path("text.png"), "not a PNG image"},
                 {f.path("photo.png"), "not a PNG image (it is a JPEG image)"},
                 {f.path("empty.png"), "the file is empty"},
                 {f.path("missing.png"), "No such file or directory"}};
    for (const auto& c : cases) {
        for (const bool first : {true, false}) {
            CAPTURE(c.file);
            CAPTURE(first);
            const std::string args = first ? c.file + " " + f.a : f.a + " " + c.file;
            // `timeout`: a FIFO that blocked would fail here rather than hang the suite.
            const auto r = collide::test::run_collide_env("timeout 20", "compare " + args);
            CHECK(r.exit_code == 2);
            CHECK(r.output.find("collide: error: cannot read PNG '" + c.file + "': " + c.says) !=
                  std::string::npos);
        }
    }
}

TEST_CASE("compare: a PNG larger than the largest frame is refused by its header, at once") {
    Fixture f;
    // Only the header of a 1-bit grey PNG of up to 23000 x 23000 (a few bytes): what must be
    // refused is the size it announces.
    for (const auto& [w, h] :
         {std::pair<std::uint32_t, std::uint32_t>{23000, 23000}, {8193, 100}, {100, 9000}}) {
        std::ofstream(f.path("huge.png"), std::ios::binary) << collide::test::png_header_only(w, h);
        const auto started = std::chrono::steady_clock::now();
        const auto r = run_collide("compare " + f.path("huge.png") + " " + f.path("huge.png") +
                                   " --diff " + f.path("d.png"));
        const auto seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        CHECK(r.exit_code == 2);
        CHECK(r.output.find(std::to_string(w) + "x" + std::to_string(h) +
                            " pixels; images are read up to 8192x8192") != std::string::npos);
        CHECK(seconds < 10.0);  // refused by its header: no decoding (it took 66 s)
    }
}

TEST_CASE("compare runs in `collide` alone: no drawing program, no GL, no encoder") {
    Fixture f;
    // A copy of the program with no collide-draw beside it and none in ../libexec.
    const fs::path alone = f.dir.path / "bin" / "collide";
    fs::create_directories(alone.parent_path());
    fs::copy_file(COLLIDE_EXE, alone);
    fs::permissions(alone, fs::perms::owner_exec, fs::perm_options::add);
    const auto r = run_command("\"" + alone.string() + "\" compare " + f.a + " " + f.b +
                               " --max-diff-pixels 5 2>&1");
    CHECK_MESSAGE(r.exit_code == 0, r.output);
    CHECK(r.output.rfind("match: 5000 pixels", 0) == 0);
    // And its help lists compare's options.
    const auto help = run_command("\"" + alone.string() + "\" compare --help 2>&1");
    CHECK(help.exit_code == 0);
    CHECK(help.output.find("--max-diff-percent") != std::string::npos);
}
