// The failures a video replays: the time-driven engine's failed steps over the video's
// simulation frames, each with the event-driven engine's collision of the same discs.
#include "replay_plan.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "collide/sim/engine.hpp"
#include "collide/sim/time_engine.hpp"

namespace collide::app {

namespace {

/// The event-driven collision that stands for `failure`: of the same pair (or the same disc with
/// a wall), the nearest in time to the time-driven contact, within a step of it.
std::optional<CollisionRecord> matching_hit(const show::ReplayFailure& failure,
                                            const std::vector<CollisionRecord>& hits) {
    const sim::StepFailure& f = failure.step;
    const bool wall = f.kind == sim::StepFailureKind::left_box;
    const double from = failure.check_before() - failure.dt;
    const double to = failure.check_after() + failure.dt;
    std::optional<CollisionRecord> best;
    double best_gap = std::numeric_limits<double>::infinity();
    for (const CollisionRecord& hit : hits) {
        if (hit.t < from || hit.t > to) continue;
        const bool same = wall ? hit.kind != CollisionKind::pair && hit.a == f.a
                               : hit.kind == CollisionKind::pair && std::min(hit.a, hit.b) == f.a &&
                                     std::max(hit.a, hit.b) == f.b;
        const double gap = std::abs(hit.t - failure.contact_time());
        if (same && gap < best_gap) {
            best = hit;
            best_gap = gap;
        }
    }
    return best;
}

/// Each failure's event-driven collision, and where its discs were then.
void add_predictions(const Scene& scene, const RenderPlan& plan,
                     std::vector<show::ReplayFailure>& failures, const std::atomic<bool>* stop) {
    if (failures.empty()) return;
    EngineOptions options = plan.event_engine;
    options.stop = stop;  // building the engine of a large scene takes seconds too
    std::vector<CollisionRecord> hits;
    {
        const std::unique_ptr<Engine> engine = make_engine(scene, options);
        engine->set_collision_listener([&](const CollisionRecord& hit) {
            const bool involved =
                std::any_of(failures.begin(), failures.end(), [&](const show::ReplayFailure& f) {
                    return hit.a == f.step.a || hit.b == f.step.a || hit.a == f.step.b;
                });
            if (involved) hits.push_back(hit);
        });
        engine->advance_to(failures.back().check_after() + failures.back().dt);
    }
    // Where the discs were at each collision: a second run stopping at those times, in order.
    std::vector<std::pair<double, show::ReplayFailure*>> when;
    for (show::ReplayFailure& failure : failures) {
        if (const std::optional<CollisionRecord> hit = matching_hit(failure, hits))
            when.emplace_back(hit->t, &failure);
    }
    std::sort(when.begin(), when.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    const std::unique_ptr<Engine> engine = make_engine(scene, options);
    for (const auto& [t, failure] : when) {
        engine->advance_to(std::max(t, engine->time()));
        const Snapshot snapshot = engine->snapshot();
        const sim::StepFailure& f = failure->step;
        show::PredictedHit predicted;
        predicted.time = t;
        predicted.a = snapshot.discs[f.a].position;
        predicted.wall = f.kind == sim::StepFailureKind::left_box;
        if (predicted.wall) {
            // The wall point the disc touches, on the side it was heading for.
            const bool x = std::abs(f.motion_a.x) >= std::abs(f.motion_a.y);
            const double r = snapshot.discs[f.a].radius;
            predicted.b = predicted.a + (x ? Vec2{std::copysign(r, f.motion_a.x), 0.0}
                                           : Vec2{0.0, std::copysign(r, f.motion_a.y)});
        } else {
            predicted.b = snapshot.discs[f.b].position;
        }
        failure->predicted = predicted;
    }
}

}  // namespace

bool shows_replay_tag(const Scene& scene, const sim::StepFailure& step) {
    if (!scene.render.replay_tag) return true;
    const auto tagged = [&](std::uint32_t i) {
        return i < scene.discs.size() && scene.discs[i].tag == *scene.render.replay_tag;
    };
    return tagged(step.a) || (step.kind == sim::StepFailureKind::missed_pair && tagged(step.b));
}

std::vector<show::ReplayFailure> find_replays(const Scene& scene, const RenderPlan& plan,
                                              const std::atomic<bool>* stop) {
    if (plan.replay == ReplayChoice::none || plan.mode == RenderMode::event) return {};
    const std::size_t wanted =
        plan.replay == ReplayChoice::first ? 1 : sim::TimeEngine::max_failure_records;
    const auto shown = [&scene](const sim::StepFailure& step) {
        return shows_replay_tag(scene, step);
    };
    sim::TimeEngine engine(scene, plan.time_engine);
    engine.set_stop_flag(stop);
    // Frame by frame, as the video takes them, until enough steps have failed (or the engine
    // keeps no more records).
    const auto enough = [&] {
        const auto& failures = engine.failures();
        return failures.size() >= sim::TimeEngine::max_failure_records ||
               static_cast<std::size_t>(std::count_if(failures.begin(), failures.end(), shown)) >=
                   wanted;
    };
    for (std::int64_t j = 0; j < plan.clock.count && !enough(); ++j)
        engine.advance_to(std::max(plan.clock.time(j), engine.time()));
    std::vector<show::ReplayFailure> out;
    for (const sim::StepFailure& step : engine.failures()) {
        if (out.size() == wanted) break;
        if (!shown(step)) continue;
        show::ReplayFailure failure;
        failure.step = step;
        failure.dt = plan.time_engine.dt;
        failure.sim_frame = show::first_frame_after_step(step.step, failure.dt, plan.clock);
        // One replay per frame shown: failures of steps a frame skips over wait for the next.
        if (failure.sim_frame < 0 || (!out.empty() && out.back().sim_frame == failure.sim_frame))
            continue;
        out.push_back(failure);
    }
    if (plan.mode != RenderMode::time) add_predictions(scene, plan, out, stop);
    return out;
}

std::optional<show::ReplayFailure> failure_after(const Scene& scene, const RenderPlan& plan,
                                                 std::int64_t frame,
                                                 const std::atomic<bool>* stop) {
    sim::TimeEngine engine(scene, plan.time_engine);
    engine.set_stop_flag(stop);
    for (std::int64_t j = 0; j < plan.clock.count; ++j) {
        engine.advance_to(std::max(plan.clock.time(j), engine.time()));
        for (const sim::StepFailure& step : engine.failures()) {
            if (!shows_replay_tag(scene, step)) continue;
            show::ReplayFailure failure;
            failure.step = step;
            failure.dt = plan.time_engine.dt;
            failure.sim_frame = show::first_frame_after_step(step.step, failure.dt, plan.clock);
            if (failure.sim_frame <= frame) continue;
            std::vector<show::ReplayFailure> found{failure};
            if (plan.mode != RenderMode::time) add_predictions(scene, plan, found, stop);
            return found.front();
        }
        // The engine keeps a few records: those of frames passed are not wanted.
        engine.forget_failures();
    }
    return std::nullopt;
}

}  // namespace collide::app
