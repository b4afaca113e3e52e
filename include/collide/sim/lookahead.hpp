#pragma once
/// \file
/// What an event-driven engine will resolve next: the lesson's "next collision" line
/// (collide/show/collision.hpp, next_collision_view). Neutral inspection: it names discs and
/// times, never words or pictures.
///
/// Why not the queue's earliest entry: the fast engine's queue holds one event per disc, and a
/// disc whose event is a cell crossing or has gone stale is predicted anew when that event is
/// popped, possibly to a collision earlier than every valid one queued. Only running the loop
/// tells, and only by the same calls (advance_to to the same times in the same order: the
/// classic engine moves every disc at each call, so other times give other bits).
///
/// Why not a twin engine run beside the watched one (the first version): it doubled the
/// event-driven work of a render. Instead the watched engine itself is run one frame early (the
/// call the next frame makes anyway, so its bits do not change), and only when a whole frame
/// passes without a collision, or past the video's last frame, is a copy of it (Engine::clone)
/// run further. A dense scene pays nothing but a listener call per collision; a sparse one a
/// copy per quiet stretch.

#include <cstdint>
#include <functional>
#include <limits>
#include <optional>

#include "collide/sim/engine.hpp"

namespace collide::sim {

/// The times the watched engine is advanced to after the frame just shown, in order: time(i)
/// for i = 1 .. count. The first `own` of them are the video's frames (the engine itself goes
/// there, frame by frame); the rest lie past its end, where only a copy goes.
struct FramesAhead {
    std::function<double(std::int64_t)> time;
    std::int64_t own = 0;
    std::int64_t count = 0;  ///< how far to look (own <= count)
};

class CollisionLookahead {
  public:
    /// Watches an event-driven `engine`, which must outlive this: takes over its collision
    /// listener (and clears it again on destruction).
    explicit CollisionLookahead(Engine& engine);
    ~CollisionLookahead();
    CollisionLookahead(const CollisionLookahead&) = delete;
    CollisionLookahead& operator=(const CollisionLookahead&) = delete;

    /// The first collision after the engine's time (the frame just shown) that the engine will
    /// resolve when advanced to `frames`' times in order; nullopt when none comes by the last.
    /// May advance the engine to frames.time(1) (when own >= 1): the next frame then finds it
    /// there. Call once per frame, in frame order. Throws Error(runtime) when the engine has to
    /// be copied and cannot be (Engine::clone gave nullptr), and whatever advance_to throws.
    [[nodiscard]] std::optional<CollisionRecord> next(const FramesAhead& frames);

  private:
    /// The listener of the engine and of its copies: keeps the first collision after after_.
    [[nodiscard]] CollisionListener recorder();
    /// Runs a copy of the engine to frames.time(first), time(first + 1), ... until it resolves a
    /// collision or the times run out; the copy is then dropped.
    void run_copy(const FramesAhead& frames, std::int64_t first);

    Engine& engine_;
    std::optional<CollisionRecord> next_;  ///< found by the latest look ahead
    /// Collisions after this time are recorded (+inf: none, while the frames' own advances run
    /// over collisions already looked at).
    double after_ = std::numeric_limits<double>::infinity();
};

}  // namespace collide::sim
