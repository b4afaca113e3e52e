/// `collide puzzle`: breadth-first search against A* on the sliding puzzle (the second lecture's
/// application of priority queues), as text (`--solve`), JSON (`--json`) or a side-by-side video.
/// The board and every option are validated, and both searches run (within their node budget),
/// before anything is printed or drawn; the searches live in collide_sim (sim/puzzle/). Compiled
/// into both programs: `collide` answers --solve and --json itself, and hands a video to
/// collide-draw (PuzzleVideoMaker, puzzle_options.hpp).

#include <fmt/core.h>

#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli_numbers.hpp"
#include "cli_types.hpp"
#include "collide/error.hpp"
#include "collide/show/puzzle_program.hpp"
#include "collide/sim/pq/queue_kind.hpp"
#include "collide/sim/puzzle/board.hpp"
#include "collide/sim/puzzle/search.hpp"
#include "commands.hpp"
#include "json_output.hpp"
#include "puzzle_options.hpp"

namespace collide::app {

namespace {

using puzzle::Board;
using puzzle::SearchResult;

/// Raw option values as CLI11 stores them.
struct PuzzleCli {
    std::string board;
    int moves = 20;
    std::uint64_t seed = 1;
    int side = 3;
    std::string heuristic = "manhattan";
    std::string pq = "binary";
    std::string method = "both";
    std::uint64_t max_nodes = puzzle::SearchLimits{}.max_nodes;
    bool solve = false;
    bool json = false;
    PuzzleVideoCli video;

    CLI::Option* method_opt = nullptr;
    CLI::Option* moves_opt = nullptr;
    CLI::Option* seed_opt = nullptr;
    CLI::Option* side_opt = nullptr;
};

Board start_board(const PuzzleCli& v) {
    if (v.board == "random") return puzzle::random_board(v.side, v.moves, v.seed, "--moves");
    for (const CLI::Option* o : {v.moves_opt, v.seed_opt, v.side_opt}) {
        if (given(o)) {
            throw_input_error(o->get_name() + ": only for `collide puzzle random` (the board \"" +
                              v.board + "\" is given)");
        }
    }
    return Board::parse(v.board, "board");
}

void require_solvable(const Board& board) {
    if (board.solvable()) return;
    throw_input_error("board \"" + board.to_string() +
                      "\" cannot be solved: " + board.unsolvable_reason());
}

/// What to try when a search hit a budget; the caller's options decide which advice fits.
[[noreturn]] void budget_error(const SearchResult& r, const PuzzleCli& v) {
    const std::string who = r.method == puzzle::Method::bfs
                                ? std::string("BFS")
                                : fmt::format("A* ({}, --pq {})", puzzle::to_string(r.heuristic),
                                              pq::to_string(r.queue));
    if (r.status == puzzle::SearchStatus::work_exceeded) {
        throw_input_error(fmt::format(
            "--pq {}: {} stopped after {} expansions without reaching the goal: the array "
            "queue's O(N) scans would take too long (the limit is {} entries scanned); use a "
            "heap (--pq binary or dary:4) or a board fewer moves from the goal",
            pq::to_string(r.queue), who, show::with_thousands(r.stats.expanded),
            show::with_thousands(puzzle::SearchLimits{}.max_scan_work)));
    }
    std::string advice;
    if (r.method == puzzle::Method::bfs && v.method == "both")
        advice = "show A* alone (--method astar), ";
    if (r.method == puzzle::Method::astar && r.heuristic == puzzle::Heuristic::hamming)
        advice = "use --heuristic manhattan, ";
    throw_input_error(fmt::format(
        "--max-nodes: {} stopped after storing {} boards (the node budget, about {} MB) without "
        "reaching the goal, {} moves deep; {}give a board fewer moves from the goal, or raise "
        "--max-nodes (at most {}, about {} bytes a board)",
        who, show::with_thousands(r.stats.enqueued),
        v.max_nodes * puzzle::bytes_per_node / 1'000'000,
        r.nodes.empty() ? 0 : r.nodes.back().moves, advice,
        show::with_thousands(puzzle::max_node_budget), puzzle::bytes_per_node));
}

/// The searches' settings, read from the options before anything runs.
struct SearchSettings {
    puzzle::Heuristic heuristic = puzzle::Heuristic::manhattan;
    pq::QueueKind queue{};
};

/// The searches to run: --method's, except that --code shows one (A* unless --method bfs):
/// the listing and its marked line go beside a single search tree.
std::string method_of(const PuzzleCli& v) {
    if (!v.video.code || v.json || v.solve) return v.method;
    if (!given(v.method_opt)) return "astar";
    if (v.method == "both") {
        throw_option_error("--code",
                           "shows the search loop beside one search; give --method "
                           "astar or --method bfs, or leave out --code to compare both");
    }
    return v.method;
}

std::vector<SearchResult> run_searches(const Board& start, const SearchSettings& settings,
                                       const PuzzleCli& v) {
    const puzzle::Heuristic heuristic = settings.heuristic;
    const pq::QueueKind queue = settings.queue;
    puzzle::SearchLimits limits;
    limits.max_nodes = static_cast<std::size_t>(v.max_nodes);
    std::vector<SearchResult> results;
    const std::string method = method_of(v);
    if (method != "astar") results.push_back(puzzle::breadth_first(start, limits));
    if (method != "bfs") results.push_back(puzzle::a_star(start, heuristic, queue, limits));
    for (const SearchResult& r : results) {
        if (!r.solved()) budget_error(r, v);
    }
    return results;
}

std::string method_title(const SearchResult& r) {
    if (r.method == puzzle::Method::bfs) return "BFS (FIFO queue)";
    return fmt::format("A* ({}, {})", puzzle::to_string(r.heuristic), pq::to_string(r.queue));
}

std::string moves_text(const SearchResult& r) {
    std::string out;
    for (const puzzle::Move& m : r.solution_moves()) {
        out +=
            fmt::format("{}{} {}", out.empty() ? "" : ", ", m.tile, puzzle::to_string(m.direction));
    }
    return out.empty() ? "(none: the board is solved)" : out;
}

void print_text(const Board& start, const std::vector<SearchResult>& results) {
    std::printf("board %s (%dx%d): manhattan %d, hamming %d\n", start.to_string().c_str(),
                start.side(), start.side(), puzzle::manhattan(start), puzzle::hamming(start));
    std::size_t title_width = 6;
    for (const SearchResult& r : results)
        title_width = std::max(title_width, method_title(r).size());
    std::printf("%s\n", fmt::format("{:<{}}  {:>9}  {:>9}  {:>13}  {:>5}", "method", title_width,
                                    "expanded", "enqueued", "largest queue", "moves")
                            .c_str());
    for (const SearchResult& r : results) {
        std::printf("%s\n",
                    fmt::format("{:<{}}  {:>9}  {:>9}  {:>13}  {:>5}", method_title(r), title_width,
                                show::with_thousands(r.stats.expanded),
                                show::with_thousands(r.stats.enqueued),
                                show::with_thousands(r.stats.max_queue), r.solution_length())
                        .c_str());
    }
    for (const SearchResult& r : results) {
        std::printf("%s: %s\n", std::string(puzzle::to_string(r.method)).c_str(),
                    moves_text(r).c_str());
    }
}

Json json_moves(const SearchResult& r) {
    Json moves = Json::array();
    for (const puzzle::Move& m : r.solution_moves()) {
        moves.push_back(Json{{"tile", m.tile}, {"direction", puzzle::to_string(m.direction)}});
    }
    return moves;
}

void print_json(const Board& start, const std::vector<SearchResult>& results) {
    Json methods = Json::array();
    for (const SearchResult& r : results) {
        Json method{{"method", r.method == puzzle::Method::bfs ? "bfs" : "astar"}};
        if (r.method == puzzle::Method::astar) {
            method["heuristic"] = puzzle::to_string(r.heuristic);
            method["pq"] = pq::to_string(r.queue);
        }
        method["expanded"] = r.stats.expanded;
        method["enqueued"] = r.stats.enqueued;
        method["max_queue"] = r.stats.max_queue;
        method["stale"] = r.stats.stale;
        method["parent_skips"] = r.stats.parent_skips;
        method["solution_length"] = r.solution_length();
        method["moves"] = json_moves(r);
        methods.push_back(std::move(method));
    }
    const Json document{{"board", start.to_string()},
                        {"side", start.side()},
                        {"manhattan", puzzle::manhattan(start)},
                        {"hamming", puzzle::hamming(start)},
                        {"methods", std::move(methods)}};
    std::fputs(json_text(document).c_str(), stdout);
}

void run(const PuzzleCli& v, const PuzzleVideoMaker& video) {
    if (v.method != "both" && v.method != "bfs" && v.method != "astar")
        throw_input_error("--method: expected both, bfs or astar, got '" + v.method + "'");
    const Board start = start_board(v);
    require_solvable(start);
    const SearchSettings settings{puzzle::parse_heuristic(v.heuristic, "--heuristic"),
                                  pq::parse_queue_kind(v.pq, "--pq")};
    if (v.json || v.solve) {
        refuse_video_options(v.video, v.json ? "--json" : "--solve");
    } else {
        (void)method_of(v);  // --code with both searches: refused before collide-draw starts
        video.check(v.video);
    }
    const std::vector<SearchResult> results = run_searches(start, settings, v);
    if (v.json) {
        print_json(start, results);
    } else if (v.solve) {
        print_text(start, results);
    } else {
        video.draw(start, results, v.video);
    }
}

}  // namespace

void add_puzzle_command(CLI::App& root, PuzzleVideoMaker video) {
    auto v = std::make_shared<PuzzleCli>();
    CLI::App* cmd = root.add_subcommand(
        "puzzle",
        "Breadth-first search against A* on the 8-puzzle (n x n up to 4x4), side by side");
    cmd->add_option("board", v->board,
                    "The board, row by row, 0 or _ for the blank (\"1 2 3 4 0 6 7 5 8\"; 4, 9 "
                    "or 16 tiles), or `random` (see --moves, --seed, --side)")
        ->required()
        ->type_name(board_type);
    v->moves_opt = add_whole_option(*cmd, "--moves", v->moves, 0, puzzle::max_random_moves,
                                    "random: moves of the blank from the goal (default 20)");
    v->seed_opt = add_whole_option(*cmd, "--seed", v->seed, 0, UINT64_MAX,
                                   "random: the seed (default 1); the same seed, the same board");
    v->side_opt = add_whole_option(*cmd, "--side", v->side, puzzle::min_side, puzzle::max_side,
                                   "random: the board's side, 2..4 (default 3)");
    cmd->add_option("--heuristic", v->heuristic,
                    "A*'s estimate of the moves left: manhattan or hamming")
        ->capture_default_str()
        ->type_name("{manhattan,hamming}");
    cmd->add_option("--pq", v->pq,
                    "A*'s priority queue: unordered|ordered|binary|dary:D|indexed[:D]")
        ->capture_default_str()
        ->type_name(queue_kind_type);
    v->method_opt = cmd->add_option("--method", v->method,
                                    "both (BFS and A*), bfs or astar (with --code: astar)")
                        ->capture_default_str()
                        ->type_name("{both,bfs,astar}");
    add_whole_option(*cmd, "--max-nodes", v->max_nodes, 1, puzzle::max_node_budget,
                     fmt::format("Node budget per search: boards stored at most (about {} bytes "
                                 "each); a search that needs more stops with exit 2 (default {})",
                                 puzzle::bytes_per_node, puzzle::SearchLimits{}.max_nodes));
    cmd->add_flag("--solve", v->solve,
                  "Print the moves and each method's counts as text instead of a video");
    cmd->add_flag("--json", v->json, "Print the same as JSON instead of a video");
    add_puzzle_video_options(*cmd, v->video);
    cmd->footer(
        "Examples:\n"
        "  collide puzzle \"1 2 3 4 0 6 7 5 8\" -o puzzle.mp4   # BFS (left) vs A* (right)\n"
        "  collide puzzle \"8 1 3 4 0 2 7 6 5\" --heuristic hamming --solve\n"
        "  collide puzzle random --moves 14 --code -o astar.mp4   # A*'s loop as code\n"
        "  collide puzzle random --moves 14 --questions on   # which board comes out next?\n"
        "  collide puzzle random --moves 20 --seed 3 --json\n"
        "See docs/puzzle.md.");
    cmd->callback([v, video = std::move(video)] { run(*v, video); });
}

}  // namespace collide::app
