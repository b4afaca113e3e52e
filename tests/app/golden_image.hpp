#pragma once
// The golden thumbnails of tests/app/golden: a thumbnail matches when some channel differs by
// more than 2 on at most 0.1% of its pixels (small rasteriser changes pass, real ones fail).
// COLLIDE_UPDATE_GOLDENS=1 rewrites the golden instead (then LOOK at the new PNG).

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "../support/skip.hpp"
#include "collide/image.hpp"
#include "collide/video/png.hpp"

namespace collide::test {

/// Share of pixels where some channel differs by more than 2 (the golden-image tolerance); 1
/// for images of different sizes.
inline double share_of_differing_pixels(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height) return 1.0;
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
        for (std::size_t c = 0; c < 4; ++c) {
            if (std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c])) > 2) {
                ++differing;
                break;
            }
        }
    }
    return static_cast<double>(differing) / (static_cast<double>(a.rgba.size()) / 4.0);
}

/// Compares a thumbnail with tests/app/golden/<name>.png, or rewrites the golden (and skips)
/// under COLLIDE_UPDATE_GOLDENS=1.
inline void check_golden(const std::filesystem::path& image_path, const std::string& name) {
    const std::filesystem::path golden =
        std::filesystem::path(COLLIDE_TESTS_DIR) / "app" / "golden" / (name + ".png");
    const Image image = video::read_png(image_path);
    const char* update = std::getenv("COLLIDE_UPDATE_GOLDENS");
    if (update != nullptr && std::string(update) == "1") {
        std::filesystem::create_directories(golden.parent_path());
        video::write_png(image, golden);
        COLLIDE_SKIP_TEST("golden rewritten, not compared: " << golden.string());
    }
    REQUIRE_MESSAGE(std::filesystem::exists(golden),
                    "missing golden " << golden.string() << " (COLLIDE_UPDATE_GOLDENS=1)");
    CHECK_MESSAGE(share_of_differing_pixels(image, video::read_png(golden)) <= 0.001, name);
}

}  // namespace collide::test
