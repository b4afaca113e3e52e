// The lean build (-DCOLLIDE_VIDEO=OFF, issue #46): the drawing program without libav writes
// thumbnails, stills and PNG frames, `compare` checks them, and a video output is refused as bad
// input (exit 2) saying that this build has no video, with nothing left behind.

#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "../app/run_collide.hpp"
#include "../support/temp_dir.hpp"
#include "collide/video/png.hpp"

using collide::test::run_collide;
using collide::test::run_command;
using collide::test::shell_quoted;
using collide::test::TempDir;

namespace fs = std::filesystem;

namespace {}  // namespace

TEST_CASE("lean: no libav among the drawing program's libraries, and --version says so") {
    const auto needed = run_command(std::string("readelf -d \"") + COLLIDE_DRAW_EXE + "\" 2>&1");
    REQUIRE(needed.exit_code == 0);
    CHECK(needed.output.find("NEEDED") != std::string::npos);
    for (const char* library :
         {"libavcodec", "libavformat", "libavutil", "libswscale", "libavfilter"}) {
        CAPTURE(library);
        CHECK(needed.output.find(library) == std::string::npos);
    }
    const auto version = run_collide("--version");
    CHECK(version.exit_code == 0);
    CHECK(version.output.find("-DCOLLIDE_VIDEO=OFF") != std::string::npos);
}

TEST_CASE("lean: a thumbnail, compared with itself and with another moment") {
    TempDir dir("lean_thumb");
    const fs::path a = dir.path / "a.png";
    const fs::path b = dir.path / "b.png";
    const fs::path c = dir.path / "c.png";
    REQUIRE(run_collide("thumbnail tunnelling -q l --at 1 -o " + shell_quoted(a)).exit_code == 0);
    REQUIRE(run_collide("thumbnail tunnelling -q l --at 1 -o " + shell_quoted(b)).exit_code == 0);
    REQUIRE(run_collide("thumbnail tunnelling -q l --at 3 -o " + shell_quoted(c)).exit_code == 0);
    const collide::Image image = collide::video::read_png(a);
    CHECK(image.width == 854);
    CHECK(image.height == 480);
    CHECK(run_collide("compare " + shell_quoted(a) + " " + shell_quoted(b)).exit_code == 0);
    CHECK(run_collide("compare " + shell_quoted(a) + " " + shell_quoted(c)).exit_code == 1);
}

TEST_CASE("lean: PNG frames and a last frame are written, an MP4 or a GIF is refused (exit 2)") {
    TempDir dir("lean_video");
    const fs::path frames = dir.path / "frames";
    const auto written =
        run_collide("render gas -q l --duration 0.2 --format png -o " + shell_quoted(frames));
    CHECK(written.exit_code == 0);
    CHECK(fs::exists(frames / "frames_00000.png"));
    const fs::path last = dir.path / "last.png";
    CHECK(run_collide("render gas -q l --duration 0.5 --last-frame -o " + shell_quoted(last))
              .exit_code == 0);
    CHECK(fs::exists(last));
    for (const std::string& args :
         {std::string("render gas -q l --duration 1 -o ") + shell_quoted(dir.path / "v.mp4"),
          std::string("render gas -q l --duration 1 -o ") + shell_quoted(dir.path / "v.gif"),
          std::string("render gas -q l --duration 1 --format gif -o ") +
              shell_quoted(dir.path / "w"),
          std::string("heap --ops \"P Q E *\" -q l -o ") + shell_quoted(dir.path / "h.mp4"),
          std::string("puzzle \"1 2 3 4 0 6 7 5 8\" -q l -o ") +
              shell_quoted(dir.path / "p.gif")}) {
        CAPTURE(args);
        const auto refused = run_collide(args);
        CHECK(refused.exit_code == 2);
        CHECK(refused.output.find("this build has no video") != std::string::npos);
    }
    // Nothing but what the accepted runs wrote: no temporary, no partial video.
    int entries = 0;
    for (const auto& entry : fs::directory_iterator(dir.path)) {
        CAPTURE(entry.path());
        CHECK((entry.path() == frames || entry.path() == last));
        ++entries;
    }
    CHECK(entries == 2);
}
