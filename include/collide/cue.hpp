#pragma once
/// \file
/// A subtitle cue: plain text and when it shows. The presentation layer (collide_show) makes
/// them from a lesson's schedule; the encoder (collide_video) writes them as a subtitle track or
/// a WebVTT/SRT file without knowing where they came from.

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

}  // namespace collide
