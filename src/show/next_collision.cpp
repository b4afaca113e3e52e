// The event-driven panel's next collision, as the lesson draws it: a thin line from the disc to
// what it will hit, and its time to go. Which collision comes next is the engine's
// (sim::CollisionLookahead); here it becomes box geometry and words.
#include <algorithm>

#include "collide/show/collision.hpp"

namespace collide::show {

NextCollisionView next_collision_view(const CollisionRecord& next, const Snapshot& snapshot,
                                      const FrameClock& clock) {
    NextCollisionView view;
    const std::size_t n = snapshot.discs.size();
    if (snapshot.dimension != 2 || next.a >= n) return view;
    const Box& box = snapshot.box;
    const DiscState& a = snapshot.discs[next.a];
    const double to_go = std::max(0.0, next.t - snapshot.time);
    view.keep_clear.push_back({a.position, a.radius});
    switch (next.kind) {
        case CollisionKind::pair: {
            if (next.b >= n) return view;
            const DiscState& b = snapshot.discs[next.b];
            // The image of b that a meets: the nearest one at the moment they touch (then they
            // are two radii apart), brought back to now. In a periodic box it may lie across an
            // edge: the line goes from each disc towards the other's image, cut at the box.
            const Vec2 at_hit =
                box.displacement(a.position + a.velocity * to_go, b.position + b.velocity * to_go);
            const Vec2 d = at_hit - (b.velocity - a.velocity) * to_go;
            view.lines.push_back({a.position, a.position + d});
            if (box.boundary == Boundary::periodic)
                view.lines.push_back({b.position, b.position - d});
            // The middle of the whole line, folded into the box: on one of its pieces.
            view.label_at = box.wrap(a.position + d * 0.5);
            view.keep_clear.push_back({b.position, b.radius});
            break;
        }
        case CollisionKind::xwall:
        case CollisionKind::ywall: {
            // Where the disc will touch the wall: its centre then, moved onto the wall.
            Vec2 hit = a.position + a.velocity * to_go;
            if (next.kind == CollisionKind::xwall) hit.x = a.velocity.x > 0.0 ? box.width : 0.0;
            if (next.kind == CollisionKind::ywall) hit.y = a.velocity.y > 0.0 ? box.height : 0.0;
            view.lines.push_back({a.position, hit});
            view.label_at = (a.position + hit) * 0.5;
            break;
        }
        case CollisionKind::zwall:
            return {};
    }
    view.text = next_collision_words(to_go, clock);
    view.short_text = next_collision_words(to_go, clock, true);
    return view;
}

}  // namespace collide::show
