#pragma once
/// \file
/// The instant replay of a time-driven failure (issue #29, item 4): the video freezes, zooms onto
/// the spot and plays the failing step again slowly. The time-driven panel shows the disc at
/// step k and at step k + 1 (ghosts), the straight jump between them across the other disc (or
/// the wall) and where they would have touched; the event-driven panel shows the same spot with
/// the collision it predicted. Which failure, when in the video, for how long, and every word
/// are decided here; the engines only report (sim::StepFailure, collision records) and the
/// renderer only paints (BoxZoom, ReplayView).
///
///   seconds into the replay  0 ..... zoom_in ........... slow_end ......... hold_end ... length
///                            zoom in, step k shown   the disc moves k -> k+1   all shown   zoom
///                            out

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "collide/box.hpp"
#include "collide/show/collision.hpp"
#include "collide/sim/time_engine.hpp"
#include "collide/view/collision.hpp"

namespace collide::show {

/// Seconds of video a replay lasts, and where its phases end.
inline constexpr double replay_seconds = 6.0;
inline constexpr double replay_zoom_in = 0.8;   ///< the zoom reaches the spot
inline constexpr double replay_slow_end = 3.6;  ///< the slow move from step k to k + 1 ends
inline constexpr double replay_hold_end = 5.3;  ///< the whole picture stands until here
/// The zoom never enlarges more than this (a disc would fill the box).
inline constexpr double max_replay_magnification = 12.0;

/// The event-driven panel's words in a replay when that engine had no collision of the failing
/// discs at that moment (its history had already parted from the time-driven one's, because
/// of the time-driven panel's earlier misses): two lines a student follows without the word
/// "run", short enough for a box a third of a 480-line frame wide.
inline constexpr std::string_view parted_words[2] = {"Here these two never meet:",
                                                     "earlier misses sent them elsewhere"};

/// The collision the event-driven engine handled at the moment of the failure.
struct PredictedHit {
    double time = 0.0;  ///< simulation time of the collision
    Vec2 a;             ///< the failing disc's centre then
    Vec2 b;             ///< the other disc's centre then (a wall hit: the wall point)
    bool wall = false;  ///< a wall collision (the disc left the box in the time-driven panel)
};

/// One failure to replay: the time-driven engine's record of the step, the simulation frame
/// after which the video replays it, and the event-driven engine's collision at that moment.
struct ReplayFailure {
    sim::StepFailure step;
    double dt = 0.0;
    std::int64_t sim_frame = 0;  ///< the first simulation frame that shows step k + 1
    std::optional<PredictedHit> predicted;

    /// Simulation times of the two checks (k dt, (k + 1) dt) and of the contact.
    [[nodiscard]] double check_before() const noexcept {
        return static_cast<double>(step.step) * dt;
    }
    [[nodiscard]] double check_after() const noexcept {
        return static_cast<double>(step.step + 1) * dt;
    }
    [[nodiscard]] double contact_time() const noexcept { return check_before() + step.contact; }
};

/// The first simulation frame of `clock` whose time shows the state after step k (k + 1 whole
/// steps of dt, as sim::TimeEngine::whole_steps counts them); -1 when no frame of the clock does.
[[nodiscard]] std::int64_t first_frame_after_step(std::uint64_t step, double dt,
                                                  const FrameClock& clock);

/// The replay segment's caption, in words a class reads ("Between two checks the disc jumped
/// through: no overlap was ever seen").
[[nodiscard]] std::string replay_caption(const ReplayFailure& failure);

/// The timeline's replay cues of `failures` (timeline.hpp), in order.
[[nodiscard]] std::vector<TimelineReplay> replay_cues(const std::vector<ReplayFailure>& failures);

/// The zoom of a replay once it has reached the spot: the failure's discs, their two states and
/// the jump between them fill about half of the box (at most max_replay_magnification).
[[nodiscard]] BoxZoom replay_target(const ReplayFailure& failure, const Box& box);

/// What the two panels draw `seconds` into the replay: the zoom (the same for both) and the
/// marks over the time-driven and the event-driven box.
struct ReplayViews {
    BoxZoom zoom;
    ReplayView time_driven;
    ReplayView event_driven;
};
[[nodiscard]] ReplayViews replay_views(const ReplayFailure& failure, const Box& box,
                                       double seconds);

/// The replay (if any) whose segment starts after simulation frame `sim_frame`.
[[nodiscard]] const ReplayFailure* replay_at(const std::vector<ReplayFailure>& failures,
                                             std::int64_t sim_frame) noexcept;

}  // namespace collide::show
