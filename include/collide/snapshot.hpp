#pragma once
/// \file
/// What an engine hands to the renderer at a frame time: every disc's state at exactly `time`,
/// plus the time-driven method's failure markers, and (only when asked for, `collide render
/// --queue`) a view of the event-driven engine's queue. The renderer sees nothing else of the
/// engines.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "collide/box.hpp"
#include "collide/disc.hpp"
#include "collide/event_kind.hpp"
#include "collide/vec2.hpp"

namespace collide {

struct DiscState {
    Vec2 position;  ///< at `Snapshot::time`; wrapped into the box for periodic boundaries
    Vec2 velocity;
    double radius = 0.0;
    double mass = 0.0;
    Rgb8 color;
    bool tagged = false;   ///< the scene gave it a tag (trails are drawn for tagged discs)
    bool escaped = false;  ///< time-driven only: entirely outside a walled box (tunnelled out)
    /// Time-driven only: went through a barrier (an immovable disc, immovable_mass_ratio) between
    /// two checks at least once so far.
    bool tunnelled = false;
};

/// Where a particle that tunnelled out of a walled box left it, as the screen shows it: the point
/// on the edge it crossed (3D: on the face, projected by the camera) and the outward direction
/// there on the screen (unit, y up).
struct ScreenExit {
    std::uint32_t disc = 0;  ///< index into Snapshot::discs
    Vec2 where;
    Vec2 out;
};

/// One event in an engine's queue. Disc indices are the scene's (as in Snapshot::discs).
struct QueuedEvent {
    double t = 0.0;                    ///< absolute simulation time the event was predicted for
    EventKind kind = EventKind::pair;  ///< never zwall: queue pictures are drawn in 2D
    std::uint32_t a = 0;               ///< the disc (pairs: the smaller index)
    std::uint32_t b = 0;               ///< pairs: the other disc; otherwise unused
    /// Invalidated since it was predicted (a disc involved has collided since): the classic loop
    /// throws it away when it pops it; the fast engine predicts the disc anew.
    bool stale = false;

    friend bool operator==(const QueuedEvent&, const QueuedEvent&) = default;
};

/// How the queue stores its events, so that it can be drawn as what it is.
enum class QueueShape : std::uint8_t {
    heap,             ///< a d-ary heap in an array: slot i's children are d i + 1 .. d i + d
    ordered_array,    ///< sorted, the next event last
    unordered_array,  ///< in insertion order; every pop scans for the next event
};

/// A read-only picture of an event-driven engine's queue at Snapshot::time, filled only when
/// asked for (Engine::watch_queue): what comes next, how the queue holds it, what left it.
struct QueueView {
    std::string name;  ///< "binary heap", "4-ary heap", "ordered array", ...
    QueueShape shape = QueueShape::heap;
    unsigned arity = 2;         ///< heap: children per node
    bool one_per_disc = false;  ///< the fast engine: each disc holds exactly one pending event
    std::uint64_t size = 0;     ///< entries in the queue now
    std::uint64_t stale_entries = 0;  ///< of which invalidated (popped and thrown away later)
    /// The next valid collisions (pairs and walls, no cell crossings), earliest first, at most the
    /// number asked for; each collision once (the fast engine holds a pair at both discs).
    std::vector<QueuedEvent> next;
    /// Heap: the first slots of its array, in array order (the top levels of the tree, root
    /// first). Ordered array: the slots nearest the top, the next event first. Unordered array:
    /// its first slots, in array order.
    std::vector<QueuedEvent> slots;
    /// Heap: levels of the tree in `slots` (the last possibly partial).
    unsigned levels = 0;
    /// Unordered array: the position of the next event in the array (it may lie beyond `slots`).
    std::uint64_t top_index = 0;
    /// The latest events popped off the queue, oldest first (a few), with `stale` telling which
    /// were thrown away. An event leaves the queue when the simulation reaches its time `t`.
    std::vector<QueuedEvent> popped;
    std::uint64_t pops = 0;        ///< events popped so far
    std::uint64_t stale_pops = 0;  ///< of which stale
};

/// How much of a queue a view carries: the caller's picture budget (a video's is in
/// collide/show/collision.hpp, show::queue_picture; the engines fill the view,
/// Engine::watch_queue). The view holds the next `next_events` collisions; a heap's slots down
/// to the deepest level with at most `tree_level_nodes` nodes and at most `tree_levels` levels;
/// an array queue's first `array_slots` slots.
struct QueueViewLimits {
    std::size_t next_events = 0;       ///< 1..sim::max_watched_events
    std::size_t tree_level_nodes = 0;  ///< >= 1
    unsigned tree_levels = 0;          ///< >= 1
    std::size_t array_slots = 0;
};

struct Snapshot {
    double time = 0.0;  ///< simulation time of this state
    Box box;
    std::vector<DiscState> discs;  ///< same order as the scene's discs
    /// Time-driven failure markers (empty for the event-driven engines).
    std::vector<std::pair<std::uint32_t, std::uint32_t>> overlapping_pairs;
    std::vector<Vec2> missed_collisions;  ///< where a collision went undetected since last frame
    /// Dimension 3 only: where each escaped sphere left its box, projected (show::project), for
    /// the "left the box" marks. A 2D snapshot leaves it empty: the exit follows from the disc's
    /// position and velocity (show::exit_point), which a projected disc's do not tell.
    std::vector<ScreenExit> exits;
    /// Event-driven engines watching their queue (Engine::watch_queue) only; empty otherwise.
    std::optional<QueueView> queue;
    /// The dimension of the particles the discs stand for: 2 (discs), or 3 when they stand in
    /// for spheres seen by a camera (show::SphereCamera): positions projected onto the screen,
    /// velocities (vx, |(vy, vz)|) so that a disc's speed is its sphere's, and the speed plot's
    /// Maxwell-Boltzmann curve is the 3D one.
    int dimension = 2;
};

}  // namespace collide
