#include "collide/sim/pq/trace.hpp"

#include <algorithm>
#include <cctype>
#include <functional>
#include <iterator>
#include <memory>
#include <set>
#include <utility>

#include "collide/error.hpp"
#include "collide/sim/pq/with_queue.hpp"
#include "pq/tokens.hpp"

namespace collide::pq {

namespace {

using tokens::is_integer;
using tokens::is_word;

[[noreturn]] void reject_token(std::string_view option, std::size_t token,
                               std::string_view spelling, const std::string& why) {
    tokens::reject(option, token, spelling, why);
}

/// A key from a token already known to be a word or an integer.
TraceKey key_from(std::string_view spelling, std::string_view option, std::size_t token) {
    if (is_word(spelling) && spelling.size() > max_trace_key_length) {
        reject_token(option, token, std::string(spelling.substr(0, max_trace_key_length)) + "...",
                     "a word of " + std::to_string(spelling.size()) + " letters; at most " +
                         std::to_string(max_trace_key_length));
    }
    const std::optional<TraceKey> key = tokens::key_of(spelling);
    if (!key) reject_token(option, token, spelling, "integer out of range");
    return *key;
}

/// One implementation of the trace behind a common interface, so that every queue can take
/// each operation in turn (the table is produced row by row, not column by column).
class TraceQueue {
  public:
    TraceQueue() = default;
    virtual ~TraceQueue() = default;
    TraceQueue(const TraceQueue&) = delete;
    TraceQueue& operator=(const TraceQueue&) = delete;

    virtual void push(const TraceKey& key) = 0;
    virtual TraceKey pop() = 0;
    /// Replaces `out` with the text of the array's first `count` entries (fewer if it is shorter).
    virtual void first_entries(std::size_t count, std::vector<std::string>& out) const = 0;
};

template <class Q>
class TraceQueueOf final : public TraceQueue {
  public:
    explicit TraceQueueOf(Q queue) : queue_(std::move(queue)) {}

    void push(const TraceKey& key) override { queue_.push(key); }
    TraceKey pop() override { return queue_.pop(); }
    void first_entries(std::size_t count, std::vector<std::string>& out) const override {
        out.clear();
        const std::size_t shown = std::min(count, queue_.size());
        for (std::size_t i = 0; i < shown; ++i) out.push_back(entry(i).text());
    }

  private:
    /// The array's entry i without copying the array (the indexed queue's array() builds one).
    const TraceKey& entry(std::size_t i) const {
        if constexpr (requires { queue_.heap().key_at(i); }) {
            return queue_.heap().key_at(i);
        } else {
            return queue_.array()[i];
        }
    }

    Q queue_;
};

template <Orientation O>
std::unique_ptr<TraceQueue> make_trace_queue(const QueueKind& kind) {
    return with_queue<TraceKey, O, std::less<TraceKey>>(
        kind, [](auto queue) -> std::unique_ptr<TraceQueue> {
            return std::make_unique<TraceQueueOf<decltype(queue)>>(std::move(queue));
        });
}

std::vector<std::unique_ptr<TraceQueue>> make_trace_queues(std::span<const QueueKind> kinds,
                                                           Orientation orientation) {
    std::vector<std::unique_ptr<TraceQueue>> queues;
    for (const QueueKind& kind : kinds) {
        queues.push_back(orientation == Orientation::max
                             ? make_trace_queue<Orientation::max>(kind)
                             : make_trace_queue<Orientation::min>(kind));
    }
    return queues;
}

/// Removes from every queue, checking each against the model's answer (a mismatch is a bug).
void remove_from_all(std::span<const std::unique_ptr<TraceQueue>> queues,
                     std::span<const QueueKind> kinds, const TraceOp& op,
                     const std::string& expected) {
    for (std::size_t q = 0; q < queues.size(); ++q) {
        const std::string got = queues[q]->pop().text();
        if (got != expected) {
            throw_runtime_error("pq trace: " + to_string(kinds[q]) + " returned '" + got +
                                "' at token " + std::to_string(op.token) + ", expected '" +
                                expected + "'");
        }
    }
}

}  // namespace

std::vector<TraceOp> parse_trace_ops(std::string_view ops, std::string_view option) {
    const std::vector<std::string_view> words = tokens::split(ops);
    if (words.empty())
        throw_input_error(std::string(option) + ": no operations given (e.g. \"P Q E * X\")");
    if (words.size() > max_trace_operations) {
        throw_input_error(std::string(option) + ": " + std::to_string(words.size()) +
                          " operations; at most " + std::to_string(max_trace_operations) +
                          " (a trace is a table to read, one row per operation)");
    }
    std::vector<TraceOp> out;
    out.reserve(words.size());
    tokens::KeyKindCheck kinds(option);
    for (std::size_t i = 0; i < words.size(); ++i) {
        TraceOp op;
        op.token = i + 1;
        op.spelling = std::string(words[i]);
        if (words[i] == "*") {
            op.remove = true;
        } else if (is_word(words[i]) || is_integer(words[i])) {
            op.key = key_from(words[i], option, op.token);
            kinds.check(op.key, op.token, op.spelling);
        } else {
            reject_token(option, op.token, op.spelling,
                         "not a key (a word of letters or an integer) nor '*' (remove)");
        }
        out.push_back(std::move(op));
    }
    return out;
}

std::vector<QueueKind> default_trace_queues() {
    return {{QueueFamily::unordered, 0},
            {QueueFamily::ordered, 0},
            {QueueFamily::binary, 2},
            {QueueFamily::dary, 3},
            {QueueFamily::indexed, default_indexed_arity}};
}

std::size_t peak_trace_size(std::span<const TraceOp> ops, std::string_view option) {
    std::size_t size = 0;
    std::size_t peak = 0;
    for (const TraceOp& op : ops) {
        if (!op.remove) {
            peak = std::max(peak, ++size);
        } else if (size == 0) {
            reject_token(option, op.token, op.spelling, "removes from an empty queue");
        } else {
            --size;
        }
    }
    return peak;
}

void for_each_trace_row(std::span<const TraceOp> ops, Orientation orientation,
                        std::span<const QueueKind> queues, std::size_t max_entries,
                        const TraceVisitor& visit, std::string_view option) {
    (void)peak_trace_size(ops, option);  // input errors before the first row
    const std::vector<std::unique_ptr<TraceQueue>> columns = make_trace_queues(queues, orientation);
    std::multiset<TraceKey> model;  // the reference: what comes out next, and the size
    TraceRow row;
    row.contents.resize(queues.size());
    for (const TraceOp& op : ops) {
        row.argument.clear();
        row.returned.clear();
        if (op.remove) {
            row.operation = orientation == Orientation::max ? "remove max" : "remove min";
            const auto next =
                orientation == Orientation::max ? std::prev(model.end()) : model.begin();
            row.returned = next->text();
            model.erase(next);
            remove_from_all(columns, queues, op, row.returned);
        } else {
            row.operation = "insert";
            row.argument = op.key.text();
            model.insert(op.key);
            for (const auto& column : columns) column->push(op.key);
        }
        row.size = model.size();
        for (std::size_t q = 0; q < columns.size(); ++q)
            columns[q]->first_entries(max_entries, row.contents[q]);
        visit(row);
    }
}

Trace run_trace(std::span<const TraceOp> ops, Orientation orientation,
                std::span<const QueueKind> queues, std::string_view option) {
    Trace trace;
    trace.queues.assign(queues.begin(), queues.end());
    trace.rows.reserve(ops.size());
    for_each_trace_row(
        ops, orientation, queues, all_trace_entries,
        [&trace](const TraceRow& row) { trace.rows.push_back(row); }, option);
    return trace;
}

}  // namespace collide::pq
