#pragma once
/// \file
/// The collision video's epilogue: the final figures of the panels on one card (missed, discs
/// that ever overlapped, left the box, collisions, the work and its ratio, why the counts differ),
/// for a lecturer to leave on screen. Pure functions of the engines' measurements.

#include <string>
#include <vector>

#include "collide/sim/measurements.hpp"
#include "collide/view/collision.hpp"

namespace collide::show {

/// One panel's final state for the card.
struct SummaryPanel {
    Measurements measurements;
    bool time_driven = false;
    /// A --dt list: this time-driven panel's step, its column headed "dt = ..." (0: one
    /// time-driven panel, headed "Time-driven").
    double dt = 0.0;
};

/// The card for `panels` (panel order) at the final `time_text` ("t = 3.000"); `walls`: the box
/// has walls (discs can leave it); `spheres`: a 3D scene, whose rows name spheres, not discs.
/// Opacity 1; the caller fades it in (summary_opacity).
[[nodiscard]] SummaryCard summary_card(const std::vector<SummaryPanel>& panels, bool walls,
                                       const std::string& time_text, bool spheres = false);

/// Why the two engines' collision counts differ, in one line under the card's table: the
/// time-driven run stepped over collisions (or let discs through a wall), or, with nothing
/// missed, each collision it fixed late sent it on another path (chaos). "" when the counts
/// agree, or without exactly one time-driven and one event-driven panel.
[[nodiscard]] std::string count_difference_note(const std::vector<SummaryPanel>& panels);

/// The caption over the card (at most max_caption_chars), in the words the panels allow: the
/// difference explained when two engines' counts differ, no word of a panel that is absent.
[[nodiscard]] std::string epilogue_caption(const std::vector<SummaryPanel>& panels);

/// The card's opacity `seconds` into the epilogue: fading in over its first half second.
[[nodiscard]] float summary_opacity(double seconds) noexcept;

/// Seconds of the epilogue: 3 s, at most a fifth of a short video.
inline constexpr double epilogue_seconds = 3.0;

}  // namespace collide::show
