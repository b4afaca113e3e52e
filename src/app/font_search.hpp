#pragma once
// Which TrueType font the drawing commands (render, thumbnail, heap, puzzle) paint text with.

#include <string>

namespace collide::app {

/// --font's help, the same on every drawing command.
inline constexpr const char* font_option_help =
    "TrueType font for the text (default: $COLLIDE_FONT, else DejaVu Sans from fonts-dejavu-core, "
    "else fontconfig's DejaVu Sans)";

/// The font file for on-screen text, first of (docs/outputs.md, "Fonts"):
///  1. `requested` (the command's --font FILE) when not empty;
///  2. $COLLIDE_FONT when set and not empty;
///  3. DejaVu Sans where Debian (fonts-dejavu-core), Fedora and Arch install it;
///  4. the file fontconfig names for "DejaVu Sans" (`fc-match`, when it is installed).
/// When none exists, the Debian path: the renderer then fails naming it and these choices.
/// Throws Error(input) naming the option or variable when --font or $COLLIDE_FONT names
/// something that is not a usable font file (missing, not a regular file, not a font, damaged,
/// beyond text::max_font_file_bytes).
[[nodiscard]] std::string find_font(const std::string& requested);

}  // namespace collide::app
