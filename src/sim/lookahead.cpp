#include "collide/sim/lookahead.hpp"

#include <algorithm>
#include <utility>

namespace collide::sim {

CollisionLookahead::CollisionLookahead(std::unique_ptr<Engine> twin) : twin_(std::move(twin)) {
    twin_->set_collision_listener([this](const CollisionRecord& r) { ahead_.push_back(r); });
}

std::optional<CollisionRecord> CollisionLookahead::next_after(double t) {
    while (!ahead_.empty() && ahead_.front().t <= t) ahead_.pop_front();
    if (ahead_.empty()) return std::nullopt;
    return ahead_.front();
}

void CollisionLookahead::advance_to(double t) {
    twin_->advance_to(std::max(t, twin_->time()));
}

}  // namespace collide::sim
