#pragma once
/// \file
/// What a video's subtitle track says and when: the words a student reads on screen, as plain
/// timed text (collide::Cue) for an MP4 subtitle stream or a WebVTT/SRT file beside the video.
/// Made here, from the lesson's timeline, so the encoder only ever sees text with times.

#include "collide/cue.hpp"
#include "collide/show/collision.hpp"
#include "collide/show/heap_program.hpp"
#include "collide/show/puzzle_program.hpp"
#include "collide/show/timeline.hpp"

namespace collide::show {

/// A collision video's cues, in order and never overlapping, within the timeline's video:
///  - the title card's segment: the title with the description, as on the card;
///  - every other segment (run, hold, replay, epilogue): the caption it shows, one cue per change
///    of text, so a replay's and the epilogue's words are in the track as on screen;
///  - a video without a card names its title alone first, for min(2 s, a quarter of the video),
///    then the caption on screen at that moment. Empty captions make no cue.
[[nodiscard]] Cues subtitle_cues(const Timeline& timeline, const LessonPlan& lesson);

/// Cues from a list of (start, text) steps that each last until the next one, the last until
/// `video_seconds` (heap and puzzle videos' step captions). Equal neighbours merge; empty texts
/// and steps at or past the end make no cue.
struct TimedText {
    double start = 0.0;
    std::string text;
};
[[nodiscard]] Cues cues_from_steps(const std::vector<TimedText>& steps, double video_seconds);

/// A heap lesson's cues: the step caption on screen at each frame of a video at `fps`, one cue
/// per change (with several panels, one line per panel: "binary heap: insert S at a[11]").
[[nodiscard]] Cues heap_subtitle_cues(const HeapProgram& lesson, int fps);
/// A puzzle lesson's cues: the panels' titles and captions on screen at each frame, likewise.
[[nodiscard]] Cues puzzle_subtitle_cues(const PuzzleProgram& lesson, int fps);

}  // namespace collide::show
