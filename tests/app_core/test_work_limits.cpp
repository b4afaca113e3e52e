// Refusing runs that cannot finish: which option or hint is named, what --no-limits lifts and
// what it does not, and `check`'s view of a scene's hints.
#include <doctest/doctest.h>

#include <limits>

#include "../support/input_error.hpp"
#include "collide/error.hpp"
#include "render_plan.hpp"
#include "work_limits.hpp"

using namespace collide;
using namespace collide::app;
using collide::test::contains;
using collide::test::input_error_message;

namespace {

Scene moving_pair() {
    Scene s;
    s.name = "pair";
    s.box = Box{1.0, 1.0, Boundary::walls};
    s.discs.push_back(Disc{{0.25, 0.5}, {0.1, 0.0}, 0.05, 1.0, {}, ""});
    s.discs.push_back(Disc{{0.75, 0.5}, {-0.1, 0.0}, 0.05, 1.0, {}, ""});
    return s;
}

std::string render_refusal(const RenderRequest& request, const Scene& scene,
                           const WorkLimits& limits = {}) {
    return input_error_message([&] {
        const RenderPlan plan = plan_render(request, scene);
        check_render_work(plan, request, show::SceneView{scene}, limits);
    });
}

}  // namespace

TEST_CASE("work limits: the render's span is its last frame time, its engines those of --mode") {
    RenderRequest request;
    request.mode = "time";
    request.duration = 2.0;
    request.speed = 1.0;
    request.fps = 10;
    request.dt = 0.05;
    request.no_epilogue = true;
    RenderPlan plan = plan_render(request, moving_pair());
    RunShape run = render_run_shape(plan);
    CHECK(run.span == doctest::Approx(1.9));  // frames 0..19 at 0.1
    CHECK(run.time_driven);
    CHECK_FALSE(run.event_driven);
    CHECK(run.dt == 0.05);
    CHECK(run.frames == 20.0);
    // The summary's 0.4 s (4 frames) are frozen: the simulation stops 0.4 earlier, the video's
    // frames stay 20.
    request.no_epilogue = false;
    plan = plan_render(request, moving_pair());
    run = render_run_shape(plan);
    CHECK(run.span == doctest::Approx(1.5));
    CHECK(run.frames == 20.0);
}

TEST_CASE(
    "work limits: an ordinary render passes, and too much work names the option responsible") {
    RenderRequest request;
    CHECK(render_refusal(request, moving_pair()).empty());
    request.speed = 1e300;
    CHECK(contains(render_refusal(request, moving_pair()), "--speed: simulating t = 0.."));
    request.speed.reset();
    request.dt = 1e-9;
    const std::string steps = render_refusal(request, moving_pair());
    CHECK(contains(steps, "--dt: the time-driven engine would take about"));
    request.mode = "event";  // no time-driven engine: its dt costs nothing
    CHECK(render_refusal(request, moving_pair()).empty());
}

TEST_CASE("work limits: a step of a --dt list too small is blamed on --dt, with its value") {
    RenderRequest request;
    request.dt_list = {0.01, 2e-9, 0.04};
    const std::string steps = render_refusal(request, moving_pair());
    CHECK(contains(steps, "--dt: the time-driven engine would take about"));
    CHECK(contains(steps, "dt = 2e-09"));
    // Beside a speed and a duration given, and a scene's speed hint: still the step's fault.
    request.speed = 1.0;
    request.duration = 5.0;
    CHECK(contains(render_refusal(request, moving_pair()), "--dt: the time-driven engine"));
    Scene hinted = moving_pair();
    hinted.render.speed = 0.5;
    hinted.render.speed_at = "pair.toml:4: render.speed";
    request.speed.reset();
    request.dt_list = {0.01, 2e-10, 0.04};
    CHECK(contains(render_refusal(request, hinted), "--dt: the time-driven engine"));
    // Below the clock's resolution: the list's step again, --no-limits or not.
    request.dt_list = {0.01, 1e-300};
    request.no_limits = true;
    const std::string never = render_refusal(request, hinted);
    CHECK(contains(never, "--dt: dt = 1e-300 is below the resolution of the clock"));
}

TEST_CASE("work limits: --no-limits lifts the limits but not a run that can never end") {
    WorkLimits tiny;
    tiny.events = 1.0;  // any collision is too many
    RenderRequest request;
    request.mode = "event";
    CHECK(contains(render_refusal(request, moving_pair(), tiny), "collisions"));
    request.no_limits = true;
    CHECK(render_refusal(request, moving_pair(), tiny).empty());
    request.mode = "both";
    request.dt = 1e-300;
    CHECK(contains(render_refusal(request, moving_pair(), tiny), "t + dt == t"));
}

TEST_CASE("work limits: a hint is named by file and line, in check as in render") {
    Scene scene = moving_pair();
    scene.render.dt = 1e-300;
    scene.render.dt_at = "demo.toml:7: render.dt";
    CHECK(contains(input_error_message([&] { check_scene_hints(scene); }),
                   "demo.toml:7: render.dt: dt = 1e-300"));
    CHECK(contains(render_refusal(RenderRequest{}, scene), "demo.toml:7: render.dt: dt = 1e-300"));
    // --dt replaces the hint: render no longer refuses.
    RenderRequest request;
    request.dt = 0.01;
    CHECK(render_refusal(request, scene).empty());

    Scene long_video = moving_pair();
    long_video.render.duration = 1e300;
    long_video.render.duration_at = "demo.toml:9: render.duration";
    CHECK(contains(input_error_message([&] { check_scene_hints(long_video); }),
                   "demo.toml:9: render.duration: expected at most 3600 seconds, got '1e+300'"));
}

TEST_CASE("work limits: check leaves overlap checks (a --td-detect choice) to render") {
    WorkLimits tiny;
    tiny.pair_checks = 1.0;
    CHECK_NOTHROW(check_scene_hints(moving_pair(), tiny));
    CHECK(contains(render_refusal(RenderRequest{}, moving_pair(), tiny), "--td-detect grid"));
}

TEST_CASE("work limits: simulate names --until and --dt") {
    EngineOptions event;
    CHECK_NOTHROW(check_simulate_work(moving_pair(), event, 100.0, false));
    CHECK(contains(
        input_error_message([&] { check_simulate_work(moving_pair(), event, 1e300, false); }),
        "--until: simulating"));
    CHECK_NOTHROW(check_simulate_work(moving_pair(), event, 1e300, true));
    CHECK(contains(input_error_message([&] {
                       check_simulate_work(moving_pair(), event,
                                           std::numeric_limits<double>::infinity(), true);
                   }),
                   "beyond the range of double precision"));
    EngineOptions time;
    time.engine = EngineKind::time;
    time.dt = 1e-300;
    CHECK(
        contains(input_error_message([&] { check_simulate_work(moving_pair(), time, 1.0, true); }),
                 "--dt: dt = 1e-300 is below the resolution"));
}
