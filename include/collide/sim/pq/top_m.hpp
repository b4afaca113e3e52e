#pragma once
/// \file
/// The M largest items of a stream in O(M) memory (the lecture's TopM): keep a min-oriented heap
/// of at most M items; a new item that beats the smallest one kept replaces it. O(log M) per
/// item, so O(N log M) for a stream of N items, however long the stream.

#include <algorithm>
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

#include "collide/sim/pq/dary_heap.hpp"
#include "collide/sim/pq/heapsort.hpp"

namespace collide::pq {

template <class T, class Less = std::less<T>>
class TopM {
  public:
    /// Keeps the m largest items under less (m = 0 keeps nothing).
    explicit TopM(std::size_t m, Less less = Less{}) : m_(m), heap_(less), less_(std::move(less)) {
        heap_.reserve(m);
    }

    /// Offers one item of the stream. An item that ties with the smallest kept one when the
    /// heap is full is dropped (the earlier item stays). O(log M).
    void offer(T x) {
        if (heap_.size() < m_) {
            heap_.push(std::move(x));
        } else if (m_ > 0 && less_(heap_.top(), x)) {
            heap_.replace_top(std::move(x));
        }
    }

    [[nodiscard]] std::size_t size() const noexcept { return heap_.size(); }
    [[nodiscard]] std::size_t capacity() const noexcept { return m_; }

    /// The items kept, largest first. O(M log M).
    [[nodiscard]] std::vector<T> largest_first() const {
        const auto kept = heap_.array();
        std::vector<T> out(kept.begin(), kept.end());
        heapsort(out.begin(), out.end(), [this](const T& a, const T& b) { return less_(a, b); });
        std::reverse(out.begin(), out.end());
        return out;
    }

  private:
    std::size_t m_;
    DaryHeap<T, Orientation::min, 2, Less> heap_;  ///< the M largest so far; top() is the smallest
    [[no_unique_address]] Less less_;
};

/// The m largest items of [first, last) under less, largest first, in O(m) extra memory.
template <std::input_iterator It, class Less = std::less<std::iter_value_t<It>>>
[[nodiscard]] std::vector<std::iter_value_t<It>> top_m(It first, It last, std::size_t m,
                                                       Less less = Less{}) {
    TopM<std::iter_value_t<It>, Less> keep(m, std::move(less));
    for (; first != last; ++first) keep.offer(*first);
    return keep.largest_first();
}

}  // namespace collide::pq
