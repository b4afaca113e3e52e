// Frames of a priority-queue lesson: lay out the token strip and the panels, build a DrawList
// (edges, slots and boxes as triangles, tree nodes as discs, glyphs per font size) on the CPU, and
// draw it through GlTarget, the collision renderer's GL half: one GL path for every picture. The
// GL half is heap_view_gl.cpp (heap_draw_target.hpp): this file links no GL, so that `collide`
// runs the fit check (HeapRenderer::fits) itself.
#include "collide/render/heap_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "code_panel.hpp"
#include "collide/assert.hpp"
#include "collide/error.hpp"
#include "collide/render/renderer.hpp"
#include "draw_list.hpp"
#include "font.hpp"
#include "heap_draw_target.hpp"
#include "heap_view_layout.hpp"
#include "layout.hpp"
#include "overlay_geometry.hpp"
#include "theme.hpp"

namespace collide::render {

// ---------------------------------------------------------------------------------------------
// Config and limits

void HeapViewConfig::validate() const {
    const auto check_size = [](const char* field, int value) {
        if (value < min_frame_side || value > max_frame_side) {
            throw_input_error(std::string("heap view.") + field + ": must be in [" +
                              std::to_string(min_frame_side) + ", " +
                              std::to_string(max_frame_side) + "], got " + std::to_string(value));
        }
    };
    check_size("width", width);
    check_size("height", height);
    if (font_path.empty()) throw_input_error("heap view.font_path: must name a TrueType font");
    if (widest_key.empty()) throw_input_error("heap view.widest_key: must not be empty");
}

std::size_t max_legible_keys(std::size_t panels, bool code) noexcept {
    constexpr std::size_t keys_per_frame_width = 36;
    constexpr std::size_t keys_beside_code = 21;  // 60 % of the width
    return (code ? keys_beside_code : keys_per_frame_width) / panel_columns(panels);
}

namespace {

PointF lerp(PointF a, PointF b, float t) noexcept {
    return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t};
}

/// Greedy word wrap to `width` pixels; at most `max_lines` lines (the last one ends in "...").
std::vector<std::string> wrap(const FontAtlas& font, const std::string& text, float width,
                              std::size_t max_lines) {
    std::vector<std::string> lines = wrap_words(font, text, width);
    if (lines.size() > max_lines) {
        lines.resize(max_lines);
        lines.back() += " ...";
    }
    return lines;
}

/// Where one panel's parts go.
struct PanelGeometry {
    RectF panel;
    float title_baseline = 0.0F;
    float title_px = 0.0F;                 ///< the title's font size
    std::vector<std::string> title_lines;  ///< one, or two in a narrow panel
    float counters_baseline = 0.0F;
    float returned_baseline = 0.0F;  ///< the keys removed so far (when the panel shows them)
    int counter_lines = 1;  ///< counters side by side, or one under the other in narrow panels
    RectF tree;             ///< the node centres' box (tree panels)
    /// The panel less the map's column where the map stands at its right: the counters, the
    /// tree and the array live in it (the title and the caption span the panel).
    RectF body;
    RectF map;              ///< indexed heap's map: beside the array, or a column at the right
    bool map_side = false;  ///< the map is the column at the panel's right (a narrow panel)
    std::vector<std::string> map_title_lines;  ///< the column's heading, one or two lines
    std::size_t map_rows = 0;                  ///< entries in one group of the column
    std::size_t map_groups = 1;                ///< groups of entries side by side
    float map_key_w = 0.0F;                    ///< the column's key cell
    float map_entry_w = 0.0F;                  ///< a key and its index
    float map_group_gap = 0.0F;                ///< between groups of entries side by side
    float slot_size = 0.0F;  ///< a slot's height (and its width, unless its text needs more)
    float slot_w = 0.0F;     ///< a slot's width: wider than tall where a key or index needs it
    float slot_top = 0.0F;   ///< the top of the array's first row
    float slots_x0 = 0.0F;
    std::size_t per_row = 1;  ///< slots in a row of the array (it wraps where they do not fit)
    float row_pitch = 0.0F;   ///< from one row of the array to the next
    float sorted_gap = 0.0F;  ///< extra space before heapsort's sorted part
    float caption_top = 0.0F;
    std::size_t caption_lines = 2;  ///< lines reserved for the caption
    float node_radius = 0.0F;
    /// Half a node's width: its radius, or more where the widest key needs it (a pill, as wide
    /// as its word, its ends round).
    float node_half_w = 0.0F;
    std::vector<PointF> nodes;  ///< node centres, pixels
    /// The panel is too small for its parts at the lesson size: the tree's levels or leaves
    /// would touch, or the map's column or a counter would not fit.
    bool cramped = false;
};

}  // namespace

// ---------------------------------------------------------------------------------------------

struct HeapRenderer::Impl {
    /// A centred key's baseline under its centre, in pixel heights of its font (capitals a
    /// little under the middle look centred).
    static constexpr float key_drop = 0.36F;

    HeapViewConfig config;
    HeapPalette colors;
    std::unique_ptr<HeapDrawTarget> target;  // the context and every GL object (none: layout only)

    std::map<int, FontAtlas> fonts;           // by pixel height (map nodes: stable addresses)
    std::map<int, std::size_t> text_run;      // pixel height -> its run in list.text
    std::map<std::string, float> need_cache;  // panel_need by kind of panel
    DrawList list;                            // slots, edges, boxes under the nodes; glyphs
    std::vector<DrawnText> drawn;             // the frame's text, for last_text()
    OverlayBatch& under = list.under;         // slots, edges, boxes: before the nodes
    OverlayBatch& over = list.over;           // token marker etc.: after the nodes

    float unit = 1.0F;         // pixels per 1/720 of the frame height
    bool beside_code = false;  // the frame being built has a code column (--code)
    std::size_t columns = 1;   // of the panel grid in the frame being built

    Impl(const HeapViewConfig& cfg, std::unique_ptr<HeapDrawTarget> draw_target)
        : config(cfg), colors(heap_palette(cfg.theme)), target(std::move(draw_target)) {
        config.validate();
        unit = static_cast<float>(config.height) / 720.0F;
        (void)font(caption_px());  // a missing font fails here, before any frame
        // The widest key as drawn, not the one of most letters.
        const FontAtlas& f = font(small_px());
        for (const std::string& k : config.keys) {
            if (f.text_width(k) > f.text_width(config.widest_key)) config.widest_key = k;
        }
    }

    /// A node: its fill or ring, drawn in order (each node its own group: a moving node stays
    /// over the still ones whatever GlTarget draws as point sprites or quads).
    void add_node(const DiscInstance& disc) {
        list.discs.push_back(disc);
        list.disc_groups.push_back(
            {list.discs.size(),
             {0.0F, 0.0F, static_cast<float>(config.width), static_cast<float>(config.height)}});
    }

    // ------------------------------------------------------------------ text

    const FontAtlas& font(float pixel_height) {
        // Atlases hold 224 glyphs; 128 px (2048 texels square) is lesson text at 2160p.
        const int px = std::clamp(static_cast<int>(std::lround(pixel_height)), 10, 128);
        auto it = fonts.find(px);
        if (it == fonts.end())
            it = fonts.emplace(px, FontAtlas(config.font_path, static_cast<float>(px))).first;
        return it->second;
    }

    /// Text from (x, baseline); `shape` is the slot or node it labels, if any (for last_text).
    void text(const FontAtlas& f, float x, float baseline, std::string_view s, Rgba8 color,
              std::optional<DrawnShape> shape = std::nullopt) {
        const int px = static_cast<int>(std::lround(f.pixel_height()));
        const auto [run, fresh] = text_run.try_emplace(px, list.text.size());
        if (fresh) list.text.push_back({&f, {}});
        f.add_text(list.text[run->second].glyphs, x, baseline, s, color);
        const float cap = f.pixel_height() * cap_height_per_pixel_height;
        drawn.push_back(
            {std::string(s), cap, {x, baseline - cap, x + f.text_width(s), baseline}, shape});
    }

    /// Text centred on (cx, cy), by the height of a capital letter.
    void centred(const FontAtlas& f, PointF c, std::string_view s, Rgba8 color,
                 std::optional<DrawnShape> shape = std::nullopt) {
        text(f, c.x - 0.5F * f.text_width(s), c.y + key_drop * f.pixel_height(), s, color, shape);
    }

    /// The smallest text a class must read: capitals 2.8 % of the frame height, as in the
    /// collision video (22 px at 854x480, 33 px at 720p).
    [[nodiscard]] float lesson_px() const {
        return lesson_pixel_height(config.width, config.height);
    }

    /// Caption size: as large as the columns allow, never under lesson_px().
    [[nodiscard]] float caption_px() const {
        const float per_column = columns <= 1 ? 36.0F : columns == 2 ? 34.0F : 33.0F;
        return std::max(lesson_px(), per_column * unit);
    }

    /// Counters, index labels, the map and the strip's labels: the lesson size.
    [[nodiscard]] float small_px() const { return lesson_px(); }

    /// Space inside a panel's edge; tighter when four or more panels share the row.
    [[nodiscard]] float padding() const { return (columns >= 4 ? 7.0F : 12.0F) * unit; }

    /// The key font for slots `height` pixels tall and `width` wide: as large as fits the widest
    /// key (a capital 0.53 of the height: a key is the first thing to read), never under the
    /// lesson size (the slot is widened for it instead: slot_text_width).
    const FontAtlas& key_font(float height, float width) {
        const float wanted = 0.85F * height;
        const FontAtlas& probe = font(wanted);
        const float text_w = probe.text_width(config.widest_key);
        const float limit = 0.86F * width;
        if (text_w <= limit) return probe;
        return font(std::max(small_px(), wanted * limit / text_w));
    }

    /// The width a slot needs for its text at the lesson size: the widest key and the widest
    /// index under it ("12"), each with a margin either side.
    [[nodiscard]] float slot_text_width(const view::HeapPanelView& p) {
        const FontAtlas& f = font(small_px());
        const auto last = static_cast<long long>(std::max<std::size_t>(p.capacity, 1)) - 1;
        const std::string widest_index = std::to_string(last + p.index_base);
        return std::max(f.text_width(config.widest_key) / 0.86F,
                        f.text_width(widest_index) + 0.35F * f.pixel_height());
    }

    /// A key's font in a node of radius `radius` (round ends) and half-width `half_w`: as large
    /// as the slots' rule gives, smaller where the widest key would touch the outline, never
    /// under the lesson size (the node is widened for it instead: node_half_width).
    const FontAtlas& node_font(float radius, float half_w) {
        float px = std::max(small_px(), 0.85F * 2.0F * radius);
        // A tenth smaller at a time: few sizes tried, each an atlas of its own.
        for (int tries = 0; tries < 16 && px > small_px() && node_half_width(radius, px) > half_w;
             ++tries)
            px = std::max(small_px(), std::floor(0.9F * px));
        return font(px);
    }

    /// Half the width a node of radius `radius` needs to hold the widest key at `px` inside its
    /// outline with a margin: the radius when the key fits the disc, more (a pill) for a word.
    [[nodiscard]] float node_half_width(float radius, float px) {
        const FontAtlas& f = font(px);
        const float inner = radius - node_outline() - 0.08F * f.pixel_height();
        const float rise = key_drop * f.pixel_height();  // the lower of the key's two half-heights
        const float side = inner > rise ? std::sqrt(inner * inner - rise * rise) : 0.0F;
        return std::max(radius, radius - side + 0.5F * f.text_width(config.widest_key));
    }

    [[nodiscard]] float node_outline() const { return std::max(1.5F, 2.5F * unit); }

    /// The least space between two levels of nodes.
    [[nodiscard]] float node_gap() const { return std::max(2.0F, 4.0F * unit); }

    // ------------------------------------------------------------------ frame

    /// What the caller promises about a frame (the views come from collide's own code, never
    /// from the user): a broken promise is a bug, caught by COLLIDE_ASSERT.
    static void check(const view::HeapFrameView& frame) {
        COLLIDE_ASSERT(!frame.panels.empty() && frame.panels.size() <= max_heap_panels,
                       "a heap frame has 1 to max_heap_panels panels");
        for (const view::HeapPanelView& p : frame.panels) {
            COLLIDE_ASSERT(p.slots.size() <= p.capacity, "no more slots than the capacity");
            COLLIDE_ASSERT(!p.swap || (p.swap->a < p.slots.size() && p.swap->b < p.slots.size()),
                           "an exchange of slots that exist");
            COLLIDE_ASSERT(!p.tree || p.arity >= 2, "a tree has arity >= 2");
        }
    }

    void build(const view::HeapFrameView& frame) {
        list.clear();  // keeps the text runs (one per font size), emptied
        drawn.clear();
        list.background = colors.background;
        const auto w = static_cast<float>(config.width);
        const auto h = static_cast<float>(config.height);
        const FrameAreas areas = frame_areas(frame);
        const float margin = areas.margin;
        const float strip_h = areas.strip_h;
        const float code_w = areas.code_w;
        for (std::size_t p = 0; p < frame.panels.size(); ++p) {
            build_panel(frame.panels[p], areas.panels[p]);
        }
        if (frame.code) {
            const FontAtlas& f = font(small_px());
            const CodeText draw = [this, &f](std::size_t, RectF row, float x, std::string_view s,
                                             Rgba8 color) {
                // As Painter::draw_text places text in a slot: centred by the font's height.
                text(f, x, row.y0 + 0.5F * (row.height() - f.pixel_height()) + f.ascent(), s,
                     color);
            };
            paint_code(*frame.code, {w - margin - code_w, strip_h, w - margin, h - margin}, f,
                       heap_code_colors(colors), under, draw);
        }
    }

    /// Where a frame's parts go: the margin, the token strip's height (its tokens built into
    /// the list), the code column's width (0: none) and the panels' rectangles.
    struct FrameAreas {
        float margin = 0.0F;
        float strip_h = 0.0F;
        float code_w = 0.0F;
        std::vector<RectF> panels;
    };

    /// The frame's areas; sets its grid (columns, beside_code). The panels have equal widths
    /// unless a panel needs more (an indexed heap's map column beside its tree), which it takes
    /// from panels that need less. --code: the listing takes a fixed column on the right, the
    /// same in every frame, so that the tree keeps its place when the operation (and its
    /// listing) changes.
    FrameAreas frame_areas(const view::HeapFrameView& frame) {
        const auto w = static_cast<float>(config.width);
        const auto h = static_cast<float>(config.height);
        columns = panel_columns(frame.panels.size());
        beside_code = frame.code.has_value();
        FrameAreas areas;
        areas.margin = (columns >= 4 ? 8.0F : 14.0F) * unit;
        areas.strip_h = build_token_strip(frame, areas.margin);
        areas.code_w = frame.code ? code_width(*frame.code) : 0.0F;
        const float panels_x1 =
            w - areas.margin - (frame.code ? areas.code_w + areas.margin : 0.0F);
        const RectF area{areas.margin, areas.strip_h, panels_x1, h - areas.margin};
        const std::vector<RectF> equal = panel_rects(frame.panels.size(), area, areas.margin);
        std::vector<float> needs;
        for (std::size_t p = 0; p < frame.panels.size(); ++p)
            needs.push_back(panel_need(frame.panels[p], equal[p]));
        areas.panels = panel_rects_by_need(needs, area, areas.margin);
        return areas;
    }

    /// Whether every panel of `frame` holds its parts at the lesson size (layout_panel: no two
    /// nodes touching, every key inside its node, the map and the counters in their place).
    bool fits(const view::HeapFrameView& frame) {
        list.clear();
        const FrameAreas areas = frame_areas(frame);
        for (std::size_t p = 0; p < frame.panels.size(); ++p) {
            if (layout_panel(frame.panels[p], areas.panels[p]).cramped) return false;
        }
        return true;
    }

    /// The code column's width (--code): the widest line of the video's listings at the lesson
    /// size, at most 45 % of the frame (a longer line is cut).
    float code_width(const view::CodeView& code) {
        view::CodeView sizing;
        sizing.title = code.title;
        sizing.lines = config.code_lines.empty() ? code.lines : config.code_lines;
        const float widest = code_panel_width(sizing, font(small_px()));
        return std::ceil(std::min(widest, 0.45F * static_cast<float>(config.width)));
    }

    /// The operations on one line, the current one on an amber tab; returns the strip's height.
    float build_token_strip(const view::HeapFrameView& frame, float margin) {
        const FontAtlas& f = font(caption_px() * 1.05F);
        const float height = f.pixel_height() * 2.0F;
        if (frame.tokens.empty()) return margin;
        const float gap = f.text_width("  ");
        const auto w = static_cast<float>(config.width);
        // Widths, then a window of tokens around the current one that fits the line.
        std::vector<float> widths;
        for (const std::string& t : frame.tokens) widths.push_back(f.text_width(t));
        const std::size_t now = frame.current_token.value_or(0);
        std::size_t first = 0;
        const auto span = [&](std::size_t a, std::size_t b) {
            float s = 0.0F;
            for (std::size_t i = a; i < b; ++i) s += widths[i] + gap;
            return s;
        };
        const float room = w - 2.0F * margin;
        std::size_t last = frame.tokens.size();
        while (span(first, last) > room && last > first + 1) {
            // Drop from whichever end is farther from the current token.
            if (now - std::min(now, first) > last - 1 - std::min(now, last - 1)) {
                ++first;
            } else {
                --last;
            }
        }
        float x = 0.5F * (w - span(first, last) + gap);
        const float baseline = 0.5F * height + 0.36F * f.pixel_height();
        for (std::size_t i = first; i < last; ++i) {
            Rgba8 color = colors.token_todo;
            if (frame.current_token && i < *frame.current_token) color = colors.token_done;
            if (frame.current_token && i == *frame.current_token) {
                const float pad = 0.3F * f.pixel_height();
                under.add_rect({x - pad, baseline - 1.05F * f.pixel_height(), x + widths[i] + pad,
                                baseline + 0.35F * f.pixel_height()},
                               heap_token_now_fill);
                color = highlight_dark_text;
            }
            text(f, x, baseline, frame.tokens[i], color);
            x += widths[i] + gap;
        }
        return height;
    }

    /// Most lines a caption takes; a longer one is cut ("...").
    static constexpr std::size_t max_caption_lines = 3;

    /// The lines to reserve for captions `width` pixels wide in font `f`: as many as the
    /// longest caption of the video wraps to (at least one), so that no line stands empty in
    /// every frame while the tree above it squeezes; without the video's captions, room for
    /// ~70 characters (the longest the lesson writes) at ~0.5 em each.
    [[nodiscard]] std::size_t caption_lines(const FontAtlas& f, float width) const {
        if (config.captions.empty()) {
            const float chars_per_line = width / (0.5F * f.pixel_height());
            return static_cast<std::size_t>(
                std::clamp(std::ceil(70.0F / chars_per_line), 2.0F, 4.0F));
        }
        std::size_t lines = 1;
        for (const std::string& caption : config.captions)
            lines = std::max(lines, wrap_words(f, caption, width).size());
        return std::min(lines, max_caption_lines);
    }

    /// The least radius of a node: a key at the lesson size with room over and under it.
    [[nodiscard]] float least_radius() const {
        return node_outline() + (0.08F + 1.4F * key_drop) * small_px();
    }

    /// Whether the indexed heap's map fits beside the array in a panel `inner_w` wide: both as
    /// wide as the slots at their least width (a key or index at the lesson size).
    bool map_beside_array(const view::HeapPanelView& p, float inner_w) {
        const auto slots = static_cast<float>(std::max<std::size_t>(p.capacity, 1));
        const float least_slot = std::max(std::ceil(small_px() / 0.85F), slot_text_width(p));
        return (inner_w - 3.0F * padding()) / (2.0F * slots) >= least_slot;
    }

    /// The width a panel needs: the least at which its layout is not cramped (the tree's nodes
    /// apart at the lesson size with the caption's lines its width gives, the map's column, the
    /// counters), found from `equal`, its equal share, down (or up, for a map's column) in steps
    /// of 4 %; arrays alone and a panel without a map ask no more than their share. Cached per
    /// kind of panel: it does not change from frame to frame.
    float panel_need(const view::HeapPanelView& p, RectF equal) {
        const std::string kind = p.title + "|" + std::to_string(p.capacity) + "|" +
                                 std::to_string(p.arity) + "|" + std::to_string(p.tree) +
                                 std::to_string(p.show_map) + std::to_string(p.returned.empty()) +
                                 std::to_string(p.counters.size()) + "|" +
                                 std::to_string(equal.width()) + "|" +
                                 std::to_string(equal.height()) + std::to_string(beside_code);
        if (const auto it = need_cache.find(kind); it != need_cache.end()) return it->second;
        const auto cramped_at = [&](float scale) {
            RectF r = equal;
            r.x1 = r.x0 + scale * equal.width();
            return layout_panel(p, r).cramped;
        };
        // Arrays alone keep their share (their rows would wrap); a panel without a map takes
        // no more than its share, it only gives what it can spare to a map's column.
        if (!p.tree) return equal.width();
        float scale = 1.0F;
        if (cramped_at(scale)) {
            if (!p.show_map) return equal.width();
            while (scale < 2.5F && cramped_at(scale)) scale += 0.04F;
        } else {
            while (scale > 0.6F && !cramped_at(scale - 0.04F)) scale -= 0.04F;
        }
        const float need = scale * equal.width();
        need_cache.emplace(kind, need);
        return need;
    }

    /// The indexed heap's map as a column (narrow panels): its heading (one line, or two), then
    /// one entry a line, the key and its index; in two or more groups side by side where the
    /// column is not tall enough (`height`). Sets the map_* fields of `g` and returns the
    /// column's width and height.
    PointF map_column(const view::HeapPanelView& p, float height, PanelGeometry& g) {
        const FontAtlas& f = font(small_px());
        const float lh = f.line_height();
        const std::size_t entries = std::max<std::size_t>(p.capacity, 1);
        const auto last = static_cast<long long>(entries) - 1 + p.index_base;
        g.map_key_w = f.text_width(config.widest_key);
        g.map_entry_w = g.map_key_w + 0.6F * f.pixel_height() + f.text_width(std::to_string(last));
        g.map_group_gap = 0.9F * f.pixel_height();
        // The heading on one line, or split where its two lines are narrowest.
        std::vector<std::string> words;
        for (std::size_t at = 0; at < p.map_title.size();) {
            const std::size_t space = p.map_title.find(' ', at);
            const std::size_t end = space == std::string::npos ? p.map_title.size() : space;
            if (end > at) words.push_back(p.map_title.substr(at, end - at));
            at = end + 1;
        }
        const auto joined = [&](std::size_t a, std::size_t b) {
            std::string out;
            for (std::size_t k = a; k < b; ++k) out += (out.empty() ? "" : " ") + words[k];
            return out;
        };
        std::vector<std::string> two{p.map_title};
        float two_w = f.text_width(p.map_title);
        for (std::size_t k = 1; k < words.size(); ++k) {
            const float w =
                std::max(f.text_width(joined(0, k)), f.text_width(joined(k, words.size())));
            if (w < two_w) {
                two_w = w;
                two = {joined(0, k), joined(k, words.size())};
            }
        }
        PointF size{};
        for (std::size_t groups = 1; groups <= 4; ++groups) {
            g.map_rows = (entries + groups - 1) / groups;
            g.map_groups = groups;
            const float body_w = static_cast<float>(groups) * g.map_entry_w +
                                 static_cast<float>(groups - 1) * g.map_group_gap;
            const bool one_line = f.text_width(p.map_title) <= std::max(body_w, two_w);
            g.map_title_lines = one_line ? std::vector<std::string>{p.map_title} : two;
            size = {std::max(body_w, one_line ? f.text_width(p.map_title) : two_w),
                    static_cast<float>(g.map_title_lines.size() + g.map_rows) * lh};
            if (size.y <= height) break;
        }
        return size;
    }

    /// Where a panel's parts go. The indexed heap's map: beside the array where the panel is
    /// wide enough for both, else a column at the panel's right beside the counters and the
    /// tree, as tall as they are (the tree needs height more than width), the array and the
    /// caption under it across the panel.
    PanelGeometry layout_panel(const view::HeapPanelView& p, RectF r) {
        const float pad = padding();
        if (!p.show_map || !p.tree || map_beside_array(p, r.width() - 2.0F * pad))
            return layout_parts(p, r, MapPlace::beside_array, 0.0F);
        // The column's height from a layout without it (its width changes only the tree's).
        const PanelGeometry plain = layout_parts(p, r, MapPlace::column, 0.0F);
        const float top = plain.counters_baseline - font(small_px()).ascent();
        const float bottom = plain.slot_top - 1.5F * pad;
        PanelGeometry sizing;
        const PointF size = map_column(p, bottom - top, sizing);
        PanelGeometry g = layout_parts(p, r, MapPlace::column, size.x + pad);
        (void)map_column(p, bottom - top, g);
        g.map = {r.x1 - pad - size.x, top, r.x1 - pad, top + size.y};
        g.cramped = g.cramped || g.map.y1 > std::min(bottom, g.slot_top - 1.5F * pad) + 0.5F;
        if (!g.cramped) return g;
        // Too narrow for the column as well (panels that cannot spare the width): the map
        // over the array, one column per key, as wide as the array's row; the tree gives it
        // its height.
        PanelGeometry above = layout_parts(p, r, MapPlace::over_array, 0.0F);
        above.cramped = true;
        return above;
    }

    /// Where the indexed heap's map goes (layout_panel).
    enum class MapPlace { beside_array, column, over_array };

    /// The layout of a panel with its map at `place`; the counters and the tree leave the
    /// panel's right `column` pixels free (the map's column).
    PanelGeometry layout_parts(const view::HeapPanelView& p, RectF r, MapPlace place,
                               float column) {
        PanelGeometry g;
        g.map_side = place == MapPlace::column;
        g.panel = r;
        g.body = r;
        g.body.x1 -= column;
        const float pad = padding();
        const FontAtlas& small = font(small_px());
        const FontAtlas& caption = font(caption_px());
        fit_title(p, r.width() - 2.0F * pad, g);
        const FontAtlas& title = font(g.title_px);
        g.title_baseline = r.y0 + pad + title.ascent();
        g.counters_baseline = g.title_baseline +
                              static_cast<float>(g.title_lines.size() - 1) * title.line_height() +
                              small.line_height() * 1.15F;
        g.caption_lines = caption_lines(caption, r.width() - 2.0F * pad);
        g.caption_top = r.y1 - pad - static_cast<float>(g.caption_lines) * caption.line_height();
        const RectF b = g.body;
        for (const view::HeapCounter& c : p.counters) {
            g.cramped = g.cramped || small.text_width(c.label + " 0000") > b.width() - 2.0F * pad;
        }
        g.counter_lines = counters_fit(p, b.width() - 2.0F * pad) ? 1 : 2;
        float counters_bottom =
            g.counters_baseline + static_cast<float>(g.counter_lines - 1) * small.line_height();
        if (!p.returned.empty()) {
            g.returned_baseline = counters_bottom + small.line_height();
            counters_bottom = g.returned_baseline;
        }

        // The tree must hold its levels apart at the least node size (a key at the lesson
        // size); where the panel leaves it less height, the array's slots give theirs (never
        // under what their keys need) and the layout is made again.
        const int levels = std::max(tree_levels(p.capacity, p.arity), 1);
        const float least = least_radius();
        const float tree_needs =
            static_cast<float>(levels) * 2.0F * least + static_cast<float>(levels - 1) * node_gap();
        // Deep trees need the height more than the array does.
        const bool deep = p.tree && levels >= 4;
        float slot_cap =
            (p.tree ? (deep ? 0.085F : 0.11F) : 0.16F) * static_cast<float>(config.height);
        RectF tree;
        for (int pass = 0; pass < 2; ++pass) {
            // The array row: square slots, as large as the width allows, at most ~1/9 of the
            // height.
            const float inner_w = r.width() - 2.0F * pad;  // the array spans the panel
            const std::size_t slots = std::max<std::size_t>(p.capacity, 1);
            // Heapsort's panel keeps room for the gap before the sorted part from the start.
            const float gap_slots = p.heap_size != SIZE_MAX ? 0.4F : 0.0F;
            g.slot_size = std::min(inner_w / (static_cast<float>(slots) + gap_slots), slot_cap);
            if (p.show_map && place == MapPlace::beside_array) {
                // The map beside the array, as wide: smaller slots keep it there (never under
                // their least width: map_beside_array).
                const float beside = (inner_w - 3.0F * pad) / (2.0F * static_cast<float>(slots));
                g.slot_size = std::min(g.slot_size, beside);
            }
            const float index_h = small.line_height();
            // Keys and indices at the lesson size at least: a slot as tall as that key needs, as
            // wide as its widest key or index ("12", a word) needs; the row wraps onto a second
            // (third...) where the panel is not wide enough for so many.
            g.slot_size = std::max(g.slot_size, std::ceil(small_px() / 0.85F));
            g.slot_w = std::max(g.slot_size, slot_text_width(p));
            g.per_row = std::clamp<std::size_t>(
                static_cast<std::size_t>((inner_w - g.slot_w * gap_slots) / g.slot_w), 1, slots);
            const std::size_t array_rows = (slots + g.per_row - 1) / g.per_row;
            g.row_pitch = g.slot_size + index_h + 0.15F * g.slot_size;
            const float array_h = g.slot_size + static_cast<float>(array_rows - 1) * g.row_pitch;
            // Under the index labels: room for the key that dips under the row in an exchange.
            g.slot_top = g.caption_top - pad - index_h - 0.45F * g.slot_size - array_h;
            const float row_w = g.slot_w * static_cast<float>(g.per_row);
            g.sorted_gap = array_rows == 1 ? g.slot_w * gap_slots : 0.0F;
            g.slots_x0 = r.x0 + 0.5F * (r.width() - row_w - g.sorted_gap);
            if (!p.tree) {
                // Arrays alone: the rows sit in the middle of the free space.
                const float top = counters_bottom + pad;
                g.slot_top = std::max(top, 0.5F * (top + g.caption_top - index_h - array_h));
                return g;
            }

            // The tree above the array; the indexed heap's map beside the array, one column per
            // key (or in its own column at the panel's right: map_side).
            float tree_bottom = g.slot_top - 1.5F * pad;
            if (p.show_map && place == MapPlace::over_array) {
                const float map_h = small.line_height() + 2.0F * map_font(g).line_height();
                g.map = {g.slots_x0, tree_bottom - map_h, g.slots_x0 + row_w, tree_bottom};
                tree_bottom = g.map.y0 - pad;
            }
            if (p.show_map && place == MapPlace::beside_array) {
                const float map_h = small.line_height() + 2.0F * map_font(g).line_height();
                g.slots_x0 = r.x0 + 0.5F * (r.width() - 2.0F * row_w - 3.0F * pad);
                const float x0 = g.slots_x0 + row_w + 3.0F * pad;
                const float y0 = g.slot_top + 0.5F * g.slot_size - 0.5F * map_h;
                g.map = {x0, y0, x0 + row_w, y0 + map_h};
                // A map taller than the array's row reaches up: the tree stays above it.
                tree_bottom = std::min(tree_bottom, g.map.y0 - pad);
            }
            tree = {b.x0 + pad, counters_bottom + pad, b.x1 - pad, tree_bottom};
            const float short_by = tree_needs - tree.height();
            if (short_by <= 0.0F) break;
            if (pass == 1) {
                // The slots gave what they could: the tree rises into the counters' margin.
                tree.y0 -= std::min(short_by, 0.75F * pad);
                break;
            }
            // A pixel off the slots' height raises the array's top by 1.15 per row (its pitch)
            // less 0.15 (the last row has no gap under it) and 0.45 (an exchange's dip).
            slot_cap = g.slot_size - short_by / (1.15F * static_cast<float>(array_rows) + 0.3F);
        }
        const float pitch_y = tree.height() / static_cast<float>(levels);
        const auto radius = [&](std::size_t across) {
            const float pitch_x =
                tree.width() / static_cast<float>(std::max<std::size_t>(across, 1));
            // Never smaller than a key at the lesson size needs over and under it.
            return std::max(least, std::min({0.42F * pitch_x, 0.44F * pitch_y, 38.0F * unit}));
        };
        // The textbook picture (each parent over its middle child) when the panel is wide enough
        // for it at full node size; else the compact one, whose nodes are larger.
        // Words need the width more than the height: the picture with fewer columns.
        const std::size_t columns_complete = tree_columns(p.capacity, p.arity, true);
        const std::size_t columns_compact = tree_columns(p.capacity, p.arity, false);
        const bool words =
            node_half_width(radius(columns_compact), small_px()) > radius(columns_compact);
        const bool complete = words ? columns_complete <= columns_compact
                                    : radius(columns_complete) >= radius(columns_compact);
        const std::size_t leaves =
            std::max<std::size_t>(tree_columns(p.capacity, p.arity, complete), 1);
        const float pitch_x = tree.width() / static_cast<float>(leaves);
        g.node_radius = radius(leaves);
        // A key too wide for the disc (a word): the node widens into a pill, as far as its
        // neighbours leave room; the key shrinks to what is left, never under the lesson size.
        const float key_px = std::max(small_px(), 0.85F * 2.0F * g.node_radius);
        g.node_half_w = std::min(node_half_width(g.node_radius, key_px),
                                 std::max(g.node_radius, 0.47F * pitch_x));
        g.tree = {tree.x0 + 0.5F * pitch_x, tree.y0 + g.node_radius, tree.x1 - 0.5F * pitch_x,
                  tree.y1 - g.node_radius};
        const std::vector<PointF> unit_positions = tree_positions(p.capacity, p.arity, complete);
        for (const PointF& u : unit_positions) {
            g.nodes.push_back(
                {g.tree.x0 + u.x * g.tree.width(), g.tree.y0 + u.y * g.tree.height()});
        }
        if (leaves == 1) {
            for (PointF& n : g.nodes) n.x = 0.5F * (tree.x0 + tree.x1);
        }
        // A key at the lesson size inside its node's outline; no two nodes touching.
        g.cramped = g.cramped || nodes_touch(g) || !key_fits(g);
        return g;
    }

    /// Whether two nodes of the tree overlap (pills: the points within the radius of a centre
    /// line node_half_w - node_radius to each side).
    [[nodiscard]] static bool nodes_touch(const PanelGeometry& g) {
        const float band = std::max(0.0F, g.node_half_w - g.node_radius);
        for (std::size_t i = 0; i < g.nodes.size(); ++i) {
            for (std::size_t j = i + 1; j < g.nodes.size(); ++j) {
                const float dx =
                    std::max(0.0F, std::abs(g.nodes[i].x - g.nodes[j].x) - 2.0F * band);
                const float dy = g.nodes[i].y - g.nodes[j].y;
                if (dx * dx + dy * dy < 4.0F * g.node_radius * g.node_radius) return true;
            }
        }
        return false;
    }

    /// Whether the widest key at the lesson size lies inside a node of `g` (its round ends
    /// included) with a margin of a tenth of a capital.
    [[nodiscard]] bool key_fits(const PanelGeometry& g) {
        const FontAtlas& f = font(small_px());
        const float cap = f.pixel_height() * cap_height_per_pixel_height;
        const float inner = g.node_radius - 0.1F * cap - 0.5F;
        const float rise = cap - key_drop * f.pixel_height();  // the box's top over the centre
        const float lower = std::max(rise, key_drop * f.pixel_height());
        if (inner <= lower) return false;
        const float reach =
            g.node_half_w - g.node_radius + std::sqrt(inner * inner - lower * lower);
        return 0.5F * f.text_width(config.widest_key) <= reach;
    }

    [[nodiscard]] PointF slot_centre(const PanelGeometry& g, const view::HeapPanelView& p,
                                     std::size_t i) const {
        const float apart = i >= p.heap_size ? g.sorted_gap : 0.0F;
        const auto column = static_cast<float>(i % g.per_row);
        const auto row = static_cast<float>(i / g.per_row);
        return {g.slots_x0 + (column + 0.5F) * g.slot_w + apart,
                g.slot_top + row * g.row_pitch + 0.5F * g.slot_size};
    }

    void build_panel(const view::HeapPanelView& p, RectF r) {
        const PanelGeometry g = layout_panel(p, r);
        under.add_rect(r, colors.panel);
        build_header(p, g);
        if (p.tree) build_tree(p, g);
        build_array(p, g);
        if (p.show_map) build_map(p, g);
        build_caption(p, g);
        if (p.tree && (!p.letters.empty() || !p.countdown.empty())) build_question(p, g);
    }

    /// A question (`--questions on`): each candidate's letter on a plate beside its node, at the
    /// first of a few places around it that covers no node, no text (key, index, title,
    /// counters, caption, map) and no other plate; where two or three trees share the frame and
    /// crowd it, farther out with a short leader line to its node (the plate then reads as its
    /// node's however near another node is). The countdown in the panel's top right corner. The
    /// reveal lights the answer's plate and fades the others.
    void build_question(const view::HeapPanelView& p, const PanelGeometry& g) {
        const FontAtlas& f = font(1.15F * lesson_px());
        const float side = 1.3F * f.pixel_height();
        const float half = 0.5F * side;
        const float gap = std::max(2.0F, 3.0F * unit);
        std::vector<PointF> plates;
        // A node is a pill: the points within its radius of a centre line node_half_w - radius
        // to each side (a disc where that is 0).
        const float band = std::max(0.0F, g.node_half_w - g.node_radius);
        const auto off_nodes = [&](const RectF& r) {
            for (const PointF& n : g.nodes) {
                const float dx = std::max({r.x0 - (n.x + band), (n.x - band) - r.x1, 0.0F});
                const float dy = std::max({r.y0 - n.y, n.y - r.y1, 0.0F});
                if (dx * dx + dy * dy < (g.node_radius + gap) * (g.node_radius + gap)) return false;
            }
            return true;
        };
        // Every text of the panel drawn so far (the question comes last), with the slot or cell
        // it labels: a plate covers none of them.
        std::vector<RectF> texts;
        for (const DrawnText& d : drawn) {
            if (d.shape && d.shape->corner > 0.0F) continue;  // a node's key: off_nodes
            const DrawnShape& b = d.shape ? *d.shape : d.box;
            texts.push_back({b.x0 - gap, b.y0 - gap, b.x1 + gap, b.y1 + gap});
        }
        const auto off_text = [&](const RectF& r) {
            return std::none_of(texts.begin(), texts.end(), [&](const RectF& t) {
                return t.x0 < r.x1 && r.x0 < t.x1 && t.y0 < r.y1 && r.y0 < t.y1;
            });
        };
        // The leaders drawn so far (node to plate): a later plate covers none of them.
        std::vector<std::pair<PointF, PointF>> leaders;
        const auto crosses = [&](PointF a, PointF b, const RectF& r) {
            const float length = std::hypot(b.x - a.x, b.y - a.y);
            const int steps = std::max(1, static_cast<int>(length / 2.0F));
            for (int k = 0; k <= steps; ++k) {
                const float t = static_cast<float>(k) / static_cast<float>(steps);
                const float x = a.x + t * (b.x - a.x);
                const float y = a.y + t * (b.y - a.y);
                if (x > r.x0 - gap && x < r.x1 + gap && y > r.y0 - gap && y < r.y1 + gap)
                    return true;
            }
            return false;
        };
        const auto clear = [&](PointF c) {
            const RectF r{c.x - half, c.y - half, c.x + half, c.y + half};
            if (!off_nodes(r) || !off_text(r)) return false;
            for (const auto& [a, b] : leaders) {
                if (crosses(a, b, r)) return false;
            }
            for (const PointF& o : plates) {
                if (std::abs(c.x - o.x) < side + gap && std::abs(c.y - o.y) < side + gap)
                    return false;
            }
            // Inside the panel, above its array (the array's keys stay uncovered too).
            return r.x0 >= g.panel.x0 + gap && r.x1 <= g.panel.x1 - gap &&
                   r.y0 >= g.panel.y0 + gap && r.y1 <= g.slot_top - gap;
        };
        // A leader from node `n` to a plate at `c` passes by every other node (and, where
        // `by_plates`, under no other plate); it may cross the faint places of the capacity
        // that hold no key.
        const std::size_t keyed = std::min({p.slots.size(), p.heap_size, g.nodes.size()});
        const auto leader_clear = [&](PointF n, PointF c, bool by_plates = true) {
            const float dx = c.x - n.x;
            const float dy = c.y - n.y;
            const float length2 = std::max(dx * dx + dy * dy, 1e-6F);
            for (std::size_t i = 0; i < keyed; ++i) {
                const PointF o = g.nodes[i];
                if ((o.x == n.x && o.y == n.y) || !visible(p, i)) continue;
                const float t =
                    std::clamp(((o.x - n.x) * dx + (o.y - n.y) * dy) / length2, 0.0F, 1.0F);
                const float ex = n.x + t * dx - o.x;
                const float ey = n.y + t * dy - o.y;
                const float reach = g.node_radius + band + gap;
                if (ex * ex + ey * ey < reach * reach) return false;
            }
            // Nor under another plate: a leader reads as its plate's only when it ends there.
            return !by_plates || std::none_of(plates.begin(), plates.end(), [&](const PointF& o) {
                return crosses(n, c, {o.x - half, o.y - half, o.x + half, o.y + half});
            });
        };
        const KeyStyle lit{heap_token_now_fill, highlight_dark_text};
        for (const view::HeapLetterView& letter : p.letters) {
            if (letter.slot >= g.nodes.size()) continue;
            const PointF n = g.nodes[letter.slot];
            const float reach = g.node_radius + gap + half;
            const float reach_x = reach + band;  // beside a pill, past its band
            // Up right first (clear of the edge to the parent for a left child), then around.
            const float dirs[][2] = {
                {0.72F, -0.72F}, {-0.72F, -0.72F}, {1.0F, 0.0F},   {-1.0F, 0.0F},
                {0.72F, 0.72F},  {-0.72F, 0.72F},  {0.0F, 1.0F},   {0.0F, -1.0F},
                {0.38F, -0.92F}, {-0.38F, -0.92F}, {0.38F, 0.92F}, {-0.38F, 0.92F},
                {0.92F, -0.38F}, {-0.92F, -0.38F}, {0.92F, 0.38F}, {-0.92F, 0.38F}};
            PointF at{n.x + dirs[0][0] * reach_x, n.y + dirs[0][1] * reach};
            // Beside the node first; where its neighbours crowd it, farther out, on a leader.
            bool placed = false;
            bool leader = false;
            for (const float farther : {0.0F, 0.5F * side, 1.0F * side, 1.6F * side, 2.3F * side,
                                        3.2F * side, 4.2F * side}) {
                for (const auto& d : dirs) {
                    const PointF c{n.x + d[0] * (reach_x + farther),
                                   n.y + d[1] * (reach + farther)};
                    if (clear(c) && (farther == 0.0F || leader_clear(n, c))) {
                        at = c;
                        placed = true;
                        leader = farther > 0.0F;
                        break;
                    }
                }
                if (placed) break;
            }
            // No place on the rings: the clear place nearest the node anywhere above the array,
            // on a leader that passes by the other nodes and plates if one can, else by the
            // other nodes (a leader through a node would point at the wrong key), else on a
            // leader bent once beside its node, round the nodes in the way.
            std::optional<PointF> elbow;
            const float bend = g.node_radius + band + 2.0F * gap;
            const auto bent = [&](PointF c) -> std::optional<PointF> {
                for (const auto& d : dirs) {
                    const PointF w{n.x + d[0] * (bend + 0.5F * half), n.y + d[1] * bend};
                    if (leader_clear(n, w, false) && leader_clear(w, c, false)) return w;
                }
                return std::nullopt;
            };
            for (const int strict : {2, 1, -1, 0}) {
                if (placed) break;
                float best = std::numeric_limits<float>::max();
                const float step = 0.25F * side;
                for (float y = g.panel.y0 + half; y <= g.slot_top - half; y += step) {
                    for (float x = g.panel.x0 + half; x <= g.panel.x1 - half; x += step) {
                        const float d = (x - n.x) * (x - n.x) + (y - n.y) * (y - n.y);
                        if (d >= best || !clear({x, y})) continue;
                        std::optional<PointF> w;
                        if (strict == -1) {
                            w = bent({x, y});
                            if (!w) continue;
                        } else if (strict > 0 && !leader_clear(n, {x, y}, strict == 2)) {
                            continue;
                        }
                        best = d;
                        at = {x, y};
                        elbow = w;
                        placed = true;
                        leader = true;
                    }
                }
            }
            plates.push_back(at);
            const float alpha = p.reveal && !letter.answer ? 0.35F : 1.0F;
            const RectF box{at.x - half, at.y - half, at.x + half, at.y + half};
            std::vector<DrawnSegment> drawn_leader;
            if (leader) {
                // From the node's outline (by way of the elbow, if any) to the plate's edge, as
                // thick as a lit edge.
                const float thick = std::max(2.0F, 3.0F * unit);
                const PointF first = elbow ? *elbow : at;
                const float dx = first.x - n.x;
                const float dy = first.y - n.y;
                const float length = std::sqrt(dx * dx + dy * dy);
                const float from = std::min(g.node_radius + band, 0.5F * length);
                const PointF a{n.x + dx * from / length, n.y + dy * from / length};
                PointF b = first;
                if (!elbow) {
                    const float to = std::max(0.0F, length - half);
                    b = {n.x + dx * to / length, n.y + dy * to / length};
                }
                over.add_line(a, b, thick, faded(lit.fill, alpha));
                drawn_leader.push_back({a.x, a.y, b.x, b.y});
                leaders.emplace_back(n, first);
                if (elbow) {
                    const float ex = at.x - elbow->x;
                    const float ey = at.y - elbow->y;
                    const float rest = std::max(std::sqrt(ex * ex + ey * ey), 1e-3F);
                    const float to = std::max(0.0F, rest - half);
                    const PointF e{elbow->x + ex * to / rest, elbow->y + ey * to / rest};
                    // A square on the bend closes the corner between the two strokes.
                    const float k = 0.5F * thick;
                    over.add_rect({elbow->x - k, elbow->y - k, elbow->x + k, elbow->y + k},
                                  faded(lit.fill, alpha));
                    over.add_line(*elbow, e, thick, faded(lit.fill, alpha));
                    drawn_leader.push_back({elbow->x, elbow->y, e.x, e.y});
                    leaders.emplace_back(*elbow, at);
                }
            }
            over.add_rect(box, faded(lit.fill, alpha));
            if (p.reveal && letter.answer)
                over.add_frame(box, std::max(2.0F, 3.0F * unit), colors.node_outline);
            DrawnShape plate{box.x0, box.y0, box.x1, box.y1, 0.0F};
            centred(f, at, letter.letter, faded(lit.text, alpha), plate);
            drawn.back().over = true;
            drawn.back().leader = std::move(drawn_leader);
        }
        if (!p.countdown.empty()) {
            // At the tree's top right, else its top left, else just above the array, else beside
            // the counters: where it covers no node, no letter and no text.
            const FontAtlas& big = font(caption_px());
            const float m = 0.15F * big.pixel_height();  // its margin either side
            const float w = big.text_width(p.countdown) + 2.0F * m;
            const float h = 1.15F * big.pixel_height();
            const float right = g.body.x1 - padding() - w;
            const float left = g.body.x0 + padding();
            const float top = g.tree.y0;
            const float low = g.slot_top - gap - h;
            const float header = g.counters_baseline - big.ascent();
            const auto free = [&](float x, float y) {
                const RectF r{x, y, x + w, y + h};
                if (!off_nodes(r) || !off_text(r)) return false;
                return std::none_of(plates.begin(), plates.end(), [&](const PointF& o) {
                    return o.x + half > r.x0 && o.x - half < r.x1 && o.y + half > r.y0 &&
                           o.y - half < r.y1;
                });
            };
            float x = right;
            float y = top;
            for (const PointF spot : {PointF{right, top}, PointF{left, top}, PointF{right, low},
                                      PointF{left, low}, PointF{right, header}}) {
                if (free(spot.x, spot.y)) {
                    x = spot.x;
                    y = spot.y;
                    break;
                }
            }
            text(big, x + m, y + big.ascent(), p.countdown, heap_token_now_fill,
                 DrawnShape{x, y, x + w, y + h, 0.0F});
            drawn.back().over = true;
        }
    }

    static std::string counter_text(const view::HeapCounter& c) { return c.label + " " + c.value; }

    static std::string counters_line(const view::HeapPanelView& p) {
        std::string line;
        for (const view::HeapCounter& c : p.counters)
            line += (line.empty() ? "" : "    ") + counter_text(c);
        return line;
    }

    /// Whether the counters fit on one line, judged on four-digit counts so that the layout does
    /// not jump when a count gains a digit.
    bool counters_fit(const view::HeapPanelView& p, float width) {
        std::string widest;
        for (const view::HeapCounter& c : p.counters)
            widest += (widest.empty() ? "" : "    ") + c.label + " 0000";
        return font(small_px()).text_width(widest) <= width;
    }

    /// The title on one line, shrunk as far as the lesson size if need be, else on two.
    void fit_title(const view::HeapPanelView& p, float room, PanelGeometry& g) {
        const FontAtlas& title = font(caption_px() * 1.05F);
        const float width = title.text_width(p.title);
        g.title_px = width <= room ? title.pixel_height()
                                   : std::max(small_px(), title.pixel_height() * room / width);
        const FontAtlas& fitted = font(g.title_px);
        g.title_lines = fitted.text_width(p.title) <= room ? std::vector<std::string>{p.title}
                                                           : wrap(fitted, p.title, room, 2);
    }

    /// "returned: Q X P M" cut to `width` by leaving out the oldest keys ("returned: ... P M"),
    /// the newest always kept: the newest removals are the ones the caption speaks of.
    static std::string newest_that_fit(const FontAtlas& f, const view::ReturnedKeys& returned,
                                       float width) {
        const auto line_from = [&](std::size_t first) {
            std::string out = returned.label + (first > 0 ? " ..." : "");
            for (std::size_t k = first; k < returned.keys.size(); ++k)
                out += " " + returned.keys[k];
            return out;
        };
        std::size_t first = 0;
        std::string out = line_from(first);
        while (f.text_width(out) > width && first + 1 < returned.keys.size())
            out = line_from(++first);
        return out;
    }

    void build_header(const view::HeapPanelView& p, const PanelGeometry& g) {
        const float pad = padding();
        const FontAtlas& title = font(g.title_px);
        float baseline = g.title_baseline;
        for (const std::string& line : g.title_lines) {
            text(title, g.panel.x0 + pad, baseline, line, colors.title);
            baseline += title.line_height();
        }
        const FontAtlas& small = font(small_px());
        if (!p.returned.empty()) {
            text(small, g.panel.x0 + pad, g.returned_baseline,
                 newest_that_fit(small, p.returned, g.body.width() - 2.0F * pad), colors.counter);
        }
        if (g.counter_lines == 1) {
            text(small, g.panel.x0 + pad, g.counters_baseline, counters_line(p), colors.counter);
            return;
        }
        baseline = g.counters_baseline;
        for (const view::HeapCounter& c : p.counters) {
            text(small, g.panel.x0 + pad, baseline, counter_text(c), colors.counter);
            baseline += small.line_height();
        }
    }

    /// Where the key of slot i is drawn now (in the tree): its node, or on its way to the other
    /// node of an exchange.
    [[nodiscard]] static PointF node_position(const view::HeapPanelView& p, const PanelGeometry& g,
                                              std::size_t i) {
        if (p.swap && (i == p.swap->a || i == p.swap->b)) {
            // Along the edge, bowed out to either side so that the two keys pass each other in
            // view instead of hiding each other halfway.
            const std::size_t other = i == p.swap->a ? p.swap->b : p.swap->a;
            PointF c = lerp(g.nodes[i], g.nodes[other], p.swap->t);
            const float dx = g.nodes[other].x - g.nodes[i].x;
            const float dy = g.nodes[other].y - g.nodes[i].y;
            const float length = std::sqrt(dx * dx + dy * dy);
            if (length > 0.0F) {
                const float bow = std::sin(3.14159265F * p.swap->t) * 1.1F * g.node_radius / length;
                c.x += -dy * bow;
                c.y += dx * bow;
            }
            return c;
        }
        return g.nodes[i];
    }

    [[nodiscard]] static float alpha_of(const view::HeapPanelView& p, view::SlotMark mark) {
        return mark == view::SlotMark::inserted || mark == view::SlotMark::leaving ? p.fade : 1.0F;
    }

    /// Whether the key of slot i shows in the tree: a key that has faded out entirely (it left
    /// the heap) is drawn no more, and a leader may pass where it was.
    [[nodiscard]] static bool visible(const view::HeapPanelView& p, std::size_t i) {
        return alpha_of(p, p.slots[i].mark) > 0.01F;
    }

    void build_tree(const view::HeapPanelView& p, const PanelGeometry& g) {
        const std::size_t in_tree = std::min(p.slots.size(), p.heap_size);
        const float edge_w = std::max(1.5F, 3.0F * unit);
        // Edges between the nodes' places (the slide follows them).
        for (std::size_t i = 1; i < in_tree; ++i) {
            const std::size_t parent = (i - 1) / p.arity;
            const bool lit = p.slots[i].mark != view::SlotMark::plain &&
                             p.slots[parent].mark == p.slots[i].mark &&
                             p.slots[i].mark != view::SlotMark::leaving;
            // An edge comes and goes with its child: a removed key takes its edge with it.
            const Rgba8 color = lit ? heap_lit_edge(p.slots[i].mark, colors) : colors.edge;
            under.add_line(g.nodes[parent], g.nodes[i], lit ? 2.2F * edge_w : edge_w,
                           faded(color, alpha_of(p, p.slots[i].mark)));
        }
        // Empty places of the capacity, faint, so the shape of a full tree shows.
        for (std::size_t i = in_tree; i < g.nodes.size(); ++i) {
            add_node(
                {g.nodes[i].x, g.nodes[i].y, g.node_radius, std::max(1.0F, unit), colors.empty});
        }
        const FontAtlas& f = node_font(g.node_radius, g.node_half_w);
        // Still nodes first, moving ones on top.
        for (int pass = 0; pass < 2; ++pass) {
            for (std::size_t i = 0; i < in_tree; ++i) {
                const bool moving = p.swap && (i == p.swap->a || i == p.swap->b);
                if (moving != (pass == 1) || !visible(p, i)) continue;
                draw_node(p.slots[i], node_position(p, g, i), g.node_radius, g.node_half_w,
                          alpha_of(p, p.slots[i].mark), f);
            }
        }
    }

    void draw_node(const view::HeapSlotView& s, PointF c, float radius, float half_w, float alpha,
                   const FontAtlas& f) {
        const KeyStyle style = heap_mark_style(s.mark, colors);
        const Rgba8 fill = faded(s.mark == view::SlotMark::plain ? colors.node : style.fill, alpha);
        const Rgba8 outline = faded(colors.node_outline, alpha);
        const float ring = node_outline();
        if (half_w > radius + 0.5F) {
            // A pill as wide as its word: two round ends and a band between them, the outline
            // first and the fill inside it.
            const float end = half_w - radius;
            // Both outlines before both fills: an end's outline never crosses the other's fill.
            for (const float x : {c.x - end, c.x + end}) add_node({x, c.y, radius, 0.0F, outline});
            for (const float x : {c.x - end, c.x + end})
                add_node({x, c.y, radius - ring, 0.0F, fill});
            over.add_rect({c.x - end, c.y - radius, c.x + end, c.y + radius}, outline);
            over.add_rect({c.x - end, c.y - radius + ring, c.x + end, c.y + radius - ring}, fill);
        } else {
            add_node({c.x, c.y, radius, 0.0F, fill});
            add_node({c.x, c.y, radius, ring, outline});
        }
        centred(f, c, s.key, faded(style.text, alpha),
                DrawnShape{c.x - half_w, c.y - radius, c.x + half_w, c.y + radius, radius});
    }

    void build_array(const view::HeapPanelView& p, const PanelGeometry& g) {
        const float s = g.slot_size;
        const float w = g.slot_w;
        const float outline = std::max(1.0F, 2.0F * unit);
        const FontAtlas& f = key_font(s, w);
        // Index labels: two digits must fit under a slot.
        const FontAtlas& small = font(small_px());
        // Slot boxes for the whole capacity; index labels under them.
        for (std::size_t i = 0; i < std::max(p.capacity, p.slots.size()); ++i) {
            const PointF c = slot_centre(g, p, i);
            const RectF box{c.x - 0.5F * w, c.y - 0.5F * s, c.x + 0.5F * w, c.y + 0.5F * s};
            Rgba8 fill = colors.background;
            if (i < p.slots.size()) {
                const view::SlotMark m = p.slots[i].mark;
                fill = i >= p.heap_size ? colors.sorted_fill : heap_mark_style(m, colors).fill;
                if (m == view::SlotMark::inserted || m == view::SlotMark::leaving)
                    fill = faded(fill, p.fade);
                if (p.swap && (i == p.swap->a || i == p.swap->b)) fill = colors.slot;  // tile away
            }
            under.add_rect(box, fill);
            under.add_frame(box, outline, i < p.slots.size() ? colors.slot_outline : colors.empty);
            const std::string index = std::to_string(static_cast<long long>(i) + p.index_base);
            // The index's column: under its slot, as wide.
            centred(small, {c.x, box.y1 + 0.62F * small.line_height()}, index, colors.index,
                    DrawnShape{box.x0, box.y1, box.x1, box.y1 + small.line_height(), 0.0F});
        }
        // Keys; an exchange slides the two keys as tiles, one over the row and one under it.
        for (std::size_t i = 0; i < p.slots.size(); ++i) {
            PointF c = slot_centre(g, p, i);
            const view::SlotMark m = p.slots[i].mark;
            Rgba8 color = i >= p.heap_size ? colors.sorted_text : heap_mark_style(m, colors).text;
            float half_w = 0.5F * w;  // the key's slot, or its tile while it slides
            float half_h = 0.5F * s;
            if (p.swap && (i == p.swap->a || i == p.swap->b)) {
                const std::size_t other = i == p.swap->a ? p.swap->b : p.swap->a;
                // Over the row clear of its keys; under it only as far as the reserved room.
                const float lift = i == p.swap->a ? -1.05F : 0.75F;
                const float arc = std::sin(3.14159265F * p.swap->t) * lift * s;
                c = lerp(c, slot_centre(g, p, other), p.swap->t);
                c.y += arc;
                half_w = 0.46F * w;
                half_h = 0.46F * s;
                const RectF tile{c.x - half_w, c.y - half_h, c.x + half_w, c.y + half_h};
                under.add_rect(tile, heap_mark_style(view::SlotMark::moving, colors).fill);
                under.add_frame(tile, outline, colors.node_outline);
            }
            centred(f, c, p.slots[i].key, faded(color, alpha_of(p, m)),
                    DrawnShape{c.x - half_w, c.y - half_h, c.x + half_w, c.y + half_h, 0.0F});
        }
        if (p.heap_size < p.slots.size()) {
            const PointF c = slot_centre(g, p, p.heap_size);
            text(small, c.x - 0.5F * w, c.y - 0.5F * s - 0.35F * small.line_height(),
                 p.sorted_label, colors.index);
        }
    }

    /// The map's text: smaller than the keys, it is the second thing to read.
    const FontAtlas& map_font(const PanelGeometry& g) {
        return font(std::max(small_px(), std::min(0.42F * g.slot_size, caption_px())));
    }

    /// The indexed heap's map as a table over the array: for each key (in the order of their
    /// handles), the index of the slot that holds it; entries an exchange is updating lit.
    void build_map(const view::HeapPanelView& p, const PanelGeometry& g) {
        if (g.map_side) {
            build_map_column(p, g);
            return;
        }
        const FontAtlas& head = font(small_px());
        const FontAtlas& f = map_font(g);
        text(head, g.map.x0, g.map.y0 + head.ascent(), p.map_title, colors.map_header);
        const float key_y = g.map.y0 + head.line_height() + 0.5F * f.line_height();
        const float index_y = key_y + f.line_height();
        for (std::size_t c = 0; c < p.map.size(); ++c) {
            const view::HeapMapRow& row = p.map[c];
            const float x = g.map.x0 + (static_cast<float>(c) + 0.5F) * g.slot_w;
            if (row.updated) {
                under.add_rect({x - 0.45F * g.slot_w, index_y - 0.5F * f.line_height(),
                                x + 0.45F * g.slot_w, index_y + 0.5F * f.line_height()},
                               heap_mark_style(view::SlotMark::moving, colors).fill);
            }
            centred(f, {x, key_y}, row.key, colors.title);
            centred(f, {x, index_y}, row.index, row.updated ? heap_map_update_text : colors.index);
        }
    }

    /// The map as a column (map_column): the heading, then a line for each key, in the order
    /// of their handles, with the index of the slot that holds it; entries an exchange is
    /// updating lit.
    void build_map_column(const view::HeapPanelView& p, const PanelGeometry& g) {
        const FontAtlas& f = font(small_px());
        const float lh = f.line_height();
        float baseline = g.map.y0 + f.ascent();
        for (const std::string& line : g.map_title_lines) {
            text(f, g.map.x1 - f.text_width(line), baseline, line, colors.map_header);
            baseline += lh;
        }
        const float top = g.map.y0 + static_cast<float>(g.map_title_lines.size()) * lh;
        const std::size_t rows = std::max<std::size_t>(g.map_rows, 1);
        for (std::size_t c = 0; c < p.map.size(); ++c) {
            const view::HeapMapRow& row = p.map[c];
            const auto group = static_cast<float>(c / rows);
            const float y = top + (static_cast<float>(c % rows) + 0.5F) * lh;
            // Groups from left to right, flush with the column's right edge (the heading's).
            const auto groups = static_cast<float>(g.map_groups);
            const float x0 = g.map.x1 - groups * g.map_entry_w - (groups - 1.0F) * g.map_group_gap +
                             group * (g.map_entry_w + g.map_group_gap);
            const float x1 = x0 + g.map_entry_w;
            const float index_w = f.text_width(row.index);
            if (row.updated) {
                const float m = 0.25F * f.pixel_height();
                under.add_rect({x1 - index_w - m, y - 0.5F * lh, x1 + m, y + 0.5F * lh},
                               heap_mark_style(view::SlotMark::moving, colors).fill);
            }
            centred(f, {x0 + 0.5F * g.map_key_w, y}, row.key, colors.title);
            text(f, x1 - index_w, y + key_drop * f.pixel_height(), row.index,
                 row.updated ? heap_map_update_text : colors.index);
        }
    }

    void build_caption(const view::HeapPanelView& p, const PanelGeometry& g) {
        const float pad = padding();
        const FontAtlas& f = font(caption_px());
        const std::vector<std::string> lines = wrap(f, p.caption, g.panel.width() - 2.0F * pad,
                                                    std::min(g.caption_lines, max_caption_lines));
        float baseline = g.caption_top + f.ascent();
        for (const std::string& line : lines) {
            text(f, g.panel.x0 + pad, baseline, line, colors.caption);
            baseline += f.line_height();
        }
    }

    // ------------------------------------------------------------------ GL

    /// The frame's draw list and its text (drawn), as render draws them.
    void lay_out(const view::HeapFrameView& frame) {
        check(frame);
        build(frame);
    }

    void render(const view::HeapFrameView& frame, Image& out) {
        COLLIDE_ASSERT(target != nullptr, "a renderer made with a context draws");
        lay_out(frame);
        target->draw(list, out);
    }
};

// ---------------------------------------------------------------------------------------------

// HeapRenderer(config, backend, notice), which makes a GL target: heap_view_gl.cpp.
HeapRenderer::HeapRenderer(const HeapViewConfig& config, std::unique_ptr<HeapDrawTarget> target)
    : impl_(std::make_unique<Impl>(config, std::move(target))) {}

HeapRenderer::HeapRenderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

HeapRenderer HeapRenderer::layout_only(const HeapViewConfig& config) {
    config.validate();
    return HeapRenderer(std::make_unique<Impl>(config, nullptr));
}

HeapRenderer::~HeapRenderer() = default;
HeapRenderer::HeapRenderer(HeapRenderer&&) noexcept = default;
HeapRenderer& HeapRenderer::operator=(HeapRenderer&&) noexcept = default;

void HeapRenderer::render(const view::HeapFrameView& frame, Image& out) {
    impl_->render(frame, out);
}

void HeapRenderer::lay_out(const view::HeapFrameView& frame) {
    impl_->lay_out(frame);
}

bool HeapRenderer::fits(const HeapViewConfig& config, const view::HeapFrameView& frame) {
    config.validate();
    Impl layout(config, nullptr);
    return layout.fits(frame);
}

const std::vector<DrawnText>& HeapRenderer::last_text() const noexcept {
    return impl_->drawn;
}

Image HeapRenderer::render(const view::HeapFrameView& frame) {
    Image image;
    render(frame, image);
    return image;
}

}  // namespace collide::render
