#pragma once
/// \file
/// A d-ary heap in a 0-based array: children of i are d*i+1 ... d*i+d, parent (i-1)/d.
/// d = 2 is the lecture's binary heap. push and pop are O(log_d N): pop makes d - 1 compares a
/// level on its way down, then a short rise (see sink_from_root).
/// D = 0 selects an arity chosen at run time (constructor argument); a compile-time D lets the
/// compiler turn the index arithmetic into shifts and unroll the child scan, so prefer it.
/// Obs (observer.hpp) sees every compare and exchange; the default NoObserver costs nothing.
/// A watched heap's pop runs the lecture's sink (exchange root and last, remove, sink) instead of
/// the bottom-up one: the same array after every operation (tested), the steps a class is taught.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "collide/sim/pq/cache_layout.hpp"
#include "collide/sim/pq/observer.hpp"
#include "collide/sim/pq/order.hpp"

namespace collide::pq {

template <class T, Orientation O = Orientation::max, unsigned D = 2, class Less = std::less<T>,
          QueueObserver Obs = NoObserver>
class DaryHeap {
    static_assert(D != 1,
                  "a heap needs at least two children per node (D = 0: chosen at run time)");

  public:
    using value_type = T;
    /// Children per node fixed at compile time, or 0 when chosen at run time (see d()).
    static constexpr unsigned arity = D;
    /// Largest run-time arity accepted; wider nodes only cost compares.
    static constexpr unsigned max_runtime_arity = 64;

    /// pop prefetches the levels ahead only in heaps of more than this many bytes.
    static constexpr std::size_t prefetch_bytes = heap_prefetch_bytes;

    /// An empty heap (a run-time-arity heap built this way is binary).
    DaryHeap() = default;
    explicit DaryHeap(Less less, Obs obs = Obs{}) : less_(std::move(less)), obs_(std::move(obs)) {}

    /// An empty heap with d children per node; only for D = 0. Throws Error(runtime) unless
    /// 2 <= d <= max_runtime_arity.
    explicit DaryHeap(unsigned d, Less less = Less{}, Obs obs = Obs{}) requires(D == 0)
        : d_(d), less_(std::move(less)), obs_(std::move(obs)) {
        if (d < 2 || d > max_runtime_arity) {
            throw_runtime_error("d-ary heap: arity " + std::to_string(d) + " out of range (2.." +
                                std::to_string(max_runtime_arity) + ")");
        }
    }

    /// Children per node.
    [[nodiscard]] std::size_t d() const noexcept {
        if constexpr (D == 0) {
            return d_;
        } else {
            return D;
        }
    }

    [[nodiscard]] bool empty() const noexcept { return a_.empty(); }
    [[nodiscard]] std::size_t size() const noexcept { return a_.size(); }
    void reserve(std::size_t n) { a_.reserve(n); }
    void clear() noexcept { a_.clear(); }

    /// The item that comes out next. Precondition: !empty().
    [[nodiscard]] const T& top() const { return a_.front(); }

    /// Inserts x. O(log_d N).
    void push(T x) {
        a_.push_back(std::move(x));
        swim(a_.size() - 1);
        validate();
    }

    /// Removes and returns the item that comes out next. Precondition: !empty(). O(d log_d N).
    T pop() {
        if constexpr (Obs::watching) {
            return pop_as_taught();
        }
        T out = std::move(a_.front());
        T last = std::move(a_.back());
        a_.pop_back();
        if (!a_.empty()) sink_from_root(std::move(last));
        validate();
        return out;
    }

    /// Replaces the item that comes out next by x and returns the old one: a pop and a push with
    /// one sink instead of a sink and a swim. Precondition: !empty(). O(d log_d N).
    T replace_top(T x) {
        T out = std::exchange(a_.front(), std::move(x));
        sink(0);
        validate();
        return out;
    }

    /// The heap array, for teaching traces and tests (index 0 comes out next).
    [[nodiscard]] std::span<const T> array() const noexcept { return a_; }

    /// The observer (e.g. a QueueRecorder's log handle).
    [[nodiscard]] const Obs& observer() const noexcept { return obs_; }

    /// Heap order: no child comes out before its parent. O(N).
    [[nodiscard]] bool is_heap() const {
        for (std::size_t i = 1; i < a_.size(); ++i) {
            if (first(a_[i], a_[(i - 1) / d()])) return false;
        }
        return true;
    }

  private:
    [[nodiscard]] bool first(const T& a, const T& b) const { return comes_first<O>(less_, a, b); }

    void swim(std::size_t i) {
        T x = std::move(a_[i]);
        while (i > 0) {
            const std::size_t parent = (i - 1) / d();
            obs_.compared(i, parent);
            if (!first(x, a_[parent])) break;
            obs_.exchanged(i, parent);
            a_[i] = std::move(a_[parent]);
            i = parent;
        }
        a_[i] = std::move(x);
    }

    /// The child of i that comes out first (the first of tying children), chosen without
    /// branches: a mispredicted branch costs more than the few selects. Precondition: i has a
    /// child.
    [[nodiscard]] std::size_t best_child(std::size_t i) const {
        const std::size_t c0 = d() * i + 1;
        const std::size_t n = a_.size();
        if constexpr (D != 0) {
            if (c0 + D <= n) return best_of<D>(c0);
        }
        const std::size_t c_end = c0 + d() < n ? c0 + d() : n;
        std::size_t best = c0;
        for (std::size_t c = c0 + 1; c < c_end; ++c) best = pick(c, best);
        return best;
    }

    /// The first-coming of the K items from index c on, as a knock-out tournament in which the
    /// left item wins ties (so the first of tying items wins, as in a left-to-right scan). Each
    /// round's compares are independent, so a full node costs about log2 K dependent steps.
    template <unsigned K>
    [[nodiscard]] std::size_t best_of(std::size_t c) const {
        if constexpr (K == 1) {
            return c;
        } else {
            return pick(best_of<K - K / 2>(c + K / 2), best_of<K / 2>(c));
        }
    }

    /// `challenger` if it comes out before `holder`, else `holder`, computed without a branch.
    [[nodiscard]] std::size_t pick(std::size_t challenger, std::size_t holder) const {
        obs_.compared(challenger, holder);
        const auto take = static_cast<std::size_t>(first(a_[challenger], a_[holder]));
        return holder + ((challenger - holder) & (std::size_t{0} - take));
    }

    /// The lecture's sink: move the item at i down while a child comes out before it.
    void sink(std::size_t i) {
        const std::size_t n = a_.size();
        T x = std::move(a_[i]);
        while (d() * i + 1 < n) {
            const std::size_t best = best_child(i);
            obs_.compared(i, best);
            if (!first(a_[best], x)) break;
            obs_.exchanged(i, best);
            a_[i] = std::move(a_[best]);
            i = best;
        }
        a_[i] = std::move(x);
    }

    /// pop of a watched heap, step by step as the lecture shows it: exchange the root with the last
    /// item, remove the last slot, sink the new root.
    T pop_as_taught() {
        const std::size_t last = a_.size() - 1;
        obs_.exchanged(0, last);
        std::swap(a_.front(), a_.back());
        T out = std::move(a_.back());
        a_.pop_back();
        obs_.removed(last);
        if (!a_.empty()) sink(0);
        validate();
        return out;
    }

    /// pop's sink of x (the former last item) from the empty root, bottom-up (Floyd): move the
    /// hole down the path of best children to a leaf without comparing against x, then let x
    /// rise from there while its parent does not come out before it. The last item nearly always
    /// belongs near the bottom, so this saves a compare and an unpredictable branch per level.
    /// Rising past ties (non-strict) makes the result identical to the lecture's sink, which
    /// stops above the first child that does not come out before x, so traces match the lecture.
    void sink_from_root(T x) {
        const std::size_t hole = hole_to_leaf();
        rise_from(hole, std::move(x));
    }

    /// Moves the hole at the root down the path of best children to a leaf; returns the leaf.
    ///
    /// In a heap larger than the caches, each level waits for a cache miss before it knows
    /// where to go next. So on each level it asks the processor to load the hole's descendants a
    /// few levels down (heap_lookahead) while the children are compared: the path continues
    /// among them (docs/benchmarks.md); heaps that fit in the caches skip it
    /// (heap_prefetch_bytes).
    std::size_t hole_to_leaf() {
        const std::size_t n = a_.size();
        const std::size_t d = this->d();
        const HeapLookahead ahead =
            n * sizeof(T) > heap_prefetch_bytes ? heap_lookahead(d, sizeof(T)) : HeapLookahead{};
        std::size_t hole = 0;
        while (d * hole + 1 < n) {
            const std::size_t first = hole * ahead.items + ahead.offset;
            if (ahead.items != 0 && first < n) {
                prefetch_lines(address_of(first), address_of(std::min(n, first + ahead.items)));
            }
            const std::size_t best = best_child(hole);
            a_[hole] = std::move(a_[best]);
            hole = best;
        }
        return hole;
    }

    [[nodiscard]] std::uintptr_t address_of(std::size_t i) const noexcept {
        return reinterpret_cast<std::uintptr_t>(a_.data() + i);
    }

    /// Puts x in the hole and lets it rise while its parent does not come out before it.
    void rise_from(std::size_t hole, T x) {
        while (hole > 0) {
            const std::size_t parent = (hole - 1) / d();
            if (first(a_[parent], x)) break;
            a_[hole] = std::move(a_[parent]);
            hole = parent;
        }
        a_[hole] = std::move(x);
    }

    void validate() const {
        if constexpr (validate_heaps) require_invariant(is_heap(), "d-ary heap order");
    }

    std::vector<T, ChildAlignedAllocator<T>> a_;  ///< children of a node share a cache line
    std::size_t d_ = D == 0 ? 2 : D;              ///< read only when D == 0
    [[no_unique_address]] Less less_{};
    [[no_unique_address]] Obs obs_{};
};

}  // namespace collide::pq
