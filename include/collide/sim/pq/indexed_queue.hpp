#pragma once
/// \file
/// IndexedHeapQueue: the indexed d-ary heap used as a plain queue of values, so that
/// `--pq indexed` runs the classic engine on it. Each pushed value gets a handle from a free
/// list (most recently freed first); pop returns the value and frees its handle.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "collide/sim/pq/indexed_heap.hpp"
#include "collide/sim/pq/order.hpp"

namespace collide::pq {

/// Requires T to be default-constructible and copyable (keys are stored per handle).
template <class T, Orientation O = Orientation::max, unsigned D = 4, class Less = std::less<T>>
class IndexedHeapQueue {
  public:
    using value_type = T;
    using heap_type = IndexedDaryHeap<T, O, D, Less>;
    using handle_type = typename heap_type::handle_type;

    IndexedHeapQueue() = default;
    explicit IndexedHeapQueue(Less less) : heap_(0, std::move(less)) {}

    [[nodiscard]] bool empty() const noexcept { return heap_.empty(); }
    [[nodiscard]] std::size_t size() const noexcept { return heap_.size(); }
    void reserve(std::size_t n) { grow_to(n); }

    /// The item that comes out next. Precondition: !empty(). O(1).
    [[nodiscard]] const T& top() const { return heap_.top_key(); }

    /// Inserts x under a fresh handle. O(d log_d N) (amortised: the handle range doubles).
    void push(T x) {
        if (free_.empty()) grow_to(heap_.capacity() < 8 ? 16 : 2 * heap_.capacity());
        const handle_type h = free_.back();
        free_.pop_back();
        heap_.push(h, std::move(x));
        validate();
    }

    /// Removes and returns the item that comes out next. Precondition: !empty(). O(d log_d N).
    T pop() {
        T out = heap_.top_key();
        free_.push_back(heap_.pop());
        validate();
        return out;
    }

    /// The keys in heap-array order, for teaching traces and tests. O(N): builds a copy.
    [[nodiscard]] std::vector<T> array() const {
        std::vector<T> keys;
        keys.reserve(heap_.size());
        for (handle_type h : heap_.array()) keys.push_back(heap_.key(h));
        return keys;
    }

    /// The heap's invariants (heap order, position map) and the free list's: every handle is
    /// either in the heap or free, never both. O(capacity).
    [[nodiscard]] bool check_invariants() const {
        if (!heap_.check_invariants() || free_.size() + heap_.size() != heap_.capacity())
            return false;
        for (handle_type h : free_) {
            if (h >= heap_.capacity() || heap_.contains(h)) return false;
        }
        return true;
    }

    /// The underlying indexed heap (handles, position map), read-only.
    [[nodiscard]] const heap_type& heap() const noexcept { return heap_; }

  private:
    /// Extends the handle range to `capacity` and adds the new handles to the free list so the
    /// lowest new handle is handed out first.
    void grow_to(std::size_t capacity) {
        const std::size_t old = heap_.capacity();
        if (capacity <= old) return;
        heap_.reserve_handles(capacity);
        for (std::size_t h = capacity; h-- > old;) free_.push_back(static_cast<handle_type>(h));
    }

    void validate() const {
        if constexpr (validate_heaps)
            require_invariant(check_invariants(), "indexed queue free list");
    }

    heap_type heap_;
    std::vector<handle_type> free_;  ///< handles not in the heap; back() is handed out next
};

}  // namespace collide::pq
