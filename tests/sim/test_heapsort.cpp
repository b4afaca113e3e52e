// Heapsort (in place, at most 2 N lg N compares) and top-M of a stream (O(M) memory).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "collide/sim/pq/heapsort.hpp"
#include "collide/sim/pq/top_m.hpp"

using namespace collide::pq;

namespace {

/// Heapsorts a copy of `in`, checks it against std::sort and returns the number of compares.
std::uint64_t heapsort_compares(const std::vector<int>& in) {
    std::vector<int> sorted = in;
    std::uint64_t compares = 0;
    heapsort(sorted.begin(), sorted.end(), [&](int a, int b) {
        ++compares;
        return a < b;
    });
    std::vector<int> expected = in;
    std::sort(expected.begin(), expected.end());
    CHECK(sorted == expected);
    return compares;
}

double two_n_lg_n(std::size_t n) {
    return n < 2 ? 0.0 : 2.0 * static_cast<double>(n) * std::log2(static_cast<double>(n));
}

std::vector<int> random_ints(std::size_t n, int range, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> value(0, range - 1);
    std::vector<int> v(n);
    for (int& x : v) x = value(rng);
    return v;
}

}  // namespace

TEST_CASE("heapsort sorts random, sorted, reversed and all-equal input within 2 N lg N compares") {
    for (std::size_t n :
         {0u, 1u, 2u, 3u, 4u, 5u, 7u, 8u, 9u, 16u, 17u, 100u, 1000u, 4096u, 8191u}) {
        CAPTURE(n);
        const std::vector<int> random = random_ints(n, 1 << 30, n);
        std::vector<int> sorted = random;
        std::sort(sorted.begin(), sorted.end());
        const std::vector<int> reversed(sorted.rbegin(), sorted.rend());
        const std::vector<int> equal(n, 7);
        const std::vector<int> few_distinct = random_ints(n, 3, n + 1);
        const std::vector<int>& sorted_input = sorted;
        for (const auto* input : {&random, &sorted_input, &reversed, &equal, &few_distinct}) {
            CHECK(static_cast<double>(heapsort_compares(*input)) <= two_n_lg_n(n));
        }
    }
}

TEST_CASE("heapsort on all-equal input is linear: every sink stops at once") {
    const std::vector<int> equal(10000, 3);
    CHECK(heapsort_compares(equal) <= 2 * 2 * equal.size());
}

TEST_CASE("heapsort takes any comparator, e.g. descending strings") {
    std::vector<std::string> words{"P", "Q", "E", "X", "A", "M", "P", "L", "E"};
    heapsort(words.begin(), words.end(), std::greater<>{});
    CHECK(words == std::vector<std::string>{"X", "Q", "P", "P", "M", "L", "E", "E", "A"});
}

TEST_CASE("top-M of a stream equals the first M of a full sort") {
    const std::vector<int> stream = random_ints(2000, 200, 5);  // many duplicates
    std::vector<int> sorted = stream;
    std::sort(sorted.begin(), sorted.end(), std::greater<>{});
    for (std::size_t m : {0u, 1u, 2u, 10u, 999u, 2000u, 3000u}) {
        CAPTURE(m);
        const std::vector<int> top = top_m(stream.begin(), stream.end(), m);
        const std::size_t kept = std::min(m, stream.size());
        REQUIRE(top.size() == kept);
        CHECK(std::equal(top.begin(), top.end(), sorted.begin()));
    }
}

TEST_CASE("TopM holds at most M items whatever the stream length") {
    TopM<int> keep(5);
    for (int i = 0; i < 100000; ++i) {
        keep.offer((i * 7919) % 100003);
        REQUIRE(keep.size() <= 5);
    }
    CHECK(keep.capacity() == 5);
    const std::vector<int> top = keep.largest_first();
    CHECK(top == std::vector<int>{100002, 100001, 100000, 99999, 99998});
}

TEST_CASE("TopM with a custom order keeps the M smallest") {
    TopM<int, std::greater<int>> keep(3, std::greater<int>{});
    for (int x : {5, 1, 9, 3, 9, 0, 7}) keep.offer(x);
    CHECK(keep.largest_first() == std::vector<int>{0, 1, 3});
}
