// RenderConfig's checks: no GL here, so that programs that only check
// options and scene hints (`collide check`) link none of the GL libraries (src/app/CMakeLists.txt).
#include <cmath>
#include <string>

#include "collide/error.hpp"
#include "collide/render/renderer.hpp"

namespace collide::render {

// ---------------------------------------------------------------------------------------------
// Config

void RenderConfig::validate() const {
    const auto fail = [](const char* field, const std::string& reason) {
        throw_input_error(std::string("render.") + field + ": " + reason);
    };
    const auto check_side = [&](const char* field, int side) {
        if (side < min_frame_side || side > max_frame_side) {
            fail(field, "must be in [" + std::to_string(min_frame_side) + ", " +
                            std::to_string(max_frame_side) + "], got " + std::to_string(side));
        }
    };
    check_side("width", width);
    check_side("height", height);
    if (!std::isfinite(speed_min) || speed_min < 0.0) fail("speed_min", "must be finite and >= 0");
    if (!std::isfinite(speed_max) || !(speed_max > speed_min)) {
        fail("speed_max", "must be finite and > speed_min");
    }
    if (!std::isfinite(mass_min) || !(mass_min > 0.0)) fail("mass_min", "must be finite and > 0");
    if (!std::isfinite(mass_max) || mass_max < mass_min) {
        fail("mass_max", "must be finite and >= mass_min");
    }
    if (trail_length < 2 || trail_length > 1024) {
        fail("trail_length", "must be in [2, 1024], got " + std::to_string(trail_length));
    }
    if (overlays != OverlayLevel::none && font_path.empty()) {
        fail("font_path", "must name a TrueType font");
    }
}

}  // namespace collide::render
