#pragma once
/// \file
/// The slide player (`--slides DIR`): one self-contained index.html that plays the video beside
/// it and stops at the end of each chapter, for a lecturer stepping through a lesson in class.
/// Inline CSS and JavaScript only (no network, no library), so the folder works from a USB stick
/// opened as file://. Keys: right arrow, space, Page Down or a click go on; left arrow or Page
/// Up go back a chapter; F full screen; S subtitles on and off. Its words (the key help, the
/// chapter line) are decided here, like every word a class reads.

#include <string>

#include "collide/cue.hpp"

namespace collide::show {

/// What the page shows: file names are relative to the page (in its folder).
struct SlidePage {
    std::string title;      ///< the page's title (the scene's title); empty: "collide"
    std::string video;      ///< the MP4's file name ("video.mp4")
    std::string subtitles;  ///< a WebVTT file for the <track> element; empty: none
    std::string language;   ///< the subtitles' language tag (BCP 47, e.g. "pl"; "und")
    Cues cues;              ///< the subtitles' cues, used where the browser refuses the file
    Chapters chapters;      ///< where the player stops; at least one
    int fps = 30;           ///< the video's frame rate: a chapter stops on its last frame
    /// The video draws its captions: the track is loaded but hidden and there is no subtitles
    /// button, so that no caption is drawn twice.
    bool cues_in_picture = false;
};

/// The page's HTML. With `?test` in its address the page plays two chapters by itself, pressing
/// the keys a lecturer would, and writes what it saw into <pre id="test-log"> (a browser test
/// reads it: "chapters N", "subtitles CUES", "showing TRACKS" (the text tracks the browser
/// draws over the video) at the start and at each stop, "stop CHAPTER SECONDS paused" at each
/// stop, "back CHAPTER SECONDS", "end").
[[nodiscard]] std::string slide_page_html(const SlidePage& page);

}  // namespace collide::show
