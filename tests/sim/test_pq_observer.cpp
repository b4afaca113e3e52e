// The queues' observers (observer.hpp) report exactly what the queues do: every call of the
// comparator is one reported compare of the two slots holding those values, and replaying the
// reported exchanges, shifts and removals on a shadow copy of the array reproduces the queue's
// own array after every operation. Checked for every implementation, both orientations.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "collide/sim/pq/binary_heap.hpp"
#include "collide/sim/pq/dary_heap.hpp"
#include "collide/sim/pq/heapsort.hpp"
#include "collide/sim/pq/indexed_heap.hpp"
#include "collide/sim/pq/observer.hpp"
#include "collide/sim/pq/ordered_array_pq.hpp"
#include "collide/sim/pq/unordered_array_pq.hpp"

using namespace collide::pq;

namespace {

/// std::less<int> that logs the values of every call.
struct CountingLess {
    std::vector<std::pair<int, int>>* calls = nullptr;
    bool operator()(int a, int b) const {
        calls->emplace_back(a, b);
        return a < b;
    }
};

/// Replays a queue's steps on a shadow array and checks them against the comparator's calls.
struct Shadow {
    std::vector<int> a;
    std::vector<QueueStep> steps;
    std::vector<std::pair<int, int>> calls;
    std::size_t compares = 0;
    std::size_t exchanges = 0;

    /// Applies and clears the steps recorded since the last call.
    void replay() {
        std::size_t call = 0;
        for (const QueueStep& e : steps) {
            switch (e.kind) {
                case QueueStep::Kind::compare: {
                    REQUIRE(call < calls.size());
                    REQUIRE(e.i < a.size());
                    REQUIRE(e.j < a.size());
                    const auto [x, y] = calls[call++];
                    if (e.i == e.j) {  // indexed change_key: the new key against the old one
                        CHECK((x == a[e.i] || y == a[e.i]));
                    } else {
                        const bool same =
                            (x == a[e.i] && y == a[e.j]) || (x == a[e.j] && y == a[e.i]);
                        CHECK(same);
                    }
                    ++compares;
                    break;
                }
                case QueueStep::Kind::exchange:
                case QueueStep::Kind::shift:
                    REQUIRE(e.i < a.size());
                    REQUIRE(e.j < a.size());
                    std::swap(a[e.i], a[e.j]);
                    ++exchanges;
                    break;
                case QueueStep::Kind::remove:
                    REQUIRE(e.i + 1 == a.size());
                    a.pop_back();
                    break;
                case QueueStep::Kind::sink:
                    break;
            }
        }
        // No compare went unreported. Validating builds (COLLIDE_VALIDATE) check the invariants
        // through the same comparator at the end of each mutation: those calls come last.
        if (!validate_heaps) CHECK(call == calls.size());
        steps.clear();
        calls.clear();
    }
};

std::vector<int> random_keys(std::size_t n, int range, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> key(0, range - 1);
    std::vector<int> out(n);
    for (int& k : out) k = key(rng);
    return out;
}

/// Random pushes and pops (pops 40 % of the time) on queue q, checked after every operation.
template <class Q>
void check_queue(Q q, Shadow& shadow, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    const std::vector<int> keys = random_keys(400, 50, seed);  // many ties
    std::size_t next = 0;
    while (next < keys.size()) {
        if (!q.empty() && rng() % 10 < 4) {
            q.pop();
        } else {
            shadow.a.push_back(keys[next]);
            q.push(keys[next++]);
        }
        shadow.replay();
        const auto array = q.array();
        REQUIRE(std::vector<int>(array.begin(), array.end()) == shadow.a);
    }
    CHECK(shadow.compares > 0);
    CHECK(shadow.exchanges > 0);
}

template <Orientation O>
void check_all_plain_queues() {
    const auto run = [](auto make, const char* name, std::uint64_t seed) {
        CAPTURE(name);
        Shadow shadow;
        check_queue(make(CountingLess{&shadow.calls}, QueueRecorder(&shadow.steps)), shadow, seed);
    };
    run([](CountingLess l,
           QueueRecorder r) { return UnorderedArrayPQ<int, O, CountingLess, QueueRecorder>(l, r); },
        "unordered", 1);
    run([](CountingLess l,
           QueueRecorder r) { return OrderedArrayPQ<int, O, CountingLess, QueueRecorder>(l, r); },
        "ordered", 2);
    run([](CountingLess l,
           QueueRecorder r) { return BinaryHeap<int, O, CountingLess, QueueRecorder>(l, r); },
        "binary", 3);
    run([](CountingLess l,
           QueueRecorder r) { return DaryHeap<int, O, 3, CountingLess, QueueRecorder>(l, r); },
        "dary:3", 4);
    run([](CountingLess l,
           QueueRecorder r) { return DaryHeap<int, O, 4, CountingLess, QueueRecorder>(l, r); },
        "dary:4", 5);
    run([](CountingLess l,
           QueueRecorder r) { return DaryHeap<int, O, 0, CountingLess, QueueRecorder>(5, l, r); },
        "dary:5 (run-time arity)", 6);
}

/// The indexed heap, with pushes, pops and key changes up and down on random handles.
template <Orientation O, unsigned D>
void check_indexed(std::uint64_t seed) {
    CAPTURE(D);
    Shadow shadow;
    constexpr std::size_t handles = 64;
    IndexedDaryHeap<int, O, D, CountingLess, void, QueueRecorder> q(
        handles, CountingLess{&shadow.calls}, QueueRecorder(&shadow.steps));
    std::mt19937_64 rng(seed);
    std::vector<std::uint32_t> slot_handle;  // the handle in each shadow slot
    std::vector<std::uint32_t> free;
    for (std::uint32_t h = handles; h-- > 0;) free.push_back(h);
    for (int step = 0; step < 600; ++step) {
        const int key = static_cast<int>(rng() % 50);
        const unsigned what = rng() % 10;
        if (!free.empty() && (q.empty() || what < 5)) {
            const std::uint32_t h = free.back();
            free.pop_back();
            shadow.a.push_back(key);
            q.push(h, key);
        } else if (what < 8) {
            free.push_back(q.pop());
        } else {
            const std::vector<std::uint32_t> order = q.array();
            const std::uint32_t h = order[rng() % order.size()];
            const std::size_t i =
                static_cast<std::size_t>(std::find(order.begin(), order.end(), h) - order.begin());
            shadow.a[i] = key;  // the observer reports the new key in the item's slot
            q.change_key(h, key);
        }
        shadow.replay();
        std::vector<int> keys;
        for (std::uint32_t h : q.array()) keys.push_back(q.key(h));
        REQUIRE(keys == shadow.a);
        REQUIRE(q.check_invariants());
        shadow.calls.clear();  // the check's own compares
    }
    CHECK(shadow.compares > 0);
    CHECK(shadow.exchanges > 0);
}

}  // namespace

TEST_CASE("observer: every queue reports exactly its compares and exchanges (max and min)") {
    check_all_plain_queues<Orientation::max>();
    check_all_plain_queues<Orientation::min>();
}

TEST_CASE(
    "observer: the indexed heap reports exactly its compares and exchanges, key changes too") {
    check_indexed<Orientation::max, 2>(11);
    check_indexed<Orientation::max, 3>(12);
    check_indexed<Orientation::min, 4>(13);
    check_indexed<Orientation::min, 8>(14);
}

TEST_CASE("observer: heapsort reports every sink, compare and exchange") {
    for (std::size_t n : {0U, 1U, 2U, 3U, 11U, 100U}) {
        CAPTURE(n);
        Shadow shadow;
        std::vector<int> v = random_keys(n, 30, n);
        shadow.a = v;
        heapsort(v.begin(), v.end(), CountingLess{&shadow.calls}, QueueRecorder(&shadow.steps));
        std::size_t sinks = 0;
        for (const QueueStep& e : shadow.steps) sinks += e.kind == QueueStep::Kind::sink;
        shadow.replay();
        CHECK(shadow.a == v);
        CHECK(std::is_sorted(v.begin(), v.end()));
        // n / 2 sinks to build the heap, then one per item of the sortdown but the last.
        CHECK(sinks == (n < 2 ? 0 : n / 2 + n - 1));
    }
}

TEST_CASE("observer: a watched heap's lecture pop leaves the same array as the engines' pop") {
    const std::vector<int> keys = random_keys(2000, 100, 21);
    std::mt19937_64 rng(22);
    std::vector<QueueStep> log;
    DaryHeap<int, Orientation::max, 3> plain;
    DaryHeap<int, Orientation::max, 3, std::less<int>, QueueRecorder> watched(std::less<int>{},
                                                                              QueueRecorder(&log));
    for (int k : keys) {
        if (!plain.empty() && rng() % 3 == 0) {
            CHECK(plain.pop() == watched.pop());
        } else {
            plain.push(k);
            watched.push(k);
        }
        REQUIRE(std::equal(plain.array().begin(), plain.array().end(), watched.array().begin(),
                           watched.array().end()));
    }
    CHECK(!log.empty());
}

TEST_CASE("observer: NoObserver takes no space in a queue") {
    CHECK(sizeof(DaryHeap<int>) ==
          sizeof(DaryHeap<int, Orientation::max, 2, std::less<int>, NoObserver>));
    CHECK(sizeof(OrderedArrayPQ<int>) == sizeof(std::vector<int>));
    CHECK(sizeof(UnorderedArrayPQ<int>) == sizeof(std::vector<int>));
}
