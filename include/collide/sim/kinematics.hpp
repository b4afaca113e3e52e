#pragma once
/// \file
/// The lecture's collision kernels as pure functions on values. "Never" is +infinity.
/// Shared by every engine (classic, fast, time-driven) so that they resolve collisions
/// identically and can be compared event by event. The pair kernels are the lecture's formulas
/// (dv.dr, d, J) in any dimension: templates over the vector type (Vec2 discs, Vec3 spheres).

#include <cmath>
#include <limits>

#include "collide/vec2.hpp"
#include "collide/vec3.hpp"

namespace collide::kinematics {

/// The time of an event that will not happen.
inline constexpr double never = std::numeric_limits<double>::infinity();

/// Time until a disc (position p, speed v along one axis, radius r) touches the wall at 0 or at
/// `extent` on that axis: (extent - r - p)/v for v > 0, (r - p)/v for v < 0, never for v == 0.
/// A disc already touching or past the wall it moves towards collides now (0), never in the past:
/// algs4 returns negative times here and lets its clock run backwards.
[[nodiscard]] inline double time_to_wall(double p, double v, double r, double extent) noexcept {
    if (v > 0.0) return std::fmax(0.0, (extent - r - p) / v);
    if (v < 0.0) return std::fmax(0.0, (r - p) / v);
    return never;
}

/// Time until two discs at separation dr = r_j - r_i with relative velocity dv = v_j - v_i touch
/// (sigma = r_i + r_j). With b = dv.dr, a = dv.dv, c = dr.dr - sigma^2 and d = b^2 - a c:
/// never when b >= 0 (separating) or d < 0 (missing); else -(b + sqrt d) / a.
/// Pairs that already overlap while approaching (c < 0, b < 0) collide now (0): algs4 predicts a
/// negative time for them and never resolves the overlap.
/// Always inlined: the classic loop calls it for every disc, and GCC -O2 otherwise leaves it out
/// of line there, where passing the vectors through the stack costs more than the kernel.
template <class Vec = Vec2>
[[nodiscard, gnu::always_inline]] inline double time_to_hit(Vec dr, Vec dv, double sigma) noexcept {
    const double b = dot(dv, dr);
    const double a = dot(dv, dv);
    const double c = dot(dr, dr) - sigma * sigma;
    const double d = b * b - a * c;
    // One test for "never" after computing d, not one per quantity: most pairs never meet, so
    // this branch goes the same way nearly every time, where "b >= 0" alone is a coin toss per
    // pair (half of all pairs separate) and mispredicting it costs more than computing d.
    if ((b >= 0.0) | ((c > 0.0) & (d < 0.0))) return never;
    if (c <= 0.0) return 0.0;
    // Citardauq form: c / (-b + sqrt d) equals -(b + sqrt d)/a but does not cancel when a is tiny.
    return c / (-b + std::sqrt(d));
}

/// The impulse exchanged by two touching discs: the vector J added to momentum of disc i
/// (disc j receives -J). Along the line of centres, magnitude 2 m_i m_j (dv.dr) / (|dr| (m_i+m_j)).
/// Uses the actual centre distance |dr| rather than sigma, so the impulse stays normal even when
/// floating-point leaves the pair a hair apart or overlapping.
template <class Vec = Vec2>
[[nodiscard]] inline Vec pair_impulse(Vec dr, Vec dv, double mi, double mj) noexcept {
    const double dist2 = dot(dr, dr);
    if (dist2 <= 0.0) return {};
    const double j_over_dist = 2.0 * mi * mj * dot(dv, dr) / ((mi + mj) * dist2);
    return j_over_dist * dr;
}

/// Elastic pair collision: updates both velocities in place and returns the impulse on disc i
/// (for the collision virial: r_ij . dp_i). dr = r_j - r_i, at contact.
template <class Vec = Vec2>
inline Vec resolve_pair(Vec& vi, Vec& vj, double mi, double mj, Vec dr) noexcept {
    const Vec impulse = pair_impulse(dr, vj - vi, mi, mj);
    vi += (1.0 / mi) * impulse;
    vj -= (1.0 / mj) * impulse;
    return impulse;
}

}  // namespace collide::kinematics
