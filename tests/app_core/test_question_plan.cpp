// Where a plan asks its questions (ask_questions, issue #45): a question that cannot be asked
// at its moment moves to the first later one that can, with a notice, and its answer is the
// engine's there; one that cannot be asked at all is refused naming its file, line and field
// (left out with a notice when --duration set the video's length); a how-many question is
// followed by the second it counts; the built-in scenes ask without a notice at every preset
// and mode, their candidates drawn apart.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "../show/question_drawing_fixture.hpp"
#include "collide/error.hpp"
#include "collide/scene/load.hpp"
#include "render_plan.hpp"
#include "replay_plan.hpp"

using namespace collide;
using namespace collide::app;

namespace {

ReplayFinder finder(const Scene& scene) {
    return [&scene](const RenderPlan& draft) { return find_replays(scene, draft); };
}

/// Two discs far apart on one line, the first moving towards the second at rest (they meet at
/// simulation time `meets`), two more at rest out of their way; one question of `kind` at `at`
/// seconds of video, written on line 12 of "q.toml"; `duration` seconds of video.
Scene quiet_scene(double meets, double at, QuestionKind kind, double duration) {
    Scene s;
    s.name = "quiet";
    s.box = Box{4.0, 1.0, Boundary::walls};
    const double r = 0.02;
    s.discs.push_back(Disc{{0.5, 0.4}, {(2.0 - 2.0 * r) / meets, 0.0}, r, 1.0, {}, ""});
    s.discs.push_back(Disc{{2.5, 0.4}, {0.0, 0.0}, r, 1.0, {}, ""});
    s.discs.push_back(Disc{{0.3, 0.9}, {0.0, 0.0}, r, 1.0, {}, ""});
    s.discs.push_back(Disc{{3.7, 0.9}, {0.0, 0.0}, r, 1.0, {}, ""});
    s.render.duration = duration;
    s.render.speed = 1.0;
    QuestionCue cue;
    cue.at = at;
    cue.kind = kind;
    cue.file = "q.toml";
    cue.line = 12;
    s.render.questions = {cue};
    return s;
}

RenderRequest request_of(const std::string& scene) {
    RenderRequest request;
    request.scene = scene;
    request.output = "unused.mp4";
    request.fps = 30;
    return request;
}

/// The simulation frame question `i` freezes on (-1: not asked).
std::int64_t frozen_frame(const RenderPlan& plan, int i) {
    for (const show::Segment& segment : plan.timeline.segments) {
        if (segment.kind == show::SegmentKind::question && segment.question == i)
            return segment.sim_frame;
    }
    return -1;
}

/// The first video frame of question `i`'s segment (-1: not asked).
std::int64_t question_video_frame(const RenderPlan& plan, int i) {
    for (const show::Segment& segment : plan.timeline.segments) {
        if (segment.kind == show::SegmentKind::question && segment.question == i)
            return segment.first_frame;
    }
    return -1;
}

bool says(const std::vector<std::string>& notices, const std::string& words) {
    return std::any_of(notices.begin(), notices.end(),
                       [&](const std::string& n) { return n.find(words) != std::string::npos; });
}

/// The message of the Error(input) plan_render throws ("" when it plans).
std::string refusal(const RenderRequest& request, const Scene& scene) {
    try {
        (void)plan_render(request, scene, finder(scene));
    } catch (const Error& e) {
        CHECK(e.kind() == ErrorKind::input);
        return e.what();
    }
    return {};
}

/// A next-collision question answered on simulation frame `frame` of `plan` by a fresh engine
/// stepped as the video steps it.
show::QuestionAnswer asked_on(const Scene& scene, const RenderPlan& plan, std::int64_t frame) {
    const std::unique_ptr<Engine> engine = make_engine(scene, plan.event_engine);
    for (std::int64_t j = 0; j <= frame; ++j) engine->advance_to(plan.clock.time(j));
    const show::FrameClock& clock = plan.clock;
    return show::answer_next_collision(
        *engine, engine->snapshot(),
        [&clock, frame](std::int64_t i) { return clock.time(frame + i); }, plan.fps, 1);
}

}  // namespace

TEST_CASE("a next-collision question in a quiet stretch moves to the first moment it is asked") {
    for (int seed = 0; seed < 6; ++seed) {
        CAPTURE(seed);
        // They meet 20 .. 25 s into the run: askable 10 s (300 frames) before, not at 3 s.
        const double meets = 20.0 + static_cast<double>(seed);
        const Scene scene = quiet_scene(meets, 3.0, QuestionKind::next_collision, 40.0);
        const RenderPlan plan = plan_render(request_of("quiet"), scene, finder(scene));
        REQUIRE(plan.questions.size() == 1);
        const show::QuestionAnswer& answer = plan.questions.front();
        REQUIRE(answer.askable);
        const std::int64_t frozen = frozen_frame(plan, 0);
        CHECK(answer.sim_frame == frozen);
        // The engine's own next collision there: the pair, at their meeting.
        const show::QuestionAnswer fresh = asked_on(scene, plan, frozen);
        REQUIRE(fresh.askable);
        const CollisionRecord& hit = answer.candidates[answer.answer];
        CHECK(hit.kind == CollisionKind::pair);
        CHECK(std::min(hit.a, hit.b) == 0);
        CHECK(std::max(hit.a, hit.b) == 1);
        CHECK(hit.t == doctest::Approx(meets).epsilon(1e-9));
        CHECK(hit.t == fresh.candidates[fresh.answer].t);
        // The first such moment: one frame earlier the engine has nothing to say.
        CHECK_FALSE(asked_on(scene, plan, frozen - 1).askable);
        CHECK(says(plan.notices, "q.toml:12: render.questions.at: moved from 3 s to "));
    }
}

TEST_CASE(
    "a question with no moment to ask is refused naming its field, or left out with "
    "--duration") {
    // They meet after the video's end: nothing to ask at 3 s nor later.
    Scene scene = quiet_scene(200.0, 3.0, QuestionKind::next_collision, 20.0);
    RenderRequest request = request_of("quiet");
    const std::string said = refusal(request, scene);
    CHECK_MESSAGE(
        said.find("q.toml:12: render.questions.at: nothing to ask at 3 s") != std::string::npos,
        said);
    request.duration = 20.0;
    const RenderPlan cut = plan_render(request, scene, finder(scene));
    CHECK(cut.questions.empty());
    CHECK(frozen_frame(cut, 0) == -1);
    CHECK(says(cut.notices, "q.toml:12: render.questions.at: nothing to ask at 3 s"));
    CHECK(says(cut.notices, "not asked"));

    // A will-see question in the same quiet video: no step of the time-driven engine fails.
    scene.render.questions.front().kind = QuestionKind::will_see;
    request.duration.reset();
    const std::string unseen = refusal(request, scene);
    CHECK_MESSAGE(unseen.find("q.toml:12: render.questions.at: nothing to ask at 3 s: the "
                              "time-driven engine misses no collision") != std::string::npos,
                  unseen);

    // No room for 3 s of thought and 2.5 s of answer before the summary card: refused too.
    scene = quiet_scene(10.0, 16.0, QuestionKind::next_collision, 20.0);
    request.duration.reset();
    const std::string full = refusal(request, scene);
    CHECK_MESSAGE(full.find("q.toml:12: render.questions.at: no room at 16 s") != std::string::npos,
                  full);
    request.duration = 20.0;
    CHECK(says(plan_render(request, scene, finder(scene)).notices, "no room at 16 s"));
}

TEST_CASE(
    "a how-many question is followed by the second it counts, else refused with the latest "
    "moment") {
    // Twenty discs in a small box: collisions every second. No card, no summary: the video is
    // the run, the question (2 s) and its answer (2.5 s).
    Scene scene = quiet_scene(1.0, 5.0, QuestionKind::how_many, 10.0);
    for (int i = 0; i < 16; ++i) {
        const double x = 0.2 + 0.23 * (i % 8);
        const double y = 0.2 + 0.5 * (i / 8);
        scene.discs.push_back(Disc{{x, y}, {0.3 * ((i % 3) - 1.0), 0.2}, 0.02, 1.0, {}, ""});
    }
    scene.render.questions.front().think = 2.0;
    RenderRequest request = request_of("quiet");
    request.no_intro = true;
    request.no_epilogue = true;
    // At 5 s: the answer ends at 9.5 s, half a second before the end.
    const std::string said = refusal(request, scene);
    CHECK_MESSAGE(said.find("q.toml:12: render.questions.at: a how-many question at 5 s") !=
                      std::string::npos,
                  said);
    CHECK_MESSAGE(said.find("the video runs 0.50 s after it; ask by 4.50 s") != std::string::npos,
                  said);
    // At the moment it names: asked, with the whole next second shown after the answer.
    for (const double at : {4.5, 3.0}) {
        CAPTURE(at);
        scene.render.questions.front().at = at;
        const RenderPlan plan = plan_render(request, scene, finder(scene));
        REQUIRE(plan.questions.size() == 1);
        CHECK(plan.questions.front().askable);
        const std::int64_t frozen = frozen_frame(plan, 0);
        CHECK(question_video_frame(plan, 0) == static_cast<std::int64_t>(at * 30 + 0.5));
        CHECK(plan.timeline.last_sim_frame() >= frozen + plan.fps);
        CHECK_FALSE(says(plan.notices, "render.questions"));
    }
    scene.render.questions.front().at = 4.6;
    CHECK(refusal(request, scene).find("ask by 4.50 s") != std::string::npos);
}

TEST_CASE("the built-in scenes ask their questions without a notice, at every preset and mode") {
    for (const std::string name : {"gas", "billiards", "tunnelling"}) {
        const Scene scene = load_scene(name, COLLIDE_ASSETS_DIR);
        REQUIRE_FALSE(scene.render.questions.empty());
        for (const std::string quality : {"l", "m", "h"}) {
            for (const std::string mode : {"both", "event", "time"}) {
                CAPTURE(name);
                CAPTURE(quality);
                CAPTURE(mode);
                RenderRequest request;
                request.scene = name;
                request.output = "unused.mp4";
                request.quality = quality;
                request.mode = mode;
                const RenderPlan plan = plan_render(request, scene, finder(scene));
                // Each question its panels answer is asked (gas and billiards ask only the
                // event-driven panel's: none with --mode time).
                CHECK(std::all_of(plan.questions.begin(), plan.questions.end(),
                                  [](const show::QuestionAnswer& a) { return a.askable; }));
                CHECK(plan.questions.size() ==
                      static_cast<std::size_t>(std::count_if(
                          scene.render.questions.begin(), scene.render.questions.end(),
                          [&](const QuestionCue& cue) {
                              return mode == "both" ||
                                     (mode == "event" ? show::needs_event_panel(cue.kind)
                                                      : show::needs_time_panel(cue.kind));
                          })));
                for (const std::string& notice : plan.notices) {
                    CAPTURE(notice);
                    // Only the mode's own: a question its one panel cannot answer.
                    const bool about_questions =
                        notice.find("render.questions") != std::string::npos;
                    CHECK((!about_questions ||
                           notice.find("-driven panel; not asked") != std::string::npos));
                }
            }
        }
    }
}

TEST_CASE("the built-in scenes' next-collision candidates are drawn apart, lines never crossing") {
    for (const std::string name : {"gas", "billiards", "tunnelling"}) {
        const Scene scene = load_scene(name, COLLIDE_ASSETS_DIR);
        for (const std::string quality : {"l", "m"}) {
            for (const std::string mode : {"both", "event"}) {
                CAPTURE(name);
                CAPTURE(quality);
                CAPTURE(mode);
                RenderRequest request = request_of(name);
                request.quality = quality;
                request.mode = mode;
                const RenderPlan plan = plan_render(request, scene, finder(scene));
                for (std::size_t i = 0; i < plan.questions.size(); ++i) {
                    const show::QuestionAnswer& answer = plan.questions[i];
                    if (answer.kind != QuestionKind::next_collision) continue;
                    CAPTURE(i);
                    REQUIRE(answer.askable);
                    // The frozen picture, as the video steps its engine there.
                    const std::unique_ptr<Engine> engine = make_engine(scene, plan.event_engine);
                    for (std::int64_t j = 0; j <= answer.sim_frame; ++j)
                        engine->advance_to(plan.clock.time(j));
                    const Snapshot now = engine->snapshot();
                    const ReplayView view =
                        show::question_view(answer, now, plan.clock, 2.5, false);
                    const double margin =
                        show::drawing_gap_share * std::min(now.box.width, now.box.height);
                    CHECK(test::closest_candidates(answer, view, now) >= margin * (1.0 - 1e-9));
                }
            }
        }
    }
}
