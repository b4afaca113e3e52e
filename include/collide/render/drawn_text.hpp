#pragma once
/// \file
/// The text of the last frame a lesson painter drew (HeapRenderer, PuzzleRenderer), line by line
/// with its size and place: what tests read to check that every word a class reads is legible
/// from the back of a hall (capitals at least 2.8 % of the frame height) and inside the tile,
/// slot or node it labels, without decoding pixels.

#include <optional>
#include <string>
#include <vector>

namespace collide::render {

/// A rectangle in frame pixels (y down), its corners rounded by `corner` pixels: a tile or a slot
/// (0), a round node (half its height: a disc, or a pill when wider than tall).
struct DrawnShape {
    float x0 = 0.0F;
    float y0 = 0.0F;
    float x1 = 0.0F;
    float y1 = 0.0F;
    float corner = 0.0F;
};

/// A straight line in frame pixels: a piece of a question plate's leader.
struct DrawnSegment {
    float x0 = 0.0F;
    float y0 = 0.0F;
    float x1 = 0.0F;
    float y1 = 0.0F;
};

/// One piece of text drawn in a frame.
struct DrawnText {
    std::string text;         ///< as drawn (after any wrapping or cutting)
    float cap_height = 0.0F;  ///< height of a capital letter, pixels
    /// Where it is: from its start to its advance's end across, from the top of a capital to
    /// the baseline down.
    DrawnShape box;
    /// The tile, slot or node it labels (a key, a tile's number, a slot's index), if any: the
    /// text belongs inside it.
    std::optional<DrawnShape> shape;
    /// Laid over the picture (a question's letter on its plate, `shape`): it must cover no other
    /// text, shape or node.
    bool over = false;
    /// The leader from a plate laid far from its node (`over`), from the node's outline to the
    /// plate's edge, straight or bent once (empty: none): it passes through no other node.
    std::vector<DrawnSegment> leader{};
};

}  // namespace collide::render
