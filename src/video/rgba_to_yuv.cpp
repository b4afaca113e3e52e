#include "rgba_to_yuv.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <vector>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#endif

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

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define COLLIDE_AVX2_CHROMA 1

// Per 16-bit lane, R G B A of two chroma samples (lane 0) and two more (lane 1): 2x2 sums of the
// 8 pixels at a (top row) and b (bottom row). `pairs` and `ones` as in chroma_row_avx2.
__attribute__((target("avx2"))) inline __m256i block_sums(const std::uint8_t* a,
                                                          const std::uint8_t* b, __m256i pairs,
                                                          __m256i ones) noexcept {
    const __m256i ta = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(a));
    const __m256i tb = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(b));
    return _mm256_add_epi16(_mm256_maddubs_epi16(_mm256_shuffle_epi8(ta, pairs), ones),
                            _mm256_maddubs_epi16(_mm256_shuffle_epi8(tb, pairs), ones));
}

// chroma_row with AVX2, 16 pixels (8 chroma samples) per step, the same integer arithmetic (so
// the same bytes): GCC does not vectorise chroma_row's stride-8 byte gathers well (bench_video;
// docs/benchmarks.md). Per 128-bit lane of 4
// pixels, a byte shuffle puts each channel of a horizontal pixel pair side by side, maddubs with
// ones adds them (<= 510), adding the bottom row's gives the 2x2 sums (<= 1020) as 16-bit lanes
// R G B A; madd with the coefficients (all fit in int16) and hadd make chroma_row's 32-bit dot
// products exactly.
__attribute__((target("avx2"))) void chroma_row_avx2(const std::uint8_t* __restrict top,
                                                     const std::uint8_t* __restrict bottom,
                                                     int width, std::uint8_t* __restrict u,
                                                     std::uint8_t* __restrict v) noexcept {
    const __m256i pairs = _mm256_setr_epi8(0, 4, 1, 5, 2, 6, 3, 7, 8, 12, 9, 13, 10, 14, 11, 15, 0,
                                           4, 1, 5, 2, 6, 3, 7, 8, 12, 9, 13, 10, 14, 11, 15);
    const __m256i ones = _mm256_set1_epi8(1);
    const __m256i u_coefficients =
        _mm256_setr_epi16(u_r, u_g, u_b, 0, u_r, u_g, u_b, 0, u_r, u_g, u_b, 0, u_r, u_g, u_b, 0);
    const __m256i v_coefficients =
        _mm256_setr_epi16(v_r, v_g, v_b, 0, v_r, v_g, v_b, 0, v_r, v_g, v_b, 0, v_r, v_g, v_b, 0);
    const __m256i offset = _mm256_set1_epi32(c_offset);
    // After packing, 32-bit group k holds 4 results: lane 0 has u0 u1 u4 u5 | v0 v1 v4 v5, lane 1
    // u2 u3 u6 u7 | v2 v3 v6 v7; gather the groups, then the bytes, into u0..u7 v0..v7.
    const __m256i groups = _mm256_setr_epi32(0, 4, 1, 5, 2, 3, 6, 7);
    const __m128i order = _mm_setr_epi8(0, 1, 4, 5, 2, 3, 6, 7, 8, 9, 12, 13, 10, 11, 14, 15);
    const int samples = width / 2;
    int cx = 0;
    for (; cx + 8 <= samples; cx += 8) {
        const __m256i s0 = block_sums(top + 8 * cx, bottom + 8 * cx, pairs, ones);  // samples 0-3
        const __m256i s1 = block_sums(top + 8 * cx + 32, bottom + 8 * cx + 32, pairs, ones);
        const __m256i us = _mm256_hadd_epi32(_mm256_madd_epi16(s0, u_coefficients),
                                             _mm256_madd_epi16(s1, u_coefficients));
        const __m256i vs = _mm256_hadd_epi32(_mm256_madd_epi16(s0, v_coefficients),
                                             _mm256_madd_epi16(s1, v_coefficients));
        const __m256i uq = _mm256_srai_epi32(_mm256_add_epi32(us, offset), shift + 2);
        const __m256i vq = _mm256_srai_epi32(_mm256_add_epi32(vs, offset), shift + 2);
        const __m256i words = _mm256_packs_epi32(uq, vq);  // 16..240: no saturation
        const __m256i bytes =
            _mm256_permutevar8x32_epi32(_mm256_packus_epi16(words, words), groups);
        const __m128i uv = _mm_shuffle_epi8(_mm256_castsi256_si128(bytes), order);
        _mm_storel_epi64(reinterpret_cast<__m128i*>(u + cx), uv);
        _mm_storel_epi64(reinterpret_cast<__m128i*>(v + cx), _mm_srli_si128(uv, 8));
    }
    chroma_row(top + 8 * cx, bottom + 8 * cx, width - 2 * cx, u + cx, v + cx);
}

bool use_avx2_chroma() noexcept {
    static const bool supported = __builtin_cpu_supports("avx2") != 0;
    return supported;
}
#endif

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
__attribute__((target_clones("avx2", "default")))
#endif
void convert_rows(const std::uint8_t* rgba, std::ptrdiff_t rgba_stride, int width, Yuv420View out,
                  int row_begin, int row_end, bool simd) noexcept {
    for (int row = row_begin; row < row_end; row += 2) {
        const std::uint8_t* top = rgba + row * rgba_stride;
        const std::uint8_t* bottom = top + rgba_stride;
        luma_row(top, width, out.y + row * out.y_stride);
        luma_row(bottom, width, out.y + (row + 1) * out.y_stride);
        std::uint8_t* u = out.u + (row / 2) * out.u_stride;
        std::uint8_t* v = out.v + (row / 2) * out.v_stride;
#ifdef COLLIDE_AVX2_CHROMA
        if (simd) {
            chroma_row_avx2(top, bottom, width, u, v);
            continue;
        }
#endif
        chroma_row(top, bottom, width, u, v);
    }
}

}  // namespace

void rgba_to_yuv420_bt709_rows(const std::uint8_t* rgba, std::ptrdiff_t rgba_stride, int width,
                               Yuv420View out, int row_begin, int row_end) noexcept {
#ifdef COLLIDE_AVX2_CHROMA
    const bool simd = use_avx2_chroma();
#else
    const bool simd = false;
#endif
    convert_rows(rgba, rgba_stride, width, out, row_begin, row_end, simd);
}

void rgba_to_yuv420_bt709_rows_portable(const std::uint8_t* rgba, std::ptrdiff_t rgba_stride,
                                        int width, Yuv420View out, int row_begin,
                                        int row_end) noexcept {
    convert_rows(rgba, rgba_stride, width, out, row_begin, row_end, false);
}

void rgba_to_yuv420_bt709(const std::uint8_t* rgba, std::ptrdiff_t rgba_stride, int width,
                          int height, Yuv420View out) noexcept {
    rgba_to_yuv420_bt709_rows(rgba, rgba_stride, width, out, 0, height);
}

}  // namespace collide::video::detail
