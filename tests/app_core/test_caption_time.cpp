// Captions timed so a class can read them (issue #44, item 6): in every built-in scene, at
// every mode (3D: its one), each caption the timeline shows is on screen, running or held, at least
// its reading time (show::caption_reading_seconds) in all. A caption a question, a replay or the
// next caption cuts to a fraction of a second (tunnelling's "Left: discs jump through the barrier",
// a third of a second before its question) is a sentence no student reads.
#include <doctest/doctest.h>
#include <fmt/core.h>

#include <algorithm>
#include <map>
#include <string>
#include <variant>

#include "collide/scene/load.hpp"
#include "collide/show/sphere_camera.hpp"
#include "collide/show/timeline.hpp"
#include "render_plan.hpp"
#include "replay_plan.hpp"

using namespace collide;
using namespace collide::app;

namespace {

/// Seconds of video each caption shows while the simulation runs or holds on it.
std::map<std::string, double> seconds_shown(const show::Timeline& timeline) {
    std::map<std::string, double> shown;
    for (const show::Segment& segment : timeline.segments) {
        if (segment.kind == show::SegmentKind::run || segment.kind == show::SegmentKind::hold)
            shown[segment.caption] += segment.end - segment.start;
    }
    return shown;
}

/// Checks each caption `plan` shows for its reading time.
void check_reading_time(const RenderPlan& plan) {
    for (const auto& [caption, seconds] : seconds_shown(plan.timeline)) {
        CAPTURE(caption);
        // Half a frame of rounding.
        CHECK(seconds + 0.5 / plan.fps >= show::caption_reading_seconds(caption));
    }
}

RenderRequest lesson_request(const std::string& name, const std::string& mode,
                             const std::string& quality) {
    RenderRequest request;
    request.scene = name;
    request.output = "unused.mp4";
    request.quality = quality;
    request.mode = mode;
    return request;
}

}  // namespace

TEST_CASE(
    "every caption of a built-in 2D scene is on screen for its reading time, at every preset and "
    "mode") {
    for (const std::string name : {"billiards", "brownian", "dense-fluid", "diffusion", "gas",
                                   "maxwell-boltzmann", "newtons-cradle", "tunnelling"}) {
        const Scene scene = load_scene(name, COLLIDE_ASSETS_DIR);
        const ReplayFinder finder = [&scene](const RenderPlan& draft) {
            return find_replays(scene, draft);
        };
        for (const std::string quality : {"l", "m", "h"}) {
            for (const std::string mode : {"both", "event", "time"}) {
                CAPTURE(name);
                CAPTURE(quality);
                CAPTURE(mode);
                check_reading_time(plan_render(lesson_request(name, mode, quality), scene, finder));
            }
        }
    }
}

TEST_CASE("every caption of a built-in 3D scene is on screen for its reading time") {
    for (const std::string name : {"alder-wainwright", "gas-3d", "spheres-freeze"}) {
        CAPTURE(name);
        const AnyScene any = load_any_scene(name);
        const SphereScene* spheres = std::get_if<SphereScene>(&any);
        REQUIRE(spheres != nullptr);
        // Planned as `collide render` plans it: through its stand-in discs, without replays.
        const Scene stand_in = show::stand_in_scene(*spheres);
        for (const std::string quality : {"l", "m", "h"}) {
            CAPTURE(quality);
            check_reading_time(plan_render(lesson_request(name, "both", quality), stand_in));
        }
    }
}

TEST_CASE("a slowed video keeps its captions' reading time, and says which it drops") {
    // --code's slow motion (16x) and --slow-motion 2: the captions move to the moments they were
    // written for (show::lesson_plan), so they may crowd together or fall after the run; each
    // shown is still read, each dropped is named.
    for (const std::string name :
         {"billiards", "brownian", "gas", "newtons-cradle", "tunnelling"}) {
        const Scene scene = load_scene(name, COLLIDE_ASSETS_DIR);
        const ReplayFinder finder = [&scene](const RenderPlan& draft) {
            return find_replays(scene, draft);
        };
        for (int pace = 0; pace < 2; ++pace) {
            CAPTURE(name);
            CAPTURE(pace);
            RenderRequest request = lesson_request(name, "both", "m");
            if (pace == 0) {
                request.queue = 4;
                request.code = true;
            }
            if (pace == 1) request.slow_motion = 2.0;
            const RenderPlan plan = plan_render(request, scene, finder);
            check_reading_time(plan);
            const std::map<std::string, double> shown = seconds_shown(plan.timeline);
            std::size_t dropped = 0;
            for (const CaptionCue& cue : scene.render.captions) {
                CAPTURE(cue.text);
                const std::string named = fmt::format("the caption at {:g} s", cue.at);
                const bool said = std::any_of(
                    plan.notices.begin(), plan.notices.end(),
                    [&](const std::string& n) { return n.find(named) != std::string::npos; });
                CHECK((shown.count(cue.text) == 1 || said));
                dropped += said ? 1 : 0;
            }
            if (pace == 0) CHECK(dropped > 0);  // 16x slower: the later moments are never reached
        }
    }
}
