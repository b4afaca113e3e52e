// The event-driven panel's next collision at the lesson level (lesson_next.cpp): its time to go
// sits on a plate that never covers the two discs, and covers no other disc where some place
// near the line is free (a break's rack, a cradle's row).
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "../support/skip.hpp"
#include "drawn_plates.hpp"
#include "layout.hpp"
#include "render_fixtures.hpp"
#include "theme.hpp"

namespace collide::render {
namespace {

using test::count_near;
using test::px;

TEST_CASE("the next collision's label covers neither the pair nor the discs above and below it") {
    if (!std::filesystem::exists(RenderConfig{}.font_path))
        COLLIDE_SKIP_TEST("no DejaVu Sans at " << RenderConfig{}.font_path);
    // A pair meeting in the middle of the box, one disc just above the pair's middle and one
    // just below: the line's middle is taken by the pair, and the places straight above and
    // below it by the two bystanders.
    Snapshot s;
    s.box = {10.0, 10.0, Boundary::walls};
    const Rgb8 pair_color{200, 60, 60};
    const Rgb8 bystander_color{40, 200, 40};
    const DiscState a = test::disc_at({4.0, 5.0}, 0.3, pair_color);
    const DiscState b = test::disc_at({6.0, 5.0}, 0.3, pair_color);
    s.discs = {a, b, test::disc_at({5.0, 5.9}, 0.35, bystander_color),
               test::disc_at({5.0, 4.1}, 0.35, bystander_color)};
    NextCollisionView next;
    next.lines = {{a.position, b.position}};
    next.text = "next hit in 0.42";
    next.short_text = "in 0.42";
    next.label_at = {5.0, 5.0};
    next.keep_clear = {{a.position, a.radius}, {b.position, b.radius}};

    const RenderConfig config = test::lesson_config(854, 480);
    Renderer renderer(config, test::test_backend());
    FrameContent frame;
    frame.panels = {{&s, "Event-driven", {}}};
    frame.panels[0].figures = {{"12", "collisions", false}};
    frame.panels[0].next_collision = next;
    const Image image = renderer.render(frame);
    test::dump_if_requested(image, "next_collision_label");

    const PanelLayout panel = test::one_panel_layout(config, s.box);
    const Rgb8 label = next_event_color(config.theme);
    const auto label_pixels_around = [&](Vec2 centre, double radius) {
        const PointF c = panel.to_pixels(centre, s.box);
        const int r = px(static_cast<float>(radius * panel.scale)) + 2;
        return count_near(image, label, 30, px(c.x) - r, px(c.y) - r, px(c.x) + r + 1,
                          px(c.y) + r + 1);
    };
    // The label is drawn (in the box, beyond the thin line's own pixels) ...
    const int in_box = count_near(image, label, 30, px(panel.box.x0), px(panel.box.y0),
                                  px(panel.box.x1), px(panel.box.y1));
    const PointF from = panel.to_pixels(a.position, s.box);
    const PointF to = panel.to_pixels(b.position, s.box);
    const int on_line =
        count_near(image, label, 30, px(from.x), px(from.y) - 3, px(to.x) + 1, px(from.y) + 4);
    CHECK(in_box - on_line > 40);
    // ... and none of its letters lies on a bystander.
    for (std::size_t k = 2; k < s.discs.size(); ++k) {
        CAPTURE(k);
        CHECK(label_pixels_around(s.discs[k].position, s.discs[k].radius) == 0);
    }
    // The bystanders are still their own colour at their centres.
    for (std::size_t k = 2; k < s.discs.size(); ++k) {
        const PointF c = panel.to_pixels(s.discs[k].position, s.box);
        CHECK(count_near(image, bystander_color, 30, px(c.x) - 2, px(c.y) - 2, px(c.x) + 3,
                         px(c.y) + 3) == 25);
    }
}

}  // namespace
}  // namespace collide::render
