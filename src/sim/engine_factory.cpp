#include <array>
#include <type_traits>

#include "collide/error.hpp"
#include "collide/named_values.hpp"
#include "collide/sim/classic_engine.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/event.hpp"
#include "collide/sim/fast_engine.hpp"
#include "collide/sim/pq/with_queue.hpp"
#include "collide/sim/time_engine.hpp"
#include "collide/space.hpp"

namespace collide {

namespace {

/// The classic loop on the queue chosen by --pq (every queue kind is compiled in).
template <int D>
std::unique_ptr<EngineOf<D>> make_classic_engine(const typename Space<D>::Scene& scene,
                                                 const EngineOptions& options) {
    return pq::with_queue<sim::Event, pq::Orientation::min, sim::EventLess>(
        options.pq, [&](auto&& queue) -> std::unique_ptr<EngineOf<D>> {
            using Queue = std::decay_t<decltype(queue)>;
            return std::make_unique<sim::BasicClassicEngine<D, Queue>>(scene, std::move(queue));
        });
}

/// The engine named by options.engine, built (the fast engine looks at options.stop while it
/// builds; the others copy the scene, O(N)).
template <int D>
std::unique_ptr<EngineOf<D>> build_engine(const typename Space<D>::Scene& scene,
                                          const EngineOptions& options) {
    switch (options.engine) {
        case EngineKind::fast:
            // Tiny periodic boxes (under three diameters) have no 3^D grid: the O(N) loop is
            // exact there.
            if (!sim::BasicFastEngine<D>::can_simulate(scene))
                return make_classic_engine<D>(scene, EngineOptions{});
            return std::make_unique<sim::BasicFastEngine<D>>(scene, options.stop);
        case EngineKind::classic:
            return make_classic_engine<D>(scene, options);
        case EngineKind::time:
            return std::make_unique<sim::BasicTimeEngine<D>>(scene, options);
    }
    throw_runtime_error("make_engine: no such engine kind");
}

/// make_engine for either dimension: one choice of engine for discs and spheres, stoppable
/// from the start by options.stop.
template <int D>
std::unique_ptr<EngineOf<D>> make_engine_of(const typename Space<D>::Scene& scene,
                                            const EngineOptions& options) {
    std::unique_ptr<EngineOf<D>> engine = build_engine<D>(scene, options);
    engine->set_stop_flag(options.stop);
    return engine;
}

}  // namespace

namespace {

constexpr std::array<NamedValue<EngineKind>, 3> engine_names{
    {{"fast", EngineKind::fast}, {"classic", EngineKind::classic}, {"time", EngineKind::time}}};
constexpr std::array<NamedValue<EngineKind>, 2> event_engine_names{
    {{"fast", EngineKind::fast}, {"classic", EngineKind::classic}}};
constexpr std::array<NamedValue<OverlapDetection>, 2> detection_names{
    {{"all-pairs", OverlapDetection::all_pairs}, {"grid", OverlapDetection::grid}}};

}  // namespace

EngineKind parse_engine_kind(std::string_view text, std::string_view option) {
    return parse_named(text, option, engine_names);
}

EngineKind parse_event_engine_kind(std::string_view text, std::string_view option) {
    return parse_named(text, option, event_engine_names, "an event-driven engine");
}

std::string_view to_string(EngineKind kind) noexcept {
    return name_of(kind, engine_names);
}

OverlapDetection parse_overlap_detection(std::string_view text, std::string_view option) {
    return parse_named(text, option, detection_names);
}

std::string_view to_string(OverlapDetection detection) noexcept {
    return name_of(detection, detection_names);
}

void EngineOptions::validate(std::string_view dt_field) const {
    validate_time_driven_options(*this, dt_field);  // one rule, shared with the engine
}

std::unique_ptr<Engine> make_engine(const Scene& scene, const EngineOptions& options) {
    return make_engine_of<2>(scene, options);
}

std::unique_ptr<SphereEngine> make_engine(const SphereScene& scene, const EngineOptions& options) {
    return make_engine_of<3>(scene, options);
}

}  // namespace collide
