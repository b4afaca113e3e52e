#include "collide/sim/pq/heap_lesson.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <functional>
#include <string>
#include <system_error>
#include <utility>

#include "collide/error.hpp"
#include "collide/sim/pq/dary_heap.hpp"
#include "collide/sim/pq/heapsort.hpp"
#include "collide/sim/pq/indexed_heap.hpp"
#include "collide/sim/pq/observer.hpp"
#include "collide/sim/pq/ordered_array_pq.hpp"
#include "collide/sim/pq/unordered_array_pq.hpp"

namespace collide::pq {

namespace {

// ------------------------------------------------------------------------------------ parsing

[[noreturn]] void reject_token(std::string_view option, std::size_t token,
                               std::string_view spelling, const std::string& why) {
    throw_input_error(std::string(option) + ": token " + std::to_string(token) + " '" +
                      std::string(spelling) + "': " + why);
}

bool is_word(std::string_view s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
        return std::isalpha(static_cast<unsigned char>(c)) != 0;
    });
}

bool is_integer(std::string_view s) {
    if (!s.empty() && (s.front() == '+' || s.front() == '-')) s.remove_prefix(1);
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
        return std::isdigit(static_cast<unsigned char>(c)) != 0;
    });
}

/// A key from one word or integer; nullopt for anything else.
std::optional<TraceKey> key_of(std::string_view text) {
    TraceKey key;
    if (is_word(text)) {
        key.word = std::string(text);
        return key;
    }
    if (!is_integer(text)) return std::nullopt;
    key.numeric = true;
    if (text.front() == '+') text.remove_prefix(1);  // from_chars takes '-' but not '+'
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), key.number);
    if (ec != std::errc{} || end != text.data() + text.size()) return std::nullopt;
    return key;
}

std::vector<std::string_view> split_tokens(std::string_view text) {
    std::vector<std::string_view> tokens;
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i])) != 0) ++i;
        const std::size_t start = i;
        while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i])) == 0) ++i;
        if (i > start) tokens.push_back(text.substr(start, i - start));
    }
    return tokens;
}

const char* kind_name(const TraceKey& key) {
    return key.numeric ? "a number" : "a word";
}

/// Words and numbers do not mix: the first key decides.
class KeyKindCheck {
  public:
    explicit KeyKindCheck(std::string_view option) : option_(option) {}
    void check(const TraceKey& key, std::size_t token, std::string_view spelling) {
        if (!first_) {
            first_ = key;
            first_spelling_ = std::string(spelling);
            return;
        }
        if (key.numeric != first_->numeric) {
            reject_token(option_, token, spelling,
                         std::string("is ") + kind_name(key) + " but the first key '" +
                             first_spelling_ + "' is " + kind_name(*first_) +
                             "; keys must be all words or all numbers");
        }
    }

  private:
    std::string_view option_;
    std::optional<TraceKey> first_;
    std::string first_spelling_;
};

// ------------------------------------------------------------------------------------ captions

std::string slot_name(std::size_t i, int base) {
    return "a[" + std::to_string(static_cast<long long>(i) + base) + "]";
}

/// "<", ">" or "=": how a compares to b as keys.
const char* relation(const std::string& a, const std::string& b, bool numeric) {
    const auto less = [numeric](const std::string& x, const std::string& y) {
        return numeric ? std::stoll(x) < std::stoll(y) : x < y;
    };
    if (less(a, b)) return "<";
    if (less(b, a)) return ">";
    return "=";
}

std::string plural(std::uint64_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

// ------------------------------------------------------------------------------------ replay

/// Turns one panel's record into steps, keeping the array the record implies.
class Replayer {
  public:
    Replayer(LessonPanel& panel, Orientation orientation, int base, bool numeric)
        : panel_(panel), max_(orientation == Orientation::max), base_(base), numeric_(numeric) {}

    LessonState& state() { return state_; }

    void begin_op(std::string prefix) {
        prefix_ = std::move(prefix);
        steps_.clear();
        op_compares_ = state_.compares;
        op_exchanges_ = state_.exchanges;
        best_.reset();
        sinking_.reset();
    }

    void appear(const std::string& key, std::size_t handle) {
        state_.keys.push_back(key);
        if (!state_.handles.empty() || panel_.kind.family == QueueFamily::indexed)
            state_.handles.push_back(handle);
        state_.heap_size = state_.keys.size();
        const std::size_t i = state_.keys.size() - 1;
        prefix_ += " at " + slot_name(i, base_);
        std::string what = prefix_;
        if (panel_.kind.family == QueueFamily::unordered) what += ", the end: nothing else to do";
        add_step(LessonStep::Kind::appear, i, i, what);
    }

    void change(std::size_t i, const std::string& new_key) {
        const std::string old = state_.keys[i];
        changed_from_ = old;
        state_.keys[i] = new_key;
        const std::string slot = slot_name(i, base_);
        std::string what = prefix_ + ": the map says " + old + " is at " + slot + "; set " + slot +
                           " = " + new_key;
        add_step(LessonStep::Kind::change, i, i, what);
    }

    void apply(const QueueEvent& e) {
        switch (e.kind) {
            case QueueEvent::Kind::compare:
                compare(e.i, e.j);
                break;
            case QueueEvent::Kind::exchange:
            case QueueEvent::Kind::shift:
                exchange(e.i, e.j, e.kind == QueueEvent::Kind::shift);
                break;
            case QueueEvent::Kind::remove:
                remove(e.i);
                break;
            case QueueEvent::Kind::sink:
                sink(e.i, e.j);
                break;
        }
    }

    /// Ends the operation: checks the replayed array against the queue's and stores the steps.
    void end_op(const std::vector<std::string>& actual, std::string_view summary_head) {
        if (actual != state_.keys) {
            throw_runtime_error("heap lesson: the record of " + panel_.title +
                                " does not reproduce its array (a bug)");
        }
        LessonPanelOp op;
        op.steps = std::move(steps_);
        op.end = state_;
        const std::uint64_t c = state_.compares - op_compares_;
        const std::uint64_t x = state_.exchanges - op_exchanges_;
        op.end.caption =
            std::string(summary_head) + ": " + plural(c, "compare", "compares") + ", " +
            plural(x, panel_.shifts ? "shift" : "exchange", panel_.shifts ? "shifts" : "exchanges");
        panel_.ops.push_back(std::move(op));
        steps_.clear();
    }

  private:
    [[nodiscard]] const char* top_word() const { return max_ ? "max" : "min"; }
    [[nodiscard]] const char* child_word() const { return max_ ? "larger" : "smaller"; }
    [[nodiscard]] bool comes_first(const std::string& a, const std::string& b) const {
        const std::string r = relation(a, b, numeric_);
        return max_ ? r == ">" : r == "<";
    }
    [[nodiscard]] std::string vs(const std::string& a, const std::string& b) const {
        return a + " " + relation(a, b, numeric_) + " " + b;
    }
    [[nodiscard]] std::size_t parent(std::size_t i) const { return (i - 1) / panel_.arity; }

    void add_step(LessonStep::Kind kind, std::size_t i, std::size_t j, std::string caption) {
        LessonStep step;
        step.kind = kind;
        step.i = i;
        step.j = j;
        step.best = best_;
        step.state = state_;
        step.state.caption = std::move(caption);
        steps_.push_back(std::move(step));
    }

    void compare(std::size_t i, std::size_t j) {
        ++state_.compares;
        const std::string& a = state_.keys[i];
        const std::string& b = state_.keys[j];
        std::string what;
        switch (panel_.kind.family) {
            case QueueFamily::unordered: {
                // best_index: slot i against the best so far, j.
                const bool better = comes_first(a, b);
                what = std::string("scan for the ") + top_word() + ": " + vs(a, b) +
                       (better ? ", new " + std::string(top_word()) + " " + a : "");
                best_ = j;
                add_step(LessonStep::Kind::compare, i, j, what);
                if (better) best_ = i;
                return;
            }
            case QueueFamily::ordered: {
                // The key being inserted (slot i) against its left neighbour (slot j).
                const bool shift = comes_first(b, a);
                what = prefix_ + "; " + vs(b, a) +
                       (shift ? ": shift " + b + " right"
                              : ": stop, " + a + " stays at " + slot_name(i, base_));
                break;
            }
            default:
                what = heap_compare_caption(i, j, a, b);
                break;
        }
        add_step(LessonStep::Kind::compare, i, j, what);
    }

    std::string heap_compare_caption(std::size_t i, std::size_t j, const std::string& a,
                                     const std::string& b) const {
        if (i == j) {  // increase-key: the new key against the old one
            return prefix_ + "; " + vs(a, changed_from_) +
                   (max_ ? ": a larger key may have to swim up"
                         : ": a larger key may have to sink");
        }
        const bool siblings = i > 0 && j > 0 && parent(i) == parent(j);
        if (siblings) {
            const std::string who = sinking_ ? "sink " + *sinking_ + ": " : "";
            return prefix_ + "; " + who + child_word() + " child? " + vs(a, b);
        }
        // i is the moving key; j its parent (swim) or its best child (sink).
        const bool up = j < i;
        const bool moves = up ? comes_first(a, b) : comes_first(b, a);
        const std::string who = !up && sinking_ ? "sink " + *sinking_ + ": " : "";
        return prefix_ + "; " + who + vs(a, b) + (moves ? ": exchange" : ": stop");
    }

    void exchange(std::size_t i, std::size_t j, bool shift) {
        ++state_.exchanges;
        const std::string& a = state_.keys[i];
        const std::string& b = state_.keys[j];
        std::string what;
        if (shift) {
            what = prefix_ + "; shift " + a + " right to " + slot_name(j, base_);
        } else if (panel_.kind.family == QueueFamily::unordered) {
            what = i == j ? std::string("remove ") + top_word() + ": " + a + " is already last"
                          : std::string("remove ") + top_word() + ": exchange " + a +
                                " with the last, " + b;
        } else if (prefix_ == "sortdown" && i == 0) {
            what = "sortdown: exchange " + std::string(top_word()) + " " + a + " with " + b +
                   " at " + slot_name(j, base_) + "; " + a + " is in place";
            sinking_ = b;
        } else if (i == j) {
            what = prefix_ + ": " + a + " is the only item";
        } else if (i == 0 && j + 1 == state_.keys.size() && steps_.empty()) {
            what = prefix_ + ": exchange the root " + a + " with the last, " + b;
            sinking_ = b;
        } else {
            what = prefix_ + "; exchange " + a + " and " + b;
        }
        add_step(LessonStep::Kind::exchange, i, j, what);
        std::swap(state_.keys[i], state_.keys[j]);
        if (!state_.handles.empty()) std::swap(state_.handles[i], state_.handles[j]);
        if (best_ == j) best_ = i;
    }

    void remove(std::size_t i) {
        const std::string key = state_.keys[i];
        best_.reset();
        add_step(LessonStep::Kind::remove, i, i,
                 prefix_ + ": " + key + " leaves " + slot_name(i, base_));
        state_.keys.pop_back();
        if (!state_.handles.empty()) state_.handles.pop_back();
        state_.heap_size = state_.keys.size();
    }

    void sink(std::size_t i, std::size_t heap_size) {
        state_.heap_size = heap_size;
        sinking_ = state_.keys[i];
        if (prefix_ == "build the heap") {
            add_step(LessonStep::Kind::sink, i, i,
                     "build the heap: sink " + state_.keys[i] + " at " + slot_name(i, base_));
        }
    }

    LessonPanel& panel_;
    bool max_;
    int base_;
    bool numeric_;
    LessonState state_;
    std::string prefix_;
    std::vector<LessonStep> steps_;
    std::uint64_t op_compares_ = 0;
    std::uint64_t op_exchanges_ = 0;
    std::optional<std::size_t> best_;
    std::optional<std::string> sinking_;  ///< the key a sink moves down
    std::string changed_from_;            ///< increase-key: the key before
};

// ------------------------------------------------------------------------------------ running

std::vector<std::string> texts(const auto& keys) {
    std::vector<std::string> out;
    for (const TraceKey& k : keys) out.push_back(k.text());
    return out;
}

std::string panel_title(const QueueKind& kind) {
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

std::string op_prefix(const LessonOp& op, Orientation orientation) {
    switch (op.kind) {
        case LessonOp::Kind::insert:
            return "insert " + op.key.text();
        case LessonOp::Kind::remove:
            return orientation == Orientation::max ? "remove max" : "remove min";
        case LessonOp::Kind::increase:
            return "increase " + op.key.text() + " to " + op.new_key.text();
    }
    return "";
}

/// What every queue does for one panel, whatever its type: push, pop, the array, the record.
template <class Q>
void run_plain(Q q, std::vector<QueueEvent>& log, std::span<const LessonOp> ops,
               Orientation orientation, Replayer& replay) {
    for (const LessonOp& op : ops) {
        replay.begin_op(op_prefix(op, orientation));
        std::string head = op_prefix(op, orientation);
        if (op.kind == LessonOp::Kind::insert) {
            replay.appear(op.key.text(), 0);
            q.push(op.key);
        } else {
            head += " " + q.pop().text();
        }
        for (const QueueEvent& e : log) replay.apply(e);
        log.clear();
        const auto array = q.array();
        replay.end_op(texts(array), head);
    }
}

template <Orientation O, unsigned D>
void run_indexed(std::vector<QueueEvent>& log, std::span<const LessonOp> ops, Replayer& replay) {
    using Heap = IndexedDaryHeap<TraceKey, O, D, std::less<TraceKey>, void, QueueRecorder>;
    std::size_t inserts = 0;
    for (const LessonOp& op : ops) inserts += op.kind == LessonOp::Kind::insert;
    Heap heap(inserts, std::less<TraceKey>{}, QueueRecorder(&log));
    std::vector<TraceKey> key_of;  // by handle: the key it was inserted or raised to
    for (const LessonOp& op : ops) {
        replay.begin_op(op_prefix(op, O));
        std::string head = op_prefix(op, O);
        if (op.kind == LessonOp::Kind::insert) {
            const auto h = static_cast<std::uint32_t>(key_of.size());
            key_of.push_back(op.key);
            replay.appear(op.key.text(), h);
            heap.push(h, op.key);
        } else if (op.kind == LessonOp::Kind::remove) {
            head += " " + heap.top_key().text();
            heap.pop();
        } else {
            std::uint32_t h = 0;
            while (h < key_of.size() && !(heap.contains(h) && key_of[h] == op.key)) ++h;
            // parse-time checks (build_operations) guarantee the key is present
            const std::vector<std::uint32_t> order = heap.array();
            const auto slot =
                static_cast<std::size_t>(std::find(order.begin(), order.end(), h) - order.begin());
            replay.change(slot, op.new_key.text());
            key_of[h] = op.new_key;
            heap.change_key(h, op.new_key);
        }
        for (const QueueEvent& e : log) replay.apply(e);
        log.clear();
        std::vector<std::string> array;
        for (std::uint32_t h : heap.array()) array.push_back(heap.key(h).text());
        replay.end_op(array, head);
    }
}

template <Orientation O>
void run_panel(const QueueKind& kind, std::span<const LessonOp> ops, Replayer& replay) {
    std::vector<QueueEvent> log;
    const QueueRecorder rec(&log);
    using K = TraceKey;
    using L = std::less<TraceKey>;
    switch (kind.family) {
        case QueueFamily::unordered:
            return run_plain(UnorderedArrayPQ<K, O, L, QueueRecorder>(L{}, rec), log, ops, O,
                             replay);
        case QueueFamily::ordered:
            return run_plain(OrderedArrayPQ<K, O, L, QueueRecorder>(L{}, rec), log, ops, O, replay);
        case QueueFamily::binary:
            return run_plain(DaryHeap<K, O, 2, L, QueueRecorder>(L{}, rec), log, ops, O, replay);
        case QueueFamily::dary:
            switch (kind.d) {
                case 2:
                    return run_plain(DaryHeap<K, O, 2, L, QueueRecorder>(L{}, rec), log, ops, O,
                                     replay);
                case 3:
                    return run_plain(DaryHeap<K, O, 3, L, QueueRecorder>(L{}, rec), log, ops, O,
                                     replay);
                case 4:
                    return run_plain(DaryHeap<K, O, 4, L, QueueRecorder>(L{}, rec), log, ops, O,
                                     replay);
                default:
                    return run_plain(DaryHeap<K, O, 0, L, QueueRecorder>(kind.d, L{}, rec), log,
                                     ops, O, replay);
            }
        case QueueFamily::indexed:
            switch (kind.d) {
                case 2:
                    return run_indexed<O, 2>(log, ops, replay);
                case 3:
                    return run_indexed<O, 3>(log, ops, replay);
                case 4:
                    return run_indexed<O, 4>(log, ops, replay);
                case 8:
                    return run_indexed<O, 8>(log, ops, replay);
                default:
                    break;
            }
            break;
    }
    throw_input_error("--impl: unsupported queue '" + to_string(kind) + "'");
}

/// Input errors a queue would only meet half-way: removal from an empty queue, increase-key
/// without `indexed`, of an absent key, or to a smaller key. Checked once on a reference model.
void check_operations(std::span<const LessonOp> ops, std::span<const QueueKind> impls,
                      Orientation orientation, std::string_view option) {
    std::vector<TraceKey> live;  // insertion order
    const bool all_indexed = std::all_of(impls.begin(), impls.end(), [](const QueueKind& k) {
        return k.family == QueueFamily::indexed;
    });
    for (const LessonOp& op : ops) {
        switch (op.kind) {
            case LessonOp::Kind::insert:
                live.push_back(op.key);
                break;
            case LessonOp::Kind::remove: {
                if (live.empty())
                    reject_token(option, op.token, op.spelling, "removes from an empty queue");
                const auto next = orientation == Orientation::max
                                      ? std::max_element(live.begin(), live.end())
                                      : std::min_element(live.begin(), live.end());
                live.erase(next);
                break;
            }
            case LessonOp::Kind::increase: {
                if (!all_indexed) {
                    reject_token(option, op.token, op.spelling,
                                 "increase-key needs --impl indexed (only the indexed heap finds a "
                                 "key through its map)");
                }
                const auto it = std::find(live.begin(), live.end(), op.key);
                if (it == live.end()) {
                    reject_token(option, op.token, op.spelling,
                                 "key " + op.key.text() + " is not in the queue");
                }
                if (op.new_key < op.key) {
                    reject_token(option, op.token, op.spelling,
                                 "increase-key to a smaller key (" + op.new_key.text() + " < " +
                                     op.key.text() + ")");
                }
                *it = op.new_key;
                break;
            }
        }
    }
}

bool numeric_keys(std::span<const LessonOp> ops) {
    for (const LessonOp& op : ops) {
        if (op.kind != LessonOp::Kind::remove) return op.key.numeric;
    }
    return false;
}

std::size_t most_items(const LessonPanel& panel) {
    std::size_t most = panel.start.keys.size();
    for (const LessonPanelOp& op : panel.ops) {
        for (const LessonStep& s : op.steps) most = std::max(most, s.state.keys.size());
        most = std::max(most, op.end.keys.size());
    }
    return most;
}

}  // namespace

// ------------------------------------------------------------------------------------ parsing

std::vector<LessonOp> parse_lesson_ops(std::string_view text, std::string_view option) {
    const std::vector<std::string_view> tokens = split_tokens(text);
    if (tokens.empty())
        throw_input_error(std::string(option) + ": no operations given (e.g. \"P Q E * X\")");
    std::vector<LessonOp> out;
    KeyKindCheck kinds(option);
    for (std::size_t t = 0; t < tokens.size(); ++t) {
        LessonOp op;
        op.token = t + 1;
        op.spelling = std::string(tokens[t]);
        const std::string_view s = tokens[t];
        const std::size_t caret = s.find('^');
        if (s == "*") {
            op.kind = LessonOp::Kind::remove;
        } else if (caret != std::string_view::npos) {
            const auto key = key_of(s.substr(0, caret));
            const auto new_key = key_of(s.substr(caret + 1));
            if (!key || !new_key) {
                reject_token(option, op.token, s,
                             "increase-key is KEY^NEW with two keys, e.g. 3^12 or E^Z");
            }
            op.kind = LessonOp::Kind::increase;
            op.key = *key;
            op.new_key = *new_key;
            kinds.check(op.key, op.token, s);
            kinds.check(op.new_key, op.token, s);
        } else if (const auto key = key_of(s)) {
            op.key = *key;
            kinds.check(op.key, op.token, s);
        } else {
            reject_token(option, op.token, s,
                         is_integer(s) ? "integer out of range"
                                       : "not a key (a word of letters or an integer), '*' "
                                         "(remove) nor KEY^NEW (increase-key)");
        }
        out.push_back(std::move(op));
    }
    return out;
}

std::vector<TraceKey> parse_sort_keys(std::string_view text, std::string_view option) {
    const std::vector<std::string_view> tokens = split_tokens(text);
    if (tokens.empty())
        throw_input_error(std::string(option) + ": no keys given (e.g. \"S O R T E X A M P L E\")");
    std::vector<TraceKey> out;
    KeyKindCheck kinds(option);
    for (std::size_t t = 0; t < tokens.size(); ++t) {
        const auto key = key_of(tokens[t]);
        if (!key) {
            reject_token(option, t + 1, tokens[t],
                         "heapsort takes keys only (words of letters or integers)");
        }
        kinds.check(*key, t + 1, tokens[t]);
        out.push_back(*key);
    }
    return out;
}

// ------------------------------------------------------------------------------------ timeline

LessonTimeline LessonTimeline::operations(std::span<const LessonOp> ops,
                                          std::span<const QueueKind> impls, Orientation orientation,
                                          int index_base, LessonPacing pacing) {
    check_operations(ops, impls, orientation, "--ops");
    LessonTimeline out;
    for (const LessonOp& op : ops) out.labels_.push_back(op.spelling);
    const bool numeric = numeric_keys(ops);
    for (const QueueKind& kind : impls) {
        LessonPanel panel;
        panel.kind = kind;
        panel.title = panel_title(kind);
        panel.tree = kind.family != QueueFamily::unordered && kind.family != QueueFamily::ordered;
        panel.arity = panel.tree ? kind.d : 1;
        panel.shifts = kind.family == QueueFamily::ordered;
        panel.start.caption = panel.title + (orientation == Orientation::max ? ", max" : ", min") +
                              "-oriented: empty";
        Replayer replay(panel, orientation, index_base, numeric);
        replay.state() = panel.start;
        if (orientation == Orientation::max) {
            run_panel<Orientation::max>(kind, ops, replay);
        } else {
            run_panel<Orientation::min>(kind, ops, replay);
        }
        out.capacity_ = std::max(out.capacity_, most_items(panel));
        out.panels_.push_back(std::move(panel));
    }
    out.finish_timing(pacing);
    return out;
}

LessonTimeline LessonTimeline::heapsort(std::span<const TraceKey> keys, Orientation orientation,
                                        int index_base, LessonPacing pacing) {
    LessonTimeline out;
    out.labels_ = {"build", "sortdown"};
    LessonPanel panel;
    panel.kind = {QueueFamily::binary, 2};
    panel.title = "heapsort";
    panel.start.keys = texts(keys);
    panel.start.heap_size = keys.size();
    panel.start.caption =
        "heapsort " + std::to_string(keys.size()) + " keys " +
        (orientation == Orientation::max ? "into ascending order" : "into descending order");
    const bool numeric = !keys.empty() && keys.front().numeric;

    // The sort itself, recorded; split at the first exchange of the root with the end.
    std::vector<TraceKey> sorted(keys.begin(), keys.end());
    std::vector<QueueEvent> log;
    const auto first_is_larger = [](const TraceKey& a, const TraceKey& b) { return b < a; };
    if (orientation == Orientation::max) {
        pq::heapsort(sorted.begin(), sorted.end(), std::less<TraceKey>{}, QueueRecorder(&log));
    } else {
        pq::heapsort(sorted.begin(), sorted.end(), first_is_larger, QueueRecorder(&log));
    }
    // The sortdown starts with the exchange just before the first sink of a smaller heap.
    const std::size_t n = keys.size();
    std::size_t split = log.size();
    for (std::size_t e = 1; e < log.size(); ++e) {
        if (log[e].kind == QueueEvent::Kind::sink && log[e].j < n) {
            split = e - 1;
            break;
        }
    }

    Replayer replay(panel, orientation, index_base, numeric);
    replay.state() = panel.start;
    replay.begin_op("build the heap");
    for (std::size_t e = 0; e < split; ++e) replay.apply(log[e]);
    std::vector<std::string> built = replay.state().keys;
    replay.end_op(built, "heap built");
    replay.begin_op("sortdown");
    for (std::size_t e = split; e < log.size(); ++e) replay.apply(log[e]);
    replay.state().heap_size = 0;
    replay.end_op(texts(sorted), "sortdown done");
    out.capacity_ = keys.size();
    out.panels_.push_back(std::move(panel));
    out.finish_timing(pacing);
    return out;
}

void LessonTimeline::finish_timing(LessonPacing pacing) {
    if (!(pacing.pace > 0.0) || pacing.pause < 0.0 || pacing.intro < 0.0 || pacing.outro < 0.0)
        throw_input_error("--pace: must be > 0");
    pacing_ = pacing;
    op_start_.clear();
    double t = pacing.intro;
    for (std::size_t k = 0; k < labels_.size(); ++k) {
        op_start_.push_back(t);
        std::size_t steps = 0;
        for (const LessonPanel& p : panels_) steps = std::max(steps, p.ops[k].steps.size());
        t += static_cast<double>(steps) * pacing.pace + pacing.pause;
    }
    op_start_.push_back(t);  // the outro starts here
}

double LessonTimeline::duration() const noexcept {
    return op_start_.back() + pacing_.outro;
}

LessonFrame LessonTimeline::frame_at(double seconds) const {
    LessonFrame frame;
    seconds = std::clamp(seconds, 0.0, duration());
    // The operation under way: the last one started at or before `seconds`.
    const auto after = std::upper_bound(op_start_.begin(), op_start_.end() - 1, seconds);
    if (after == op_start_.begin()) {
        frame.op = labels_.size();
        for (const LessonPanel& p : panels_) frame.panels.push_back({&p.start, nullptr, 0.0});
        return frame;
    }
    frame.started = true;
    frame.finished = seconds >= op_start_.back();
    frame.op = static_cast<std::size_t>(after - op_start_.begin()) - 1;
    const double into = seconds - op_start_[frame.op];
    const auto step = static_cast<std::size_t>(into / pacing_.pace);
    for (const LessonPanel& p : panels_) {
        const LessonPanelOp& op = p.ops[frame.op];
        if (step < op.steps.size()) {
            const double progress = into / pacing_.pace - static_cast<double>(step);
            frame.panels.push_back({&op.steps[step].state, &op.steps[step], progress});
        } else {
            frame.panels.push_back({&op.end, nullptr, 0.0});
        }
    }
    return frame;
}

}  // namespace collide::pq
