// End-to-end tests of `--preview`: the real program with a real window, as a user runs it. They
// need a display: ctest runs them under `xvfb-run -a` (tests/CMakeLists.txt, entries
// "collide_app_tests:xvfb: ..."); without DISPLAY they skip (COLLIDE_SKIP_TEST), which ctest shows
// as skipped.
#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "../support/skip.hpp"
#include "../support/temp_dir.hpp"
#include "run_collide.hpp"

namespace fs = std::filesystem;
using collide::test::run_collide;
using collide::test::TempDir;

namespace {

bool have_display() {
    const char* display = std::getenv("DISPLAY");
    return display != nullptr && *display != '\0';
}

std::string read_bytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Runs a shell command; returns stdout and stderr.
std::string shell(const std::string& cmd) {
    std::string out;
    FILE* pipe = popen((cmd + " 2>&1").c_str(), "r");
    if (pipe == nullptr) return out;
    char buf[512];
    while (std::fgets(buf, sizeof buf, pipe) != nullptr) out += buf;
    pclose(pipe);
    return out;
}

/// The preview opened (no "continuing without" notice) and nothing crashed.
void check_previewed(const collide::test::RunResult& r) {
    CHECK_MESSAGE(r.exit_code == 0, r.output);
    CHECK_MESSAGE(r.output.find("continuing without") == std::string::npos, r.output);
}

// A few seconds of video, small so the test stays fast; both panels (the title the window gets).
const std::string video_args = "render gas --size 320x180 --fps 15 --duration 4 --progress none";

}  // namespace

TEST_CASE("display: ffplay plays the MP4 with its subtitle track drawn to the end and silently") {
    if (!have_display()) {
        COLLIDE_SKIP_TEST("DISPLAY is not set (the xvfb ctest entry runs this under xvfb-run)");
    }
    if (shell("command -v ffplay").empty()) COLLIDE_SKIP_TEST("ffplay is not installed");
    TempDir dir("ffplay");
    const fs::path out = dir.path / "gas.mp4";
    const auto r = run_collide(video_args + " --lang en -o " + out.string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    // ffplay draws text subtitles through libass (-vf subtitles, as mpv does by default).
    const std::string played = shell(
        "timeout 120 ffplay -autoexit -nostats -loglevel error -vf subtitles=" + out.string() +
        " " + out.string() + "; echo \"exit $?\"");
    CHECK_MESSAGE(played == "exit 0\n", played);
}

TEST_CASE("display: render --preview encodes the same file as without it") {
    if (!have_display()) {
        COLLIDE_SKIP_TEST("DISPLAY is not set (the xvfb ctest entry runs this under xvfb-run)");
    }
    TempDir dir("preview");
    for (const char* mode : {"both", "event", "time"}) {
        CAPTURE(mode);
        const std::string args = video_args + " --mode " + mode + " -o ";
        const fs::path plain = dir.path / (std::string(mode) + ".mp4");
        const fs::path previewed = dir.path / (std::string(mode) + "-preview.mp4");
        const auto without = run_collide(args + plain.string());
        REQUIRE_MESSAGE(without.exit_code == 0, without.output);
        check_previewed(run_collide(args + previewed.string() + " --preview"));
        const std::string bytes = read_bytes(plain);
        CHECK(bytes.size() > 1000);
        CHECK(bytes == read_bytes(previewed));
    }
}

TEST_CASE("display: thumbnail --preview writes the same PNG as without it") {
    if (!have_display()) {
        COLLIDE_SKIP_TEST("DISPLAY is not set (the xvfb ctest entry runs this under xvfb-run)");
    }
    TempDir dir("preview_thumb");
    const std::string args = "thumbnail gas --size 320x180 --at 2 -o ";
    const auto without = run_collide(args + (dir.path / "plain.png").string());
    REQUIRE_MESSAGE(without.exit_code == 0, without.output);
    check_previewed(run_collide(args + (dir.path / "preview.png").string() + " --preview"));
    const std::string bytes = read_bytes(dir.path / "plain.png");
    CHECK(bytes.size() > 1000);
    CHECK(bytes == read_bytes(dir.path / "preview.png"));
}

TEST_CASE("display: closing the preview window stops the preview and not the render") {
    if (!have_display()) {
        COLLIDE_SKIP_TEST("DISPLAY is not set (the xvfb ctest entry runs this under xvfb-run)");
    }
    TempDir dir("preview_close");
    // Long enough (450 frames) that the window is closed while the render is still going.
    const std::string args = "render gas --size 320x180 --fps 15 --duration 30 --progress none -o ";
    const fs::path plain = dir.path / "plain.mp4";
    const fs::path closed = dir.path / "closed.mp4";
    const auto without = run_collide(args + plain.string());
    REQUIRE_MESSAGE(without.exit_code == 0, without.output);

    // The helper closes the window as a user would. It starts first and is already watching
    // when the window appears, so that however busy the machine, the window closes early in the
    // render (450 frames) rather than after a start-up of unknown length; it waits up to 120 s.
    const fs::path script = dir.path / "close.sh";
    std::ofstream(script) << '"' << COLLIDE_CLOSE_WINDOW
                          << "\" 'collide: time-driven vs event-driven' 120 &\n"
                          << "helper=$!\n"
                          << '"' << COLLIDE_EXE << "\" " << args << closed.string()
                          << " --preview >/dev/null 2>&1 &\n"
                          << "pid=$!\n"
                          << "wait $helper\n"
                          << "echo helper=$?\n"
                          << "kill -0 $pid 2>/dev/null && echo still-rendering\n"
                          << "wait $pid\n"
                          << "echo collide=$?\n";
    const std::string report = shell("sh " + script.string());
    CHECK_MESSAGE(report.find("helper=0") != std::string::npos, report);
    CHECK_MESSAGE(report.find("still-rendering") != std::string::npos, report);
    CHECK_MESSAGE(report.find("collide=0") != std::string::npos, report);
    const std::string bytes = read_bytes(plain);
    CHECK(bytes.size() > 1000);
    CHECK(bytes == read_bytes(closed));
}
