#pragma once
// `collide compare`: two images pixel by pixel, for golden-image checks in CI.

#include <cstdint>

#include "collide/image.hpp"

namespace collide::app {

/// A rectangle of pixels, corners included: x0..x1, y0..y1 (empty when x1 < x0).
struct PixelBox {
    int x0 = 0;
    int y0 = 0;
    int x1 = -1;
    int y1 = -1;
    [[nodiscard]] bool empty() const noexcept { return x1 < x0 || y1 < y0; }
    [[nodiscard]] int width() const noexcept { return empty() ? 0 : x1 - x0 + 1; }
    [[nodiscard]] int height() const noexcept { return empty() ? 0 : y1 - y0 + 1; }
};

/// How two images of one size differ.
struct ImageComparison {
    std::int64_t pixels = 0;      ///< width * height
    std::int64_t differing = 0;   ///< pixels whose largest channel difference exceeds the tolerance
    std::int64_t touched = 0;     ///< pixels that differ at all (within the tolerance or not)
    int largest = 0;              ///< largest channel difference of any pixel (0..255)
    double mean_differing = 0.0;  ///< mean of the largest channel difference over `differing`
    PixelBox differing_box;       ///< the smallest rectangle holding every differing pixel
    /// No pixel differs beyond the tolerance (no allowance: CompareAllowance's defaults).
    [[nodiscard]] bool match() const noexcept { return differing == 0; }
    /// The share of the pixels that differ, in percent (0 for an empty image).
    [[nodiscard]] double differing_percent() const noexcept {
        return pixels == 0 ? 0.0
                           : 100.0 * static_cast<double>(differing) / static_cast<double>(pixels);
    }
};

/// What a comparison lets pass: a pixel differs when a channel differs by more than `tolerance`;
/// the images match when at most `max_pixels` pixels and at most `max_percent` % of them differ.
struct CompareAllowance {
    int tolerance = 0;            ///< 0..255 per channel
    std::int64_t max_pixels = 0;  ///< differing pixels allowed
    double max_percent = 100.0;   ///< share of differing pixels allowed, 0..100
};

/// Whether `c` is within `allowance` (its tolerance must be the one `c` was computed with).
[[nodiscard]] bool within(const ImageComparison& c, const CompareAllowance& allowance) noexcept;

/// Compares `a` and `b` (same size, RGBA8, alpha included): a pixel differs when one of its
/// channels differs by more than `tolerance` (0..255). O(pixels).
[[nodiscard]] ImageComparison compare_images(const Image& a, const Image& b, int tolerance);

/// A picture of where `a` and `b` (same size) differ: `a` in dim grey, pixels beyond the
/// tolerance in red (brighter for larger differences), pixels that differ within it in yellow.
[[nodiscard]] Image difference_image(const Image& a, const Image& b, int tolerance);

}  // namespace collide::app
