// The hand-written BT.709 RGBA -> yuv420p converter against the standard's formula.

#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "rgba_to_yuv.hpp"
#include "video_test_support.hpp"

using namespace collide::video::detail;

namespace {

struct Planes {
    int width;
    int height;
    std::vector<std::uint8_t> y, u, v;
    Planes(int w, int h)
        : width(w),
          height(h),
          y(std::size_t(w) * h),
          u(std::size_t(w / 2) * (h / 2)),
          v(std::size_t(w / 2) * (h / 2)) {}
    Yuv420View view() { return {y.data(), u.data(), v.data(), width, width / 2, width / 2}; }
};

Planes convert(const collide::Image& image) {
    Planes planes(image.width, image.height);
    rgba_to_yuv420_bt709(image.rgba.data(), std::ptrdiff_t(image.stride()), image.width,
                         image.height, planes.view());
    return planes;
}

collide::Image solid(int r, int g, int b) {
    collide::Image image(4, 2);
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 4; ++x) {
            std::uint8_t* p = image.pixel(x, y);
            p[0] = std::uint8_t(r);
            p[1] = std::uint8_t(g);
            p[2] = std::uint8_t(b);
            p[3] = 255;
        }
    }
    return image;
}

}  // namespace

TEST_CASE("primaries, white and black land on the BT.709 limited-range code values") {
    struct Case {
        int r, g, b, y, u, v;
    };
    // The 100% colour bar values of BT.709 in 8 bits.
    for (const Case c : {Case{255, 255, 255, 235, 128, 128}, Case{0, 0, 0, 16, 128, 128},
                         Case{255, 0, 0, 63, 102, 240}, Case{0, 255, 0, 173, 42, 26},
                         Case{0, 0, 255, 32, 240, 118}}) {
        CAPTURE(c.r);
        CAPTURE(c.g);
        CAPTURE(c.b);
        const Planes planes = convert(solid(c.r, c.g, c.b));
        CHECK(int(planes.y[0]) == c.y);
        CHECK(int(planes.y[5]) == c.y);
        CHECK(int(planes.u[1]) == c.u);
        CHECK(int(planes.v[1]) == c.v);
    }
}

TEST_CASE("random pixels: within 1 code value of the exact formula") {
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> byte(0, 255);
    collide::Image image(64, 32);
    for (auto& value : image.rgba) value = std::uint8_t(byte(rng));
    const Planes planes = convert(image);
    const collide::video::testing::Yuv420 exact = collide::video::testing::exact_yuv420(image);
    int worst = 0;
    for (std::size_t i = 0; i < exact.y.size(); ++i) {
        worst = std::max(worst, int(std::lround(std::abs(planes.y[i] - exact.y[i]) + 0.49)));
    }
    for (std::size_t i = 0; i < exact.u.size(); ++i) {
        worst = std::max(worst, int(std::ceil(std::abs(planes.u[i] - exact.u[i]) - 0.5)));
        worst = std::max(worst, int(std::ceil(std::abs(planes.v[i] - exact.v[i]) - 0.5)));
    }
    CHECK(worst <= 1);
}

TEST_CASE("the SIMD kernels give the portable code's bytes") {
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> byte(0, 255);
    // Widths below, at and past the 16-pixel SIMD step (the tail is done by the portable code).
    for (const int width : {2, 14, 16, 18, 46, 130}) {
        CAPTURE(width);
        collide::Image image(width, 6);
        for (auto& value : image.rgba) value = std::uint8_t(byte(rng));
        // Extremes of the 2x2 sums: saturated primaries, white and black blocks.
        const int corners[][3] = {
            {255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}, {0, 0, 0}};
        for (int x = 0; x < width; ++x) {
            for (int y = 0; y < 2; ++y) {
                std::uint8_t* p = image.pixel(x, y);
                for (int c = 0; c < 3; ++c) p[c] = std::uint8_t(corners[(x / 2) % 5][c]);
            }
        }
        Planes fast(width, image.height);
        Planes portable(width, image.height);
        rgba_to_yuv420_bt709_rows(image.rgba.data(), std::ptrdiff_t(image.stride()), width,
                                  fast.view(), 0, image.height);
        rgba_to_yuv420_bt709_rows_portable(image.rgba.data(), std::ptrdiff_t(image.stride()), width,
                                           portable.view(), 0, image.height);
        CHECK(fast.y == portable.y);
        CHECK(fast.u == portable.u);
        CHECK(fast.v == portable.v);
    }
}
