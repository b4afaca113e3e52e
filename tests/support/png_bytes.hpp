#pragma once
// Shared by the test suites: the bytes of hand-made PNG files, for the readers' refusals.

#include <cstdint>
#include <string>

namespace collide::test {

/// The bytes of a PNG that is nothing but its signature, a header chunk for a `width` x `height`
/// 1-bit grey image and an end chunk (CRCs zero: the reader must refuse it by its header, before
/// anything would be decoded).
inline std::string png_header_only(std::uint32_t width, std::uint32_t height) {
    std::string bytes("\x89PNG\r\n\x1a\n", 8);
    const auto be32 = [&](std::uint32_t v) {
        for (int shift = 24; shift >= 0; shift -= 8)
            bytes += static_cast<char>((v >> shift) & 0xff);
    };
    be32(13);
    bytes += "IHDR";
    be32(width);
    be32(height);
    bytes +=
        std::string("\x01\x00\x00\x00\x00", 5);  // 1 bit, grey, deflate, no filter, no interlace
    be32(0);
    be32(0);
    bytes += "IEND";
    be32(0);
    return bytes;
}

}  // namespace collide::test
