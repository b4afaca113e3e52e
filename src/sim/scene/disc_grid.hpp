#pragma once
// A uniform cell grid over the box for "does this disc overlap any disc already placed?" queries,
// used by validation and by the generators. Each disc is filed in every cell its bounding square
// touches, so discs of very different sizes (one big tracer among small discs) need no special
// case: two discs can only overlap if their bounding squares share a cell.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "collide/box.hpp"
#include "collide/vec2.hpp"

namespace collide::detail {

class DiscGrid {
  public:
    /// A grid over `box` with cells of about `cell_size` (enlarged so there are at most
    /// about `max_cells` cells; periodic boxes get an exact number of cells per side).
    DiscGrid(const Box& box, double cell_size, std::size_t max_cells);

    /// Files disc `id` (centre p, radius r) in every cell its bounding square touches.
    void insert(std::uint32_t id, Vec2 p, double r);

    /// Calls visit(id) for each disc filed in a cell touched by the bounding square of (p, r);
    /// a disc may be visited more than once. Stops and returns true as soon as visit returns true.
    template <class Visit>
    bool any_near(Vec2 p, double r, Visit&& visit) const {
        CellRange xs = range_x(p.x, r);
        CellRange ys = range_y(p.y, r);
        for (int iy = ys.lo; iy <= ys.hi; ++iy) {
            const std::size_t row = static_cast<std::size_t>(wrap_index(iy, ny_)) * nx_;
            for (int ix = xs.lo; ix <= xs.hi; ++ix) {
                const std::size_t cell = row + static_cast<std::size_t>(wrap_index(ix, nx_));
                for (std::uint32_t e = head_[cell]; e != none; e = entries_[e].next) {
                    if (visit(entries_[e].id)) return true;
                }
            }
        }
        return false;
    }

    /// Number of (disc, cell) entries filed so far: insertion cost, for sizing decisions.
    [[nodiscard]] std::size_t entry_count() const noexcept { return entries_.size(); }

  private:
    static constexpr std::uint32_t none = 0xffffffffu;
    struct Entry {
        std::uint32_t id;
        std::uint32_t next;
    };
    struct CellRange {
        int lo;
        int hi;
    };

    [[nodiscard]] CellRange range_x(double x, double r) const noexcept {
        return range(x, r, cell_w_, nx_);
    }
    [[nodiscard]] CellRange range_y(double y, double r) const noexcept {
        return range(y, r, cell_h_, ny_);
    }
    [[nodiscard]] CellRange range(double c, double r, double cell, int n) const noexcept;
    [[nodiscard]] int wrap_index(int i, int n) const noexcept {
        if (!periodic_) return i;
        const int m = i % n;
        return m < 0 ? m + n : m;
    }

    bool periodic_ = false;
    int nx_ = 1;
    int ny_ = 1;
    double cell_w_ = 1.0;
    double cell_h_ = 1.0;
    std::vector<std::uint32_t> head_;  // first entry of each cell, or none
    std::vector<Entry> entries_;       // singly linked lists, newest first
};

}  // namespace collide::detail
