#include "collide/error.hpp"
#include "collide/sim/classic_engine.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/event.hpp"
#include "collide/sim/fast_engine.hpp"
#include "collide/sim/pq/dary_heap.hpp"

namespace collide {

namespace {

std::unique_ptr<Engine> make_classic_engine(const Scene& scene, const EngineOptions& options) {
    if (options.pq != "binary") {
        throw_input_error("--pq", 0, "", "unknown queue kind '" + options.pq + "'");
    }
    using Queue = pq::DaryHeap<sim::Event, pq::Orientation::min, 2, sim::EventLess>;
    return std::make_unique<sim::ClassicEngine<Queue>>(scene);
}

}  // namespace

std::unique_ptr<Engine> make_engine(const Scene& scene, const EngineOptions& options) {
    if (options.engine == "fast") return std::make_unique<sim::FastEngine>(scene);
    if (options.engine == "classic") return make_classic_engine(scene, options);
    // Each engine adds its branch here as it lands.
    throw_input_error("--engine", 0, "", "unknown engine '" + options.engine + "'");
}

}  // namespace collide
