#pragma once
/// \file
/// A 3D vector of doubles: sphere positions (box units) and velocities (box units per time unit).
/// The same operations as Vec2, so that the kinematics and the engines are written once for both
/// (collide/space.hpp).

#include <cmath>

namespace collide {

struct Vec3 {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;

    constexpr Vec3& operator+=(Vec3 o) noexcept {
        x += o.x;
        y += o.y;
        z += o.z;
        return *this;
    }
    constexpr Vec3& operator-=(Vec3 o) noexcept {
        x -= o.x;
        y -= o.y;
        z -= o.z;
        return *this;
    }
    constexpr Vec3& operator*=(double s) noexcept {
        x *= s;
        y *= s;
        z *= s;
        return *this;
    }
    friend constexpr Vec3 operator+(Vec3 a, Vec3 b) noexcept {
        return {a.x + b.x, a.y + b.y, a.z + b.z};
    }
    friend constexpr Vec3 operator-(Vec3 a, Vec3 b) noexcept {
        return {a.x - b.x, a.y - b.y, a.z - b.z};
    }
    friend constexpr Vec3 operator-(Vec3 a) noexcept { return {-a.x, -a.y, -a.z}; }
    friend constexpr Vec3 operator*(double s, Vec3 a) noexcept {
        return {s * a.x, s * a.y, s * a.z};
    }
    friend constexpr Vec3 operator*(Vec3 a, double s) noexcept {
        return {s * a.x, s * a.y, s * a.z};
    }
    friend constexpr bool operator==(Vec3 a, Vec3 b) noexcept = default;
};

[[nodiscard]] constexpr double dot(Vec3 a, Vec3 b) noexcept {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
[[nodiscard]] constexpr double norm2(Vec3 a) noexcept {
    return dot(a, a);
}
[[nodiscard]] inline double norm(Vec3 a) noexcept {
    return std::sqrt(norm2(a));
}

}  // namespace collide
