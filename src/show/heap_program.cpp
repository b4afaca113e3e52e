#include "collide/show/heap_program.hpp"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <utility>

#include "collide/error.hpp"
#include "collide/show/ease.hpp"
#include "collide/show/heap_code.hpp"
#include "collide/show/questions.hpp"

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

// ------------------------------------------------------------------------------------ questions

/// A question's chapter (from its operation's start to the reveal) lasts at least this long, so
/// that a heap video's chapters stay at least 4 s apart (chapters.hpp).
constexpr double question_chapter_seconds = 4.0;
/// The think time when the operation leaves room: long enough for a class to look at every
/// letter.
constexpr double think_seconds = 3.0;

/// splitmix64: a letter order that is the same on every platform (std::shuffle's is not).
std::uint64_t mix(std::uint64_t& state) {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30U)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27U)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31U);
}

/// Whether the lesson shows step `s` of an operation of kind `op` (the Captioner's rule: a
/// sink's start is only shown while building the heap).
bool shown_step(const HeapStep& s, HeapOp::Kind op) {
    return s.kind != HeapStep::Kind::sink || op == HeapOp::Kind::build;
}

/// Where a key that starts at `from` before step `first` of `steps` ends, following the
/// recorded exchanges; `path` gets every slot it passes, `from` first.
std::size_t follow(const std::vector<HeapStep>& steps, std::size_t first, std::size_t from,
                   std::vector<std::size_t>& path) {
    std::size_t at = from;
    path = {from};
    for (std::size_t s = first; s < steps.size(); ++s) {
        const HeapStep& step = steps[s];
        if (step.kind != HeapStep::Kind::exchange || step.i == step.j) continue;
        if (step.i == at) {
            at = step.j;
        } else if (step.j == at) {
            at = step.i;
        } else {
            continue;
        }
        path.push_back(at);
    }
    return at;
}

/// Candidate slots, the answer first: for a swim the slots on the way to the root nearest the
/// answer; for a sink the slots passed, the answer's children (had it gone on) and its sibling
/// (had the other child been larger). `size`: the heap's keys while K moves.
std::vector<std::size_t> candidate_slots(std::size_t answer, std::size_t from,
                                         const std::vector<std::size_t>& path, bool swim,
                                         unsigned arity, std::size_t size) {
    std::vector<std::size_t> pool;
    const auto add = [&](std::size_t slot) {
        if (slot < size && std::find(pool.begin(), pool.end(), slot) == pool.end())
            pool.push_back(slot);
    };
    add(answer);
    if (swim) {
        // The slots from `from` up to the root, in order; the answer's neighbours on it first.
        std::vector<std::size_t> chain{from};
        while (chain.back() > 0) chain.push_back((chain.back() - 1) / arity);
        const auto at =
            static_cast<std::size_t>(std::find(chain.begin(), chain.end(), answer) - chain.begin());
        for (std::size_t d = 1; d < chain.size(); ++d) {
            if (at >= d) add(chain[at - d]);
            if (at + d < chain.size()) add(chain[at + d]);
        }
    } else {
        const auto children = [&](std::size_t i) {
            std::vector<std::size_t> out;
            for (std::size_t c = arity * i + 1; c <= arity * i + arity && c < size; ++c)
                out.push_back(c);
            return out;
        };
        const std::vector<std::size_t> below = children(answer);
        std::vector<std::size_t> beside;
        if (answer > 0) {
            for (const std::size_t c : children((answer - 1) / arity))
                if (c != answer) beside.push_back(c);
        }
        // One of each kind first, so that every kind of mistake has its letter.
        if (path.size() >= 2) add(path[path.size() - 2]);
        if (!below.empty()) add(below.front());
        if (!beside.empty()) add(beside.front());
        for (auto it = path.rbegin(); it != path.rend(); ++it) add(*it);
        for (const std::size_t c : below) add(c);
        for (const std::size_t c : beside) add(c);
    }
    if (pool.size() > max_candidates) pool.resize(max_candidates);
    return pool;
}

/// "A, B or C".
std::string letters_list(std::size_t n) {
    std::string out;
    for (std::size_t i = 0; i < n; ++i) {
        if (i > 0) out += i + 1 == n ? " or " : ", ";
        out += candidate_letter(i);
    }
    return out;
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

    lay_out();
}

void HeapProgram::lay_out() {
    op_start_.clear();
    double t = pacing_.intro;
    for (std::size_t k = 0; k < record_.ops().size(); ++k) {
        op_start_.push_back(t);
        std::size_t steps = 0;
        for (const PanelText& p : text_) steps = std::max(steps, p.ops[k].shown.size());
        t += static_cast<double>(steps) * pacing_.pace + pacing_.pause;
        if (const HeapQuestion* q = question_of(k)) t += q->seconds();
    }
    op_start_.push_back(t);  // the outro starts here
}

const HeapQuestion* HeapProgram::question_of(std::size_t op) const noexcept {
    for (const HeapQuestion& q : questions_) {
        if (q.op == op) return &q;
    }
    return nullptr;
}

void HeapProgram::ask_questions(bool on) {
    questions_.clear();
    if (on) questions_ = heap_questions(*this);
    lay_out();
}

double HeapProgram::question_start(std::size_t q) const {
    const HeapQuestion& question = questions_.at(q);
    return op_start_[question.op] + static_cast<double>(question.before) * pacing_.pace;
}

std::vector<HeapQuestion> heap_questions(const HeapProgram& lesson) {
    const pq::HeapRecord& record = lesson.record();
    std::vector<HeapQuestion> out;
    if (record.heapsort()) return out;
    const std::vector<pq::HeapPanel>& panels = record.panels();
    const auto heap =
        std::find_if(panels.begin(), panels.end(), [](const pq::HeapPanel& p) { return p.tree; });
    if (heap == panels.end()) return out;
    const auto panel = static_cast<std::size_t>(heap - panels.begin());
    const bool max = record.orientation() == pq::Orientation::max;
    const double pace = lesson.pacing().pace;
    for (std::size_t k = 0; k < record.ops().size(); ++k) {
        const HeapOp& op = record.ops()[k];
        const pq::PanelOp& done = heap->ops[k];
        // The step that puts K where it starts: its appearance, the remove that leaves the last
        // key at the root, its change. The question holds right after it.
        HeapStep::Kind starter = HeapStep::Kind::appear;
        bool swim = true;
        if (op.kind == HeapOp::Kind::remove) {
            starter = HeapStep::Kind::remove;
            swim = false;
        } else if (op.kind == HeapOp::Kind::increase) {
            starter = HeapStep::Kind::change;
            swim = max;
        } else if (op.kind != HeapOp::Kind::insert) {
            continue;
        }
        const auto it = std::find_if(done.steps.begin(), done.steps.end(),
                                     [&](const HeapStep& s) { return s.kind == starter; });
        if (it == done.steps.end()) continue;
        const auto first = static_cast<std::size_t>(it - done.steps.begin()) + 1;
        std::size_t before = 0;  // shown steps up to and including the starter
        for (std::size_t s = 0; s < first; ++s) before += shown_step(done.steps[s], op.kind);
        const std::size_t size = done.end.keys.size();
        // A remove: the last key, now at the root, sinks; the others: the key at the starter's
        // slot.
        const std::size_t from = op.kind == HeapOp::Kind::remove ? 0 : it->i;
        if (from >= size || before == 0) continue;
        std::vector<std::size_t> path;
        const std::size_t answer = follow(done.steps, first, from, path);
        std::vector<std::size_t> slots =
            candidate_slots(answer, from, path, swim, heap->arity, size);
        if (slots.size() < min_candidates) continue;
        // Letters in an order of their own (the answer's letter tells nothing).
        std::uint64_t state = 0x45ULL * (k + 1);
        for (std::size_t i = slots.size() - 1; i > 0; --i)
            std::swap(slots[i], slots[mix(state) % (i + 1)]);
        HeapQuestion q;
        q.op = k;
        q.panel = panel;
        q.before = before;
        q.key = done.end.keys[answer];
        q.from = from;
        q.answer =
            static_cast<std::size_t>(std::find(slots.begin(), slots.end(), answer) - slots.begin());
        q.candidates = std::move(slots);
        q.think = std::max({min_think_seconds, think_seconds,
                            question_chapter_seconds - static_cast<double>(before) * pace});
        q.reveal = reveal_seconds;
        q.question = "Where does " + q.key + " end up: " + letters_list(q.candidates.size()) + "?";
        q.answer_words = "Answer: " + candidate_letter(q.answer) + ", " + q.key +
                         (answer == from ? " stays at " : " ends up at ") +
                         slot_name(answer, lesson.index_base());
        out.push_back(std::move(q));
    }
    return out;
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
    double into = seconds - op_start_[moment.op];
    if (const HeapQuestion* q = question_of(moment.op)) {
        // The question holds the lesson before its step `before`: every panel at rest on the
        // step before (each panel's own, as in lock-step), then the run goes on.
        const double asked = static_cast<double>(q->before) * pacing_.pace;
        if (into >= asked && into < asked + q->seconds()) {
            moment.question = static_cast<int>(q - questions_.data());
            moment.reveal = into >= asked + q->think;
            moment.think_left = moment.reveal ? 0.0 : asked + q->think - into;
            into = asked - 0.5 * pacing_.pace;  // inside the step before: its progress set below
        } else if (into >= asked + q->seconds()) {
            into -= q->seconds();
        }
    }
    const auto step = static_cast<std::size_t>(into / pacing_.pace);
    for (std::size_t p = 0; p < panels.size(); ++p) {
        const pq::PanelOp& op = panels[p].ops[moment.op];
        const OpText& text = text_[p].ops[moment.op];
        if (step < text.shown.size()) {
            const double progress = moment.question >= 0
                                        ? 1.0  // at rest: where the step left things
                                        : into / pacing_.pace - static_cast<double>(step);
            const pq::HeapStep& s = op.steps[text.shown[step]];
            moment.panels.push_back({&s.state, &s, progress, &text.captions[step]});
        } else {
            moment.panels.push_back({&op.end, nullptr, 0.0, &text.summary});
        }
    }
    if (moment.question >= 0) {
        const HeapQuestion& q = questions_[static_cast<std::size_t>(moment.question)];
        moment.panels[q.panel].caption = moment.reveal ? &q.answer_words : &q.question;
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
    if (moment.question >= 0) {
        const HeapQuestion& q = questions_[static_cast<std::size_t>(moment.question)];
        view::HeapPanelView& panel = view.panels[q.panel];
        for (std::size_t i = 0; i < q.candidates.size(); ++i)
            panel.letters.push_back({q.candidates[i], candidate_letter(i), i == q.answer});
        panel.reveal = moment.reveal;
        if (!moment.reveal) panel.countdown = countdown_words(moment.think_left);
    }
    if (code_) view.code = code_at(moment);
    return view;
}

std::vector<double> HeapProgram::fit_check_times() const {
    // A frame's layout changes with what it shows (a line of returned keys once one is
    // returned, the question's letters): one frame before, one halfway, one after all of it.
    return {0.0, 0.5 * duration(), duration()};
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

std::vector<std::string> HeapProgram::captions() const {
    std::vector<std::string> out;
    const auto consider = [&](const std::string& caption) {
        if (std::find(out.begin(), out.end(), caption) == out.end()) out.push_back(caption);
    };
    for (const PanelText& panel : text_) {
        consider(panel.start);
        for (const OpText& op : panel.ops) {
            for (const std::string& caption : op.captions) consider(caption);
            consider(op.summary);
        }
    }
    for (const HeapQuestion& q : questions_) {
        consider(q.question);
        consider(q.answer_words);
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
