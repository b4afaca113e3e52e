// The lesson level's layout (layout.hpp): title above each box, figures (and a note) below it,
// the column beside the boxes, the caption line, the queue strip; the compact form below
// compact_width. Pure arithmetic.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "code_panel.hpp"
#include "layout.hpp"

namespace collide::render {

namespace {

/// The lesson form below compact_width: boxes fill the frame under the scene's title (a
/// thumbnail names what it shows) and one line per panel.
FrameLayout compact_layout(const LayoutInput& in, float body) {
    FrameLayout layout;
    layout.compact = true;
    layout.body_pixel_height = body;
    layout.headline_pixel_height = body;
    const auto width = static_cast<float>(in.width);
    const auto height = static_cast<float>(in.height);
    const float m = std::max(2.0F, std::round(std::min(width, height) * 0.012F));
    layout.margin = m;
    // Two lines at the top, set close (a line as tall as the text) so the boxes keep the frame.
    const float line = std::round(body);
    const auto n = static_cast<float>(in.boxes.size());
    const float room_w = (width - (n + 1.0F) * m) / n;
    layout.text.push_back({TextRole::title, -1, {m, m, width - m, m + line}, body});
    const float lines_top = m + line;
    const float top = lines_top + line + std::max(3.0F, m);  // clear of the box's wall
    const float room_h = height - top - m;
    for (std::size_t i = 0; i < in.boxes.size(); ++i) {
        PanelLayout panel;
        const float x0 = m + static_cast<float>(i) * (room_w + m);
        panel.area = {x0 - 0.5F * m, 0.0F, x0 + room_w + 0.5F * m, height};
        panel.scale = fit_scale(in.boxes[i], room_w, room_h);
        panel.box = place_box(in.boxes[i], panel.scale, x0, x0 + room_w, top);
        layout.panels.push_back(panel);
        layout.text.push_back({TextRole::figures,
                               static_cast<int>(i),
                               {x0, lines_top, x0 + room_w, lines_top + line},
                               body});
    }
    return layout;
}

/// Where the column goes and the lesson's sizes, for lay_out_column.
struct ColumnMetrics {
    float x0 = 0.0F;      ///< the column's left edge
    float width = 0.0F;   ///< its width
    float top = 0.0F;     ///< its top: the boxes' top
    float bottom = 0.0F;  ///< its bottom: the boxes' bottom
    float line = 0.0F;    ///< a body line
    float head_line = 0.0F;
    float gap = 0.0F;
    float body = 0.0F;  ///< body text size (px)
    float head = 0.0F;  ///< headline text size (px)
    /// The work figures in body size (beside a small plot; under more than two bars), so that
    /// the bars fit.
    bool body_values = false;
};

/// The column beside the boxes (layout.column and its text slots).
void lay_out_column(FrameLayout& layout, const LayoutInput& in, const ColumnMetrics& metrics) {
    // The column: clock (and its unit), "work so far" (or, under two bars, their ratio), one bar
    // per panel (label, bar, value), energy, colour legend, plot. Groups that do not fit are left
    // out, least important last.
    const auto [column_x0, column_w, top, box_bottom, line, head_line, gap, body, head,
                body_values] = metrics;
    ColumnLayout& column = layout.column;
    column.area = {column_x0, top, column_x0 + column_w, box_bottom};
    const float bar_h = std::round(0.45F * line);
    float y = top;
    const auto fits = [&](float h) { return y + h <= column.area.y1; };
    const auto add = [&](TextRole role, int panel, float h, float px) {
        layout.text.push_back({role, panel, {column_x0, y, column_x0 + column_w, y + h}, px});
        y += h;
    };
    if (fits(line)) add(TextRole::clock, -1, line, body);
    if (in.clock_unit && fits(line)) add(TextRole::clock, -1, line, body);
    const auto panels = static_cast<float>(in.boxes.size());
    // Beside a small plot the work figures are body sized: the plot needs the height.
    const float value_line = metrics.body_values ? line : head_line;
    const float value_px = metrics.body_values ? body : head;
    // Under two bars their ratio ("131x less work") says what the heading would.
    const float cost_h = gap + line + panels * (line + bar_h + gap + value_line);
    const float energy_h = gap + 2.0F * line;
    if (in.large_plot) {
        // The plot is the subject: it comes first and takes what the energy line leaves, and
        // the cost graphic's room too unless the plot keeps at least 7 lines beside it.
        const float rest = column.area.y1 - y - energy_h;
        const bool with_cost = rest - cost_h >= 7.0F * line;
        const float h = std::max(0.0F, with_cost ? rest - cost_h : rest);
        column.plot = {column_x0, y + gap, column_x0 + column_w, y + h};
        y += h;
    }
    if (fits(cost_h)) {
        y += gap;
        if (!in.cost_ratio) add(TextRole::cost_heading, -1, line, body);
        const float bars_top = y;
        for (std::size_t i = 0; i < in.boxes.size(); ++i) {
            add(TextRole::cost_label, static_cast<int>(i), line, body);
            y += bar_h + gap;  // the bar itself
            add(TextRole::cost_value, static_cast<int>(i), value_line, value_px);
        }
        column.bars = {column_x0, bars_top, column_x0 + column_w, y};
        if (in.cost_ratio) add(TextRole::cost_ratio, -1, line, body);
    }
    if (fits(energy_h)) {
        y += gap;
        add(TextRole::energy, -1, line, body);  // "Energy" / "conserved": two narrow lines
        add(TextRole::energy, -1, line, body);
    }
    if (in.color_legend && fits(gap + bar_h + line)) {
        y += gap;
        column.legend_bar = {column_x0, y, column_x0 + column_w, y + bar_h};
        y += bar_h;
        add(TextRole::legend, -1, line, body);
    }
    y += gap;
    // A small plot may reach down beside the figures row: the figures stay under their own box,
    // so that strip between (or beside) the boxes is free.
    const float plot_bottom = in.small_plot ? column.area.y1 + gap + head_line : column.area.y1;
    if (!in.large_plot && plot_bottom - y > 3.0F * line) {
        column.plot = {column_x0, y, column_x0 + column_w, plot_bottom};
    }
}

/// Three to five boxes (a --dt list beside the event-driven panel): a grid of one or two rows,
/// whichever gives the larger boxes, each cell its title, box, figures (and note, marks lines);
/// the column on the right, the caption under everything. No queue strip, no code column (the
/// plan refuses them beside a list).
FrameLayout grid_layout(const LayoutInput& in, float body) {
    FrameLayout layout;
    const float head = std::round(body * headline_scale);
    layout.body_pixel_height = body;
    layout.headline_pixel_height = head;
    const auto width = static_cast<float>(in.width);
    const auto height = static_cast<float>(in.height);
    const float m = std::max(3.0F, std::round(height * 0.014F));
    layout.margin = m;
    const float line = std::round(body * 1.25F);
    const float head_line = std::round(head * 1.2F);
    const float gap = std::round(0.6F * m);
    const bool mark_line =
        std::find(in.mark_lines.begin(), in.mark_lines.end(), true) != in.mark_lines.end();
    const float above = line + gap;  // the title
    const float below = gap + head_line + (in.note_line ? line : 0.0F) + (mark_line ? line : 0.0F);
    const float caption_top = height - m - line;
    const float column_w =
        std::round(in.large_plot ? 0.30F * width : std::max(0.15F * width, 6.5F * body));
    // The cells: from the left margin to the column, from the top margin to the caption.
    const float cells_w = width - column_w - 3.0F * m;
    const float cells_h = caption_top - gap - m;
    const std::size_t n = in.boxes.size();
    struct Grid {
        std::size_t columns = 1;
        float cell_w = 0.0F;
        double scale = 0.0;
    };
    Grid best;
    for (const std::size_t rows : {std::size_t{1}, std::size_t{2}}) {
        Grid grid;
        grid.columns = (n + rows - 1) / rows;
        const auto cols = static_cast<float>(grid.columns);
        grid.cell_w = (cells_w - (cols - 1.0F) * m) / cols;
        const float cell_h =
            (cells_h - static_cast<float>(rows - 1) * gap) / static_cast<float>(rows);
        grid.scale = std::numeric_limits<double>::max();
        for (const Box& box : in.boxes)
            grid.scale = std::min(grid.scale, fit_scale(box, grid.cell_w, cell_h - above - below));
        // Two rows give each title and figures row a wider cell: worth boxes a little smaller.
        const double wider_text = rows == 2 ? 1.25 : 1.0;
        if (grid.scale * wider_text > best.scale) best = grid;
    }
    float box_h = 0.0F;
    for (const Box& box : in.boxes)
        box_h = std::max(box_h, static_cast<float>(box.height * best.scale));
    const std::size_t rows = (n + best.columns - 1) / best.columns;
    const float row_h = above + box_h + below;
    const float used_h = static_cast<float>(rows) * row_h + static_cast<float>(rows - 1) * gap;
    const float y0 = m + std::round(0.5F * (cells_h - used_h));  // the grid centred vertically
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t row = i / best.columns;
        const float x0 = m + static_cast<float>(i % best.columns) * (best.cell_w + m);
        const float x1 = x0 + best.cell_w;
        const float top = y0 + static_cast<float>(row) * (row_h + gap) + above;
        const int p = static_cast<int>(i);
        PanelLayout panel;
        panel.scale = best.scale;
        panel.box = place_box(in.boxes[i], best.scale, x0, x1, top);
        panel.area = {x0 - 0.5F * m, top - above, x1 + 0.5F * m, top + box_h + below};
        layout.text.push_back({TextRole::title, p, {x0, top - gap - line, x1, top - gap}, body});
        float y = top + box_h + gap;
        layout.text.push_back({TextRole::figures, p, {x0, y, x1, y + head_line}, head});
        y += head_line;
        if (in.note_line) {
            layout.text.push_back({TextRole::note, p, {x0, y, x1, y + line}, body});
            y += line;
        }
        if (mark_line && p < static_cast<int>(in.mark_lines.size()) && in.mark_lines[i])
            layout.text.push_back({TextRole::marks, p, {x0, y, x1, y + line}, body});
        layout.panels.push_back(panel);
    }
    layout.text.push_back({TextRole::caption, -1, {m, caption_top, width - m, height - m}, body});
    // The column beside the whole grid: one bar per panel needs its height.
    const float column_x0 = width - m - column_w;
    // It starts at the top margin, and has no line for the clock's unit: five bars need it all.
    LayoutInput column_in = in;
    column_in.clock_unit = false;
    column_in.small_plot = false;  // the plot stops at the column's foot, above the caption
    lay_out_column(
        layout, column_in,
        {column_x0, column_w, m, caption_top - gap, line, head_line, gap, body, head, true});
    return layout;
}

/// The queue strip's height when the boxes and the strip share `room` (px): what the boxes leave
/// at queue_boxes_share of the frame, between queue_strip_min_share and queue_strip_share of its
/// height.
float queue_strip_height(const LayoutInput& in, float room) {
    const auto width = static_cast<float>(in.width);
    const auto height = static_cast<float>(in.height);
    double area = 0.0;  // the boxes' area at one pixel per unit
    double tallest = 0.0;
    for (const Box& box : in.boxes) {
        area += box.width * box.height;
        tallest = std::max(tallest, box.height);
    }
    const double scale = std::sqrt(queue_boxes_share * width * height / std::max(area, 1e-12));
    const auto boxes_h = static_cast<float>(std::ceil(tallest * scale));
    return std::round(
        std::clamp(room - boxes_h, queue_strip_min_share * height, queue_strip_share * height));
}

/// One panel beside its text: a square box cannot fill a 16:9 frame under a title and over
/// figures, so the box takes the frame's height (above the caption) on the left, and on its right
/// come, top to bottom: the --code column, the title, figures, note, marks and how lines, the
/// queue strip, and the column (clock, cost, energy, plot) in what is left.
FrameLayout side_layout(const LayoutInput& in, float body) {
    FrameLayout layout;
    const float head = std::round(body * headline_scale);
    layout.body_pixel_height = body;
    layout.headline_pixel_height = head;
    const auto width = static_cast<float>(in.width);
    const auto height = static_cast<float>(in.height);
    const float m = std::max(3.0F, std::round(height * 0.014F));
    layout.margin = m;
    const float line = body;
    const float head_line = head;
    const float gap = std::round(0.6F * m);
    const float caption_top = height - m - line;
    const Box& box = in.boxes.front();
    // The text on the right needs at least this width (a title, two figures), and the code its.
    const float code_w = in.code_rows > 0 ? std::ceil(in.code_width) : 0.0F;
    const float text_w = std::max(code_w, std::max(0.3F * width, 10.0F * body));
    // A crowded box's numbers take a column beside it, left of the text but for the queue strip
    // (add_frame_numbers): a box as tall as the frame leaves that width spare at 16:9.
    const float numbers_w = in.queue_panel == 0 ? std::ceil(in.number_column) : 0.0F;
    const double scale =
        fit_scale(box, width - text_w - 3.0F * m - numbers_w, caption_top - gap - m);
    PanelLayout panel;
    panel.scale = scale;
    panel.box = place_box(box, scale, m, m + static_cast<float>(box.width * scale), m);
    panel.area = {0.0F, 0.0F, panel.box.x1 + 0.5F * m, caption_top - gap};
    layout.panels.push_back(panel);
    const float x0 = panel.box.x1 + m + numbers_w;
    const float x1 = width - m;
    const float bottom = panel.box.y1;
    float y = m;
    if (code_w > 0.0F) {
        const float rows_h = (static_cast<float>(in.code_rows) * 1.2F + 1.2F) * body;
        // With the queue the listing stands at the frame's right edge: the room it leaves beside
        // the box is where a crowded box's disc numbers go (add_frame_label).
        const float code_x0 = in.queue_panel == 0 ? std::max(x0, x1 - code_w) : x0;
        layout.code = {code_x0, y, std::min(x1, code_x0 + code_w), y + std::ceil(rows_h)};
        for (const RectF& row : code_rows(layout.code, body, in.code_rows))
            layout.text.push_back({TextRole::code, -1, row, body});
        y = layout.code.y1 + gap;
    }
    const auto add = [&](TextRole role, float h, float px) {
        layout.text.push_back({role, 0, {x0, y, x1, y + h}, px});
        y += h;
    };
    add(TextRole::title, line, body);
    y += gap;
    add(TextRole::figures, head_line, head);
    if (in.note_line) add(TextRole::note, line, body);
    if (!in.mark_lines.empty() && in.mark_lines.front()) add(TextRole::marks, line, body);
    if (in.how_line) add(TextRole::how, line, body);
    if (in.queue_panel == 0) {
        layout.queue_panel = 0;
        const float rest = bottom - (y + gap);
        // The strip takes up to its share, leaving the column its clock (two lines) when it can.
        const float strip_h = std::round(std::clamp(
            rest - 2.0F * line - gap, queue_strip_min_share * height, queue_strip_share * height));
        // The strip keeps the width beside the box whole (its heading and counts are said
        // whole): a crowded box's number column stops over and under it.
        layout.queue_strip = {x0 - numbers_w, y + gap, x1, y + gap + strip_h};
        layout.text.push_back({TextRole::queue, 0, layout.queue_strip, body});
        y = layout.queue_strip.y1;
    }
    layout.text.push_back({TextRole::caption, -1, {m, caption_top, width - m, height - m}, body});
    LayoutInput column_in = in;
    column_in.small_plot = false;  // the plot stops at the box's foot, above the caption
    lay_out_column(layout, column_in,
                   {x0, x1 - x0, y + gap, bottom, line, head_line, gap, body, head, false});
    return layout;
}

}  // namespace

FrameLayout lesson_layout(const LayoutInput& in) {
    const float body = lesson_pixel_height(in.width, in.height);
    if (in.width < compact_width) return compact_layout(in, body);
    if (in.boxes.size() > 2) return grid_layout(in, body);
    if (in.boxes.size() == 1) return side_layout(in, body);
    FrameLayout layout;
    const float head = std::round(body * headline_scale);
    layout.body_pixel_height = body;
    layout.headline_pixel_height = head;
    const auto height = static_cast<float>(in.height);
    const float m = std::max(3.0F, std::round(height * 0.014F));
    // --code: a column on the right edge for the pseudocode with the column (clock, energy,
    // cost) under it, so that the boxes stand side by side without the column between them
    // and keep their share (issue 44: >= 35 % with the queue); the queue strip and the caption
    // under them keep the frame's width.
    const auto full_width = static_cast<float>(in.width);
    const float code_w = in.code_rows > 0 ? std::ceil(in.code_width) : 0.0F;
    const bool column_under_code = code_w > 0.0F;
    const float side_w =
        column_under_code ? std::max(code_w, std::max(0.15F * full_width, 6.5F * body)) : 0.0F;
    const float width = full_width - (column_under_code ? side_w + m : 0.0F);
    layout.margin = m;
    // Lines as tall as the font: a pixel height holds ascent and descent, so rows never touch,
    // and the boxes keep the height (issue 44: >= 55 % of the frame).
    const float line = body;
    const float head_line = head;
    const float gap = std::round(0.6F * m);

    // Vertical: title | box | figures | at most two lines of note, marks, how ... caption.
    const float box_top = m + line + gap;
    const auto wants_marks = [&](std::size_t i) {
        return i < in.mark_lines.size() && in.mark_lines[i];
    };
    const bool mark_line = wants_marks(0) || wants_marks(1);
    // A note is the left panel's only (dt longer than a frame): when a marks line comes too, the
    // right panel's other line (its how, or with the queue its legend) moves up into the note's
    // line, and the left panel's marks take the marks line's whole width. The left panel's how
    // is then left out (its failures stay whole in a figures row that is wide enough).
    const bool two = in.boxes.size() == 2;
    const bool how_with_note = two && in.note_line && mark_line && in.how_line;
    const bool marks_with_note = two && in.note_line && mark_line && !in.how_line && wants_marks(1);
    const bool how_line = in.how_line && !how_with_note;
    const float below = gap + head_line + (in.note_line ? line : 0.0F) + (mark_line ? line : 0.0F) +
                        (how_line ? line : 0.0F);
    const float caption_top = height - m - line;
    const bool queue = in.queue_panel >= 0 && in.queue_panel < static_cast<int>(in.boxes.size());
    // The strip's frame sits right under the last line (its text keeps its own padding).
    const float queue_h =
        queue ? queue_strip_height(in, caption_top - gap - below - box_top) : 0.0F;
    const float room_h = caption_top - gap - below - box_top - queue_h;
    // Horizontal: [m box m column m box m] or [m box m column m].
    const auto n = static_cast<float>(in.boxes.size());
    // A large plot is the subject, but the boxes and it together fill the frame: a quarter of
    // the width leaves the boxes their height.
    const float column_w =
        column_under_code
            ? 0.0F
            : std::round(in.large_plot ? 0.25F * width : std::max(0.15F * width, 6.5F * body));
    const float column_margins = column_under_code ? 0.0F : m;
    const float room_w = (width - column_w - (n + 1.0F) * m - column_margins) / n;

    double scale = std::numeric_limits<double>::max();
    for (const Box& box : in.boxes) scale = std::min(scale, fit_scale(box, room_w, room_h));
    float used_w = column_w + (n + 1.0F) * m + column_margins;
    float used_h = 0.0F;
    for (const Box& box : in.boxes) {
        used_w += static_cast<float>(box.width * scale);
        used_h = std::max(used_h, static_cast<float>(box.height * scale));
    }
    const float dx = std::round(0.5F * (width - used_w));
    const float dy = std::round(0.5F * (room_h - used_h));  // centre the stack vertically

    float x = dx + m;
    std::vector<float> box_x0;
    float column_x0 = 0.0F;
    for (std::size_t i = 0; i < in.boxes.size(); ++i) {
        if (i == 1) {  // the column sits between two boxes (or under the code: none here)
            column_x0 = x;
            x += column_w + column_margins;
        }
        box_x0.push_back(x);
        x += static_cast<float>(in.boxes[i].width * scale) + m;
    }
    if (in.boxes.size() == 1) column_x0 = x;
    // Where the two panels' text meets: the column's middle, or without it the boxes' gap's.
    const float column_mid = column_under_code ? column_x0 - 0.5F * m : column_x0 + 0.5F * column_w;

    const float top = box_top + dy;
    for (std::size_t i = 0; i < in.boxes.size(); ++i) {
        PanelLayout panel;
        panel.scale = scale;
        const float bw = static_cast<float>(in.boxes[i].width * scale);
        panel.box = place_box(in.boxes[i], scale, box_x0[i], box_x0[i] + bw, top);
        // Text of a panel may reach to the column's middle (two panels) or the frame's edge.
        const bool left_of_column = i == 0 && in.boxes.size() == 2;
        const float text_x0 = left_of_column ? std::max(m, panel.box.x0 - m)
                                             : (i == 0 ? panel.box.x0 : column_mid + 0.5F * m);
        // The right one of two panels may reach the frame's edge; a single panel's text stops
        // short of the column on its right.
        const float text_x1 = left_of_column         ? column_mid - 0.5F * m
                              : in.boxes.size() == 2 ? width - m
                                                     : std::min(width - m, panel.box.x1 + m);
        panel.area = {left_of_column ? 0.0F : (i == 0 ? 0.0F : column_mid), 0.0F,
                      left_of_column ? column_mid : width, caption_top - gap};
        const int p = static_cast<int>(i);
        // The left title and note may start at the frame's margin: when the boxes are inset (the
        // queue strip makes them smaller) "Time-driven: steps of dt = ..." still fits a line.
        const float title_x0 = left_of_column ? m : text_x0;
        layout.text.push_back(
            {TextRole::title, p, {title_x0, top - gap - line, text_x1, top - gap}, body});
        float y = std::max(panel.box.y1, top) + gap;
        // Figures stay under their own box, so the two panels' rows cannot run together. With
        // the queue strip the left one starts at the frame's margin like its title: its inset box
        // leaves too narrow a row for two failures, and the strip has taken the how line they
        // would continue on; likewise when the how line has given its place.
        const float figures_x0 = left_of_column ? (queue || how_with_note ? title_x0 : text_x0)
                                                : std::max(text_x0, panel.box.x0);
        const float figures_x1 = left_of_column ? std::min(text_x1, panel.box.x1) : text_x1;
        layout.text.push_back(
            {TextRole::figures, p, {figures_x0, y, figures_x1, y + head_line}, head});
        y += head_line;
        if (in.note_line) {
            const TextRole role = p == 0 || !(how_with_note || marks_with_note) ? TextRole::note
                                  : how_with_note                               ? TextRole::how
                                                                                : TextRole::marks;
            layout.text.push_back({role, p, {title_x0, y, text_x1, y + line}, body});
            y += line;
        }
        if (mark_line) {
            const bool right_has_row = wants_marks(1) && !marks_with_note;
            const float x1 = left_of_column && !right_has_row ? width - m : text_x1;
            if (wants_marks(i) && !(p == 1 && marks_with_note))
                layout.text.push_back({TextRole::marks, p, {title_x0, y, x1, y + line}, body});
            y += line;
        }
        if (how_line) {
            layout.text.push_back({TextRole::how, p, {title_x0, y, text_x1, y + line}, body});
            y += line;
        }
        if (queue && p == in.queue_panel) {
            // Under the figures, across the frame: a tree of events needs the width.
            layout.queue_panel = p;
            layout.queue_strip = {m, y, full_width - m, y + queue_h};
            layout.text.push_back({TextRole::queue, p, layout.queue_strip, body});
        }
        layout.panels.push_back(panel);
    }
    const float box_bottom = top + used_h;
    layout.text.push_back(
        {TextRole::caption, -1, {m, caption_top, full_width - m, height - m}, body});
    if (column_under_code) {
        // As tall as its rows (1.2 lines each and the padding), down to the strip at most; the
        // column takes what it leaves down to the boxes' foot.
        const float bottom =
            layout.queue_panel >= 0 ? layout.queue_strip.y0 - gap : caption_top - gap;
        const float rows_h = (static_cast<float>(in.code_rows) * 1.2F + 1.2F) * body;
        const float code_x0 = full_width - m - side_w;
        layout.code = {code_x0, m, code_x0 + code_w, std::min(bottom, m + std::ceil(rows_h))};
        for (const RectF& row : code_rows(layout.code, body, in.code_rows))
            layout.text.push_back({TextRole::code, -1, row, body});
        // The right panel's lines under its box (queue legend, marks, how) move to the foot of
        // this column, so that the left panel's note and marks take the width under both boxes
        // whole ("Moves only every 96th frame" is never cut).
        std::vector<TextSlot> right_lines;
        for (auto it = layout.text.begin(); it != layout.text.end();) {
            const bool under_right =
                it->panel == 1 && (it->role == TextRole::marks || it->role == TextRole::how ||
                                   it->role == TextRole::note);
            if (under_right) {
                right_lines.push_back(*it);
                it = layout.text.erase(it);
                continue;
            }
            if (it->panel == 0 && (it->role == TextRole::marks || it->role == TextRole::note))
                it->rect.x1 = width - m;
            ++it;
        }
        // A crowded right box's numbers take a column beside it under the code: the column's
        // text and the right panel's lines start right of it.
        const float numbers_w = layout.queue_panel == 1 ? std::ceil(in.number_column) : 0.0F;
        const float text_x0 = code_x0 + numbers_w;
        const float text_w = side_w - numbers_w;
        const float side_bottom = std::max(box_bottom, bottom);
        float y = side_bottom - static_cast<float>(right_lines.size()) * line;
        for (TextSlot& slot : right_lines) {
            slot.rect = {text_x0, y, text_x0 + text_w, y + line};
            layout.text.push_back(slot);
            y += line;
        }
        const float column_bottom = side_bottom - static_cast<float>(right_lines.size()) * line -
                                    (right_lines.empty() ? 0.0F : gap);
        LayoutInput column_in = in;
        column_in.small_plot = false;  // the plot stops at the boxes' foot
        lay_out_column(layout, column_in,
                       {text_x0, text_w, layout.code.y1 + gap, column_bottom, line, head_line, gap,
                        body, head, true});
        return layout;
    }

    lay_out_column(
        layout, in,
        {column_x0, column_w, top, box_bottom, line, head_line, gap, body, head, in.small_plot});
    return layout;
}

}  // namespace collide::render
