// Brownian's caption "Its trail is a random walk" (issue #44, item 6) must come over a trail a
// student sees as a walk: measured on the engine the video runs, up to the simulation time of
// the caption's first frame, the tracer's path (its trail) reaches over several of its own
// diameters and turns, not a hook hidden under the disc.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "collide/scene/load.hpp"
#include "collide/sim/engine.hpp"
#include "render_plan.hpp"
#include "replay_plan.hpp"

using namespace collide;
using namespace collide::app;

namespace {

constexpr const char* walk_caption = "Its trail is a random walk: Brownian motion";

/// The simulation frame the caption first shows, as `collide render -q quality` plans it.
double caption_time(const Scene& scene, const std::string& quality) {
    RenderRequest request;
    request.scene = "brownian";
    request.output = "unused.mp4";
    request.quality = quality;
    // With its replays, as the video plans it: a replay holds the simulation.
    const ReplayFinder finder = [&scene](const RenderPlan& draft) {
        return find_replays(scene, draft);
    };
    const RenderPlan plan = plan_render(request, scene, finder);
    for (const show::Segment& segment : plan.timeline.segments)
        if (segment.caption == walk_caption) return plan.clock.time(segment.sim_frame);
    return -1.0;
}

/// The tracer's path (the centre every 0.1 time units; a frame at -q l is 0.33) up to `until`.
std::vector<Vec2> tracer_path(const Scene& scene, std::size_t tracer, double until) {
    // The event-driven engine, exact: the walk the right panel shows.
    const std::unique_ptr<Engine> engine = make_engine(scene, EngineOptions{});
    std::vector<Vec2> path;
    for (double t = 0.0; t <= until; t += 0.1) {
        engine->advance_to(t);
        path.push_back(engine->snapshot().discs[tracer].position);
    }
    return path;
}

}  // namespace

TEST_CASE("brownian: by its random-walk caption the tracer's trail is a crooked walk") {
    // The scene's own discs and two other draws of them (`--seed`): the walk is the physics',
    // not one lucky seed's.
    for (const std::optional<std::uint64_t> seed :
         {std::optional<std::uint64_t>{}, std::optional<std::uint64_t>{1},
          std::optional<std::uint64_t>{2}}) {
        CAPTURE(seed.value_or(0));
        const Scene scene = load_scene("brownian", COLLIDE_ASSETS_DIR, SceneOptions{seed});
        const auto tracer =
            static_cast<std::size_t>(std::find_if(scene.discs.begin(), scene.discs.end(),
                                                  [](const Disc& d) { return d.tag == "tracer"; }) -
                                     scene.discs.begin());
        REQUIRE(tracer < scene.discs.size());
        const double diameter = 2.0 * scene.discs[tracer].radius;
        // -q l and -q m: the same simulation time per second of video, the caption's frame may
        // differ by one. One run to the later of the two; each looks at its part.
        const double until_l = caption_time(scene, "l");
        const double until_m = caption_time(scene, "m");
        REQUIRE(until_l > 0.0);
        REQUIRE(until_m > 0.0);
        const std::vector<Vec2> whole = tracer_path(scene, tracer, std::max(until_l, until_m));
        for (const double until : {until_l, until_m}) {
            CAPTURE(until);
            const auto points =
                std::min(whole.size(), static_cast<std::size_t>(until / 0.1 + 1e-6) + 1);
            const std::vector<Vec2> path(whole.begin(),
                                         whole.begin() + static_cast<std::ptrdiff_t>(points));
            double x0 = path.front().x;
            double x1 = x0;
            double y0 = path.front().y;
            double y1 = y0;
            double length = 0.0;
            for (std::size_t k = 1; k < path.size(); ++k) {
                x0 = std::min(x0, path[k].x);
                x1 = std::max(x1, path[k].x);
                y0 = std::min(y0, path[k].y);
                y1 = std::max(y1, path[k].y);
                length += std::hypot(path[k].x - path[k - 1].x, path[k].y - path[k - 1].y);
            }
            // Far enough to be seen beside the disc: the trail's extent at least three diameters
            // (the disc covers one), and its length several times that.
            const double extent = std::max(x1 - x0, y1 - y0) / diameter;
            CHECK(extent >= 3.0);
            CHECK(length / diameter >= 10.0);
            // Crooked: over stretches of a quarter diameter, the heading turns by more than 60
            // degrees again and again; a drift or a single hook would not.
            std::vector<Vec2> steps;
            Vec2 from = path.front();
            for (const Vec2& p : path) {
                if (std::hypot(p.x - from.x, p.y - from.y) < 0.25 * diameter) continue;
                steps.push_back({p.x - from.x, p.y - from.y});
                from = p;
            }
            int turns = 0;
            for (std::size_t k = 1; k < steps.size(); ++k)
                if (steps[k].x * steps[k - 1].x + steps[k].y * steps[k - 1].y <
                    0.5 * std::hypot(steps[k].x, steps[k].y) *
                        std::hypot(steps[k - 1].x, steps[k - 1].y))
                    ++turns;
            MESSAGE("extent ", extent, " diameters, length ", length / diameter, ", turns ", turns,
                    ", until t = ", until);
            CHECK(turns >= 4);
        }
    }
}
