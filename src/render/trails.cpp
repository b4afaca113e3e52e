#include "trails.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "theme.hpp"

namespace collide::render {

bool wraps_between(const Box& box, Vec2 a, Vec2 b) noexcept {
    if (box.boundary != Boundary::periodic) return false;
    return std::abs(b.x - a.x) > 0.5 * box.width || std::abs(b.y - a.y) > 0.5 * box.height;
}

std::optional<std::pair<Vec2, Vec2>> clip_to_box(const Box& box, Vec2 a, Vec2 b) noexcept {
    // Liang-Barsky: keep the parameter range [t0, t1] of a + t (b - a) inside every slab.
    double t0 = 0.0;
    double t1 = 1.0;
    const Vec2 d = b - a;
    const auto slab = [&](double delta, double low_gap, double high_gap) {
        // low_gap = a - low edge, high_gap = high edge - a (both >= 0 when a is inside)
        if (delta == 0.0) return low_gap >= 0.0 && high_gap >= 0.0;
        const double t_low = -low_gap / delta;
        const double t_high = high_gap / delta;
        t0 = std::max(t0, std::min(t_low, t_high));
        t1 = std::min(t1, std::max(t_low, t_high));
        return t0 <= t1;
    };
    if (!slab(d.x, a.x, box.width - a.x) || !slab(d.y, a.y, box.height - a.y)) return std::nullopt;
    return std::pair{a + t0 * d, a + t1 * d};
}

namespace {

/// Keeps the positions at even indices and the newest one: half the points, same start and end.
void thin(std::deque<Vec2>& path) {
    std::deque<Vec2> kept;
    for (std::size_t i = 0; i < path.size(); i += 2) kept.push_back(path[i]);
    if (path.size() % 2 == 0) kept.push_back(path.back());
    path = std::move(kept);
}

}  // namespace

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
        std::deque<Vec2>& path = paths_[k];
        path.push_back(snapshot.discs[tagged_[k]].position);
        if (path.size() <= length_) continue;
        if (whole_path_) {
            thin(path);
        } else {
            path.pop_front();
        }
    }
}

void TrailHistory::draw(OverlayBatch& batch, const Box& box,
                        const std::function<PointF(Vec2)>& to_pixels,
                        const std::vector<Rgb8>& colors, float width, float min_share) const {
    constexpr float max_alpha = trail_max_alpha;
    for (std::size_t k = 0; k < tagged_.size(); ++k) {
        const std::deque<Vec2>& path = paths_[k];
        const Rgb8 color = colors[tagged_[k]];
        for (std::size_t i = 1; i < path.size(); ++i) {
            // Fade by age counted from the newest point, so a young trail is not faint.
            const float age =
                static_cast<float>(i + length_ - path.size()) / static_cast<float>(length_);
            const float share = min_share + (1.0F - min_share) * age;
            const Rgba8 faded = with_alpha(color, static_cast<std::uint8_t>(max_alpha * share));
            const Vec2 a = path[i - 1];
            const Vec2 b = path[i];
            if (!wraps_between(box, a, b)) {
                batch.add_line(to_pixels(a), to_pixels(b), width, faded);
                continue;
            }
            // Across the seam: the step is the minimum-image displacement, drawn once leaving
            // from a and once arriving at b, each cut at the box edge.
            const Vec2 step = box.displacement(a, b);
            for (const auto& [from, to] : {std::pair{a, a + step}, std::pair{b - step, b}}) {
                if (const auto inside = clip_to_box(box, from, to)) {
                    batch.add_line(to_pixels(inside->first), to_pixels(inside->second), width,
                                   faded);
                }
            }
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
