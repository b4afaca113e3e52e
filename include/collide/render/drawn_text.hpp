#pragma once
/// \file
/// The text of the last frame a lesson painter drew (HeapRenderer, PuzzleRenderer), line by line
/// with its size: what tests read to check that every word a class reads is legible from the back
/// of a hall (capitals at least 2.8 % of the frame height) without decoding pixels.

#include <string>

namespace collide::render {

/// One piece of text drawn in a frame.
struct DrawnText {
    std::string text;         ///< as drawn (after any wrapping or cutting)
    float cap_height = 0.0F;  ///< height of a capital letter, pixels
};

}  // namespace collide::render
