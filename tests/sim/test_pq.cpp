// Every queue of the lecture against a reference model (std::multiset) on long random operation
// sequences with many duplicate keys, with the queue's invariant checked after every operation;
// the indexed heap's handle operations; agreement of all queues under a strict total order.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <iterator>
#include <map>
#include <random>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "collide/error.hpp"
#include "collide/sim/pq/indexed_heap.hpp"
#include "collide/sim/pq/with_queue.hpp"

using namespace collide::pq;

namespace {

/// 10^5 operations per random sequence. COLLIDE_VALIDATE builds run an O(N) validator inside
/// every mutation and in CI are -O0 sanitizer builds, so there a sequence is 2.5 * 10^4
/// operations to keep the suite within seconds.
constexpr int ops_per_sequence = validate_heaps ? 25'000 : 100'000;

/// The structural invariant of each queue (an unordered array has none).
template <class Q>
bool holds_invariant(const Q& q) {
    if constexpr (requires { q.is_heap(); }) {
        return q.is_heap();
    } else if constexpr (requires { q.is_sorted(); }) {
        return q.is_sorted();
    } else if constexpr (requires { q.check_invariants(); }) {
        return q.check_invariants();
    } else {
        return true;
    }
}

/// The item the reference model says comes out next.
template <Orientation O>
int model_top(const std::multiset<int>& model) {
    if constexpr (O == Orientation::max) {
        return *model.rbegin();
    } else {
        return *model.begin();
    }
}

/// Random pushes and pops (keys from a small range, so many duplicates), with the push
/// probability switching between 0.65 and 0.35 every `swing` operations so the queue repeatedly
/// grows to about 0.3 * swing items and drains, often to empty. Compares every top and pop with
/// the model and checks the invariant after every operation. Returns the sequence popped.
template <Orientation O, Queue Q>
std::vector<int> check_against_model(Q q, std::uint64_t seed, int swing, int key_range,
                                     int ops = ops_per_sequence) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> key(0, key_range - 1);
    std::bernoulli_distribution grow(0.65);
    std::bernoulli_distribution shrink(0.35);
    std::multiset<int> model;
    std::vector<int> popped;
    std::size_t mismatches = 0;
    std::size_t broken = 0;
    std::size_t largest = 0;
    for (int op = 0; op < ops; ++op) {
        const bool growing = (op / swing) % 2 == 0;
        const bool push = model.empty() || (growing ? grow(rng) : shrink(rng));
        if (push) {
            const int k = key(rng);
            q.push(k);
            model.insert(k);
        } else {
            const int expected = model_top<O>(model);
            mismatches += (q.top() != expected);
            const int got = q.pop();
            mismatches += (got != expected);
            model.erase(model.find(expected));
            popped.push_back(got);
        }
        mismatches += (q.size() != model.size()) + (q.empty() != model.empty());
        // Validating builds check inside every mutation (and throw); don't pay for it twice.
        if constexpr (!validate_heaps) broken += !holds_invariant(q);
        largest = std::max(largest, model.size());
    }
    CHECK(mismatches == 0);
    CHECK(broken == 0);
    CHECK(largest >= static_cast<std::size_t>(swing) / 5);  // the sequence did exercise depth
    CHECK(popped.size() > static_cast<std::size_t>(ops) / 3);
    return popped;
}

/// Small queues (about 15 items at most) keep the O(N) implementations and the O(N) validators
/// of COLLIDE_VALIDATE builds fast; the key range is narrow so most keys are duplicates.
template <Orientation O>
void check_kinds_against_model(std::initializer_list<const char*> kinds) {
    constexpr int swing = 50;
    constexpr int key_range = 20;
    for (const char* text : kinds) {
        CAPTURE(text);
        const std::uint64_t seed = 20261121;
        with_queue<int, O, std::less<int>>(parse_queue_kind(text), [&](auto q) {
            (void)check_against_model<O>(std::move(q), seed, swing, key_range);
        });
    }
}

}  // namespace

// Every implementation and every compiled arity, each in one orientation (both orientations are
// covered for arrays, heaps and the indexed heap).
TEST_CASE(
    "max-queues match a multiset over 10^5 random operations with duplicates (fewer when "
    "validating)") {
    check_kinds_against_model<Orientation::max>(
        {"unordered", "binary", "dary:4", "dary:5", "indexed:4"});
}

TEST_CASE(
    "min-queues match a multiset over 10^5 random operations with duplicates (fewer when "
    "validating)") {
    check_kinds_against_model<Orientation::min>(
        {"ordered", "dary:3", "dary:8", "indexed:2", "indexed:8"});
}

TEST_CASE("heaps match a multiset when they grow deep (thousands of items)") {
    // The heaps only: the array queues are O(N) per operation. In validating builds the O(N)
    // checker runs after every mutation, so the sequences are shorter there.
    const int swing = validate_heaps ? 1000 : 12000;
    const int ops = validate_heaps ? 6'000 : ops_per_sequence;
    const int keys = 1 << 20;
    check_against_model<Orientation::min>(BinaryHeap<int, Orientation::min>{}, 7, swing, keys, ops);
    check_against_model<Orientation::max>(BinaryHeap<int, Orientation::max>{}, 7, swing, keys, ops);
    check_against_model<Orientation::min>(DaryHeap<int, Orientation::min, 3>{}, 8, swing, keys,
                                          ops);
    check_against_model<Orientation::max>(DaryHeap<int, Orientation::max, 8>{}, 9, swing, keys,
                                          ops);
    check_against_model<Orientation::max>(DaryHeap<int, Orientation::max, 0>(6), 10, swing, keys,
                                          ops);
    check_against_model<Orientation::min>(IndexedHeapQueue<int, Orientation::min, 4>{}, 11, swing,
                                          keys, ops);
}

namespace {

using TimedId = std::pair<int, int>;  ///< (time, id): an event key in miniature

/// Orders by time only: many distinct keys tie.
struct TimeOnlyLess {
    bool operator()(const TimedId& a, const TimedId& b) const { return a.first < b.first; }
};

/// A fixed random sequence of pushes (true) and pops over keys with many equal times.
struct TieWorkload {
    std::vector<bool> push;
    std::vector<TimedId> keys;

    TieWorkload() {
        std::mt19937_64 rng(42);
        std::uniform_int_distribution<int> time(0, 30);
        std::bernoulli_distribution grow(0.55);
        for (int i = 0; i < 2000; ++i) {
            push.push_back(grow(rng));
            keys.emplace_back(time(rng), i);
        }
    }

    /// Runs the workload on a queue of kind `text`, then drains it; returns everything popped.
    template <class Less>
    std::vector<TimedId> run(const char* text) const {
        return with_queue<TimedId, Orientation::min, Less>(parse_queue_kind(text), [&](auto q) {
            std::vector<TimedId> out;
            for (std::size_t i = 0; i < push.size(); ++i) {
                if (push[i] || q.empty()) {
                    q.push(keys[i]);
                } else {
                    out.push_back(q.pop());
                }
            }
            while (!q.empty()) out.push_back(q.pop());
            return out;
        });
    }

    /// The same workload on an ordered set, the reference.
    [[nodiscard]] std::vector<TimedId> run_model() const {
        std::set<TimedId> model;
        std::vector<TimedId> out;
        for (std::size_t i = 0; i < push.size(); ++i) {
            if (push[i] || model.empty()) {
                model.insert(keys[i]);
            } else {
                out.push_back(*model.begin());
                model.erase(model.begin());
            }
        }
        out.insert(out.end(), model.begin(), model.end());
        return out;
    }
};

constexpr const char* all_kinds[] = {"unordered", "ordered", "binary",    "dary:3",    "dary:4",
                                     "dary:8",    "dary:6",  "indexed:2", "indexed:4", "indexed:8"};

}  // namespace

TEST_CASE("under a strict total order every queue hands out the same sequence") {
    // (time, id) compared lexicographically: the id breaks every time tie, as an engine's event
    // key must, so all implementations agree item for item.
    const TieWorkload work;
    const auto reference = work.run<std::less<TimedId>>("binary");
    REQUIRE(reference.size() > work.keys.size() / 2);  // everything pushed, then drained
    CHECK(reference == work.run_model());
    for (const char* text : all_kinds) {
        CAPTURE(text);
        CHECK(work.run<std::less<TimedId>>(text) == reference);
    }
}

TEST_CASE("with ties under Less the implementations may disagree (why event keys break ties)") {
    const TieWorkload work;
    const auto reference = work.run<TimeOnlyLess>("binary");
    int disagreeing = 0;
    for (const char* text : all_kinds) {
        const auto out = work.run<TimeOnlyLess>(text);
        REQUIRE(out.size() == reference.size());
        for (std::size_t i = 0; i < out.size(); ++i) REQUIRE(out[i].first == reference[i].first);
        disagreeing += (out != reference);
    }
    CHECK(disagreeing > 0);  // same times in the same order, but not the same ids
}

// ---- the indexed heap's handle operations against a model ------------------------------------

TEST_CASE(
    "IndexedDaryHeap matches a model over 10^5 random handle operations (fewer when validating)") {
    constexpr unsigned handles = 300;
    IndexedDaryHeap<int, Orientation::min, 3> heap(handles);
    std::map<unsigned, int> key_of;            // model: handle -> key
    std::set<std::pair<int, unsigned>> order;  // model: (key, handle); ties of keys allowed
    std::mt19937_64 rng(99);
    std::uniform_int_distribution<unsigned> handle(0, handles - 1);
    std::uniform_int_distribution<int> key(0, 400);
    std::uniform_int_distribution<int> what(0, 5);
    std::size_t mismatches = 0;
    std::size_t broken = 0;
    for (int op = 0; op < ops_per_sequence; ++op) {
        const unsigned h = handle(rng);
        const int k = key(rng);
        const bool present = key_of.count(h) > 0;
        mismatches += (heap.contains(h) != present);
        switch (what(rng)) {
            case 0:  // push or change
                heap.push_or_change(h, k);
                if (present) order.erase({key_of[h], h});
                key_of[h] = k;
                order.insert({k, h});
                break;
            case 1:  // pop: the top key must be the model's smallest (the handle may be any tie)
                if (order.empty()) break;
                mismatches += (heap.top_key() != order.begin()->first);
                {
                    const unsigned got = heap.pop();
                    mismatches += (key_of.count(got) == 0 || key_of[got] != order.begin()->first);
                    order.erase({key_of[got], got});
                    key_of.erase(got);
                }
                break;
            case 2:  // erase
                if (!present) {
                    CHECK_THROWS_AS(heap.erase(h), collide::Error);
                    break;
                }
                heap.erase(h);
                order.erase({key_of[h], h});
                key_of.erase(h);
                break;
            case 3:  // decrease_key, which must refuse a larger key
                if (!present) break;
                if (k > key_of[h]) {
                    CHECK_THROWS_AS(heap.decrease_key(h, k), collide::Error);
                    break;
                }
                heap.decrease_key(h, k);
                order.erase({key_of[h], h});
                key_of[h] = k;
                order.insert({k, h});
                break;
            case 4:  // increase_key, which must refuse a smaller key
                if (!present) break;
                if (k < key_of[h]) {
                    CHECK_THROWS_AS(heap.increase_key(h, k), collide::Error);
                    break;
                }
                heap.increase_key(h, k);
                order.erase({key_of[h], h});
                key_of[h] = k;
                order.insert({k, h});
                break;
            default:  // key lookup
                if (present) {
                    mismatches += (heap.key(h) != key_of[h]);
                } else {
                    CHECK_THROWS_AS((void)heap.key(h), collide::Error);
                }
                break;
        }
        mismatches += (heap.size() != key_of.size());
        if constexpr (!validate_heaps) broken += !heap.check_invariants();
    }
    CHECK(mismatches == 0);
    CHECK(broken == 0);
}

TEST_CASE("IndexedDaryHeap refuses misuse with an Error and stays intact") {
    IndexedDaryHeap<double, Orientation::max, 4> heap(4);
    heap.push(0, 1.0);
    heap.push(2, 5.0);
    CHECK_THROWS_AS(heap.push(4, 1.0), collide::Error);          // handle out of range
    CHECK_THROWS_AS(heap.push(2, 1.0), collide::Error);          // already present
    CHECK_THROWS_AS(heap.change_key(1, 1.0), collide::Error);    // not in the heap
    CHECK_THROWS_AS(heap.change_key(99, 1.0), collide::Error);   // beyond the handle range
    CHECK_THROWS_AS(heap.increase_key(0, 0.5), collide::Error);  // wrong direction
    CHECK_THROWS_AS(heap.decrease_key(2, 6.0), collide::Error);  // wrong direction
    CHECK(heap.check_invariants());
    CHECK(heap.top() == 2);
    heap.increase_key(0, 9.0);  // max-oriented: a larger key moves up
    CHECK(heap.top() == 0);
    heap.reserve_handles(10);
    heap.push(9, 7.0);
    CHECK(heap.pop() == 0);
    CHECK(heap.pop() == 9);
    CHECK(heap.pop() == 2);
    CHECK(heap.empty());
    CHECK(heap.check_invariants());
}

// ---- keys that name their own handle (the fast engine's layout: no handle array) --------------

namespace {

struct OwnedKey {
    int key = 0;
    std::uint32_t handle = 0;
    bool operator<(const OwnedKey& o) const {
        return key != o.key ? key < o.key : handle < o.handle;
    }
};
struct OwnerOf {
    std::uint32_t operator()(const OwnedKey& k) const noexcept { return k.handle; }
};

}  // namespace

TEST_CASE(
    "IndexedDaryHeap with keys naming their handles matches a model and refuses a wrong name") {
    constexpr unsigned handles = 200;
    IndexedDaryHeap<OwnedKey, Orientation::min, 4, std::less<OwnedKey>, OwnerOf> heap(handles);
    std::set<std::pair<int, unsigned>> order;  // model: (key, handle)
    std::map<unsigned, int> key_of;
    std::mt19937_64 rng(7);
    std::uniform_int_distribution<unsigned> handle(0, handles - 1);
    std::uniform_int_distribution<int> key(0, 300);
    std::size_t mismatches = 0;
    const int ops = validate_heaps ? 6'000 : 30'000;
    for (int op = 0; op < ops; ++op) {
        const unsigned h = handle(rng);
        const int k = key(rng);
        if (op % 3 == 2 && !order.empty()) {
            mismatches +=
                heap.top() != order.begin()->second || heap.top_key().key != order.begin()->first;
            const unsigned got = heap.pop();
            order.erase({key_of[got], got});
            key_of.erase(got);
        } else {
            heap.push_or_change(h, OwnedKey{k, h});
            if (key_of.count(h) > 0) order.erase({key_of[h], h});
            key_of[h] = k;
            order.insert({k, h});
        }
        mismatches += heap.size() != order.size();
    }
    CHECK(mismatches == 0);
    CHECK(heap.check_invariants());
    std::vector<unsigned> model;
    for (const auto& [k, h] : order) model.push_back(h);
    std::vector<unsigned> in_array = heap.array();
    std::sort(in_array.begin(), in_array.end());
    std::sort(model.begin(), model.end());
    CHECK(in_array == model);
    // A key that names another handle is a programming error, refused before any change.
    const unsigned present = heap.top();
    CHECK_THROWS_AS(heap.change_key(present, OwnedKey{0, present + 1}), collide::Error);
    CHECK(heap.check_invariants());
    CHECK(heap.top() == present);
}

TEST_CASE("IndexedDaryHeap larger than the caches (sinks prefetch levels ahead) matches a model") {
    // 256-byte keys: 5000 of them exceed prefetch_bytes, so sinks take the prefetching path.
    struct FatKey {
        int key = 0;
        std::uint32_t handle = 0;
        std::array<char, 248> ballast{};
        bool operator<(const FatKey& o) const {
            return key != o.key ? key < o.key : handle < o.handle;
        }
    };
    struct FatOwner {
        std::uint32_t operator()(const FatKey& k) const noexcept { return k.handle; }
    };
    using Heap = IndexedDaryHeap<FatKey, Orientation::min, 4, std::less<FatKey>, FatOwner>;
    constexpr unsigned handles = 5000;
    static_assert(handles * sizeof(FatKey) > Heap::prefetch_bytes);
    Heap heap(handles);
    std::set<std::pair<int, unsigned>> order;  // model: (key, handle)
    std::map<unsigned, int> key_of;
    std::mt19937_64 rng(11);
    std::uniform_int_distribution<unsigned> handle(0, handles - 1);
    std::uniform_int_distribution<int> key(0, 1'000'000);
    const auto set_key = [&](unsigned h, int k) {
        heap.push_or_change(h, FatKey{k, h, {}});
        if (key_of.count(h) > 0) order.erase({key_of[h], h});
        key_of[h] = k;
        order.insert({k, h});
    };
    for (unsigned h = 0; h < handles; ++h) set_key(h, key(rng));
    std::size_t mismatches = 0;
    std::size_t broken = 0;
    std::size_t largest = 0;
    const int ops = validate_heaps ? 4'000 : 40'000;
    for (int op = 0; op < ops; ++op) {
        const unsigned h = handle(rng);
        if (op % 4 == 3 && !order.empty()) {
            // The engine's step: the top's key moves later (a sink from the root).
            const unsigned top = heap.top();
            mismatches +=
                top != order.begin()->second || heap.top_key().key != order.begin()->first;
            set_key(top, order.begin()->first + key(rng));
        } else if (op % 4 == 2 && !order.empty()) {
            const unsigned got = heap.pop();
            mismatches += got != order.begin()->second;
            order.erase({key_of[got], got});
            key_of.erase(got);
        } else {
            set_key(h, key(rng));
        }
        largest = std::max(largest, heap.size());
        mismatches += heap.size() != order.size();
        if (op % 101 == 0) broken += !heap.check_invariants();
    }
    CHECK(largest * sizeof(FatKey) > Heap::prefetch_bytes);
    CHECK(mismatches == 0);
    CHECK(broken == 0);
    CHECK(heap.check_invariants());
    std::vector<unsigned> drained;
    while (!heap.empty()) drained.push_back(heap.pop());
    std::vector<unsigned> model;
    for (const auto& [k, h] : order) model.push_back(h);
    CHECK(drained == model);
}

// ---- DaryHeap's bottom-up pop leaves exactly the lecture's array --------------------------------

namespace {

/// The lecture's heap, written as plainly as possible: pop moves the last item to the root and
/// sinks it while a child comes out before it (first of tying children).
template <unsigned D, class T = int>
struct TextbookMaxHeap {
    std::vector<T> a;

    void push(T x) {
        a.push_back(x);
        for (std::size_t i = a.size() - 1; i > 0 && a[(i - 1) / D] < a[i]; i = (i - 1) / D) {
            std::swap(a[i], a[(i - 1) / D]);
        }
    }

    T pop() {
        const T out = a.front();
        a.front() = a.back();
        a.pop_back();
        std::size_t i = 0;
        for (;;) {
            std::size_t best = D * i + 1;
            if (best >= a.size()) break;
            for (std::size_t c = best + 1; c < std::min<std::size_t>(D * i + D + 1, a.size());
                 ++c) {
                if (a[best] < a[c]) best = c;
            }
            if (!(a[i] < a[best])) break;
            std::swap(a[i], a[best]);
            i = best;
        }
        return out;
    }
};

/// An item of Bytes bytes: the heap's storage puts item 1 on a cache line, which for items
/// narrower than a line means starting the array mid-line and for wider ones not at all.
template <std::size_t Bytes>
struct SizedItem {
    int key = 0;
    std::array<char, Bytes - sizeof(int)> payload{};
    friend bool operator<(const SizedItem& a, const SizedItem& b) { return a.key < b.key; }
    friend bool operator==(const SizedItem& a, const SizedItem& b) { return a.key == b.key; }
};

/// Returns the largest heap's size in bytes.
template <unsigned D, class T = int>
std::size_t check_same_arrays_as_textbook(int ops = 6000) {
    CAPTURE(D);
    CAPTURE(sizeof(T));
    DaryHeap<T, Orientation::max, D> fast;
    TextbookMaxHeap<D, T> plain;
    std::mt19937_64 rng(D);
    std::uniform_int_distribution<int> key(0, 9);  // mostly ties
    std::bernoulli_distribution push(0.55);
    std::size_t differing = 0;
    std::size_t largest = 0;
    for (int op = 0; op < ops; ++op) {
        if (plain.a.empty() || push(rng)) {
            T k{};
            if constexpr (std::is_same_v<T, int>) {
                k = key(rng);
            } else {
                k.key = key(rng);
            }
            fast.push(k);
            plain.push(k);
        } else {
            differing += fast.pop() != plain.pop();
        }
        differing += !std::ranges::equal(fast.array(), plain.a);
        largest = std::max(largest, plain.a.size());
    }
    CHECK(differing == 0);
    CHECK(plain.a.size() > 100);
    return largest * sizeof(T);
}

}  // namespace

TEST_CASE("DaryHeap's bottom-up pop leaves the same array as the lecture's sink, ties included") {
    check_same_arrays_as_textbook<2>();
    check_same_arrays_as_textbook<3>();
    check_same_arrays_as_textbook<4>();
    check_same_arrays_as_textbook<8>();
}

TEST_CASE("items of any width (line-aligned children storage) match the lecture's sink too") {
    check_same_arrays_as_textbook<2, SizedItem<12>>(3000);
    check_same_arrays_as_textbook<4, SizedItem<16>>(3000);
    check_same_arrays_as_textbook<3, SizedItem<96>>(3000);
    check_same_arrays_as_textbook<8, SizedItem<200>>(3000);
}

TEST_CASE("heaps larger than the caches (pop prefetches levels ahead) match the lecture's sink") {
    using Fat = SizedItem<4096>;
    constexpr std::size_t limit = DaryHeap<Fat, Orientation::max, 2>::prefetch_bytes;
    CHECK(check_same_arrays_as_textbook<2, Fat>(4000) > limit);
    CHECK(check_same_arrays_as_textbook<3, Fat>(4000) > limit);
    CHECK(check_same_arrays_as_textbook<4, Fat>(4000) > limit);
}

TEST_CASE("a d-ary heap stores item 1 at the start of a cache line, so children share lines") {
    DaryHeap<double, Orientation::min, 4> heap;
    for (int i = 0; i < 100; ++i) heap.push(i);
    CHECK(reinterpret_cast<std::uintptr_t>(heap.array().data() + 1) % heap_line_bytes == 0);
    DaryHeap<SizedItem<16>, Orientation::max, 4> wide;
    for (int i = 0; i < 100; ++i) wide.push(SizedItem<16>{i, {}});
    CHECK(reinterpret_cast<std::uintptr_t>(wide.array().data() + 1) % heap_line_bytes == 0);
}

TEST_CASE("a heap array past the huge-page threshold still puts item 1 on a cache line") {
    // Allocated directly: filling a heap this big would take minutes with the per-push checks
    // of COLLIDE_VALIDATE builds.
    ChildAlignedAllocator<double> alloc;
    const std::size_t n = huge_page_min_bytes / sizeof(double) + 1000;
    double* a = alloc.allocate(n);
    CHECK(reinterpret_cast<std::uintptr_t>(a + 1) % heap_line_bytes == 0);
    std::fill_n(a, n, 1.5);  // the whole range is usable (ASan: no overflow)
    CHECK(a[n - 1] == 1.5);
    alloc.deallocate(a, n);
}

TEST_CASE("BigVector: big arrays start on a huge page, keep their contents as they grow") {
    BigVector<std::uint32_t> small(100, 7);
    CHECK(std::count(small.begin(), small.end(), 7U) == 100);
    BigVector<std::uint32_t> grown;
    const std::uint32_t n = static_cast<std::uint32_t>(2 * huge_page_min_bytes / 4);
    for (std::uint32_t i = 0; i < n; ++i) grown.push_back(i * 3U);  // crosses the threshold
    CHECK(reinterpret_cast<std::uintptr_t>(grown.data()) % huge_page_bytes == 0);
    bool intact = true;
    for (std::uint32_t i = 0; i < n; ++i) intact = intact && grown[i] == i * 3U;
    CHECK(intact);
    BigVector<std::uint32_t> copy = grown;  // copies allocate through the same policy
    CHECK(copy == grown);
    grown.clear();
    grown.shrink_to_fit();  // frees the big block (ASan: size and alignment must match)
    CHECK(copy.back() == (n - 1) * 3U);
}
