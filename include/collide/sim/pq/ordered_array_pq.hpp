#pragma once
/// \file
/// The lecture's eager priority queue: an array kept sorted so that the item that comes out next
/// is the last one. insert shifts larger items right, as in insertion sort, in O(N); remove pops
/// the back in O(1). A max-queue is therefore ascending (A E E L M P), a min-queue descending.
/// Obs (observer.hpp) sees each compare and shift; the default NoObserver costs nothing.

#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

#include "collide/sim/pq/observer.hpp"
#include "collide/sim/pq/order.hpp"

namespace collide::pq {

template <class T, Orientation O = Orientation::max, class Less = std::less<T>,
          QueueObserver Obs = NoObserver>
class OrderedArrayPQ {
  public:
    using value_type = T;

    OrderedArrayPQ() = default;
    explicit OrderedArrayPQ(Less less, Obs obs = Obs{})
        : less_(std::move(less)), obs_(std::move(obs)) {}

    [[nodiscard]] bool empty() const noexcept { return a_.empty(); }
    [[nodiscard]] std::size_t size() const noexcept { return a_.size(); }
    void reserve(std::size_t n) { a_.reserve(n); }
    void clear() noexcept { a_.clear(); }

    /// The item that comes out next. Precondition: !empty(). O(1).
    [[nodiscard]] const T& top() const { return a_.back(); }

    /// Inserts x at its sorted place, after any items it ties with (so of tying items the newest
    /// comes out first). O(N) moves.
    void push(T x) {
        std::size_t i = a_.size();
        a_.push_back(std::move(x));
        T moving = std::move(a_[i]);
        while (i > 0 && (obs_.compared(i, i - 1), comes_first<O>(less_, a_[i - 1], moving))) {
            obs_.shifted(i - 1, i);
            a_[i] = std::move(a_[i - 1]);
            --i;
        }
        a_[i] = std::move(moving);
        validate();
    }

    /// Removes and returns the item that comes out next. Precondition: !empty(). O(1).
    T pop() {
        T out = std::move(a_.back());
        a_.pop_back();
        obs_.removed(a_.size());
        return out;
    }

    /// The sorted array (last item comes out next), for teaching traces and tests.
    [[nodiscard]] const std::vector<T>& array() const noexcept { return a_; }

    /// Sorted order: no item comes out before an item behind it. O(N).
    [[nodiscard]] bool is_sorted() const {
        for (std::size_t i = 1; i < a_.size(); ++i) {
            if (comes_first<O>(less_, a_[i - 1], a_[i])) return false;
        }
        return true;
    }

  private:
    void validate() const {
        if constexpr (validate_heaps) require_invariant(is_sorted(), "ordered array order");
    }

    std::vector<T> a_;
    [[no_unique_address]] Less less_{};
    [[no_unique_address]] Obs obs_{};
};

}  // namespace collide::pq
