#include "rgba_to_yuv.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <thread>
#include <vector>

namespace collide::video::detail {
namespace {

// BT.709 luma weights and the limited ("MPEG") range: Y in 16..235, Cb/Cr in 16..240.
constexpr double kr = 0.2126;
constexpr double kb = 0.0722;
constexpr double kg = 1.0 - kr - kb;
constexpr double luma_scale = 219.0 / 255.0;
constexpr double chroma_scale = 224.0 / 255.0;

constexpr int shift = 16;  // fixed-point fraction bits; sums of 4 pixels still fit in int32
constexpr int fixed(double value) {
    return static_cast<int>(value * (1 << shift) + (value < 0 ? -0.5 : 0.5));
}

constexpr int y_r = fixed(luma_scale * kr);
constexpr int y_g = fixed(luma_scale * kg);
constexpr int y_b = fixed(luma_scale * kb);
constexpr int u_r = fixed(-chroma_scale * kr / (2 * (1 - kb)));
constexpr int u_g = fixed(-chroma_scale * kg / (2 * (1 - kb)));
constexpr int u_b = fixed(chroma_scale * 0.5);
constexpr int v_r = fixed(chroma_scale * 0.5);
constexpr int v_g = fixed(-chroma_scale * kg / (2 * (1 - kr)));
constexpr int v_b = fixed(-chroma_scale * kb / (2 * (1 - kr)));

constexpr int y_offset = (16 << shift) + (1 << (shift - 1));  // +16, rounded
// Chroma works on the sum of 4 pixels: two more fraction bits.
constexpr int c_offset = (128 << (shift + 2)) + (1 << (shift + 1));

inline std::uint8_t luma(int r, int g, int b) noexcept {
    return static_cast<std::uint8_t>((y_r * r + y_g * g + y_b * b + y_offset) >> shift);
}

// Each pixel read as one 32-bit word and split with shifts (R in the low byte on little-endian
// machines): GCC vectorises this form, not the byte-strided one.
void luma_row(const std::uint8_t* __restrict rgba, int width, std::uint8_t* __restrict y) noexcept {
    if constexpr (std::endian::native == std::endian::little) {
        for (int x = 0; x < width; ++x) {
            std::uint32_t p = 0;
            std::memcpy(&p, rgba + 4 * x, 4);
            y[x] = luma(static_cast<int>(p & 0xFFU), static_cast<int>((p >> 8) & 0xFFU),
                        static_cast<int>((p >> 16) & 0xFFU));
        }
    } else {
        for (int x = 0; x < width; ++x) {
            const std::uint8_t* p = rgba + 4 * x;
            y[x] = luma(p[0], p[1], p[2]);
        }
    }
}

// __restrict: the planes never alias the RGBA input; without it GCC adds run-time alias checks.
void chroma_row(const std::uint8_t* __restrict top, const std::uint8_t* __restrict bottom,
                int width, std::uint8_t* __restrict u, std::uint8_t* __restrict v) noexcept {
    for (int cx = 0; cx < width / 2; ++cx) {
        const std::uint8_t* a = top + 8 * cx;
        const std::uint8_t* b = bottom + 8 * cx;
        const int r = a[0] + a[4] + b[0] + b[4];
        const int g = a[1] + a[5] + b[1] + b[5];
        const int bl = a[2] + a[6] + b[2] + b[6];
        u[cx] = static_cast<std::uint8_t>((u_r * r + u_g * g + u_b * bl + c_offset) >> (shift + 2));
        v[cx] = static_cast<std::uint8_t>((v_r * r + v_g * g + v_b * bl + c_offset) >> (shift + 2));
    }
}

}  // namespace

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
__attribute__((target_clones("avx2", "default")))
#endif
void rgba_to_yuv420_bt709_rows(const std::uint8_t* rgba, std::ptrdiff_t rgba_stride, int width,
                               Yuv420View out, int row_begin, int row_end) noexcept {
    for (int row = row_begin; row < row_end; row += 2) {
        const std::uint8_t* top = rgba + row * rgba_stride;
        const std::uint8_t* bottom = top + rgba_stride;
        luma_row(top, width, out.y + row * out.y_stride);
        luma_row(bottom, width, out.y + (row + 1) * out.y_stride);
        chroma_row(top, bottom, width, out.u + (row / 2) * out.u_stride,
                   out.v + (row / 2) * out.v_stride);
    }
}

void rgba_to_yuv420_bt709(const std::uint8_t* rgba, std::ptrdiff_t rgba_stride, int width,
                          int height, Yuv420View out, int threads) {
    threads = std::clamp(threads, 1, std::max(1, height / 2));
    const int band = (height / threads) & ~1;
    std::vector<std::jthread> workers;
    workers.reserve(static_cast<std::size_t>(threads - 1));
    for (int i = 0; i + 1 < threads; ++i) {
        workers.emplace_back([=] {
            rgba_to_yuv420_bt709_rows(rgba, rgba_stride, width, out, i * band, (i + 1) * band);
        });
    }
    // The calling thread takes the last (possibly taller) band.
    rgba_to_yuv420_bt709_rows(rgba, rgba_stride, width, out, (threads - 1) * band, height);
}

namespace {

SwsPtr make_bt709_sws(int width, int height, int flags) {
    SwsPtr context(sws_getContext(width, height, AV_PIX_FMT_RGBA, width, height, AV_PIX_FMT_YUV420P,
                                  flags, nullptr, nullptr, nullptr));
    if (!context)
        throw_runtime_error("libswscale: cannot create an RGBA -> yuv420p converter");
    int* inverse_table = nullptr;
    int* table = nullptr;
    int source_range = 0;
    int destination_range = 0;
    int brightness = 0;
    int contrast = 0;
    int saturation = 0;
    sws_getColorspaceDetails(context.get(), &inverse_table, &source_range, &table,
                             &destination_range, &brightness, &contrast, &saturation);
    // Source: full-range RGB; destination: BT.709 matrix, limited range (what the tags say).
    check_av(sws_setColorspaceDetails(context.get(), inverse_table, 1,
                                      sws_getCoefficients(SWS_CS_ITU709), 0, brightness, contrast,
                                      saturation),
             "libswscale: cannot select BT.709");
    return context;
}

void sws_band(SwsContext* context, const std::uint8_t* rgba, std::ptrdiff_t rgba_stride, int rows,
              Yuv420View out, int row_begin) {
    const std::uint8_t* source[1] = {rgba + row_begin * rgba_stride};
    const int source_stride[1] = {static_cast<int>(rgba_stride)};
    std::uint8_t* destination[3] = {out.y + row_begin * out.y_stride,
                                    out.u + (row_begin / 2) * out.u_stride,
                                    out.v + (row_begin / 2) * out.v_stride};
    const int destination_stride[3] = {static_cast<int>(out.y_stride),
                                       static_cast<int>(out.u_stride),
                                       static_cast<int>(out.v_stride)};
    sws_scale(context, source, source_stride, 0, rows, destination, destination_stride);
}

}  // namespace

SwsConverter::SwsConverter(int width, int height, int flags, int bands)
    : width_(width), height_(height), bands_(std::clamp(bands, 1, 2)) {
    band_rows_ = bands_ == 1 ? height : (height / 2) & ~1;
    first_ = make_bt709_sws(width, band_rows_, flags);
    if (bands_ == 2)
        last_ = make_bt709_sws(width, height - band_rows_, flags);
}

void SwsConverter::convert(const std::uint8_t* rgba, std::ptrdiff_t rgba_stride, Yuv420View out) {
    if (bands_ == 1) {
        sws_band(first_.get(), rgba, rgba_stride, height_, out, 0);
        return;
    }
    std::jthread helper([&] { sws_band(first_.get(), rgba, rgba_stride, band_rows_, out, 0); });
    sws_band(last_.get(), rgba, rgba_stride, height_ - band_rows_, out, band_rows_);
}

}  // namespace collide::video::detail
