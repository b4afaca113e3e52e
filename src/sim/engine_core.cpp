#include "collide/sim/engine_core.hpp"

#include <limits>

#include "collide/error.hpp"

namespace collide::sim {

void require_forward(double now, double t) {
    if (!(t >= now)) {  // also false for NaN
        throw_scene_error("", 0, "until",
                          "cannot advance to t = " + std::to_string(t) +
                              ": the simulation is at t = " + std::to_string(now) +
                              " and time never runs backwards");
    }
    if (t > std::numeric_limits<double>::max()) {
        throw_scene_error("", 0, "until", "the end time must be finite");
    }
}

}  // namespace collide::sim
