#include "collide/show/heap_code.hpp"

#include <string>

namespace collide::show {

namespace {

using pq::HeapOp;
using pq::HeapStep;
using pq::QueueFamily;

/// What a line of a listing stands for: the kind of recorded step that carries it out. A line
/// without a role (a header, `k = p`) is never the current one: no step of its own shows it.
enum class Role {
    none,
    put_key,          ///< insert: the new key appears at the end
    set_key,          ///< increase-key: the key changes in place
    check_key,        ///< increase-key: the new key against the old one
    swim_stop,        ///< swim: the key against its parent
    swim_exchange,    ///< swim: the key and its parent exchange
    pick_child,       ///< sink: two children compared, to find the one that comes first
    sink_stop,        ///< sink: the key against that child
    sink_exchange,    ///< sink: the key and that child exchange
    swap_root_last,   ///< remove: the root and the last key exchange
    take_out,         ///< remove: the last slot leaves
    build_sink,       ///< heapsort's construction: a sink starts
    sortdown_swap,    ///< heapsort's sortdown: the root and the heap's last key exchange
    sortdown_shrink,  ///< heapsort's sortdown: the sink of the new root starts
};

struct Line {
    int indent;
    std::string text;
    Role role;
};

/// The words that turn around with the orientation.
struct Words {
    const char* first;  ///< "larger": the child that comes out first
    const char* holds;  ///< ">=": a key that stays where it is against one below it
    const char* top;    ///< "max"
};

Words words_of(pq::Orientation orientation) {
    if (orientation == pq::Orientation::max) return {"larger", ">=", "max"};
    return {"smaller", "<=", "min"};
}

void add_swim(std::vector<Line>& out, const Words& w) {
    out.push_back({0, "swim(k):", Role::none});
    out.push_back({1, "while k is not the root:", Role::none});
    out.push_back({2, "p = parent(k)", Role::none});
    out.push_back({2, std::string("if a[p] ") + w.holds + " a[k]: stop", Role::swim_stop});
    out.push_back({2, "exchange a[k], a[p]", Role::swim_exchange});
    out.push_back({2, "k = p", Role::none});
}

void add_sink(std::vector<Line>& out, const Words& w) {
    out.push_back({0, "sink(k):", Role::none});
    out.push_back({1, "while k has a child:", Role::none});
    out.push_back({2, std::string("j = the ") + w.first + " child", Role::pick_child});
    out.push_back({2, std::string("if a[k] ") + w.holds + " a[j]: stop", Role::sink_stop});
    out.push_back({2, "exchange a[k], a[j]", Role::sink_exchange});
    out.push_back({2, "k = j", Role::none});
}

std::vector<Line> listing(HeapOp::Kind op, pq::Orientation orientation) {
    const Words w = words_of(orientation);
    const bool max = orientation == pq::Orientation::max;
    std::vector<Line> out;
    switch (op) {
        case HeapOp::Kind::insert:
            out.push_back({0, "insert(key):", Role::none});
            out.push_back({1, "last = last + 1", Role::none});
            out.push_back({1, "a[last] = key", Role::put_key});
            out.push_back({1, "swim(last)", Role::none});
            add_swim(out, w);
            break;
        case HeapOp::Kind::remove:
            out.push_back({0, std::string("remove_") + w.top + "():", Role::none});
            out.push_back({1, "exchange a[root], a[last]", Role::swap_root_last});
            out.push_back({1, "take out a[last]", Role::take_out});
            out.push_back({1, "sink(root)", Role::none});
            out.push_back({1, "return the key taken out", Role::none});
            add_sink(out, w);
            break;
        case HeapOp::Kind::increase:
            out.push_back({0, "increase_key(i, key):", Role::none});
            out.push_back({1, "k = qp[i]", Role::none});
            out.push_back({1, "old = a[k]; a[k] = key", Role::set_key});
            out.push_back({1, "if key < old: refuse", Role::check_key});
            if (max) {
                out.push_back({1, "swim(k)", Role::none});
                add_swim(out, w);
            } else {
                out.push_back({1, "sink(k)", Role::none});
                add_sink(out, w);
            }
            break;
        case HeapOp::Kind::build:
        case HeapOp::Kind::sortdown:
            // One listing for both passes: the class sees where the second starts.
            out.push_back({0, "heapsort(a):", Role::none});
            out.push_back({1, "for each parent k, last first:", Role::none});
            out.push_back({2, "sink(k)", Role::build_sink});
            out.push_back({1, "while the heap has 2+ keys:", Role::none});
            out.push_back({2, "exchange a[root], a[last]", Role::sortdown_swap});
            out.push_back({2, "a[last] leaves the heap", Role::none});
            out.push_back({2, "sink(root)", Role::sortdown_shrink});
            add_sink(out, w);
            break;
    }
    return out;
}

/// Whether the swim (true) or the sink (false) carries out the compares and exchanges of `op`.
bool swims(HeapOp::Kind op, pq::Orientation orientation) {
    if (op == HeapOp::Kind::insert) return true;
    if (op == HeapOp::Kind::increase) return orientation == pq::Orientation::max;
    return false;
}

Role role_of(const pq::HeapPanel& panel, HeapOp::Kind op, pq::Orientation orientation,
             const pq::PanelOp& done, std::size_t s) {
    const HeapStep& step = done.steps[s];
    const bool swim = swims(op, orientation);
    switch (step.kind) {
        case HeapStep::Kind::appear:
            return Role::put_key;
        case HeapStep::Kind::change:
            return Role::set_key;
        case HeapStep::Kind::remove:
            return Role::take_out;
        case HeapStep::Kind::sink:
            return op == HeapOp::Kind::build ? Role::build_sink : Role::sortdown_shrink;
        case HeapStep::Kind::shift:
            return Role::none;  // the ordered array's: no heap listing has it
        case HeapStep::Kind::compare: {
            if (step.i == step.j) return Role::check_key;  // increase-key: new against old
            const std::size_t d = panel.arity;
            const bool siblings = step.i > 0 && step.j > 0 && (step.i - 1) / d == (step.j - 1) / d;
            if (siblings) return Role::pick_child;
            return swim ? Role::swim_stop : Role::sink_stop;
        }
        case HeapStep::Kind::exchange: {
            if (op == HeapOp::Kind::remove) {
                // The exchange of the root with the last comes before the removal; the sink's
                // exchanges after it.
                for (std::size_t k = s + 1; k < done.steps.size(); ++k) {
                    if (done.steps[k].kind == HeapStep::Kind::remove) return Role::swap_root_last;
                }
                return Role::sink_exchange;
            }
            if (op == HeapOp::Kind::sortdown) {
                // Every round of the sortdown is its exchange, then the sink it starts.
                const bool next_sinks =
                    s + 1 < done.steps.size() && done.steps[s + 1].kind == HeapStep::Kind::sink;
                return next_sinks ? Role::sortdown_swap : Role::sink_exchange;
            }
            return swim ? Role::swim_exchange : Role::sink_exchange;
        }
    }
    return Role::none;
}

}  // namespace

bool heap_code_fits(const pq::HeapRecord& record) noexcept {
    if (record.panels().size() != 1) return false;
    const QueueFamily family = record.panels().front().kind.family;
    return family == QueueFamily::binary || family == QueueFamily::dary ||
           family == QueueFamily::indexed;
}

std::vector<view::CodeLineView> heap_code(HeapOp::Kind op, pq::Orientation orientation) {
    std::vector<view::CodeLineView> out;
    for (Line& line : listing(op, orientation)) out.push_back({line.indent, std::move(line.text)});
    return out;
}

std::optional<std::size_t> heap_code_line(const pq::HeapPanel& panel, HeapOp::Kind op,
                                          pq::Orientation orientation, const pq::PanelOp& done,
                                          std::size_t s) {
    const Role role = role_of(panel, op, orientation, done, s);
    if (role == Role::none) return std::nullopt;
    const std::vector<Line> lines = listing(op, orientation);
    for (std::size_t k = 0; k < lines.size(); ++k) {
        if (lines[k].role == role) return k;
    }
    return std::nullopt;
}

}  // namespace collide::show
