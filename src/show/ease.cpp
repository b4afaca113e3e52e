#include "collide/show/ease.hpp"

#include <algorithm>

namespace collide::show {

float ease(double x) noexcept {
    const double t = std::clamp(x, 0.0, 1.0);
    return static_cast<float>(t * t * (3.0 - 2.0 * t));
}

}  // namespace collide::show
