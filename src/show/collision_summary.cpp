// The collision video's epilogue card: the final figures of each panel, the work ratio in the
// running cost graphic's unit, and why the collision counts differ when they do.
#include "collide/show/collision_summary.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cstdint>
#include <utility>

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

std::uint64_t collisions_of(const Measurements& m) {
    return m.collisions_pair + m.collisions_wall;
}

/// The two engines of a video that compares them once (one time-driven panel, one
/// event-driven), or nulls.
std::pair<const SummaryPanel*, const SummaryPanel*> compared_pair(
    const std::vector<SummaryPanel>& panels) {
    const SummaryPanel* time = nullptr;
    const SummaryPanel* event = nullptr;
    std::size_t times = 0;
    for (const SummaryPanel& p : panels) {
        if (p.time_driven) {
            time = &p;
            ++times;
        } else {
            event = &p;
        }
    }
    if (times != 1 || event == nullptr) return {nullptr, nullptr};
    return {time, event};
}

/// The time-driven run's failures that changed its count: collisions stepped over and discs
/// that went through a wall.
std::uint64_t failures_of(const Measurements& m) {
    return m.missed_collisions + m.escaped;
}

}  // namespace

std::string count_difference_note(const std::vector<SummaryPanel>& panels) {
    const auto [time, event] = compared_pair(panels);
    if (time == nullptr) return "";
    const Measurements& t = time->measurements;
    if (collisions_of(t) == collisions_of(event->measurements)) return "";
    if (failures_of(t) == 0) return "None missed: late fixes sent the runs apart (chaos)";
    return "Each miss sent the runs on other paths: the counts differ";
}

std::string epilogue_caption(const std::vector<SummaryPanel>& panels) {
    const auto [time, event] = compared_pair(panels);
    if (time == nullptr) {
        if (panels.size() == 1) return "In the end: the final figures";
        return "In the end: the final figures of each step";
    }
    const Measurements& t = time->measurements;
    if (collisions_of(t) == collisions_of(event->measurements))
        return "In the end: both methods counted the same collisions";
    if (failures_of(t) == 0) return "Counts differ with none missed: the runs took other paths";
    const std::uint64_t missed = t.missed_collisions;
    if (missed == 0) return "Discs went through a wall: the runs took different paths";
    return fmt::format("Time-driven missed {}: the runs took different paths", count(missed));
}

SummaryCard summary_card(const std::vector<SummaryPanel>& panels, bool walls,
                         const std::string& time_text, bool spheres) {
    SummaryCard card;
    card.title = fmt::format("In the end, at {}", time_text);
    card.opacity = 1.0F;
    SummaryRow missed{"collisions missed", {}};
    const std::string bodies = spheres ? "spheres" : "discs";
    // "ever": beside the panel's live "0 overlapping" at the end, "that overlapped" read as a
    // contradiction (issue 44); the card counts every one seen overlapping in any frame.
    SummaryRow overlapping{bodies + " that ever overlapped", {}};
    // Through a wall or through a barrier of immovable discs: the lessons' word, "tunnelled".
    SummaryRow tunnelled{bodies + " that tunnelled", {}};
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
        // Every disc seen overlapping in any frame, not only at the end: the break of a rack
        // overlaps six discs for a few frames, and the card must not say 0.
        overlapping.values.push_back(panel.time_driven ? count(m.discs_overlapped) : "0");
        tunnelled.values.push_back(panel.time_driven ? count(tunnelled_discs(m, walls)) : "0");
        collisions.values.push_back(count(m.collisions_pair + m.collisions_wall));
        // The running cost graphic's unit (show::work_done): the bars named what each side
        // counts, and the footer gives the ratio. Numbers only: with the units ("1.22M pair
        // tests", "14,300 pairs + queue") the two values ran together in a 640-pixel frame.
        cost.values.push_back(count_text(work_done(m, panel.time_driven)));
    }
    card.rows = {missed, overlapping};
    // A walled box always says it (nothing tunnelled is a result); a periodic one once any disc
    // went through a barrier.
    const bool any_tunnelled = std::any_of(panels.begin(), panels.end(), [](const SummaryPanel& p) {
        return p.time_driven && p.measurements.tunnelled > 0;
    });
    if (walls || any_tunnelled) card.rows.push_back(tunnelled);
    card.rows.push_back(collisions);
    card.rows.push_back(cost);
    card.footer = footer(panels);
    card.note = count_difference_note(panels);
    return card;
}

float summary_opacity(double seconds) noexcept {
    constexpr double fade = 0.5;
    return static_cast<float>(std::clamp(seconds / fade, 0.0, 1.0));
}

}  // namespace collide::show
