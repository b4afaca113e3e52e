#pragma once
/// \file
/// Subtitle cues and chapters: plain text and when it shows. The presentation layer
/// (collide_show) makes them from a lesson's timeline; the encoder (collide_video) writes them as
/// a subtitle track, MP4 chapters or a WebVTT/SRT file without knowing where they came from.

#include <string>
#include <vector>

namespace collide {

/// Text shown from `start` to `end` seconds of video (0 <= start < end). Lines are separated by
/// '\n'; the text is plain (no markup: characters such as '<' or '{' are just characters).
struct Cue {
    double start = 0.0;
    double end = 0.0;
    std::string text;
};

using Cues = std::vector<Cue>;

/// A chapter: a titled stretch [start, end) seconds of video, what players list for navigation.
/// `title` is one line of plain text. `still` (start <= still < end) is the time of the frame
/// that stands for the chapter: where the slide player stops and what its still shows, the last
/// frame unless that one is fading out (a title card).
struct Chapter {
    double start = 0.0;
    double end = 0.0;
    std::string title;
    double still = 0.0;
};

/// Chapters in order, each starting where the previous one ended.
using Chapters = std::vector<Chapter>;

}  // namespace collide
