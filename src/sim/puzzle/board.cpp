#include "collide/sim/puzzle/board.hpp"

#include <cstddef>
#include <random>
#include <string>
#include <vector>

#include "collide/error.hpp"

namespace collide::puzzle {

namespace {

std::string quoted(std::string_view text) {
    return "'" + std::string(text) + "'";
}

std::vector<std::string_view> split_tokens(std::string_view text) {
    std::vector<std::string_view> tokens;
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\n')) ++i;
        const std::size_t start = i;
        while (i < text.size() && text[i] != ' ' && text[i] != '\t' && text[i] != '\n') ++i;
        if (i > start) tokens.push_back(text.substr(start, i - start));
    }
    return tokens;
}

int side_for_count(std::size_t count) {
    for (int side = min_side; side <= max_side; ++side) {
        if (count == static_cast<std::size_t>(side * side)) return side;
    }
    return 0;
}

/// The tile a token names: 0 for `0` or `_`, else 1..cells-1; -1 when it is no number at all,
/// -2 when it is a number out of range.
int tile_of(std::string_view token, int cells) {
    if (token == "_") return 0;
    if (token.empty() || token.size() > 2) {
        for (char c : token) {
            if (c < '0' || c > '9') return -1;
        }
        return -2;
    }
    int value = 0;
    for (char c : token) {
        if (c < '0' || c > '9') return -1;
        value = value * 10 + (c - '0');
    }
    return value < cells ? value : -2;
}

/// "tile 8 is" or "tiles 5, 8 are" (blank: "the blank is"): what the tokens leave out.
std::string missing_tiles(const std::vector<std::string_view>& tokens, int cells) {
    std::vector<bool> present(static_cast<std::size_t>(cells), false);
    for (std::string_view token : tokens) {
        const int tile = tile_of(token, cells);
        if (tile >= 0) present[static_cast<std::size_t>(tile)] = true;
    }
    std::vector<std::string> names;
    for (int t = 1; t < cells; ++t) {
        if (!present[static_cast<std::size_t>(t)]) names.push_back(std::to_string(t));
    }
    if (!present[0]) names.emplace_back("the blank");
    std::string list;
    for (std::size_t i = 0; i < names.size(); ++i) list += (i == 0 ? "" : ", ") + names[i];
    if (names.size() == 1) return (names[0] == "the blank" ? "" : "tile ") + list + " is";
    return "tiles " + list + " are";
}

std::string board_sizes_hint() {
    return "a board has 4 tiles (2x2), 9 (3x3) or 16 (4x4), blank included, e.g. \"1 2 3 4 0 6 "
           "7 5 8\"";
}

}  // namespace

std::string_view to_string(Direction direction) noexcept {
    switch (direction) {
        case Direction::up:
            return "up";
        case Direction::down:
            return "down";
        case Direction::left:
            return "left";
        case Direction::right:
            return "right";
    }
    return "?";
}

Board Board::goal(int side) {
    if (side < min_side || side > max_side) {
        throw_input_error("puzzle: side " + std::to_string(side) + " out of range (" +
                          std::to_string(min_side) + ".." + std::to_string(max_side) + ")");
    }
    const int cells = side * side;
    std::uint64_t packed = 0;
    for (int i = 0; i + 1 < cells; ++i) packed |= static_cast<std::uint64_t>(i + 1) << (4 * i);
    return Board(packed, side, cells - 1);
}

Board Board::parse(std::string_view text, std::string_view option) {
    const std::string where(option);
    const std::vector<std::string_view> tokens = split_tokens(text);
    const int side = side_for_count(tokens.size());
    if (side == 0) {
        std::string why = std::to_string(tokens.size()) + " token" +
                          (tokens.size() == 1 ? "" : "s") + "; " + board_sizes_hint();
        if (tokens.size() > 16) why += " (the 17th token is " + quoted(tokens[16]) + ")";
        throw_input_error(where + ": " + why);
    }
    const int cells = side * side;
    std::vector<int> first_at(static_cast<std::size_t>(cells), 0);  // 1-based token position
    std::uint64_t packed = 0;
    int blank = 0;
    for (int i = 0; i < cells; ++i) {
        const std::string_view token = tokens[static_cast<std::size_t>(i)];
        const std::string at = " (token " + std::to_string(i + 1) + ")";
        const int tile = tile_of(token, cells);
        if (tile == -1) {
            throw_input_error(where + ": " + quoted(token) + at +
                              " is not a tile: tiles are numbers, 0 or _ for the blank");
        }
        if (tile == -2) {
            throw_input_error(where + ": " + quoted(token) + at + " is out of range: a " +
                              std::to_string(side) + "x" + std::to_string(side) +
                              " board has tiles 1.." + std::to_string(cells - 1) +
                              " and one blank (0 or _)");
        }
        auto& seen = first_at[static_cast<std::size_t>(tile)];
        if (seen != 0) {
            const std::string what =
                tile == 0 ? "a second blank" : "tile " + std::to_string(tile) + " again";
            throw_input_error(where + ": " + quoted(token) + at + " is " + what +
                              " (first at token " + std::to_string(seen) + "); " +
                              missing_tiles(tokens, cells) + " missing");
        }
        seen = i + 1;
        if (tile == 0) blank = i;
        packed |= static_cast<std::uint64_t>(tile) << (4 * i);
    }
    // Every token is distinct and in range and there are `cells` of them: nothing is missing.
    return Board(packed, side, blank);
}

Board Board::unpack(std::uint64_t packed, int side) {
    int blank = 0;
    for (int i = 0; i < side * side; ++i) {
        if (((packed >> (4 * i)) & 0xFU) == 0) blank = i;
    }
    return Board(packed, side, blank);
}

int Board::inversions() const noexcept {
    int count = 0;
    for (int i = 0; i < cells(); ++i) {
        const int a = tile(i);
        if (a == 0) continue;
        for (int j = i + 1; j < cells(); ++j) {
            const int b = tile(j);
            if (b != 0 && b < a) ++count;
        }
    }
    return count;
}

bool Board::solvable() const noexcept {
    const int parity = side_ % 2 == 1 ? inversions() : inversions() + blank_ / side_;
    return side_ % 2 == 1 ? parity % 2 == 0 : parity % 2 == 1;
}

std::string Board::unsolvable_reason() const {
    if (solvable()) return {};
    const int inv = inversions();
    const std::string counted = std::to_string(inv) + " inversion" + (inv == 1 ? "" : "s");
    if (side_ % 2 == 1) {
        return "it has " + counted +
               " (pairs of tiles in the wrong order, row by row), an odd number; a move never "
               "changes that parity and the goal has 0, so no sequence of moves solves it "
               "(exchanging two tiles would make it solvable)";
    }
    const int row = blank_ / side_;
    return "it has " + counted + " and the blank is in row " + std::to_string(row) +
           " (0 = top): their sum, " + std::to_string(inv + row) +
           ", is even; on an even-sided board a move never changes that parity and the goal's "
           "is odd, so no sequence of moves solves it (exchanging two tiles would make it "
           "solvable)";
}

Board Board::with_blank_at(int cell) const noexcept {
    const std::uint64_t moved = (packed_ >> (4 * cell)) & 0xFU;
    const std::uint64_t packed =
        (packed_ & ~(std::uint64_t{0xF} << (4 * cell))) | (moved << (4 * blank_));
    return Board(packed, side_, cell);
}

Move Board::move_to(const Board& next) const noexcept {
    // The tile sits where the blank goes and slides towards where the blank was.
    const int to = next.blank_;
    Move move;
    move.tile = tile(to);
    if (to == blank_ - side_) {
        move.direction = Direction::down;
    } else if (to == blank_ + side_) {
        move.direction = Direction::up;
    } else if (to == blank_ - 1) {
        move.direction = Direction::right;
    } else {
        move.direction = Direction::left;
    }
    return move;
}

std::string Board::to_string() const {
    std::string out;
    for (int i = 0; i < cells(); ++i) {
        if (i > 0) out += ' ';
        out += std::to_string(tile(i));
    }
    return out;
}

int hamming(const Board& board) noexcept {
    int count = 0;
    for (int i = 0; i < board.cells(); ++i) {
        const int t = board.tile(i);
        if (t != 0 && t != i + 1) ++count;
    }
    return count;
}

int manhattan(const Board& board) noexcept {
    const int n = board.side();
    int sum = 0;
    for (int i = 0; i < board.cells(); ++i) {
        const int t = board.tile(i);
        if (t == 0) continue;
        const int goal = t - 1;
        const int dr = i / n - goal / n;
        const int dc = i % n - goal % n;
        sum += (dr < 0 ? -dr : dr) + (dc < 0 ? -dc : dc);
    }
    return sum;
}

Heuristic parse_heuristic(std::string_view text, std::string_view option) {
    if (text == "manhattan") return Heuristic::manhattan;
    if (text == "hamming") return Heuristic::hamming;
    throw_input_error(std::string(option) + ": unknown heuristic '" + std::string(text) +
                      "' (expected manhattan or hamming)");
}

std::string_view to_string(Heuristic heuristic) noexcept {
    return heuristic == Heuristic::hamming ? "hamming" : "manhattan";
}

int estimate(Heuristic heuristic, const Board& board) noexcept {
    return heuristic == Heuristic::hamming ? hamming(board) : manhattan(board);
}

Board random_board(int side, int moves, std::uint64_t seed, std::string_view moves_field) {
    if (moves < 0 || moves > max_random_moves) {
        throw_input_error(std::string(moves_field) + ": must be 0.." +
                          std::to_string(max_random_moves) + ", got " + std::to_string(moves));
    }
    Board board = Board::goal(side);
    std::mt19937_64 rng(seed);
    int previous_blank = -1;
    std::vector<Board> choices;
    for (int k = 0; k < moves; ++k) {
        choices.clear();
        board.for_each_neighbour([&](const Board& next, int) {
            if (next.blank() != previous_blank) choices.push_back(next);
        });
        // The raw output, not a std:: distribution: those differ between standard libraries.
        const Board next = choices[static_cast<std::size_t>(rng() % choices.size())];
        previous_blank = board.blank();
        board = next;
    }
    return board;
}

}  // namespace collide::puzzle
