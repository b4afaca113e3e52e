#pragma once
// What each candidate of a next-collision question draws, read back from the question's picture
// (question_view): its discs, its connectors (the lines in its tint) and its discs' velocity
// arrows; and how close two candidates' drawings come. The show tests and the plan tests (the
// built-in scenes) check with it that the candidates' drawings do not cross.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "collide/show/questions.hpp"

namespace collide::test {

/// A segment thickened by `radius` (a disc: a point and its radius).
struct Piece {
    Vec2 from;
    Vec2 to;
    double radius = 0.0;
};

inline double point_to_segment(Vec2 p, Vec2 a, Vec2 b) {
    const Vec2 d = b - a;
    const double length2 = d.x * d.x + d.y * d.y;
    double t = 0.0;
    if (length2 > 0.0) t = std::clamp(((p.x - a.x) * d.x + (p.y - a.y) * d.y) / length2, 0.0, 1.0);
    return norm(p - (a + d * t));
}

/// 0 where the segments cross, else the least distance of an end to the other segment.
inline double segments_apart(const Piece& x, const Piece& y) {
    const auto side = [](Vec2 o, Vec2 a, Vec2 b) {
        return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    const double s1 = side(y.from, y.to, x.from);
    const double s2 = side(y.from, y.to, x.to);
    const double s3 = side(x.from, x.to, y.from);
    const double s4 = side(x.from, x.to, y.to);
    if (s1 * s2 < 0.0 && s3 * s4 < 0.0) return 0.0;
    return std::min({point_to_segment(x.from, y.from, y.to), point_to_segment(x.to, y.from, y.to),
                     point_to_segment(y.from, x.from, x.to), point_to_segment(y.to, x.from, x.to)});
}

/// The discs of candidate `c`.
inline std::vector<std::uint32_t> candidate_discs_of(const CollisionRecord& c) {
    if (c.kind == CollisionKind::pair) return {c.a, c.b};
    return {c.a};
}

/// Candidate i's drawing in `view` (the question's picture, not the reveal): its discs, its
/// connectors at full opacity (a faint leader to a letter moved away is the letter's, not the
/// contact's), and the velocity arrows that end at its discs' leading edges.
inline std::vector<Piece> candidate_drawing(const show::QuestionAnswer& answer, std::size_t i,
                                            const ReplayView& view, const Snapshot& now) {
    std::vector<Piece> out;
    for (const std::uint32_t k : candidate_discs_of(answer.candidates[i])) {
        const DiscState& d = now.discs[k];
        out.push_back({d.position, d.position, d.radius});
        if (!(norm(d.velocity) > 0.0)) continue;
        const Vec2 edge = d.position + d.velocity * (d.radius / norm(d.velocity));
        for (const BoxLine& line : view.lines) {
            if (line.style == LineStyle::motion && norm(line.to - edge) < 1e-12)
                out.push_back({line.from, line.to});
        }
    }
    for (const BoxLine& line : view.lines) {
        if (line.style == LineStyle::connector && line.tint == static_cast<int>(i) &&
            line.opacity == 1.0F)
            out.push_back({line.from, line.to});
    }
    return out;
}

/// How close the drawings of two different candidates come (edge to edge; 0 where they cross or
/// overlap), over every pair of candidates.
inline double closest_candidates(const show::QuestionAnswer& answer, const ReplayView& view,
                                 const Snapshot& now) {
    double closest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < answer.candidates.size(); ++i) {
        const std::vector<Piece> x = candidate_drawing(answer, i, view, now);
        for (std::size_t j = i + 1; j < answer.candidates.size(); ++j) {
            for (const Piece& p : x) {
                for (const Piece& q : candidate_drawing(answer, j, view, now))
                    closest = std::min(closest,
                                       std::max(0.0, segments_apart(p, q) - p.radius - q.radius));
            }
        }
    }
    return closest;
}

}  // namespace collide::test
