// The event calendar (pq::CalendarQueue) against a reference model (std::set ordered like the
// calendar's Less) on random simulations: events rescheduled near and far (beyond the ring, into
// the overflow list), removed, and popped in time order; the invariant checked as it goes.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "collide/sim/pq/calendar_queue.hpp"

using namespace collide::pq;

namespace {

struct TimedKey {
    double t = 0.0;
    std::uint32_t handle = 0;
    bool operator<(const TimedKey& o) const { return t != o.t ? t < o.t : handle < o.handle; }
};
struct HandleOfKey {
    std::uint32_t operator()(const TimedKey& k) const noexcept { return k.handle; }
};
using Calendar = CalendarQueue<TimedKey, std::less<TimedKey>, HandleOfKey>;

/// A simulation's queue: pops in time order while events are rescheduled at now + a delay.
/// Checks every pop against the model; returns the number of mismatches.
std::size_t simulate(Calendar& calendar, std::uint32_t handles, int ops, std::mt19937_64& rng,
                     const std::function<double(std::mt19937_64&)>& delay) {
    std::set<std::pair<double, std::uint32_t>> model;
    std::map<std::uint32_t, double> time_of;
    std::uniform_int_distribution<std::uint32_t> handle(0, handles - 1);
    std::uniform_int_distribution<int> what(0, 9);
    double now = 0.0;
    std::size_t mismatches = 0;
    const auto reschedule = [&](std::uint32_t h, double t) {
        calendar.push_or_change(h, TimedKey{t, h});
        if (time_of.count(h) > 0) model.erase({time_of[h], h});
        time_of[h] = t;
        model.insert({t, h});
    };
    for (int op = 0; op < ops; ++op) {
        const int w = what(rng);
        if (w < 4 && !model.empty()) {
            // Pop: the earliest event, then its handle is rescheduled (a particle's next event).
            mismatches += !calendar.settle();
            const auto [t, h] = *model.begin();
            mismatches += calendar.top() != h || calendar.top_key().t != t;
            now = t;
            reschedule(h, now + delay(rng));
        } else if (w < 5) {
            const std::uint32_t h = handle(rng);
            calendar.erase(h);
            if (time_of.count(h) > 0) {
                model.erase({time_of[h], h});
                time_of.erase(h);
            }
        } else {
            // Ties on purpose: delays of 0 put several events at the same time.
            reschedule(handle(rng), w == 9 ? now : now + delay(rng));
        }
        mismatches += calendar.size() != model.size();
        if (op % 97 == 0 && !calendar.check_invariants()) ++mismatches;
    }
    // Drain: everything comes out in the model's order.
    while (!model.empty()) {
        mismatches += !calendar.settle();
        const auto [t, h] = *model.begin();
        mismatches += calendar.top() != h || calendar.top_key().t != t;
        calendar.erase(h);
        model.erase(model.begin());
    }
    mismatches += calendar.settle();
    return mismatches;
}

/// Delays of mean 1, but one in twenty uniform in [far, far + span): past the ring when the ring
/// is shorter than `far`.
auto mostly_near(double far, double span) {
    return [far, span](std::mt19937_64& g) {
        std::exponential_distribution<double> near(1.0);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        return u(g) < 0.05 ? far + span * u(g) : near(g);
    };
}

}  // namespace

TEST_CASE("the event calendar pops in the model's order, near, far and beyond its ring") {
    constexpr std::uint32_t handles = 300;
    std::mt19937_64 rng(11);
    // Mostly exponential delays (the ring), a few far beyond it (the overflow list).
    const auto delay = mostly_near(50.0, 200.0);
    Calendar calendar(handles);
    calendar.tune(0.01, 64, 0.0);  // ring of 0.64 time units
    CHECK(simulate(calendar, handles, 40'000, rng, delay) == 0);
    CHECK(calendar.check_invariants());
    CHECK(calendar.empty());
}

TEST_CASE("an event calendar's ring rounds up to a power of two and still pops in order") {
    // A block's bucket is a mask of its number, so the ring must be a power of two.
    constexpr std::uint32_t handles = 200;
    std::mt19937_64 rng(23);
    const auto delay = mostly_near(5.0, 20.0);
    Calendar calendar(handles);
    calendar.tune(0.03, 10, 0.0);
    CHECK(calendar.buckets() == 16);
    CHECK(simulate(calendar, handles, 20'000, rng, delay) == 0);
    calendar.tune(0.03, 3, 0.0);
    CHECK(calendar.buckets() == 4);
    CHECK(simulate(calendar, handles, 5'000, rng, delay) == 0);
}

TEST_CASE("an event calendar of one block is a plain heap, and tune() re-files what it holds") {
    constexpr std::uint32_t handles = 100;
    std::mt19937_64 rng(5);
    const auto delay = [](std::mt19937_64& g) {
        return std::exponential_distribution<double>(2.0)(g);
    };
    Calendar calendar(handles);  // untuned: one block
    for (std::uint32_t h = 0; h < handles; ++h) calendar.push_or_change(h, TimedKey{0.01 * h, h});
    CHECK(calendar.near().size() == handles);
    calendar.tune(0.05, 16, 0.0);
    CHECK(calendar.size() == handles);
    CHECK(calendar.near().size() < handles);  // the later ones went to the ring
    CHECK(calendar.check_invariants());
    for (std::uint32_t h = 0; h < handles; ++h) calendar.erase(h);
    CHECK(calendar.empty());
    calendar.tune(std::numeric_limits<double>::infinity(), 2, 0.0);
    CHECK(simulate(calendar, handles, 5'000, rng, delay) == 0);
}

TEST_CASE("an event calendar tuned to one block frees its lists' entries and takes them back") {
    // The fast engine runs many discs' calendar as one block (src/sim/fast_calendar.cpp).
    constexpr std::uint32_t handles = 1000;
    std::mt19937_64 rng(9);
    const auto delay = [](std::mt19937_64& g) {
        return std::exponential_distribution<double>(2.0)(g);
    };
    Calendar calendar(handles);
    calendar.tune(0.01, 64, 0.0);
    for (std::uint32_t h = 0; h < handles; ++h) calendar.push_or_change(h, TimedKey{0.001 * h, h});
    const std::size_t with_lists = calendar.bytes();
    calendar.tune(std::numeric_limits<double>::infinity(), 2, 0.0);
    CHECK(calendar.size() == handles);
    CHECK(calendar.near().size() == handles);
    CHECK(calendar.bytes() < with_lists);  // 32 bytes of entry per handle gone, 16 of key added
    CHECK(calendar.check_invariants());
    // New handles and erased ones go through the heap alone.
    calendar.reserve_handles(2 * handles);
    calendar.push_or_change(handles + 7, TimedKey{0.5, handles + 7});
    calendar.erase(handles + 8);  // never filed
    CHECK(calendar.contains(handles + 7));
    CHECK_FALSE(calendar.contains(handles + 8));
    for (std::uint32_t h = 0; h < 2 * handles; ++h) calendar.erase(h);
    CHECK(calendar.empty());
    CHECK(simulate(calendar, 2 * handles, 5'000, rng, delay) == 0);
    // Blocks again: the entries come back and later events go to the ring.
    calendar.tune(0.01, 64, 0.0);
    for (std::uint32_t h = 0; h < 2 * handles; ++h) {
        calendar.push_or_change(h, TimedKey{0.001 * h, h});
    }
    CHECK(calendar.near().size() < calendar.size());
    CHECK(calendar.check_invariants());
    for (std::uint32_t h = 0; h < 2 * handles; ++h) calendar.erase(h);
    CHECK(calendar.empty());
    CHECK(simulate(calendar, 2 * handles, 5'000, rng, delay) == 0);
}

TEST_CASE("the event calendar jumps over empty blocks and files times near the double range") {
    Calendar calendar(4);
    calendar.tune(1e-3, 64, 0.0);
    // One event a million blocks ahead (overflow, then a jump), one beyond any block index.
    calendar.push_or_change(0, TimedKey{1000.0, 0});
    calendar.push_or_change(1, TimedKey{1e300, 1});
    calendar.push_or_change(2, TimedKey{0.5, 2});
    CHECK(calendar.check_invariants());
    const std::uint32_t order[] = {2, 0, 1};
    for (std::uint32_t h : order) {
        REQUIRE(calendar.settle());
        CHECK(calendar.top() == h);
        calendar.erase(h);
        CHECK(calendar.check_invariants());
    }
    CHECK_FALSE(calendar.settle());
}

TEST_CASE("a calendar past 1 MiB of entries walks ahead and still pops in the model's order") {
    // The walk ahead (step_ahead) switches on past 32,768 handles of capacity: below every other
    // test's size. It may read entries that moved since (a hint), so what it hands on_ahead must
    // still be a handle of the calendar, and the pops must not change. 2,000 events spread over
    // 40,000 handles: the walk's size at a small cost where every mutation is validated.
    constexpr std::uint32_t capacity = 40'000;
    constexpr std::uint32_t events = 2'000;
    constexpr std::uint32_t spread = capacity / events;
    constexpr int pops = 10'000;
    Calendar calendar(capacity);
    // About eight events a block (mean delay 1), the ring reaching about eight time units ahead.
    calendar.tune(8.0 / events, 2'048, 0.0);
    std::mt19937_64 rng(47);
    std::exponential_distribution<double> delay(1.0);
    std::set<std::pair<double, std::uint32_t>> model;
    for (std::uint32_t k = 0; k < events; ++k) {
        const std::uint32_t h = k * spread;
        const double t = delay(rng);
        calendar.push_or_change(h, TimedKey{t, h});
        model.insert({t, h});
    }
    std::size_t mismatches = 0;
    std::size_t walked = 0;
    std::size_t strangers = 0;
    const auto on_ahead = [&](std::uint32_t h, const TimedKey& k) {
        ++walked;
        strangers += h >= capacity || h % spread != 0 || k.handle != h;
    };
    for (int pop = 0; pop < pops; ++pop) {
        mismatches += !calendar.settle(on_ahead);
        const auto [t, h] = *model.begin();
        mismatches += calendar.top() != h || calendar.top_key().t != t;
        // The popped handle's next event, as a particle's would be.
        model.erase(model.begin());
        const double next = t + delay(rng);
        calendar.push_or_change(h, TimedKey{next, h});
        model.insert({next, h});
    }
    CHECK(mismatches == 0);
    CHECK(walked > pops / 2);  // about one step per pop
    CHECK(strangers == 0);
    CHECK(calendar.check_invariants());
    CHECK(calendar.size() == events);
}
