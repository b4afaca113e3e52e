// Frames of `collide puzzle`: a heading over one or two panels (BFS left, A* right). Each panel
// is laid out in a 1280x720 design space scaled to the frame, described as a DrawList
// (rectangles, lines, text) on the CPU and drawn by GlTarget, like the collision frames.
#include "collide/render/puzzle_view.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "code_panel.hpp"
#include "collide/assert.hpp"
#include "collide/error.hpp"
#include "draw_list.hpp"
#include "font.hpp"
#include "gl_target.hpp"
#include "layout.hpp"
#include "theme.hpp"

namespace collide::render {

void PuzzleViewConfig::validate() const {
    const auto check = [](const char* field, int value, int low) {
        if (value < low || value > 8192) {
            throw_input_error(std::string("puzzle view.") + field + ": must be in [" +
                              std::to_string(low) + ", 8192], got " + std::to_string(value));
        }
    };
    check("width", width, 320);
    check("height", height, 180);
    if (font_path.empty()) throw_input_error("puzzle view.font_path: must name a TrueType font");
}

namespace {

/// The design space: positions are given for 1280x720 and scaled.
constexpr float design_width = 1280.0F;
constexpr float design_height = 720.0F;

/// Font sizes in design pixels; no text is drawn under the lesson size (Impl::lesson_px).
constexpr float heading_px = 34.0F;
constexpr float title_px = 34.0F;
constexpr float playback_px = 38.0F;

/// A small board's digits are the lesson size; a cell is this much larger.
constexpr float cell_per_digit = 1.28F;

/// What the caller promises about a board (a bug when broken: see collide/assert.hpp).
void check_board(const view::PuzzleBoardView& b) {
    COLLIDE_ASSERT(
        b.side >= 2 && b.side <= 4 && b.tiles.size() == static_cast<std::size_t>(b.side * b.side),
        "a board of side 2 to 4 with side * side tiles");
}

}  // namespace

struct PuzzleRenderer::Impl {
    PuzzleViewConfig config;
    PuzzlePalette colors;
    GlTarget target;  // owns the context: destroyed first, its objects with it
    float sx = 1.0F;
    float sy = 1.0F;
    float s = 1.0F;                   // scale of sizes (fonts, boards): the smaller of sx and sy
    float lesson = 10.0F;             // the smallest text, px: capitals 2.8 % of the frame height
    std::map<int, FontAtlas> fonts;   // by pixel height
    std::map<int, std::size_t> runs;  // pixel height -> index in list.text
    DrawList list;
    std::vector<DrawnText> drawn;  // the frame's text, for last_text()

    Impl(const PuzzleViewConfig& cfg, std::unique_ptr<Context> context)
        : config(cfg),
          colors(puzzle_palette(cfg.theme)),
          target(cfg.width, cfg.height, std::move(context)) {
        sx = static_cast<float>(config.width) / design_width;
        sy = static_cast<float>(config.height) / design_height;
        s = std::min(sx, sy);
        lesson = lesson_pixel_height(config.width, config.height);
        // Every size the frames use, baked once (a missing font fails here, before any frame).
        for (float px : {heading_px, title_px, playback_px}) (void)font(design(px));
        (void)font(lesson);
        list.background = colors.background;
    }

    /// A design size in frame pixels, never under the lesson size.
    [[nodiscard]] float design(float design_px) const { return std::max(lesson, design_px * s); }

    const FontAtlas& font(float px) {
        const int key = static_cast<int>(std::lround(std::max(lesson, px)));
        auto it = fonts.find(key);
        if (it == fonts.end()) {
            it = fonts.try_emplace(key, config.font_path, static_cast<float>(key)).first;
            runs[key] = list.text.size();
            list.text.push_back({&it->second, {}});
        }
        return it->second;
    }

    [[nodiscard]] float line(float px) { return font(px).line_height(); }

    /// Text with its baseline at (x, y) in frame pixels, `px` pixels tall; returns the x after it.
    /// `shape`: the tile it numbers, if any (for last_text).
    float text(float x, float y, float px, std::string_view str, Rgba8 color,
               std::optional<DrawnShape> shape = std::nullopt) {
        const FontAtlas& f = font(px);
        const int key = static_cast<int>(std::lround(f.pixel_height()));
        const float cap = f.pixel_height() * cap_height_per_pixel_height;
        x = std::round(x);
        y = std::round(y);
        drawn.push_back({std::string(str), cap, {x, y - cap, x + f.text_width(str), y}, shape});
        return f.add_text(list.text[runs.at(key)].glyphs, x, y, str, color);
    }

    float width_of(float px, std::string_view str) { return font(px).text_width(str); }

    void centred_text(float cx, float y, float px, std::string_view str, Rgba8 color) {
        text(cx - width_of(px, str) / 2.0F, y, px, str, color);
    }

    /// Text cut with "..." to fit `width` pixels.
    void fitted_text(float x, float y, float width, float px, std::string str, Rgba8 color) {
        while (str.size() > 3 && width_of(px, str) > width) {
            str.erase(str.size() - 4);
            str += "...";
        }
        text(x, y, px, str, color);
    }

    /// Text wrapped to `width` on at most `max_lines` lines from the top `y`; returns the y
    /// under it.
    float wrapped_text(float x, float y, float width, float px, const std::string& str,
                       std::size_t max_lines, Rgba8 color, bool centred = false) {
        std::vector<std::string> lines = wrap_words(font(px), str, width);
        if (lines.size() > max_lines) lines.resize(max_lines);
        for (const std::string& l : lines) {
            if (centred) {
                centred_text(x + width / 2.0F, y + font(px).ascent(), px, l, color);
            } else {
                fitted_text(x, y + font(px).ascent(), width, px, l, color);
            }
            y += line(px);
        }
        return y;
    }

    [[nodiscard]] float X(float design_x) const { return design_x * sx; }
    [[nodiscard]] float Y(float design_y) const { return design_y * sy; }

    /// A board whose top-left corner is (x, y) with cells `cell` pixels wide; a tile sliding as
    /// `slide` says is drawn between its two cells.
    void draw_board(const view::PuzzleBoardView& b, float x, float y, float cell, float font_px,
                    const view::PuzzleSlideView& slide = {}) {
        const float gap = std::max(1.0F, std::round(cell * 0.08F));
        const float size = cell * static_cast<float>(b.side);
        list.under.add_rect({x - gap, y - gap, x + size + gap, y + size + gap}, colors.blank);
        for (int i = 0; i < b.side * b.side; ++i) {
            const int tile = b.tiles[static_cast<std::size_t>(i)];
            if (tile == 0 || i == slide.to) continue;
            draw_tile(tile, x + cell * static_cast<float>(i % b.side),
                      y + cell * static_cast<float>(i / b.side), cell, gap, font_px, colors.tile);
        }
        if (slide.from >= 0 && slide.to >= 0) {
            const int tile = b.tiles[static_cast<std::size_t>(slide.to)];
            const float t = std::clamp(slide.t, 0.0F, 1.0F);
            const float fx = static_cast<float>(slide.from % b.side);
            const float fy = static_cast<float>(slide.from / b.side);
            const float tx = static_cast<float>(slide.to % b.side);
            const float ty = static_cast<float>(slide.to / b.side);
            draw_tile(tile, x + cell * (fx + (tx - fx) * t), y + cell * (fy + (ty - fy) * t), cell,
                      gap, font_px, colors.sliding_tile);
        }
        if (b.mark != view::PuzzleMark::plain) {
            const float w = std::max(2.0F, std::round(4.0F * s));
            list.under.add_frame({x - gap - w, y - gap - w, x + size + gap + w, y + size + gap + w},
                                 w, puzzle_mark_color(b.mark, colors));
        }
    }

    void draw_tile(int tile, float x, float y, float cell, float gap, float font_px, Rgba8 fill) {
        const RectF face{x + gap / 2, y + gap / 2, x + cell - gap / 2, y + cell - gap / 2};
        list.under.add_rect(face, fill);
        const FontAtlas& f = font(font_px);
        const std::string label = std::to_string(tile);
        text(x + (cell - f.text_width(label)) / 2.0F, y + (cell + f.ascent() * 0.72F) / 2.0F,
             font_px, label, colors.tile_text,
             DrawnShape{face.x0, face.y0, face.x1, face.y1, 0.0F});
    }

    /// The smallest cell whose tile holds the board's widest number at the lesson size with a
    /// margin either side (two digits on a 15-puzzle): the tiles' numbers never run together.
    [[nodiscard]] float least_cell(int side) {
        const float digits = width_of(lesson, side * side > 10 ? "00" : "0");
        // The tile is the cell less its gap (8 %); a fifth of a capital either side of the number.
        return std::ceil((digits + 0.25F * lesson) / 0.92F);
    }

    /// The cell of a small board: its digits at the lesson size, in a cell a little larger
    /// (cell_per_digit) where a box of `width` x `height` has room, never smaller than they need.
    [[nodiscard]] float small_cell(int side, float width, float height) {
        const float fit = std::min(width, height) / static_cast<float>(side);
        const float least = least_cell(side);
        return std::floor(std::max(std::min(fit, std::max(cell_per_digit * lesson, least)), least));
    }

    /// The side of the panel's boards (3 before any is drawn).
    [[nodiscard]] static int side_of(const view::PuzzlePanelView& p) {
        if (!p.board.tiles.empty()) return p.board.side;
        if (!p.queue.empty()) return p.queue.front().side;
        for (const view::PuzzleRowView& row : p.rows) {
            if (!row.boards.empty()) return row.boards.front().side;
        }
        return 3;
    }

    /// The widest board label ("12+19=31"): the width a board's slot needs.
    [[nodiscard]] float label_room() { return width_of(lesson, "00+00=00"); }

    void draw_panel(const view::PuzzlePanelView& p, RectF area) {
        list.under.add_rect(area, colors.panel);
        const float pad = X(14);
        const float inner = area.width() - 2.0F * pad;
        const float x0 = area.x0 + pad;
        // Header: the title (two lines at most), one counter a line, the status.
        float y = wrapped_text(x0, area.y0 + 0.5F * pad, inner, design(title_px), p.title, 2,
                               colors.title);
        for (const std::string& c : p.counters) {
            fitted_text(x0, y + font(lesson).ascent(), inner, lesson, c, colors.counter);
            y += line(lesson);
        }
        fitted_text(x0, y + font(lesson).ascent(), inner, lesson, p.status, colors.status);
        y += line(lesson) + 0.5F * pad;
        const RectF body{x0, y, area.x1 - pad, area.y1 - pad};
        if (p.playback) {
            draw_playback(p, body);
            return;
        }
        const int side = side_of(p);
        const float board_w =
            static_cast<float>(side) * std::max(cell_per_digit * lesson, least_cell(side));
        const float queue_w = std::max(label_room(), board_w) + X(8);
        const RectF tree{body.x0, body.y0, body.x1 - queue_w - X(16), body.y1};
        if (p.rows.empty() && !p.board.tiles.empty()) {
            draw_playback(p, tree);  // before the first expansion: the start, large
        } else {
            draw_tree(p, tree);
        }
        draw_queue(p, {body.x1 - queue_w, body.y0, body.x1, body.y1});
    }

    void draw_tree(const view::PuzzlePanelView& p, RectF area) {
        const float l = line(lesson);
        const float ascent = font(lesson).ascent();
        float top = area.y0;
        if (!p.hidden_rows.empty()) {
            fitted_text(area.x0, top + ascent, area.width(), lesson, p.hidden_rows, colors.label);
            top += l;
        }
        const std::size_t rows = std::min(p.rows.size(), p.shown.rows);
        if (rows == 0) return;
        const float row_h = (area.y1 - top) / static_cast<float>(p.shown.rows);
        const float slot_w = area.width() / static_cast<float>(p.shown.row_boards);
        const float gap = 0.3F * l;
        // Label centres of the row above, for the edges.
        std::vector<PointF> above;
        for (std::size_t r = 0; r < rows; ++r) {
            const view::PuzzleRowView& row = p.rows[r];
            const float y = top + row_h * static_cast<float>(r);
            const std::string label = row.label + ": " + row.count;
            fitted_text(area.x0, y + ascent, area.width(), lesson, label, colors.title);
            std::vector<PointF> here;
            const std::size_t n = std::min(row.boards.size(), p.shown.row_boards);
            for (std::size_t i = 0; i < n; ++i) {
                const view::PuzzleBoardView& b = row.boards[i];
                const float cell =
                    small_cell(b.side, slot_w - X(16), row_h - 2.0F * l - 2.0F * gap);
                const float size = cell * static_cast<float>(b.side);
                const float cx = area.x0 + slot_w * (static_cast<float>(i) + 0.5F);
                const float by = y + l + gap;
                if (r > 0) {
                    const bool linked =
                        b.parent >= 0 && static_cast<std::size_t>(b.parent) < above.size();
                    const PointF from =
                        linked ? above[static_cast<std::size_t>(b.parent)] : PointF{cx, y};
                    list.under.add_line(from, {cx, by - gap}, std::max(1.5F, 2.5F * s),
                                        linked ? colors.edge : colors.edge_unlinked);
                }
                draw_board(b, cx - size / 2.0F, by, cell, lesson);
                centred_text(cx, by + size + gap + ascent, lesson, b.label, colors.label);
                here.push_back({cx, by + size + gap + l});
            }
            // The edges into this row pass the row's label: a plate in the panel's colour, drawn
            // over them down to where they end, keeps the label clear and leaves no stub.
            if (r > 0) {
                const float pad = 0.2F * l;
                list.under.add_rect(
                    {area.x0 - pad, y + ascent - l + pad,
                     area.x0 + std::min(width_of(lesson, label), area.width()) + pad, y + l},
                    colors.panel);
            }
            above = std::move(here);
        }
    }

    void draw_queue(const view::PuzzlePanelView& p, RectF area) {
        const float l = line(lesson);
        const float ascent = font(lesson).ascent();
        list.under.add_rect({area.x0 - X(8), area.y0 - Y(4), area.x1 + X(6), area.y1},
                            colors.queue_fill);
        fitted_text(area.x0, area.y0 + ascent, area.width(), lesson, p.queue_title, colors.title);
        const std::size_t shown = p.shown.queue;
        const float gap = 0.3F * l;
        // Room for the entries between the title and two lines of "+N more".
        const float entry_h = (area.height() - 3.0F * l) / static_cast<float>(shown);
        float y = area.y0 + l + gap;
        for (std::size_t i = 0; i < std::min(p.queue.size(), shown); ++i) {
            const view::PuzzleBoardView& b = p.queue[i];
            const float cell = small_cell(b.side, area.width(), entry_h - l - 2.0F * gap);
            const float size = cell * static_cast<float>(b.side);
            const float cx = 0.5F * (area.x0 + area.x1);
            draw_board(b, cx - size / 2.0F, y, cell, lesson);
            centred_text(cx, y + size + gap + ascent, lesson, b.label, colors.title);
            y += size + l + 2.0F * gap;
        }
        if (!p.queue_more.empty())
            wrapped_text(area.x0, y, area.width(), lesson, p.queue_more, 2, colors.label);
    }

    void draw_playback(const view::PuzzlePanelView& p, RectF area) {
        const view::PuzzleBoardView& b = p.board;
        const float px = design(playback_px);
        const float top =
            wrapped_text(area.x0, area.y0, area.width(), px, p.caption, 2, colors.title, true) +
            Y(12);
        const float room = std::min(area.width() - X(40), area.y1 - top - Y(10));
        const float cell = std::floor(std::min(room / static_cast<float>(b.side), 120.0F * s));
        const float size = cell * static_cast<float>(b.side);
        const float x = std::round((area.x0 + area.x1 - size) / 2.0F);
        draw_board(b, x, std::round(top), cell, std::max(lesson, cell * 0.45F), p.slide);
    }

    const DrawList& build(const view::PuzzleFrameView& frame) {
        COLLIDE_ASSERT(!frame.panels.empty() && frame.panels.size() <= 2,
                       "a puzzle frame has 1 or 2 panels");
        for (const view::PuzzlePanelView& p : frame.panels) {
            if (p.playback || !p.board.tiles.empty()) check_board(p.board);
            for (const view::PuzzleRowView& row : p.rows) {
                for (const view::PuzzleBoardView& b : row.boards) check_board(b);
            }
            for (const view::PuzzleBoardView& b : p.queue) check_board(b);
        }
        list.clear();
        drawn.clear();
        const float heading = design(heading_px);
        const float margin = X(12);
        fitted_text(X(20), Y(8) + font(heading).ascent(), X(design_width) - X(40), heading,
                    frame.heading, colors.title);
        const float top = Y(8) + line(heading) + Y(4);
        const float gap = X(12);
        const float bottom = std::round(Y(design_height) - Y(8));
        // --code: the listing in a column on the right at the lesson size, as wide as its widest
        // line (the listing is the same in every frame, so the panel keeps its place).
        float panels_x1 = X(design_width) - margin;
        if (frame.code) {
            const float code_w = std::ceil(
                std::min(code_panel_width(*frame.code, font(lesson)), 0.45F * X(design_width)));
            draw_code(*frame.code, {panels_x1 - code_w, std::round(top), panels_x1, bottom});
            panels_x1 -= code_w + gap;
        }
        const float panel_w =
            (panels_x1 - margin - gap * static_cast<float>(frame.panels.size() - 1)) /
            static_cast<float>(frame.panels.size());
        for (std::size_t i = 0; i < frame.panels.size(); ++i) {
            const float x0 = margin + (panel_w + gap) * static_cast<float>(i);
            draw_panel(frame.panels[i],
                       {std::round(x0), std::round(top), std::round(x0 + panel_w), bottom});
        }
        return list;
    }

    void draw_code(const view::CodeView& code, RectF area) {
        const FontAtlas& f = font(lesson);
        const CodeText draw = [this, &f](std::size_t, RectF row, float x, std::string_view str,
                                         Rgba8 color) {
            // As Painter::draw_text places text in a slot: centred by the font's height.
            text(x, row.y0 + 0.5F * (row.height() - f.pixel_height()) + f.ascent(),
                 f.pixel_height(), str, color);
        };
        paint_code(code, area, f, puzzle_code_colors(colors), list.under, draw);
    }
};

PuzzleRenderer::PuzzleRenderer(const PuzzleViewConfig& config, Backend backend,
                               const NoticeSink& notice) {
    config.validate();  // before creating a context for a config we would reject anyway
    impl_ =
        std::make_unique<Impl>(config, make_context(backend, config.width, config.height, notice));
}

PuzzleRenderer::~PuzzleRenderer() = default;
PuzzleRenderer::PuzzleRenderer(PuzzleRenderer&&) noexcept = default;
PuzzleRenderer& PuzzleRenderer::operator=(PuzzleRenderer&&) noexcept = default;

void PuzzleRenderer::render(const view::PuzzleFrameView& frame, Image& out) {
    const DrawList& list = impl_->build(frame);
    impl_->target.draw(list);
    impl_->target.read_pixels(list, out);
}

const std::vector<DrawnText>& PuzzleRenderer::last_text() const noexcept {
    return impl_->drawn;
}

Image PuzzleRenderer::render(const view::PuzzleFrameView& frame) {
    Image image;
    render(frame, image);
    return image;
}

}  // namespace collide::render
