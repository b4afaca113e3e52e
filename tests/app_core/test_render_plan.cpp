// The pure pieces of `collide render`: presets, sizes, speed derivation, frame clocks, dt steps,
// option precedence (command line > scene hint > default).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "collide/error.hpp"
#include "collide/sim/generate.hpp"
#include "collide/sim/time_engine.hpp"
#include "pipeline.hpp"
#include "render_plan.hpp"

using namespace collide;
using namespace collide::app;

namespace {

Scene two_disc_scene(double speed) {
    Scene s;
    s.name = "two";
    s.box = Box{2.0, 1.0, Boundary::walls};
    s.discs.push_back(Disc{{0.5, 0.5}, {speed, 0.0}, 0.05, 1.0, {}, ""});
    s.discs.push_back(Disc{{1.5, 0.5}, {-speed, 0.0}, 0.05, 1.0, {}, ""});
    return s;
}

}  // namespace

TEST_CASE("quality presets are the manim-like l/m/h/k sizes and rates") {
    CHECK(quality_preset("l").width == 854);
    CHECK(quality_preset("l").fps == 15);
    CHECK(quality_preset("m").height == 720);
    CHECK(quality_preset("h").fps == 60);
    CHECK(quality_preset("k").width == 3840);
    CHECK_THROWS_AS((void)quality_preset("x"), Error);
}

TEST_CASE("--size parses WxH and names the option when it is bad") {
    const FrameSize s = parse_frame_size("640x360");
    CHECK(s.width == 640);
    CHECK(s.height == 360);
    for (const char* bad : {"640", "x360", "640x", "0x360", "640x-2", "abcxdef", "99999x10"}) {
        try {
            (void)parse_frame_size(bad);
            FAIL("accepted " << bad);
        } catch (const Error& e) {
            CHECK(e.exit_code() == 2);
            CHECK(std::string(e.what()).find("--size") != std::string::npos);
        }
    }
}

TEST_CASE("the derived speed makes a typical disc cross the box in about ten seconds of video") {
    const Scene slow = two_disc_scene(0.01);  // algs4-like speeds
    const SpeedChoice a = choose_speed(slow, std::nullopt);
    CHECK(a.source == "derived");
    CHECK(a.speed == doctest::Approx(2.0 / (crossing_seconds * 0.01)));
    const Scene fast = two_disc_scene(100.0);  // molecular-scale speeds
    CHECK(choose_speed(fast, std::nullopt).speed ==
          doctest::Approx(2.0 / (crossing_seconds * 100.0)));
    // the command line beats the scene hint, which beats the derivation
    Scene hinted = slow;
    hinted.render.speed = 3.0;
    CHECK(choose_speed(hinted, std::nullopt).speed == 3.0);
    CHECK(choose_speed(hinted, 5.0).speed == 5.0);
}

TEST_CASE("a scene where nothing moves falls back with a notice instead of dividing by zero") {
    const SpeedChoice c = choose_speed(two_disc_scene(0.0), std::nullopt);
    CHECK(c.speed > 0.0);
    CHECK_FALSE(c.notice.empty());
}

TEST_CASE("frame k is at exactly k * speed / fps") {
    const FrameClock clock = video_clock(2.0, 0.5, 15);
    CHECK(clock.count == 30);
    CHECK(clock.time(0) == 0.0);
    CHECK(clock.time(10) == doctest::Approx(10 * 0.5 / 15).epsilon(1e-15));
    CHECK(clock.time(29) == doctest::Approx(29 * 0.5 / 15));
    CHECK_THROWS_AS((void)video_clock(0.0, 1.0, 30), Error);
    CHECK_THROWS_AS((void)video_clock(1.0, -1.0, 30), Error);
}

// Issue #28 item 1: step k of the time-driven engine ends at k dt from t = 0 for every caller.
// A chaotic gas (dense enough that every step has contacts and misses) amplifies the last bit of
// any difference, so the states must be equal bit for bit, not approximately.
TEST_CASE(
    "render at two frame rates, a thumbnail and simulate give the time-driven engine the same "
    "steps, counts and states") {
    Scene scene;
    scene.name = "chaos";
    scene.box = Box{1.0, 1.0, Boundary::walls};
    GenerateSpec spec;
    spec.count = 300;
    spec.radius = 0.012;
    spec.seed = 7;
    generate_discs(scene, spec);
    const double dt = 0.0037;  // divides neither frame interval: frames fall between steps
    const double until = 2.0;
    const auto state = [](const Snapshot& s) {
        std::vector<double> out;
        for (const DiscState& d : s.discs)
            out.insert(out.end(), {d.position.x, d.position.y, d.velocity.x, d.velocity.y});
        return out;
    };
    struct Result {
        Measurements m;
        Snapshot snap;
    };
    const auto through_frames = [&](const RenderPlan& plan) {
        const show::CollisionSettings settings = collision_settings(plan);
        show::CollisionSimulation source(show::SceneView{scene}, settings);
        show::CollisionState frame;
        for (std::int64_t k = 0; k < plan.clock.count; ++k) frame = source.state(k);
        return Result{source.measurements().front(), frame.panels.front().snapshot};
    };
    RenderRequest request;
    request.scene = "chaos";
    request.size = "320x180";
    request.speed = 1.0;
    request.dt = dt;
    request.mode = "time";
    request.duration = until;
    request.no_epilogue = true;  // every video frame a new state
    std::vector<Result> results;
    for (const int fps : {15, 24}) {  // video clocks ending at 2.0 - 1/fps
        request.fps = fps;
        RenderPlan plan = plan_render(request, scene);
        plan.clock.count += 1;  // and one frame more: exactly `until`
        plan.clock.last_time = until;
        plan.timeline = show::running_timeline(fps, plan.clock.count);
        results.push_back(through_frames(plan));
    }
    request.fps = 30;
    RenderPlan still = plan_render(request, scene);
    still.clock = still_clock(until, 1.0, 30);  // the frames of `thumbnail --at 2`
    still.timeline = show::running_timeline(30, still.clock.count);
    results.push_back(through_frames(still));
    auto simulate = make_engine(scene, still.time_engine);  // `simulate --until 2` does this
    simulate->advance_to(until);
    results.push_back({simulate->measurements(), simulate->snapshot()});

    const Result& reference = results.back();
    const auto steps = sim::TimeEngine::whole_steps(until, dt);
    CHECK(steps == 540);  // 540 dt = 1.998 <= 2 < 541 dt
    CHECK(reference.m.steps == steps);
    CHECK(reference.snap.time == static_cast<double>(steps) * dt);
    CHECK(reference.m.collisions_pair > 100);  // a run where the last bits matter
    CHECK(reference.m.missed_collisions > 0);
    for (const Result& r : results) {
        CHECK(r.m.steps == reference.m.steps);
        CHECK(r.snap.time == reference.snap.time);
        CHECK(r.m.collisions_pair == reference.m.collisions_pair);
        CHECK(r.m.collisions_wall == reference.m.collisions_wall);
        CHECK(r.m.missed_collisions == reference.m.missed_collisions);
        CHECK(r.m.overlap_checks == reference.m.overlap_checks);
        CHECK(r.m.escaped == reference.m.escaped);
        CHECK(state(r.snap) == state(reference.snap));
    }
}

TEST_CASE("dt divides the frame interval, or the plan says what the panel will show") {
    CHECK(divides(0.01, 0.05));
    CHECK_FALSE(divides(0.03, 0.05));
    RenderRequest request;
    request.scene = "two";
    request.size = "320x180";
    request.fps = 10;
    request.speed = 0.1;  // frame interval 0.01
    request.dt = 0.04;
    const RenderPlan plan = plan_render(request, two_disc_scene(0.1));
    CHECK(plan.time_engine.dt == 0.04);
    REQUIRE_FALSE(plan.notices.empty());
    CHECK(plan.notices.front().find("latest step") != std::string::npos);
}

TEST_CASE("plan_render: command line over scene hints over defaults, and the default output path") {
    Scene scene = two_disc_scene(0.1);
    scene.render.duration = 3.0;
    scene.render.color_mode = ColorMode::speed;
    RenderRequest request;
    request.scene = "two";
    RenderPlan plan = plan_render(request, scene);
    CHECK(plan.duration == 3.0);
    CHECK(plan.render.color_mode == render::ColorMode::speed);
    CHECK(plan.width == 1280);
    CHECK(plan.fps == 30);
    CHECK(plan.output == std::filesystem::path("out") / "two.mp4");
    CHECK(plan.mode == RenderMode::both);
    request.duration = 1.0;
    request.color = "scene";
    request.quality = "l";
    plan = plan_render(request, scene);
    CHECK(plan.duration == 1.0);
    CHECK(plan.render.color_mode == render::ColorMode::scene);
    CHECK(plan.width == 854);
    CHECK(plan.timeline.frame_count() == 15);  // video frames; the simulation's are fewer
}

TEST_CASE("plan_render rejects bad options with the option's name") {
    const Scene scene = two_disc_scene(0.1);
    const auto rejects = [&](auto&& edit, const char* option) {
        RenderRequest request;
        request.scene = "two";
        edit(request);
        try {
            (void)plan_render(request, scene);
            FAIL("accepted a bad " << option);
        } catch (const Error& e) {
            CHECK(e.exit_code() == 2);
            CHECK_MESSAGE(std::string(e.what()).find(option) != std::string::npos, e.what());
        }
    };
    rejects([](RenderRequest& r) { r.mode = "sideways"; }, "--mode");
    rejects([](RenderRequest& r) { r.fps = 0; }, "--fps");
    rejects([](RenderRequest& r) { r.duration = -1.0; }, "--duration");
    rejects([](RenderRequest& r) { r.dt = 0.0; }, "--dt");
    rejects([](RenderRequest& r) { r.color = "rainbow"; }, "--color");
    rejects([](RenderRequest& r) { r.format = "avi"; }, "--format");
    rejects([](RenderRequest& r) { r.engine = EngineKind::time; }, "--engine");
    rejects([](RenderRequest& r) { r.queue = 0; }, "--queue");
    rejects([](RenderRequest& r) { r.queue = 21; }, "--queue");
    rejects(
        [](RenderRequest& r) {
            r.queue = 5;
            r.mode = "time";
        },
        "--queue");
    rejects(
        [](RenderRequest& r) {
            r.queue = 5;
            r.overlays = "none";
        },
        "--queue");
    rejects([](RenderRequest& r) { r.slow_motion = 0.5; }, "--slow-motion");
    rejects([](RenderRequest& r) { r.slow_motion = 1e9; }, "--slow-motion");
    rejects([](RenderRequest& r) { r.slow_motion = std::nan(""); }, "--slow-motion");
}

TEST_CASE("--queue asks for the event queue and --slow-motion slows the video, not the physics") {
    const Scene scene = two_disc_scene(0.2);
    RenderRequest request;
    request.scene = "two";
    const RenderPlan plain = plan_render(request, scene);
    CHECK(plain.queue_events == 0);
    CHECK(plain.slow_motion == 1.0);
    request.queue = 7;
    request.slow_motion = 4.0;
    const RenderPlan slow = plan_render(request, scene);
    CHECK(slow.queue_events == 7);
    CHECK(slow.speed.speed == doctest::Approx(plain.speed.speed / 4.0));
    CHECK(slow.clock.interval == doctest::Approx(plain.clock.interval / 4.0));
    CHECK(slow.time_engine.dt == plain.time_engine.dt);  // same physics, more frames per step
    CHECK(slow.lesson.frames_per_step == 4 * plain.lesson.frames_per_step);
    request.mode = "event";
    CHECK(plan_render(request, scene).queue_events == 7);
}

TEST_CASE(
    "plan_render carries the parsed engine options to both panels, and titles name the queue") {
    const Scene scene = two_disc_scene(0.1);
    RenderRequest request;
    request.scene = "two";
    request.engine = EngineKind::classic;
    request.pq = pq::parse_queue_kind("indexed");
    request.td_detect = OverlapDetection::grid;
    const RenderPlan plan = plan_render(request, scene);
    CHECK(plan.event_engine.engine == EngineKind::classic);
    CHECK(plan.event_engine.pq == pq::QueueKind{pq::QueueFamily::indexed, 4});
    CHECK(plan.time_engine.engine == EngineKind::time);
    CHECK(plan.time_engine.td_detect == OverlapDetection::grid);
    // The canonical spelling, with the arity in use (`--pq indexed` is indexed:4).
    CHECK(show::event_panel_title(plan.event_engine) == "Event-driven (priority queue: indexed:4)");
    CHECK(show::event_lesson_title(plan.event_engine) == "Event-driven: queue (indexed:4)");
    request.engine = EngineKind::fast;
    CHECK(show::event_lesson_title(plan_render(request, scene).event_engine) ==
          "Event-driven: priority queue");
}

TEST_CASE("--format decides for a path without extension, a clashing extension names both") {
    const Scene scene = two_disc_scene(0.1);
    RenderRequest request;
    request.scene = "two";
    request.format = "mp4";
    request.output = "noext";
    const RenderPlan plan = plan_render(request, scene);
    CHECK(plan.format == video::VideoFormat::mp4);
    CHECK(plan.output == "noext");
    request.output = "clip.gif";
    try {
        (void)plan_render(request, scene);
        FAIL("accepted clip.gif as mp4");
    } catch (const Error& e) {
        CHECK(e.exit_code() == 2);
        CHECK(std::string(e.what()) == "-o: 'clip.gif' ends in .gif, but --format is mp4");
    }
}

TEST_CASE("the default dt comes from the scene, never from the preset or the frame rate") {
    const Scene scene = two_disc_scene(0.2);
    double dt = 0.0;
    for (const char* q : {"l", "m", "h", "k"}) {
        RenderRequest request;
        request.scene = "two";
        request.quality = q;
        const RenderPlan plan = plan_render(request, scene);
        if (dt == 0.0) dt = plan.time_engine.dt;
        CHECK_MESSAGE(plan.time_engine.dt == dt, "-q " << q);
    }
    CHECK(dt == doctest::Approx(default_dt(choose_speed(scene, std::nullopt).speed)));
    RenderRequest request;
    request.fps = 7;
    CHECK(plan_render(request, scene).time_engine.dt == dt);
    // At 60 fps a step spans two frames: the lesson says so and counts them.
    request.fps = 60;
    const RenderPlan plan = plan_render(request, scene);
    CHECK(plan.lesson.frames_per_step == 2);
    CHECK(show::step_note(plan.time_engine.dt, plan.clock.interval) ==
          "Moves only every 2nd frame");
    CHECK(show::step_note(0.01, 0.02).empty());
}

TEST_CASE("captions follow the scene's schedule, and the intro card fades out after ~2 s") {
    Scene scene = two_disc_scene(0.2);
    scene.title = "Two discs";
    scene.description = "They meet in the middle";
    scene.render.duration = 10.0;
    scene.render.caption = "Always";
    scene.render.captions = {{2.0, "From two", "s.toml", 7}, {6.0, "From six", "s.toml", 10}};
    RenderRequest request;
    const RenderPlan plan = plan_render(request, scene);
    CHECK(plan.lesson.caption_at(0.0) == "Always");
    CHECK(plan.lesson.caption_at(1.99) == "Always");
    CHECK(plan.lesson.caption_at(2.0) == "From two");
    CHECK(plan.lesson.caption_at(5.9) == "From two");
    CHECK(plan.lesson.caption_at(9.0) == "From six");
    CHECK(plan.lesson.intro_opacity(0.0) == 1.0F);
    CHECK(plan.lesson.intro_opacity(1.75) == doctest::Approx(0.5));
    CHECK(plan.lesson.intro_opacity(2.0) == 0.0F);
    // --no-intro: none.
    request.no_intro = true;
    CHECK(plan_render(request, scene).lesson.intro_opacity(0.0) == 0.0F);
    request.no_intro = false;
    // A still image has no intro card.
    request.still = true;
    CHECK(plan_render(request, scene).lesson.intro_opacity(0.0) == 0.0F);
}

TEST_CASE("the speed histogram shows by default with enough moving discs, or when the scene asks") {
    // 250 light discs and 300 immovable ones (a barrier): 250 moving is enough.
    Scene gas = two_disc_scene(0.2);
    gas.discs.clear();
    for (int i = 0; i < 550; ++i) {
        const double mass = i < 250 ? 1.0 : 1e6;
        gas.discs.push_back(
            Disc{{0.01 + 0.0035 * i, 0.5}, {i < 250 ? 0.1 : 0.0, 0.0}, 0.001, mass, {}, ""});
    }
    RenderRequest request;
    CHECK(plan_render(request, gas).lesson.histogram == render::PlotSize::small);
    // 150 moving among 400 is not: the barrier discs never count (tunnelling, billiards, ...).
    gas.discs.erase(gas.discs.begin(), gas.discs.begin() + 100);
    CHECK(show::moving_disc_count(gas) == 150);
    CHECK(plan_render(request, gas).lesson.histogram == render::PlotSize::none);
    // The scene decides over the default.
    gas.render.histogram = PlotSize::small;
    CHECK(plan_render(request, gas).lesson.histogram == render::PlotSize::small);
    gas.render.histogram = PlotSize::large;
    CHECK(plan_render(request, gas).lesson.histogram == render::PlotSize::large);
    gas.render.histogram = PlotSize::none;
    gas.discs.resize(600, gas.discs.front());
    CHECK(plan_render(request, gas).lesson.histogram == render::PlotSize::none);
}

TEST_CASE("captions beyond the video: an error naming the scene line, or a notice for --duration") {
    Scene scene = two_disc_scene(0.2);
    scene.render.captions = {{12.0, "Too late", "s.toml", 9}};
    RenderRequest request;  // the default 10 s video
    const std::string message = [&] {
        try {
            (void)plan_render(request, scene);
        } catch (const Error& e) {
            CHECK(e.kind() == ErrorKind::input);
            return std::string(e.what());
        }
        return std::string();
    }();
    CHECK(message.find("s.toml:9") != std::string::npos);
    CHECK(message.find("beyond the video") != std::string::npos);
    request.duration = 4.0;  // a preview: shorter on purpose
    scene.render.captions = {{1.0, "Early", "s.toml", 5}, {6.0, "Later", "s.toml", 9}};
    const RenderPlan plan = plan_render(request, scene);
    CHECK(plan.lesson.captions.size() == 1);
    bool noticed = false;
    for (const std::string& n : plan.notices) noticed |= n.find("6 s") != std::string::npos;
    CHECK(noticed);
}

TEST_CASE("a hold beyond the video: an error naming the scene line, or cut short for --duration") {
    Scene scene = two_disc_scene(0.2);
    scene.render.captions = {{8.0, "Held too long", "s.toml", 9, 3.0}};
    RenderRequest request;  // the default 10 s video
    try {
        (void)plan_render(request, scene);
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(e.kind() == ErrorKind::input);
        const std::string message = e.what();
        CHECK(message.find("s.toml:9") != std::string::npos);
        CHECK(message.find("render.captions.hold") != std::string::npos);
        CHECK(message.find("beyond the video") != std::string::npos);
    }
    request.duration = 9.0;
    scene.render.captions = {{1.0, "Held", "s.toml", 5, 1.0}, {7.0, "Cut", "s.toml", 9, 3.0}};
    const RenderPlan plan = plan_render(request, scene);
    REQUIRE(plan.lesson.captions.size() == 2);
    CHECK(plan.lesson.captions[1].hold == doctest::Approx(2.0));
}

TEST_CASE("the video's timeline: the card waits, holds freeze, a still only runs") {
    Scene scene = two_disc_scene(0.2);
    scene.title = "Two discs";
    scene.description = "They meet in the middle";
    scene.render.duration = 10.0;
    scene.render.captions = {{4.0, "Held", "s.toml", 5, 1.0}};
    RenderRequest request;
    request.fps = 10;
    const RenderPlan plan = plan_render(request, scene);
    const show::Timeline& timeline = plan.timeline;
    CHECK(timeline.frame_count() == 100);
    REQUIRE(timeline.segments.size() >= 4);
    CHECK(timeline.segments[0].kind == show::SegmentKind::card);
    CHECK_FALSE(timeline.segments[0].moves);
    CHECK(timeline.segments[0].end_frame == 20);
    CHECK(timeline.segment_at(40).kind == show::SegmentKind::hold);
    CHECK(timeline.segments.back().kind == show::SegmentKind::epilogue);
    // The simulation clock has as many frames as the video shows states.
    CHECK(plan.clock.count == timeline.sim_frame_count());
    CHECK(plan.clock.last_time == doctest::Approx(plan.clock.interval * (plan.clock.count - 1)));
    // --no-intro, --no-epilogue: the simulation from the first frame to the last.
    request.no_intro = true;
    request.no_epilogue = true;
    const RenderPlan bare = plan_render(request, scene);
    CHECK(bare.timeline.segments.front().kind == show::SegmentKind::run);
    CHECK(bare.timeline.segments.back().kind == show::SegmentKind::run);
    CHECK(bare.timeline.sim_frame_count() == 100 - 10);  // the hold's frames
    // A still: the video's last simulation frame, only running (no card, hold or summary).
    request = RenderRequest{};
    request.fps = 10;
    request.last_frame = true;
    const RenderPlan still = plan_render(request, scene);
    for (const show::Segment& s : still.timeline.segments) {
        CHECK(s.kind == show::SegmentKind::run);
        CHECK(s.moves);
    }
    CHECK(still.clock.count == plan.clock.count);
    CHECK(still.clock.last_time == plan.clock.last_time);
    // Holds and the card are read where captions are: not at --overlays none.
    request = RenderRequest{};
    request.fps = 10;
    request.overlays = "none";
    for (const show::Segment& s : plan_render(request, scene).timeline.segments)
        CHECK(s.kind == show::SegmentKind::run);
}

TEST_CASE("still_clock refuses a time more frame intervals away than int64 / double can count") {
    for (const auto& [at, speed] :
         {std::pair{1e18, 1.0}, std::pair{1e15, 1.0}, std::pair{1.0, 1e-300}}) {
        CAPTURE(at);
        try {
            (void)still_clock(at, speed, 30);
            FAIL("no error");
        } catch (const Error& e) {
            CHECK(e.kind() == ErrorKind::input);
            CHECK(std::string(e.what()).rfind("--at: ", 0) == 0);
        }
    }
    CHECK(still_clock(1e12, 1.0, 30).count == 30000000000001);  // far, but countable
}

TEST_CASE("a speed too small for any time step is named where it was written, not as a dt") {
    // 5e-324 / 30 is 0: before, "scene [render] dt: expected a positive time step, got '0'",
    // a field the user never wrote, without file or line.
    Scene scene = two_disc_scene(0.1);
    scene.render.speed = 5e-324;
    scene.render.speed_at = "s.toml:7: render.speed";
    RenderRequest request;
    request.scene = "two";
    try {
        (void)plan_render(request, scene);
        FAIL("accepted speed = 5e-324");
    } catch (const Error& e) {
        const std::string message = e.what();
        CAPTURE(message);
        CHECK(e.exit_code() == 2);
        CHECK(message.rfind("s.toml:7: render.speed: ", 0) == 0);
        CHECK(message.find("dt:") == std::string::npos);
    }
    request.speed = 5e-324;
    try {
        (void)plan_render(request, scene);
        FAIL("accepted --speed 5e-324");
    } catch (const Error& e) {
        CHECK(std::string(e.what()).rfind("--speed: ", 0) == 0);
    }
}

// Issue #29 item 7: `--dt A,B[,C[,D]]`, the dt trade-off in one picture.
TEST_CASE("--dt lists: 2 to 4 distinct positive steps, anything else exits naming --dt") {
    CHECK(parse_dt_list("0.01,0.02,0.04") == std::vector<double>{0.01, 0.02, 0.04});
    CHECK(parse_dt_list("0.04,0.01") == std::vector<double>{0.04, 0.01});  // the order given
    CHECK(parse_dt_list("1e-2,0.02,0.03,0.04").size() == 4);
    const auto message = [](const char* text) {
        try {
            (void)parse_dt_list(text, "--dt");
        } catch (const Error& e) {
            CHECK(e.kind() == ErrorKind::input);
            return std::string(e.what());
        }
        return std::string();
    };
    const std::string five = message("0.01,0.02,0.03,0.04,0.05");
    CHECK(five.starts_with("--dt: "));
    CHECK(five.find("has 5 steps") != std::string::npos);
    CHECK(five.find("2 to 4") != std::string::npos);
    CHECK(message("0.01,0.02,0.01").find("0.01 is given twice") != std::string::npos);
    CHECK(message("0.01,-0.02").find("got '-0.02'") != std::string::npos);
    CHECK(message("0.01,0").find("got '0'") != std::string::npos);
    CHECK(message("0.01,x").find("got 'x'") != std::string::npos);
    CHECK(message("0.01,").find("got ''") != std::string::npos);
    CHECK(message("0.01,inf").find("got 'inf'") != std::string::npos);
}

namespace {
/// A gas dense and fast enough that every step of 1/100 or more misses contacts.
Scene missing_gas() {
    Scene scene;
    scene.name = "misses";
    scene.box = Box{1.0, 1.0, Boundary::walls};
    GenerateSpec spec;
    spec.count = 200;
    spec.radius = 0.012;
    spec.seed = 11;
    generate_discs(scene, spec);
    return scene;
}

RenderRequest dt_list_request() {
    RenderRequest request;
    request.scene = "misses";
    request.size = "320x180";
    request.speed = 1.0;
    request.duration = 1.0;
    request.dt_list = {0.01, 0.02, 0.04};
    return request;
}
}  // namespace

TEST_CASE("--dt list: one time-driven panel per step, each missing what its engine alone misses") {
    const Scene scene = missing_gas();
    const RenderPlan plan = plan_render(dt_list_request(), scene);
    REQUIRE(plan.time_steps == std::vector<double>{0.01, 0.02, 0.04});
    CHECK(plan.time_engine.dt == 0.01);        // the work limits' estimate: the costliest
    CHECK(plan.replay == ReplayChoice::none);  // each panel fails at its own steps
    CHECK(plan.lesson.step_note.empty());      // no one note for all the panels
    // The scene's captions speak of two panels ("Left: ..."): the list's own caption instead.
    CHECK(plan.lesson.caption == show::step_list_caption);
    CHECK(plan.lesson.captions.empty());
    const show::CollisionSettings settings = collision_settings(plan);
    show::CollisionSimulation source(show::SceneView{scene}, settings);
    show::CollisionState frame;
    for (std::int64_t k = 0; k < plan.timeline.frame_count(); ++k) frame = source.state(k);
    REQUIRE(frame.panels.size() == 4);
    CHECK_FALSE(frame.panels.back().time_driven);
    std::uint64_t most_missed = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        const show::PanelState& panel = frame.panels[i];
        INFO("dt = " << plan.time_steps[i]);
        CHECK(panel.time_driven);
        CHECK(panel.compared_dt == plan.time_steps[i]);
        CHECK(panel.title.find(show::dt_text(plan.time_steps[i])) != std::string::npos);
        // What `collide simulate --engine time --dt X --until T` reports for the same scene.
        EngineOptions options = plan.time_engine;
        options.dt = plan.time_steps[i];
        auto alone = make_engine(scene, options);
        alone->advance_to(frame.time);
        CHECK(panel.measurements.missed_collisions == alone->measurements().missed_collisions);
        CHECK(panel.measurements.overlap_checks == alone->measurements().overlap_checks);
        most_missed = std::max(most_missed, panel.measurements.missed_collisions);
    }
    CHECK(most_missed > 0);  // a run where the steps differ in what they miss
    // Too small a dt costs work: half the step, twice the pair tests.
    CHECK(frame.panels[0].measurements.overlap_checks >
          frame.panels[2].measurements.overlap_checks);
}

TEST_CASE("--dt list beside what cannot show it: --mode event, --queue, --replay first") {
    const Scene scene = missing_gas();
    const auto option_of = [&](const RenderRequest& request) {
        try {
            (void)plan_render(request, scene);
        } catch (const Error& e) {
            const std::string message = e.what();
            return message.substr(0, message.find(':'));
        }
        return std::string("accepted");
    };
    RenderRequest request = dt_list_request();
    request.mode = "event";
    CHECK(option_of(request) == "--dt");
    request = dt_list_request();
    request.queue = 5;
    CHECK(option_of(request) == "--dt");
    request = dt_list_request();
    request.replay = "first";
    CHECK(option_of(request) == "--replay");
    request.replay = "none";
    CHECK(option_of(request) == "accepted");
    request = dt_list_request();
    request.mode = "time";  // the steps alone, without the event-driven panel
    CHECK(option_of(request) == "accepted");
}
