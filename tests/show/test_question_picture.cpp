// What the event-driven panel draws while a next-collision question holds (questions.hpp,
// question_view): each candidate disc's velocity as an arrow a class can read, ending at the
// disc's leading edge (the fastest motion_arrow_share of the box, the others the move over the
// same time), and a heading that keeps clear of every disc (the painter places it: here, that
// every disc is named); each candidate's connector and letter in its own tint, the arrows in none;
// candidates whose drawings keep apart where the engine offers such distractors.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <set>
#include <vector>

#include "../sim/scene_fixtures.hpp"
#include "collide/show/questions.hpp"
#include "frame_clock_fixture.hpp"
#include "question_drawing_fixture.hpp"

using namespace collide;
using namespace collide::show;

namespace {

using test::after_frame;
using test::clock_of;

/// The discs of the candidates, each once.
std::set<std::uint32_t> candidate_discs(const QuestionAnswer& answer) {
    std::set<std::uint32_t> out;
    for (const CollisionRecord& c : answer.candidates) {
        out.insert(c.a);
        if (c.kind == CollisionKind::pair) out.insert(c.b);
    }
    return out;
}

/// The line along `disc`'s velocity that ends at its leading edge (its arrow), or none.
const BoxLine* arrow_of(const ReplayView& view, const DiscState& disc) {
    const Vec2 direction = disc.velocity;
    const Vec2 edge = disc.position + direction * (disc.radius / norm(direction));
    for (const BoxLine& line : view.lines) {
        const Vec2 d = line.to - line.from;
        if (line.style != LineStyle::motion || norm(line.to - edge) > 1e-12 || !(norm(d) > 0.0))
            continue;
        const double cosine = (d.x * direction.x + d.y * direction.y) / (norm(d) * norm(direction));
        if (cosine > 1.0 - 1e-9) return &line;
    }
    return nullptr;
}

}  // namespace

TEST_CASE("a next-collision question draws every candidate disc's velocity, one time for all") {
    const FrameClock clock = clock_of(400, 1.0 / 30.0);
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        CAPTURE(seed);
        const Scene scene = test::lattice_fluid(5, 0.15, Boundary::walls, seed);
        const std::unique_ptr<Engine> engine = make_engine(scene, EngineOptions{});
        for (std::int64_t j = 0; j <= 10; ++j) engine->advance_to(clock.time(j));
        const Snapshot now = engine->snapshot();
        const QuestionAnswer answer =
            answer_next_collision(*engine, now, after_frame(clock, 10), 30, seed);
        REQUIRE(answer.askable);
        const ReplayView asking = question_view(answer, now, clock, 2.5, false);
        const ReplayView reveal = question_view(answer, now, clock, 1.0, true);
        const double side = std::min(now.box.width, now.box.height);
        double longest = 0.0;
        double seconds = -1.0;  // the one time every arrow shows
        const CollisionRecord& right = answer.candidates[answer.answer];
        for (const std::uint32_t k : candidate_discs(answer)) {
            CAPTURE(k);
            const DiscState& d = now.discs[k];
            const double speed = norm(d.velocity);
            if (!(speed > 0.0)) continue;
            const BoxLine* arrow = arrow_of(asking, d);
            REQUIRE(arrow != nullptr);
            CHECK(arrow->opacity == 1.0F);
            CHECK_FALSE(arrow->failure);
            const double length = norm(arrow->to - arrow->from);
            longest = std::max(longest, length);
            if (seconds < 0.0) seconds = length / speed;
            CHECK(length / speed == doctest::Approx(seconds).epsilon(1e-9));
            // The reveal keeps the answer's arrows and fades the others'.
            const BoxLine* shown = arrow_of(reveal, d);
            REQUIRE(shown != nullptr);
            const bool answers =
                k == right.a || (right.kind == CollisionKind::pair && k == right.b);
            CHECK(shown->opacity == (answers ? 1.0F : 0.3F));
        }
        // The fastest disc's arrow reads at -q l: a fixed share of the box.
        CHECK(longest == doctest::Approx(motion_arrow_share * side).epsilon(1e-9));
        // No disc outside the candidates gets an arrow.
        const std::set<std::uint32_t> named = candidate_discs(answer);
        for (std::uint32_t k = 0; k < now.discs.size(); ++k) {
            if (named.count(k) == 0 && norm(now.discs[k].velocity) > 0.0)
                CHECK(arrow_of(asking, now.discs[k]) == nullptr);
        }
        // The heading keeps clear of every disc: the painter is told of each one.
        REQUIRE(asking.keep_clear.size() == now.discs.size());
        for (std::size_t k = 0; k < now.discs.size(); ++k) {
            CHECK(asking.keep_clear[k].centre.x == now.discs[k].position.x);
            CHECK(asking.keep_clear[k].centre.y == now.discs[k].position.y);
            CHECK(asking.keep_clear[k].radius == now.discs[k].radius);
        }
        CHECK(reveal.keep_clear.size() == now.discs.size());
    }
}

TEST_CASE("a next-collision question tints each candidate's lines and letter, never the arrows") {
    const FrameClock clock = clock_of(400, 1.0 / 30.0);
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        CAPTURE(seed);
        const Boundary boundary = seed % 3 == 0 ? Boundary::periodic : Boundary::walls;
        const Scene scene = test::lattice_fluid(5, 0.15, boundary, seed);
        const std::unique_ptr<Engine> engine = make_engine(scene, EngineOptions{});
        for (std::int64_t j = 0; j <= 10; ++j) engine->advance_to(clock.time(j));
        const Snapshot now = engine->snapshot();
        const QuestionAnswer answer =
            answer_next_collision(*engine, now, after_frame(clock, 10), 30, seed);
        REQUIRE(answer.askable);
        for (const bool reveal : {false, true}) {
            CAPTURE(reveal);
            const ReplayView view = question_view(answer, now, clock, 2.5, reveal);
            REQUIRE(view.labels.size() == answer.candidates.size());
            for (std::size_t i = 0; i < view.labels.size(); ++i)
                CHECK(view.labels[i].tint == static_cast<int>(i));
            std::vector<int> connectors(answer.candidates.size(), 0);
            for (const BoxLine& line : view.lines) {
                // A question draws no thick jump: connectors and arrows only.
                CHECK(line.style != LineStyle::jump);
                if (line.style == LineStyle::motion) {
                    CHECK(line.tint == no_tint);
                    continue;
                }
                REQUIRE(line.tint >= 0);
                REQUIRE(line.tint < static_cast<int>(answer.candidates.size()));
                ++connectors[static_cast<std::size_t>(line.tint)];
                CHECK(line.failure ==
                      (reveal && static_cast<std::size_t>(line.tint) == answer.answer));
            }
            // Every candidate has its line (a pair touching now has none: not offered here).
            for (const int n : connectors) CHECK(n >= 1);
        }
    }
}

TEST_CASE("a next-collision question's connectors stop at the discs' edges") {
    const FrameClock clock = clock_of(400, 1.0 / 30.0);
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        CAPTURE(seed);
        const Scene scene = test::lattice_fluid(5, 0.2, Boundary::walls, seed);
        const std::unique_ptr<Engine> engine = make_engine(scene, EngineOptions{});
        for (std::int64_t j = 0; j <= 10; ++j) engine->advance_to(clock.time(j));
        const Snapshot now = engine->snapshot();
        const QuestionAnswer answer =
            answer_next_collision(*engine, now, after_frame(clock, 10), 30, seed);
        REQUIRE(answer.askable);
        const ReplayView view = question_view(answer, now, clock, 2.5, false);
        for (const BoxLine& line : view.lines) {
            if (line.style != LineStyle::connector || line.opacity != 1.0F) continue;
            const CollisionRecord& c = answer.candidates[static_cast<std::size_t>(line.tint)];
            for (const std::uint32_t k : test::candidate_discs_of(c)) {
                const DiscState& d = now.discs[k];
                // Ends on the edge (within rounding), nothing inside the disc.
                CHECK(test::point_to_segment(d.position, line.from, line.to) >=
                      d.radius * (1.0 - 1e-9));
                const double to_end =
                    std::min(norm(line.from - d.position), norm(line.to - d.position));
                CHECK(to_end == doctest::Approx(d.radius).epsilon(1e-9));
            }
        }
    }
}

TEST_CASE("a next-collision question's candidates are drawn apart where the engine allows") {
    // Fluids of a few dozen discs in a box with room (the lesson's scenes): every seed offers
    // distractors whose discs, lines and arrows keep apart from the answer's and each other's.
    int crossed = 0;
    const int seeds = 40;
    for (std::uint64_t seed = 1; seed <= static_cast<std::uint64_t>(seeds); ++seed) {
        CAPTURE(seed);
        const FrameClock clock = clock_of(400, 1.0 / 30.0);
        const Boundary boundary = seed % 4 == 0 ? Boundary::periodic : Boundary::walls;
        const double eta = 0.05 + 0.025 * static_cast<double>(seed % 5);
        const Scene scene = test::lattice_fluid(4 + seed % 3, eta, boundary, seed);
        const auto k = static_cast<std::int64_t>(seed * 7 % 50);
        const std::unique_ptr<Engine> engine = make_engine(scene, EngineOptions{});
        for (std::int64_t j = 0; j <= k; ++j) engine->advance_to(clock.time(j));
        const Snapshot now = engine->snapshot();
        const QuestionAnswer answer =
            answer_next_collision(*engine, now, after_frame(clock, k), 30, seed);
        REQUIRE(answer.askable);
        const ReplayView view = question_view(answer, now, clock, 2.5, false);
        const double margin = drawing_gap_share * std::min(now.box.width, now.box.height);
        const double closest = test::closest_candidates(answer, view, now);
        INFO("closest " << closest << " margin " << margin);
        if (closest < margin * (1.0 - 1e-9)) ++crossed;
    }
    CHECK(crossed == 0);
}
