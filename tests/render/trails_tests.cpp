// Trails of tagged discs: history across frames, and in periodic boxes a step across the seam is
// drawn on both sides, cut at the edges, never as a line across the whole box.
#include <doctest/doctest.h>

#include <algorithm>

#include "layout.hpp"
#include "render_fixtures.hpp"
#include "trails.hpp"

namespace collide::render {
namespace {

TEST_CASE("clip_to_box keeps the part of a segment inside the box") {
    const Box box{10.0, 5.0, Boundary::periodic};
    const auto inside = clip_to_box(box, {9.0, 2.0}, {11.0, 3.0});
    REQUIRE(inside.has_value());
    CHECK(inside->first.x == doctest::Approx(9.0));
    CHECK(inside->second.x == doctest::Approx(10.0));
    CHECK(inside->second.y == doctest::Approx(2.5));
    CHECK_FALSE(clip_to_box(box, {11.0, 1.0}, {12.0, 1.0}).has_value());
    const auto whole = clip_to_box(box, {1.0, 1.0}, {2.0, 2.0});
    REQUIRE(whole.has_value());
    CHECK(whole->first.x == doctest::Approx(1.0));
    CHECK(whole->second.y == doctest::Approx(2.0));
}

TEST_CASE("trail history keeps the last trail_length positions of tagged discs") {
    TrailHistory history(3);
    Snapshot s;
    s.box = {10.0, 10.0, Boundary::walls};
    s.discs = {test::disc_at({1.0, 1.0}, 0.1, {255, 0, 0}),
               test::disc_at({5.0, 5.0}, 0.1, {0, 0, 255})};
    s.discs[0].tagged = true;
    for (int i = 0; i < 5; ++i) {
        s.time = i;
        s.discs[0].position = {1.0 + i, 1.0};
        history.update(s);
    }
    const std::vector<Vec2> path = history.points(0);
    REQUIRE(path.size() == 3);
    CHECK(path.front().x == doctest::Approx(3.0));
    CHECK(path.back().x == doctest::Approx(5.0));
    CHECK(history.points(1).empty());  // not tagged
    s.time = 0.0;                      // time going backwards resets the history
    history.update(s);
    CHECK(history.points(0).size() == 1);
}

TEST_CASE("a whole-path trail keeps its start past trail_length, thinned, within the length") {
    TrailHistory history(8, true);
    Snapshot s;
    s.box = {1000.0, 10.0, Boundary::walls};
    s.discs = {test::disc_at({0.0, 1.0}, 0.1, {255, 0, 0})};
    s.discs[0].tagged = true;
    for (int i = 0; i < 100; ++i) {
        s.time = i;
        s.discs[0].position = {static_cast<double>(i), 1.0};
        history.update(s);
        const std::vector<Vec2> path = history.points(0);
        REQUIRE(path.size() <= 8);
        CHECK(path.front().x == doctest::Approx(0.0));                    // the start stays
        CHECK(path.back().x == doctest::Approx(static_cast<double>(i)));  // and the newest
        CHECK(std::is_sorted(path.begin(), path.end(),
                             [](Vec2 a, Vec2 b) { return a.x < b.x; }));  // in order
    }
}

TEST_CASE("a trail crossing the seam of a periodic box shows on both sides and not across") {
    RenderConfig config = test::small_config(false);
    Renderer renderer(config, test::test_backend());
    Snapshot s;
    s.box = {10.0, 10.0, Boundary::periodic};
    s.discs = {test::disc_at({7.0, 5.0}, 0.05, {255, 40, 40})};
    s.discs[0].tagged = true;
    FrameContent frame;
    frame.panels = {{&s, "", {}}};
    Image image;
    for (int i = 0; i <= 8; ++i) {  // x: 7.0 -> 11.0, wrapped: crosses x = 10 after step 6
        s.time = 0.1 * i;
        s.discs[0].position = s.box.wrap({7.0 + 0.5 * i, 5.0});
        renderer.render(frame, image);
    }
    test::dump_if_requested(image, "trail_periodic_seam");
    const PanelLayout panel = compute_layout(config, {s.box}, 0.0F).panels[0];
    const auto reddish = [&](double x_box) {
        const PointF p = panel.to_pixels({x_box, 5.0}, s.box);
        const Rgb8 c = test::rgb_at(image, static_cast<int>(p.x), static_cast<int>(p.y));
        return c.r > c.g + 25;
    };
    CHECK(reddish(8.0));        // the trail before the seam
    CHECK(reddish(9.9));        // the step leaving through the right edge
    CHECK(reddish(0.1));        // the same step arriving through the left edge
    CHECK_FALSE(reddish(3.0));  // no line across the middle of the box
    CHECK_FALSE(reddish(5.0));
}

}  // namespace
}  // namespace collide::render
