#pragma once
/// \file
/// RGBA8 -> yuv420p (BT.709, limited/MPEG range) conversion, hand-written in fixed point (far
/// less CPU than libswscale, see docs/benchmarks.md). Internal to collide_video.

#include <cstddef>
#include <cstdint>

namespace collide::video::detail {

/// Destination planes of a yuv420p picture (chroma planes are half width, half height).
struct Yuv420View {
    std::uint8_t* y = nullptr;
    std::uint8_t* u = nullptr;
    std::uint8_t* v = nullptr;
    std::ptrdiff_t y_stride = 0;
    std::ptrdiff_t u_stride = 0;
    std::ptrdiff_t v_stride = 0;
};

/// Converts rows [row_begin, row_end) (both even) of an RGBA image `width` pixels wide (even).
/// Luma per pixel; chroma from the 2x2 block average (alpha ignored). Integer arithmetic with
/// 16-bit coefficients: within +-1 of the exact BT.709 formula. O(width * rows).
void rgba_to_yuv420_bt709_rows(const std::uint8_t* rgba, std::ptrdiff_t rgba_stride, int width,
                               Yuv420View out, int row_begin, int row_end) noexcept;

/// rgba_to_yuv420_bt709_rows without the SIMD kernels (chosen at run time on x86-64 with AVX2):
/// the same bytes, slower. The tests compare the two.
void rgba_to_yuv420_bt709_rows_portable(const std::uint8_t* rgba, std::ptrdiff_t rgba_stride,
                                        int width, Yuv420View out, int row_begin,
                                        int row_end) noexcept;

/// Whole picture (`width`, `height` even), on the calling thread.
void rgba_to_yuv420_bt709(const std::uint8_t* rgba, std::ptrdiff_t rgba_stride, int width,
                          int height, Yuv420View out) noexcept;

}  // namespace collide::video::detail
