#include "measurements_report.hpp"

#include <fmt/core.h>

#include <variant>

#include "json_output.hpp"

namespace collide::app {

std::vector<ReportField> report_fields(const Measurements& m) {
    return {
        {"t", m.t},
        {"events", m.events},
        {"collisions", m.collisions_pair + m.collisions_wall},
        {"collisions_pair", m.collisions_pair},
        {"collisions_wall", m.collisions_wall},
        {"collisions_xwall", m.collisions_xwall},
        {"collisions_ywall", m.collisions_ywall},
        {"cell_crossings", m.cell_crossings},
        {"list_rebuilds", m.list_rebuilds},
        {"predictions", m.predictions},
        {"pq_pushes", m.queue.pushes},
        {"pq_pops", m.queue.pops},
        {"pq_updates", m.queue.updates},
        {"stale_events", m.queue.stale_pops},
        {"pq_max_size", m.queue.max_size},
        {"kinetic_energy", m.kinetic_energy},
        {"momentum_x", m.momentum.x},
        {"momentum_y", m.momentum.y},
        {"temperature", m.temperature},
        {"pressure", m.pressure},
        {"compressibility", m.compressibility},
        {"packing_fraction", m.packing_fraction},
        {"max_overlap", m.max_overlap},
        {"msd", m.msd},
        {"wall_seconds", m.wall_seconds},
        {"collisions_per_second", m.collisions_per_second},
        {"engine_bytes", m.engine_bytes},
        {"overlap_checks", m.overlap_checks},
        {"missed_collisions", m.missed_collisions},
        {"escaped", m.escaped},
        {"overlapping_pairs", m.overlapping_pairs},
        {"energy_drift", m.energy_drift},
        {"steps", m.steps},
        {"max_overlap_seen", m.max_overlap_seen},
        {"seconds_per_time_unit", m.seconds_per_time_unit},
    };
}

namespace {

/// Shortest round-trip representation of numbers.
std::string value_text(const ReportField& field) {
    if (const auto* count = std::get_if<std::uint64_t>(&field.value)) return std::to_string(*count);
    if (const auto* real = std::get_if<double>(&field.value)) return fmt::format("{}", *real);
    return std::get<std::string>(field.value);
}

}  // namespace

std::string format_text(const std::vector<ReportField>& fields) {
    std::string out;
    for (const ReportField& f : fields) out += f.key + ": " + value_text(f) + '\n';
    return out;
}

std::string format_json(const std::vector<ReportField>& fields) {
    Json object = Json::object();
    for (const ReportField& f : fields) {
        std::visit([&](const auto& value) { object[f.key] = value; }, f.value);
    }
    return json_text(object);
}

}  // namespace collide::app
