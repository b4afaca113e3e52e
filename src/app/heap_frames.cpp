#include "heap_frames.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace collide::app {

namespace {

using pq::LessonStep;
using render::SlotMark;

/// Fractions of a step: a slide or a fade takes the first part, the rest holds still so the
/// class sees where things landed before the next step.
constexpr double slide_part = 0.8;
constexpr double fade_part = 0.5;

double part(double progress, double fraction) noexcept {
    return std::clamp(progress / fraction, 0.0, 1.0);
}

void mark_step(const LessonStep& step, double progress, render::HeapPanelView& view) {
    auto& slots = view.slots;
    const auto mark = [&](std::size_t i, SlotMark m) {
        if (i < slots.size()) slots[i].mark = m;
    };
    switch (step.kind) {
        case LessonStep::Kind::appear:
            mark(step.i, SlotMark::inserted);
            view.fade = ease(part(progress, fade_part));
            break;
        case LessonStep::Kind::compare:
            mark(step.i, SlotMark::compared);
            mark(step.j, SlotMark::compared);
            break;
        case LessonStep::Kind::exchange:
            mark(step.i, SlotMark::moving);
            mark(step.j, SlotMark::moving);
            if (step.i != step.j)
                view.swap = render::HeapSwapView{step.i, step.j, ease(part(progress, slide_part))};
            break;
        case LessonStep::Kind::remove:
            mark(step.i, SlotMark::leaving);
            view.fade = 1.0F - ease(part(progress, slide_part));
            break;
        case LessonStep::Kind::change:
            mark(step.i, SlotMark::changed);
            break;
        case LessonStep::Kind::sink:
            mark(step.i, SlotMark::sinking);
            break;
    }
    // The unordered array's scan keeps its max so far in view.
    if (step.best && step.kind == LessonStep::Kind::compare) mark(*step.best, SlotMark::best);
}

std::vector<render::HeapMapRow> map_rows(const pq::LessonState& state, const HeapShow& show,
                                         const std::optional<render::HeapSwapView>& swap) {
    std::vector<std::pair<std::size_t, std::size_t>> by_handle;  // (handle, slot)
    for (std::size_t i = 0; i < state.handles.size(); ++i)
        by_handle.emplace_back(state.handles[i], i);
    std::sort(by_handle.begin(), by_handle.end());
    std::vector<render::HeapMapRow> rows;
    for (const auto& [handle, slot] : by_handle) {
        render::HeapMapRow row;
        row.key = state.keys[slot];
        row.updated = swap && (slot == swap->a || slot == swap->b);
        // Once the keys have landed (the step's rest), the lit entries show where they are now:
        // the picture at rest never contradicts the array.
        std::size_t shown = slot;
        if (row.updated && swap->t >= 1.0F) shown = slot == swap->a ? swap->b : swap->a;
        row.index = std::to_string(static_cast<long long>(shown) + show.index_base);
        rows.push_back(std::move(row));
    }
    return rows;
}

render::HeapPanelView panel_view(const pq::LessonTimeline& timeline, const pq::LessonPanel& panel,
                                 const pq::LessonPanelFrame& frame, const HeapShow& show) {
    const pq::LessonState& state = *frame.state;
    render::HeapPanelView view;
    view.title = show.sort ? panel.title + (show.min ? " (descending)" : " (ascending)")
                           : panel.title + (show.min ? " (min)" : " (max)");
    view.counters = {"compares " + std::to_string(state.compares),
                     (panel.shifts ? "shifts " : "exchanges ") + std::to_string(state.exchanges)};
    view.caption = state.caption;
    view.tree = panel.tree;
    view.arity = std::max(panel.arity, 2U);
    view.capacity = timeline.capacity();
    view.index_base = show.index_base;
    for (const std::string& key : state.keys) view.slots.push_back({key, SlotMark::plain});
    if (show.sort) view.heap_size = state.heap_size;
    if (frame.step != nullptr) mark_step(*frame.step, frame.progress, view);
    view.show_map = panel.kind.family == pq::QueueFamily::indexed;
    if (view.show_map) view.map = map_rows(state, show, view.swap);
    return view;
}

}  // namespace

float ease(double x) noexcept {
    const double t = std::clamp(x, 0.0, 1.0);
    return static_cast<float>(t * t * (3.0 - 2.0 * t));
}

render::HeapFrameView heap_frame_at(const pq::LessonTimeline& timeline, const HeapShow& show,
                                    double seconds) {
    const pq::LessonFrame frame = timeline.frame_at(seconds);
    render::HeapFrameView view;
    view.tokens = timeline.op_labels();
    if (frame.finished) {
        view.current_token = view.tokens.size();  // all done, none under way
    } else if (frame.started) {
        view.current_token = frame.op;
    }
    for (std::size_t p = 0; p < frame.panels.size(); ++p) {
        view.panels.push_back(panel_view(timeline, timeline.panels()[p], frame.panels[p], show));
    }
    return view;
}

std::string widest_key(const pq::LessonTimeline& timeline) {
    std::string widest = "W";
    const auto consider = [&](const pq::LessonState& s) {
        for (const std::string& k : s.keys) {
            if (k.size() > widest.size()) widest = k;
        }
    };
    for (const pq::LessonPanel& panel : timeline.panels()) {
        consider(panel.start);
        for (const pq::LessonPanelOp& op : panel.ops) {
            for (const pq::LessonStep& step : op.steps) consider(step.state);
            consider(op.end);
        }
    }
    return widest;
}

}  // namespace collide::app
