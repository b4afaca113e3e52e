// A replay's labels (lesson_replay.cpp) sit beside the ghosts they name, never on one: the
// class must see the discs the words are about (#44 item 3). Read from the plates the painter
// drew (--layout-json's other_text) against the ghosts' circles in pixels.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "../support/skip.hpp"
#include "drawn_plates.hpp"
#include "layout.hpp"
#include "render_fixtures.hpp"

namespace collide::render {

using test::Plate;
using test::plates;
using test::touches;

TEST_CASE("a replay's labels sit beside the ghosts, not on them, wherever the spot is") {
    if (!std::filesystem::exists(RenderConfig{}.font_path))
        COLLIDE_SKIP_TEST("no DejaVu Sans at " << RenderConfig{}.font_path);
    for (const int height : {480, 720}) {
        // A label asked for above a ghost with another ghost right there; one beside a ghost at
        // the box's right edge (pushed back into the box, it would land on the ghost); one below
        // a ghost with two more ghosts under it.
        for (const double edge : {5.0, 9.4}) {
            CAPTURE(height);
            CAPTURE(edge);
            Snapshot s;
            s.box = {10.0, 10.0, Boundary::walls};
            s.discs = {test::disc_at({1.0, 1.0}, 0.1, {90, 90, 90})};
            ReplayView replay;
            replay.heading = "Replay: 1 step, 8x enlarged";
            const std::vector<GhostDisc> ghosts = {
                {{edge, 5.0}, 0.5, false, false, 1.0F},
                {{edge, 6.2}, 0.5, false, true, 1.0F},
                {{edge, 3.8}, 0.5, true, false, 1.0F},
                {{edge, 2.6}, 0.5, false, false, 1.0F},
            };
            replay.ghosts = ghosts;
            BoxLabel above{{edge, 5.0}, "check t = 0.08"};
            above.side = LabelSide::above;
            above.clear = 0.5;
            BoxLabel right{{edge, 6.2}, "hit t = 0.0613, unseen"};
            right.side = LabelSide::right;
            right.clear = 1.0;
            right.failure = true;
            BoxLabel below{{edge, 5.0}, "check t = 0.12"};
            below.side = LabelSide::below;
            below.clear = 0.5;
            replay.labels = {above, right, below};

            const RenderConfig config = test::lesson_config(height * 16 / 9, height);
            Renderer renderer(config, test::test_backend());
            FrameContent frame;
            frame.panels = {{&s, "Time-driven", {}}};
            frame.panels[0].figures = {{"3", "missed", true}};
            frame.panels[0].replay = replay;
            const Image image = renderer.render(frame);
            test::dump_if_requested(image, "replay_labels_" + std::to_string(height));

            const PanelLayout panel = test::one_panel_layout(config, s.box);
            const std::vector<Plate> drawn = plates(renderer, frame);
            for (const BoxLabel& label : replay.labels) {
                CAPTURE(label.text);
                const auto plate = std::find_if(drawn.begin(), drawn.end(), [&](const Plate& p) {
                    return p.text == label.text;
                });
                REQUIRE(plate != drawn.end());
                // Inside the box, on no ghost ...
                CHECK(plate->rect.x0 >= panel.box.x0 - 0.5F);
                CHECK(plate->rect.x1 <= panel.box.x1 + 0.5F);
                for (const GhostDisc& g : ghosts) {
                    const PointF c = panel.to_pixels(g.where, s.box);
                    CHECK_FALSE(
                        touches(plate->rect, c, static_cast<float>(g.radius * panel.scale), 0.0F));
                }
                // ... and near the ghost it names (within a few ghost sizes).
                const PointF at = panel.to_pixels(label.at, s.box);
                const float centre_x = 0.5F * (plate->rect.x0 + plate->rect.x1);
                const float centre_y = 0.5F * (plate->rect.y0 + plate->rect.y1);
                CHECK(std::hypot(centre_x - at.x, centre_y - at.y) <
                      0.5F * plate->rect.width() + 6.0F * static_cast<float>(panel.scale));
                for (const Plate& other : drawn) {
                    if (&other != &*plate) CHECK_FALSE(overlaps(plate->rect, other.rect));
                }
            }
        }
    }
}

}  // namespace collide::render
