#pragma once
// `collide compare`: two images pixel by pixel, for golden-image checks in CI.

#include <cstdint>

#include "collide/image.hpp"

namespace collide::app {

/// How two images of one size differ.
struct ImageComparison {
    std::int64_t pixels = 0;      ///< width * height
    std::int64_t differing = 0;   ///< pixels whose largest channel difference exceeds the tolerance
    std::int64_t touched = 0;     ///< pixels that differ at all (within the tolerance or not)
    int largest = 0;              ///< largest channel difference of any pixel (0..255)
    double mean_differing = 0.0;  ///< mean of the largest channel difference over `differing`
    [[nodiscard]] bool match() const noexcept { return differing == 0; }
};

/// Compares `a` and `b` (same size, RGBA8, alpha included): a pixel differs when one of its
/// channels differs by more than `tolerance` (0..255). O(pixels).
[[nodiscard]] ImageComparison compare_images(const Image& a, const Image& b, int tolerance);

/// A picture of where `a` and `b` (same size) differ: `a` in dim grey, pixels beyond the
/// tolerance in red (brighter for larger differences), pixels that differ within it in yellow.
[[nodiscard]] Image difference_image(const Image& a, const Image& b, int tolerance);

}  // namespace collide::app
