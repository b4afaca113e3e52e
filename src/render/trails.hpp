#pragma once
// Internal: per-panel history of tagged discs' positions across frames, drawn as fading
// polylines; where a disc wraps around a periodic box the step is drawn on both sides of the
// seam, cut at the box edges.

#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "collide/snapshot.hpp"
#include "overlay_geometry.hpp"

namespace collide::render {

class TrailHistory {
  public:
    /// Keeps up to `length` positions per tagged disc (>= 2). Past that, the oldest position is
    /// dropped, or with `whole_path` every other position is dropped instead, so the trail keeps
    /// its start (a Brownian tracer's whole path) at a coarser spacing and bounded cost.
    explicit TrailHistory(int length, bool whole_path = false)
        : length_(static_cast<std::size_t>(length)), whole_path_(whole_path) {}

    /// Records the tagged discs' positions. Starts over when the disc count changes or time
    /// goes backwards (a new video or a seek). O(tagged discs).
    void update(const Snapshot& snapshot);
    void reset() noexcept;

    /// Appends every trail: oldest point transparent, newest `max_alpha`. `to_pixels` maps box
    /// coordinates to frame pixels; colours are indexed like the snapshot's discs.
    /// `min_share` in [0, 1): the oldest point's opacity as a share of the newest's (0: fades
    /// out completely; the lesson level keeps the whole path visible).
    void draw(OverlayBatch& batch, const Box& box, const std::function<PointF(Vec2)>& to_pixels,
              const std::vector<Rgb8>& colors, float width, float min_share = 0.0F) const;

    /// The recorded positions of disc `index` (oldest first); empty when it is not tagged.
    [[nodiscard]] std::vector<Vec2> points(std::uint32_t index) const;

  private:
    std::size_t length_;
    bool whole_path_ = false;
    std::size_t disc_count_ = 0;
    double last_time_ = 0.0;
    bool started_ = false;
    std::vector<std::uint32_t> tagged_;    // indices of tagged discs
    std::vector<std::deque<Vec2>> paths_;  // parallel to tagged_
};

/// True when the step a -> b is a jump across a periodic box (not motion): longer than half the
/// box in x or y.
[[nodiscard]] bool wraps_between(const Box& box, Vec2 a, Vec2 b) noexcept;

/// The part of segment a-b inside [0, width] x [0, height] (box units), none if it misses.
[[nodiscard]] std::optional<std::pair<Vec2, Vec2>> clip_to_box(const Box& box, Vec2 a,
                                                               Vec2 b) noexcept;

}  // namespace collide::render
