// Which failures a video replays (replay_plan.hpp) and where its timeline puts them: the step
// replayed is the first the time-driven engine failed, the replay follows the first frame that
// shows the state after it, the simulation clock stands still during it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "../sim/scene_fixtures.hpp"
#include "collide/sim/time_engine.hpp"
#include "render_plan.hpp"
#include "replay_plan.hpp"

using namespace collide;
using namespace collide::app;

namespace {

/// A fast disc through a resting heavy one (dt = 0.1 steps over it), later a second one.
Scene tunnel_scene() {
    Scene s;
    s.name = "tunnel";
    s.box = Box{2.0, 1.0, Boundary::walls};
    s.discs.push_back(Disc{{0.15, 0.5}, {1.0, 0.0}, 0.01, 1.0, {}, ""});
    s.discs.push_back(Disc{{0.5, 0.5}, {0.0, 0.0}, 0.01, 1e5, {}, ""});
    s.discs.push_back(Disc{{0.15, 0.2}, {1.0, 0.0}, 0.01, 1.0, {}, ""});
    s.discs.push_back(Disc{{0.7, 0.2}, {0.0, 0.0}, 0.01, 1e5, {}, ""});
    return s;
}

RenderRequest tunnel_request() {
    RenderRequest request;
    request.scene = "tunnel";
    request.duration = 30.0;
    request.speed = 0.1;
    request.dt = 0.1;
    request.output = "unused.mp4";
    return request;
}

ReplayFinder finder(const Scene& scene) {
    return [&scene](const RenderPlan& draft) { return find_replays(scene, draft); };
}

/// The first step after which the engine's count of missed collisions is not zero (found by
/// counting, not from its failure records).
std::uint64_t first_missed_step(const Scene& scene, double dt) {
    EngineOptions options;
    options.engine = EngineKind::time;
    options.dt = dt;
    sim::TimeEngine engine(scene, options);
    for (std::uint64_t k = 1; k < 1000; ++k) {
        engine.advance_to(static_cast<double>(k) * dt);
        if (engine.measurements().missed_collisions > 0) return k - 1;
    }
    return 0;
}

}  // namespace

TEST_CASE("the replayed step is the first failure, shown after the first frame showing k + 1") {
    const Scene scene = tunnel_scene();
    const RenderPlan plan = plan_render(tunnel_request(), scene, finder(scene));
    REQUIRE(plan.replays.size() == 1);
    const show::ReplayFailure& failure = plan.replays.front();
    CHECK(failure.step.step == first_missed_step(scene, 0.1));
    CHECK(failure.step.a == 0);
    CHECK(failure.step.b == 1);
    // The event-driven engine's collision of the same pair, at the straight paths' contact.
    REQUIRE(failure.predicted.has_value());
    CHECK(failure.predicted->time == doctest::Approx(failure.contact_time()).epsilon(1e-9));
    // The replay segment: right after the first frame showing step k + 1, frozen on it.
    int replays = 0;
    for (const show::Segment& segment : plan.timeline.segments) {
        if (segment.kind != show::SegmentKind::replay) continue;
        ++replays;
        CHECK_FALSE(segment.moves);
        CHECK(segment.sim_frame == failure.sim_frame);
        CHECK(plan.timeline.sim_frame(segment.first_frame - 1) == failure.sim_frame);
        CHECK(plan.timeline.sim_frame(segment.end_frame - 1) == failure.sim_frame);
        CHECK(segment.frames() == static_cast<std::int64_t>(show::replay_seconds * plan.fps + 0.5));
    }
    CHECK(replays == 1);
    const double after_step = static_cast<double>(failure.step.step + 1) * 0.1;
    CHECK(plan.clock.time(failure.sim_frame) >= after_step - 1e-9);
    CHECK(plan.clock.time(failure.sim_frame - 1) < after_step - 1e-9);
}

TEST_CASE("--replay all replays each failed step, none replays nothing, a bad value throws") {
    const Scene scene = tunnel_scene();
    RenderRequest request = tunnel_request();
    request.replay = "all";
    const RenderPlan all = plan_render(request, scene, finder(scene));
    CHECK(all.replays.size() == 2);
    request.replay = "none";
    const RenderPlan none = plan_render(request, scene, finder(scene));
    CHECK(none.replays.empty());
    for (const show::Segment& segment : none.timeline.segments)
        CHECK(segment.kind != show::SegmentKind::replay);
    request.replay = "sometimes";
    CHECK_THROWS_AS((void)plan_render(request, scene, finder(scene)), Error);
    // The lesson level only: a full-level video has no replay.
    request.replay.reset();
    request.overlays = "full";
    CHECK(plan_render(request, scene, finder(scene)).replays.empty());
}

TEST_CASE("a replay_tag replays the first failure of a disc with that tag, skipping the others") {
    // Discs 0 -> 1 fail first, 2 -> 3 later: tagging 3 makes the later failure the replayed one.
    Scene scene = tunnel_scene();
    scene.discs[3].tag = "barrier";
    scene.render.replay_tag = "barrier";
    const RenderPlan plan = plan_render(tunnel_request(), scene, finder(scene));
    REQUIRE(plan.replays.size() == 1);
    const show::ReplayFailure& failure = plan.replays.front();
    CHECK(failure.step.a == 2);
    CHECK(failure.step.b == 3);
    CHECK(failure.step.step > first_missed_step(scene, 0.1));
    CHECK(shows_replay_tag(scene, failure.step));
    // A tag no failing disc carries: nothing replayed (the untagged failures are not shown).
    scene.discs[3].tag.clear();
    scene.discs[3].tag = "other";
    scene.render.replay_tag = "nobody";
    CHECK(plan_render(tunnel_request(), scene, finder(scene)).replays.empty());
}

namespace {

/// The frame a plan's question `i` freezes on (-1: not asked).
std::int64_t frozen_frame(const RenderPlan& plan, int i) {
    for (const show::Segment& segment : plan.timeline.segments) {
        if (segment.kind == show::SegmentKind::question && segment.question == i)
            return segment.sim_frame;
    }
    return -1;
}

}  // namespace

TEST_CASE("will see: asked just before the time-driven engine's next failed step, for many seeds") {
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        CAPTURE(seed);
        Scene scene = test::lattice_fluid(6, 0.1, Boundary::walls, seed);
        QuestionCue cue;
        cue.at = 2.5 + 0.4 * static_cast<double>(seed);
        cue.kind = QuestionKind::how_many;
        scene.render.questions = {cue};
        RenderRequest request;
        request.scene = "gas";
        request.duration = 30.0;
        request.speed = 0.1;
        request.dt = 0.02;  // a disc moves about 0.03 a step, more than a diameter (0.02)
        request.output = "unused.mp4";
        // Where the picture freezes on a question at that moment (how-many is asked there).
        const std::int64_t at = frozen_frame(plan_render(request, scene, finder(scene)), 0);
        REQUIRE(at >= 0);
        scene.render.questions.front().kind = QuestionKind::will_see;
        const RenderPlan plan = plan_render(request, scene, finder(scene));
        REQUIRE(plan.questions.size() == 1);
        const show::QuestionAnswer& answer = plan.questions.front();
        REQUIRE(answer.askable);
        REQUIRE(answer.failure.has_value());
        const std::int64_t frozen = frozen_frame(plan, 0);
        CHECK(frozen == answer.sim_frame);
        CHECK(frozen >= at);
        CHECK(answer.failure->sim_frame == frozen + 1);
        // A fresh engine, stepped as the video steps it: no failed step recorded after the
        // asked moment up to the frozen frame; the step the next frame takes fails, with the
        // pair marked, and counts missed collisions (its own count, not its records).
        sim::TimeEngine engine(scene, plan.time_engine);
        for (std::int64_t j = 0; j <= at; ++j) engine.advance_to(plan.clock.time(j));
        engine.forget_failures();
        for (std::int64_t j = at + 1; j <= frozen; ++j) engine.advance_to(plan.clock.time(j));
        CHECK(engine.failures().empty());
        const std::uint64_t missed = engine.measurements().missed_collisions;
        engine.advance_to(plan.clock.time(frozen + 1));
        REQUIRE(engine.failures().size() == 1);
        const sim::StepFailure& step = answer.failure->step;
        CHECK(engine.failures().front().step == step.step);
        CHECK(engine.failures().front().a == step.a);
        CHECK(engine.failures().front().b == step.b);
        if (step.kind == sim::StepFailureKind::missed_pair)
            CHECK(engine.measurements().missed_collisions > missed);
        // The reveal is the replay of that step: as long as a replay, and no second replay of it.
        bool revealed = false;
        for (const show::Segment& segment : plan.timeline.segments) {
            if (segment.kind == show::SegmentKind::reveal && segment.question == 0) {
                revealed = true;
                CHECK(segment.sim_frame == frozen);
                CHECK(segment.frames() ==
                      static_cast<std::int64_t>(show::replay_seconds * plan.fps + 0.5));
            }
            if (segment.kind == show::SegmentKind::replay)
                CHECK(segment.sim_frame != answer.failure->sim_frame);
        }
        CHECK(revealed);
        // A move is told when the question lands more than quiet_move_seconds after its `at`
        // (a frame either side of that: no claim).
        double landed = -1.0;
        for (const show::Segment& segment : plan.timeline.segments)
            if (segment.kind == show::SegmentKind::question) landed = segment.start;
        const double moved = landed - cue.at;
        const double frame = 1.0 / plan.fps;
        const bool said = std::any_of(
            plan.notices.begin(), plan.notices.end(),
            [](const std::string& n) { return n.find("moved from") != std::string::npos; });
        if (moved > show::quiet_move_seconds + frame) CHECK(said);
        if (moved < show::quiet_move_seconds - frame) CHECK_FALSE(said);
    }
}
