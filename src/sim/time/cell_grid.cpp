#include "time/cell_grid.hpp"

#include <algorithm>
#include <cmath>

namespace collide::sim::detail {

namespace {

/// Cells per axis never exceed this: a huge grid of empty cells costs more than it saves, and
/// larger cells are always correct (they only add candidate pairs). 2048^2 cells in 2D, 256^3 in
/// 3D (16 M list heads).
template <int D>
constexpr std::size_t max_cells_per_axis = D == 2 ? 2048 : 256;

std::size_t cells_along(double extent, double reach, std::size_t cap) {
    if (!(reach > 0.0) || !std::isfinite(reach)) {
        return reach > 0.0 ? 1 : cap;
    }
    const double fit = std::floor(extent / reach);
    if (!(fit >= 1.0)) {
        return 1;
    }
    return std::min(cap, static_cast<std::size_t>(std::min(fit, static_cast<double>(cap))));
}

/// Index of coordinate x in n cells of width w, clamped to the grid (escaped discs, x == extent).
std::size_t clamped_index(double x, double w, std::size_t n) {
    const double k = std::floor(x / w);
    if (!(k >= 0.0)) {
        return 0;
    }
    if (k >= static_cast<double>(n - 1)) {
        return n - 1;
    }
    return static_cast<std::size_t>(k);
}

/// About 4 cells per particle at most (2D: 2 sqrt N per axis; 3D: (4 N)^(1/3)): finer grids
/// would be mostly empty.
template <int D>
std::size_t per_axis_cap(std::size_t n) {
    const auto count = static_cast<double>(n);
    const double fit = D == 2 ? 2.0 * std::sqrt(count) : std::cbrt(4.0 * count);
    return std::clamp<std::size_t>(static_cast<std::size_t>(fit) + 1, 1, max_cells_per_axis<D>);
}

}  // namespace

template <int D>
const std::vector<typename BasicCellGrid<D>::Cell>& BasicCellGrid<D>::half_neighbourhood() {
    static const std::vector<Cell> offsets = [] {
        std::vector<Cell> out;
        Cell o{};
        o.fill(-1);
        for (;;) {
            // "After" zero: the last non-zero component is positive.
            int last = 0;
            for (int k = D - 1; k >= 0 && last == 0; --k) last = o[k];
            if (last > 0) out.push_back(o);
            int k = 0;
            while (k < D && ++o[k] > 1) o[k++] = -1;
            if (k == D) break;
        }
        return out;
    }();
    return offsets;
}

template <int D>
bool BasicCellGrid<D>::build(const BoxType& box, const std::vector<Vec>& positions, double reach) {
    box_ = box;
    periodic_ = box.boundary == Boundary::periodic;
    const std::size_t cap = per_axis_cap<D>(positions.size());
    const Vec extent = Space<D>::extent(box);
    cells_ = 1;
    for (int k = 0; k < D; ++k) {
        n_[k] = cells_along(axis(extent, k), reach, cap);
        if (periodic_ && n_[k] < 3) {
            return false;
        }
        side_[k] = axis(extent, k) / static_cast<double>(n_[k]);
        cells_ *= n_[k];
    }

    half_step_.clear();
    for (const Cell& offset : half_neighbourhood()) {
        std::ptrdiff_t step = 0;
        for (int k = D - 1; k >= 0; --k) {
            step = step * static_cast<std::ptrdiff_t>(n_[k]) + offset[k];
        }
        half_step_.push_back(step);
    }

    // Counting sort by cell: stable, so ids stay ascending within a cell (deterministic order).
    cell_start_.assign(cells_ + 1, 0);
    cell_id_.resize(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
        cell_id_[i] = static_cast<std::uint32_t>(cell_of(positions[i]));
        ++cell_start_[cell_id_[i] + 1];
    }
    for (std::size_t c = 0; c < cells_; ++c) {
        cell_start_[c + 1] += cell_start_[c];
    }
    sorted_.resize(positions.size());
    std::vector<std::uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
    for (std::size_t i = 0; i < positions.size(); ++i) {
        sorted_[fill[cell_id_[i]]++] = static_cast<std::uint32_t>(i);
    }
    return true;
}

template <int D>
std::size_t BasicCellGrid<D>::cell_of(Vec p) const noexcept {
    const Vec q = box_.wrap(p);  // identity for walls
    std::size_t cell = 0;
    for (int k = D - 1; k >= 0; --k) {
        cell = cell * n_[k] + clamped_index(axis(q, k), side_[k], n_[k]);
    }
    return cell;
}

template <int D>
bool BasicCellGrid<D>::neighbour(const Cell& c, const Cell& offset,
                                 std::size_t& out) const noexcept {
    std::size_t cell = 0;
    for (int k = D - 1; k >= 0; --k) {
        const auto count = static_cast<long long>(n_[k]);
        long long moved = static_cast<long long>(c[k]) + offset[k];
        if (moved < 0 || moved >= count) {
            if (!periodic_) {
                return false;
            }
            moved = (moved + count) % count;
        }
        cell = cell * n_[k] + static_cast<std::size_t>(moved);
    }
    out = cell;
    return true;
}

template class BasicCellGrid<2>;
template class BasicCellGrid<3>;

}  // namespace collide::sim::detail
