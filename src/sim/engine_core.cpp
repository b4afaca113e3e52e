#include "collide/sim/engine_core.hpp"

#include <limits>

#include "collide/error.hpp"

namespace collide::sim {

Appearance::Appearance(const Scene& scene) {
    colors.reserve(scene.discs.size());
    tagged.reserve(scene.discs.size());
    for (const Disc& d : scene.discs) {
        colors.push_back(d.color);
        tagged.push_back(d.tag.empty() ? 0 : 1);
        any_tagged = any_tagged || !d.tag.empty();
    }
}

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

EngineCore::EngineCore(const Scene& scene) : box_(scene.box), appearance_(scene) {}

Snapshot EngineCore::start_snapshot(double t) const {
    Snapshot s;
    s.time = t;
    s.box = box_;
    s.discs.resize(appearance_.colors.size());
    for (std::size_t k = 0; k < s.discs.size(); ++k) {
        s.discs[k].color = appearance_.colors[k];
        s.discs[k].tagged = appearance_.tagged[k] != 0;
    }
    return s;
}

Measurements EngineCore::measurements(double t, const std::vector<Vec2>& velocities,
                                      const std::vector<double>& masses,
                                      const std::vector<double>& radii,
                                      std::uint64_t engine_bytes) const {
    const EngineCounters& c = counters_;
    Measurements m;
    m.t = t;
    m.collisions_pair = c.collisions_pair;
    m.collisions_xwall = c.collisions_xwall;
    m.collisions_ywall = c.collisions_ywall;
    m.collisions_wall = c.collisions_xwall + c.collisions_ywall;
    m.cell_crossings = c.cell_crossings;
    m.events = m.collisions_pair + m.collisions_wall + m.cell_crossings;
    m.predictions = c.predictions;
    m.queue = c.queue;
    fill_thermodynamics(m, velocities, masses, radii, box_, c.impulses);
    m.wall_seconds = c.wall_seconds;
    if (c.wall_seconds > 0.0) {
        m.collisions_per_second =
            static_cast<double>(m.collisions_pair + m.collisions_wall) / c.wall_seconds;
    }
    m.engine_bytes = engine_bytes;
    return m;
}

}  // namespace collide::sim
