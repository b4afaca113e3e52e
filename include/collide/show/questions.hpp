#pragma once
/// \file
/// Pause and ponder (issue #45): a collision video stops, asks, holds the question while the class
/// thinks, then reveals the answer, which comes from the event-driven engine itself, never from
/// the words of the scene. Here: what each kind of question asks, how the engine answers it (a
/// copy of the engine at the frozen frame is run ahead; the video's own engine is never touched),
/// the words of the question and of its answer, and what the event-driven panel draws meanwhile
/// (the candidates' lines and letters, the countdown, the answer).
///
///   timeline   ... run )[ question: frozen, "Think: 3", A B C marked )[ reveal: "Answer: B" )[ run
///   engine     the same frame throughout: a copy of it answers, the run goes on from it

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "collide/render_options.hpp"
#include "collide/scene.hpp"
#include "collide/show/collision.hpp"
#include "collide/show/replay.hpp"
#include "collide/show/timeline.hpp"
#include "collide/sim/engine.hpp"
#include "collide/snapshot.hpp"
#include "collide/view/collision.hpp"

namespace collide::show {

/// A class needs at least this long to think (seconds of video frozen on a question).
inline constexpr double min_think_seconds = 2.0;
/// The answer on screen before the run goes on, seconds of video.
inline constexpr double reveal_seconds = 2.5;
/// The most candidates a next-collision question marks (A..D), and the fewest.
inline constexpr std::size_t max_candidates = 4;
inline constexpr std::size_t min_candidates = 2;
/// How far a copy of the engine is run to find the collisions after the frozen frame, in frames
/// (at 30 frames a second, ten seconds of video): a moment quieter than that has nothing to ask
/// (the question moves on to the first frame that has: next_askable_frame).
inline constexpr std::int64_t look_ahead_frames = 300;

/// A question that cannot be asked on its frame moves to the first later moment it can (a
/// will-see question: the frame before the time-driven engine's next failed step; the others:
/// next_askable_frame). One that lands less than this many seconds of video after its `at` moves
/// without a notice: the author's moment, to within what a class could tell apart (tunnelling's
/// `at = 12` lands at 12.13 s to 12.18 s from -q l to -q h, a frame's rounding and a step apart).
inline constexpr double quiet_move_seconds = 0.5;

/// True when `kind` is answered by the event-driven engine (next-collision, how-many): a video
/// without the event-driven panel (`--mode time`) does not ask it.
[[nodiscard]] bool needs_event_panel(QuestionKind kind) noexcept;
/// True when `kind` is answered by the time-driven engine (will-see): a video without a
/// time-driven panel (`--mode event`) does not ask it.
[[nodiscard]] bool needs_time_panel(QuestionKind kind) noexcept;

/// How long the answer to `kind` shows: a will-see question's answer is the replay of the
/// failing step (replay_seconds), the others' reveal_seconds.
[[nodiscard]] double reveal_seconds_of(QuestionKind kind) noexcept;

/// What the engine answered to one question.
struct QuestionAnswer {
    QuestionKind kind = QuestionKind::next_collision;
    std::int64_t sim_frame = 0;  ///< the simulation frame the picture froze on
    double time = 0.0;           ///< its simulation time
    /// next_collision: the candidates in letter order (A, B, ...); one is the engine's next.
    std::vector<CollisionRecord> candidates;
    std::size_t answer = 0;  ///< next_collision: the index of the engine's next collision
    /// how_many: the collisions the engine resolves over the next second of video (the frames
    /// after the frozen one), between discs and with walls.
    std::int64_t pairs = 0;
    std::int64_t walls = 0;
    [[nodiscard]] std::int64_t count() const noexcept { return pairs + walls; }
    /// will_see: the time-driven engine's next step from the frozen frame, which fails (the
    /// collision of its discs is never seen by a check); the reveal replays it.
    std::optional<ReplayFailure> failure;
    /// False when the engine had nothing to ask about here (no collision within the look ahead).
    bool askable = false;
};

/// The simulation time of the frames after the frozen one: time(1) is the next frame's.
using FramesAfter = std::function<double(std::int64_t)>;

/// A next-collision question's distractors must look different from its answer in the frozen
/// picture (issue #45: at -q l gas offered three contacts that all looked touching). A later
/// collision is preferred as a distractor when it comes at least distractor_time_factor times the
/// answer's time to go after the frozen frame, and at least distractor_video_seconds of video
/// (the frames after it, at the video's speed), and when its discs (or its disc and the nearer
/// wall it hits) are at least distractor_gap_share of the box's smaller side apart now (about 5
/// pixels at -q l: not touching while they slide by). Near misses at least that far apart come
/// next, then any near miss, then any later collision (the question is asked whenever one exists).
inline constexpr double distractor_time_factor = 3.0;
inline constexpr double distractor_video_seconds = 0.4;
inline constexpr double distractor_gap_share = 0.015;

/// Which pair collides next, asked of `engine` (event-driven, at the frozen frame's time, as the
/// video has advanced it): a copy of it is run to `after(1)`, `after(2)`, ... (the calls the video
/// makes, so the same bits) until it has resolved enough collisions or `look_ahead_frames` passed.
/// The engine's first collision is a candidate; the others are collisions it resolves later (of
/// other discs where it can) that a class can tell from it in the picture (distractor_time_factor,
/// distractor_video_seconds at `fps` frames a second of video, distractor_gap_share) and, where
/// those are too few, the nearest pairs of discs that do not meet before the last collision seen
/// (visibly apart first). Their order (which letter the answer gets) is shuffled by `seed`.
/// `snapshot` is the engine's state now. Not askable when the engine resolves nothing within the
/// look ahead or cannot be copied.
[[nodiscard]] QuestionAnswer answer_next_collision(const Engine& engine, const Snapshot& snapshot,
                                                   const FramesAfter& after, int fps,
                                                   std::uint64_t seed);

/// How many collisions in the next second of video: a copy of `engine` run to after(1) ..
/// after(fps), the collisions it resolves counted (a second without any is askable too: zero).
[[nodiscard]] QuestionAnswer answer_how_many(const Engine& engine, const FramesAfter& after,
                                             int fps);

/// Will the next check see this collision? Asked on simulation frame `sim_frame` (time `time`),
/// the frame just before the one that first shows the state after `failure`'s step (the
/// time-driven engine's own record of a failed step, found by running it as the video does):
/// askable only there, and then the answer is the engine's: the check did not see it.
[[nodiscard]] QuestionAnswer answer_will_see(const ReplayFailure& failure, std::int64_t sim_frame,
                                             double time);

/// Where a question was written, for notices: "gas.toml:42" ("the scene" when not read from a
/// file).
[[nodiscard]] std::string question_place(const QuestionCue& cue);

/// "A", "B", ...: candidate i's letter.
[[nodiscard]] std::string candidate_letter(std::size_t i);

/// The question's words: `authored` when the scene gives them, else the kind's ("Pause and think:
/// which pair collides next, A, B or C?"); at most max_caption_chars.
[[nodiscard]] std::string question_words(const QuestionAnswer& answer, const std::string& authored);
/// The answer's words: "Answer: B, discs 12 and 40 (in 0.42)", "Answer: 7 collisions (5 between
/// discs, 2 with walls)". At most max_caption_chars.
[[nodiscard]] std::string answer_words(const QuestionAnswer& answer, const FrameClock& clock);

/// The countdown while a question holds: "Think: 3" with `seconds_left` in (2, 3].
[[nodiscard]] std::string countdown_words(double seconds_left);

/// What the time-driven panel draws while a will-see question holds: the failing step's two discs
/// marked (the others faint), each one's move over the next step as an arrow, "Think: 3". The
/// reveal is the replay (replay_views of answer.failure).
[[nodiscard]] ReplayView will_see_view(const QuestionAnswer& answer, double seconds_left);

/// How long the arrow of the fastest disc of a next-collision question is, a share of the box's
/// smaller side (the other discs' arrows are their moves over the same time): about 50 pixels
/// where the box is 340 high, as it is at `-q l`.
inline constexpr double motion_arrow_share = 0.15;

/// The least gap a next-collision question keeps between two candidates' drawings (their discs,
/// connectors and velocity arrows), a share of the box's smaller side (about 3 pixels at -q l),
/// where the engine offers distractors that allow it: candidates whose lines cross read as one
/// tangle.
inline constexpr double drawing_gap_share = 0.01;

/// What the event-driven panel draws while the question holds (`reveal` false: the candidates'
/// lines, each candidate disc's velocity as an arrow ending at its leading edge
/// (motion_arrow_share), their letters on plates clear of every disc, the others faint, and
/// "Think: 3" counting down over `seconds_left`) and while its answer shows (`reveal`: the
/// answer's line in the failure colour with its letter and arrows, the others faded, "Answer:
/// B"). The heading keeps clear of every disc (keep_clear: all of them). `snapshot`: the frozen
/// state.
[[nodiscard]] ReplayView question_view(const QuestionAnswer& answer, const Snapshot& snapshot,
                                       const FrameClock& clock, double seconds_left, bool reveal);

/// Where a letter's plate goes: the point nearest `near` inside `box` that keeps `plate` box units
/// from every disc's edge, from `taken` (letters placed before, `plate` apart again) and from
/// `lines` (the other candidates' lines), searched on rings around `near`; where none keeps off
/// the lines, the same without them; the freest point found where none keeps that far from the
/// discs and letters.
[[nodiscard]] Vec2 clear_spot(Vec2 near, double plate, const Snapshot& snapshot,
                              const std::vector<Vec2>& taken,
                              const std::vector<BoxLine>& lines = {});

/// Every question `timeline` asks (questions_asked), answered by an event-driven engine of
/// `scene` (`options`) advanced frame by frame on `clock` to the frame each question freezes on.
/// Indexed like the script's questions (`kinds`); a question the timeline does not ask, or a
/// will-see question (the time-driven engine answers those: answer_will_see), stays not askable.
/// Throws Error(input) for options make_engine rejects, Error(runtime) once `stop` is set.
[[nodiscard]] std::vector<QuestionAnswer> answer_questions(const Scene& scene,
                                                           const EngineOptions& options,
                                                           const FrameClock& clock,
                                                           const Timeline& timeline,
                                                           const std::vector<QuestionKind>& kinds,
                                                           const std::atomic<bool>* stop = nullptr);

/// Where a next-collision question not askable on simulation frame `frozen` can be asked: the
/// first frame after it, up to `last`, at which answer_next_collision answers (the event-driven
/// engine of `scene` resolves a collision within look_ahead_frames of it, and a second candidate
/// exists); nullopt when none does. One engine run ahead of the frames tried, frame by frame on
/// `clock` as the video runs it (the same calls as answer_questions makes, so the same bits):
/// O(frames) steps of the engine, not one copy run per frame tried. Throws Error(input) for
/// options make_engine rejects, Error(runtime) once `stop` is set.
[[nodiscard]] std::optional<std::int64_t> next_askable_frame(
    const Scene& scene, const EngineOptions& options, const FrameClock& clock, std::int64_t frozen,
    std::int64_t last, const std::atomic<bool>* stop = nullptr);

}  // namespace collide::show
