#include "collide/sim/pq/heap_record.hpp"

#include <algorithm>
#include <cctype>
#include <functional>
#include <string>
#include <utility>

#include "collide/error.hpp"
#include "collide/sim/pq/dary_heap.hpp"
#include "collide/sim/pq/heapsort.hpp"
#include "collide/sim/pq/indexed_heap.hpp"
#include "collide/sim/pq/observer.hpp"
#include "collide/sim/pq/ordered_array_pq.hpp"
#include "collide/sim/pq/unordered_array_pq.hpp"
#include "pq/tokens.hpp"

namespace collide::pq {

namespace {

// ------------------------------------------------------------------------------------ parsing

using tokens::is_integer;
using tokens::key_of;
using tokens::KeyKindCheck;

[[noreturn]] void reject_token(std::string_view field, std::size_t token, std::string_view spelling,
                               const std::string& why) {
    tokens::reject(field, token, spelling, why);
}

// ------------------------------------------------------------------------------------ replay

/// How key a orders against key b: < 0, 0 or > 0 (numerically for integer keys).
int order_of(const std::string& a, const std::string& b, bool numeric) {
    const auto less = [numeric](const std::string& x, const std::string& y) {
        return numeric ? std::stoll(x) < std::stoll(y) : x < y;
    };
    if (less(a, b)) return -1;
    if (less(b, a)) return 1;
    return 0;
}

/// Turns one panel's record into steps, keeping the array the record implies.
class Replayer {
  public:
    Replayer(HeapPanel& panel, Orientation orientation, bool numeric)
        : panel_(panel), max_(orientation == Orientation::max), numeric_(numeric) {}

    ArrayState& state() { return state_; }

    void begin_op() {
        steps_.clear();
        best_.reset();
    }

    void appear(const std::string& key, std::size_t handle) {
        state_.keys.push_back(key);
        if (!state_.handles.empty() || panel_.kind.family == QueueFamily::indexed)
            state_.handles.push_back(handle);
        state_.heap_size = state_.keys.size();
        const std::size_t i = state_.keys.size() - 1;
        add_step(HeapStep::Kind::appear, i, i);
    }

    void change(std::size_t i, const std::string& new_key) {
        changed_from_ = state_.keys[i];
        state_.keys[i] = new_key;
        add_step(HeapStep::Kind::change, i, i).from = changed_from_;
    }

    void apply(const QueueStep& e) {
        switch (e.kind) {
            case QueueStep::Kind::compare:
                compare(e.i, e.j);
                break;
            case QueueStep::Kind::exchange:
            case QueueStep::Kind::shift:
                exchange(e.i, e.j, e.kind == QueueStep::Kind::shift);
                break;
            case QueueStep::Kind::remove:
                remove(e.i);
                break;
            case QueueStep::Kind::sink:
                state_.heap_size = e.j;
                add_step(HeapStep::Kind::sink, e.i, e.j);
                break;
        }
    }

    /// Ends the operation: checks the replayed array against the queue's and stores the steps.
    void end_op(const std::vector<std::string>& actual, std::string removed = {}) {
        if (actual != state_.keys) {
            throw_runtime_error("heap lesson: the record of " + to_string(panel_.kind) +
                                " does not reproduce its array (a bug)");
        }
        PanelOp op;
        op.steps = std::move(steps_);
        op.end = state_;
        op.removed = std::move(removed);
        panel_.ops.push_back(std::move(op));
        steps_.clear();
    }

  private:
    HeapStep& add_step(HeapStep::Kind kind, std::size_t i, std::size_t j) {
        HeapStep step;
        step.kind = kind;
        step.i = i;
        step.j = j;
        step.best = best_;
        step.state = state_;
        steps_.push_back(std::move(step));
        return steps_.back();
    }

    void compare(std::size_t i, std::size_t j) {
        ++state_.compares;
        const std::string& a = state_.keys[i];
        const std::string& b = i == j ? changed_from_ : state_.keys[j];
        const int order = order_of(a, b, numeric_);
        if (panel_.kind.family == QueueFamily::unordered) {
            // best_index: slot i against the best so far, j.
            best_ = j;
            add_step(HeapStep::Kind::compare, i, j).order = order;
            if (max_ ? order > 0 : order < 0) best_ = i;
            return;
        }
        add_step(HeapStep::Kind::compare, i, j).order = order;
    }

    void exchange(std::size_t i, std::size_t j, bool shift) {
        ++state_.exchanges;
        add_step(shift ? HeapStep::Kind::shift : HeapStep::Kind::exchange, i, j);
        std::swap(state_.keys[i], state_.keys[j]);
        if (!state_.handles.empty()) std::swap(state_.handles[i], state_.handles[j]);
        if (best_ == j) best_ = i;
    }

    void remove(std::size_t i) {
        best_.reset();
        add_step(HeapStep::Kind::remove, i, i);
        state_.keys.pop_back();
        if (!state_.handles.empty()) state_.handles.pop_back();
        state_.heap_size = state_.keys.size();
    }

    HeapPanel& panel_;
    bool max_;
    bool numeric_;
    ArrayState state_;
    std::vector<HeapStep> steps_;
    std::optional<std::size_t> best_;
    std::string changed_from_;  ///< increase-key: the key before
};

// ------------------------------------------------------------------------------------ running

std::vector<std::string> texts(const auto& keys) {
    std::vector<std::string> out;
    for (const TraceKey& k : keys) out.push_back(k.text());
    return out;
}

/// What every queue does for one panel, whatever its type: push, pop, the array, the record.
template <class Q>
void run_plain(Q q, std::vector<QueueStep>& log, std::span<const HeapOp> ops, Replayer& replay) {
    for (const HeapOp& op : ops) {
        replay.begin_op();
        std::string removed;
        if (op.kind == HeapOp::Kind::insert) {
            replay.appear(op.key.text(), 0);
            q.push(op.key);
        } else {
            removed = q.pop().text();
        }
        for (const QueueStep& e : log) replay.apply(e);
        log.clear();
        const auto array = q.array();
        replay.end_op(texts(array), std::move(removed));
    }
}

template <Orientation O, unsigned D>
void run_indexed(std::vector<QueueStep>& log, std::span<const HeapOp> ops, Replayer& replay) {
    using Heap = IndexedDaryHeap<TraceKey, O, D, std::less<TraceKey>, void, QueueRecorder>;
    std::size_t inserts = 0;
    for (const HeapOp& op : ops) inserts += op.kind == HeapOp::Kind::insert;
    Heap heap(inserts, std::less<TraceKey>{}, QueueRecorder(&log));
    std::vector<TraceKey> key_of;  // by handle: the key it was inserted or raised to
    for (const HeapOp& op : ops) {
        replay.begin_op();
        std::string removed;
        if (op.kind == HeapOp::Kind::insert) {
            const auto h = static_cast<std::uint32_t>(key_of.size());
            key_of.push_back(op.key);
            replay.appear(op.key.text(), h);
            heap.push(h, op.key);
        } else if (op.kind == HeapOp::Kind::remove) {
            removed = heap.top_key().text();
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
        for (const QueueStep& e : log) replay.apply(e);
        log.clear();
        std::vector<std::string> array;
        for (std::uint32_t h : heap.array()) array.push_back(heap.key(h).text());
        replay.end_op(array, std::move(removed));
    }
}

template <Orientation O>
void run_panel(const QueueKind& kind, std::span<const HeapOp> ops, std::string_view impl_field,
               Replayer& replay) {
    std::vector<QueueStep> log;
    const QueueRecorder rec(&log);
    using K = TraceKey;
    using L = std::less<TraceKey>;
    switch (kind.family) {
        case QueueFamily::unordered:
            return run_plain(UnorderedArrayPQ<K, O, L, QueueRecorder>(L{}, rec), log, ops, replay);
        case QueueFamily::ordered:
            return run_plain(OrderedArrayPQ<K, O, L, QueueRecorder>(L{}, rec), log, ops, replay);
        case QueueFamily::binary:
            return run_plain(DaryHeap<K, O, 2, L, QueueRecorder>(L{}, rec), log, ops, replay);
        case QueueFamily::dary:
            switch (kind.d) {
                case 2:
                    return run_plain(DaryHeap<K, O, 2, L, QueueRecorder>(L{}, rec), log, ops,
                                     replay);
                case 3:
                    return run_plain(DaryHeap<K, O, 3, L, QueueRecorder>(L{}, rec), log, ops,
                                     replay);
                case 4:
                    return run_plain(DaryHeap<K, O, 4, L, QueueRecorder>(L{}, rec), log, ops,
                                     replay);
                default:
                    return run_plain(DaryHeap<K, O, 0, L, QueueRecorder>(kind.d, L{}, rec), log,
                                     ops, replay);
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
    throw_input_error(std::string(impl_field) + ": unsupported queue '" + to_string(kind) + "'");
}

/// Input errors a queue would only meet half-way: removal from an empty queue, increase-key
/// without `indexed`, of an absent key, or to a smaller key. Checked once on a reference model.
void check_operations(std::span<const HeapOp> ops, std::span<const QueueKind> impls,
                      Orientation orientation, std::string_view field,
                      std::string_view impl_field) {
    std::vector<TraceKey> live;  // insertion order
    const bool all_indexed = std::all_of(impls.begin(), impls.end(), [](const QueueKind& k) {
        return k.family == QueueFamily::indexed;
    });
    for (const HeapOp& op : ops) {
        switch (op.kind) {
            case HeapOp::Kind::insert:
                live.push_back(op.key);
                break;
            case HeapOp::Kind::remove: {
                if (live.empty())
                    reject_token(field, op.token, op.spelling, "removes from an empty queue");
                const auto next = orientation == Orientation::max
                                      ? std::max_element(live.begin(), live.end())
                                      : std::min_element(live.begin(), live.end());
                live.erase(next);
                break;
            }
            case HeapOp::Kind::increase: {
                if (!all_indexed) {
                    reject_token(field, op.token, op.spelling,
                                 "increase-key needs " + std::string(impl_field) +
                                     " indexed (only the indexed heap finds a key through its "
                                     "map)");
                }
                const auto it = std::find(live.begin(), live.end(), op.key);
                if (it == live.end()) {
                    reject_token(field, op.token, op.spelling,
                                 "key " + op.key.text() + " is not in the queue");
                }
                if (op.new_key < op.key) {
                    reject_token(field, op.token, op.spelling,
                                 "increase-key to a smaller key (" + op.new_key.text() + " < " +
                                     op.key.text() + ")");
                }
                *it = op.new_key;
                break;
            }
            case HeapOp::Kind::build:
            case HeapOp::Kind::sortdown:
                throw_runtime_error("heap lesson: heapsort's phases are not operations (a bug)");
        }
    }
}

bool numeric_keys(std::span<const HeapOp> ops) {
    for (const HeapOp& op : ops) {
        if (op.kind != HeapOp::Kind::remove) return op.key.numeric;
    }
    return false;
}

std::size_t most_items(const HeapPanel& panel) {
    std::size_t most = panel.start.keys.size();
    for (const PanelOp& op : panel.ops) {
        for (const HeapStep& s : op.steps) most = std::max(most, s.state.keys.size());
        most = std::max(most, op.end.keys.size());
    }
    return most;
}

}  // namespace

// ------------------------------------------------------------------------------------ parsing

std::vector<HeapOp> parse_heap_ops(std::string_view text, std::string_view field) {
    const std::vector<std::string_view> words = tokens::split(text);
    if (words.empty())
        throw_input_error(std::string(field) + ": no operations given (e.g. \"P Q E * X\")");
    std::vector<HeapOp> out;
    KeyKindCheck kinds(field);
    for (std::size_t t = 0; t < words.size(); ++t) {
        HeapOp op;
        op.token = t + 1;
        op.spelling = std::string(words[t]);
        const std::string_view s = words[t];
        const std::size_t caret = s.find('^');
        if (s == "*") {
            op.kind = HeapOp::Kind::remove;
        } else if (caret != std::string_view::npos) {
            const auto key = key_of(s.substr(0, caret));
            const auto new_key = key_of(s.substr(caret + 1));
            if (!key || !new_key) {
                reject_token(field, op.token, s,
                             "increase-key is KEY^NEW with two keys, e.g. 3^12 or E^Z");
            }
            op.kind = HeapOp::Kind::increase;
            op.key = *key;
            op.new_key = *new_key;
            kinds.check(op.key, op.token, s);
            kinds.check(op.new_key, op.token, s);
        } else if (const auto key = key_of(s)) {
            op.key = *key;
            kinds.check(op.key, op.token, s);
        } else {
            reject_token(field, op.token, s,
                         is_integer(s) ? "integer out of range"
                                       : "not a key (a word of letters or an integer), '*' "
                                         "(remove) nor KEY^NEW (increase-key)");
        }
        out.push_back(std::move(op));
    }
    return out;
}

std::vector<TraceKey> parse_sort_keys(std::string_view text, std::string_view field) {
    const std::vector<std::string_view> words = tokens::split(text);
    if (words.empty())
        throw_input_error(std::string(field) + ": no keys given (e.g. \"S O R T E X A M P L E\")");
    std::vector<TraceKey> out;
    KeyKindCheck kinds(field);
    for (std::size_t t = 0; t < words.size(); ++t) {
        const auto key = key_of(words[t]);
        if (!key) {
            reject_token(field, t + 1, words[t],
                         "heapsort takes keys only (words of letters or integers)");
        }
        kinds.check(*key, t + 1, words[t]);
        out.push_back(*key);
    }
    return out;
}

// ------------------------------------------------------------------------------------ timeline

HeapRecord HeapRecord::operations(std::span<const HeapOp> ops, std::span<const QueueKind> impls,
                                  Orientation orientation, std::string_view field,
                                  std::string_view impl_field) {
    check_operations(ops, impls, orientation, field, impl_field);
    HeapRecord out;
    out.ops_.assign(ops.begin(), ops.end());
    out.orientation_ = orientation;
    const bool numeric = numeric_keys(ops);
    for (const QueueKind& kind : impls) {
        HeapPanel panel;
        panel.kind = kind;
        panel.tree = kind.family != QueueFamily::unordered && kind.family != QueueFamily::ordered;
        panel.arity = panel.tree ? kind.d : 1;
        panel.shifts = kind.family == QueueFamily::ordered;
        Replayer replay(panel, orientation, numeric);
        replay.state() = panel.start;
        if (orientation == Orientation::max) {
            run_panel<Orientation::max>(kind, ops, impl_field, replay);
        } else {
            run_panel<Orientation::min>(kind, ops, impl_field, replay);
        }
        out.capacity_ = std::max(out.capacity_, most_items(panel));
        out.panels_.push_back(std::move(panel));
    }
    return out;
}

HeapRecord HeapRecord::heapsort(std::span<const TraceKey> keys, Orientation orientation) {
    HeapRecord out;
    out.heapsort_ = true;
    out.orientation_ = orientation;
    out.ops_.resize(2);
    out.ops_[0].kind = HeapOp::Kind::build;
    out.ops_[1].kind = HeapOp::Kind::sortdown;
    HeapPanel panel;
    panel.kind = {QueueFamily::binary, 2};
    panel.start.keys = texts(keys);
    panel.start.heap_size = keys.size();
    const bool numeric = !keys.empty() && keys.front().numeric;

    // The sort itself, recorded; split at the first exchange of the root with the end.
    std::vector<TraceKey> sorted(keys.begin(), keys.end());
    std::vector<QueueStep> log;
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
        if (log[e].kind == QueueStep::Kind::sink && log[e].j < n) {
            split = e - 1;
            break;
        }
    }

    Replayer replay(panel, orientation, numeric);
    replay.state() = panel.start;
    replay.begin_op();
    for (std::size_t e = 0; e < split; ++e) replay.apply(log[e]);
    std::vector<std::string> built = replay.state().keys;
    replay.end_op(built);
    replay.begin_op();
    for (std::size_t e = split; e < log.size(); ++e) replay.apply(log[e]);
    replay.state().heap_size = 0;
    replay.end_op(texts(sorted));
    out.capacity_ = keys.size();
    out.panels_.push_back(std::move(panel));
    return out;
}

}  // namespace collide::pq
