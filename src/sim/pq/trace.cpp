#include "collide/sim/pq/trace.hpp"

#include <cctype>
#include <charconv>
#include <functional>
#include <set>
#include <system_error>
#include <utility>

#include "collide/error.hpp"

namespace collide::pq {

namespace {

[[noreturn]] void reject_token(std::string_view option, std::size_t token,
                               std::string_view spelling, const std::string& why) {
    throw_input_error(std::string(option) + ": token " + std::to_string(token) + " '" +
                      std::string(spelling) + "': " + why);
}

bool is_word(std::string_view s) {
    if (s.empty()) return false;
    for (char c : s) {
        if (std::isalpha(static_cast<unsigned char>(c)) == 0) return false;
    }
    return true;
}

bool is_integer(std::string_view s) {
    if (!s.empty() && (s.front() == '+' || s.front() == '-')) s.remove_prefix(1);
    if (s.empty()) return false;
    for (char c : s) {
        if (std::isdigit(static_cast<unsigned char>(c)) == 0) return false;
    }
    return true;
}

/// A key from a token already known to be a word or an integer.
TraceKey key_from(std::string_view spelling, std::string_view option, std::size_t token) {
    TraceKey key;
    if (is_word(spelling)) {
        key.word = std::string(spelling);
        return key;
    }
    key.numeric = true;
    std::string_view digits = spelling;
    if (digits.front() == '+') digits.remove_prefix(1);  // from_chars takes '-' but not '+'
    const auto [end, ec] =
        std::from_chars(digits.data(), digits.data() + digits.size(), key.number);
    if (ec != std::errc{} || end != digits.data() + digits.size()) {
        reject_token(option, token, spelling, "integer out of range");
    }
    return key;
}

const char* type_name(const TraceKey& key) {
    return key.numeric ? "a number" : "a word";
}

/// Splits at ASCII white space.
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

std::vector<std::string> texts_of(const auto& keys) {
    std::vector<std::string> out;
    out.reserve(keys.size());
    for (const TraceKey& k : keys) out.push_back(k.text());
    return out;
}

/// The reference model's view of the trace: operation, argument, return value and size.
std::vector<TraceRow> model_rows(std::span<const TraceOp> ops, Orientation orientation,
                                 std::string_view option) {
    std::multiset<TraceKey> model;
    std::vector<TraceRow> rows;
    rows.reserve(ops.size());
    for (const TraceOp& op : ops) {
        TraceRow row;
        if (op.remove) {
            row.operation = orientation == Orientation::max ? "remove max" : "remove min";
            if (model.empty())
                reject_token(option, op.token, op.spelling, "removes from an empty queue");
            const auto next =
                orientation == Orientation::max ? std::prev(model.end()) : model.begin();
            row.returned = next->text();
            model.erase(next);
        } else {
            row.operation = "insert";
            row.argument = op.key.text();
            model.insert(op.key);
        }
        row.size = model.size();
        rows.push_back(std::move(row));
    }
    return rows;
}

/// Runs the operations on one queue, appending its array to every row's contents and checking
/// each removal against the model's.
template <Orientation O>
void add_queue_column(const QueueKind& kind, std::span<const TraceOp> ops,
                      std::vector<TraceRow>& rows) {
    with_queue<TraceKey, O, std::less<TraceKey>>(kind, [&](auto q) {
        for (std::size_t i = 0; i < ops.size(); ++i) {
            if (ops[i].remove) {
                const std::string got = q.pop().text();
                if (got != rows[i].returned) {
                    throw_runtime_error("pq trace: " + to_string(kind) + " returned '" + got +
                                        "' at token " + std::to_string(ops[i].token) +
                                        ", expected '" + rows[i].returned + "'");
                }
            } else {
                q.push(ops[i].key);
            }
            rows[i].contents.push_back(texts_of(q.array()));
        }
    });
}

}  // namespace

std::vector<TraceOp> parse_trace_ops(std::string_view ops, std::string_view option) {
    const std::vector<std::string_view> tokens = split_tokens(ops);
    if (tokens.empty())
        throw_input_error(std::string(option) + ": no operations given (e.g. \"P Q E * X\")");
    std::vector<TraceOp> out;
    out.reserve(tokens.size());
    std::size_t first_key = tokens.size();  // index in `out` of the first key; none yet
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        TraceOp op;
        op.token = i + 1;
        op.spelling = std::string(tokens[i]);
        if (tokens[i] == "*") {
            op.remove = true;
        } else if (is_word(tokens[i]) || is_integer(tokens[i])) {
            op.key = key_from(tokens[i], option, op.token);
        } else {
            reject_token(option, op.token, op.spelling,
                         "not a key (a word of letters or an integer) nor '*' (remove)");
        }
        out.push_back(std::move(op));
        if (out.back().remove) continue;
        if (first_key == tokens.size()) {
            first_key = i;
        } else if (out.back().key.numeric != out[first_key].key.numeric) {
            reject_token(option, out.back().token, out.back().spelling,
                         std::string("is ") + type_name(out.back().key) + " but the first key '" +
                             out[first_key].spelling + "' is " + type_name(out[first_key].key) +
                             "; keys must be all words or all numbers");
        }
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

Trace run_trace(std::span<const TraceOp> ops, Orientation orientation,
                std::span<const QueueKind> queues, std::string_view option) {
    Trace trace;
    trace.queues.assign(queues.begin(), queues.end());
    trace.rows = model_rows(ops, orientation, option);
    for (const QueueKind& kind : queues) {
        if (orientation == Orientation::max) {
            add_queue_column<Orientation::max>(kind, ops, trace.rows);
        } else {
            add_queue_column<Orientation::min>(kind, ops, trace.rows);
        }
    }
    return trace;
}

}  // namespace collide::pq
