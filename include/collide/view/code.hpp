#pragma once
/// \file
/// The lecture's pseudocode on screen (`--code`): a listing beside the animation, one line
/// marked as the one the picture is carrying out. The presentation layer (collide/show/...)
/// writes the lines and picks the marked one for frame k; a painter draws them as it is told
/// (the current line on a plate with a marker beside it, so that it reads without colour).
/// Std-only: no simulation types, no drawing.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace collide::view {

/// One line of a listing.
struct CodeLineView {
    int indent = 0;    ///< nesting depth, >= 0: the painter indents by a fixed step per level
    std::string text;  ///< the line without its indentation, e.g. "exchange a[k] and a[j]"
};

/// A listing and where the animation is in it.
struct CodeView {
    std::string title;                ///< over the listing, e.g. "the code"; "" draws none
    std::vector<CodeLineView> lines;  ///< top to bottom
    /// The line the frame shows being carried out (an index into `lines`); unset: none (before
    /// the first step, between operations, after the last).
    std::optional<std::size_t> current;
};

}  // namespace collide::view
