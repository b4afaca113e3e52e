/// `collide pq`: the lecture's priority-queue trace table, for the classroom or for slides.
/// The trace itself (operations run on each implementation) comes from collide_sim; this file
/// only reads the options and lays the table out as text, CSV or Markdown.

#include <fmt/core.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "collide/sim/pq/trace.hpp"
#include "commands.hpp"

namespace collide::app {

namespace {

struct PqOptions {
    std::string ops;
    bool min = false;
    std::vector<std::string> impls;  ///< empty: every implementation
    std::string format = "text";
};

using Table = std::vector<std::vector<std::string>>;  ///< rows of cells; row 0 is the header

std::string join(const std::vector<std::string>& items, const char* separator) {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (i > 0) out += separator;
        out += items[i];
    }
    return out;
}

Table table_of(const pq::Trace& trace) {
    Table table;
    std::vector<std::string> header{"operation", "argument", "return", "size"};
    for (const pq::QueueKind& kind : trace.queues) header.push_back(pq::to_string(kind));
    table.push_back(std::move(header));
    for (const pq::TraceRow& row : trace.rows) {
        std::vector<std::string> cells{row.operation, row.argument, row.returned,
                                       std::to_string(row.size)};
        for (const auto& array : row.contents) cells.push_back(join(array, " "));
        table.push_back(std::move(cells));
    }
    return table;
}

/// Columns padded to their widest cell, two spaces apart, a rule under the header.
std::string as_text(const Table& table) {
    std::vector<std::size_t> width(table.front().size(), 0);
    for (const auto& row : table) {
        for (std::size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], row[c].size());
    }
    std::string out;
    const auto add_line = [&](const std::vector<std::string>& cells) {
        std::string line;
        for (std::size_t c = 0; c < cells.size(); ++c)
            line += fmt::format("{:<{}}  ", cells[c], width[c]);
        line.erase(line.find_last_not_of(' ') + 1);  // no trailing blanks
        out += line + '\n';
    };
    add_line(table.front());
    std::vector<std::string> rule;
    for (std::size_t w : width) rule.emplace_back(w, '-');
    add_line(rule);
    for (std::size_t r = 1; r < table.size(); ++r) add_line(table[r]);
    return out;
}

/// RFC 4180: quote a field holding a comma, quote or line break; double inner quotes.
std::string csv_field(const std::string& cell) {
    if (cell.find_first_of(",\"\n\r") == std::string::npos) return cell;
    std::string out = "\"";
    for (char ch : cell) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    return out + '"';
}

std::string as_csv(const Table& table) {
    std::string out;
    for (const auto& row : table) {
        std::vector<std::string> fields;
        for (const auto& cell : row) fields.push_back(csv_field(cell));
        out += join(fields, ",") + '\n';
    }
    return out;
}

std::string as_markdown(const Table& table) {
    const auto line = [](const std::vector<std::string>& cells) {
        return "| " + join(cells, " | ") + " |\n";
    };
    std::string out = line(table.front());
    out += line(std::vector<std::string>(table.front().size(), "---"));
    for (std::size_t r = 1; r < table.size(); ++r) out += line(table[r]);
    return out;
}

void run_pq(const PqOptions& options) {
    const std::vector<pq::TraceOp> ops = pq::parse_trace_ops(options.ops, "--ops");
    std::vector<pq::QueueKind> kinds;
    for (const std::string& impl : options.impls)
        kinds.push_back(pq::parse_queue_kind(impl, "--impl"));
    if (kinds.empty()) kinds = pq::default_trace_queues();
    const auto orientation = options.min ? pq::Orientation::min : pq::Orientation::max;
    const Table table = table_of(pq::run_trace(ops, orientation, kinds, "--ops"));

    std::string text;
    if (options.format == "csv") {
        text = as_csv(table);
    } else if (options.format == "markdown") {
        text = as_markdown(table);
    } else {
        text = as_text(table);
    }
    std::fputs(text.c_str(), stdout);
}

}  // namespace

void add_pq_command(CLI::App& root) {
    auto options = std::make_shared<PqOptions>();
    CLI::App* pq = root.add_subcommand(
        "pq",
        "Trace the lecture's priority queues: insert keys, '*' removes the max (or min), "
        "one table row per operation with every implementation's array");
    pq->add_option(
          "--ops", options->ops,
          "Operations separated by spaces: a word of letters or an integer inserts it, '*' "
          "removes; keys must be all words (byte order: A < Z < a) or all integers, "
          "e.g. \"P Q E * X A M * P L E *\"")
        ->required();
    pq->add_flag("--min", options->min,
                 "A min-queue ('*' removes the smallest) instead of a max-queue");
    pq->add_option("--impl", options->impls,
                   "Implementations to show, repeatable or comma-separated: "
                   "unordered|ordered|binary|dary:D|indexed[:D] (default: unordered, ordered, "
                   "binary, dary:3, indexed)")
        ->delimiter(',');
    pq->add_option("--format", options->format, "Table format: text, csv or markdown")
        ->check(CLI::IsMember({"text", "csv", "markdown"}))
        ->capture_default_str();
    pq->callback([options] { run_pq(*options); });
}

}  // namespace collide::app
