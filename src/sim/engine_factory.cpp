#include <type_traits>

#include "collide/error.hpp"
#include "collide/sim/classic_engine.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/event.hpp"
#include "collide/sim/fast_engine.hpp"
#include "collide/sim/pq/queue_kind.hpp"
#include "collide/sim/time_engine.hpp"

namespace collide {

namespace {

/// The classic loop on the queue named by --pq (every queue kind is compiled in).
std::unique_ptr<Engine> make_classic_engine(const Scene& scene, const EngineOptions& options) {
    const pq::QueueKind kind = pq::parse_queue_kind(options.pq, "--pq");
    return pq::with_queue<sim::Event, pq::Orientation::min, sim::EventLess>(
        kind, [&](auto&& queue) -> std::unique_ptr<Engine> {
            using Queue = std::decay_t<decltype(queue)>;
            return std::make_unique<sim::ClassicEngine<Queue>>(scene, std::move(queue));
        });
}

}  // namespace

void EngineOptions::validate() const {
    if (engine != "fast" && engine != "classic" && engine != "time") {
        throw_input_error("--engine", 0, "",
                          "unknown engine '" + engine + "' (expected fast|classic|time)");
    }
    (void)pq::parse_queue_kind(pq, "--pq");
    validate_time_driven_options(*this);  // --dt, --td-detect: one rule, shared with the engine
}

std::unique_ptr<Engine> make_engine(const Scene& scene, const EngineOptions& options) {
    if (options.engine == "fast") {
        // Tiny periodic boxes (under three diameters) have no 3 x 3 grid: the O(N) loop is exact
        // there.
        if (!sim::FastEngine::can_simulate(scene))
            return make_classic_engine(scene, EngineOptions{});
        return std::make_unique<sim::FastEngine>(scene);
    }
    if (options.engine == "classic") return make_classic_engine(scene, options);
    if (options.engine == "time") return std::make_unique<sim::TimeEngine>(scene, options);
    throw_input_error("--engine", 0, "", "unknown engine '" + options.engine + "'");
}

}  // namespace collide
