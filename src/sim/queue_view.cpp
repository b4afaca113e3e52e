#include "collide/sim/queue_view.hpp"

#include "collide/error.hpp"

namespace collide::sim {

void QueueWatch::start(const QueueViewLimits& limits) {
    const std::size_t next_events = limits.next_events;
    if (next_events < 1 || next_events > max_watched_events) {
        throw_scene_error("", 0, "queue",
                          "shows 1 to " + std::to_string(max_watched_events) +
                              " upcoming events, got " + std::to_string(next_events));
    }
    limits_ = limits;
}

std::vector<QueuedEvent> QueueWatch::popped() const {
    const std::uint64_t kept = std::min<std::uint64_t>(recorded_, watched_pops);
    std::vector<QueuedEvent> out;
    out.reserve(kept);
    for (std::uint64_t k = recorded_ - kept; k < recorded_; ++k)
        out.push_back(ring_[k % watched_pops]);
    return out;
}

unsigned shown_tree_levels(std::size_t arity, std::size_t size,
                           const QueueViewLimits& limits) noexcept {
    if (size == 0) return 0;
    unsigned levels = 1;
    std::size_t width = 1;  // nodes in the level below the last one counted
    std::size_t slots = 1;
    while (slots < size && levels < limits.tree_levels) {
        width *= std::max<std::size_t>(arity, 2);
        if (width > limits.tree_level_nodes) break;
        slots += width;
        ++levels;
    }
    return levels;
}

std::size_t shown_tree_slots(std::size_t arity, unsigned levels, std::size_t size) noexcept {
    std::size_t slots = 0;
    std::size_t width = 1;
    for (unsigned l = 0; l < levels; ++l) {
        slots += width;
        width *= std::max<std::size_t>(arity, 2);
    }
    return std::min(slots, size);
}

void keep_next_collisions(std::vector<QueuedEvent>& events, std::size_t k) {
    std::erase_if(events,
                  [](const QueuedEvent& e) { return e.stale || e.kind == EventKind::cell; });
    const auto earlier = [](const QueuedEvent& x, const QueuedEvent& y) {
        if (x.t != y.t) return x.t < y.t;
        if (x.kind != y.kind) return x.kind < y.kind;
        if (x.a != y.a) return x.a < y.a;
        return x.b < y.b;
    };
    std::sort(events.begin(), events.end(), earlier);
    // One collision once: the fast engine holds a pair at both discs, predicted from either side
    // (their times may differ in the last bit), so the earliest of each (kind, a, b) stays.
    std::vector<QueuedEvent> kept;
    for (const QueuedEvent& e : events) {
        if (kept.size() == k) break;
        const bool repeat = std::any_of(kept.begin(), kept.end(), [&](const QueuedEvent& x) {
            return x.kind == e.kind && x.a == e.a && x.b == e.b;
        });
        if (!repeat) kept.push_back(e);
    }
    events = std::move(kept);
}

namespace detail {

std::string queue_name(QueueShape shape, std::size_t arity, bool indexed) {
    switch (shape) {
        case QueueShape::ordered_array:
            return "ordered array";
        case QueueShape::unordered_array:
            return "unordered array";
        case QueueShape::heap:
            break;
    }
    std::string name = arity == 2 ? "binary heap" : std::to_string(arity) + "-ary heap";
    return indexed ? "indexed " + name : name;
}

}  // namespace detail

}  // namespace collide::sim
