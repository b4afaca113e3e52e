#include "collide/sim/lookahead.hpp"

#include <algorithm>
#include <memory>

#include "collide/error.hpp"

namespace collide::sim {

namespace {

/// Stops recording when a look ahead ends, however it ends (a stop flag throws from advance_to).
class Recording {
  public:
    Recording(double& after, double from) : after_(after) { after_ = from; }
    ~Recording() { after_ = std::numeric_limits<double>::infinity(); }
    Recording(const Recording&) = delete;
    Recording& operator=(const Recording&) = delete;

  private:
    double& after_;
};

/// advance_to as the video calls it: never backwards (the engine may already be there).
void advance(Engine& engine, double t) {
    engine.advance_to(std::max(t, engine.time()));
}

}  // namespace

CollisionLookahead::CollisionLookahead(Engine& engine) : engine_(engine) {
    engine_.set_collision_listener(recorder());
}

CollisionLookahead::~CollisionLookahead() {
    engine_.set_collision_listener(nullptr);
}

CollisionListener CollisionLookahead::recorder() {
    return [this](const CollisionRecord& r) {
        if (!next_ && r.t > after_) next_ = r;
    };
}

std::optional<CollisionRecord> CollisionLookahead::next(const FramesAhead& frames) {
    const double shown = engine_.time();
    // Nothing happens before the collision found last: it is still the next one.
    if (next_ && next_->t > shown) return next_;
    // It has passed, and with it every later collision of the look ahead that found it (that
    // one stopped at the first frame time at or after it, the time shown now at the latest).
    next_.reset();
    const Recording recording(after_, shown);
    std::int64_t first_for_copy = 1;
    if (frames.own >= 1) {
        // The next frame's own call, made early: same time, same order, same bits.
        advance(engine_, frames.time(1));
        first_for_copy = 2;
    }
    if (!next_ && first_for_copy <= frames.count) run_copy(frames, first_for_copy);
    return next_;
}

void CollisionLookahead::run_copy(const FramesAhead& frames, std::int64_t first) {
    const std::unique_ptr<Engine> copy = engine_.clone();
    if (!copy) throw_runtime_error("next collision: this engine cannot be copied to look ahead");
    copy->set_collision_listener(recorder());
    for (std::int64_t i = first; i <= frames.count && !next_; ++i) advance(*copy, frames.time(i));
}

}  // namespace collide::sim
