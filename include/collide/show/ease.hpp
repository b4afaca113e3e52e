#pragma once
/// \file
/// Motion shared by the videos' programs: how a slide or a fade moves over its part of a step.

namespace collide::show {

/// Smooth start and stop of a slide: 0 at 0, 1 at 1, flat at both ends (smoothstep); `x` is
/// clamped to [0, 1].
[[nodiscard]] float ease(double x) noexcept;

}  // namespace collide::show
