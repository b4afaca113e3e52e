#pragma once
/// \file
/// RGBA8 -> yuv420p (BT.709, limited/MPEG range) conversion: a hand-written fixed-point converter
/// (the one the encoders use) and a libswscale-based one kept for comparison in bench_video and as
/// a reference in the tests. Internal to collide_video.

#include <cstddef>
#include <cstdint>

#include "av_handles.hpp"

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

/// Whole picture (`width`, `height` even), split into `threads` horizontal bands converted in
/// parallel (1 = on the calling thread only).
void rgba_to_yuv420_bt709(const std::uint8_t* rgba, std::ptrdiff_t rgba_stride, int width,
                          int height, Yuv420View out, int threads);

/// libswscale RGBA -> yuv420p with BT.709 coefficients and limited range (set through
/// sws_setColorspaceDetails; the default would be BT.601), optionally in `bands` horizontal bands
/// with one SwsContext each, converted on `bands` threads. Move-only.
class SwsConverter {
  public:
    /// `flags`: SWS_BICUBIC (libswscale's default), SWS_FAST_BILINEAR, ... Throws Error(runtime).
    SwsConverter(int width, int height, int flags, int bands);
    void convert(const std::uint8_t* rgba, std::ptrdiff_t rgba_stride, Yuv420View out);

  private:
    int width_ = 0;
    int height_ = 0;
    int band_rows_ = 0;  ///< rows per band (even); the last band takes the remainder
    SwsPtr first_;       ///< band of band_rows_ rows
    SwsPtr last_;        ///< the final band (may be taller); null when bands == 1
    int bands_ = 1;
};

}  // namespace collide::video::detail
