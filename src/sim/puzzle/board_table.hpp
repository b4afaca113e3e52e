#pragma once
// Internal: an open-addressing hash map from a packed board (never 0, see Board::packed) to a
// node id, for the searches' "seen" sets. Keys and values in two arrays (12 bytes a slot), at
// most 70% full: about 17-34 bytes per board, a third of std::unordered_map's, which matters
// when a BFS stores two million boards.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace collide::puzzle {

class BoardTable {
  public:
    BoardTable() : keys_(min_slots, 0), values_(min_slots, 0) {}

    /// The node id stored for `board`, or nullptr.
    [[nodiscard]] std::uint32_t* find(std::uint64_t board) noexcept {
        for (std::size_t i = slot_of(board);; i = (i + 1) & mask()) {
            if (keys_[i] == board) return &values_[i];
            if (keys_[i] == 0) return nullptr;
        }
    }

    /// Stores `id` for `board` (which must not be present).
    void insert(std::uint64_t board, std::uint32_t id) {
        if (10 * (size_ + 1) > 7 * keys_.size()) grow();
        place(board, id);
        ++size_;
    }

    [[nodiscard]] std::size_t size() const noexcept { return size_; }

  private:
    static constexpr std::size_t min_slots = 1024;

    [[nodiscard]] std::size_t mask() const noexcept { return keys_.size() - 1; }

    /// splitmix64's finaliser: packed boards differ in few low bits, so they need mixing.
    [[nodiscard]] std::size_t slot_of(std::uint64_t key) const noexcept {
        key ^= key >> 30;
        key *= 0xbf58476d1ce4e5b9ULL;
        key ^= key >> 27;
        key *= 0x94d049bb133111ebULL;
        key ^= key >> 31;
        return static_cast<std::size_t>(key) & mask();
    }

    void place(std::uint64_t board, std::uint32_t id) noexcept {
        std::size_t i = slot_of(board);
        while (keys_[i] != 0) i = (i + 1) & mask();
        keys_[i] = board;
        values_[i] = id;
    }

    void grow() {
        std::vector<std::uint64_t> keys(keys_.size() * 2, 0);
        std::vector<std::uint32_t> values(values_.size() * 2, 0);
        keys.swap(keys_);
        values.swap(values_);
        for (std::size_t i = 0; i < keys.size(); ++i) {
            if (keys[i] != 0) place(keys[i], values[i]);
        }
    }

    std::vector<std::uint64_t> keys_;
    std::vector<std::uint32_t> values_;
    std::size_t size_ = 0;
};

}  // namespace collide::puzzle
