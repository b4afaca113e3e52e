// Core checks of the d-ary and indexed heaps used by the engines (the full randomised suite
// against a reference model lives in test_pq.cpp).
#include <doctest/doctest.h>

#include "collide/sim/pq/dary_heap.hpp"
#include "collide/sim/pq/indexed_heap.hpp"

using namespace collide::pq;

TEST_CASE("DaryHeap max-oriented pops in descending order") {
    DaryHeap<int, Orientation::max, 3> h;
    for (int x : {5, 1, 9, 3, 9, 0, 7}) h.push(x);
    CHECK(h.is_heap());
    std::vector<int> out;
    while (!h.empty()) out.push_back(h.pop());
    CHECK(out == std::vector<int>{9, 9, 7, 5, 3, 1, 0});
}

TEST_CASE("IndexedDaryHeap: change_key moves items both ways and keeps pos the inverse of heap") {
    IndexedDaryHeap<double, Orientation::min, 2> h(8);
    for (unsigned i = 0; i < 8; ++i) h.push(i, 10.0 + i);
    CHECK(h.top() == 0);
    h.decrease_key(7, 1.0);
    CHECK(h.top() == 7);
    h.increase_key(7, 100.0);
    CHECK(h.top() == 0);
    h.erase(0);
    CHECK(h.top() == 1);
    CHECK_FALSE(h.contains(0));
    CHECK(h.check_invariants());
    CHECK_THROWS_AS(h.decrease_key(3, 50.0), collide::Error);  // wrong direction
    CHECK_THROWS_AS(h.erase(0), collide::Error);               // unknown handle
    CHECK_THROWS_AS(h.push(1, 3.0), collide::Error);           // already present
}
