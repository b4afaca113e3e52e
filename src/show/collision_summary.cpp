// The collision video's epilogue card: the final figures side by side, and the work ratio.
#include "collide/show/collision_summary.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cstdint>

#include "collide/number_text.hpp"
#include "collide/show/collision.hpp"

namespace collide::show {

namespace {

std::string count(std::uint64_t n) {
    return with_separators(static_cast<long long>(n));
}

/// The work a panel did, in its own unit: pair tests (time-driven), queue steps (event-driven).
std::uint64_t work(const SummaryPanel& panel) {
    const Measurements& m = panel.measurements;
    return panel.time_driven ? m.overlap_checks : m.queue.pushes + m.queue.pops;
}

/// "The time-driven side did 286 times the work": the ratio of the two panels' work, or ""
/// without both panels (or without work to compare).
std::string work_ratio(const std::vector<SummaryPanel>& panels) {
    const auto time = std::find_if(panels.begin(), panels.end(),
                                   [](const SummaryPanel& p) { return p.time_driven; });
    const auto event = std::find_if(panels.begin(), panels.end(),
                                    [](const SummaryPanel& p) { return !p.time_driven; });
    if (time == panels.end() || event == panels.end()) return "";
    const auto t = static_cast<double>(work(*time));
    const auto e = static_cast<double>(work(*event));
    if (!(t > 0.0) || !(e > 0.0)) return "";
    if (t >= e) return fmt::format("Time-driven: {:.3g} times the work of the queue", t / e);
    return fmt::format("Event-driven: {:.3g} times the work of the steps", e / t);
}

}  // namespace

SummaryCard summary_card(const std::vector<SummaryPanel>& panels, bool walls,
                         const std::string& time_text) {
    SummaryCard card;
    card.title = fmt::format("In the end, at {}", time_text);
    card.opacity = 1.0F;
    SummaryRow missed{"collisions missed", {}};
    SummaryRow overlapping{"discs overlapping", {}};
    SummaryRow left{"discs that left the box", {}};
    SummaryRow collisions{"collisions", {}};
    SummaryRow cost{"work", {}};
    for (const SummaryPanel& panel : panels) {
        const Measurements& m = panel.measurements;
        card.columns.emplace_back(panel.time_driven ? "Time-driven" : "Event-driven");
        // The event-driven engine predicts every contact: nothing to miss, no overlap.
        missed.values.push_back(panel.time_driven ? count(m.missed_collisions) : "0");
        overlapping.values.push_back(panel.time_driven ? count(m.overlapping_pairs) : "0");
        left.values.push_back(panel.time_driven ? count(m.escaped) : "0");
        collisions.values.push_back(count(m.collisions_pair + m.collisions_wall));
        cost.values.push_back(fmt::format("{} {}", short_count(static_cast<double>(work(panel))),
                                          panel.time_driven ? "pair tests" : "queue steps"));
    }
    card.rows = {missed, overlapping};
    if (walls) card.rows.push_back(left);
    card.rows.push_back(collisions);
    card.rows.push_back(cost);
    card.footer = work_ratio(panels);
    return card;
}

float summary_opacity(double seconds) noexcept {
    constexpr double fade = 0.5;
    return static_cast<float>(std::clamp(seconds / fade, 0.0, 1.0));
}

}  // namespace collide::show
