#pragma once
/// \file
/// A video's chapters: where players let a class jump to and where the slide player stops, with
/// the titles they list. Made here from the lesson's timeline (a collision video) or from the
/// step captions (heap and puzzle videos), so the encoder only ever sees titled times.

#include <vector>

#include "collide/cue.hpp"
#include "collide/show/heap_program.hpp"
#include "collide/show/timeline.hpp"

namespace collide::show {

/// The shortest chapter of a heap video, in seconds of video: a class jumps between operations,
/// not between steps (a chapter per step made 55 chapters in 43 s).
inline constexpr double min_heap_chapter_seconds = 4.0;

/// The shortest stretch of the run showing a caption again that is a chapter of its own, in
/// seconds of video: a caption back for a third of a second between a replay and a question is
/// no stop for the slide player.
inline constexpr double min_run_chapter_seconds = 1.0;

/// A collision video's chapters, one per stretch of the timeline a class would name: the title
/// card (its title), each caption (the run and the hold that show it are one chapter), the
/// replay, each question (the slide player stops on it, its countdown over) and its answer, and
/// the epilogue; a caption back for less than min_run_chapter_seconds joins the chapter after it.
/// Back to back from 0 to the video's end, at the segments' frame times; titles are one line (a
/// caption's line breaks become spaces). Each chapter's still is its last frame; the card's is its
/// last frame before the fade-out of `card_fade` seconds at its end
/// (LessonPlan::intro_fade_seconds); a replay's, and the reveal of a question whose
/// `replaying_reveals` entry (by question index) is true, the last frame of the replay's hold,
/// before its picture fades (replay_hold_end): a handout page or a slide shows the failure whole,
/// not the nearly empty frame it fades to. Empty for an empty timeline.
[[nodiscard]] Chapters timeline_chapters(const Timeline& timeline, double card_fade = 0.0,
                                         const std::vector<bool>& replaying_reveals = {});

/// Chapters from subtitle cues (heap and puzzle videos: one per step caption): each starts
/// where its cue starts (the first at 0) and ends where the next begins, the last at
/// `video_seconds`; the title is the cue's text on one line (a panel per line becomes
/// "line / line"); the still is its last frame at `fps`. Empty when there are no cues.
[[nodiscard]] Chapters chapters_from_cues(const Cues& cues, double video_seconds, int fps);

/// A heap video's chapters: one per operation ("insert S", "remove the max X", "build the
/// heap"), the operations too short for a chapter of their own grouped with the next ones
/// ("insert P, insert Q, insert E"; more than three: "insert P ... insert E (5 operations)") so
/// that every chapter lasts at least min_heap_chapter_seconds (one chapter for a shorter video).
/// The intro goes with the first operation, the outro with the last; back to back from 0 to
/// `video_seconds`; the still is each chapter's last frame at `fps`. A question
/// (HeapProgram::questions) ends its chapter where its reveal starts ("insert S: Where does S end
/// up: A, B or C?"; the slide player stops on it) and its reveal starts the next ("Answer: B, S
/// ends up at a[2]").
[[nodiscard]] Chapters heap_chapters(const HeapProgram& lesson, double video_seconds, int fps);

/// `text` as one line: line breaks become `separator`, runs of spaces one space, no spaces at
/// either end.
[[nodiscard]] std::string one_line(const std::string& text, std::string_view separator = " ");

}  // namespace collide::show
