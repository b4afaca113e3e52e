// Which failures a lesson marks: the budget shared between kinds and spread over the box, and
// the legend's words.
#include "collide/show/failure_marks.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <utility>
#include <vector>

#include "collide/number_text.hpp"

namespace collide::show {

namespace {

constexpr std::size_t kinds = failure_kinds;

/// The cells of the grid in a scattered order: a stride coprime with the cell count, so that any
/// first few cells lie in different rows and columns rather than along the bottom.
std::vector<std::size_t> scattered_cells() {
    constexpr auto n = static_cast<std::size_t>(mark_grid * mark_grid);
    std::size_t stride = std::max<std::size_t>(1, (n * 9) / 20);
    while (std::gcd(stride, n) != 1) --stride;
    std::vector<std::size_t> order(n);
    for (std::size_t k = 0; k < n; ++k) order[k] = (k * stride) % n;
    return order;
}

std::size_t cell_of(Vec2 p, const Box& box) {
    const auto axis = [](double v, double extent) {
        const double share = extent > 0.0 ? v / extent : 0.0;
        const auto cell = static_cast<long>(std::floor(share * mark_grid));
        return static_cast<std::size_t>(std::clamp(cell, 0L, static_cast<long>(mark_grid - 1)));
    };
    return axis(p.y, box.height) * static_cast<std::size_t>(mark_grid) + axis(p.x, box.width);
}

double mean_radius(const Snapshot& snapshot) {
    double sum = 0.0;
    for (const DiscState& d : snapshot.discs) sum += d.radius;
    return snapshot.discs.empty() ? 0.0 : sum / static_cast<double>(snapshot.discs.size());
}

/// The exit of disc i as its snapshot carries it (spheres: projected by the camera); none for a
/// 2D disc, whose exit follows from its position and velocity (exit_point).
std::optional<Exit> projected_exit(const Snapshot& snapshot, std::uint32_t i) {
    for (const ScreenExit& e : snapshot.exits) {
        if (e.disc == i) return Exit{e.where, e.out};
    }
    return std::nullopt;
}

}  // namespace

std::string failure_name(FailureKind kind) {
    switch (kind) {
        case FailureKind::missed:
            return "missed collision";
        case FailureKind::overlapping:
            return "overlapping";
        case FailureKind::left_box:
            return "left the box";
        case FailureKind::tunnelled:
            return "went through a barrier";
    }
    return "failure";
}

std::string wrap_words() {
    return "edges wrap around";
}

std::string unmarked_words(std::size_t unmarked) {
    if (unmarked == 0) return {};
    // Read after the kinds the legend names: "missed collision  overlapping  and 1,234 more not
    // drawn": failures of those kinds beyond the marks' budget, which the box does not show.
    return "and " + with_separators(static_cast<long long>(unmarked)) + " more not drawn";
}

bool mark_line(bool time_driven, bool says_wrap, const Box& box) {
    return time_driven || (says_wrap && box.boundary == Boundary::periodic);
}

KindCounts fair_shares(const KindCounts& available, std::size_t budget) {
    KindCounts share{};
    // Kinds in order of fewest candidates: each takes what it needs of an equal split of what
    // is left, so a kind with few failures leaves its unused share to the others.
    KindCounts order{};
    for (std::size_t k = 0; k < kinds; ++k) order[k] = k;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return available[a] < available[b]; });
    std::size_t left = budget;
    std::size_t wanting = 0;
    for (const std::size_t k : order) wanting += available[k] > 0 ? 1 : 0;
    for (const std::size_t k : order) {
        if (available[k] == 0) continue;
        // The larger kinds (later in the order) get the remainder's extra marks.
        const std::size_t equal = left / wanting;
        share[k] = std::min(available[k], equal);
        left -= share[k];
        --wanting;
    }
    // Whole-number rounding can leave a few marks: hand them out from the largest kind down.
    for (auto it = order.rbegin(); it != order.rend() && left > 0; ++it) {
        const std::size_t more = std::min(left, available[*it] - share[*it]);
        share[*it] += more;
        left -= more;
    }
    return share;
}

std::vector<std::size_t> spread_over_box(const std::vector<Vec2>& points, const Box& box,
                                         std::size_t count) {
    count = std::min(count, points.size());
    static const std::vector<std::size_t> cells = scattered_cells();
    std::vector<std::vector<std::size_t>> in_cell(cells.size());
    for (std::size_t i = 0; i < points.size(); ++i) in_cell[cell_of(points[i], box)].push_back(i);
    std::vector<std::size_t> picked;
    picked.reserve(count);
    for (std::size_t round = 0; picked.size() < count; ++round) {
        for (const std::size_t c : cells) {
            if (picked.size() == count) break;
            if (round < in_cell[c].size()) picked.push_back(in_cell[c][round]);
        }
    }
    return picked;
}

Exit exit_point(const DiscState& disc, const Box& box) {
    const Vec2 p = disc.position;
    const Vec2 v = disc.velocity;
    // Going back along -v, the centre is inside on an axis from the time it crossed that axis's
    // edge on: inside the box from the latest of those times, on the edge crossed last.
    double back = -1.0;
    Vec2 out{0.0, 0.0};
    const auto consider = [&](double t, Vec2 normal) {
        if (t > back) {
            back = t;
            out = normal;
        }
    };
    if (p.x > box.width && v.x > 0.0) consider((p.x - box.width) / v.x, {1.0, 0.0});
    if (p.x < 0.0 && v.x < 0.0) consider(p.x / v.x, {-1.0, 0.0});
    if (p.y > box.height && v.y > 0.0) consider((p.y - box.height) / v.y, {0.0, 1.0});
    if (p.y < 0.0 && v.y < 0.0) consider(p.y / v.y, {0.0, -1.0});
    Vec2 where = back >= 0.0 ? p - back * v : p;
    if (back < 0.0) {
        // Not moving away (turned round outside): the edge it is farthest beyond.
        const double over_x = std::max(-p.x, p.x - box.width);
        const double over_y = std::max(-p.y, p.y - box.height);
        out = over_x >= over_y ? Vec2{p.x < 0.0 ? -1.0 : 1.0, 0.0}
                               : Vec2{0.0, p.y < 0.0 ? -1.0 : 1.0};
    }
    where.x = std::clamp(where.x, 0.0, box.width);
    where.y = std::clamp(where.y, 0.0, box.height);
    if (out.x != 0.0) where.x = out.x > 0.0 ? box.width : 0.0;  // on the edge crossed, exactly
    if (out.y != 0.0) where.y = out.y > 0.0 ? box.height : 0.0;
    return {where, out};
}

void FailureMarks::update(const Snapshot& snapshot, double video_time) {
    remember(snapshot, video_time);
    choose(snapshot, video_time);
}

void FailureMarks::remember(const Snapshot& snapshot, double video_time) {
    const bool new_state = !last_time_ || *last_time_ != snapshot.time;
    if (last_time_ && snapshot.time < *last_time_) {  // a seek or a new video
        missed_.clear();
        overlaps_.clear();
        left_.clear();
        seen_.clear();
    }
    last_time_ = snapshot.time;
    if (new_state) {
        for (const Vec2 where : snapshot.missed_collisions) missed_.push_back({where, video_time});
    }
    std::erase_if(missed_, [&](const Missed& m) { return video_time - m.born >= mark_seconds; });
    remember_overlaps(snapshot, video_time);
    // Discs outside now: keep where they left from the first frame they were seen outside. A
    // sphere's exit comes projected with the snapshot, anew each frame: the camera may turn.
    std::vector<Left> still;
    for (std::uint32_t i = 0; i < snapshot.discs.size(); ++i) {
        if (!snapshot.discs[i].escaped) continue;
        const auto known =
            std::find_if(left_.begin(), left_.end(), [&](const Left& l) { return l.disc == i; });
        const std::optional<Exit> projected = projected_exit(snapshot, i);
        if (known != left_.end()) {
            still.push_back(*known);
            if (projected) still.back().exit = *projected;
        } else {
            still.push_back(
                Left{i, projected ? *projected : exit_point(snapshot.discs[i], snapshot.box),
                     left_seen_++});
        }
    }
    left_ = std::move(still);
}

void FailureMarks::remember_overlaps(const Snapshot& snapshot, double video_time) {
    const Box& box = snapshot.box;
    std::vector<Overlap> now;
    now.reserve(snapshot.overlapping_pairs.size());
    for (const auto& [a, b] : snapshot.overlapping_pairs) {
        if (a >= snapshot.discs.size() || b >= snapshot.discs.size()) continue;
        const DiscState& da = snapshot.discs[a];
        const DiscState& db = snapshot.discs[b];
        now.push_back({{a, b},
                       box.wrap(da.position + 0.5 * box.displacement(da.position, db.position)),
                       std::max(da.radius, db.radius) * 2.0,
                       video_time});
    }
    const auto by_pair = [](const Overlap& x, const Overlap& y) { return x.pair < y.pair; };
    std::sort(now.begin(), now.end(), by_pair);
    // The pairs overlapping now, and those that parted less than mark_seconds ago: a parted pair
    // keeps its cross where it last overlapped, fading, so that an overlap of one frame is seen.
    std::vector<Overlap> kept;
    kept.reserve(now.size() + overlaps_.size());
    auto old = overlaps_.begin();
    for (const Overlap& o : now) {
        for (; old != overlaps_.end() && by_pair(*old, o); ++old) kept.push_back(*old);
        if (old != overlaps_.end() && old->pair == o.pair) ++old;  // seen again: now's
        kept.push_back(o);
    }
    kept.insert(kept.end(), old, overlaps_.end());
    std::erase_if(kept, [&](const Overlap& o) { return video_time - o.seen >= mark_seconds; });
    overlaps_ = std::move(kept);
}

void FailureMarks::choose(const Snapshot& snapshot, double video_time) {
    const Box& box = snapshot.box;
    // Candidates of each kind, most preferred first: the newest rings, the pairs scrambled, the
    // discs that left most recently.
    std::array<std::vector<FailureMark>, kinds> candidates;
    const double ring = missed_mark_radii * mean_radius(snapshot);
    for (auto it = missed_.rbegin(); it != missed_.rend(); ++it) {
        const auto opacity =
            static_cast<float>(std::clamp(1.0 - (video_time - it->born) / mark_seconds, 0.0, 1.0));
        candidates[0].push_back({FailureKind::missed, it->where, {}, ring, opacity});
    }
    // Overlapping pairs: those overlapping now first, then those that parted, most recent first;
    // within each, a scrambled order of the pair (a fixed hash), not the engine's index order,
    // which follows the discs' starting lattice (a dense fluid's first pairs all straddle one
    // seam).
    std::vector<const Overlap*> pairs;
    pairs.reserve(overlaps_.size());
    for (const Overlap& o : overlaps_) pairs.push_back(&o);
    const auto scramble = [](std::pair<std::uint32_t, std::uint32_t> p) {
        return (static_cast<std::uint64_t>(p.first) * 0x9E3779B97F4A7C15ULL) ^
               (static_cast<std::uint64_t>(p.second) * 0xC2B2AE3D27D4EB4FULL);
    };
    std::sort(pairs.begin(), pairs.end(), [&](const Overlap* x, const Overlap* y) {
        if (x->seen != y->seen) return x->seen > y->seen;
        return scramble(x->pair) < scramble(y->pair);
    });
    for (const Overlap* o : pairs) {
        const auto opacity =
            static_cast<float>(std::clamp(1.0 - (video_time - o->seen) / mark_seconds, 0.0, 1.0));
        candidates[1].push_back({FailureKind::overlapping, o->where, {}, o->size, opacity});
    }
    std::vector<const Left*> newest;
    for (const Left& l : left_) newest.push_back(&l);
    std::sort(newest.begin(), newest.end(),
              [](const Left* a, const Left* b) { return a->order > b->order; });
    for (const Left* l : newest) {
        candidates[2].push_back({FailureKind::left_box, l->exit.where, l->exit.out, ring, 1.0F});
    }

    // Discs that went through a barrier (and are not outside a walled box, whose arrow says
    // more): a diamond round each, where it is now, for the rest of the video.
    for (const DiscState& d : snapshot.discs) {
        if (d.tunnelled && !d.escaped)
            candidates[3].push_back({FailureKind::tunnelled, d.position, {}, d.radius, 1.0F});
    }

    KindCounts available{};
    for (std::size_t k = 0; k < kinds; ++k) available[k] = candidates[k].size();
    const KindCounts shares = fair_shares(available, budget_);
    marks_.clear();
    std::size_t total = 0;
    for (std::size_t k = 0; k < kinds; ++k) {
        total += candidates[k].size();
        std::vector<Vec2> points;
        points.reserve(candidates[k].size());
        for (const FailureMark& m : candidates[k]) points.push_back(m.where);
        for (const std::size_t i : spread_over_box(points, box, shares[k])) {
            marks_.push_back(candidates[k][i]);
        }
        const auto kind = static_cast<FailureKind>(k);
        if (shares[k] > 0 && std::find(seen_.begin(), seen_.end(), kind) == seen_.end()) {
            seen_.push_back(kind);
        }
    }
    words_.items.clear();
    for (const FailureKind kind : seen_) words_.items.push_back({kind, failure_name(kind)});
    words_.wraps = say_wrap_ && box.boundary == Boundary::periodic ? wrap_words() : std::string{};
    words_.unmarked = unmarked_words(total - marks_.size());
}

}  // namespace collide::show
