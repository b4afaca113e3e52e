#pragma once
/// \file
/// Which failures of a time-driven panel a lesson marks, and the words of the mark legend: a
/// missed collision keeps its ring for a second of video, an overlapping pair is marked while it
/// overlaps and for a second of video after (fading, so that an overlap of one frame is still
/// seen), a disc that left a walled box is marked where it crossed the edge. The marker budget
/// is shared fairly between the kinds present and spread over the box, so no kind and no corner
/// takes every mark. The renderer paints the marks it is handed (FailureMark); it chooses none.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "collide/box.hpp"
#include "collide/snapshot.hpp"
#include "collide/view/collision.hpp"

namespace collide::show {

/// How long a missed collision's ring, or an overlap's cross once the pair has parted, stays on
/// screen, in seconds of video (fading out).
inline constexpr double mark_seconds = 1.0;
/// At most this many marks in a panel's box; the failures beyond are counted in the legend.
inline constexpr std::size_t mark_budget = 30;
/// The box is cut into mark_grid x mark_grid cells; marks of one kind go round the cells.
inline constexpr int mark_grid = 4;
/// A missed collision's ring: this many mean disc radii (box units).
inline constexpr double missed_mark_radii = 2.5;

/// The legend's name of a kind ("missed collision", "overlapping", "left the box").
[[nodiscard]] std::string failure_name(FailureKind kind);
/// The legend's note on a periodic box ("edges wrap around").
[[nodiscard]] std::string wrap_words();
/// The legend's count of failures without a mark, after the kinds it names ("and 1,234 more
/// not drawn"; "" for 0).
[[nodiscard]] std::string unmarked_words(std::size_t unmarked);

/// True when a panel keeps a legend line under its figures: a time-driven panel (it may fail),
/// or the panel of a periodic box that says once that the edges wrap around (the caller's
/// choice: `says_wrap`). The same for every frame of a video, so the layout stays put.
[[nodiscard]] bool mark_line(bool time_driven, bool says_wrap, const Box& box);

/// A number per kind of failure, indexed by FailureKind's value.
using KindCounts = std::array<std::size_t, failure_kinds>;

/// Shares `budget` marks between kinds with `available[k]` candidates each: every kind gets an
/// equal share, and what a kind cannot use goes to the others (water filling). The result is
/// never more than available, sums to min(budget, total), and differs by at most one between
/// kinds that have more candidates than their share.
[[nodiscard]] KindCounts fair_shares(const KindCounts& available, std::size_t budget);

/// Picks `count` of `points` (box coordinates, in order of preference) spread over the box: the
/// box is cut into mark_grid x mark_grid cells visited in a fixed scattered order, each round
/// taking the most preferred point left in every cell. Returns the indices picked, in the order
/// picked (deterministic).
[[nodiscard]] std::vector<std::size_t> spread_over_box(const std::vector<Vec2>& points,
                                                       const Box& box, std::size_t count);

/// Where a disc that left a walled box crossed its edge (its centre's path traced back along its
/// velocity), and the edge's outward normal.
struct Exit {
    Vec2 where;
    Vec2 out;
};
[[nodiscard]] Exit exit_point(const DiscState& disc, const Box& box);

/// One panel's failure marks across the frames of a video (frames in order; a frame whose
/// snapshot is earlier than the last one starts over, as a seek or a new video).
class FailureMarks {
  public:
    /// `say_wrap`: this panel's legend says that a periodic box's edges wrap around.
    explicit FailureMarks(std::size_t budget = mark_budget, bool say_wrap = false)
        : budget_(budget), say_wrap_(say_wrap) {}

    /// Takes the frame's snapshot at `video_time` (seconds of video): remembers its missed
    /// collisions if the state is new (a held time-driven state is not counted again) and its
    /// overlapping pairs, forgets rings and parted pairs older than mark_seconds, and chooses
    /// the marks and legend words of this frame.
    void update(const Snapshot& snapshot, double video_time);

    /// The marks of the last update, kind by kind (missed, overlapping, left the box).
    [[nodiscard]] const std::vector<FailureMark>& marks() const noexcept { return marks_; }
    /// The legend of the last update: the kinds marked so far in the video, in order of first
    /// appearance, the wrap note (if asked for and the box is periodic) and the unmarked count.
    [[nodiscard]] const MarkWords& words() const noexcept { return words_; }

  private:
    struct Missed {
        Vec2 where;
        double born = 0.0;  ///< video seconds
    };
    /// An overlapping pair, while it overlaps and for mark_seconds after it last did.
    struct Overlap {
        std::pair<std::uint32_t, std::uint32_t> pair;
        Vec2 where;         ///< the midpoint when last seen overlapping
        double size = 0.0;  ///< the cross's size (box units)
        double seen = 0.0;  ///< video seconds when last seen overlapping
    };
    struct Left {
        std::uint32_t disc = 0;
        Exit exit;
        std::uint64_t order = 0;  ///< when it was first seen outside (newest marked first)
    };
    void remember(const Snapshot& snapshot, double video_time);
    void remember_overlaps(const Snapshot& snapshot, double video_time);
    void choose(const Snapshot& snapshot, double video_time);

    std::size_t budget_;
    bool say_wrap_;
    std::vector<Missed> missed_;
    std::vector<Overlap> overlaps_;  ///< sorted by pair
    std::vector<Left> left_;         ///< discs outside the box now, with where they left
    std::uint64_t left_seen_ = 0;
    std::optional<double> last_time_;
    std::vector<FailureKind> seen_;  ///< kinds marked so far, in order of first appearance
    std::vector<FailureMark> marks_;
    MarkWords words_;
};

}  // namespace collide::show
