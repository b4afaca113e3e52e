#include "scene/disc_grid.hpp"

#include <algorithm>
#include <cmath>

namespace collide::detail {

namespace {

// Cells per side, at least 1; the product is kept near max_cells at most.
int cells_along(double length, double cell_size) {
    const double n = std::floor(length / cell_size);
    if (!(n >= 1.0)) return 1;
    return static_cast<int>(std::min(n, 1e6));
}

}  // namespace

DiscGrid::DiscGrid(const Box& box, double cell_size, std::size_t max_cells)
    : periodic_(box.boundary == Boundary::periodic) {
    if (!(cell_size > 0.0) || !std::isfinite(cell_size))
        cell_size = std::max(box.width, box.height);
    // Enlarge cells until the grid fits the budget (a few tiny discs in a big box).
    const double budget = static_cast<double>(std::max<std::size_t>(max_cells, 1));
    while ((box.width / cell_size) * (box.height / cell_size) > budget) cell_size *= 2.0;
    nx_ = cells_along(box.width, cell_size);
    ny_ = cells_along(box.height, cell_size);
    // Cells tile the box exactly (periodic wrapping needs it; walls do not mind).
    cell_w_ = box.width / nx_;
    cell_h_ = box.height / ny_;
    head_.assign(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_), none);
}

DiscGrid::CellRange DiscGrid::range(double c, double r, double cell, int n) const noexcept {
    // Callers validate first; still, never turn a NaN or infinity into an int.
    if (!std::isfinite(c) || !std::isfinite(r)) return {0, n - 1};
    const double lo = std::floor((c - r) / cell);
    const double hi = std::floor((c + r) / cell);
    if (periodic_) {
        // A square wider than the box touches every column once; wrap_index maps the rest
        // (positions arrive wrapped, so lo and hi are within a cell or so of the box).
        if (hi - lo + 1.0 >= n || !(std::abs(lo) < 1e9)) return {0, n - 1};
        return {static_cast<int>(lo), static_cast<int>(hi)};
    }
    // Walls: positions outside the box (rejected elsewhere) clamp to the border cells.
    const double top = static_cast<double>(n - 1);
    return {static_cast<int>(std::clamp(lo, 0.0, top)), static_cast<int>(std::clamp(hi, 0.0, top))};
}

void DiscGrid::insert(std::uint32_t id, Vec2 p, double r) {
    const CellRange xs = range_x(p.x, r);
    const CellRange ys = range_y(p.y, r);
    for (int iy = ys.lo; iy <= ys.hi; ++iy) {
        const std::size_t row = static_cast<std::size_t>(wrap_index(iy, ny_)) * nx_;
        for (int ix = xs.lo; ix <= xs.hi; ++ix) {
            const std::size_t cell = row + static_cast<std::size_t>(wrap_index(ix, nx_));
            entries_.push_back({id, head_[cell]});
            head_[cell] = static_cast<std::uint32_t>(entries_.size() - 1);
        }
    }
}

}  // namespace collide::detail
