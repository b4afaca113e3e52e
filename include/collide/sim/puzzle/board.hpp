#pragma once
/// \file
/// The n x n sliding puzzle (the 8-puzzle for n = 3, the 15-puzzle for n = 4): boards packed in
/// 64 bits (4 bits per cell), parsing with errors that name the bad token, solvability by the
/// parity of inversions, the Hamming and Manhattan heuristics, and deterministic random boards.
///
///     const Board b = Board::parse("1 2 3 4 0 6 7 5 8");   // throws Error(input) naming a token
///     manhattan(b) == 2; b.solvable() == true;
///     b.for_each_neighbour([](const Board& next, int tile) { ... });

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace collide::puzzle {

/// Smallest and largest boards: 2x2 (3 tiles) to 4x4 (15 tiles, 4 bits per cell in 64 bits).
inline constexpr int min_side = 2;
inline constexpr int max_side = 4;

/// Which way a tile slides into the blank.
enum class Direction : std::uint8_t { up, down, left, right };

/// "up", "down", "left", "right".
[[nodiscard]] std::string_view to_string(Direction direction) noexcept;

/// One move: `tile` slides `direction` into the blank.
struct Move {
    int tile = 0;
    Direction direction = Direction::up;
    friend bool operator==(const Move&, const Move&) = default;
};

/// A board of side n (2..4): cell i (row-major, 0-based) holds tile 1..n*n-1 or the blank 0.
/// A small value type (16 bytes); equal boards have equal packed() values.
class Board {
  public:
    /// The solved board of side n: 1 2 ... n*n-1 then the blank. Throws Error(input) unless
    /// 2 <= side <= 4.
    [[nodiscard]] static Board goal(int side);

    /// Parses tiles separated by spaces, `0` or `_` for the blank; the side comes from the count
    /// (4, 9 or 16). Throws Error(input) "`option`: ..." naming the first bad token (by its text
    /// and position), a repeated or missing tile, or a wrong count. Does not check solvability.
    [[nodiscard]] static Board parse(std::string_view text, std::string_view option = "board");

    /// A board from packed cells (see packed()) and its side; the blank's cell is found.
    [[nodiscard]] static Board unpack(std::uint64_t packed, int side);

    [[nodiscard]] int side() const noexcept { return side_; }
    [[nodiscard]] int cells() const noexcept { return side_ * side_; }
    /// The tile in cell i (0 for the blank). Precondition: 0 <= i < cells().
    [[nodiscard]] int tile(int cell) const noexcept {
        return static_cast<int>((packed_ >> (4 * cell)) & 0xFU);
    }
    /// The blank's cell.
    [[nodiscard]] int blank() const noexcept { return blank_; }
    /// Cell i in bits 4i..4i+3. Never 0 (tile 1 is somewhere), so 0 can mark an empty slot.
    [[nodiscard]] std::uint64_t packed() const noexcept { return packed_; }

    /// Inversions: pairs of tiles (blank excluded) in the wrong order, reading row by row.
    [[nodiscard]] int inversions() const noexcept;
    /// Whether the goal can be reached: for odd n, an even number of inversions; for even n,
    /// inversions plus the blank's row (0 = top) odd. A move never changes this parity.
    [[nodiscard]] bool solvable() const noexcept;
    /// Why the board cannot be solved, in a sentence for the user; empty when it can.
    [[nodiscard]] std::string unsolvable_reason() const;

    [[nodiscard]] bool is_goal() const noexcept { return packed_ == goal(side_).packed_; }

    /// The board after the blank moves to `cell` (a neighbour of blank()).
    [[nodiscard]] Board with_blank_at(int cell) const noexcept;

    /// Calls f(next, moved_tile) for each board one move away, in a fixed order (the blank moves
    /// up, down, left, right), so searches are deterministic.
    template <class F>
    void for_each_neighbour(F&& f) const {
        const int row = blank_ / side_;
        const int col = blank_ % side_;
        if (row > 0) emit(blank_ - side_, f);
        if (row + 1 < side_) emit(blank_ + side_, f);
        if (col > 0) emit(blank_ - 1, f);
        if (col + 1 < side_) emit(blank_ + 1, f);
    }

    /// The move that turns this board into `next` (a neighbour).
    [[nodiscard]] Move move_to(const Board& next) const noexcept;

    /// "1 2 3 4 0 6 7 5 8" (0 for the blank): parse(to_string()) == *this.
    [[nodiscard]] std::string to_string() const;

    friend bool operator==(const Board& a, const Board& b) noexcept {
        return a.packed_ == b.packed_ && a.side_ == b.side_;
    }

  private:
    Board(std::uint64_t packed, int side, int blank) noexcept
        : packed_(packed),
          side_(static_cast<std::uint8_t>(side)),
          blank_(static_cast<std::uint8_t>(blank)) {}

    template <class F>
    void emit(int cell, F& f) const {
        f(with_blank_at(cell), tile(cell));
    }

    std::uint64_t packed_ = 0;
    std::uint8_t side_ = 3;
    std::uint8_t blank_ = 0;
};

/// Tiles (blank excluded) not in their goal cell. Never overestimates the moves left.
[[nodiscard]] int hamming(const Board& board) noexcept;
/// Sum over the tiles (blank excluded) of their row and column distances to their goal cell.
/// Never overestimates, and changes by exactly 1 per move (consistent).
[[nodiscard]] int manhattan(const Board& board) noexcept;

/// Which heuristic A* adds to the moves made.
enum class Heuristic : std::uint8_t { hamming, manhattan };

/// Parses "hamming" or "manhattan"; throws Error(input) naming `option` otherwise.
[[nodiscard]] Heuristic parse_heuristic(std::string_view text,
                                        std::string_view option = "heuristic");
[[nodiscard]] std::string_view to_string(Heuristic heuristic) noexcept;
[[nodiscard]] int estimate(Heuristic heuristic, const Board& board) noexcept;

/// Most moves random_board accepts (far beyond any board's diameter: 31 for 3x3, 80 for 4x4).
inline constexpr int max_random_moves = 1000;

/// A solvable board reached from the goal of side `side` by `moves` random moves of the blank,
/// never undoing the move just made; the same (side, moves, seed) gives the same board on every
/// platform (std::mt19937_64's output is specified). Its shortest solution takes at most `moves`
/// moves, and may take fewer (a random walk can come back near the goal). Throws Error(input)
/// for a side outside 2..4, or naming `moves_field` for moves outside 0..max_random_moves.
[[nodiscard]] Board random_board(int side, int moves, std::uint64_t seed,
                                 std::string_view moves_field = "moves");

}  // namespace collide::puzzle
