#include "collide/video/handout.hpp"

#include <cairo-pdf.h>
#include <cairo.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "collide/error.hpp"

namespace collide::video {

namespace {

// A4 landscape in PostScript points (1/72 inch), what cairo's PDF surface measures in.
constexpr double page_width = 841.89;
constexpr double page_height = 595.28;
constexpr double margin = 36.0;
constexpr double title_size = 18.0;
constexpr double caption_size = 12.0;
constexpr double footer_size = 8.0;
/// Room kept under the still for the caption: four lines at most are what a chapter's words
/// take (a caption, a heap step); longer text is cut with an ellipsis.
constexpr int caption_lines = 4;
constexpr double line_gap = 1.35;
/// Sans-serif through fontconfig: the handout is read on paper, next to the video's own font.
constexpr const char* font_family = "sans-serif";

struct SurfaceDeleter {
    void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
struct ContextDeleter {
    void operator()(cairo_t* c) const { cairo_destroy(c); }
};
using Surface = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;
using Context = std::unique_ptr<cairo_t, ContextDeleter>;

cairo_status_t append_bytes(void* closure, const unsigned char* data, unsigned int length) {
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
}

void check(cairo_status_t status, const char* what) {
    if (status != CAIRO_STATUS_SUCCESS)
        throw_runtime_error(std::string("handout: ") + what + ": " +
                            cairo_status_to_string(status));
}

/// The still as a cairo image (RGB24: the frames are opaque; premultiplied BGRx in memory).
Surface image_surface(const Image& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4)
        throw_runtime_error("handout: a chapter's still is empty");
    Surface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, image.width, image.height));
    check(cairo_surface_status(surface.get()), "cannot hold a still");
    cairo_surface_flush(surface.get());
    unsigned char* data = cairo_image_surface_get_data(surface.get());
    const int stride = cairo_image_surface_get_stride(surface.get());
    for (int y = 0; y < image.height; ++y) {
        auto* row =
            reinterpret_cast<std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
        const unsigned char* in = image.rgba.data() + static_cast<std::size_t>(y) * image.width * 4;
        for (int x = 0; x < image.width; ++x, in += 4) {
            row[x] = (std::uint32_t{in[0]} << 16) | (std::uint32_t{in[1]} << 8) | in[2];
        }
    }
    cairo_surface_mark_dirty(surface.get());
    return surface;
}

double text_width(cairo_t* cr, const std::string& text) {
    cairo_text_extents_t extents;
    cairo_text_extents(cr, text.c_str(), &extents);
    return extents.x_advance;
}

/// `text` broken at spaces into lines no wider than `width` at the current font (a word wider
/// than the line stays whole); the text's own line breaks are kept.
std::vector<std::string> wrapped_lines(cairo_t* cr, const std::string& text, double width) {
    std::vector<std::string> lines;
    std::istringstream paragraphs(text);
    for (std::string paragraph; std::getline(paragraphs, paragraph);) {
        std::istringstream words(paragraph);
        std::string line;
        for (std::string word; words >> word;) {
            const std::string longer = line.empty() ? word : line + " " + word;
            if (!line.empty() && text_width(cr, longer) > width) {
                lines.push_back(line);
                line = word;
            } else {
                line = longer;
            }
        }
        if (!line.empty()) lines.push_back(line);
    }
    return lines;
}

void draw_text(cairo_t* cr, double x, double baseline, const std::string& text) {
    cairo_move_to(cr, x, baseline);
    cairo_show_text(cr, text.c_str());
}

/// The still scaled into the box (x, y, w, h), centred, aspect kept, with a thin frame.
void draw_still(cairo_t* cr, const Image& image, double x, double y, double w, double h) {
    const Surface still = image_surface(image);
    const double scale = std::min(w / image.width, h / image.height);
    const double shown_w = image.width * scale;
    const double shown_h = image.height * scale;
    const double left = x + (w - shown_w) / 2;
    cairo_save(cr);
    cairo_translate(cr, left, y);
    cairo_scale(cr, scale, scale);
    cairo_set_source_surface(cr, still.get(), 0, 0);
    cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_GOOD);
    cairo_paint(cr);
    cairo_restore(cr);
    cairo_set_source_rgb(cr, 0.6, 0.6, 0.6);
    cairo_set_line_width(cr, 0.5);
    cairo_rectangle(cr, left, y, shown_w, shown_h);
    cairo_stroke(cr);
}

void draw_page(cairo_t* cr, const HandoutPage& page, const std::string& footer) {
    const double text_width_max = page_width - 2 * margin;
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    cairo_select_font_face(cr, font_family, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
    cairo_set_font_size(cr, title_size);
    // A long title (a caption) is set smaller to stay on one line, down to the caption's size.
    const double title_width = text_width(cr, page.title);
    if (title_width > text_width_max)
        cairo_set_font_size(cr, std::max(caption_size, title_size * text_width_max / title_width));
    double y = margin + title_size;
    draw_text(cr, margin, y, page.title);
    y += title_size * 0.6;

    const double caption_height = caption_lines * caption_size * line_gap;
    const double still_height = page_height - y - margin - caption_height - footer_size * 3;
    draw_still(cr, page.still, margin, y, text_width_max, still_height);
    const double shown_h = page.still.height * std::min(text_width_max / page.still.width,
                                                        still_height / page.still.height);
    y += shown_h + caption_size * 1.8;

    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    cairo_select_font_face(cr, font_family, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, caption_size);
    std::vector<std::string> lines = wrapped_lines(cr, page.caption, text_width_max);
    if (lines.size() > static_cast<std::size_t>(caption_lines)) {
        lines.resize(caption_lines);
        lines.back() += " \xE2\x80\xA6";  // the rest is in the video
    }
    for (const std::string& line : lines) {
        draw_text(cr, margin, y, line);
        y += caption_size * line_gap;
    }

    cairo_set_source_rgb(cr, 0.4, 0.4, 0.4);
    cairo_set_font_size(cr, footer_size);
    draw_text(cr, page_width - margin - text_width(cr, footer), page_height - margin / 2, footer);
}

}  // namespace

Image handout_still(const Image& frame) {
    const int factor = (frame.width + max_handout_still_width - 1) / max_handout_still_width;
    if (factor <= 1) return frame;
    Image still(frame.width / factor, frame.height / factor);
    const int area = factor * factor;
    for (int y = 0; y < still.height; ++y) {
        for (int x = 0; x < still.width; ++x) {
            int sum[4] = {0, 0, 0, 0};
            for (int dy = 0; dy < factor; ++dy) {
                const std::uint8_t* in = frame.pixel(x * factor, y * factor + dy);
                for (int dx = 0; dx < factor; ++dx, in += 4) {
                    for (int c = 0; c < 4; ++c) sum[c] += in[c];
                }
            }
            std::uint8_t* out = still.pixel(x, y);
            for (int c = 0; c < 4; ++c) out[c] = static_cast<std::uint8_t>(sum[c] / area);
        }
    }
    return still;
}

std::string handout_pdf(const std::vector<HandoutPage>& pages, const std::string& title) {
    if (pages.empty()) throw_runtime_error("handout: no chapters, so no pages");
    std::string bytes;
    {
        const Surface pdf(
            cairo_pdf_surface_create_for_stream(append_bytes, &bytes, page_width, page_height));
        check(cairo_surface_status(pdf.get()), "cannot start the PDF");
        cairo_pdf_surface_set_metadata(pdf.get(), CAIRO_PDF_METADATA_TITLE, title.c_str());
        cairo_pdf_surface_set_metadata(pdf.get(), CAIRO_PDF_METADATA_CREATOR, "collide");
        const Context cr(cairo_create(pdf.get()));
        for (std::size_t i = 0; i < pages.size(); ++i) {
            const std::string footer = title + "  \xC2\xB7  " + std::to_string(i + 1) + " / " +
                                       std::to_string(pages.size());
            draw_page(cr.get(), pages[i], footer);
            cairo_show_page(cr.get());
            check(cairo_status(cr.get()), "cannot draw a page");
        }
        cairo_surface_finish(pdf.get());
        check(cairo_surface_status(pdf.get()), "cannot finish the PDF");
    }
    return bytes;
}

}  // namespace collide::video
