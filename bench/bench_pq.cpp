// Priority queues under an event queue's workload (docs/benchmarks.md, "Priority queues").
//
// hold/<queue>/N: the hold model of a discrete-event simulation: N pending events; each step
//   pops the earliest and pushes it back at its time plus a random (exponential) increment, so
//   the size stays N and the key distribution is the one an event queue sees. One step = pop+push.
// decrease/<indexed:D>/N: an indexed heap of N handles where 3 steps in 4 move a random handle's
//   key earlier (decrease_key, as when a particle's next event is re-predicted sooner) and 1 in 4
//   is a hold step (pop the earliest, reinsert later).
// Compare queues by the ratio of their times in one run (the machine is shared).

#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <queue>
#include <random>
#include <string>
#include <vector>

#include "collide/sim/pq/indexed_heap.hpp"
#include "collide/sim/pq/with_queue.hpp"

namespace {

using namespace collide::pq;

/// std::priority_queue behind the Queue interface (pop returns the item), the baseline.
class StdPriorityQueue {
  public:
    using value_type = double;
    [[nodiscard]] bool empty() const { return q_.empty(); }
    [[nodiscard]] std::size_t size() const { return q_.size(); }
    [[nodiscard]] const double& top() const { return q_.top(); }
    void push(double x) { q_.push(x); }
    double pop() {
        const double out = q_.top();
        q_.pop();
        return out;
    }

  private:
    std::priority_queue<double, std::vector<double>, std::greater<>> q_;
};
static_assert(Queue<StdPriorityQueue>);

/// Pre-drawn random numbers, so the timed loop measures the queue and not the generator.
struct RandomTable {
    static constexpr std::size_t size = 1 << 16;  // a power of two: index with a mask
    std::vector<double> exponential;              // mean 1
    std::vector<double> uniform;                  // [0, 1)
    std::vector<std::uint32_t> bits;

    RandomTable() : exponential(size), uniform(size), bits(size) {
        std::mt19937_64 rng(12345);
        std::exponential_distribution<double> exp1(1.0);
        std::uniform_real_distribution<double> u01(0.0, 1.0);
        for (std::size_t i = 0; i < size; ++i) {
            exponential[i] = exp1(rng);
            uniform[i] = u01(rng);
            bits[i] = static_cast<std::uint32_t>(rng());
        }
    }
};

const RandomTable& table() {
    static const RandomTable t;  // read-only benchmark input, built once
    return t;
}

bool refuse_validating_build(benchmark::State& state) {
    if constexpr (validate_heaps) {
        state.SkipWithError("built with COLLIDE_VALIDATE: O(N) checks after every operation");
        return true;
    }
    return false;
}

template <class Q>
void hold(benchmark::State& state, Q q) {
    if (refuse_validating_build(state)) return;
    const auto n = static_cast<std::size_t>(state.range(0));
    const RandomTable& r = table();
    // Start as a simulation does: n events spread over the first n time units.
    for (std::size_t i = 0; i < n; ++i) q.push(static_cast<double>(n) * r.uniform[i % r.size]);
    std::size_t k = 0;
    for (auto _ : state) {
        const double t = q.pop();
        q.push(t + static_cast<double>(n) * r.exponential[k++ & (r.size - 1)]);
    }
    benchmark::DoNotOptimize(q.top());
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

template <unsigned D>
void decrease_heavy(benchmark::State& state) {
    if (refuse_validating_build(state)) return;
    const auto n = static_cast<std::size_t>(state.range(0));
    const RandomTable& r = table();
    IndexedDaryHeap<double, Orientation::min, D> heap(n);
    for (std::size_t h = 0; h < n; ++h) {
        heap.push(static_cast<std::uint32_t>(h), static_cast<double>(n) * r.uniform[h % r.size]);
    }
    std::size_t k = 0;
    for (auto _ : state) {
        const std::size_t j = k++ & (r.size - 1);
        if ((r.bits[j] & 3u) != 0) {
            // Re-predicted sooner: somewhere between now (the top) and its old time.
            const auto h = static_cast<std::uint32_t>(r.bits[j] % n);
            const double now = heap.top_key();
            heap.decrease_key(h, now + (heap.key(h) - now) * r.uniform[j]);
        } else {
            const double t = heap.top_key();
            heap.push(heap.pop(), t + static_cast<double>(n) * r.exponential[j]);
        }
    }
    benchmark::DoNotOptimize(heap.top());
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

void register_hold(const std::string& name, auto make_queue, std::int64_t largest_n) {
    benchmark::RegisterBenchmark(
        ("hold/" + name).c_str(),
        [make_queue](benchmark::State& state) { hold(state, make_queue()); })
        ->RangeMultiplier(10)
        ->Range(1000, largest_n);
}

void register_all() {
    constexpr std::int64_t million = 1'000'000;
    register_hold(
        "std::priority_queue", [] { return StdPriorityQueue{}; }, million);
    for (const char* kind : {"binary", "dary:3", "dary:4", "dary:8", "dary:5", "indexed:2",
                             "indexed:4", "indexed:8"}) {
        with_queue<double, Orientation::min, std::less<double>>(
            parse_queue_kind(kind), [&](auto q) {
                register_hold(
                    kind, [q] { return q; }, million);
            });
    }
    // O(N) per operation: only where a step stays in microseconds.
    register_hold(
        "unordered", [] { return UnorderedArrayPQ<double, Orientation::min>{}; }, 10'000);
    register_hold(
        "ordered", [] { return OrderedArrayPQ<double, Orientation::min>{}; }, 10'000);

    benchmark::RegisterBenchmark("decrease/indexed:2", decrease_heavy<2>)
        ->RangeMultiplier(10)
        ->Range(1000, million);
    benchmark::RegisterBenchmark("decrease/indexed:3", decrease_heavy<3>)
        ->RangeMultiplier(10)
        ->Range(1000, million);
    benchmark::RegisterBenchmark("decrease/indexed:4", decrease_heavy<4>)
        ->RangeMultiplier(10)
        ->Range(1000, million);
    benchmark::RegisterBenchmark("decrease/indexed:8", decrease_heavy<8>)
        ->RangeMultiplier(10)
        ->Range(1000, million);
}

}  // namespace

int main(int argc, char** argv) {
    register_all();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
