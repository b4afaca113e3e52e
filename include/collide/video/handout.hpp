#pragma once
/// \file
/// A handout: a PDF with one page per chapter, its still and its words (what a slide deck's PDF
/// export gives a class), drawn through cairo. Sees only images and text.

#include <string>
#include <vector>

#include "collide/image.hpp"

namespace collide::video {

/// One page: a chapter's title, the frame that stands for it and the words on screen with it.
struct HandoutPage {
    std::string title;    ///< one line, e.g. "Collisions are predicted"
    Image still;          ///< RGBA, any size (scaled to the page, aspect kept)
    std::string caption;  ///< plain text, lines separated by '\n'; may be empty
};

/// The widest still a page keeps: about 190 dpi across the page's 27 cm, more than a printer
/// shows, so a 4K video's handout stays small (and so do the stills held until the PDF is made).
inline constexpr int max_handout_still_width = 1600;

/// `frame` as a page keeps it: shrunk by the smallest whole factor that brings it to at most
/// max_handout_still_width pixels wide (each pixel the mean of a factor x factor box; edges that
/// do not fill a box are dropped), or as it is when narrow enough. Cost: O(width * height).
[[nodiscard]] Image handout_still(const Image& frame);

/// The PDF's bytes: A4 landscape pages, each with the document's `title` and the page's number
/// in a footer, the chapter's title, its still and its caption wrapped under it. Cost: the
/// stills' pixels, compressed. Throws Error(runtime) when there are no pages or cairo fails.
[[nodiscard]] std::string handout_pdf(const std::vector<HandoutPage>& pages,
                                      const std::string& title);

}  // namespace collide::video
