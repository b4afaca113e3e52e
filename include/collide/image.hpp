#pragma once
/// \file
/// An RGBA8 image, rows top-down: what the renderer produces and the encoders consume.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace collide {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  ///< width * height * 4 bytes, row 0 is the top row

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * h * 4, 0) {}
    [[nodiscard]] std::size_t stride() const noexcept {
        return static_cast<std::size_t>(width) * 4;
    }
    [[nodiscard]] std::uint8_t* pixel(int x, int y) noexcept {
        return rgba.data() + static_cast<std::size_t>(y) * stride() +
               static_cast<std::size_t>(x) * 4;
    }
    [[nodiscard]] const std::uint8_t* pixel(int x, int y) const noexcept {
        return rgba.data() + static_cast<std::size_t>(y) * stride() +
               static_cast<std::size_t>(x) * 4;
    }
};

}  // namespace collide
