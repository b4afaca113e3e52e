#include "collide/error.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/time_engine.hpp"

namespace collide {

std::unique_ptr<Engine> make_engine(const Scene& scene, const EngineOptions& options) {
    // Each engine adds its branch here as it lands.
    if (options.engine == "time") return std::make_unique<TimeEngine>(scene, options);
    throw_input_error("--engine", 0, "", "unknown engine '" + options.engine + "'");
}

}  // namespace collide
