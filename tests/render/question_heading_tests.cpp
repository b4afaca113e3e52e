// A question's heading ("Think: 3", "Answer: B") covers no disc and no letter (#45): the painter
// puts it at the top of the box where that is clear of the discs the view names (keep_clear),
// else at the nearest clear place. Read from the plates the painter drew (--layout-json's
// other_text) against the discs' circles in pixels, for many random boxes of discs.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "../support/skip.hpp"
#include "drawn_plates.hpp"
#include "layout.hpp"
#include "render_fixtures.hpp"

namespace collide::render {
namespace {

using test::Plate;
using test::plates;
using test::touches;

/// `count` discs of radius `radius` at random places that do not overlap, in a unit box; the
/// first one at the top middle, where a heading drawn at the top would cover it.
Snapshot random_discs(std::uint32_t seed, int count, double radius) {
    Snapshot s;
    s.box = {1.0, 1.0, Boundary::walls};
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> place(radius, 1.0 - radius);
    s.discs.push_back(test::disc_at({0.5, radius + 0.01}, radius, {200, 150, 40}));
    for (int tries = 0; tries < 20000 && static_cast<int>(s.discs.size()) < count; ++tries) {
        const Vec2 p{place(rng), place(rng)};
        const bool free = std::none_of(s.discs.begin(), s.discs.end(), [&](const DiscState& d) {
            return norm(d.position - p) < d.radius + radius;
        });
        if (free) s.discs.push_back(test::disc_at(p, radius, {200, 150, 40}));
    }
    return s;
}

}  // namespace

TEST_CASE("a question's heading covers no disc and no letter, for many boxes of discs") {
    if (!std::filesystem::exists(RenderConfig{}.font_path))
        COLLIDE_SKIP_TEST("no DejaVu Sans at " << RenderConfig{}.font_path);
    for (const int height : {480, 720}) {
        const RenderConfig config = test::lesson_config(height * 16 / 9, height);
        Renderer renderer(config, test::test_backend());
        for (std::uint32_t seed = 1; seed <= 12; ++seed) {
            for (const std::string heading : {"Think: 3", "Answer: B"}) {
                CAPTURE(height);
                CAPTURE(seed);
                CAPTURE(heading);
                // From a few discs to a box three times as crowded as gas (16 % covered).
                const int count = 5 + static_cast<int>(seed) * 3;
                const Snapshot s = random_discs(seed, count, 0.035);
                ReplayView replay;
                replay.heading = heading;
                for (const DiscState& d : s.discs)
                    replay.keep_clear.push_back({d.position, d.radius});
                // Two letters where show puts them: on points clear of the discs.
                BoxLabel a{{0.5, 0.12}, "A"};
                a.side = LabelSide::over;
                BoxLabel b{{0.3, 0.5}, "B"};
                b.side = LabelSide::over;
                replay.labels = {a, b};

                FrameContent frame;
                frame.panels = {{&s, "Event-driven", {}}};
                frame.panels[0].replay = replay;
                const Image image = renderer.render(frame);
                test::dump_if_requested(image, "question_heading_" + std::to_string(height) + "_" +
                                                   std::to_string(seed));

                const PanelLayout panel = test::one_panel_layout(config, s.box);
                const std::vector<Plate> drawn = plates(renderer, frame);
                const auto plate = std::find_if(drawn.begin(), drawn.end(),
                                                [&](const Plate& p) { return p.text == heading; });
                REQUIRE(plate != drawn.end());
                CHECK(plate->rect.x0 >= panel.box.x0 - 0.5F);
                CHECK(plate->rect.x1 <= panel.box.x1 + 0.5F);
                CHECK(plate->rect.y0 >= panel.box.y0 - 0.5F);
                CHECK(plate->rect.y1 <= panel.box.y1 + 0.5F);
                for (const DiscState& d : s.discs) {
                    const PointF c = panel.to_pixels(d.position, s.box);
                    CHECK_FALSE(
                        touches(plate->rect, c, static_cast<float>(d.radius * panel.scale), 0.0F));
                }
                for (const Plate& other : drawn) {
                    if (other.text == "A" || other.text == "B")
                        CHECK_FALSE(overlaps(plate->rect, other.rect));
                }
            }
        }
    }
}

TEST_CASE("a heading without discs to keep clear of stays at the top middle of the box") {
    if (!std::filesystem::exists(RenderConfig{}.font_path))
        COLLIDE_SKIP_TEST("no DejaVu Sans at " << RenderConfig{}.font_path);
    const RenderConfig config = test::lesson_config(854, 480);
    Renderer renderer(config, test::test_backend());
    Snapshot s;
    s.box = {1.0, 1.0, Boundary::walls};
    s.discs = {test::disc_at({0.5, 0.05}, 0.04, {200, 150, 40})};
    FrameContent frame;
    frame.panels = {{&s, "Event-driven", {}}};
    frame.panels[0].replay.heading = "Replay: one step, 9x enlarged";
    (void)renderer.render(frame);
    const PanelLayout panel = test::one_panel_layout(config, s.box);
    const std::vector<Plate> drawn = plates(renderer, frame);
    const auto plate = std::find_if(drawn.begin(), drawn.end(), [&](const Plate& p) {
        return p.text == frame.panels[0].replay.heading;
    });
    REQUIRE(plate != drawn.end());
    CHECK(0.5F * (plate->rect.x0 + plate->rect.x1) ==
          doctest::Approx(0.5F * (panel.box.x0 + panel.box.x1)).epsilon(0.01));
    CHECK(plate->rect.y0 < panel.box.y0 + plate->rect.height());
}

}  // namespace collide::render
