#include "image_compare.hpp"

#include <algorithm>
#include <cstdlib>

namespace collide::app {

namespace {

/// The largest of the four channel differences of pixel `i`.
int pixel_difference(const Image& a, const Image& b, std::size_t i) {
    int largest = 0;
    for (std::size_t c = 0; c < 4; ++c) {
        largest = std::max(largest, std::abs(int{a.rgba[i + c]} - int{b.rgba[i + c]}));
    }
    return largest;
}

}  // namespace

bool within(const ImageComparison& c, const CompareAllowance& allowance) noexcept {
    // In integers and doubles exactly: differing <= max_percent / 100 * pixels.
    return c.differing <= allowance.max_pixels &&
           100.0 * static_cast<double>(c.differing) <=
               allowance.max_percent * static_cast<double>(c.pixels);
}

ImageComparison compare_images(const Image& a, const Image& b, int tolerance) {
    ImageComparison result;
    result.pixels = static_cast<std::int64_t>(a.width) * a.height;
    double sum = 0.0;
    PixelBox& box = result.differing_box;
    for (std::size_t i = 0; i + 3 < a.rgba.size() && i + 3 < b.rgba.size(); i += 4) {
        const int d = pixel_difference(a, b, i);
        if (d == 0) continue;
        ++result.touched;
        result.largest = std::max(result.largest, d);
        if (d > tolerance) {
            const auto pixel = static_cast<std::int64_t>(i / 4);
            const auto x = static_cast<int>(pixel % a.width);
            const auto y = static_cast<int>(pixel / a.width);
            if (result.differing == 0) box = {x, y, x, y};
            box = {std::min(box.x0, x), std::min(box.y0, y), std::max(box.x1, x),
                   std::max(box.y1, y)};
            ++result.differing;
            sum += d;
        }
    }
    if (result.differing > 0) result.mean_differing = sum / static_cast<double>(result.differing);
    return result;
}

Image difference_image(const Image& a, const Image& b, int tolerance) {
    Image out(a.width, a.height);
    for (std::size_t i = 0; i + 3 < a.rgba.size() && i + 3 < b.rgba.size(); i += 4) {
        const int d = pixel_difference(a, b, i);
        std::uint8_t* p = out.rgba.data() + i;
        if (d > tolerance) {
            p[0] = static_cast<std::uint8_t>(std::min(255, 128 + d));
            p[1] = 0;
            p[2] = 0;
        } else if (d > 0) {
            p[0] = 230;
            p[1] = 200;
            p[2] = 0;
        } else {
            // Rec. 601 luma of a, at a quarter of its brightness: context, not competition.
            const int luma = (299 * a.rgba[i] + 587 * a.rgba[i + 1] + 114 * a.rgba[i + 2]) / 1000;
            const auto grey = static_cast<std::uint8_t>(luma / 4);
            p[0] = p[1] = p[2] = grey;
        }
        p[3] = 255;
    }
    return out;
}

}  // namespace collide::app
