#pragma once
/// \file
/// The lecture's heapsort, in place on a random-access range: bottom-up heap construction (sink
/// every internal node, last to first; fewer than 2N compares), then sort-down (swap the root,
/// the largest, with the last item of the heap, shrink the heap, sink the new root). Each sink
/// level costs at most 2 compares (pick the larger child, compare it with the sinking item), so
/// the whole sort makes at most 2 N lg N compares. Not stable; O(1) extra memory.

#include <cstddef>
#include <functional>
#include <iterator>
#include <utility>

#include "collide/sim/pq/observer.hpp"

namespace collide::pq {

namespace detail {

/// Sinks the item at root i of the max-heap held in first[0 .. n) under less.
template <std::random_access_iterator It, class Less, class Obs>
void heapsort_sink(It first, std::size_t i, std::size_t n, Less& less, Obs& obs) {
    using diff = std::iter_difference_t<It>;
    auto at = [&](std::size_t k) -> decltype(auto) { return first[static_cast<diff>(k)]; };
    obs.sink_starts(i, n);
    auto x = std::move(at(i));
    for (;;) {
        std::size_t child = 2 * i + 1;
        if (child >= n) break;
        if (child + 1 < n && (obs.compared(child + 1, child), less(at(child), at(child + 1))))
            ++child;
        obs.compared(i, child);
        if (!less(x, at(child))) break;
        obs.exchanged(i, child);
        at(i) = std::move(at(child));
        i = child;
    }
    at(i) = std::move(x);
}

}  // namespace detail

/// Sorts [first, last) into ascending order under `less` (a strict weak order). At most
/// 2 N lg N calls of `less` for N items; O(1) extra memory; not stable. `less` is taken by
/// reference so a counting comparator sees every call. `obs` (observer.hpp) sees every sink,
/// compare and exchange (the sortdown's exchange of root and last included).
template <std::random_access_iterator It, class Less = std::less<>, QueueObserver Obs = NoObserver>
void heapsort(It first, It last, Less&& less = Less{}, Obs obs = Obs{}) {
    const auto n = static_cast<std::size_t>(last - first);
    if (n < 2) return;
    for (std::size_t i = n / 2; i-- > 0;) detail::heapsort_sink(first, i, n, less, obs);
    for (std::size_t end = n - 1; end > 0; --end) {
        obs.exchanged(0, end);
        std::iter_swap(first, first + static_cast<std::iter_difference_t<It>>(end));
        detail::heapsort_sink(first, 0, end, less, obs);
    }
}

}  // namespace collide::pq
