// The tournament tree (pq::TournamentTree) and the fast engine's queue that holds it or the
// calendar (pq::CalendarOrTree), against a reference model (std::set ordered like their Less):
// random pops, re-keys (ties on purpose), erasures; the winners checked as they go.
#include <doctest/doctest.h>

#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "collide/error.hpp"
#include "collide/sim/pq/calendar_or_tree.hpp"
#include "collide/sim/pq/tournament_tree.hpp"

using namespace collide::pq;

namespace {

struct TimedKey {
    double t = 0.0;
    std::uint32_t handle = 0;
    /// Ties broken against the handle order (larger handle first), so that a tree which fell
    /// back on leaf order instead of Less would pop ties wrongly.
    bool operator<(const TimedKey& o) const { return t != o.t ? t < o.t : handle > o.handle; }
};
struct HandleOfKey {
    std::uint32_t operator()(const TimedKey& k) const noexcept { return k.handle; }
};
using Tree = TournamentTree<TimedKey, std::less<TimedKey>, HandleOfKey>;
using Queue = CalendarOrTree<TimedKey, std::less<TimedKey>, HandleOfKey>;

using Model = std::set<std::pair<double, std::uint32_t>,
                       std::function<bool(const std::pair<double, std::uint32_t>&,
                                          const std::pair<double, std::uint32_t>&)>>;

Model make_model() {
    return Model([](const auto& x, const auto& y) {
        return TimedKey{x.first, x.second} < TimedKey{y.first, y.second};
    });
}

/// A simulation's queue: pops the earliest event and re-keys its handle, re-keys others up and
/// down, erases some, every step checked against the model; returns the mismatches.
template <class Q>
std::size_t simulate(Q& queue, std::uint32_t handles, int ops, std::mt19937_64& rng) {
    Model model = make_model();
    std::map<std::uint32_t, double> time_of;
    queue.for_each([&](std::uint32_t h, const TimedKey& k) {
        model.insert({k.t, h});
        time_of[h] = k.t;
    });
    std::uniform_int_distribution<std::uint32_t> handle(0, handles - 1);
    std::uniform_int_distribution<int> what(0, 9);
    // Coarse times (multiples of 1/8) so that ties are common.
    std::uniform_int_distribution<int> ahead(0, 40);
    double now = 0.0;
    std::size_t mismatches = 0;
    const auto rekey = [&](std::uint32_t h, double t) {
        queue.push_or_change(h, TimedKey{t, h});
        if (time_of.count(h) > 0) model.erase({time_of[h], h});
        time_of[h] = t;
        model.insert({t, h});
    };
    for (int op = 0; op < ops; ++op) {
        const int w = what(rng);
        if (w < 4 && !model.empty()) {
            mismatches += !queue.settle();
            const auto [t, h] = *model.begin();
            mismatches += queue.top() != h || queue.top_key().t != t;
            now = t;
            rekey(h, now + ahead(rng) / 8.0);
        } else if (w < 5) {
            const std::uint32_t h = handle(rng);
            mismatches += queue.contains(h) != (time_of.count(h) > 0);
            if (queue.contains(h)) queue.erase(h);
            if (time_of.count(h) > 0) {
                model.erase({time_of[h], h});
                time_of.erase(h);
            }
        } else {
            // Earlier or later than the handle's key, or the same key again.
            const std::uint32_t h = handle(rng);
            rekey(h, w == 9 && time_of.count(h) > 0 ? time_of[h] : now + ahead(rng) / 8.0);
        }
        mismatches += queue.size() != model.size();
        if (op % 61 == 0 && !queue.check_invariants()) ++mismatches;
    }
    // Drain: everything comes out in the model's order.
    while (!model.empty()) {
        mismatches += !queue.settle();
        const auto [t, h] = *model.begin();
        mismatches += queue.top() != h || queue.top_key().t != t;
        mismatches += queue.key(h).t != t;
        queue.erase(h);
        model.erase(model.begin());
    }
    mismatches += queue.settle();
    return mismatches;
}

}  // namespace

TEST_CASE("a tournament tree pops in the model's order, ties by Less, at every padding of leaves") {
    // Leaves are padded to one more than a multiple of 3: capacities of each remainder, and a
    // tree of one handle.
    for (std::uint32_t handles : {1U, 2U, 3U, 4U, 5U, 17U, 300U, 1001U}) {
        CAPTURE(handles);
        std::mt19937_64 rng(handles);
        Tree tree(handles);
        CHECK(tree.check_invariants());
        CHECK(simulate(tree, handles, 20'000, rng) == 0);
        CHECK(tree.empty());
        CHECK(tree.check_invariants());
    }
}

TEST_CASE("a tournament tree grows its handle range and keeps what it holds") {
    std::mt19937_64 rng(3);
    Tree tree(10);
    for (std::uint32_t h = 0; h < 10; h += 2) tree.push_or_change(h, TimedKey{1.0 + h, h});
    tree.reserve_handles(500);
    CHECK(tree.capacity() == 500);
    CHECK(tree.size() == 5);
    CHECK(tree.key(8).t == 9.0);
    CHECK(tree.top() == 0);
    tree.push_or_change(499, TimedKey{0.5, 499});
    CHECK(tree.top() == 499);
    CHECK(tree.check_invariants());
    CHECK(simulate(tree, 500, 10'000, rng) == 0);
    tree.release();
    CHECK(tree.empty());
    CHECK(tree.capacity() == 0);
    CHECK_FALSE(tree.contains(0));
}

TEST_CASE("a tournament tree refuses unknown handles, keys of other handles and endless times") {
    Tree tree(4);
    tree.push_or_change(1, TimedKey{2.0, 1});
    CHECK_THROWS_AS(tree.push_or_change(4, TimedKey{1.0, 4}), collide::Error);
    CHECK_THROWS_AS(tree.push_or_change(2, TimedKey{1.0, 3}), collide::Error);
    CHECK_THROWS_AS(tree.push_or_change(2, TimedKey{std::numeric_limits<double>::infinity(), 2}),
                    collide::Error);
    CHECK_THROWS_AS(tree.erase(2), collide::Error);
    CHECK_THROWS_AS((void)tree.key(0), collide::Error);
    CHECK(tree.size() == 1);
    CHECK(tree.top() == 1);
    CHECK(tree.check_invariants());
}

TEST_CASE("the fast engine's queue moves its entries between the calendar and the tree") {
    constexpr std::uint32_t handles = 700;
    std::mt19937_64 rng(17);
    Queue queue(handles);
    queue.tune(0.05, 64, 0.0);
    CHECK_FALSE(queue.tree());
    CHECK(simulate(queue, handles, 5'000, rng) == 0);
    for (std::uint32_t h = 0; h < handles; h += 3) queue.push_or_change(h, TimedKey{0.01 * h, h});
    const std::size_t held = queue.size();
    queue.use_tree();
    CHECK(queue.tree());
    CHECK(queue.size() == held);
    CHECK(queue.near().empty());
    CHECK(queue.check_invariants());
    // The calendar's heap is freed: what remains is the tree's 16-byte nodes, 4/3 per handle.
    CHECK(queue.bytes() < 16 * (handles * 4 / 3 + 4) + 64);
    CHECK(simulate(queue, handles, 10'000, rng) == 0);
    // Handles added while the tree is on, then back to the calendar (a watched engine).
    queue.reserve_handles(2 * handles);
    for (std::uint32_t h = 0; h < 2 * handles; h += 5) {
        queue.push_or_change(h, TimedKey{0.02 * h, h});
    }
    const std::size_t more = queue.size();
    queue.tune(std::numeric_limits<double>::infinity(), 2, 0.0);
    CHECK_FALSE(queue.tree());
    CHECK(queue.size() == more);
    CHECK(queue.near().size() == more);
    CHECK(queue.check_invariants());
    CHECK(simulate(queue, 2 * handles, 10'000, rng) == 0);
}
