// The renderer's colours in one place: the themes' palettes, the engines' accents, the colour
// reserved for failures and the contrast rule, and the colour helpers every painter shares.
#include "theme.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace collide::render {

namespace {

double linear_channel(int c) {
    const double v = c / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

// sRGB to linear light, tabulated: the contrast rule runs per disc in colour-mapped scenes.
double channel_luminance(std::uint8_t c) {
    static const std::array<double, 256> table = [] {
        std::array<double, 256> t{};
        for (int i = 0; i < 256; ++i) t[static_cast<std::size_t>(i)] = linear_channel(i);
        return t;
    }();
    return table[c];
}

double luminance(Rgb8 c) {
    return 0.2126 * channel_luminance(c.r) + 0.7152 * channel_luminance(c.g) +
           0.0722 * channel_luminance(c.b);
}

}  // namespace

Rgba8 faded(Rgba8 c, float opacity) noexcept {
    c.a = static_cast<std::uint8_t>(std::lround(std::clamp(opacity, 0.0F, 1.0F) * c.a));
    return c;
}

Rgb8 rgb(Rgba8 c) noexcept {
    return {c.r, c.g, c.b};
}

Palette palette(Theme theme) noexcept {
    if (theme == Theme::light) {
        return {{236, 236, 240, 255}, {255, 255, 255, 255}, {40, 40, 48, 255},
                {150, 150, 170, 255}, {10, 10, 15, 255},    {35, 35, 45, 255},
                {95, 95, 105, 255},   {190, 0, 150, 255},   {30, 30, 36, 255},
                {110, 110, 135, 255}};
    }
    return {{22, 22, 28, 255},    {34, 36, 46, 255},    {205, 205, 215, 255}, {95, 95, 120, 255},
            {245, 245, 245, 255}, {215, 215, 222, 255}, {150, 150, 160, 255}, {255, 40, 220, 255},
            {225, 225, 232, 255}, {130, 130, 160, 255}};
}

PlotColors plot_colors(Theme theme) noexcept {
    if (theme == Theme::dark) return dark_plot_colors;
    const Palette p = palette(theme);
    // The zero line: halfway between the axis grey and the page, quieter than the axes.
    const auto mix = [](std::uint8_t a, std::uint8_t b) {
        return static_cast<std::uint8_t>((static_cast<int>(a) + static_cast<int>(b)) / 2);
    };
    const Rgba8 zero{mix(p.muted.r, p.background.r), mix(p.muted.g, p.background.g),
                     mix(p.muted.b, p.background.b), 255};
    return {p.text, p.muted, p.title, zero};
}

HeapPalette heap_palette(Theme theme) noexcept {
    if (theme == Theme::light) {
        return {{236, 236, 240, 255}, {255, 255, 255, 255}, {10, 10, 15, 255},
                {55, 55, 65, 255},    {20, 20, 25, 255},    {128, 130, 148, 255},
                {226, 229, 238, 255}, {85, 88, 105, 255},   {195, 197, 210, 255},
                {214, 218, 230, 255}, {80, 82, 98, 255},    {40, 40, 50, 255},
                {205, 207, 216, 255}, {10, 10, 15, 255},    {35, 35, 45, 255},
                {100, 102, 116, 255}, {75, 77, 95, 255}};
    }
    return {{22, 22, 28, 255},    {32, 34, 44, 255},    {245, 245, 245, 255}, {190, 190, 200, 255},
            {255, 255, 255, 255}, {105, 108, 128, 255}, {52, 56, 74, 255},    {150, 152, 170, 255},
            {70, 72, 90, 255},    {58, 62, 84, 255},    {165, 168, 185, 255}, {215, 215, 225, 255},
            {40, 43, 55, 255},    {245, 245, 245, 255}, {200, 200, 210, 255}, {138, 140, 156, 255},
            {170, 172, 190, 255}};
}

KeyStyle heap_mark_style(view::SlotMark mark, const HeapPalette& palette) noexcept {
    constexpr Rgba8 white{255, 255, 255, 255};
    switch (mark) {
        case view::SlotMark::plain:
            return {palette.slot, palette.title};
        case view::SlotMark::compared:
            return {{240, 170, 40, 255}, highlight_dark_text};
        case view::SlotMark::moving:
            return {{70, 145, 240, 255}, white};
        case view::SlotMark::inserted:
            return {{70, 185, 100, 255}, highlight_dark_text};
        case view::SlotMark::changed:
            return {{175, 110, 230, 255}, white};
        case view::SlotMark::best:
            return {{40, 175, 175, 255}, highlight_dark_text};
        case view::SlotMark::leaving:
            return {{225, 70, 70, 255}, white};
        case view::SlotMark::sinking:
            return {{240, 170, 40, 255}, highlight_dark_text};
    }
    return {palette.slot, palette.title};
}

CodeColors code_colors(const Palette& palette) noexcept {
    const Rgb8 edge = with_contrast(rgb(heap_token_now_fill), rgb(palette.box_fill), mark_contrast);
    return {palette.box_fill,    palette.muted,       palette.text,
            highlight_dark_text, heap_token_now_fill, {edge.r, edge.g, edge.b, 255},
            palette.title};
}

CodeColors heap_code_colors(const HeapPalette& palette) noexcept {
    const Rgb8 edge = with_contrast(rgb(heap_token_now_fill), rgb(palette.panel), mark_contrast);
    return {palette.panel,       palette.map_header,  palette.counter,
            highlight_dark_text, heap_token_now_fill, {edge.r, edge.g, edge.b, 255},
            palette.title};
}

Rgba8 heap_lit_edge(view::SlotMark mark, const HeapPalette& palette) noexcept {
    const Rgb8 c =
        with_contrast(rgb(heap_mark_style(mark, palette).fill), rgb(palette.panel), mark_contrast);
    return {c.r, c.g, c.b, 255};
}

PuzzlePalette puzzle_palette(Theme theme) noexcept {
    if (theme == Theme::light) {
        // The collision video's light page; boards keep light tiles in a dark frame (a board
        // reads the same in both themes), marks and amber text darkened to stand out on white.
        return {
            {236, 236, 240, 255}, {255, 255, 255, 255}, {10, 10, 15, 255},    {55, 55, 65, 255},
            {150, 95, 0, 255},    {80, 82, 98, 255},    {130, 132, 150, 255}, {185, 187, 200, 255},
            {240, 241, 246, 255}, {222, 224, 232, 255}, {24, 24, 30, 255},    {70, 72, 88, 255},
            {240, 170, 40, 255},  {180, 105, 0, 255},   {30, 140, 60, 255},   {40, 105, 210, 255}};
    }
    // The collision video's dark theme.
    return {{22, 22, 28, 255},   {32, 34, 44, 255},    {245, 245, 245, 255}, {200, 200, 210, 255},
            {240, 190, 80, 255}, {175, 178, 195, 255}, {105, 108, 128, 255}, {70, 72, 90, 255},
            {38, 40, 52, 255},   {222, 224, 232, 255}, {24, 24, 30, 255},    {48, 50, 64, 255},
            {240, 170, 40, 255}, {240, 170, 40, 255},  {80, 200, 110, 255},  {90, 160, 245, 255}};
}

CodeColors puzzle_code_colors(const PuzzlePalette& palette) noexcept {
    const Rgb8 edge = with_contrast(rgb(palette.sliding_tile), rgb(palette.panel), mark_contrast);
    return {palette.panel,       palette.title,        palette.counter,
            highlight_dark_text, palette.sliding_tile, {edge.r, edge.g, edge.b, 255},
            palette.title};
}

Rgba8 puzzle_mark_color(view::PuzzleMark mark, const PuzzlePalette& palette) noexcept {
    switch (mark) {
        case view::PuzzleMark::current:
            return palette.current;
        case view::PuzzleMark::goal:
            return palette.goal;
        case view::PuzzleMark::solution:
            return palette.solution;
        case view::PuzzleMark::plain:
            break;
    }
    return palette.edge;
}

Rgb8 panel_accent(bool time_driven, Theme theme) noexcept {
    const Rgb8 accent = time_driven ? time_driven_accent : event_driven_accent;
    if (theme == Theme::dark) return accent;
    return with_contrast(accent, rgb(palette(theme).background), mark_contrast);
}

Rgb8 next_event_color(Theme theme) noexcept {
    return theme == Theme::light ? next_event_light : next_event_dark;
}

Rgb8 candidate_color(int tint, Theme theme) noexcept {
    const auto i = static_cast<std::size_t>(std::max(0, tint)) % candidate_tints;
    return theme == Theme::light ? candidate_light[i] : candidate_dark[i];
}

Rgb8 motion_arrow_color(Theme theme) noexcept {
    return rgb(palette(theme).text);
}

Rgb8 failure_color(Theme theme) noexcept {
    return rgb(palette(theme).failure);
}

Rgb8 box_fill_color(Theme theme) noexcept {
    return rgb(palette(theme).box_fill);
}

bool near_failure_color(Rgb8 c) noexcept {
    // Magenta family: red and blue both well above green. Both themes' failure colours are in it.
    const int r = c.r;
    const int g = c.g;
    const int b = c.b;
    return r > 150 && b > 120 && g < std::min(r, b) - 70;
}

Rgb8 away_from_failure_color(Rgb8 c) noexcept {
    if (!near_failure_color(c)) return c;
    // Towards violet: keep the brightness, pull red down until the colour leaves the family.
    Rgb8 out = c;
    while (near_failure_color(out) && out.r > 0) out.r = static_cast<std::uint8_t>(out.r - 5);
    return out;
}

double contrast_ratio(Rgb8 a, Rgb8 b) noexcept {
    const double la = luminance(a);
    const double lb = luminance(b);
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

Rgb8 blend(Rgb8 color, Rgb8 background, float opacity) noexcept {
    // The GL blend (SRC_ALPHA, ONE_MINUS_SRC_ALPHA) on 8-bit channels, alpha quantised as stored.
    const float a =
        static_cast<float>(std::lround(std::clamp(opacity, 0.0F, 1.0F) * 255.0F)) / 255.0F;
    const auto mix = [a](std::uint8_t c, std::uint8_t b) {
        return static_cast<std::uint8_t>(
            std::lround(a * static_cast<float>(c) + (1.0F - a) * static_cast<float>(b)));
    };
    return {mix(color.r, background.r), mix(color.g, background.g), mix(color.b, background.b)};
}

float least_opacity(Rgb8 color, Rgb8 background, double ratio) noexcept {
    if (contrast_ratio(color, background) < ratio) return 1.0F;
    int low = 0;  // contrast grows with opacity: the first alpha step that keeps the ratio
    int high = 255;
    while (low < high) {
        const int mid = (low + high) / 2;
        if (contrast_ratio(blend(color, background, static_cast<float>(mid) / 255.0F),
                           background) >= ratio) {
            high = mid;
        } else {
            low = mid + 1;
        }
    }
    return static_cast<float>(high) / 255.0F;
}

Rgb8 with_contrast(Rgb8 color, Rgb8 background, double ratio) noexcept {
    const Rgb8 black{0, 0, 0};
    const Rgb8 white{255, 255, 255};
    const Rgb8 target =
        contrast_ratio(black, background) >= contrast_ratio(white, background) ? black : white;
    Rgb8 out = color;
    for (int step = 1; step <= 20 && contrast_ratio(out, background) < ratio; ++step) {
        out = blend(target, color, static_cast<float>(step) / 20.0F);
    }
    return out;
}

float mark_floor(Theme theme) noexcept {
    const Palette p = palette(theme);
    return least_opacity(rgb(p.failure), rgb(p.box_fill), mark_contrast);
}

Rgb8 accent_text(Rgb8 accent, Theme theme) noexcept {
    return with_contrast(accent, rgb(palette(theme).background), text_contrast);
}

TrailLook trail_look(Rgb8 disc, Theme theme) noexcept {
    const Rgb8 fill = rgb(palette(theme).box_fill);
    // Clear of the box by a margin, so that the trail can still fade to a third of its alpha
    // and keep 3:1 at its faintest.
    TrailLook look;
    look.color = with_contrast(disc, fill, 2.0 * text_contrast);
    const float least = least_opacity(look.color, fill, mark_contrast);
    // Half a step over: the trail truncates its alpha to whole steps.
    look.min_share = std::clamp((least * 255.0F + 0.5F) / trail_max_alpha, 0.35F, 1.0F);
    return look;
}

float legible_trails(const std::vector<Rgb8>& colors, const std::vector<DiscState>& discs,
                     Theme theme, std::vector<Rgb8>& out) {
    out = colors;
    float share = 0.35F;
    for (std::size_t k = 0; k < discs.size() && k < colors.size(); ++k) {
        if (!discs[k].tagged) continue;
        const TrailLook look = trail_look(colors[k], theme);
        out[k] = look.color;
        share = std::max(share, look.min_share);
    }
    return share;
}

std::vector<ColorPair> color_pairs(Theme theme) {
    const Palette p = palette(theme);
    const Rgb8 page = rgb(p.background);
    const Rgb8 box = rgb(p.box_fill);
    const PlotColors plot = plot_colors(theme);
    std::vector<ColorPair> pairs = {
        {"title on the page", rgb(p.title), page, text_contrast},
        {"text on the page", rgb(p.text), page, text_contrast},
        {"muted text on the page (cost heading, queue labels)", rgb(p.muted), page, text_contrast},
        {"failure figure and count on the page", rgb(p.failure), page, text_contrast},
        {"plot labels on the page", rgb(plot.label), page, text_contrast},
        {"plot axes on the page", rgb(plot.axis), page, mark_contrast},
        {"plot curve on the page", rgb(plot.curve), page, mark_contrast},
        {"wall against the page", rgb(p.wall), page, mark_contrast},
        {"wall against the box", rgb(p.wall), box, mark_contrast},
        {"dashed periodic edge against the page", rgb(p.wrap_edge), page, mark_contrast},
        {"dashed periodic edge against the box", rgb(p.wrap_edge), box, mark_contrast},
        {"disc outline on the box", rgb(p.outline), box, mark_contrast},
        {"failure mark on the box", rgb(p.failure), box, mark_contrast},
        {"fading failure ring at its faintest", blend(rgb(p.failure), box, mark_floor(theme)), box,
         mark_contrast},
        {"legend symbol on the page", rgb(p.failure), page, mark_contrast},
        {"queue labels on a box plate", rgb(p.text), box, text_contrast},
        {"muted queue labels on a box plate", rgb(p.muted), box, text_contrast},
        {"queue: the next event's label on the page", next_event_color(theme), page, text_contrast},
        {"queue: the next event's label on a box plate", next_event_color(theme), box,
         text_contrast},
        {"next collision: its thin line on the box", next_event_color(theme), box, mark_contrast},
        {"queue: a queued event's label in the box (text at 75 %)", blend(rgb(p.text), box, 0.75F),
         box, text_contrast},
        {"queue: a slot's time on the page (text at 85 %)", blend(rgb(p.text), page, 0.85F), page,
         text_contrast},
        {"queue: the tree's edges on the page (muted at 80 %)", blend(rgb(p.muted), page, 0.8F),
         page, mark_contrast},
    };
    const CodeColors code = code_colors(p);
    pairs.push_back(
        {"code: the title on its panel", rgb(code.title), rgb(code.panel), text_contrast});
    pairs.push_back({"code: a line on its panel", rgb(code.text), rgb(code.panel), text_contrast});
    pairs.push_back(
        {"code: the current line on its plate", rgb(code.current), rgb(code.plate), text_contrast});
    pairs.push_back({"code: the current line's chevron on the panel", rgb(code.marker),
                     rgb(code.panel), mark_contrast});
    pairs.push_back({"code: the current line's plate edge on the panel", rgb(code.plate_edge),
                     rgb(code.panel), mark_contrast});
    pairs.push_back(
        {"question: a velocity arrow on the box", motion_arrow_color(theme), box, mark_contrast});
    for (int tint = 0; tint < static_cast<int>(candidate_tints); ++tint) {
        // The letter on its plate (the box's colour), the line on the box.
        pairs.push_back({"question: a candidate's letter on its plate",
                         candidate_color(tint, theme), box, text_contrast});
    }
    for (const bool time_driven : {true, false}) {
        const Rgb8 accent = panel_accent(time_driven, theme);
        pairs.push_back({time_driven ? "time-driven cost label on the page"
                                     : "event-driven cost label on the page",
                         accent_text(accent, theme), page, text_contrast});
        pairs.push_back({time_driven ? "time-driven bar and curve on the page"
                                     : "event-driven bar and curve on the page",
                         accent, page, mark_contrast});
    }
    return pairs;
}

std::vector<ColorPair> heap_color_pairs(Theme theme) {
    const HeapPalette p = heap_palette(theme);
    const Rgb8 page = rgb(p.background);
    const Rgb8 panel = rgb(p.panel);
    std::vector<ColorPair> pairs = {
        {"heap: operations to come on the page", rgb(p.token_todo), page, text_contrast},
        {"heap: operations done on the page", rgb(p.token_done), page, text_contrast},
        {"heap: the operation under way on its tab", rgb(highlight_dark_text),
         rgb(heap_token_now_fill), text_contrast},
        {"heap: title on the panel", rgb(p.title), panel, text_contrast},
        {"heap: counters on the panel", rgb(p.counter), panel, text_contrast},
        {"heap: caption on the panel", rgb(p.caption), panel, text_contrast},
        {"heap: map heading on the panel", rgb(p.map_header), panel, text_contrast},
        {"heap: slot indices and 'sorted' on the panel", rgb(p.index), panel, text_contrast},
        {"heap: map keys on the panel", rgb(p.title), panel, text_contrast},
        {"heap: a map entry being updated, on its tab", rgb(heap_map_update_text),
         rgb(heap_mark_style(view::SlotMark::moving, p).fill), text_contrast},
        {"heap: a plain key in its slot", rgb(p.title), rgb(p.slot), large_text_contrast},
        {"heap: a plain key in its node", rgb(p.title), rgb(p.node), large_text_contrast},
        {"heap: a sorted key in its slot", rgb(p.sorted_text), rgb(p.sorted_fill),
         large_text_contrast},
        {"heap: a key in an empty slot (the page's colour)", rgb(p.title), page,
         large_text_contrast},
        {"heap: tree edges on the panel", rgb(p.edge), panel, mark_contrast},
        {"heap: node outlines on the panel", rgb(p.node_outline), panel, mark_contrast},
        {"heap: slot outlines on the panel", rgb(p.slot_outline), panel, mark_contrast},
    };
    const CodeColors code = heap_code_colors(p);
    const Rgb8 code_panel = rgb(code.panel);
    pairs.push_back(
        {"heap code: the title on its panel", rgb(code.title), code_panel, text_contrast});
    pairs.push_back({"heap code: a line on its panel", rgb(code.text), code_panel, text_contrast});
    pairs.push_back({"heap code: the current line on its plate", rgb(code.current), rgb(code.plate),
                     text_contrast});
    pairs.push_back({"heap code: the current line's chevron on the panel", rgb(code.marker),
                     code_panel, mark_contrast});
    // The plate must stand out from the panel too: it is the bar the eye finds first.
    pairs.push_back({"heap code: the current line's plate edge on the panel", rgb(code.plate_edge),
                     code_panel, mark_contrast});
    for (const view::SlotMark mark :
         {view::SlotMark::compared, view::SlotMark::moving, view::SlotMark::inserted,
          view::SlotMark::changed, view::SlotMark::best, view::SlotMark::leaving,
          view::SlotMark::sinking}) {
        const KeyStyle style = heap_mark_style(mark, p);
        pairs.push_back({"heap: a highlighted key on its fill", rgb(style.text), rgb(style.fill),
                         large_text_contrast});
        pairs.push_back({"heap: a lit tree edge on the panel", rgb(heap_lit_edge(mark, p)), panel,
                         mark_contrast});
    }
    return pairs;
}

std::vector<ColorPair> puzzle_color_pairs(Theme theme) {
    const PuzzlePalette p = puzzle_palette(theme);
    const Rgb8 page = rgb(p.background);
    const Rgb8 panel = rgb(p.panel);
    const Rgb8 queue = rgb(p.queue_fill);
    std::vector<ColorPair> pairs = {
        {"puzzle: heading on the page", rgb(p.title), page, text_contrast},
        {"puzzle: title, rows and caption on the panel", rgb(p.title), panel, text_contrast},
        {"puzzle: counters on the panel", rgb(p.counter), panel, text_contrast},
        {"puzzle: status on the panel", rgb(p.status), panel, text_contrast},
        {"puzzle: board labels on the panel", rgb(p.label), panel, text_contrast},
        {"puzzle: the queue's title and labels on its fill", rgb(p.title), queue, text_contrast},
        {"puzzle: '+N more' on the queue's fill", rgb(p.label), queue, text_contrast},
        {"puzzle: tile numbers", rgb(p.tile_text), rgb(p.tile), text_contrast},
        {"puzzle: a sliding tile's number", rgb(p.tile_text), rgb(p.sliding_tile), text_contrast},
        {"puzzle: tree edges on the panel", rgb(p.edge), panel, mark_contrast},
    };
    // A board reads by its outer edge: its light tiles on a dark page, its dark frame on a light
    // one; whichever stands out more must keep 3:1.
    for (const Rgb8 under : {panel, queue}) {
        const Rgb8 edge = contrast_ratio(rgb(p.tile), under) >= contrast_ratio(rgb(p.blank), under)
                              ? rgb(p.tile)
                              : rgb(p.blank);
        pairs.push_back(
            {"puzzle: a board's outer edge (tiles or frame)", edge, under, mark_contrast});
    }
    for (const view::PuzzleMark mark :
         {view::PuzzleMark::current, view::PuzzleMark::goal, view::PuzzleMark::solution}) {
        const Rgb8 frame = rgb(puzzle_mark_color(mark, p));
        pairs.push_back(
            {"puzzle: a marked board's frame on the panel", frame, panel, mark_contrast});
        pairs.push_back(
            {"puzzle: a marked board's frame on the queue's fill", frame, queue, mark_contrast});
    }
    const CodeColors code = puzzle_code_colors(p);
    const Rgb8 code_panel = rgb(code.panel);
    pairs.push_back(
        {"puzzle code: the title on its panel", rgb(code.title), code_panel, text_contrast});
    pairs.push_back(
        {"puzzle code: a line on its panel", rgb(code.text), code_panel, text_contrast});
    pairs.push_back({"puzzle code: the current line on its plate", rgb(code.current),
                     rgb(code.plate), text_contrast});
    pairs.push_back({"puzzle code: the current line's chevron on the panel", rgb(code.marker),
                     code_panel, mark_contrast});
    pairs.push_back({"puzzle code: the current line's plate edge on the panel",
                     rgb(code.plate_edge), code_panel, mark_contrast});
    return pairs;
}

}  // namespace collide::render
