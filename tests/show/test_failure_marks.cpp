// Which failures a lesson marks (collide/show/failure_marks.hpp): the budget shared fairly
// between kinds and spread over the box, where a disc left, rings that fade, the legend's words.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <set>
#include <vector>

#include "collide/show/failure_marks.hpp"

using namespace collide;
using namespace collide::show;

namespace {

DiscState disc(Vec2 p, Vec2 v = {}, double r = 0.01) {
    DiscState d;
    d.position = p;
    d.velocity = v;
    d.radius = r;
    d.mass = 1.0;
    return d;
}

std::size_t count_kind(const std::vector<FailureMark>& marks, FailureKind kind) {
    return static_cast<std::size_t>(std::count_if(
        marks.begin(), marks.end(), [&](const FailureMark& m) { return m.kind == kind; }));
}

/// A unit box with `missed` missed collisions, `pairs` overlapping pairs and `gone` discs
/// outside (every failure along the bottom, as a dense fluid's index order would list them).
Snapshot failing(std::size_t missed, std::size_t pairs, std::size_t gone, double time = 1.0) {
    Snapshot s;
    s.time = time;
    s.box = {1.0, 1.0, Boundary::walls};
    for (std::size_t k = 0; k < pairs; ++k) {
        const double x = (static_cast<double>(k) + 0.5) / static_cast<double>(pairs + 1);
        s.discs.push_back(disc({x, 0.05}));
        s.discs.push_back(disc({x + 0.005, 0.05}));
        s.overlapping_pairs.emplace_back(2 * k, 2 * k + 1);
    }
    for (std::size_t k = 0; k < gone; ++k) {
        DiscState d = disc(
            {1.2, 0.1 + 0.8 * static_cast<double>(k) / static_cast<double>(gone + 1)}, {1.0, 0.0});
        d.escaped = true;
        s.discs.push_back(d);
    }
    for (std::size_t k = 0; k < missed; ++k) {
        s.missed_collisions.push_back(
            {0.5, 0.1 + 0.8 * static_cast<double>(k) / static_cast<double>(missed + 1)});
    }
    return s;
}

}  // namespace

TEST_CASE("the marker budget is shared fairly between the kinds present") {
    CHECK(fair_shares({100, 100, 100, 0}, 30) == KindCounts{10, 10, 10, 0});
    CHECK(fair_shares({100, 100, 100, 100}, 30) == KindCounts{7, 7, 8, 8});
    // A kind with few failures gets them all; the others share what it leaves.
    CHECK(fair_shares({2, 100, 100, 0}, 30) == KindCounts{2, 14, 14, 0});
    CHECK(fair_shares({0, 741, 0, 4}, 30) == KindCounts{0, 26, 0, 4});
    CHECK(fair_shares({5, 3, 1, 2}, 30) == KindCounts{5, 3, 1, 2});
    CHECK(fair_shares({0, 0, 0, 0}, 30) == KindCounts{0, 0, 0, 0});
    for (std::size_t a = 0; a < 40; a += 3) {
        for (std::size_t b = 0; b < 40; b += 5) {
            for (std::size_t c = 0; c < 40; c += 7) {
                for (std::size_t d = 0; d < 40; d += 11) {
                    const KindCounts available{a, b, c, d};
                    const KindCounts share = fair_shares(available, 30);
                    INFO(a << " " << b << " " << c << " " << d);
                    CHECK(share[0] + share[1] + share[2] + share[3] ==
                          std::min<std::size_t>(30, a + b + c + d));
                    for (std::size_t k = 0; k < share.size(); ++k) {
                        CHECK(share[k] <= available[k]);
                        for (std::size_t j = 0; j < share.size(); ++j) {
                            // A kind that did not get all it has got at least as many as any
                            // other.
                            if (share[k] < available[k]) CHECK(share[k] + 1 >= share[j]);
                        }
                    }
                }
            }
        }
    }
}

TEST_CASE("marks of one kind are spread over the box, not taken in list order") {
    const Box box{1.0, 1.0, Boundary::walls};
    // 60 points along the bottom first (the order an index list gives), then 12 over the rest.
    std::vector<Vec2> points;
    for (int k = 0; k < 60; ++k) points.push_back({(k + 0.5) / 60.0, 0.05});
    for (int k = 0; k < 12; ++k) points.push_back({(k % 4 + 0.5) / 4.0, 0.375 + 0.25 * (k / 4)});
    const std::vector<std::size_t> picked = spread_over_box(points, box, 16);
    REQUIRE(picked.size() == 16);
    std::set<std::size_t> unique(picked.begin(), picked.end());
    CHECK(unique.size() == 16);
    const auto bottom = static_cast<std::size_t>(
        std::count_if(picked.begin(), picked.end(), [](std::size_t i) { return i < 60; }));
    CHECK(bottom == 4);  // one per cell of the bottom row: the other 12 cells have a point each
    // Fewer points than asked: all of them.
    CHECK(spread_over_box({{0.1, 0.1}, {0.9, 0.9}}, box, 5).size() == 2);
}

TEST_CASE("a disc that left the box is marked where its centre crossed the edge") {
    const Box box{2.0, 1.0, Boundary::walls};
    Exit e = exit_point(disc({2.5, 0.6}, {1.0, 0.2}), box);
    CHECK(e.where.x == doctest::Approx(2.0));
    CHECK(e.where.y == doctest::Approx(0.5));
    CHECK(e.out.x == 1.0);
    CHECK(e.out.y == 0.0);
    // Through the bottom, moving left as well: the edge crossed last is the one it left by.
    e = exit_point(disc({0.5, -0.5}, {-0.1, -1.0}), box);
    CHECK(e.where.x == doctest::Approx(0.55));
    CHECK(e.where.y == doctest::Approx(0.0));
    CHECK(e.out.y == -1.0);
    // Not moving away: the edge it is beyond.
    e = exit_point(disc({-0.3, 0.4}, {0.0, 0.0}), box);
    CHECK(e.where.x == 0.0);
    CHECK(e.out.x == -1.0);
}

TEST_CASE("each kind of failure is handed over with its own kind, and the legend names it") {
    FailureMarks marks;
    marks.update(failing(1, 1, 1), 0.0);
    const std::vector<FailureMark>& m = marks.marks();
    REQUIRE(m.size() == 3);
    CHECK(count_kind(m, FailureKind::missed) == 1);
    CHECK(count_kind(m, FailureKind::overlapping) == 1);
    CHECK(count_kind(m, FailureKind::left_box) == 1);
    for (const FailureMark& mark : m) {
        if (mark.kind != FailureKind::left_box) continue;
        CHECK(mark.where.x == doctest::Approx(1.0));  // on the right edge, pointing out
        CHECK(mark.out.x == 1.0);
    }
    const MarkWords& words = marks.words();
    REQUIRE(words.items.size() == 3);
    CHECK(words.items[0].name == "missed collision");
    CHECK(words.items[1].name == "overlapping");
    CHECK(words.items[2].name == "left the box");
    CHECK(words.unmarked.empty());
    CHECK(words.wraps.empty());  // walls
}

TEST_CASE("a disc that went through a barrier keeps a diamond where it is, frame after frame") {
    FailureMarks marks;
    Snapshot s = failing(0, 0, 0);
    s.discs.push_back(disc({0.3, 0.4}));
    DiscState through = disc({0.7, 0.6}, {0.5, 0.0}, 0.02);
    through.tunnelled = true;
    s.discs.push_back(through);
    DiscState gone = disc({1.3, 0.6}, {1.0, 0.0});  // through a wall too: its arrow says it
    gone.tunnelled = true;
    gone.escaped = true;
    s.discs.push_back(gone);
    marks.update(s, 0.0);
    REQUIRE(count_kind(marks.marks(), FailureKind::tunnelled) == 1);
    CHECK(count_kind(marks.marks(), FailureKind::left_box) == 1);
    const auto diamond =
        std::find_if(marks.marks().begin(), marks.marks().end(),
                     [](const FailureMark& m) { return m.kind == FailureKind::tunnelled; });
    CHECK(diamond->where.x == doctest::Approx(0.7));
    CHECK(diamond->size == doctest::Approx(0.02));
    CHECK(diamond->opacity == 1.0F);
    REQUIRE(marks.words().items.size() == 2);
    CHECK(marks.words().items[0].name == "left the box");
    CHECK(marks.words().items[1].name == "went through a barrier");
    // Long after, moved on: still marked, at full strength, where the disc is now.
    s.time = 30.0;
    s.discs[1].position = {0.9, 0.2};
    marks.update(s, 30.0);
    for (const FailureMark& m : marks.marks()) {
        if (m.kind != FailureKind::tunnelled) continue;
        CHECK(m.where.x == doctest::Approx(0.9));
        CHECK(m.opacity == 1.0F);
    }
    CHECK(count_kind(marks.marks(), FailureKind::tunnelled) == 1);
}

TEST_CASE("the legend names a kind from the first frame it is marked on, in order of appearance") {
    FailureMarks marks;
    marks.update(failing(0, 0, 0, 0.1), 0.0);
    CHECK(marks.words().items.empty());
    marks.update(failing(0, 2, 0, 0.2), 0.1);
    REQUIRE(marks.words().items.size() == 1);
    CHECK(marks.words().items[0].kind == FailureKind::overlapping);
    marks.update(failing(1, 0, 0, 0.3), 0.2);  // the overlap is gone, the legend keeps it
    REQUIRE(marks.words().items.size() == 2);
    CHECK(marks.words().items[1].kind == FailureKind::missed);
}

TEST_CASE("a budget over many failures: fair between kinds, the rest counted in the legend") {
    FailureMarks marks(30);
    marks.update(failing(4, 200, 60), 0.0);
    const std::vector<FailureMark>& m = marks.marks();
    CHECK(m.size() == 30);
    CHECK(count_kind(m, FailureKind::missed) == 4);
    CHECK(count_kind(m, FailureKind::overlapping) == 13);
    CHECK(count_kind(m, FailureKind::left_box) == 13);
    CHECK(marks.words().unmarked == "and 234 more not drawn");
}

TEST_CASE("a missed collision's ring stays one second of video and fades, a held state adds none") {
    FailureMarks marks;
    Snapshot s = failing(1, 0, 0, 0.5);
    marks.update(s, 0.0);
    REQUIRE(marks.marks().size() == 1);
    CHECK(marks.marks()[0].opacity == doctest::Approx(1.0));
    marks.update(s, 0.25);  // the same state held: not added again
    REQUIRE(marks.marks().size() == 1);
    CHECK(marks.marks()[0].opacity == doctest::Approx(0.75));
    s.time = 0.6;
    s.missed_collisions.clear();
    marks.update(s, 0.99);
    CHECK(marks.marks().size() == 1);
    marks.update(s, 1.0);
    CHECK(marks.marks().empty());
    // An earlier state (a seek, a new video) starts over.
    marks.update(failing(0, 0, 0, 0.1), 1.1);
    CHECK(marks.words().items.empty());
}

TEST_CASE("an overlap of one frame keeps its cross a second of video, fading, where it was") {
    FailureMarks marks;
    Snapshot s = failing(0, 1, 0, 0.5);
    const Vec2 mid = 0.5 * (s.discs[0].position + s.discs[1].position);
    marks.update(s, 2.0);
    REQUIRE(marks.marks().size() == 1);
    CHECK(marks.marks()[0].opacity == doctest::Approx(1.0));
    // The next state: the pair has parted and moved on; the cross stays where they overlapped.
    s.time = 0.6;
    s.overlapping_pairs.clear();
    s.discs[0].position = {0.1, 0.9};
    s.discs[1].position = {0.9, 0.9};
    const double frame = 1.0 / 30.0;
    for (double t = 2.0 + frame; t < 2.0 + mark_seconds - 1e-9; t += frame) {
        marks.update(s, t);
        REQUIRE(marks.marks().size() == 1);
        CHECK(marks.marks()[0].kind == FailureKind::overlapping);
        CHECK(marks.marks()[0].where.x == doctest::Approx(mid.x));
        CHECK(marks.marks()[0].where.y == doctest::Approx(mid.y));
        CHECK(marks.marks()[0].opacity == doctest::Approx(1.0 - (t - 2.0) / mark_seconds));
    }
    marks.update(s, 2.0 + mark_seconds);
    CHECK(marks.marks().empty());
    CHECK(marks.words().items.size() == 1);  // the legend still names what was marked
}

TEST_CASE("a pair that overlaps again is marked at full strength, once") {
    FailureMarks marks;
    Snapshot s = failing(0, 2, 0, 0.5);
    marks.update(s, 0.0);
    s.time = 0.6;
    s.overlapping_pairs.pop_back();  // the second pair parts
    marks.update(s, 0.5);
    REQUIRE(marks.marks().size() == 2);
    // The pair overlapping now comes first, the parted one fades.
    CHECK(marks.marks()[0].opacity == doctest::Approx(1.0));
    CHECK(marks.marks()[1].opacity == doctest::Approx(0.5));
    s.time = 0.7;
    s.overlapping_pairs.emplace_back(2, 3);  // and overlaps again
    marks.update(s, 0.6);
    REQUIRE(marks.marks().size() == 2);
    CHECK(marks.marks()[0].opacity == doctest::Approx(1.0));
    CHECK(marks.marks()[1].opacity == doctest::Approx(1.0));
}

TEST_CASE("a periodic box's legend says once that the edges wrap around") {
    Snapshot s = failing(0, 0, 0);
    s.box.boundary = Boundary::periodic;
    FailureMarks says(mark_budget, true);
    FailureMarks silent(mark_budget, false);
    says.update(s, 0.0);
    silent.update(s, 0.0);
    CHECK(says.words().wraps == "edges wrap around");
    CHECK(silent.words().wraps.empty());
    CHECK(mark_line(false, true, s.box));
    CHECK_FALSE(mark_line(false, false, s.box));
    CHECK(mark_line(true, false, s.box));
    s.box.boundary = Boundary::walls;
    CHECK_FALSE(mark_line(false, true, s.box));
}
