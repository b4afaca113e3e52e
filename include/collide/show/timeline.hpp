#pragma once
/// \file
/// A lesson's timeline: the collision video as a sequence of segments on one clock (video
/// frames), each with a kind, the simulation frame it shows and the caption a class reads. One
/// structure drives the frames (`collide render`: which simulation frame video frame k shows,
/// which caption) and is written out with `--timeline-json` (the subtitle track and the chapters
/// come from it). Plain data: built by build_timeline, read by anyone.
///
///   video frames  0 ......... C ................ a ....... a+H ............ F-E ....... F
///   segments      [ card     )[ run             )[ hold     )[ run          )[ epilogue  )
///   simulation    frozen at 0  1, 2, 3, ...  s    frozen at s  s+1, s+2 ... J  frozen at J
///
/// A frozen segment shows the simulation frame shown last (frame 0 when it comes first); the
/// run after it continues with the next one, so every simulation frame 0..J is shown, in order,
/// and the simulation clock never moves during a card, a hold, a replay or the epilogue.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace collide::show {

/// What a segment of the video is for.
enum class SegmentKind {
    card,      ///< the title card over the first frame
    run,       ///< the simulation playing
    hold,      ///< the picture frozen while a caption reads
    replay,    ///< the first failure shown again, slowly
    epilogue,  ///< the final figures side by side
    question,  ///< the picture frozen on a question while the class thinks (its countdown runs)
    reveal,    ///< the picture still frozen, the question's answer shown; the run goes on after
};

/// "card", "run", "hold", "replay", "epilogue", "question", "reveal".
[[nodiscard]] std::string_view segment_kind_name(SegmentKind kind) noexcept;

/// One segment: video frames [first_frame, end_frame) (never empty), in seconds [start, end).
struct Segment {
    SegmentKind kind = SegmentKind::run;
    std::int64_t first_frame = 0;
    std::int64_t end_frame = 0;
    double start = 0.0;  ///< seconds of video: first_frame / fps
    double end = 0.0;    ///< seconds of video: end_frame / fps
    /// The simulation frame (an index on the video's FrameClock) of the segment's first frame.
    std::int64_t sim_frame = 0;
    /// True when the simulation advances one frame per video frame; false: frozen at sim_frame.
    bool moves = true;
    std::string caption;  ///< the words shown throughout ("" none; a card: its title)
    /// A question or its reveal: the index of the question in the script's (-1: neither).
    int question = -1;

    [[nodiscard]] std::int64_t frames() const noexcept { return end_frame - first_frame; }
    /// The simulation frame video frame k shows (first_frame <= k < end_frame).
    [[nodiscard]] std::int64_t sim_frame_at(std::int64_t k) const noexcept {
        return moves ? sim_frame + (k - first_frame) : sim_frame;
    }
    /// The simulation frame of the segment's last video frame.
    [[nodiscard]] std::int64_t last_sim_frame() const noexcept {
        return sim_frame_at(end_frame - 1);
    }
};

/// The whole video. Invariants (build_timeline): the first segment starts at frame 0, each next
/// one where the previous ended (no gap, no overlap), and the simulation frames shown are
/// 0, 1, ..., last_sim_frame() in order.
struct Timeline {
    int fps = 30;
    std::vector<Segment> segments;

    /// Video frames in all (0 without segments).
    [[nodiscard]] std::int64_t frame_count() const noexcept;
    /// The segment holding video frame k (0 <= k < frame_count()).
    [[nodiscard]] const Segment& segment_at(std::int64_t k) const;
    /// The simulation frame video frame k shows.
    [[nodiscard]] std::int64_t sim_frame(std::int64_t k) const {
        return segment_at(k).sim_frame_at(k);
    }
    /// The last simulation frame the video shows (its final state).
    [[nodiscard]] std::int64_t last_sim_frame() const noexcept;
    /// Simulation frames shown: last_sim_frame() + 1.
    [[nodiscard]] std::int64_t sim_frame_count() const noexcept { return last_sim_frame() + 1; }
};

/// A scripted caption on the timeline: from `at` seconds of video, `hold` seconds of it frozen.
struct TimelineCue {
    double at = 0.0;
    std::string text;
    double hold = 0.0;  ///< seconds of video the picture stays frozen from `at` (0: none)
};

/// Seconds a class needs to read `caption` before the picture changes its subject: half a second
/// and 0.3 s a word (about 200 words a minute), at least 1.5 s and at most 4 s.
[[nodiscard]] double caption_reading_seconds(std::string_view caption) noexcept;

/// A replay on the timeline: right after the video frame that first shows simulation frame
/// `after_sim_frame`, `seconds` of video frozen on it while a failure is shown again. When the
/// caption on screen then appeared less than its reading time before, a hold on it comes first.
struct TimelineReplay {
    std::int64_t after_sim_frame = 0;
    double seconds = 0.0;
    std::string caption;
};

/// A question on the timeline (show/questions.hpp asks them): from the first running frame at or
/// after `at` seconds of video, `think` seconds frozen on the question, then `reveal` seconds
/// frozen on its answer; the simulation then runs on from the frame the picture froze on.
struct TimelineQuestion {
    double at = 0.0;
    double think = 0.0;
    double reveal = 0.0;
    std::string question;  ///< the question segment's caption
    std::string answer;    ///< the reveal segment's caption
    /// The reveal replays the failed step after the frozen frame (a will-see question): the
    /// replay of the failure whose frame follows it is not placed again.
    bool reveal_replays = false;
};

/// What the video is to show, in seconds of video.
struct TimelineScript {
    int fps = 30;
    std::int64_t frames = 1;        ///< video frames in all, >= 1
    double card_seconds = 0.0;      ///< the title card at the start (0: none)
    bool card_waits = true;         ///< the simulation waits for the card (false: runs beneath it)
    std::string card_title;         ///< the card segment's caption
    std::string caption;            ///< shown where no cue applies
    std::vector<TimelineCue> cues;  ///< `at` increasing
    /// Replays, `after_sim_frame` increasing: each takes the frames after its simulation frame
    /// is first shown (over a hold there); one that would not end before the epilogue, or whose
    /// frame is never shown running, or that would fall on a question, is left out.
    std::vector<TimelineReplay> replays;
    double epilogue_seconds = 0.0;  ///< the last seconds, frozen on the final state (0: none)
    std::string epilogue_caption;   ///< the epilogue segment's caption
    /// Questions, `at` increasing. Each takes the first stretch of think + reveal frames from
    /// `at` on that only runs (no card, hold or earlier question in it), before replays are
    /// placed; one that would not end before the epilogue is left out (see questions_asked).
    std::vector<TimelineQuestion> questions;
};

/// The segments of `script`. Seconds become whole frames (rounded); a hold that would start
/// inside the card starts after it, one that would overlap the next hold or the epilogue is cut
/// short there (plans refuse such scripts before: see the scene checks). Frozen stretches never
/// take the whole video: at least one frame runs. Never throws for a script with frames >= 1.
[[nodiscard]] Timeline build_timeline(const TimelineScript& script);

/// The questions `timeline` asks, as indices into its script's questions (each once, in order):
/// those build_timeline found room for.
[[nodiscard]] std::vector<int> questions_asked(const Timeline& timeline);

/// A timeline that only runs: video frame k shows simulation frame k (a still's frames).
[[nodiscard]] Timeline running_timeline(int fps, std::int64_t frames, std::string caption = {});

}  // namespace collide::show
