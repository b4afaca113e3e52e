#pragma once
/// \file
/// Which failures a `collide render` video replays (issue #29, item 4): a run of the time-driven
/// engine over the video's simulation frames finds the steps that failed (sim::StepFailure), and
/// a run of the event-driven engine the collision it handled at each of those moments. Runs
/// before the video (its timeline makes room for the replays): a scene with a failure in its
/// first steps costs a few steps; one without runs the time-driven engine over the whole video.

#include <atomic>
#include <optional>
#include <vector>

#include "collide/scene.hpp"
#include "collide/show/replay.hpp"
#include "render_plan.hpp"

namespace collide::app {

/// True when `step` may be replayed: the scene names no replay_tag, or a disc of the step (the
/// pair's either, the disc that left the box) carries it.
[[nodiscard]] bool shows_replay_tag(const Scene& scene, const sim::StepFailure& step);

/// The failures `plan` replays (plan.replay: the first, or all the engine records, of those
/// shows_replay_tag keeps: with a replay_tag, none when the engine's first records have none), each
/// with the simulation frame after which it is shown (on plan.clock) and, when the plan has an
/// event-driven panel, its collision of the same discs at that moment. Empty for
/// ReplayChoice::none or a scene that does not fail within plan.clock. Once `stop` is set
/// (nullptr: never) throws Error(runtime) within a step or a few thousand events.
[[nodiscard]] std::vector<show::ReplayFailure> find_replays(
    const Scene& scene, const RenderPlan& plan, const std::atomic<bool>* stop = nullptr);

/// The time-driven engine's first failed step (of shows_replay_tag's discs) whose first frame
/// after it (on plan.clock) comes after simulation frame `frame`: run frame by frame as the video
/// runs it, with the event-driven collision of the same discs when the plan has that panel.
/// Empty when none fails within plan.clock. `stop` as find_replays.
[[nodiscard]] std::optional<show::ReplayFailure> failure_after(
    const Scene& scene, const RenderPlan& plan, std::int64_t frame,
    const std::atomic<bool>* stop = nullptr);

}  // namespace collide::app
