// The collision video's clock: frame times, the time-driven engine's steps between them, and the
// clock a class reads.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "collide/show/collision.hpp"

namespace collide::show {

namespace {
bool positive_finite(double x) {
    return std::isfinite(x) && x > 0.0;
}
}  // namespace

bool divides(double dt, double interval) noexcept {
    if (!positive_finite(dt) || !positive_finite(interval)) return false;
    const double steps = interval / dt;
    return std::abs(steps - std::round(steps)) <= divide_tolerance * std::max(1.0, steps);
}

namespace {
/// "t = 12.345": the time part of the clock.
std::string time_part(double t, const FrameClock& clock) {
    if (clock.interval >= 1e-3 && clock.last_time < 1e6) return fmt::format("t = {:.3f}", t);
    // Enough significant digits for consecutive frames to differ: one per decade from the frame
    // interval up to the last frame's time, and two more.
    const double decades =
        clock.last_time > clock.interval ? std::log10(clock.last_time / clock.interval) : 0.0;
    const int digits = std::clamp(static_cast<int>(std::ceil(decades)) + 2, 4, 15);
    return fmt::format("t = {:.{}g}", t, digits);
}
}  // namespace

std::string clock_label(double t, const FrameClock& clock, double speed) {
    return fmt::format("{}   ({:.3g}/s)", time_part(t, clock), speed);
}

namespace {
/// The lesson's clock: as many decimals as tell one frame from the next, at most three (a class
/// reads "t = 45.0", not "t = 45.000", when frames are 0.1 apart).
bool lesson_decimals_apply(const FrameClock& clock) {
    return clock.interval >= 1e-3 && clock.last_time < 1e6;
}
int lesson_decimals(const FrameClock& clock) {
    return std::clamp(static_cast<int>(std::ceil(-std::log10(clock.interval) - 1e-9)), 0, 3);
}
std::string lesson_clock(double t, const FrameClock& clock) {
    if (!lesson_decimals_apply(clock)) return time_part(t, clock);
    return fmt::format("t = {:.{}f}", t, lesson_decimals(clock));
}
}  // namespace

std::string next_collision_words(double to_go, const FrameClock& clock, bool short_form) {
    const std::string lead = short_form ? "in " : "next hit in ";
    // In the units and decimals of the clock beside it, so that a class can add the two.
    if (!lesson_decimals_apply(clock)) return lead + fmt::format("{:.3g}", to_go);
    const int decimals = lesson_decimals(clock);
    const double smallest = std::pow(10.0, -decimals);
    // "0.00" would say the hit is now: below the last decimal it is "< 0.01".
    if (to_go < 0.5 * smallest) return lead + fmt::format("< {:.{}f}", smallest, decimals);
    return lead + fmt::format("{:.{}f}", to_go, decimals);
}

std::string clock_text(double t, const FrameClock& clock, double speed, OverlayLevel level) {
    // The lesson's column is narrow and the playback rate is no lesson: the time alone (its unit,
    // time_unit, goes on a line of its own).
    return level == OverlayLevel::lesson ? lesson_clock(t, clock) : clock_label(t, clock, speed);
}

}  // namespace collide::show
