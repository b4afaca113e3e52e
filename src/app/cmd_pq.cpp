/// `collide pq`: the lecture's priority-queue trace table, for the classroom or for slides.
/// The trace itself (operations run on each implementation) comes from collide_sim; this file
/// only reads the options and lays the table out as text, CSV or Markdown, row by row as the
/// trace runs, so memory and output stay linear in the number of operations.

#include <fmt/core.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "cli_types.hpp"
#include "collide/error.hpp"
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

/// Entries of each array printed per row: a lecture's arrays stay far below (a five-level binary
/// heap holds 31); longer ones end in "... (+N more)" so that a row's width does not grow with
/// the input. The header says so when it happens.
constexpr std::size_t shown_entries = 32;

/// Implementations per table (each is a column; a lecture compares a handful).
constexpr std::size_t max_impls = 16;

using Cells = std::vector<std::string>;

std::string join(const Cells& items, const char* separator) {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (i > 0) out += separator;
        out += items[i];
    }
    return out;
}

/// The table's layout, known before the first row: its columns and whether arrays are cut short.
struct TableShape {
    std::vector<pq::QueueKind> queues;
    bool cut_short = false;  ///< some array grows beyond shown_entries

    [[nodiscard]] Cells header() const {
        Cells cells{"operation", "argument", "return", "size"};
        for (const pq::QueueKind& kind : queues) {
            cells.push_back(pq::to_string(kind) +
                            (cut_short ? fmt::format(" (first {})", shown_entries) : ""));
        }
        return cells;
    }
};

Cells cells_of(const pq::TraceRow& row) {
    Cells cells{row.operation, row.argument, row.returned, std::to_string(row.size)};
    for (const auto& array : row.contents) {
        std::string cell = join(array, " ");
        if (array.size() < row.size)
            cell += fmt::format(" ... (+{} more)", row.size - array.size());
        cells.push_back(std::move(cell));
    }
    return cells;
}

/// Produces the table row by row (header first); nothing is kept between rows.
using RowSink = std::function<void(const Cells&)>;

/// One trace run: the header, then each operation's row, handed to `sink`.
struct TableSource {
    const std::vector<pq::TraceOp>& ops;
    pq::Orientation orientation;
    TableShape shape;

    void stream(const RowSink& sink) const {
        sink(shape.header());
        pq::for_each_trace_row(
            ops, orientation, shape.queues, shown_entries,
            [&sink](const pq::TraceRow& row) { sink(cells_of(row)); }, "--ops");
    }
};

void print(const std::string& line) {
    std::fputs(line.c_str(), stdout);
}

/// Columns padded to their widest cell, two spaces apart, a rule under the header. The widths
/// need every row: the trace runs twice (measure, then print) rather than keeping the rows.
void print_text(const TableSource& table) {
    std::vector<std::size_t> width;
    table.stream([&width](const Cells& cells) {
        width.resize(cells.size(), 0);
        for (std::size_t c = 0; c < cells.size(); ++c)
            width[c] = std::max(width[c], cells[c].size());
    });
    const auto print_line = [&width](const Cells& cells) {
        std::string line;
        for (std::size_t c = 0; c < cells.size(); ++c)
            line += fmt::format("{:<{}}  ", cells[c], width[c]);
        line.erase(line.find_last_not_of(' ') + 1);  // no trailing blanks
        print(line + '\n');
    };
    bool header = true;
    table.stream([&](const Cells& cells) {
        print_line(cells);
        if (!header) return;
        header = false;
        Cells rule;
        for (std::size_t w : width) rule.emplace_back(w, '-');
        print_line(rule);
    });
}

/// RFC 4180: quote a field holding a comma, quote or line break; double inner quotes.
std::string csv_field(const std::string& cell) {
    if (cell.find_first_of(",\"\n\r") == std::string::npos) return cell;
    std::string out = "\"";
    for (char ch : cell) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    return out + '"';
}

void print_csv(const TableSource& table) {
    table.stream([](const Cells& cells) {
        Cells fields;
        for (const auto& cell : cells) fields.push_back(csv_field(cell));
        print(join(fields, ",") + '\n');
    });
}

void print_markdown(const TableSource& table) {
    bool header = true;
    table.stream([&header](const Cells& cells) {
        print("| " + join(cells, " | ") + " |\n");
        if (!header) return;
        header = false;
        print("| " + join(Cells(cells.size(), "---"), " | ") + " |\n");
    });
}

std::vector<pq::QueueKind> queues_of(const std::vector<std::string>& impls) {
    if (impls.size() > max_impls) {
        throw_option_error("--impl", fmt::format("{} implementations; at most {} (one column each)",
                                                 impls.size(), max_impls));
    }
    std::vector<pq::QueueKind> kinds;
    for (const std::string& impl : impls) kinds.push_back(pq::parse_queue_kind(impl, "--impl"));
    if (kinds.empty()) kinds = pq::default_trace_queues();
    return kinds;
}

void run_pq(const PqOptions& options) {
    const std::vector<pq::TraceOp> ops = pq::parse_trace_ops(options.ops, "--ops");
    TableShape shape;
    shape.queues = queues_of(options.impls);
    shape.cut_short = pq::peak_trace_size(ops, "--ops") > shown_entries;
    const TableSource table{ops, options.min ? pq::Orientation::min : pq::Orientation::max,
                            std::move(shape)};
    if (options.format == "csv") {
        print_csv(table);
    } else if (options.format == "markdown") {
        print_markdown(table);
    } else {
        print_text(table);
    }
}

}  // namespace

void add_pq_command(CLI::App& root) {
    auto options = std::make_shared<PqOptions>();
    CLI::App* pq = root.add_subcommand(
        "pq",
        fmt::format("Trace the lecture's priority queues: insert keys, '*' removes the max (or "
                    "min), one table row per operation with every implementation's array (its "
                    "first {} entries, then '... (+N more)')",
                    shown_entries));
    pq->add_option(
          "--ops", options->ops,
          fmt::format("Operations separated by spaces: a word of letters or an integer inserts "
                      "it, '*' removes; keys must be all words (byte order: A < Z < a) or all "
                      "integers, e.g. \"P Q E * X A M * P L E *\"; at most {} operations, words "
                      "of at most {} letters",
                      pq::max_trace_operations, pq::max_trace_key_length))
        ->required()
        ->type_name(operations_type);
    pq->add_flag("--min", options->min,
                 "A min-queue ('*' removes the smallest) instead of a max-queue");
    pq->add_option("--impl", options->impls,
                   fmt::format("Implementations to show, repeatable or comma-separated: "
                               "unordered|ordered|binary|dary:D|indexed[:D] (default: unordered, "
                               "ordered, binary, dary:3, indexed); at most {}",
                               max_impls))
        ->delimiter(',')
        ->type_name(queue_kind_type);
    pq->add_option("--format", options->format, "Table format: text, csv or markdown")
        ->check(CLI::IsMember({"text", "csv", "markdown"}))
        ->capture_default_str()
        ->type_name("{text,csv,markdown}");  // the choices, without IsMember's "TEXT:"
    pq->callback([options] { run_pq(*options); });
}

}  // namespace collide::app
