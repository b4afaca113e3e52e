// The collision video's epilogue card: the final figures side by side, and the work ratio in the
// running cost graphic's unit.
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

/// "Event-driven: 13x less work": the two panels' work in the unit of the running cost graphic
/// (pair computations plus queue operations, show::work_done), or "" without both panels (or
/// without work to compare).
std::string footer(const std::vector<SummaryPanel>& panels) {
    const auto time = std::find_if(panels.begin(), panels.end(),
                                   [](const SummaryPanel& p) { return p.time_driven; });
    const auto event = std::find_if(panels.begin(), panels.end(),
                                    [](const SummaryPanel& p) { return !p.time_driven; });
    if (time == panels.end() || event == panels.end()) return "";
    // Several steps compared: the work row is the comparison, one ratio would pick one step.
    if (std::count_if(panels.begin(), panels.end(),
                      [](const SummaryPanel& p) { return p.time_driven; }) > 1)
        return "";
    const std::string ratio =
        work_ratio(work_done(time->measurements, true), work_done(event->measurements, false));
    if (ratio.empty()) return "";
    return fmt::format("Event-driven: {}", ratio);
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
    const bool compared =
        std::any_of(panels.begin(), panels.end(), [](const SummaryPanel& p) { return p.dt > 0.0; });
    for (const SummaryPanel& panel : panels) {
        const Measurements& m = panel.measurements;
        // Beside several "dt = ..." columns the event-driven one is "Event": its colour says
        // the rest, and the four columns keep lesson-size text.
        card.columns.emplace_back(!panel.time_driven
                                      ? std::string(compared ? "Event" : "Event-driven")
                                  : panel.dt > 0.0 ? fmt::format("dt = {}", dt_text(panel.dt))
                                                   : std::string("Time-driven"));
        // The event-driven engine predicts every contact: nothing to miss, no overlap.
        missed.values.push_back(panel.time_driven ? count(m.missed_collisions) : "0");
        overlapping.values.push_back(panel.time_driven ? count(m.overlapping_pairs) : "0");
        left.values.push_back(panel.time_driven ? count(m.escaped) : "0");
        collisions.values.push_back(count(m.collisions_pair + m.collisions_wall));
        // The running cost graphic's unit (show::work_done): the bars named what each side
        // counts, and the footer gives the ratio. Numbers only: with the units ("1.22M pair
        // tests", "14.3k pairs + queue") the two values ran together in a 640-pixel frame.
        cost.values.push_back(short_count(work_done(m, panel.time_driven)));
    }
    card.rows = {missed, overlapping};
    if (walls) card.rows.push_back(left);
    card.rows.push_back(collisions);
    card.rows.push_back(cost);
    card.footer = footer(panels);
    return card;
}

float summary_opacity(double seconds) noexcept {
    constexpr double fade = 0.5;
    return static_cast<float>(std::clamp(seconds / fade, 0.0, 1.0));
}

}  // namespace collide::show
