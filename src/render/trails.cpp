#include "trails.hpp"

#include <cmath>

namespace collide::render {

bool wraps_between(const Box& box, Vec2 a, Vec2 b) noexcept {
    if (box.boundary != Boundary::periodic) return false;
    return std::abs(b.x - a.x) > 0.5 * box.width || std::abs(b.y - a.y) > 0.5 * box.height;
}

void TrailHistory::reset() noexcept {
    started_ = false;
    disc_count_ = 0;
    tagged_.clear();
    paths_.clear();
}

void TrailHistory::update(const Snapshot& snapshot) {
    if (started_ && (snapshot.discs.size() != disc_count_ || snapshot.time < last_time_)) reset();
    if (!started_) {
        disc_count_ = snapshot.discs.size();
        for (std::uint32_t i = 0; i < snapshot.discs.size(); ++i) {
            if (snapshot.discs[i].tagged) tagged_.push_back(i);
        }
        paths_.assign(tagged_.size(), {});
        started_ = true;
    }
    last_time_ = snapshot.time;
    for (std::size_t k = 0; k < tagged_.size(); ++k) {
        paths_[k].push_back(snapshot.discs[tagged_[k]].position);
        if (paths_[k].size() > length_) paths_[k].pop_front();
    }
}

void TrailHistory::draw(OverlayBatch& batch, const Box& box,
                        const std::function<PointF(Vec2)>& to_pixels,
                        const std::vector<Rgb8>& colors, float width) const {
    constexpr float max_alpha = 200.0F;
    for (std::size_t k = 0; k < tagged_.size(); ++k) {
        const std::deque<Vec2>& path = paths_[k];
        const Rgb8 color = colors[tagged_[k]];
        for (std::size_t i = 1; i < path.size(); ++i) {
            if (wraps_between(box, path[i - 1], path[i])) continue;  // break the line
            const float age = static_cast<float>(i) / static_cast<float>(length_);
            const auto alpha = static_cast<std::uint8_t>(max_alpha * age);
            batch.add_line(to_pixels(path[i - 1]), to_pixels(path[i]), width,
                           with_alpha(color, alpha));
        }
    }
}

std::vector<Vec2> TrailHistory::points(std::uint32_t index) const {
    for (std::size_t k = 0; k < tagged_.size(); ++k) {
        if (tagged_[k] == index) return {paths_[k].begin(), paths_[k].end()};
    }
    return {};
}

}  // namespace collide::render
