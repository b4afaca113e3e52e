#pragma once
/// \file
/// A uniform cell grid over the box for the time-driven engine's `--td-detect grid`: it lists every
/// pair of discs closer than a given reach (and some farther ones), each pair exactly once, so that
/// the per-step checks cost about O(N) instead of N(N-1)/2 for a gas.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "collide/box.hpp"
#include "collide/vec2.hpp"

namespace collide::sim::detail {

class CellGrid {
  public:
    /// Sorts the discs into cells at least `reach` wide (box units). Discs outside a walled box
    /// (escaped) go to the nearest border cell, which keeps neighbours neighbours. Returns false
    /// when a periodic box is too small for three cells per axis (neighbour cells would repeat):
    /// the caller then tests all pairs. O(N + cells).
    bool build(const Box& box, const std::vector<Vec2>& positions, double reach);

    /// Calls visit(i, j) with i < j once for every pair of discs in the same or adjacent cells
    /// (adjacent across the edges of a periodic box). Valid after build() returned true.
    template <typename Visit>
    void for_each_pair(Visit&& visit) const {
        for (std::size_t cy = 0; cy < ny_; ++cy) {
            for (std::size_t cx = 0; cx < nx_; ++cx) {
                const std::size_t home = cx + nx_ * cy;
                visit_within(home, visit);
                // Half of the 8 neighbours (E, NW, N, NE) so that every pair of cells meets once.
                constexpr int offsets[4][2] = {{1, 0}, {-1, 1}, {0, 1}, {1, 1}};
                for (const auto& off : offsets) {
                    std::size_t other = 0;
                    if (neighbour(cx, cy, off[0], off[1], other)) {
                        visit_across(home, other, visit);
                    }
                }
            }
        }
    }

    /// Heap memory held (capacity), bytes.
    [[nodiscard]] std::size_t bytes() const noexcept {
        return (cell_start_.capacity() + sorted_.capacity() + cell_id_.capacity()) *
               sizeof(std::uint32_t);
    }

  private:
    [[nodiscard]] std::size_t cell_of(Vec2 p) const noexcept;
    [[nodiscard]] bool neighbour(std::size_t cx, std::size_t cy, int ox, int oy,
                                 std::size_t& out) const noexcept;

    template <typename Visit>
    void visit_within(std::size_t cell, Visit& visit) const {
        for (std::uint32_t a = cell_start_[cell]; a < cell_start_[cell + 1]; ++a) {
            for (std::uint32_t b = a + 1; b < cell_start_[cell + 1]; ++b) {
                visit(sorted_[a], sorted_[b]);  // counting sort keeps ids ascending in a cell
            }
        }
    }

    template <typename Visit>
    void visit_across(std::size_t cell, std::size_t other, Visit& visit) const {
        for (std::uint32_t a = cell_start_[cell]; a < cell_start_[cell + 1]; ++a) {
            for (std::uint32_t b = cell_start_[other]; b < cell_start_[other + 1]; ++b) {
                const std::uint32_t i = sorted_[a];
                const std::uint32_t j = sorted_[b];
                if (i < j) {
                    visit(i, j);
                } else {
                    visit(j, i);
                }
            }
        }
    }

    Box box_;
    bool periodic_ = false;
    std::size_t nx_ = 1;
    std::size_t ny_ = 1;
    double cell_w_ = 1.0;
    double cell_h_ = 1.0;
    std::vector<std::uint32_t> cell_start_;  ///< discs of cell c are sorted_[cell_start_[c] ..
                                             ///< cell_start_[c + 1])
    std::vector<std::uint32_t> sorted_;      ///< disc ids ordered by cell, ascending within one
    std::vector<std::uint32_t> cell_id_;     ///< cell of each disc
};

}  // namespace collide::sim::detail
