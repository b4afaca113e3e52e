#pragma once
/// \file
/// The lecture's lazy priority queue: an unordered array. insert appends in O(1); remove finds the
/// item that comes out next in O(N), swaps it with the last item and shrinks the array.
/// Obs (observer.hpp) sees the scan's compares and the exchange; the default NoObserver costs
/// nothing. top() scans too but reports nothing: only mutations are watched.

#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

#include "collide/sim/pq/observer.hpp"
#include "collide/sim/pq/order.hpp"

namespace collide::pq {

template <class T, Orientation O = Orientation::max, class Less = std::less<T>,
          QueueObserver Obs = NoObserver>
class UnorderedArrayPQ {
  public:
    using value_type = T;

    UnorderedArrayPQ() = default;
    explicit UnorderedArrayPQ(Less less, Obs obs = Obs{})
        : less_(std::move(less)), obs_(std::move(obs)) {}

    [[nodiscard]] bool empty() const noexcept { return a_.empty(); }
    [[nodiscard]] std::size_t size() const noexcept { return a_.size(); }
    void reserve(std::size_t n) { a_.reserve(n); }
    void clear() noexcept { a_.clear(); }

    /// The item that comes out next. Precondition: !empty(). O(N).
    [[nodiscard]] const T& top() const { return a_[best_index(NoObserver{})]; }

    /// Appends x. O(1) amortised.
    void push(T x) { a_.push_back(std::move(x)); }

    /// Removes and returns the item that comes out next (of tying items, the one nearest the
    /// front of the array). Precondition: !empty(). O(N).
    T pop() {
        const std::size_t best = best_index(obs_);
        obs_.exchanged(best, a_.size() - 1);
        std::swap(a_[best], a_.back());
        T out = std::move(a_.back());
        a_.pop_back();
        obs_.removed(a_.size());
        return out;
    }

    /// The array in storage order, for teaching traces and tests.
    [[nodiscard]] const std::vector<T>& array() const noexcept { return a_; }

  private:
    template <class Watcher>
    [[nodiscard]] std::size_t best_index(const Watcher& watcher) const {
        std::size_t best = 0;
        for (std::size_t i = 1; i < a_.size(); ++i) {
            watcher.compared(i, best);
            if (comes_first<O>(less_, a_[i], a_[best])) best = i;
        }
        return best;
    }

    std::vector<T> a_;
    [[no_unique_address]] Less less_{};
    [[no_unique_address]] Obs obs_{};
};

}  // namespace collide::pq
