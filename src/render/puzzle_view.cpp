// Frames of `collide puzzle`: a heading over one or two panels (BFS left, A* right). Each panel
// is laid out in a 1280x720 design space scaled to the frame, described as a DrawList
// (rectangles, lines, text) on the CPU and drawn by GlTarget, like the collision frames.
#include "collide/render/puzzle_view.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <string_view>

#include "collide/assert.hpp"
#include "collide/error.hpp"
#include "draw_list.hpp"
#include "font.hpp"
#include "gl_target.hpp"
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

/// Font sizes in design pixels (text never gets smaller than min_font_px on screen).
constexpr float heading_px = 24.0F;
constexpr float title_px = 24.0F;
constexpr float body_px = 17.0F;
constexpr float small_px = 14.0F;
constexpr float playback_px = 22.0F;
constexpr float min_font_px = 9.0F;

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
    std::map<int, FontAtlas> fonts;   // by pixel height
    std::map<int, std::size_t> runs;  // pixel height -> index in list.text
    DrawList list;

    Impl(const PuzzleViewConfig& cfg, std::unique_ptr<Context> context)
        : config(cfg),
          colors(puzzle_palette(cfg.theme)),
          target(cfg.width, cfg.height, std::move(context)) {
        sx = static_cast<float>(config.width) / design_width;
        sy = static_cast<float>(config.height) / design_height;
        s = std::min(sx, sy);
        // Every size the frames use, baked once (a missing font fails here, before any frame).
        for (float px : {heading_px, title_px, body_px, small_px, playback_px}) (void)font(px);
        list.background = colors.background;
    }

    int font_key(float design_px) const {
        return static_cast<int>(std::lround(std::max(min_font_px, design_px * s)));
    }

    const FontAtlas& font(float design_px) {
        const int key = font_key(design_px);
        auto it = fonts.find(key);
        if (it == fonts.end()) {
            it = fonts.try_emplace(key, config.font_path, static_cast<float>(key)).first;
            runs[key] = list.text.size();
            list.text.push_back({&it->second, {}});
        }
        return it->second;
    }

    OverlayBatch& glyphs(float design_px) {
        (void)font(design_px);
        return list.text[runs.at(font_key(design_px))].glyphs;
    }

    /// Text with its baseline at (x, y) in frame pixels; returns the x after it.
    float text(float x, float y, float design_px, std::string_view str, Rgba8 color) {
        const FontAtlas& f = font(design_px);
        return f.add_text(glyphs(design_px), std::round(x), std::round(y), str, color);
    }

    float width_of(float design_px, std::string_view str) {
        return font(design_px).text_width(str);
    }

    void centred_text(float cx, float y, float design_px, std::string_view str, Rgba8 color) {
        text(cx - width_of(design_px, str) / 2.0F, y, design_px, str, color);
    }

    /// Text cut with "..." to fit `width` pixels.
    void fitted_text(float x, float y, float width, float design_px, std::string str, Rgba8 color) {
        while (str.size() > 3 && width_of(design_px, str) > width) {
            str.erase(str.size() - 4);
            str += "...";
        }
        text(x, y, design_px, str, color);
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
            const float w = std::max(2.0F, std::round(3.0F * s));
            list.under.add_frame({x - gap - w, y - gap - w, x + size + gap + w, y + size + gap + w},
                                 w, puzzle_mark_color(b.mark, colors));
        }
    }

    void draw_tile(int tile, float x, float y, float cell, float gap, float font_px, Rgba8 fill) {
        list.under.add_rect({x + gap / 2, y + gap / 2, x + cell - gap / 2, y + cell - gap / 2},
                            fill);
        const FontAtlas& f = font(font_px);
        const std::string label = std::to_string(tile);
        text(x + (cell - f.text_width(label)) / 2.0F, y + (cell + f.ascent() * 0.72F) / 2.0F,
             font_px, label, colors.tile_text);
    }

    void draw_panel(const view::PuzzlePanelView& p, RectF area) {
        list.under.add_rect(area, colors.panel);
        const float x0 = area.x0 + X(14);
        text(x0, area.y0 + Y(30), title_px, p.title, colors.title);
        std::string counters;
        for (const std::string& c : p.counters) counters += (counters.empty() ? "" : "    ") + c;
        fitted_text(x0, area.y0 + Y(56), area.width() - X(28), body_px, counters, colors.counter);
        fitted_text(x0, area.y0 + Y(80), area.width() - X(28), body_px, p.status, colors.status);
        const RectF body{area.x0, area.y0 + Y(96), area.x1, area.y1 - Y(10)};
        if (p.playback) {
            draw_playback(p, body);
        } else {
            const RectF tree{body.x0 + X(10), body.y0, body.x1 - X(176), body.y1};
            if (p.rows.empty() && !p.board.tiles.empty()) {
                draw_playback(p, tree);  // before the first expansion: the start, large
            } else {
                draw_tree(p, tree);
            }
            draw_queue(p, {body.x1 - X(168), body.y0, body.x1 - X(10), body.y1});
        }
    }

    /// Cells of a small board that fits a `width` x `height` box: as large as the box allows up
    /// to 26 design pixels (a single panel has room for larger boards than two side by side).
    [[nodiscard]] float small_cell(int side, float width, float height) const {
        const float fit = std::min(width, height) / static_cast<float>(side);
        return std::floor(std::min(fit, 26.0F * s));
    }

    void draw_tree(const view::PuzzlePanelView& p, RectF area) {
        float top = area.y0;
        if (!p.hidden_rows.empty()) {
            fitted_text(area.x0, top + Y(12), area.width(), small_px, p.hidden_rows, colors.label);
            top += Y(22);
        }
        const std::size_t rows = std::min(p.rows.size(), view::max_puzzle_rows);
        if (rows == 0) return;
        const float row_h = (area.y1 - top) / static_cast<float>(view::max_puzzle_rows);
        const float label_w = X(104);
        const float slot_w =
            (area.width() - label_w) / static_cast<float>(view::max_puzzle_row_boards);
        // Board centres of the row above, for the edges.
        std::vector<PointF> above;
        for (std::size_t r = 0; r < rows; ++r) {
            const view::PuzzleRowView& row = p.rows[r];
            const float y = top + row_h * static_cast<float>(r);
            text(area.x0, y + Y(18), body_px, row.label, colors.title);
            text(area.x0, y + Y(36), small_px, row.count, colors.label);
            std::vector<PointF> here;
            const std::size_t n = std::min(row.boards.size(), view::max_puzzle_row_boards);
            for (std::size_t i = 0; i < n; ++i) {
                const view::PuzzleBoardView& b = row.boards[i];
                const float cell = small_cell(b.side, slot_w - X(10), row_h - Y(34));
                const float size = cell * static_cast<float>(b.side);
                const float cx = area.x0 + label_w + slot_w * (static_cast<float>(i) + 0.5F);
                const float by = y + Y(4);
                if (r > 0) {
                    const PointF to{cx, by - 2.0F};
                    const bool linked =
                        b.parent >= 0 && static_cast<std::size_t>(b.parent) < above.size();
                    const PointF from =
                        linked ? above[static_cast<std::size_t>(b.parent)] : PointF{cx, by - Y(14)};
                    list.under.add_line(from, to, std::max(1.0F, 1.5F * s),
                                        linked ? colors.edge : colors.edge_unlinked);
                }
                draw_board(b, cx - size / 2.0F, by, cell, cell / s * 0.8F);
                centred_text(cx, by + size + Y(17), small_px, b.label, colors.label);
                here.push_back({cx, by + size + Y(22)});
            }
            above = std::move(here);
        }
    }

    void draw_queue(const view::PuzzlePanelView& p, RectF area) {
        list.under.add_rect({area.x0 - X(6), area.y0 - Y(4), area.x1 + X(4), area.y1},
                            colors.queue_fill);
        fitted_text(area.x0, area.y0 + Y(16), area.width(), body_px, p.queue_title, colors.title);
        float y = area.y0 + Y(30);
        for (std::size_t i = 0; i < std::min(p.queue.size(), view::max_puzzle_queue_shown); ++i) {
            const view::PuzzleBoardView& b = p.queue[i];
            const float cell = small_cell(
                b.side, area.width() - X(74),
                (area.y1 - area.y0 - Y(64)) / static_cast<float>(view::max_puzzle_queue_shown) -
                    Y(14));
            draw_board(b, area.x0 + X(4), y, cell, cell / s * 0.8F);
            text(area.x0 + X(4) + cell * static_cast<float>(b.side) + X(10),
                 y + cell * static_cast<float>(b.side) / 2.0F + Y(5), small_px, b.label,
                 colors.title);
            y += cell * static_cast<float>(b.side) + Y(14);
        }
        if (!p.queue_more.empty())
            fitted_text(area.x0, y + Y(12), area.width(), small_px, p.queue_more, colors.label);
    }

    void draw_playback(const view::PuzzlePanelView& p, RectF area) {
        const view::PuzzleBoardView& b = p.board;
        centred_text((area.x0 + area.x1) / 2.0F, area.y0 + Y(30), playback_px, p.caption,
                     colors.title);
        const float room = std::min(area.width() - X(80), area.height() - Y(90));
        const float cell = std::floor(std::min(room / static_cast<float>(b.side), 120.0F * s));
        const float size = cell * static_cast<float>(b.side);
        const float x = std::round((area.x0 + area.x1 - size) / 2.0F);
        const float y = std::round(area.y0 + Y(60));
        draw_board(b, x, y, cell, cell * 0.45F / s, p.slide);
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
        text(X(20), Y(34), heading_px, frame.heading, colors.title);
        const float gap = X(12);
        const float panel_w =
            (X(design_width) - 2 * X(12) - gap * static_cast<float>(frame.panels.size() - 1)) /
            static_cast<float>(frame.panels.size());
        for (std::size_t i = 0; i < frame.panels.size(); ++i) {
            const float x0 = X(12) + (panel_w + gap) * static_cast<float>(i);
            draw_panel(frame.panels[i], {std::round(x0), std::round(Y(50)),
                                         std::round(x0 + panel_w), std::round(Y(710))});
        }
        return list;
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

Image PuzzleRenderer::render(const view::PuzzleFrameView& frame) {
    Image image;
    render(frame, image);
    return image;
}

}  // namespace collide::render
