#pragma once
/// \file
/// What an event-driven engine will resolve next, known by running a twin of it ahead: the
/// lesson's "next collision" line (collide/show/collision.hpp, next_collision_view). Neutral
/// inspection: it names discs and times, never words or pictures.
///
/// Why a twin and not the queue's earliest entry: the fast engine's queue holds one event per
/// disc, and a disc whose event is a cell crossing or has gone stale is predicted anew when that
/// event is popped, possibly to a collision earlier than every valid one queued. Only running
/// the loop tells. The twin is the same engine on the same scene, advanced to the same times in
/// the same order as the engine it mirrors, so it resolves the same collisions bit for bit.

#include <cstddef>
#include <deque>
#include <memory>
#include <optional>

#include "collide/sim/engine.hpp"

namespace collide::sim {

class CollisionLookahead {
  public:
    /// `twin`: a fresh engine built like the one it mirrors (make_engine with the same scene and
    /// options), not yet advanced. Takes over its collision listener.
    explicit CollisionLookahead(std::unique_ptr<Engine> twin);

    /// Forgets the collisions at or before `t` (the mirrored engine has resolved them) and
    /// returns the first one after it that the twin has resolved, if any. O(collisions dropped).
    [[nodiscard]] std::optional<CollisionRecord> next_after(double t);
    /// Advances the twin to max(t, time()), as the mirrored engine would be advanced: call with
    /// the mirrored engine's times in its order for as long as next_after finds nothing.
    void advance_to(double t);
    /// How far the twin has run.
    [[nodiscard]] double time() const noexcept { return twin_->time(); }
    /// Stops the twin like the engine it mirrors (EngineBase::set_stop_flag).
    void set_stop_flag(const std::atomic<bool>* stop) noexcept { twin_->set_stop_flag(stop); }

  private:
    std::unique_ptr<Engine> twin_;
    std::deque<CollisionRecord> ahead_;  ///< resolved by the twin, not yet passed
};

}  // namespace collide::sim
