// Pause and ponder: the questions a collision video asks, answered by a copy of the event-driven
// engine at the frozen frame, their words, and what the event-driven panel draws while they hold.
#include "collide/show/questions.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>

#include "collide/error.hpp"

namespace collide::show {

namespace {

/// The collisions a copy of the engine resolves after its time, in order.
struct Ahead {
    std::vector<CollisionRecord> hits;
    bool copied = false;
};

/// Runs a copy of `engine` to after(1), after(2), ... until it has resolved `enough` collisions
/// (0: every frame up to `frames`) or `frames` frames passed.
Ahead run_copy(const Engine& engine, const FramesAfter& after, std::int64_t frames,
               std::size_t enough) {
    Ahead out;
    const std::unique_ptr<Engine> copy = engine.clone();
    if (!copy) return out;
    out.copied = true;
    copy->set_collision_listener([&out](const CollisionRecord& hit) { out.hits.push_back(hit); });
    for (std::int64_t i = 1; i <= frames; ++i) {
        copy->advance_to(std::max(after(i), copy->time()));
        if (enough > 0 && out.hits.size() >= enough) break;
    }
    copy->set_collision_listener(nullptr);
    return out;
}

/// The same collision, whenever: the same discs (a pair either way round) or disc and wall.
bool same_contact(const CollisionRecord& x, const CollisionRecord& y) {
    if (x.kind != y.kind) return false;
    if (x.kind != CollisionKind::pair) return x.a == y.a;
    return std::min(x.a, x.b) == std::min(y.a, y.b) && std::max(x.a, x.b) == std::max(y.a, y.b);
}

bool shares_disc(const CollisionRecord& x, const CollisionRecord& y) {
    const auto has = [](const CollisionRecord& r, std::uint32_t i) {
        return r.a == i || (r.kind == CollisionKind::pair && r.b == i);
    };
    return has(y, x.a) || (x.kind == CollisionKind::pair && has(y, x.b));
}

/// splitmix64: a shuffle the same on every platform (std::shuffle's is the library's own).
std::uint64_t mix(std::uint64_t& state) {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30U)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27U)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31U);
}

/// The gap between two discs' edges now (periodic box: to the nearest image).
double gap(const Snapshot& snapshot, std::uint32_t a, std::uint32_t b) {
    const DiscState& x = snapshot.discs[a];
    const DiscState& y = snapshot.discs[b];
    return norm(snapshot.box.displacement(x.position, y.position)) - x.radius - y.radius;
}

/// True when the pair `r` may be offered as a near miss: it does not collide among `seen` (the
/// collisions of the look ahead) and shares no disc with `avoid` (the candidates so far).
bool may_offer_as_miss(const CollisionRecord& r, const std::vector<CollisionRecord>& seen,
                       const std::vector<CollisionRecord>& avoid) {
    const auto same = [&r](const CollisionRecord& s) { return same_contact(r, s); };
    const auto near = [&r](const CollisionRecord& s) { return shares_disc(r, s); };
    return std::none_of(seen.begin(), seen.end(), same) &&
           std::none_of(avoid.begin(), avoid.end(), near);
}

/// The discs near_misses looks at: the first 2,000 (its search is O(n^2)).
std::uint32_t near_miss_discs(std::size_t discs) {
    return static_cast<std::uint32_t>(std::min<std::size_t>(discs, 2000));
}

CollisionRecord pair_record(std::uint32_t a, std::uint32_t b) {
    CollisionRecord r;
    r.t = std::numeric_limits<double>::infinity();
    r.a = a;
    r.b = b;
    return r;
}

/// Near pairs that do not collide among `seen` (the collisions of the look ahead, which end
/// after the answer) and that `accept` takes: the pairs of discs closest edge to edge but at
/// least `apart`, nearest first, sharing no disc with `avoid` nor with each other. At most
/// `wanted`; O(n^2) over at most the first 2,000 discs.
template <typename Accept>
std::vector<CollisionRecord> near_misses(const Snapshot& snapshot,
                                         const std::vector<CollisionRecord>& seen,
                                         const std::vector<CollisionRecord>& avoid,
                                         std::size_t wanted, double apart, const Accept& accept) {
    const std::uint32_t n = near_miss_discs(snapshot.discs.size());
    std::vector<std::pair<double, CollisionRecord>> pairs;
    for (std::uint32_t a = 0; a < n; ++a) {
        for (std::uint32_t b = a + 1; b < n; ++b) {
            const CollisionRecord r = pair_record(a, b);
            const double g = gap(snapshot, a, b);
            if (g >= apart && may_offer_as_miss(r, seen, avoid)) pairs.emplace_back(g, r);
        }
    }
    std::sort(pairs.begin(), pairs.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<CollisionRecord> out;
    for (const auto& [g, r] : pairs) {
        if (out.size() == wanted) break;
        const auto near = [&r](const CollisionRecord& s) { return shares_disc(r, s); };
        if (std::any_of(out.begin(), out.end(), near) || !accept(r, out)) continue;
        out.push_back(r);
    }
    return out;
}

/// True when near_misses would find one among `discs` discs: the first pair it may offer ends
/// the search (O(n) pairs at most before one is found: `seen` and `avoid` exclude few).
bool has_near_miss(std::size_t discs, const std::vector<CollisionRecord>& seen,
                   const std::vector<CollisionRecord>& avoid) {
    const std::uint32_t n = near_miss_discs(discs);
    for (std::uint32_t a = 0; a < n; ++a) {
        for (std::uint32_t b = a + 1; b < n; ++b) {
            if (may_offer_as_miss(pair_record(a, b), seen, avoid)) return true;
        }
    }
    return false;
}

/// The gap a class sees between `r`'s discs now, or between its disc and the nearer wall across
/// which it hits (a disc near one wall may hit the other later: the nearer one is the gap the
/// picture shows).
double contact_gap(const CollisionRecord& r, const Snapshot& snapshot) {
    const std::size_t n = snapshot.discs.size();
    if (r.a >= n || (r.kind == CollisionKind::pair && r.b >= n)) return 0.0;
    if (r.kind == CollisionKind::pair) return gap(snapshot, r.a, r.b);
    const DiscState& d = snapshot.discs[r.a];
    const Box& box = snapshot.box;
    if (r.kind == CollisionKind::xwall)
        return std::min(d.position.x, box.width - d.position.x) - d.radius;
    if (r.kind == CollisionKind::ywall)
        return std::min(d.position.y, box.height - d.position.y) - d.radius;
    return 0.0;
}

/// The discs a candidate names: its pair, or its one disc.
std::vector<std::uint32_t> discs_of(const CollisionRecord& c) {
    if (c.kind == CollisionKind::pair) return {c.a, c.b};
    return {c.a};
}

/// The time over which every candidate disc's arrow shows its move: the fastest disc of
/// `candidates` moves motion_arrow_share of the box's smaller side in it; 0 when none moves.
double arrow_seconds(const std::vector<CollisionRecord>& candidates, const Snapshot& snapshot) {
    double fastest = 0.0;
    for (const CollisionRecord& c : candidates) {
        for (const std::uint32_t k : discs_of(c)) {
            if (k < snapshot.discs.size())
                fastest = std::max(fastest, norm(snapshot.discs[k].velocity));
        }
    }
    if (!(fastest > 0.0) || !std::isfinite(fastest)) return 0.0;
    return motion_arrow_share * std::min(snapshot.box.width, snapshot.box.height) / fastest;
}

/// Disc `d`'s velocity as an arrow ending at its leading edge: its move over `seconds`, behind
/// the disc (where it came from), so that a disc at a wall heading into it keeps its arrow inside
/// the box. None for a disc at rest.
std::optional<BoxLine> motion_arrow(const DiscState& d, double seconds) {
    const double speed = norm(d.velocity);
    if (!(speed > 0.0) || !(seconds > 0.0)) return std::nullopt;
    const Vec2 edge = d.position + d.velocity * (d.radius / speed);
    BoxLine arrow{edge - d.velocity * seconds, edge};
    arrow.style = LineStyle::motion;
    return arrow;
}

/// `line` without its ends' `cut_from` and `cut_to` (box units); none when nothing is left.
std::optional<BoxLine> trimmed(BoxLine line, double cut_from, double cut_to) {
    const Vec2 d = line.to - line.from;
    const double length = norm(d);
    if (!(length > cut_from + cut_to)) return std::nullopt;
    const Vec2 u = d * (1.0 / length);
    line.from = line.from + u * cut_from;
    line.to = line.to - u * cut_to;
    return line;
}

/// Candidate `c`'s connector: the line of its contact (next_collision_view's: between its discs,
/// or from its disc to the point of the wall it hits), cut at the discs' edges so that it joins
/// them without crossing them. A near miss (no time) joins its discs as they are now.
std::vector<BoxLine> connector_lines(const CollisionRecord& c, const Snapshot& snapshot) {
    CollisionRecord shown = c;
    if (!std::isfinite(shown.t)) shown.t = snapshot.time;
    // The clock only words the time to go, which a connector does not show.
    const NextCollisionView seen = next_collision_view(shown, snapshot, FrameClock{});
    std::vector<BoxLine> out;
    const double ra = snapshot.discs[c.a].radius;
    const double rb = c.kind == CollisionKind::pair ? snapshot.discs[c.b].radius : 0.0;
    for (std::size_t k = 0; k < seen.lines.size(); ++k) {
        // next_collision_view's lines start at disc a (a periodic pair's second one at b, towards
        // a's image).
        const bool from_a = k == 0;
        std::optional<BoxLine> line = trimmed(seen.lines[k], from_a ? ra : rb, from_a ? rb : ra);
        if (!line) continue;
        line->style = LineStyle::connector;
        out.push_back(*line);
    }
    return out;
}

/// A piece of a candidate's drawing: the segment from `from` to `to` thickened by `radius` (a
/// disc: a point and its radius; a line: none).
struct Stroke {
    Vec2 from;
    Vec2 to;
    double radius = 0.0;
};

/// The distance from point p to the segment [a, b].
double point_segment_distance(Vec2 p, Vec2 a, Vec2 b) {
    const Vec2 d = b - a;
    const double length2 = dot(d, d);
    const double t = length2 > 0.0 ? std::clamp(dot(p - a, d) / length2, 0.0, 1.0) : 0.0;
    return norm(p - (a + d * t));
}

/// The distance between segments [p1, q1] and [p2, q2]: 0 where they cross, else the least of
/// their ends' distances to the other.
double segment_distance(Vec2 p1, Vec2 q1, Vec2 p2, Vec2 q2) {
    const auto cross = [](Vec2 o, Vec2 a, Vec2 b) {
        return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    const double d1 = cross(p2, q2, p1);
    const double d2 = cross(p2, q2, q1);
    const double d3 = cross(p1, q1, p2);
    const double d4 = cross(p1, q1, q2);
    if (((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0)) &&
        ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0)))
        return 0.0;
    return std::min({point_segment_distance(p1, p2, q2), point_segment_distance(q1, p2, q2),
                     point_segment_distance(p2, p1, q1), point_segment_distance(q2, p1, q1)});
}

/// What candidate `c` draws in the question's picture: its discs, its connector and its discs'
/// arrows over `seconds` (arrow_seconds).
std::vector<Stroke> drawing_of(const CollisionRecord& c, const Snapshot& snapshot, double seconds) {
    std::vector<Stroke> out;
    for (const std::uint32_t k : discs_of(c)) {
        const DiscState& d = snapshot.discs[k];
        out.push_back({d.position, d.position, d.radius});
        if (const std::optional<BoxLine> arrow = motion_arrow(d, seconds))
            out.push_back({arrow->from, arrow->to, 0.0});
    }
    for (const BoxLine& line : connector_lines(c, snapshot)) out.push_back({line.from, line.to});
    return out;
}

/// True when no piece of `x` comes within `margin` of a piece of `y`.
bool drawings_apart(const std::vector<Stroke>& x, const std::vector<Stroke>& y, double margin) {
    return std::all_of(x.begin(), x.end(), [&](const Stroke& s) {
        return std::all_of(y.begin(), y.end(), [&](const Stroke& o) {
            return segment_distance(s.from, s.to, o.from, o.to) - s.radius - o.radius >= margin;
        });
    });
}

/// True when `c`'s drawing keeps drawing_gap_share of the box's smaller side from each of
/// `chosen`'s, all drawn as they would be with `c` among them (its arrows' time: adding a
/// faster disc only shortens the arrows of those chosen before, which stay apart).
bool drawn_apart(const CollisionRecord& c, const std::vector<CollisionRecord>& chosen,
                 const Snapshot& snapshot) {
    std::vector<CollisionRecord> all = chosen;
    all.push_back(c);
    const double seconds = arrow_seconds(all, snapshot);
    const double margin = drawing_gap_share * std::min(snapshot.box.width, snapshot.box.height);
    const std::vector<Stroke> mine = drawing_of(c, snapshot, seconds);
    return std::all_of(chosen.begin(), chosen.end(), [&](const CollisionRecord& other) {
        return drawings_apart(mine, drawing_of(other, snapshot, seconds), margin);
    });
}

/// What a distractor must be for a class to tell it from the answer in the frozen picture.
struct TellApart {
    double now = 0.0;    ///< the frozen frame's simulation time
    double later = 0.0;  ///< its contact at least this long after now (simulation time)
    double apart = 0.0;  ///< its discs (or disc and wall) at least this far apart now
    const Snapshot* picture = nullptr;
};

TellApart tell_apart(const CollisionRecord& next, const Snapshot& snapshot,
                     const FramesAfter& after, int fps) {
    TellApart out;
    out.now = snapshot.time;
    const auto frames =
        static_cast<std::int64_t>(std::ceil(distractor_video_seconds * std::max(1, fps)));
    out.later = std::max(distractor_time_factor * (next.t - out.now), after(frames) - out.now);
    out.apart = distractor_gap_share * std::min(snapshot.box.width, snapshot.box.height);
    out.picture = &snapshot;
    return out;
}

/// True when the later collision `hit` looks like a later one in the picture: far enough ahead in
/// time, and its discs (or disc and wall) visibly apart now, not touching while they slide by.
bool distinct_in_picture(const CollisionRecord& hit, const TellApart& rule) {
    return hit.t - rule.now >= rule.later && contact_gap(hit, *rule.picture) >= rule.apart;
}

/// Adds to `chosen` (the engine's next collision first) later collisions of `hits` that `accept`
/// takes (of other discs first, their lines apart, then any other contact), never one at the
/// very time of the first (two answers at once would both be right), up to max_candidates - 1.
template <typename Accept>
void add_later_hits(const std::vector<CollisionRecord>& hits, std::vector<CollisionRecord>& chosen,
                    const Accept& accept) {
    // A copy: pushing onto `chosen` may move its elements.
    const CollisionRecord next = chosen.front();
    for (const bool apart : {true, false}) {
        for (const CollisionRecord& hit : hits) {
            if (chosen.size() >= max_candidates - 1) return;
            const auto same = [&hit](const CollisionRecord& c) { return same_contact(hit, c); };
            const auto near = [&hit](const CollisionRecord& c) { return shares_disc(hit, c); };
            if (!(hit.t > next.t) || std::any_of(chosen.begin(), chosen.end(), same)) continue;
            if (apart && std::any_of(chosen.begin(), chosen.end(), near)) continue;
            if (accept(hit)) chosen.push_back(hit);
        }
    }
}

/// The near pairs add_near_misses tries for drawings kept apart, nearest first.
constexpr std::size_t near_pair_tries = 256;

/// Adds near misses (near_misses) visibly apart by at least `apart` to `chosen`, up to
/// max_candidates - 1; `drawn_clear`: only those whose drawings keep apart from the others'
/// (drawn_apart).
void add_near_misses(const Snapshot& snapshot, const std::vector<CollisionRecord>& hits,
                     double apart, bool drawn_clear, std::vector<CollisionRecord>& chosen) {
    if (chosen.size() >= max_candidates - 1) return;
    // In a crowded box few pairs keep apart: the nearest near_pair_tries are tried, no more
    // (the search stays O(n^2) in the pairs' gaps, not in their drawings).
    std::size_t tried = 0;
    const auto accept = [&](const CollisionRecord& r, const std::vector<CollisionRecord>& more) {
        if (!drawn_clear) return true;
        if (++tried > near_pair_tries) return false;
        std::vector<CollisionRecord> all = chosen;
        all.insert(all.end(), more.begin(), more.end());
        return drawn_apart(r, all, snapshot);
    };
    const std::vector<CollisionRecord> misses =
        near_misses(snapshot, hits, chosen, max_candidates - 1 - chosen.size(), apart, accept);
    chosen.insert(chosen.end(), misses.begin(), misses.end());
}

/// The contacts a next-collision question offers from those resolved ahead (`hits`, in order, not
/// empty): the first, then distractors a class can tell from it in the picture, best first:
/// later collisions distinct_in_picture, then near misses visibly apart, each first among those
/// whose drawings (discs, connector, arrows) keep apart from the others' (drawn_apart: no
/// tangle of crossing lines where another choice exists), then any near misses, then any later
/// collisions. At most max_candidates - 1.
std::vector<CollisionRecord> offered_collisions(const std::vector<CollisionRecord>& hits,
                                                const Snapshot& snapshot, const TellApart& rule) {
    std::vector<CollisionRecord> chosen{hits.front()};
    for (const bool drawn_clear : {true, false}) {
        add_later_hits(hits, chosen, [&](const CollisionRecord& hit) {
            return distinct_in_picture(hit, rule) &&
                   (!drawn_clear || drawn_apart(hit, chosen, snapshot));
        });
        add_near_misses(snapshot, hits, rule.apart, drawn_clear, chosen);
    }
    add_near_misses(snapshot, hits, -std::numeric_limits<double>::infinity(), false, chosen);
    add_later_hits(hits, chosen, [](const CollisionRecord&) { return true; });
    return chosen;
}

/// True when `hits` hold a later contact than the first's (a second candidate whatever the
/// picture: offered_collisions' last resort).
bool has_later_contact(const std::vector<CollisionRecord>& hits) {
    const CollisionRecord& next = hits.front();
    return std::any_of(hits.begin(), hits.end(), [&next](const CollisionRecord& hit) {
        return hit.t > next.t && !same_contact(hit, next);
    });
}

/// The collisions a copy asked for a next-collision question resolves: enough that a few of
/// them involve other discs than the first's.
constexpr std::size_t next_collision_hits = 24;

/// True when answer_next_collision answers, for `discs` discs, from the collisions `hits` its
/// copy resolved: one at least, and a second candidate (a later collision or a near miss; which
/// ones the picture prefers changes what is offered, never whether one is).
bool next_collision_askable(const std::vector<CollisionRecord>& hits, std::size_t discs) {
    if (hits.empty()) return false;
    return has_later_contact(hits) || has_near_miss(discs, hits, {hits.front()});
}

/// The time of simulation frame j on `clock`, past its last frame too (one interval a frame):
/// the calls the video makes, so that a copy run to them resolves the same bits.
double frame_time(const FrameClock& clock, std::int64_t j) {
    const std::int64_t count = clock.count;
    return j < count ? clock.time(j)
                     : clock.time(count - 1) + static_cast<double>(j - count + 1) * clock.interval;
}

std::string disc_words(const CollisionRecord& r) {
    if (r.kind == CollisionKind::pair)
        return fmt::format("discs {} and {}", std::min(r.a, r.b), std::max(r.a, r.b));
    return fmt::format("disc {} and the wall", r.a);
}

/// Each candidate disc's velocity as an arrow that ends at its leading edge (motion_arrow), over
/// one time for all (arrow_seconds), in the motion colour, no candidate's: the class compares the
/// gaps with the arrows (which disc heads for which, how fast) and never reads an arrow as a
/// candidate's line. In the reveal the answer's discs keep theirs, the others fade.
void add_motion_arrows(ReplayView& view, const QuestionAnswer& answer, const Snapshot& snapshot,
                       bool reveal) {
    std::vector<std::pair<std::uint32_t, bool>> discs;  // (disc, one of the answer's)
    for (std::size_t i = 0; i < answer.candidates.size(); ++i) {
        for (const std::uint32_t k : discs_of(answer.candidates[i])) {
            const bool right = i == answer.answer;
            const auto found = std::find_if(discs.begin(), discs.end(),
                                            [k](const auto& d) { return d.first == k; });
            if (found == discs.end()) {
                if (k < snapshot.discs.size()) discs.emplace_back(k, right);
            } else {
                found->second = found->second || right;
            }
        }
    }
    const double seconds = arrow_seconds(answer.candidates, snapshot);
    for (const auto& [k, right] : discs) {
        std::optional<BoxLine> arrow = motion_arrow(snapshot.discs[k], seconds);
        if (!arrow) continue;
        arrow->opacity = reveal && !right ? 0.3F : 1.0F;
        view.lines.push_back(*arrow);
    }
}

/// clear_spot's search, keeping `plate` from the discs and `taken` and, with `lines`, from those
/// too; `found`: whether the point returned keeps that far.
Vec2 clear_spot_among(Vec2 near, double plate, const Snapshot& snapshot,
                      const std::vector<Vec2>& taken, const std::vector<BoxLine>& lines,
                      bool& found) {
    const Box& box = snapshot.box;
    found = false;
    const auto clearance = [&](Vec2 p) {
        double free = std::numeric_limits<double>::infinity();
        for (const DiscState& d : snapshot.discs)
            free = std::min(free, norm(p - d.position) - d.radius);
        for (const Vec2& t : taken) free = std::min(free, norm(p - t) - plate);
        for (const BoxLine& l : lines)
            free = std::min(free, point_segment_distance(p, l.from, l.to));
        return free;
    };
    const auto inside = [&](Vec2 p) {
        return p.x >= plate && p.x <= box.width - plate && p.y >= plate &&
               p.y <= box.height - plate;
    };
    Vec2 best = near;
    double best_free = -std::numeric_limits<double>::infinity();
    constexpr int rings = 12;
    constexpr int around = 16;
    for (int ring = 0; ring <= rings; ++ring) {
        const double r = 0.5 * plate * ring;
        for (int k = 0; k < (ring == 0 ? 1 : around); ++k) {
            const double angle = 2.0 * std::numbers::pi * k / around;
            const Vec2 p{near.x + r * std::cos(angle), near.y + r * std::sin(angle)};
            if (!inside(p)) continue;
            const double free = clearance(p);
            if (free >= plate) {
                found = true;
                return p;
            }
            if (free > best_free) {
                best_free = free;
                best = p;
            }
        }
    }
    return best;
}

}  // namespace

bool needs_event_panel(QuestionKind kind) noexcept {
    switch (kind) {
        case QuestionKind::next_collision:
        case QuestionKind::how_many:
            return true;
        case QuestionKind::will_see:
            return false;
    }
    return true;
}

bool needs_time_panel(QuestionKind kind) noexcept {
    return kind == QuestionKind::will_see;
}

double reveal_seconds_of(QuestionKind kind) noexcept {
    return kind == QuestionKind::will_see ? replay_seconds : reveal_seconds;
}

QuestionAnswer answer_will_see(const ReplayFailure& failure, std::int64_t sim_frame, double time) {
    QuestionAnswer out;
    out.kind = QuestionKind::will_see;
    out.sim_frame = sim_frame;
    out.time = time;
    // The frozen frame shows the state before the failing step; the next frame is its check.
    if (failure.sim_frame != sim_frame + 1 || failure.check_before() > time) return out;
    out.failure = failure;
    out.askable = true;
    return out;
}

QuestionAnswer answer_next_collision(const Engine& engine, const Snapshot& snapshot,
                                     const FramesAfter& after, int fps, std::uint64_t seed) {
    QuestionAnswer out;
    out.kind = QuestionKind::next_collision;
    out.time = snapshot.time;
    if (snapshot.dimension != 2) return out;
    const Ahead ahead = run_copy(engine, after, look_ahead_frames, next_collision_hits);
    if (ahead.hits.empty()) return out;
    const TellApart rule = tell_apart(ahead.hits.front(), snapshot, after, fps);
    const std::vector<CollisionRecord> chosen = offered_collisions(ahead.hits, snapshot, rule);
    if (chosen.size() < min_candidates) return out;
    // Fisher-Yates by the seed: which letter the answer gets.
    std::vector<std::size_t> order(chosen.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::uint64_t state = seed;
    for (std::size_t i = order.size() - 1; i > 0; --i)
        std::swap(order[i], order[static_cast<std::size_t>(mix(state) % (i + 1))]);
    for (std::size_t i = 0; i < order.size(); ++i) {
        out.candidates.push_back(chosen[order[i]]);
        if (order[i] == 0) out.answer = i;
    }
    out.askable = true;
    return out;
}

QuestionAnswer answer_how_many(const Engine& engine, const FramesAfter& after, int fps) {
    QuestionAnswer out;
    out.kind = QuestionKind::how_many;
    out.time = engine.time();
    const Ahead ahead = run_copy(engine, after, std::max(1, fps), 0);
    if (!ahead.copied) return out;
    for (const CollisionRecord& hit : ahead.hits)
        ++(hit.kind == CollisionKind::pair ? out.pairs : out.walls);
    out.askable = true;
    return out;
}

std::string question_place(const QuestionCue& cue) {
    if (cue.file.empty()) return "the scene";
    return cue.file + ":" + std::to_string(cue.line);
}

std::string candidate_letter(std::size_t i) {
    return std::string(1, static_cast<char>('A' + static_cast<int>(i % 26)));
}

std::string question_words(const QuestionAnswer& answer, const std::string& authored) {
    if (!authored.empty()) return authored;
    switch (answer.kind) {
        case QuestionKind::next_collision: {
            std::string letters;
            for (std::size_t i = 0; i < answer.candidates.size(); ++i) {
                if (i > 0) letters += i + 1 == answer.candidates.size() ? " or " : ", ";
                letters += candidate_letter(i);
            }
            return "Pause and think: which collides first, " + letters + "?";
        }
        case QuestionKind::how_many:
            return "Pause and think: how many collisions in the next second?";
        case QuestionKind::will_see:
            return answer.failure && answer.failure->step.kind == sim::StepFailureKind::left_box
                       ? "Pause and think: will the next check see this wall hit?"
                       : "Pause and think: will the next check see this collision?";
    }
    return {};
}

std::string answer_words(const QuestionAnswer& answer, const FrameClock& clock) {
    switch (answer.kind) {
        case QuestionKind::next_collision: {
            if (answer.answer >= answer.candidates.size()) return {};
            const CollisionRecord& hit = answer.candidates[answer.answer];
            return fmt::format("Answer: {}, {} ({})", candidate_letter(answer.answer),
                               disc_words(hit),
                               next_collision_words(hit.t - answer.time, clock, true));
        }
        case QuestionKind::how_many: {
            const std::int64_t n = answer.count();
            if (n == 0) return "Answer: none in the next second";
            std::string out = fmt::format("Answer: {} collision{}", n, n == 1 ? "" : "s");
            if (answer.pairs > 0 && answer.walls > 0)
                out +=
                    fmt::format(" ({} between discs, {} with walls)", answer.pairs, answer.walls);
            return out;
        }
        case QuestionKind::will_see: {
            if (!answer.failure) return {};
            // The engine's record says the check after the step saw no overlap.
            return answer.failure->step.kind == sim::StepFailureKind::left_box
                       ? "Answer: no, the disc jumps through the wall unseen"
                       : "Answer: no, the discs pass through each other unseen";
        }
    }
    return {};
}

Vec2 clear_spot(Vec2 near, double plate, const Snapshot& snapshot, const std::vector<Vec2>& taken,
                const std::vector<BoxLine>& lines) {
    bool found = false;
    if (!lines.empty()) {
        const Vec2 off_lines = clear_spot_among(near, plate, snapshot, taken, lines, found);
        if (found) return off_lines;
    }
    // No place off the lines: off the discs and letters still (a letter never hides a disc).
    return clear_spot_among(near, plate, snapshot, taken, {}, found);
}

std::string countdown_words(double seconds_left) {
    return fmt::format("Think: {}", std::max(1, static_cast<int>(std::ceil(seconds_left - 1e-9))));
}

ReplayView will_see_view(const QuestionAnswer& answer, double seconds_left) {
    ReplayView view;
    if (!answer.askable || !answer.failure) return view;
    const sim::StepFailure& f = answer.failure->step;
    view.heading = countdown_words(seconds_left);
    // Each disc's straight move over the step the check follows: where it will be then.
    view.lines.push_back(BoxLine{f.before_a, f.before_a + f.motion_a});
    view.focus.push_back(f.a);
    if (f.kind == sim::StepFailureKind::missed_pair) {
        if (norm(f.motion_b) > 0.0)
            view.lines.push_back(BoxLine{f.before_b, f.before_b + f.motion_b});
        view.focus.push_back(f.b);
    }
    return view;
}

ReplayView question_view(const QuestionAnswer& answer, const Snapshot& snapshot,
                         const FrameClock& clock, double seconds_left, bool reveal) {
    ReplayView view;
    // A will-see question is the time-driven panel's (will_see_view, then the replay).
    if (!answer.askable || answer.kind == QuestionKind::will_see) return view;
    if (reveal) {
        view.heading = answer.kind == QuestionKind::next_collision
                           ? "Answer: " + candidate_letter(answer.answer)
                           : fmt::format("Answer: {}", answer.count());
    } else {
        view.heading = countdown_words(seconds_left);
    }
    // The heading keeps clear of every disc (the painter measures its words and finds the place):
    // the class must see them all while it thinks.
    view.keep_clear.reserve(snapshot.discs.size());
    for (const DiscState& d : snapshot.discs) view.keep_clear.push_back({d.position, d.radius});
    if (answer.kind != QuestionKind::next_collision) return view;
    // The letter's plate, in box units: about the lesson's text size where a box fills most of
    // the frame's height (a letter 2.8 % of it on a plate of about twice that).
    const double plate = 0.05 * std::min(snapshot.box.width, snapshot.box.height);
    // Every line first (connectors, then the arrows), so that each letter keeps off the lines of
    // the others where it can. A candidate's connector, leader and letter share its tint: a
    // class tells the candidates apart by colour as well as by letter where they sit close.
    std::vector<std::size_t> connectors_of;  // each candidate's first connector in view.lines
    for (std::size_t i = 0; i < answer.candidates.size(); ++i) {
        connectors_of.push_back(view.lines.size());
        const bool right = i == answer.answer;
        for (BoxLine line : connector_lines(answer.candidates[i], snapshot)) {
            line.tint = static_cast<int>(i);
            line.failure = reveal && right;
            line.opacity = reveal && !right ? 0.3F : 1.0F;
            view.lines.push_back(line);
        }
    }
    connectors_of.push_back(view.lines.size());
    add_motion_arrows(view, answer, snapshot, reveal);
    const std::vector<BoxLine> drawn = view.lines;
    std::vector<Vec2> taken;
    for (std::size_t i = 0; i < answer.candidates.size(); ++i) {
        const CollisionRecord& c = answer.candidates[i];
        CollisionRecord shown = c;
        if (!std::isfinite(shown.t)) shown.t = snapshot.time;
        const NextCollisionView seen = next_collision_view(shown, snapshot, clock);
        if (seen.lines.empty()) continue;
        const bool right = i == answer.answer;
        const float opacity = reveal && !right ? 0.3F : 1.0F;
        // The lines a letter keeps off: all but its own connector (it names that one).
        std::vector<BoxLine> others;
        for (std::size_t k = 0; k < drawn.size(); ++k) {
            if (k < connectors_of[i] || k >= connectors_of[i + 1]) others.push_back(drawn[k]);
        }
        const Vec2 at = clear_spot(seen.label_at, plate, snapshot, taken, others);
        taken.push_back(at);
        BoxLabel label;
        label.at = at;
        label.text = candidate_letter(i);
        label.side = LabelSide::over;
        label.failure = reveal && right;
        label.opacity = opacity;
        label.tint = static_cast<int>(i);
        view.labels.push_back(label);
        if (norm(at - seen.label_at) > plate) {
            // A letter moved away from its line: a faint leader back to it.
            BoxLine leader{at, seen.label_at};
            leader.style = LineStyle::connector;
            leader.tint = static_cast<int>(i);
            leader.failure = reveal && right;
            leader.opacity = 0.5F * opacity;
            view.lines.push_back(leader);
        }
        view.focus.push_back(c.a);
        if (c.kind == CollisionKind::pair) view.focus.push_back(c.b);
    }
    return view;
}

std::vector<QuestionAnswer> answer_questions(const Scene& scene, const EngineOptions& options,
                                             const FrameClock& clock, const Timeline& timeline,
                                             const std::vector<QuestionKind>& kinds,
                                             const std::atomic<bool>* stop) {
    std::vector<QuestionAnswer> out(kinds.size());
    for (std::size_t i = 0; i < kinds.size(); ++i) out[i].kind = kinds[i];
    std::vector<std::pair<std::int64_t, int>> asked;  // (simulation frame, question)
    for (const Segment& segment : timeline.segments) {
        if (segment.kind == SegmentKind::question && segment.question >= 0 &&
            static_cast<std::size_t>(segment.question) < kinds.size())
            asked.emplace_back(segment.sim_frame, segment.question);
    }
    if (asked.empty()) return out;
    EngineOptions copy = options;
    copy.stop = stop;
    const std::unique_ptr<Engine> engine = make_engine(scene, copy);
    // The video's calls: frame by frame on the clock (the same times, so the same bits).
    std::int64_t at = -1;
    for (const auto& [frame, question] : asked) {
        while (at < frame) {
            ++at;
            engine->advance_to(std::max(frame_time(clock, at), engine->time()));
        }
        const FramesAfter after = [&clock, f = frame](std::int64_t i) {
            return frame_time(clock, f + i);
        };
        const auto q = static_cast<std::size_t>(question);
        if (kinds[q] == QuestionKind::will_see) continue;  // the time-driven engine's
        if (kinds[q] == QuestionKind::next_collision) {
            const std::uint64_t seed = 0x51ED5EEDULL ^ (static_cast<std::uint64_t>(frame) << 8U) ^
                                       static_cast<std::uint64_t>(question);
            out[q] = answer_next_collision(*engine, engine->snapshot(), after, timeline.fps, seed);
        } else {
            out[q] = answer_how_many(*engine, after, timeline.fps);
        }
        out[q].sim_frame = frame;
    }
    return out;
}

std::optional<std::int64_t> next_askable_frame(const Scene& scene, const EngineOptions& options,
                                               const FrameClock& clock, std::int64_t frozen,
                                               std::int64_t last, const std::atomic<bool>* stop) {
    if (last <= frozen) return std::nullopt;
    EngineOptions copy = options;
    copy.stop = stop;
    // One engine, run ahead of the frame g being tried by up to look_ahead_frames, frame by frame
    // as the video runs it: the collisions it resolves on frames g+1, g+2, ... are those a copy
    // asked at g would resolve (the same calls, so the same bits), and each g reads them off.
    const std::unique_ptr<Engine> scout = make_engine(scene, copy);
    std::deque<std::pair<std::int64_t, CollisionRecord>> ahead;  // (the frame it ends on, hit)
    std::int64_t scouted = 0;
    scout->advance_to(std::max(frame_time(clock, 0), scout->time()));
    scout->set_collision_listener(
        [&ahead, &scouted](const CollisionRecord& hit) { ahead.emplace_back(scouted, hit); });
    std::optional<std::int64_t> found;
    std::vector<CollisionRecord> hits;
    for (std::int64_t g = frozen + 1; g <= last && !found; ++g) {
        while (!ahead.empty() && ahead.front().first <= g) ahead.pop_front();
        // As run_copy stops: after the frame on which the collisions reach enough, else after
        // look_ahead_frames frames.
        hits.clear();
        for (std::int64_t i = 1; i <= look_ahead_frames; ++i) {
            while (scouted < g + i) {
                ++scouted;
                scout->advance_to(std::max(frame_time(clock, scouted), scout->time()));
            }
            for (std::size_t h = hits.size(); h < ahead.size() && ahead[h].first == g + i; ++h)
                hits.push_back(ahead[h].second);
            if (hits.size() >= next_collision_hits) break;
        }
        if (next_collision_askable(hits, scene.discs.size())) found = g;
    }
    scout->set_collision_listener(nullptr);
    return found;
}

}  // namespace collide::show
