#pragma once
/// \file
/// A uniform cell grid over the box for the time-driven engine's `--td-detect grid`: it lists every
/// pair of particles closer than a given reach (and some farther ones), each pair exactly once, so
/// that the per-step checks cost about O(N) instead of N(N-1)/2 for a gas. One code for discs and
/// spheres: BasicCellGrid<D> over the 3^D-cell neighbourhood (CellGrid: discs).

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "collide/space.hpp"

namespace collide::sim::detail {

template <int D>
class BasicCellGrid {
  public:
    using Vec = typename Space<D>::Vec;
    using BoxType = typename Space<D>::Box;

    /// Sorts the particles into cells at least `reach` wide (box units). Particles outside a
    /// walled box (escaped) go to the nearest border cell, which keeps neighbours neighbours.
    /// Returns false when a periodic box is too small for three cells per axis (neighbour cells
    /// would repeat): the caller then tests all pairs. O(N + cells).
    bool build(const BoxType& box, const std::vector<Vec>& positions, double reach);

    /// Calls visit(i, j) with i < j once for every pair of particles in the same or adjacent
    /// cells (adjacent across the edges of a periodic box). Valid after build() returned true.
    template <typename Visit>
    void for_each_pair(Visit&& visit) const {
        const std::vector<Cell>& half = half_neighbourhood();
        Cell c{};
        for (std::size_t home = 0; home < cells_; ++home) {
            visit_within(home, visit);
            // Half of the 3^D - 1 neighbours (2D: E, NW, N, NE) so that every pair of cells
            // meets once. Away from the edges a neighbour is a fixed step in the linear index.
            const bool inside = interior(c);
            for (std::size_t o = 0; o < half.size(); ++o) {
                std::size_t other = home + static_cast<std::size_t>(half_step_[o]);
                if (inside || neighbour(c, half[o], other)) visit_across(home, other, visit);
            }
            next_cell(c);
        }
    }

    /// Heap memory held (capacity), bytes.
    [[nodiscard]] std::size_t bytes() const noexcept {
        return (cell_start_.capacity() + sorted_.capacity() + cell_id_.capacity()) *
               sizeof(std::uint32_t);
    }

  private:
    using Cell = std::array<int, D>;  ///< cell coordinates, or an offset from a cell

    /// The offsets o with o "after" zero (the last non-zero component positive, x varying
    /// fastest): 4 in 2D, 13 in 3D, in that order.
    [[nodiscard]] static const std::vector<Cell>& half_neighbourhood();
    /// c moves to the next cell in linear order (x fastest).
    void next_cell(Cell& c) const noexcept {
        for (int k = 0; k < D; ++k) {
            if (++c[k] < static_cast<int>(n_[k])) return;
            c[k] = 0;
        }
    }
    /// No coordinate of c on the grid's edge: every neighbour is inside, without wrapping.
    [[nodiscard]] bool interior(const Cell& c) const noexcept {
        bool inside = true;
        for (int k = 0; k < D; ++k) {
            inside = inside && c[k] > 0 && static_cast<std::size_t>(c[k]) + 1 < n_[k];
        }
        return inside;
    }
    [[nodiscard]] std::size_t cell_of(Vec p) const noexcept;
    [[nodiscard]] bool neighbour(const Cell& c, const Cell& offset,
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

    BoxType box_;
    bool periodic_ = false;
    std::array<std::size_t, D> n_{};  ///< cells per axis
    std::size_t cells_ = 0;           ///< product of n_
    std::array<double, D> side_{};    ///< cell sides
    /// The linear-index step to each half_neighbourhood() offset from an interior cell.
    std::vector<std::ptrdiff_t> half_step_;
    std::vector<std::uint32_t> cell_start_;  ///< particles of cell c are sorted_[cell_start_[c]
                                             ///< .. cell_start_[c + 1])
    std::vector<std::uint32_t> sorted_;      ///< particle ids ordered by cell, ascending in one
    std::vector<std::uint32_t> cell_id_;     ///< cell of each particle
};

extern template class BasicCellGrid<2>;
extern template class BasicCellGrid<3>;

using CellGrid = BasicCellGrid<2>;

}  // namespace collide::sim::detail
