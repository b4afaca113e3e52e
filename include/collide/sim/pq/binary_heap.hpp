#pragma once
/// \file
/// The lecture's binary heap: a d-ary heap with d = 2 (0-based array: parent (i-1)/2, children
/// 2i+1 and 2i+2; push swims the new item up, pop moves the last item to the root and sinks it).

#include <functional>

#include "collide/sim/pq/dary_heap.hpp"

namespace collide::pq {

template <class T, Orientation O = Orientation::max, class Less = std::less<T>,
          QueueObserver Obs = NoObserver>
using BinaryHeap = DaryHeap<T, O, 2, Less, Obs>;

}  // namespace collide::pq
