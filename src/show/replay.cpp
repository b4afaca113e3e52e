// The instant replay of a time-driven failure: when it comes, the zoom onto the spot, the slow
// move from step k to step k + 1 with its ghosts, and every word of it.
#include "collide/show/replay.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "collide/show/ease.hpp"

namespace collide::show {

namespace {

/// A time as the replay's labels say it: three significant digits ("0.08", "0.0613").
std::string time_words(double t) {
    return fmt::format("{:.3g}", t);
}

bool through_wall(const ReplayFailure& failure) {
    return failure.step.kind == sim::StepFailureKind::left_box;
}

/// The failure's discs near one another (a periodic box may hold them on opposite sides): the
/// disc that moved most (the one that jumped) where it was, the other placed relative to it.
struct Geometry {
    bool swapped = false;  ///< the mover is the record's disc b
    Vec2 a0, a1;           ///< the mover at step k and where its straight move took it
    Vec2 b0, b1;           ///< the other disc likewise (a wall failure: the mover again)
    double ra = 0.0;
    double rb = 0.0;
    Vec2 where;             ///< the contact (pair) or the wall crossing
    double fraction = 0.0;  ///< the contact's share of the step, in [0, 1]
};

Geometry geometry(const ReplayFailure& failure, const Box& box) {
    const sim::StepFailure& f = failure.step;
    Geometry g;
    g.swapped = norm(f.motion_b) > norm(f.motion_a);
    const Vec2 before = g.swapped ? f.before_b : f.before_a;
    const Vec2 other = g.swapped ? f.before_a : f.before_b;
    g.a0 = before;
    g.a1 = before + (g.swapped ? f.motion_b : f.motion_a);
    g.b0 = before + box.displacement(before, other);
    g.b1 = g.b0 + (g.swapped ? f.motion_a : f.motion_b);
    g.ra = g.swapped ? f.radius_b : f.radius_a;
    g.rb = g.swapped ? f.radius_a : f.radius_b;
    // The record's contact point is in disc a's frame: carried next to the mover.
    g.where = before + box.displacement(before, f.where);
    g.fraction = failure.dt > 0.0 ? std::clamp(f.contact / failure.dt, 0.0, 1.0) : 0.0;
    return g;
}

Vec2 lerp(Vec2 a, Vec2 b, double t) {
    return a + t * (b - a);
}

/// The side of a point that `direction` (box coordinates, y up) points to, by its larger part.
LabelSide side_towards(Vec2 direction) {
    if (std::abs(direction.x) > std::abs(direction.y))
        return direction.x > 0.0 ? LabelSide::right : LabelSide::left;
    return direction.y > 0.0 ? LabelSide::above : LabelSide::below;
}

/// Across a move (perpendicular to it), towards `room` (the middle of the view).
LabelSide side_across(Vec2 move, Vec2 from, Vec2 room) {
    const Vec2 normal{-move.y, move.x};
    return side_towards(dot(normal, room - from) >= 0.0 ? normal : -1.0 * normal);
}

/// How far the replay is: the zoom's share (0 whole box .. 1 at the spot), the slow move's
/// share of the step (0 at step k .. 1 at step k + 1), and the marks' opacity.
struct Phase {
    double zoom = 0.0;
    double move = 0.0;
    float opacity = 1.0F;
};

Phase phase_at(double seconds) {
    Phase p;
    const double in = ease(seconds / replay_zoom_in);
    const double out = ease((replay_seconds - seconds) / (replay_seconds - replay_hold_end));
    p.zoom = std::min<double>(in, out);
    p.move = std::clamp((seconds - replay_zoom_in) / (replay_slow_end - replay_zoom_in), 0.0, 1.0);
    p.opacity = static_cast<float>(std::min<double>(ease(seconds / (0.5 * replay_zoom_in)), out));
    return p;
}

ReplayView time_driven_view(const ReplayFailure& failure, const Geometry& g, const Phase& p,
                            double magnification, Vec2 view_centre) {
    const float o = p.opacity;
    ReplayView view;
    view.heading = fmt::format("Replay: 1 step, {:.0f}x enlarged", magnification);
    const bool wall = through_wall(failure);
    const bool b_moves = !wall && norm(g.b1 - g.b0) > 1e-3 * g.rb;
    // Step k, as the check saw it: no overlap.
    view.ghosts.push_back({g.a0, g.ra, false, false, o});
    if (b_moves) view.ghosts.push_back({g.b0, g.rb, false, false, o});
    const Vec2 move = g.a1 - g.a0;
    BoxLabel before{g.a0, fmt::format("check t = {}", time_words(failure.check_before()))};
    before.side = side_towards(-1.0 * move);  // behind the move
    before.opacity = o;
    before.clear = g.ra;
    view.labels.push_back(before);
    // The straight move between the checks, drawn as far as the replay has got.
    const Vec2 a_now = lerp(g.a0, g.a1, p.move);
    const Vec2 b_now = lerp(g.b0, g.b1, p.move);
    if (p.move > 0.0) view.lines.push_back({g.a0, a_now, true, o});
    if (b_moves && p.move > 0.0) view.lines.push_back({g.b0, b_now, true, 0.6F * o});
    // Step k + 1: the check sees no overlap again.
    if (p.move >= 1.0) {
        view.ghosts.push_back({g.a1, g.ra, false, false, o});
        if (b_moves) view.ghosts.push_back({g.b1, g.rb, false, false, o});
        BoxLabel after{g.a1, fmt::format("check t = {}", time_words(failure.check_after()))};
        after.side = side_towards(move);  // ahead of it
        after.opacity = o;
        after.clear = g.ra;
        view.labels.push_back(after);
    }
    // Where they touched (or the disc crossed the wall): no check ever saw it.
    if (p.move >= g.fraction && p.move > 0.0) {
        view.ghosts.push_back({lerp(g.a0, g.a1, g.fraction), g.ra, false, true, o});
        if (!wall) view.ghosts.push_back({lerp(g.b0, g.b1, g.fraction), g.rb, false, true, o});
        BoxLabel hit{g.where,
                     wall ? fmt::format("wall t = {}, unseen", time_words(failure.contact_time()))
                          : fmt::format("hit t = {}, unseen", time_words(failure.contact_time()))};
        hit.failure = true;
        hit.side = side_across(move, g.where, view_centre);
        hit.opacity = o;
        hit.clear = 2.0 * g.ra;
        view.labels.push_back(hit);
    }
    // The discs on their way (in the failure colour while they overlap), in place of the
    // snapshot's own (at step k + 1 already); the other discs faint.
    const bool overlap = !wall && norm(a_now - b_now) < g.ra + g.rb;
    view.ghosts.push_back({a_now, g.ra, true, overlap && p.move < 1.0, 1.0F});
    if (b_moves) view.ghosts.push_back({b_now, g.rb, true, overlap && p.move < 1.0, 1.0F});
    const std::uint32_t mover = g.swapped ? failure.step.b : failure.step.a;
    view.hidden = {mover};
    view.focus = {failure.step.a, failure.step.b};
    if (b_moves) view.hidden.push_back(g.swapped ? failure.step.a : failure.step.b);
    return view;
}

ReplayView event_driven_view(const ReplayFailure& failure, const Geometry& g, const Phase& p,
                             const Box& box, Vec2 view_centre) {
    const float o = p.opacity;
    ReplayView view;
    view.heading = "Same moment: event-driven";
    view.focus = {failure.step.a, failure.step.b};
    if (!failure.predicted) {
        // The event-driven run never brought these two together here: the time-driven panel's
        // earlier failures changed its history. Say so, or the panel shows an empty spot.
        for (const LabelSide side : {LabelSide::above, LabelSide::below}) {
            BoxLabel apart{view_centre,
                           std::string(parted_words[side == LabelSide::above ? 0 : 1])};
            apart.side = side;
            apart.opacity = o;
            view.labels.push_back(apart);
        }
        return view;
    }
    const PredictedHit& hit = *failure.predicted;
    // The mover and the other disc at the collision, near the time-driven spot (a periodic box
    // may hold them a box width away).
    const Vec2 mover = g.swapped && !hit.wall ? hit.b : hit.a;
    const Vec2 other = g.swapped && !hit.wall ? hit.a : hit.b;
    const Vec2 a = g.a0 + box.displacement(g.a0, mover);
    const Vec2 b = a + (hit.wall ? other - mover : box.displacement(mover, other));
    const Vec2 contact = hit.wall ? b : a + (g.ra / (g.ra + g.rb)) * (b - a);
    BoxLabel label{contact, fmt::format("predicted hit t = {}", time_words(hit.time))};
    label.side = side_across(g.a1 - g.a0, contact, view_centre);
    label.opacity = o;
    label.clear = 2.0 * g.ra;
    view.labels.push_back(label);
    // The collision itself once the time-driven replay reaches that moment.
    if (p.move >= g.fraction && p.move > 0.0) {
        view.ghosts.push_back({a, g.ra, false, false, o});
        if (!hit.wall) view.ghosts.push_back({b, g.rb, false, false, o});
        BoxLabel bounce{a, "it bounces"};
        bounce.side = side_towards(-1.0 * (g.a1 - g.a0));
        bounce.opacity = o;
        bounce.clear = g.ra;
        view.labels.push_back(bounce);
    }
    return view;
}

}  // namespace

std::int64_t first_frame_after_step(std::uint64_t step, double dt, const FrameClock& clock) {
    if (!(dt > 0.0) || !(clock.interval > 0.0)) return -1;
    const double end = static_cast<double>(step + 1) * dt;
    auto j = static_cast<std::int64_t>(std::floor(end / clock.interval)) - 1;
    j = std::max<std::int64_t>(0, j);
    while (j < clock.count && sim::TimeEngine::whole_steps(clock.time(j), dt) < step + 1) ++j;
    return j < clock.count ? j : -1;
}

std::string replay_caption(const ReplayFailure& failure) {
    if (through_wall(failure)) return "Between two checks the disc jumped through the wall";
    return "Between two checks the disc jumped through: no overlap was ever seen";
}

std::vector<TimelineReplay> replay_cues(const std::vector<ReplayFailure>& failures) {
    std::vector<TimelineReplay> cues;
    for (const ReplayFailure& failure : failures)
        cues.push_back({failure.sim_frame, replay_seconds, replay_caption(failure)});
    return cues;
}

BoxZoom replay_target(const ReplayFailure& failure, const Box& box) {
    const Geometry g = geometry(failure, box);
    const double r = std::max(g.ra, through_wall(failure) ? g.ra : g.rb);
    Vec2 low{std::min({g.a0.x, g.a1.x, g.b0.x, g.b1.x}),
             std::min({g.a0.y, g.a1.y, g.b0.y, g.b1.y})};
    Vec2 high{std::max({g.a0.x, g.a1.x, g.b0.x, g.b1.x}),
              std::max({g.a0.y, g.a1.y, g.b0.y, g.b1.y})};
    low = low - Vec2{r, r};
    high = high + Vec2{r, r};
    // The discs and their move fill about half of the view: room for the labels around them.
    const double width = std::max(high.x - low.x, 6.0 * r);
    const double height = std::max(high.y - low.y, 6.0 * r);
    const double fit = 0.5 * std::min(box.width / width, box.height / height);
    BoxZoom zoom;
    zoom.centre = 0.5 * (low + high);
    zoom.magnification = std::clamp(fit, 1.0, max_replay_magnification);
    return zoom;
}

ReplayViews replay_views(const ReplayFailure& failure, const Box& box, double seconds) {
    const Geometry g = geometry(failure, box);
    const Phase p = phase_at(seconds);
    const BoxZoom target = replay_target(failure, box);
    ReplayViews frame;
    // Enlarging by equal factors each frame, the spot sliding to the middle as it grows.
    const double m = std::pow(target.magnification, p.zoom);
    const double slide =
        target.magnification > 1.0 ? (1.0 - 1.0 / m) / (1.0 - 1.0 / target.magnification) : 1.0;
    const Vec2 middle{0.5 * box.width, 0.5 * box.height};
    frame.zoom.centre = lerp(middle, target.centre, slide);
    frame.zoom.magnification = m;
    frame.time_driven = time_driven_view(failure, g, p, target.magnification, target.centre);
    frame.event_driven = event_driven_view(failure, g, p, box, target.centre);
    return frame;
}

const ReplayFailure* replay_at(const std::vector<ReplayFailure>& failures,
                               std::int64_t sim_frame) noexcept {
    const auto it = std::find_if(failures.begin(), failures.end(),
                                 [&](const ReplayFailure& f) { return f.sim_frame == sim_frame; });
    return it == failures.end() ? nullptr : &*it;
}

}  // namespace collide::show
