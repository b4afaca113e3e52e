#include "collide/show/heap_program.hpp"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <utility>

#include "collide/error.hpp"
#include "collide/show/ease.hpp"
#include "collide/show/heap_code.hpp"

namespace collide::show {

namespace {

using pq::HeapOp;
using pq::HeapStep;
using pq::QueueFamily;
using view::SlotMark;

// ------------------------------------------------------------------------------------ captions

std::string slot_name(std::size_t i, int base) {
    return "a[" + std::to_string(static_cast<long long>(i) + base) + "]";
}

/// "<", ">" or "=" for a step's order (< 0, > 0, 0).
const char* relation(int order) {
    if (order < 0) return "<";
    if (order > 0) return ">";
    return "=";
}

std::string plural(std::uint64_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

/// What an operation is called while it runs.
std::string op_prefix(const HeapOp& op, pq::Orientation orientation) {
    switch (op.kind) {
        case HeapOp::Kind::insert:
            return "insert " + op.key.text();
        case HeapOp::Kind::remove:
            return orientation == pq::Orientation::max ? "remove max" : "remove min";
        case HeapOp::Kind::increase:
            return "increase " + op.key.text() + " to " + op.new_key.text();
        case HeapOp::Kind::build:
            return "build the heap";
        case HeapOp::Kind::sortdown:
            return "sortdown";
    }
    return "";
}

/// What an operation is called in its summary.
std::string op_summary_head(const HeapOp& op, const pq::PanelOp& done,
                            pq::Orientation orientation) {
    switch (op.kind) {
        case HeapOp::Kind::remove:
            return op_prefix(op, orientation) + " " + done.removed;
        case HeapOp::Kind::build:
            return "heap built";
        case HeapOp::Kind::sortdown:
            return "sortdown done";
        default:
            return op_prefix(op, orientation);
    }
}

/// Words for one panel's steps, operation by operation, in the record's order: it keeps what a
/// caption refers back to (the operation's name with the slot an insert landed in, the key a
/// sink moves down, the key before an increase-key).
class Captioner {
  public:
    Captioner(const pq::HeapPanel& panel, pq::Orientation orientation, int base)
        : panel_(panel), max_(orientation == pq::Orientation::max), base_(base) {}

    HeapProgram::OpText op(const HeapOp& op, const pq::PanelOp& done,
                           const pq::ArrayState& before) {
        op_ = op.kind;
        prefix_ = op_prefix(op, max_ ? pq::Orientation::max : pq::Orientation::min);
        sinking_.reset();
        HeapProgram::OpText text;
        for (std::size_t s = 0; s < done.steps.size(); ++s) {
            const bool first = text.shown.empty();
            std::optional<std::string> caption = step(done.steps[s], first);
            if (!caption) continue;
            text.shown.push_back(s);
            text.captions.push_back(std::move(*caption));
        }
        const std::uint64_t c = done.end.compares - before.compares;
        const std::uint64_t x = done.end.exchanges - before.exchanges;
        text.summary =
            op_summary_head(op, done, max_ ? pq::Orientation::max : pq::Orientation::min) + ": " +
            plural(c, "compare", "compares") + ", " +
            plural(x, panel_.shifts ? "shift" : "exchange", panel_.shifts ? "shifts" : "exchanges");
        if (op.kind == HeapOp::Kind::sortdown) {
            // The last words of a heapsort: the totals the counters show, so that the screen
            // never holds two different totals.
            text.summary +=
                "; heapsort in all: " + plural(done.end.compares, "compare", "compares") + ", " +
                plural(done.end.exchanges, "exchange", "exchanges");
        }
        return text;
    }

  private:
    [[nodiscard]] const char* top_word() const { return max_ ? "max" : "min"; }
    [[nodiscard]] const char* child_word() const { return max_ ? "larger" : "smaller"; }
    /// Whether a key that orders `order` against another comes out before it.
    [[nodiscard]] bool comes_first(int order) const { return max_ ? order > 0 : order < 0; }
    [[nodiscard]] static std::string vs(const std::string& a, const std::string& b, int order) {
        return a + " " + relation(order) + " " + b;
    }
    [[nodiscard]] std::size_t parent(std::size_t i) const { return (i - 1) / panel_.arity; }
    [[nodiscard]] std::string slot(std::size_t i) const { return slot_name(i, base_); }

    /// The caption of a step, or none for a step not shown (a sortdown's sinks: its exchange
    /// says which key sinks).
    std::optional<std::string> step(const HeapStep& s, bool first) {
        const std::vector<std::string>& keys = s.state.keys;
        switch (s.kind) {
            case HeapStep::Kind::appear:
                prefix_ += " at " + slot(s.i);
                return prefix_ + (panel_.kind.family == QueueFamily::unordered
                                      ? ", the end: nothing else to do"
                                      : "");
            case HeapStep::Kind::change:
                changed_from_ = s.from;
                return prefix_ + ": qp[] says " + s.from + " is at " + slot(s.i) + "; set " +
                       slot(s.i) + " = " + keys[s.i];
            case HeapStep::Kind::compare:
                return compare(s.i, s.j, keys[s.i], keys[s.j], s.order);
            case HeapStep::Kind::shift:
                return prefix_ + "; shift " + keys[s.i] + " right to " + slot(s.j);
            case HeapStep::Kind::exchange:
                return exchange(s.i, s.j, keys, first);
            case HeapStep::Kind::remove:
                return prefix_ + ": " + keys[s.i] + " leaves " + slot(s.i);
            case HeapStep::Kind::sink:
                sinking_ = keys[s.i];
                if (op_ != HeapOp::Kind::build) return std::nullopt;
                return "build the heap: sink " + keys[s.i] + " at " + slot(s.i);
        }
        return std::nullopt;
    }

    std::string compare(std::size_t i, std::size_t j, const std::string& a, const std::string& b,
                        int order) const {
        switch (panel_.kind.family) {
            case QueueFamily::unordered:
                // best_index: slot i against the best so far, j.
                return std::string("scan for the ") + top_word() + ": " + vs(a, b, order) +
                       (comes_first(order) ? ", new " + std::string(top_word()) + " " + a : "");
            case QueueFamily::ordered:
                // The key being inserted (slot i) against its left neighbour (slot j).
                return prefix_ + "; " + vs(b, a, -order) +
                       (comes_first(-order) ? ": shift " + b + " right"
                                            : ": stop, " + a + " stays at " + slot(i));
            default:
                break;
        }
        if (i == j) {  // increase-key: the new key against the old one
            return prefix_ + "; " + vs(a, changed_from_, order) +
                   (max_ ? ": a larger key may have to swim up"
                         : ": a larger key may have to sink");
        }
        const bool siblings = i > 0 && j > 0 && parent(i) == parent(j);
        if (siblings) {
            const std::string who = sinking_ ? "sink " + *sinking_ + ": " : "";
            return prefix_ + "; " + who + child_word() + " child? " + vs(a, b, order);
        }
        // i is the moving key; j its parent (swim) or its best child (sink).
        const bool up = j < i;
        const bool moves = up ? comes_first(order) : comes_first(-order);
        const std::string who = !up && sinking_ ? "sink " + *sinking_ + ": " : "";
        return prefix_ + "; " + who + vs(a, b, order) + (moves ? ": exchange" : ": stop");
    }

    std::string exchange(std::size_t i, std::size_t j, const std::vector<std::string>& keys,
                         bool first) {
        const std::string& a = keys[i];
        const std::string& b = keys[j];
        if (panel_.kind.family == QueueFamily::unordered) {
            return i == j ? std::string("remove ") + top_word() + ": " + a + " is already last"
                          : std::string("remove ") + top_word() + ": exchange " + a +
                                " with the last, " + b;
        }
        if (op_ == HeapOp::Kind::sortdown && i == 0) {
            sinking_ = b;
            return "sortdown: exchange " + std::string(top_word()) + " " + a + " with " + b +
                   " at " + slot(j) + "; " + a + " is in place";
        }
        if (i == j) return prefix_ + ": " + a + " is the only item";
        if (i == 0 && j + 1 == keys.size() && first) {
            sinking_ = b;
            return prefix_ + ": exchange the root " + a + " with the last, " + b;
        }
        return prefix_ + "; exchange " + a + " and " + b;
    }

    const pq::HeapPanel& panel_;
    bool max_;
    int base_;
    HeapOp::Kind op_ = HeapOp::Kind::insert;
    std::string prefix_;
    std::optional<std::string> sinking_;  ///< the key a sink moves down
    std::string changed_from_;            ///< increase-key: the key before
};

// ------------------------------------------------------------------------------------ frames

/// Fractions of a step: a slide or a fade takes the first part, the rest holds still so the
/// class sees where things landed before the next step.
constexpr double slide_part = 0.8;
constexpr double fade_part = 0.5;

double part(double progress, double fraction) noexcept {
    return std::clamp(progress / fraction, 0.0, 1.0);
}

void mark_step(const HeapStep& step, double progress, view::HeapPanelView& view) {
    auto& slots = view.slots;
    const auto mark = [&](std::size_t i, SlotMark m) {
        if (i < slots.size()) slots[i].mark = m;
    };
    switch (step.kind) {
        case HeapStep::Kind::appear:
            mark(step.i, SlotMark::inserted);
            view.fade = ease(part(progress, fade_part));
            break;
        case HeapStep::Kind::compare:
            mark(step.i, SlotMark::compared);
            mark(step.j, SlotMark::compared);
            break;
        case HeapStep::Kind::exchange:
        case HeapStep::Kind::shift:
            mark(step.i, SlotMark::moving);
            mark(step.j, SlotMark::moving);
            if (step.i != step.j)
                view.swap = view::HeapSwapView{step.i, step.j, ease(part(progress, slide_part))};
            break;
        case HeapStep::Kind::remove:
            mark(step.i, SlotMark::leaving);
            view.fade = 1.0F - ease(part(progress, slide_part));
            break;
        case HeapStep::Kind::change:
            mark(step.i, SlotMark::changed);
            break;
        case HeapStep::Kind::sink:
            mark(step.i, SlotMark::sinking);
            break;
    }
    // The unordered array's scan keeps its max so far in view.
    if (step.best && step.kind == HeapStep::Kind::compare) mark(*step.best, SlotMark::best);
}

std::vector<view::HeapMapRow> map_rows(const pq::ArrayState& state, int index_base,
                                       const std::optional<view::HeapSwapView>& swap) {
    std::vector<std::pair<std::size_t, std::size_t>> by_handle;  // (handle, slot)
    for (std::size_t i = 0; i < state.handles.size(); ++i)
        by_handle.emplace_back(state.handles[i], i);
    std::sort(by_handle.begin(), by_handle.end());
    std::vector<view::HeapMapRow> rows;
    for (const auto& [handle, slot] : by_handle) {
        view::HeapMapRow row;
        row.key = state.keys[slot];
        row.updated = swap && (slot == swap->a || slot == swap->b);
        // Once the keys have landed (the step's rest), the lit entries show where they are now:
        // the picture at rest never contradicts the array.
        std::size_t shown = slot;
        if (row.updated && swap->t >= 1.0F) shown = slot == swap->a ? swap->b : swap->a;
        row.index = std::to_string(static_cast<long long>(shown) + index_base);
        rows.push_back(std::move(row));
    }
    return rows;
}

}  // namespace

HeapPacing heap_pacing(double pace) noexcept {
    HeapPacing pacing;
    pacing.pace = pace;
    pacing.pause = 0.6 * pace;
    pacing.intro = std::max(1.0, 1.5 * pace);
    pacing.outro = std::max(2.5, 3.0 * pace);
    return pacing;
}

std::string panel_title(const pq::QueueKind& kind) {
    switch (kind.family) {
        case QueueFamily::unordered:
            return "unordered array";
        case QueueFamily::ordered:
            return "ordered array";
        case QueueFamily::binary:
            return "binary heap";
        case QueueFamily::dary:
            return kind.d == 2 ? "binary heap" : std::to_string(kind.d) + "-heap";
        case QueueFamily::indexed:
            return "indexed " +
                   (kind.d == 2 ? std::string("binary heap") : std::to_string(kind.d) + "-heap");
    }
    return to_string(kind);
}

HeapProgram::HeapProgram(pq::HeapRecord record, HeapPacing pacing, int index_base)
    : record_(std::move(record)), pacing_(pacing), index_base_(index_base) {
    if (!(pacing.pace > 0.0) || pacing.pause < 0.0 || pacing.intro < 0.0 || pacing.outro < 0.0)
        throw_input_error("pace: must be > 0");
    const bool max = record_.orientation() == pq::Orientation::max;
    const std::vector<HeapOp>& ops = record_.ops();
    for (const HeapOp& op : ops) {
        switch (op.kind) {
            case HeapOp::Kind::build:
                labels_.emplace_back("build");
                break;
            case HeapOp::Kind::sortdown:
                labels_.emplace_back("sortdown");
                break;
            default:
                labels_.push_back(op.spelling);
                break;
        }
    }
    for (const pq::HeapPanel& panel : record_.panels()) {
        PanelText text;
        if (record_.heapsort()) {
            text.title = "heapsort";
            text.start = "heapsort " + std::to_string(panel.start.keys.size()) + " keys " +
                         (max ? "into ascending order" : "into descending order");
        } else {
            text.title = panel_title(panel.kind);
            text.start = text.title + (max ? ", max" : ", min") + "-oriented: empty";
        }
        Captioner captioner(panel, record_.orientation(), index_base_);
        const pq::ArrayState* before = &panel.start;
        for (std::size_t k = 0; k < ops.size(); ++k) {
            text.ops.push_back(captioner.op(ops[k], panel.ops[k], *before));
            before = &panel.ops[k].end;
        }
        text_.push_back(std::move(text));
    }

    double t = pacing.intro;
    for (std::size_t k = 0; k < ops.size(); ++k) {
        op_start_.push_back(t);
        std::size_t steps = 0;
        for (const PanelText& p : text_) steps = std::max(steps, p.ops[k].shown.size());
        t += static_cast<double>(steps) * pacing.pace + pacing.pause;
    }
    op_start_.push_back(t);  // the outro starts here
}

std::string HeapProgram::name() const {
    std::string out;
    for (const PanelText& p : text_) out += (out.empty() ? "" : ", ") + p.title;
    return out;
}

double HeapProgram::duration() const noexcept {
    return op_start_.back() + pacing_.outro;
}

HeapMoment HeapProgram::moment_at(double seconds) const {
    HeapMoment moment;
    seconds = std::clamp(seconds, 0.0, duration());
    const std::vector<pq::HeapPanel>& panels = record_.panels();
    // The operation under way: the last one started at or before `seconds`.
    const auto after = std::upper_bound(op_start_.begin(), op_start_.end() - 1, seconds);
    if (after == op_start_.begin()) {
        moment.op = labels_.size();
        for (std::size_t p = 0; p < panels.size(); ++p)
            moment.panels.push_back({&panels[p].start, nullptr, 0.0, &text_[p].start});
        return moment;
    }
    moment.started = true;
    moment.finished = seconds >= op_start_.back();
    moment.op = static_cast<std::size_t>(after - op_start_.begin()) - 1;
    const double into = seconds - op_start_[moment.op];
    const auto step = static_cast<std::size_t>(into / pacing_.pace);
    for (std::size_t p = 0; p < panels.size(); ++p) {
        const pq::PanelOp& op = panels[p].ops[moment.op];
        const OpText& text = text_[p].ops[moment.op];
        if (step < text.shown.size()) {
            const double progress = into / pacing_.pace - static_cast<double>(step);
            const pq::HeapStep& s = op.steps[text.shown[step]];
            moment.panels.push_back({&s.state, &s, progress, &text.captions[step]});
        } else {
            moment.panels.push_back({&op.end, nullptr, 0.0, &text.summary});
        }
    }
    return moment;
}

view::HeapPanelView HeapProgram::panel_view(std::size_t panel,
                                            const HeapPanelMoment& moment) const {
    const pq::HeapPanel& record = record_.panels()[panel];
    const pq::ArrayState& state = *moment.state;
    const bool min = record_.orientation() == pq::Orientation::min;
    const bool sort = record_.heapsort();
    const std::string& title = text_[panel].title;
    view::HeapPanelView view;
    view.title = sort ? title + (min ? " (descending)" : " (ascending)")
                      : title + (min ? " (min)" : " (max)");
    view.counters = {{"compares", std::to_string(state.compares)},
                     {record.shifts ? "shifts" : "exchanges", std::to_string(state.exchanges)}};
    view.sorted_label = "sorted";
    view.caption = *moment.caption;
    view.tree = record.tree;
    view.arity = std::max(record.arity, 2U);
    view.capacity = record_.capacity();
    view.index_base = index_base_;
    for (const std::string& key : state.keys) view.slots.push_back({key, SlotMark::plain});
    if (sort) view.heap_size = state.heap_size;
    if (moment.step != nullptr) mark_step(*moment.step, moment.progress, view);
    view.show_map = record.kind.family == QueueFamily::indexed;
    if (view.show_map) {
        // IndexMinPQ's names: keys[i] is the key of handle i, qp[i] the slot of pq[] it is in.
        view.map_title = "keys[i] / qp[i]";
        view.map = map_rows(state, index_base_, view.swap);
    }
    return view;
}

view::HeapFrameView HeapProgram::frame_at(double seconds) const {
    const HeapMoment moment = moment_at(seconds);
    view::HeapFrameView view;
    view.tokens = labels_;
    if (moment.finished) {
        view.current_token = view.tokens.size();  // all done, none under way
    } else if (moment.started) {
        view.current_token = moment.op;
    }
    for (std::size_t p = 0; p < moment.panels.size(); ++p) {
        view.panels.push_back(panel_view(p, moment.panels[p]));
        view.panels.back().returned = returned(p, moment);
    }
    if (code_) view.code = code_at(moment);
    return view;
}

void HeapProgram::show_code(bool on) {
    if (on && !heap_code_fits(record_))
        throw_input_error("code: shows the code of one heap; give a single heap implementation");
    code_ = on;
}

std::vector<view::CodeLineView> HeapProgram::code_lines() const {
    std::vector<view::CodeLineView> out;
    std::vector<HeapOp::Kind> seen;
    for (const HeapOp& op : record_.ops()) {
        if (std::find(seen.begin(), seen.end(), op.kind) != seen.end()) continue;
        seen.push_back(op.kind);
        for (view::CodeLineView& line : heap_code(op.kind, record_.orientation()))
            out.push_back(std::move(line));
    }
    return out;
}

view::CodeView HeapProgram::code_at(const HeapMoment& moment) const {
    const std::vector<HeapOp>& ops = record_.ops();
    view::CodeView code;
    code.title = "pseudocode";
    if (ops.empty()) return code;
    // The intro shows the first operation's listing; the outro keeps the last one's.
    const std::size_t op = std::min(moment.started ? moment.op : 0, ops.size() - 1);
    code.lines = heap_code(ops[op].kind, record_.orientation());
    if (!moment.started || moment.panels.empty() || moment.panels.front().step == nullptr)
        return code;
    const pq::PanelOp& done = record_.panels().front().ops[op];
    const auto s = static_cast<std::size_t>(moment.panels.front().step - done.steps.data());
    code.current =
        heap_code_line(record_.panels().front(), ops[op].kind, record_.orientation(), done, s);
    return code;
}

view::ReturnedKeys HeapProgram::returned(std::size_t panel, const HeapMoment& moment) const {
    const std::vector<HeapOp>& ops = record_.ops();
    const bool removes = std::any_of(
        ops.begin(), ops.end(), [](const HeapOp& op) { return op.kind == HeapOp::Kind::remove; });
    if (!removes || record_.heapsort()) return {};
    // An operation's key counts as returned once its steps are done (its summary is shown).
    const bool op_done = moment.started && moment.panels[panel].step == nullptr;
    const std::size_t done = !moment.started ? 0 : moment.op + (op_done ? 1 : 0);
    view::ReturnedKeys out{"returned:", {}};
    for (std::size_t k = 0; k < std::min(done, ops.size()); ++k) {
        if (ops[k].kind != HeapOp::Kind::remove) continue;
        out.keys.push_back(record_.panels()[panel].ops[k].removed);
    }
    if (out.keys.empty()) out.keys.push_back("-");
    return out;
}

std::vector<std::string> HeapProgram::keys() const {
    std::vector<std::string> out;
    const auto consider = [&](const pq::ArrayState& s) {
        for (const std::string& k : s.keys) {
            if (std::find(out.begin(), out.end(), k) == out.end()) out.push_back(k);
        }
    };
    for (const pq::HeapPanel& panel : record_.panels()) {
        consider(panel.start);
        for (const pq::PanelOp& op : panel.ops) {
            for (const pq::HeapStep& step : op.steps) consider(step.state);
            consider(op.end);
        }
    }
    return out;
}

std::string HeapProgram::widest_key() const {
    std::string widest = "W";
    const auto consider = [&](const pq::ArrayState& s) {
        for (const std::string& k : s.keys) {
            if (k.size() > widest.size()) widest = k;
        }
    };
    for (const pq::HeapPanel& panel : record_.panels()) {
        consider(panel.start);
        for (const pq::PanelOp& op : panel.ops) {
            for (const pq::HeapStep& step : op.steps) consider(step.state);
            consider(op.end);
        }
    }
    return widest;
}

}  // namespace collide::show
