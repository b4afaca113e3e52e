// Small files (issue #46): every PNG collide writes is opaque and stored as RGB (no alpha channel
// that is always 255), and the sizes it prints are SI units, named right (kB = 1000 bytes).

#include <doctest/doctest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "../support/temp_dir.hpp"
#include "run_collide.hpp"

using collide::test::run_collide;
using collide::test::TempDir;

namespace {

namespace fs = std::filesystem;

/// The colour type in a PNG file's header: 2 RGB, 6 RGBA.
int png_colour_type(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    REQUIRE(bytes.size() > 25);
    REQUIRE(bytes.compare(12, 4, "IHDR") == 0);
    return static_cast<unsigned char>(bytes[25]);
}

}  // namespace

TEST_CASE("thumbnail and PNG frames are RGB PNGs, and the size printed is in kB of 1000 bytes") {
    TempDir dir("small_files");
    for (const char* size : {"320x180", "641x359"}) {
        CAPTURE(size);
        const fs::path png = dir.path / (std::string("t") + size + ".png");
        const auto r =
            run_collide(std::string("thumbnail gas --at 1 --size ") + size + " -o " + png.string());
        REQUIRE_MESSAGE(r.exit_code == 0, r.output);
        CHECK(png_colour_type(png) == 2);
        const auto bytes = fs::file_size(png);
        REQUIRE(bytes >= 1000);
        REQUIRE(bytes < 1'000'000);
        std::array<char, 64> shown_text{};
        std::snprintf(shown_text.data(), shown_text.size(), ", %.1f kB,",
                      static_cast<double>(bytes) / 1000.0);
        const std::string shown = shown_text.data();
        CHECK_MESSAGE(r.output.find(shown) != std::string::npos, r.output << " lacks " << shown);
    }
    const fs::path frames = dir.path / "frames";
    const auto r = run_collide(
        "render gas -q l --size 160x90 --duration 0.2 --fps 5 --format png -o " + frames.string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    int seen = 0;
    for (const auto& entry : fs::directory_iterator(frames)) {
        CHECK(png_colour_type(entry.path()) == 2);
        ++seen;
    }
    CHECK(seen >= 1);
}
