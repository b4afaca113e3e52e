#include "time/cell_grid.hpp"

#include <algorithm>
#include <cmath>

namespace collide::sim::detail {

namespace {

/// Cells per axis never exceed this: a huge grid of empty cells costs more than it saves, and
/// larger cells are always correct (they only add candidate pairs).
constexpr std::size_t max_cells_per_axis = 2048;

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

}  // namespace

bool CellGrid::build(const Box& box, const std::vector<Vec2>& positions, double reach) {
    box_ = box;
    periodic_ = box.boundary == Boundary::periodic;
    // About 4 cells per disc at most: finer grids would be mostly empty.
    const auto per_axis_cap = std::clamp<std::size_t>(
        static_cast<std::size_t>(2.0 * std::sqrt(static_cast<double>(positions.size()))) + 1, 1,
        max_cells_per_axis);
    nx_ = cells_along(box.width, reach, per_axis_cap);
    ny_ = cells_along(box.height, reach, per_axis_cap);
    if (periodic_ && (nx_ < 3 || ny_ < 3)) {
        return false;
    }
    cell_w_ = box.width / static_cast<double>(nx_);
    cell_h_ = box.height / static_cast<double>(ny_);

    // Counting sort by cell: stable, so ids stay ascending within a cell (deterministic order).
    const std::size_t cells = nx_ * ny_;
    cell_start_.assign(cells + 1, 0);
    cell_id_.resize(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
        cell_id_[i] = static_cast<std::uint32_t>(cell_of(positions[i]));
        ++cell_start_[cell_id_[i] + 1];
    }
    for (std::size_t c = 0; c < cells; ++c) {
        cell_start_[c + 1] += cell_start_[c];
    }
    sorted_.resize(positions.size());
    std::vector<std::uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
    for (std::size_t i = 0; i < positions.size(); ++i) {
        sorted_[fill[cell_id_[i]]++] = static_cast<std::uint32_t>(i);
    }
    return true;
}

std::size_t CellGrid::cell_of(Vec2 p) const noexcept {
    const Vec2 q = box_.wrap(p);  // identity for walls
    return clamped_index(q.x, cell_w_, nx_) + nx_ * clamped_index(q.y, cell_h_, ny_);
}

bool CellGrid::neighbour(std::size_t cx, std::size_t cy, int ox, int oy,
                         std::size_t& out) const noexcept {
    auto shift = [this](std::size_t c, int o, std::size_t n, std::size_t& result) {
        const auto moved = static_cast<long long>(c) + o;
        const auto count = static_cast<long long>(n);
        if (moved >= 0 && moved < count) {
            result = static_cast<std::size_t>(moved);
            return true;
        }
        if (!periodic_) {
            return false;
        }
        result = static_cast<std::size_t>((moved + count) % count);
        return true;
    };
    std::size_t nx = 0;
    std::size_t ny = 0;
    if (!shift(cx, ox, nx_, nx) || !shift(cy, oy, ny_, ny)) {
        return false;
    }
    out = nx + nx_ * ny;
    return true;
}

}  // namespace collide::sim::detail
