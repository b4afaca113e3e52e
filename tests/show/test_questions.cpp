// Pause and ponder (collide/show/questions.hpp): the answers come from the engines. For many
// scenes and moments, the revealed answer is the collision a fresh engine, stepped on its own,
// resolves first (and the count it resolves in the next second); the distractors are not.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "../sim/scene_fixtures.hpp"
#include "collide/show/questions.hpp"
#include "collide/show/timeline.hpp"
#include "frame_clock_fixture.hpp"

using namespace collide;
using namespace collide::show;

namespace {

using test::after_frame;
using test::clock_of;

/// A fresh engine stepped to frame k as a video steps it, then on in small steps: the first
/// collision after frame k.
std::optional<CollisionRecord> first_after(const Scene& scene, const EngineOptions& options,
                                           const FrameClock& clock, std::int64_t k) {
    const std::unique_ptr<Engine> engine = make_engine(scene, options);
    for (std::int64_t j = 0; j <= k; ++j) engine->advance_to(clock.time(j));
    std::optional<CollisionRecord> first;
    engine->set_collision_listener([&](const CollisionRecord& r) {
        if (!first) first = r;
    });
    const double now = engine->time();
    for (int step = 1; step <= 4000 && !first; ++step) engine->advance_to(now + step * 1e-3);
    return first;
}

bool same_contact(const CollisionRecord& x, const CollisionRecord& y) {
    if (x.kind != y.kind) return false;
    if (x.kind != CollisionKind::pair) return x.a == y.a;
    return std::min(x.a, x.b) == std::min(y.a, y.b) && std::max(x.a, x.b) == std::max(y.a, y.b);
}

}  // namespace

TEST_CASE("next collision: the answer is the engine's next collision, the distractors are not") {
    const FrameClock clock = clock_of(400, 1.0 / 30.0);
    std::set<std::size_t> letters;
    int asked = 0;
    for (std::uint64_t seed = 1; seed <= 24; ++seed) {
        EngineOptions options;
        options.engine = seed % 3 == 0 ? EngineKind::classic : EngineKind::fast;
        const Boundary boundary = seed % 2 == 0 ? Boundary::periodic : Boundary::walls;
        const Scene scene = test::lattice_fluid(5, 0.25, boundary, seed);
        const std::int64_t k = static_cast<std::int64_t>(seed * 7 % 40);
        CAPTURE(seed);
        const std::unique_ptr<Engine> engine = make_engine(scene, options);
        for (std::int64_t j = 0; j <= k; ++j) engine->advance_to(clock.time(j));
        const double before = engine->time();
        const QuestionAnswer answer =
            answer_next_collision(*engine, engine->snapshot(), after_frame(clock, k), 30, seed);
        CHECK(engine->time() == before);  // a copy answered: the video's engine is untouched
        const std::optional<CollisionRecord> truth = first_after(scene, options, clock, k);
        REQUIRE(truth.has_value());
        REQUIRE(answer.askable);
        ++asked;
        REQUIRE(answer.candidates.size() >= min_candidates);
        REQUIRE(answer.candidates.size() <= max_candidates);
        REQUIRE(answer.answer < answer.candidates.size());
        const CollisionRecord& right = answer.candidates[answer.answer];
        CHECK(same_contact(right, *truth));
        CHECK(right.t == doctest::Approx(truth->t).epsilon(1e-9));
        for (std::size_t i = 0; i < answer.candidates.size(); ++i) {
            if (i == answer.answer) continue;
            CAPTURE(i);
            CHECK_FALSE(same_contact(answer.candidates[i], *truth));
            CHECK(answer.candidates[i].t > truth->t);
            for (std::size_t j = i + 1; j < answer.candidates.size(); ++j)
                CHECK_FALSE(same_contact(answer.candidates[i], answer.candidates[j]));
        }
        letters.insert(answer.answer);
    }
    CHECK(asked == 24);
    CHECK(letters.size() >= 3);  // the answer is not always the same letter
}

namespace {

/// The collisions a copy asked on frame k resolves, as answer_next_collision runs it: frame by
/// frame after k until 24 are seen or look_ahead_frames passed.
std::vector<CollisionRecord> look_ahead(const Scene& scene, const EngineOptions& options,
                                        const FrameClock& clock, std::int64_t k) {
    const std::unique_ptr<Engine> engine = make_engine(scene, options);
    for (std::int64_t j = 0; j <= k; ++j) engine->advance_to(clock.time(j));
    std::vector<CollisionRecord> hits;
    engine->set_collision_listener([&hits](const CollisionRecord& r) { hits.push_back(r); });
    const FramesAfter after = after_frame(clock, k);
    for (std::int64_t i = 1; i <= look_ahead_frames && hits.size() < 24; ++i)
        engine->advance_to(after(i));
    engine->set_collision_listener(nullptr);
    return hits;
}

/// The gap the picture shows for `c`: between its discs, or its disc and the nearer wall it hits.
double seen_gap(const CollisionRecord& c, const Snapshot& now) {
    const DiscState& a = now.discs[c.a];
    if (c.kind == CollisionKind::pair) {
        const DiscState& b = now.discs[c.b];
        return norm(now.box.displacement(a.position, b.position)) - a.radius - b.radius;
    }
    if (c.kind == CollisionKind::xwall)
        return std::min(a.position.x, now.box.width - a.position.x) - a.radius;
    return std::min(a.position.y, now.box.height - a.position.y) - a.radius;
}

}  // namespace

TEST_CASE("next collision: every distractor looks different from the answer in the picture") {
    int later = 0;
    int misses = 0;
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        CAPTURE(seed);
        // A video slowed as render slows a dense fluid (a box crossing takes seconds of video),
        // or one so fast that every collision ahead comes within a blink (near misses only).
        const int fps = seed % 2 == 0 ? 15 : 30;
        const double speed = seed % 5 == 4 ? 1.0 : 0.01 * static_cast<double>(1 + seed % 3);
        const FrameClock clock = clock_of(400, speed / fps);
        EngineOptions options;
        options.engine = seed % 3 == 0 ? EngineKind::classic : EngineKind::fast;
        const Boundary boundary = seed % 4 == 1 ? Boundary::periodic : Boundary::walls;
        const double eta = 0.05 + 0.05 * static_cast<double>(seed % 5);
        const Scene scene = test::lattice_fluid(4 + seed % 3, eta, boundary, seed);
        const auto k = static_cast<std::int64_t>(seed * 11 % 60);
        const std::unique_ptr<Engine> engine = make_engine(scene, options);
        for (std::int64_t j = 0; j <= k; ++j) engine->advance_to(clock.time(j));
        const Snapshot now = engine->snapshot();
        const FramesAfter after = after_frame(clock, k);
        const QuestionAnswer answer = answer_next_collision(*engine, now, after, fps, seed);
        const std::vector<CollisionRecord> hits = look_ahead(scene, options, clock, k);
        REQUIRE_FALSE(hits.empty());
        REQUIRE(answer.askable);
        REQUIRE(answer.answer < answer.candidates.size());
        const CollisionRecord& right = answer.candidates[answer.answer];
        CHECK(same_contact(right, hits.front()));
        CHECK(right.t == hits.front().t);
        // The rule's bounds, from the answer's time to go and the video's speed.
        const auto frames = static_cast<std::int64_t>(std::ceil(distractor_video_seconds * fps));
        const double bound =
            std::max(distractor_time_factor * (right.t - now.time), after(frames) - now.time);
        const double apart = distractor_gap_share * std::min(now.box.width, now.box.height);
        for (std::size_t i = 0; i < answer.candidates.size(); ++i) {
            if (i == answer.answer) continue;
            CAPTURE(i);
            const CollisionRecord& c = answer.candidates[i];
            CHECK_FALSE(same_contact(c, hits.front()));
            // Visibly apart now, whichever kind it is.
            CHECK(seen_gap(c, now) >= apart);
            const auto seen = std::find_if(
                hits.begin(), hits.end(),
                [&c](const CollisionRecord& h) { return same_contact(h, c) && h.t == c.t; });
            if (seen != hits.end()) {
                ++later;  // a later collision of the engine's, far enough ahead
                CHECK(c.t - now.time >= bound);
            } else {
                ++misses;  // a near miss: the pair never meets within the look ahead
                CHECK(c.kind == CollisionKind::pair);
                CHECK_FALSE(std::isfinite(c.t));
                CHECK(std::none_of(hits.begin(), hits.end(),
                                   [&c](const CollisionRecord& h) { return same_contact(h, c); }));
            }
        }
        // Every candidate is drawn where the picture is: a near miss's line joins its discs.
        const ReplayView asking = question_view(answer, now, clock, 2.5, false);
        REQUIRE(asking.labels.size() == answer.candidates.size());
        for (const BoxLine& line : asking.lines)
            CHECK((std::isfinite(norm(line.from)) && std::isfinite(norm(line.to))));
        for (const BoxLabel& label : asking.labels) CHECK(std::isfinite(norm(label.at)));
    }
    CHECK(later >= 20);  // both kinds of distractor are offered across the seeds
    CHECK(misses >= 5);
}

TEST_CASE("next collision: a disc sliding along a wall it touches is no distractor") {
    const FrameClock clock = clock_of(400, 1.0 / 15.0);
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
        CAPTURE(seed);
        // A pair about to meet (the answer), a disc touching the left wall that grazes into it
        // later while it slides up, and two discs well apart heading for each other later.
        Scene s;
        s.box = Box{1.0, 1.0, Boundary::walls};
        const double r = 0.03;
        // It touches the wall (0.1 % of the box apart) and meets it 3 .. 5.5 s on.
        const double lean = 1e-4 / (2.5 + 0.5 * static_cast<double>(seed));
        s.discs.push_back(Disc{{0.5, 0.8}, {0.2, 0.0}, r, 1.0, {}, ""});
        s.discs.push_back(Disc{{0.5 + 2.0 * r + 0.002, 0.8}, {-0.2, 0.0}, r, 1.0, {}, ""});
        s.discs.push_back(Disc{{r + 1e-4, 0.3}, {-lean, 0.15}, r, 1.0, {}, ""});
        s.discs.push_back(Disc{{0.4, 0.3}, {0.1, 0.0}, r, 1.0, {}, ""});
        s.discs.push_back(Disc{{0.8, 0.3}, {-0.1, 0.0}, r, 1.0, {}, ""});
        const std::unique_ptr<Engine> engine = make_engine(s, EngineOptions{});
        engine->advance_to(clock.time(0));
        const Snapshot now = engine->snapshot();
        const QuestionAnswer answer =
            answer_next_collision(*engine, now, after_frame(clock, 0), 15, seed);
        REQUIRE(answer.askable);
        // The sliding disc's wall hit is among the collisions ahead (and of other discs than the
        // answer's: the rule before #45's fix offered it).
        const std::vector<CollisionRecord> hits = look_ahead(s, EngineOptions{}, clock, 0);
        CHECK(std::any_of(hits.begin(), hits.end(), [](const CollisionRecord& h) {
            return h.kind == CollisionKind::xwall && h.a == 2;
        }));
        const CollisionRecord& right = answer.candidates[answer.answer];
        CHECK(right.kind == CollisionKind::pair);
        CHECK(std::min(right.a, right.b) == 0);
        bool offers_far_pair = false;
        for (const CollisionRecord& c : answer.candidates) {
            CHECK_FALSE((c.kind == CollisionKind::xwall && c.a == 2));
            offers_far_pair =
                offers_far_pair || (c.kind == CollisionKind::pair && std::min(c.a, c.b) == 3 &&
                                    std::max(c.a, c.b) == 4);
        }
        CHECK(offers_far_pair);
    }
}

TEST_CASE("how many: the count is what the engine resolves over the next second of video") {
    const FrameClock clock = clock_of(400, 1.0 / 30.0);
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        CAPTURE(seed);
        EngineOptions options;
        const Scene scene = test::lattice_fluid(6, 0.3, Boundary::walls, seed);
        const std::int64_t k = static_cast<std::int64_t>(seed * 5 % 30);
        const std::unique_ptr<Engine> engine = make_engine(scene, options);
        for (std::int64_t j = 0; j <= k; ++j) engine->advance_to(clock.time(j));
        const QuestionAnswer answer = answer_how_many(*engine, after_frame(clock, k), 30);
        REQUIRE(answer.askable);
        // A fresh engine over the frames k + 1 .. k + 30.
        const std::unique_ptr<Engine> fresh = make_engine(scene, options);
        for (std::int64_t j = 0; j <= k; ++j) fresh->advance_to(clock.time(j));
        std::int64_t pairs = 0;
        std::int64_t walls = 0;
        fresh->set_collision_listener(
            [&](const CollisionRecord& r) { ++(r.kind == CollisionKind::pair ? pairs : walls); });
        for (std::int64_t j = k + 1; j <= k + 30; ++j) fresh->advance_to(clock.time(j));
        CHECK(answer.pairs == pairs);
        CHECK(answer.walls == walls);
        CHECK(answer.count() > 0);
        const std::string words = answer_words(answer, clock);
        CHECK(words.find(std::to_string(pairs + walls)) != std::string::npos);
        CHECK(words.size() <= max_caption_chars);
    }
}

TEST_CASE("answer_questions: each question answered at the frame the timeline freezes on") {
    const Scene scene = test::lattice_fluid(5, 0.25, Boundary::walls, 3);
    TimelineScript script;
    script.fps = 30;
    script.frames = 300;
    script.questions = {{1.0, 2.0, 1.0, "", ""}, {5.0, 2.0, 1.0, "", ""}};
    const Timeline timeline = build_timeline(script);
    REQUIRE(questions_asked(timeline) == std::vector<int>{0, 1});
    const FrameClock clock = clock_of(timeline.sim_frame_count(), 1.0 / 30.0);
    const EngineOptions options;
    const std::vector<QuestionAnswer> answers = answer_questions(
        scene, options, clock, timeline, {QuestionKind::next_collision, QuestionKind::how_many});
    REQUIRE(answers.size() == 2);
    std::vector<std::int64_t> frozen;
    for (const Segment& s : timeline.segments)
        if (s.kind == SegmentKind::question) frozen.push_back(s.sim_frame);
    REQUIRE(frozen.size() == 2);
    CHECK(answers[0].sim_frame == frozen[0]);
    CHECK(answers[1].sim_frame == frozen[1]);
    REQUIRE(answers[0].askable);
    const std::optional<CollisionRecord> truth = first_after(scene, options, clock, frozen[0]);
    REQUIRE(truth.has_value());
    CHECK(same_contact(answers[0].candidates[answers[0].answer], *truth));
    CHECK(answers[1].kind == QuestionKind::how_many);
    CHECK(answers[1].askable);
}

TEST_CASE("the question's words, its countdown and the answer's words") {
    QuestionAnswer answer;
    answer.kind = QuestionKind::next_collision;
    answer.time = 1.0;
    CollisionRecord a;
    a.t = 1.5;
    a.a = 3;
    a.b = 7;
    CollisionRecord b = a;
    b.t = 2.0;
    b.a = 1;
    b.b = 2;
    CollisionRecord c;
    c.t = 2.5;
    c.kind = CollisionKind::xwall;
    c.a = 4;
    answer.candidates = {b, a, c};
    answer.answer = 1;
    answer.askable = true;
    CHECK(question_words(answer, "") == "Pause and think: which collides first, A, B or C?");
    CHECK(question_words(answer, "Which first?") == "Which first?");
    const std::string words = answer_words(answer, clock_of(100, 0.01));
    CHECK(words.rfind("Answer: B, discs 3 and 7", 0) == 0);
    CHECK(words.size() <= max_caption_chars);
    CHECK(countdown_words(3.0) == "Think: 3");
    CHECK(countdown_words(2.01) == "Think: 3");
    CHECK(countdown_words(0.2) == "Think: 1");
    answer.kind = QuestionKind::how_many;
    answer.pairs = 0;
    answer.walls = 0;
    CHECK(answer_words(answer, clock_of(100, 0.01)) == "Answer: none in the next second");
    answer.pairs = 5;
    answer.walls = 2;
    CHECK(answer_words(answer, clock_of(100, 0.01)) ==
          "Answer: 7 collisions (5 between discs, 2 with walls)");
}

TEST_CASE("the picture: letters clear of every disc, the answer marked only in the reveal") {
    const FrameClock clock = clock_of(400, 1.0 / 30.0);
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
        CAPTURE(seed);
        const Scene scene = test::lattice_fluid(4, 0.1, Boundary::walls, seed);
        const std::unique_ptr<Engine> engine = make_engine(scene, EngineOptions{});
        for (std::int64_t j = 0; j <= 5; ++j) engine->advance_to(clock.time(j));
        const Snapshot now = engine->snapshot();
        const QuestionAnswer answer =
            answer_next_collision(*engine, now, after_frame(clock, 5), 30, seed);
        REQUIRE(answer.askable);
        const ReplayView asking = question_view(answer, now, clock, 2.5, false);
        CHECK(asking.heading == "Think: 3");
        REQUIRE(asking.labels.size() == answer.candidates.size());
        const double plate = 0.05 * std::min(now.box.width, now.box.height);
        for (std::size_t i = 0; i < asking.labels.size(); ++i) {
            const BoxLabel& label = asking.labels[i];
            CHECK(label.text == candidate_letter(i));
            CHECK_FALSE(label.failure);  // no hint while the class thinks
            for (const DiscState& d : now.discs)
                CHECK(norm(label.at - d.position) - d.radius >= plate - 1e-12);
        }
        for (const BoxLine& line : asking.lines) CHECK_FALSE(line.failure);
        const ReplayView reveal = question_view(answer, now, clock, 1.0, true);
        CHECK(reveal.heading == "Answer: " + candidate_letter(answer.answer));
        for (std::size_t i = 0; i < reveal.labels.size(); ++i)
            CHECK(reveal.labels[i].failure == (i == answer.answer));
    }
}

TEST_CASE("will see: asked only on the frame before the failing step, answered by its record") {
    CHECK(needs_time_panel(QuestionKind::will_see));
    CHECK_FALSE(needs_event_panel(QuestionKind::will_see));
    CHECK_FALSE(needs_time_panel(QuestionKind::next_collision));
    CHECK(reveal_seconds_of(QuestionKind::will_see) == replay_seconds);
    CHECK(reveal_seconds_of(QuestionKind::how_many) == reveal_seconds);
    ReplayFailure failure;
    failure.dt = 0.04;
    failure.step.kind = sim::StepFailureKind::missed_pair;
    failure.step.step = 5;  // the state before at 0.2, after at 0.24
    failure.step.a = 2;
    failure.step.b = 9;
    failure.step.before_a = {0.3, 0.5};
    failure.step.motion_a = {0.04, 0.0};
    failure.step.before_b = {0.32, 0.5};
    failure.sim_frame = 36;
    // Frame 35 shows the state before the step: askable there, nowhere else.
    const QuestionAnswer answer = answer_will_see(failure, 35, 0.23);
    REQUIRE(answer.askable);
    REQUIRE(answer.failure.has_value());
    CHECK(answer.failure->step.a == 2);
    CHECK_FALSE(answer_will_see(failure, 34, 0.22).askable);
    CHECK_FALSE(answer_will_see(failure, 36, 0.24).askable);
    CHECK(question_words(answer, "") == "Pause and think: will the next check see this collision?");
    const std::string words = answer_words(answer, clock_of(100, 0.01));
    CHECK(words.rfind("Answer: no", 0) == 0);
    CHECK(words.size() <= max_caption_chars);
    // The time-driven panel marks the two discs and the moves of the step to come.
    const ReplayView view = will_see_view(answer, 2.5);
    CHECK(view.heading == "Think: 3");
    CHECK(view.focus == std::vector<std::uint32_t>{2, 9});
    REQUIRE(view.lines.size() == 1);  // disc 9 rests: no move to draw
    CHECK(view.lines[0].from.x == doctest::Approx(0.3));
    CHECK(view.lines[0].to.x == doctest::Approx(0.34));
    // The event-driven panel has nothing of its own to mark for it.
    Snapshot snapshot;
    snapshot.box = Box{1.0, 1.0, Boundary::walls};
    CHECK(question_view(answer, snapshot, clock_of(100, 0.01), 2.5, false).empty());
    failure.step.kind = sim::StepFailureKind::left_box;
    const QuestionAnswer wall = answer_will_see(failure, 35, 0.23);
    CHECK(answer_words(wall, clock_of(100, 0.01)).find("wall") != std::string::npos);
    CHECK(will_see_view(wall, 1.0).focus == std::vector<std::uint32_t>{2});
}

namespace {

/// Two discs far apart on one line of a long box, the first moving towards the second at rest,
/// and two more at rest out of their way: nothing collides until the two meet at `meets`
/// (simulation time), then the second runs on to the wall.
Scene far_pair(double meets, std::uint64_t seed) {
    Scene s;
    s.name = "far";
    s.box = Box{4.0, 1.0, Boundary::walls};
    const double r = 0.02;
    const double y = 0.3 + 0.05 * static_cast<double>(seed % 7);
    const double apart = 2.0 + 0.1 * static_cast<double>(seed % 5);  // centre to centre
    const double v = (apart - 2.0 * r) / meets;
    s.discs.push_back(Disc{{0.5, y}, {v, 0.0}, r, 1.0, {}, ""});
    s.discs.push_back(Disc{{0.5 + apart, y}, {0.0, 0.0}, r, 1.0, {}, ""});
    s.discs.push_back(Disc{{0.3, 0.9}, {0.0, 0.0}, r, 1.0, {}, ""});
    s.discs.push_back(Disc{{3.7, 0.9}, {0.0, 0.0}, r, 1.0, {}, ""});  // a near miss to offer
    return s;
}

/// A lattice fluid whose discs move `slower` times slower: its first collisions come late.
Scene slowed_fluid(std::uint64_t seed, double slower) {
    Scene s = test::lattice_fluid(4, 0.05, Boundary::walls, seed);
    for (Disc& d : s.discs) d.velocity = d.velocity * (1.0 / slower);
    return s;
}

/// Whether a next-collision question is askable on each frame `from` .. `to` of `clock`: a
/// fresh engine stepped as the video steps it, asked on each (a copy run per frame: the slow
/// way next_askable_frame avoids).
std::vector<bool> askable_frames(const Scene& scene, const EngineOptions& options,
                                 const FrameClock& clock, std::int64_t from, std::int64_t to) {
    const std::unique_ptr<Engine> engine = make_engine(scene, options);
    std::vector<bool> out;
    for (std::int64_t j = 0; j <= to; ++j) {
        engine->advance_to(std::max(clock.time(j), engine->time()));
        if (j < from) continue;
        out.push_back(
            answer_next_collision(*engine, engine->snapshot(), after_frame(clock, j), 30, 7)
                .askable);
    }
    return out;
}

/// Checks that `scene` is not askable on frame `frozen`, and that next_askable_frame finds the
/// first frame after it that is, where the answer is the engine's own next collision. False
/// when `frozen` is askable already (nothing to move).
bool moves_to_first_askable(const Scene& scene, const EngineOptions& options,
                            const FrameClock& clock, std::int64_t frozen) {
    const std::optional<std::int64_t> to =
        next_askable_frame(scene, options, clock, frozen, clock.count - 1);
    REQUIRE(to.has_value());
    CHECK(*to > frozen);
    const std::vector<bool> askable = askable_frames(scene, options, clock, frozen, *to);
    if (askable.front()) return false;
    CAPTURE(*to);
    // Every frame between is as quiet; the one it lands on answers.
    for (std::size_t i = 0; i + 1 < askable.size(); ++i) CHECK_FALSE(askable[i]);
    CHECK(askable.back());
    const std::unique_ptr<Engine> engine = make_engine(scene, options);
    for (std::int64_t j = 0; j <= *to; ++j) engine->advance_to(clock.time(j));
    const QuestionAnswer answer =
        answer_next_collision(*engine, engine->snapshot(), after_frame(clock, *to), 30, 11);
    REQUIRE(answer.askable);
    // A fresh engine's first collision after that frame, frame by frame.
    std::optional<CollisionRecord> truth;
    engine->set_collision_listener([&truth](const CollisionRecord& r) {
        if (!truth) truth = r;
    });
    for (std::int64_t j = *to + 1; j <= *to + look_ahead_frames && !truth; ++j)
        engine->advance_to(clock.time(j));
    engine->set_collision_listener(nullptr);
    REQUIRE(truth.has_value());
    CHECK(same_contact(answer.candidates[answer.answer], *truth));
    CHECK(answer.candidates[answer.answer].t == doctest::Approx(truth->t).epsilon(1e-9));
    return true;
}

}  // namespace

TEST_CASE("next_askable_frame: a quiet moment moves to the first frame the engine answers") {
    const FrameClock clock = clock_of(1200, 1.0 / 30.0);
    int moved = 0;
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
        CAPTURE(seed);
        EngineOptions options;
        options.engine = seed % 3 == 0 ? EngineKind::classic : EngineKind::fast;
        // The pair meets on frame 400 .. 700: askable from 300 frames before.
        const Scene pair = far_pair(static_cast<double>(400 + 37 * seed) / 30.0, seed);
        moved += moves_to_first_askable(pair, options, clock, static_cast<std::int64_t>(seed * 9));
        // A fluid slowed down: its own first collisions, wherever they are.
        moved += moves_to_first_askable(slowed_fluid(seed, 1500.0), options, clock,
                                        static_cast<std::int64_t>(seed * 5));
    }
    CHECK(moved >= 12);
}

TEST_CASE("next_askable_frame: nowhere when no later frame answers before the last") {
    const FrameClock clock = clock_of(900, 1.0 / 30.0);
    // One disc alone, to and fro between two walls: its hits are one contact (a disc and the
    // walls across x), so never a second candidate.
    Scene alone;
    alone.box = Box{1.0, 1.0, Boundary::walls};
    alone.discs.push_back(Disc{{0.3, 0.5}, {0.4, 0.0}, 0.05, 1.0, {}, ""});
    CHECK_FALSE(next_askable_frame(alone, EngineOptions{}, clock, 0, clock.count - 1));
    // A pair meeting on frame 800: askable from frame 500, not before the last frame 450.
    const Scene pair = far_pair(800.0 / 30.0, 1);
    CHECK_FALSE(next_askable_frame(pair, EngineOptions{}, clock, 10, 450));
    const std::optional<std::int64_t> later =
        next_askable_frame(pair, EngineOptions{}, clock, 10, 899);
    REQUIRE(later.has_value());
    CHECK(*later >= 499);  // the hit 300 frames on, give or take its frame's rounding
    CHECK(*later <= 501);
    CHECK_FALSE(next_askable_frame(pair, EngineOptions{}, clock, 899, 899));
}
