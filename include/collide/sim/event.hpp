#pragma once
/// \file
/// The event key shared by the event-driven engines, and the named tolerances they use.
/// Events are ordered by a strict total order (time, kind, ids, collision counts), so every
/// priority queue pops them in the same sequence and the classic and fast engines break ties
/// between simultaneous events the same way.

#include <cstdint>
#include <limits>

#include "collide/event_kind.hpp"

namespace collide::sim {

/// Marks "no disc" in 32-bit disc indices.
inline constexpr std::uint32_t no_disc = std::numeric_limits<std::uint32_t>::max();

/// Relative distance under which two discs that have just collided with each other count as
/// still touching. Right after an elastic collision the pair separates (dv.dr > 0) in exact
/// arithmetic, but for grazing contacts rounding can leave dv.dr a hair negative with the discs
/// a hair overlapping; time_to_hit would then answer "now" again and again (a zero-time loop).
/// Such a pair cannot meet again before one of them hits something else, so the engines do not
/// predict it while it is still within this relative distance of contact.
inline constexpr double just_collided_slack = 1e-9;

/// Overlap (in units of the pair's contact distance sigma) that the engines promise never to
/// exceed, unless the scene starts with a deeper overlap. Predictions are exact up to rounding
/// (relative error ~1e-16 per step, compounded over local-clock advances), so 1e-9 leaves six
/// orders of magnitude of headroom while still catching any real miss (a missed collision
/// overlaps by ~ speed x mean free time, which is many orders larger).
inline constexpr double overlap_tolerance = 1e-9;

/// An event as the classic engine queues it (lazy invalidation by collision counts, as in
/// the lecture). Pair events are normalised to a < b so that the same collision predicted from
/// either disc is the same key.
struct Event {
    double t = 0.0;  ///< absolute simulation time
    EventKind kind = EventKind::pair;
    std::uint32_t a = 0;        ///< the disc (pairs: the smaller index)
    std::uint32_t b = no_disc;  ///< the other disc (pairs only)
    std::uint32_t count_a = 0;  ///< a's collision count when predicted
    std::uint32_t count_b = 0;  ///< b's collision count when predicted (pairs only)
};

/// Strict total order on events: time, then kind, then disc ids, then counts.
struct EventLess {
    [[nodiscard]] constexpr bool operator()(const Event& x, const Event& y) const noexcept {
        if (x.t != y.t) return x.t < y.t;
        if (x.kind != y.kind) return x.kind < y.kind;
        if (x.a != y.a) return x.a < y.a;
        if (x.b != y.b) return x.b < y.b;
        if (x.count_a != y.count_a) return x.count_a < y.count_a;
        return x.count_b < y.count_b;
    }
};

}  // namespace collide::sim
