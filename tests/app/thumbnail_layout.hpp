// The frame's layout as `collide thumbnail ... --layout-json` writes it: what the layout tests
// (the boxes' share of the frame, the queue strip's text) read, through the real program.
#pragma once

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "../support/temp_dir.hpp"
#include "run_collide.hpp"

/// The layout of `scene`'s thumbnail at `at` s (0.5 unless given), preset `preset`, with
/// `options`, drawn in `dir`.
inline nlohmann::json thumbnail_layout(const collide::test::TempDir& dir, const std::string& scene,
                                       const char* preset, const char* options,
                                       const char* at = "0.5") {
    const std::filesystem::path json = dir.path / "layout.json";
    const auto r = collide::test::run_collide(
        "thumbnail " + scene + " -q " + preset + " --at " + at + " " + options +
        " --progress none -o " + (dir.path / "t.png").string() + " --layout-json " + json.string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    std::ifstream in(json);
    return nlohmann::json::parse(in);
}
