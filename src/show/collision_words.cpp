// The collision video's words: titles, counters, figures, the compact line, the cost graphic's
// label, the step note and the energy line.
#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "collide/number_text.hpp"
#include "collide/show/collision.hpp"
#include "collide/show/plot_words.hpp"
#include "collide/sim/pq/queue_kind.hpp"

namespace collide::show {

std::string dt_text(double dt) {
    std::string decimal = fmt::format("{:.3g}", dt);
    if (!(std::isfinite(dt) && dt > 0.0)) return decimal;
    // Exact in three digits (0.05, 0.0125): as written.
    if (std::abs(std::strtod(decimal.c_str(), nullptr) - dt) <= 1e-9 * dt) return decimal;
    // A whole fraction with a small denominator (the default dt = speed / 30): 1/30, 2/75.
    constexpr int largest_denominator = 1000;
    for (int q = 2; q <= largest_denominator; ++q) {
        const double p = dt * q;
        const double whole = std::round(p);
        if (whole >= 1.0 && whole < 1000.0 && std::abs(p - whole) <= 1e-9 * p)
            return fmt::format("{:.0f}/{}", whole, q);
    }
    return decimal;
}

std::string time_lesson_title(double dt) {
    return fmt::format("Time-driven: steps of dt = {}", dt_text(dt));
}

std::string event_lesson_title(const EngineOptions& options) {
    if (options.engine == EngineKind::classic)
        return fmt::format("Event-driven: queue ({})", pq::to_string(options.pq));
    return "Event-driven: priority queue";
}

std::string time_panel_title(double dt) {
    return fmt::format("Time-driven, dt = {}", dt_text(dt));
}

std::string event_panel_title(const EngineOptions& options) {
    if (options.engine == EngineKind::classic)
        return fmt::format("Event-driven (priority queue: {})", pq::to_string(options.pq));
    return "Event-driven (priority queue)";
}

std::string panel_title(bool time_driven, OverlayLevel level, const EngineOptions& options,
                        bool beside_code) {
    const bool lesson = level == OverlayLevel::lesson;
    if (lesson && beside_code)
        return time_driven ? fmt::format("Time-driven: dt = {}", dt_text(options.dt))
                           : std::string("Event-driven");
    if (time_driven) return lesson ? time_lesson_title(options.dt) : time_panel_title(options.dt);
    return lesson ? event_lesson_title(options) : event_panel_title(options);
}

std::string compared_step_title(double dt, OverlayLevel /*level*/) {
    // The lesson's "Time-driven: steps of dt = ..." is too long for a third of the frame; the
    // comparison is the subject, so every level names the step the same short way.
    return time_panel_title(dt);
}

std::string compared_step_short_title(double dt) {
    return fmt::format("dt = {}", dt_text(dt));
}

std::string compared_cost_label(double dt) {
    return fmt::format("dt = {}", dt_text(dt));
}

namespace {
/// The largest number of steps in "Moves on q of every p frames": beyond it the pattern is too
/// long to see, and the note says "about".
constexpr int largest_step_pattern = 12;
}  // namespace

std::string step_note(double dt, double frame_interval) {
    if (!(dt > frame_interval * (1.0 + divide_tolerance))) return {};
    const double frames = dt / frame_interval;
    if (divides(frame_interval, dt)) {
        const long n = std::lround(frames);
        const char* suffix = n % 10 == 2 && n % 100 != 12   ? "nd"
                             : n % 10 == 3 && n % 100 != 13 ? "rd"
                                                            : "th";
        return fmt::format("Moves only every {}{} frame", n, suffix);
    }
    // q steps take p frames: the state changes on q of every p frames (1.5 frames a step: on
    // 2 of every 3).
    for (int q = 2; q <= largest_step_pattern; ++q) {
        const double p = frames * q;
        if (std::abs(p - std::round(p)) <= divide_tolerance * p)
            return fmt::format("Moves on {} of every {:.0f} frames", q, std::round(p));
    }
    return fmt::format("Moves about once every {:.2g} frames", frames);
}

int whole_frames_per_step(double dt, double frame_interval) noexcept {
    if (!(dt > frame_interval * (1.0 + divide_tolerance)) || !divides(frame_interval, dt)) return 1;
    const double frames = std::round(dt / frame_interval);
    return frames < 1e6 ? static_cast<int>(frames) : 1;
}

std::string short_count(double value) {
    return collide::count_text(value);
}

std::vector<std::string> time_driven_counters(const Measurements& m, double energy_drift) {
    // Short "label  value" pairs: the renderer lays them out in a grid of narrow columns.
    return {
        fmt::format("steps  {}", short_count(static_cast<double>(m.steps))),
        fmt::format("checks  {}", short_count(static_cast<double>(m.overlap_checks))),
        fmt::format("collisions  {}",
                    short_count(static_cast<double>(m.collisions_pair + m.collisions_wall))),
        fmt::format("overlaps now  {}", short_count(static_cast<double>(m.overlapping_pairs))),
        fmt::format("deepest  {:.2g}", m.max_overlap),
        fmt::format("missed  {}", short_count(static_cast<double>(m.missed_collisions))),
        fmt::format("escaped  {}", short_count(static_cast<double>(m.escaped))),
        fmt::format("energy drift  {:+.1e}", energy_drift),
        fmt::format("checks/time  {}",
                    m.t > 0.0 ? short_count(static_cast<double>(m.overlap_checks) / m.t) : "-"),
    };
}

std::vector<std::string> event_driven_counters(const Measurements& m, double energy_drift) {
    const std::uint64_t queue_ops = m.queue.pushes + m.queue.pops + m.queue.updates;
    const double stale_share = m.queue.pops > 0 ? 100.0 * static_cast<double>(m.queue.stale_pops) /
                                                      static_cast<double>(m.queue.pops)
                                                : 0.0;
    const double work = work_done(m, false);
    return {
        fmt::format("events  {}", short_count(static_cast<double>(m.events))),
        fmt::format("collisions  {}",
                    short_count(static_cast<double>(m.collisions_pair + m.collisions_wall))),
        fmt::format("predictions  {}", short_count(static_cast<double>(m.predictions))),
        fmt::format("queue ops  {}", short_count(static_cast<double>(queue_ops))),
        fmt::format("queue max  {}", short_count(static_cast<double>(m.queue.max_size))),
        fmt::format("stale pops  {:.0f}%", stale_share),
        fmt::format("overlaps now  {}", m.max_overlap > 0.0 ? "yes" : "0"),
        fmt::format("energy drift  {:+.1e}", energy_drift),
        fmt::format("ops/time  {}", m.t > 0.0 ? short_count(work / m.t) : "-"),
    };
}

namespace {
std::string count_text(std::uint64_t n) {
    return with_separators(static_cast<long long>(n));
}

/// "collisions", or "collision" beside a 1: the figure reads "1 collision".
const char* collisions_word(std::uint64_t n) {
    return n == 1 ? "collision" : "collisions";
}
}  // namespace

std::uint64_t tunnelled_discs(const Measurements& m, bool walls) noexcept {
    return std::max(m.tunnelled, walls ? m.escaped : std::uint64_t{0});
}

std::vector<Figure> time_driven_figures(const Measurements& m, bool walls) {
    std::vector<Figure> out = {
        {count_text(m.missed_collisions), "missed", true},
        {count_text(m.overlapping_pairs), "overlapping", true},
    };
    // Discs through a wall (they left the box) or through a barrier of immovable discs: one
    // figure, in the word the lessons teach.
    const std::uint64_t through = tunnelled_discs(m, walls);
    if (through > 0) out.push_back({count_text(through), "tunnelled", true});
    const std::uint64_t collisions = m.collisions_pair + m.collisions_wall;
    out.push_back({count_text(collisions), collisions_word(collisions), false});
    return out;
}

std::vector<Figure> event_driven_figures(const Measurements& m) {
    const std::uint64_t collisions = m.collisions_pair + m.collisions_wall;
    return {
        {count_text(collisions), collisions_word(collisions), false},
        {"0", "missed", true},
    };
}

std::string energy_line(const std::vector<EngineDrift>& panels) {
    if (panels.empty()) return {};
    const auto conserved = [](const EngineDrift& d) { return d.largest <= round_off_drift; };
    if (panels.size() == 1)
        return conserved(panels[0]) ? "Energy conserved" : "Energy not conserved";
    std::size_t kept = 0;
    for (const EngineDrift& d : panels) kept += conserved(d) ? 1 : 0;
    const bool two = panels.size() == 2;
    if (kept == panels.size()) return two ? "Both conserve energy" : "All conserve energy";
    if (kept == 0) return two ? "Neither conserves energy" : "None conserves energy";
    for (const EngineDrift& d : panels) {
        if (!conserved(d))
            return d.time_driven ? "Time-driven: energy drifts" : "Event-driven: energy drifts";
    }
    return {};
}

double work_done(const Measurements& m, bool time_driven) noexcept {
    const auto n = [](std::uint64_t count) { return static_cast<double>(count); };
    if (time_driven) return n(m.overlap_checks) + n(m.predictions);
    return n(m.predictions) + n(m.queue.pushes) + n(m.queue.pops) + n(m.queue.updates);
}

std::string time_driven_work_line(const Measurements& m) {
    // The parts are work_done's (time_driven): the overlap checks and the roll-backs' contact
    // times (predictions).
    return fmt::format("{} {}: {} overlap checks + {} contact-time computations",
                       cost_text(work_done(m, true)), time_driven_cost_label,
                       short_count(static_cast<double>(m.overlap_checks)),
                       short_count(static_cast<double>(m.predictions)));
}

std::string work_ratio(double time_work, double event_work) {
    if (!(time_work > 0.0) || !(event_work > 0.0)) return {};
    const bool less = time_work >= event_work;
    const double ratio = less ? time_work / event_work : event_work / time_work;
    const std::string times =
        ratio < 9.95 ? fmt::format("{:.2g}", ratio) : fmt::format("{:.0f}", ratio);
    if (times == "1") return "the same work";
    return fmt::format("{}x {} work", times, less ? "less" : "more");
}

namespace {
/// Why an engine's work grows as it does, in a line under its figures.
std::string how_it_works(bool time_driven, EngineKind engine) {
    if (time_driven) return "Each step: all N\u00b2/2 pairs";
    if (engine == EngineKind::classic) return "Each event: 2N pairs, log N queue";
    return "Each event: a few pairs, log N queue";
}
}  // namespace

PanelWords panel_words(const Measurements& m, bool time_driven, bool walls, double drift,
                       EngineKind engine) {
    PanelWords out;
    out.cost = work_done(m, time_driven);
    out.cost_text = cost_text(out.cost);
    out.cost_words = cost_in_words(out.cost);
    out.how = how_it_works(time_driven, engine);
    if (time_driven) {
        out.counters = time_driven_counters(m, drift);
        out.figures = time_driven_figures(m, walls);
        out.compact_line = fmt::format("{} missed", count_text(m.missed_collisions));
        out.cost_label = time_driven_cost_label;
    } else {
        out.counters = event_driven_counters(m, drift);
        out.figures = event_driven_figures(m);
        out.compact_line =
            fmt::format("{} collisions", count_text(m.collisions_pair + m.collisions_wall));
        out.cost_label = "pairs + queue";
    }
    return out;
}

ColorKeyWords color_key(ColorMode mode, double speed_min, double speed_max, double mass_min,
                        double mass_max) {
    // Three significant digits, as printf's %.3g writes them ("1.5", "0.001", "1e+04").
    const auto value = [](double v) {
        char text[32];
        std::snprintf(text, sizeof text, "%.3g", v);
        return std::string(text);
    };
    ColorKeyWords out;
    switch (mode) {
        case ColorMode::speed:
            out = {"slow", "fast", "speed", value(speed_min), value(speed_max), ""};
            break;
        case ColorMode::mass:
            out = {"light", "heavy", "mass (log)", value(mass_min), value(mass_max), ""};
            break;
        case ColorMode::tag:
            out.tagged = "tagged";
            break;
        case ColorMode::scene:
            break;
    }
    return out;
}

QueueViewLimits queue_picture(std::size_t next_events) noexcept {
    QueueViewLimits limits;
    limits.next_events = next_events;
    limits.tree_level_nodes = queue_tree_level_nodes;
    limits.tree_levels = queue_tree_levels;
    limits.array_slots = queue_array_slots;
    return limits;
}

namespace {

/// "3-7", "5 wall", "5 cell": what an event involves, in the fewest characters.
std::string event_label(const QueuedEvent& e) {
    switch (e.kind) {
        case EventKind::pair:
            return fmt::format("{}-{}", e.a, e.b);
        case EventKind::xwall:
        case EventKind::ywall:
        case EventKind::zwall:
            return fmt::format("{} wall", e.a);
        case EventKind::cell:
            return fmt::format("{} cell", e.a);
    }
    return "?";
}

/// Time to go, short: "0.42", "12.3", "3.1e-05".
std::string time_to_go(double dt) {
    if (dt < 0.0) dt = 0.0;
    if (dt >= 0.01 && dt < 1000.0) return fmt::format("{:.3g}", dt);
    if (dt == 0.0) return "0";
    return fmt::format("{:.2g}", dt);
}

}  // namespace

QueueWords queue_words(const QueueView& queue, double now) {
    const auto separated = [](std::uint64_t n) {
        return with_separators(static_cast<long long>(n));
    };
    QueueWords out;
    out.heading = fmt::format("Event queue: {}, {} {}", queue.name, separated(queue.size),
                              queue.size == 1 ? "entry" : "entries");
    if (queue.one_per_disc) {
        out.heading += " (one per disc)";
    } else if (queue.stale_entries > 0) {
        out.heading += fmt::format(", {} stale", separated(queue.stale_entries));
    }
    // Beside one box at the small presets the strip is narrow: the queue's kind and size say it.
    out.short_heading = fmt::format("{}, {} {}", queue.name, separated(queue.size),
                                    queue.size == 1 ? "entry" : "entries");
    if (!out.short_heading.empty())
        out.short_heading[0] =
            static_cast<char>(std::toupper(static_cast<unsigned char>(out.short_heading[0])));
    // None listed (billiards before the break: the cue ball's next event is a cell crossing):
    // "Next 0 collisions" said nothing a student could use.
    out.legend = queue.next.empty() ? std::string("No collision predicted yet")
                 : queue.next.size() == 1
                     ? std::string("Next collision, time to go")
                     : fmt::format("Next {} collisions, time to go", queue.next.size());
    out.stale_popped = queue.one_per_disc ? "  stale: re-predict" : "  stale: skipped";
    out.stale_leaving = "skipped";
    out.counts =
        queue.one_per_disc
            ? fmt::format("{} pops, {} stale", separated(queue.pops), separated(queue.stale_pops))
            : fmt::format("{} of {} pops stale", separated(queue.stale_pops),
                          separated(queue.pops));
    out.counts_lines = {fmt::format("{} pops", separated(queue.pops)),
                        fmt::format("{} stale", separated(queue.stale_pops))};
    out.popped_heading = "Popped (newest first)";
    out.short_popped_heading = "Popped";
    out.resolved_popped = "  resolved";
    out.crossing_popped = "  crossing";
    out.stale_slot = "stale";
    out.fresh_leaving = "popped";
    if (queue.size > queue.slots.size())
        out.below = fmt::format("+{} below", separated(queue.size - queue.slots.size()));
    if (queue.shape == QueueShape::ordered_array) {
        out.row_caption = "Sorted: the next event is at the end (shown first)";
    } else if (queue.shape != QueueShape::heap) {
        out.row_caption = fmt::format(
            "Stored as pushed; every pop scans for the earliest (slot {})", queue.top_index);
    }
    for (const QueuedEvent& e : queue.next) out.next_times.push_back(time_to_go(e.t - now));
    if (!queue.next.empty()) {
        const QueuedEvent& e = queue.next.front();
        out.next_discs.push_back(std::to_string(e.a));
        if (e.kind == EventKind::pair) out.next_discs.push_back(std::to_string(e.b));
    }
    // Every disc of a listed event is numbered, so that "3-7" in the strip finds its discs.
    const auto numbered = [&](std::uint32_t disc) {
        if (!queue.next.empty()) {
            const QueuedEvent& e = queue.next.front();
            if (disc == e.a || (e.kind == EventKind::pair && disc == e.b)) return true;
        }
        return std::any_of(out.listed_discs.begin(), out.listed_discs.end(),
                           [disc](const QueueWords::NumberedDisc& d) { return d.disc == disc; });
    };
    for (std::size_t r = 1; r < queue.next.size(); ++r) {
        const QueuedEvent& e = queue.next[r];
        if (e.kind == EventKind::cell) continue;  // bookkeeping: not drawn in the box
        for (const std::uint32_t disc : {e.a, e.b}) {
            if (disc == e.b && e.kind != EventKind::pair) continue;
            if (!numbered(disc)) out.listed_discs.push_back({disc, std::to_string(disc)});
        }
    }
    for (const QueuedEvent& e : queue.slots) {
        out.slot_labels.push_back(event_label(e));
        out.slot_times.push_back(time_to_go(e.t - now));
    }
    for (const QueuedEvent& e : queue.popped) out.popped_labels.push_back(event_label(e));
    return out;
}

}  // namespace collide::show
