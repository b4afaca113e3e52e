#include <cmath>
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
        throw_input_error("--engine", 0, "", "unknown engine '" + engine + "' (expected fast|classic|time)");
    }
    (void)pq::parse_queue_kind(pq, "--pq");
    if (!(dt > 0.0) || !std::isfinite(dt)) {
        throw_input_error("--dt", 0, "", "the time step must be a positive finite number");
    }
    if (td_detect != "all-pairs" && td_detect != "grid") {
        throw_input_error("--td-detect", 0, "", "unknown detection '" + td_detect + "' (expected all-pairs|grid)");
    }
}

std::unique_ptr<Engine> make_engine(const Scene& scene, const EngineOptions& options) {
    if (options.engine == "fast") {
        // Tiny periodic boxes (under three diameters) have no 3 x 3 grid: the O(N) loop is exact there.
        if (!sim::FastEngine::can_simulate(scene)) return make_classic_engine(scene, EngineOptions{});
        return std::make_unique<sim::FastEngine>(scene);
    }
    if (options.engine == "classic") return make_classic_engine(scene, options);
    if (options.engine == "time") return std::make_unique<TimeEngine>(scene, options);
    throw_input_error("--engine", 0, "", "unknown engine '" + options.engine + "'");
}

}  // namespace collide
