#pragma once
/// \file
/// A 2D vector of doubles: positions (box units) and velocities (box units per time unit).

#include <cmath>

namespace collide {

struct Vec2 {
    double x = 0.0;
    double y = 0.0;

    constexpr Vec2& operator+=(Vec2 o) noexcept {
        x += o.x;
        y += o.y;
        return *this;
    }
    constexpr Vec2& operator-=(Vec2 o) noexcept {
        x -= o.x;
        y -= o.y;
        return *this;
    }
    constexpr Vec2& operator*=(double s) noexcept {
        x *= s;
        y *= s;
        return *this;
    }
    friend constexpr Vec2 operator+(Vec2 a, Vec2 b) noexcept { return {a.x + b.x, a.y + b.y}; }
    friend constexpr Vec2 operator-(Vec2 a, Vec2 b) noexcept { return {a.x - b.x, a.y - b.y}; }
    friend constexpr Vec2 operator-(Vec2 a) noexcept { return {-a.x, -a.y}; }
    friend constexpr Vec2 operator*(double s, Vec2 a) noexcept { return {s * a.x, s * a.y}; }
    friend constexpr Vec2 operator*(Vec2 a, double s) noexcept { return {s * a.x, s * a.y}; }
    friend constexpr bool operator==(Vec2 a, Vec2 b) noexcept = default;
};

[[nodiscard]] constexpr double dot(Vec2 a, Vec2 b) noexcept {
    return a.x * b.x + a.y * b.y;
}
[[nodiscard]] constexpr double norm2(Vec2 a) noexcept {
    return dot(a, a);
}
[[nodiscard]] inline double norm(Vec2 a) noexcept {
    return std::sqrt(norm2(a));
}

}  // namespace collide
