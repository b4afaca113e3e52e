// The common queue interface, the run-time choice of queue (`--pq`) and its dispatch to types.
#include <doctest/doctest.h>

#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "collide/error.hpp"
#include "collide/sim/pq/with_queue.hpp"

using namespace collide::pq;

static_assert(Queue<UnorderedArrayPQ<int>>);
static_assert(Queue<OrderedArrayPQ<int, Orientation::min>>);
static_assert(Queue<BinaryHeap<double, Orientation::min>>);
static_assert(Queue<DaryHeap<int, Orientation::max, 3>>);
static_assert(Queue<DaryHeap<int, Orientation::max, 0>>);
static_assert(Queue<IndexedHeapQueue<double, Orientation::min, 4>>);

namespace {

/// Pushes every value, then pops everything; returns the pop order.
template <Queue Q>
std::vector<typename Q::value_type> drain_after_pushing(
    Q q, const std::vector<typename Q::value_type>& in) {
    for (const auto& x : in) q.push(x);
    std::vector<typename Q::value_type> out;
    while (!q.empty()) {
        const auto expected_top = q.top();
        out.push_back(q.pop());
        CHECK(out.back() == expected_top);
    }
    return out;
}

std::string error_message(std::string_view text) {
    try {
        (void)parse_queue_kind(text);
    } catch (const collide::Error& e) {
        CHECK(e.kind() == collide::ErrorKind::input);
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("parse_queue_kind accepts every documented spelling and round-trips to_string") {
    CHECK(parse_queue_kind("unordered").family == QueueFamily::unordered);
    CHECK(parse_queue_kind("ordered").family == QueueFamily::ordered);
    CHECK(parse_queue_kind("binary") == QueueKind{QueueFamily::binary, 2});
    CHECK(parse_queue_kind("dary:3") == QueueKind{QueueFamily::dary, 3});
    CHECK(parse_queue_kind("dary:17") == QueueKind{QueueFamily::dary, 17});
    CHECK(parse_queue_kind("indexed") == QueueKind{QueueFamily::indexed, default_indexed_arity});
    CHECK(parse_queue_kind("indexed:8") == QueueKind{QueueFamily::indexed, 8});
    for (const char* text :
         {"unordered", "ordered", "binary", "dary:2", "dary:8", "indexed:2", "indexed:3"}) {
        CHECK(to_string(parse_queue_kind(text)) == text);
    }
}

TEST_CASE("parse_queue_kind names the field and the bad token") {
    CHECK(error_message("x") ==
          "pq: expected a queue: unordered, ordered, binary, dary:D or indexed[:D], got 'x'");
    CHECK(error_message("dary:65") ==
          "pq: expected dary:D with D a whole number from 2 to 64, got 'dary:65'");
    CHECK(error_message("indexed:5") ==
          "pq: expected indexed:D with D = 2, 3, 4 or 8 (or indexed alone: D = 4), got "
          "'indexed:5'");
    CHECK(error_message("dary").find("'dary'") != std::string::npos);
    CHECK(error_message("dary:").find("'dary:'") != std::string::npos);
    CHECK(error_message("dary:1").find("'dary:1'") != std::string::npos);
    CHECK(error_message("dary:65").find("'dary:65'") != std::string::npos);
    CHECK(error_message("dary:4x").find("'dary:4x'") != std::string::npos);
    CHECK(error_message("indexed:5").find("'indexed:5'") != std::string::npos);
    CHECK(error_message("Binary").find("'Binary'") != std::string::npos);
    CHECK(error_message("").find("''") != std::string::npos);
    try {
        (void)parse_queue_kind("heap", "--impl");
        FAIL("no throw");
    } catch (const collide::Error& e) {
        CHECK(std::string(e.what()).rfind("--impl: expected a queue", 0) == 0);
    }
}

TEST_CASE("with_queue hands f a queue of the kind asked for, each popping in the same order") {
    const std::vector<int> in{5, 1, 9, 3, 9, 0, 7, 7, -2};
    const std::vector<int> expected{-2, 0, 1, 3, 5, 7, 7, 9, 9};
    for (const char* text :
         {"unordered", "ordered", "binary", "dary:2", "dary:3", "dary:4", "dary:8", "dary:5",
          "indexed", "indexed:2", "indexed:3", "indexed:8"}) {
        CAPTURE(text);
        const auto out = with_queue<int, Orientation::min, std::less<int>>(
            parse_queue_kind(text), [&](auto q) { return drain_after_pushing(std::move(q), in); });
        CHECK(out == expected);
    }
}

TEST_CASE(
    "with_queue picks compile-time types for the common arities and a run-time one otherwise") {
    const auto arity_of = [](const char* text) {
        return with_queue<int, Orientation::max, std::less<int>>(
            parse_queue_kind(text), [](auto&& q) {
                using Q = std::remove_cvref_t<decltype(q)>;
                if constexpr (requires { Q::arity; }) {
                    return std::make_tuple(Q::arity, std::size_t{q.d()});
                } else {
                    return std::make_tuple(1u, std::size_t{0});
                }
            });
    };
    CHECK(arity_of("binary") == std::make_tuple(2u, std::size_t{2}));
    CHECK(arity_of("dary:8") == std::make_tuple(8u, std::size_t{8}));
    CHECK(arity_of("dary:6") == std::make_tuple(0u, std::size_t{6}));
}

TEST_CASE("a run-time arity outside 2..64 is refused") {
    CHECK_THROWS_AS((DaryHeap<int, Orientation::max, 0>(1)), collide::Error);
    CHECK_THROWS_AS((DaryHeap<int, Orientation::max, 0>(65)), collide::Error);
    CHECK(DaryHeap<int, Orientation::max, 0>(64).d() == 64);
}

TEST_CASE("IndexedHeapQueue recycles handles and keeps the position map consistent") {
    IndexedHeapQueue<int, Orientation::max, 2> q;
    for (int round = 0; round < 3; ++round) {
        for (int x = 0; x < 20; ++x) q.push((x * 7) % 20);
        for (int x = 19; x >= 10; --x) CHECK(q.pop() == x);
    }
    CHECK(q.size() == 30);
    CHECK(q.heap().capacity() == 64);  // at most 40 present: 16 -> 32 -> 64
    for (int i = 0; i < 1000; ++i) {
        q.push(100 + i);
        CHECK(q.pop() == 100 + i);
    }
    CHECK(q.heap().capacity() == 64);  // freed handles were reused
    CHECK(q.check_invariants());
    CHECK(q.array().size() == 30);
}
