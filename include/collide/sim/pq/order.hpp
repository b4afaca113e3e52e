#pragma once
/// \file
/// Orientation of the lecture's priority queues and the shared "which comes out first" rule.

#include <cstdlib>
#include <functional>

#include "collide/error.hpp"

namespace collide::pq {

/// Which end of the key order a queue hands out first.
enum class Orientation {
    max,  ///< remove-max queue (the lecture's MaxPQ): the largest key under `Less` comes out first
    min,  ///< remove-min queue (event queues): the smallest key under `Less` comes out first
};

/// True when `a` must come out before `b` in a queue of orientation O ordered by `less`.
/// Keys that tie under `less` give false both ways; queues that must agree on the order of ties
/// (the engines' event queues) use a key type whose `less` is a strict total order.
template <Orientation O, class Less, class T>
[[nodiscard]] constexpr bool comes_first(const Less& less, const T& a, const T& b) {
    if constexpr (O == Orientation::max) {
        return less(b, a);
    } else {
        return less(a, b);
    }
}

/// Called after every mutation when COLLIDE_VALIDATE is on: a broken heap is a programming error
/// that must stop the test at the mutation that caused it, not later.
inline void require_invariant(bool ok, const char* what) {
    if (!ok) throw_runtime_error(std::string("priority-queue invariant violated: ") + what);
}

#if defined(COLLIDE_VALIDATE)
inline constexpr bool validate_heaps = true;
#else
inline constexpr bool validate_heaps = false;
#endif

}  // namespace collide::pq
