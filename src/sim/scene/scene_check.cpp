// Scene validation: cheap per-disc checks first, then the O(N) grid search for overlaps.

#include "collide/sim/scene_check.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <sstream>

#include "collide/error.hpp"
#include "scene/disc_grid.hpp"

namespace collide {

namespace {

std::string format_number(double v) {
    std::ostringstream s;
    s.precision(6);
    s << v;
    return s.str();
}

std::string point_text(Vec2 p) {
    // One stream rather than "(" + ...: GCC 12 -O3 warns falsely (-Wrestrict) on the latter.
    std::ostringstream s;
    s.precision(6);
    s << '(' << p.x << ", " << p.y << ')';
    return s.str();
}

// "file:line: field" without a reason (the prefix of a message).
std::string location_text(const SourceLocation& where) {
    std::string s = where.file;
    if (where.line > 0) s += (s.empty() ? "line " : ":") + std::to_string(where.line);
    if (!where.field.empty()) s += (s.empty() ? "" : ": ") + where.field;
    return s;
}

[[noreturn]] void fail_at(const SourceLocation& where, const std::string& field_suffix,
                          const std::string& reason) {
    std::string field = where.field;
    if (!field_suffix.empty()) field += (field.empty() ? "" : " ") + field_suffix;
    throw_scene_error(where.file, where.line, field, reason);
}

// "1e+200 is outside ..." for a value beyond the range the engines compute with.
std::string out_of_range_reason(double value, bool with_lower_bound) {
    // One stream rather than "[" + ...: GCC 12 -O3 warns falsely (-Wrestrict) on the latter.
    std::ostringstream s;
    s.precision(6);
    s << value << " is outside the range collide computes with (";
    if (with_lower_bound) {
        s << '[' << min_scene_magnitude << ", " << max_scene_magnitude << ']';
    } else {
        s << "at most " << max_scene_magnitude;
    }
    s << "): beyond it the collision formulas overflow or underflow";
    return s.str();
}

bool below_max(double magnitude) noexcept {
    return magnitude <= max_scene_magnitude;
}

bool components_below_max(Vec2 v) noexcept {
    return below_max(std::abs(v.x)) && below_max(std::abs(v.y));
}

bool in_range(double positive) noexcept {
    return positive >= min_scene_magnitude && positive <= max_scene_magnitude;
}

void check_box(const Box& box) {
    if (!(box.width > 0.0) || !std::isfinite(box.width)) {
        throw_scene_error("", 0, "box.width",
                          "must be a finite number > 0 (got " + format_number(box.width) + ")");
    }
    if (!(box.height > 0.0) || !std::isfinite(box.height)) {
        throw_scene_error("", 0, "box.height",
                          "must be a finite number > 0 (got " + format_number(box.height) + ")");
    }
    if (box.width > max_scene_magnitude)
        throw_scene_error("", 0, "box.width", out_of_range_reason(box.width, false));
    if (box.height > max_scene_magnitude)
        throw_scene_error("", 0, "box.height", out_of_range_reason(box.height, false));
}

bool finite(Vec2 v) noexcept {
    return std::isfinite(v.x) && std::isfinite(v.y);
}

void check_disc_values(const Disc& d, const SourceLocation& where) {
    if (!finite(d.position))
        fail_at(where, "position", "not a finite number " + point_text(d.position));
    if (!finite(d.velocity))
        fail_at(where, "velocity", "not a finite number " + point_text(d.velocity));
    if (!std::isfinite(d.radius))
        fail_at(where, "radius", "not a finite number (" + format_number(d.radius) + ")");
    if (!(d.radius > 0.0))
        fail_at(where, "radius", "must be > 0 (got " + format_number(d.radius) + ")");
    if (!std::isfinite(d.mass))
        fail_at(where, "mass", "not a finite number (" + format_number(d.mass) + ")");
    if (!(d.mass > 0.0)) fail_at(where, "mass", "must be > 0 (got " + format_number(d.mass) + ")");
    const auto check_components = [&](Vec2 v, const char* field) {
        for (const double c : {v.x, v.y})
            if (!below_max(std::abs(c))) fail_at(where, field, out_of_range_reason(c, false));
    };
    check_components(d.position, "position");
    check_components(d.velocity, "velocity");
    if (!in_range(d.radius)) fail_at(where, "radius", out_of_range_reason(d.radius, true));
    if (!in_range(d.mass)) fail_at(where, "mass", out_of_range_reason(d.mass, true));
}

// The checks of check_disc_values, as one test (no strings built for the good discs).
bool disc_values_ok(const Disc& d) noexcept {
    return finite(d.position) && finite(d.velocity) && components_below_max(d.position) &&
           components_below_max(d.velocity) && in_range(d.radius) && in_range(d.mass);
}

// How far a walled box is exceeded, as text ("right edge at 1.01 > width 1"), or empty.
std::string outside_reason(const Box& box, const Disc& d) {
    const Vec2 p = d.position;
    const double r = d.radius;
    const double slack = contact_tolerance * r;
    if (p.x - r < -slack) return "left edge at x = " + format_number(p.x - r) + " < 0";
    if (p.x + r > box.width + slack)
        return "right edge at x = " + format_number(p.x + r) + " > " + format_number(box.width);
    if (p.y - r < -slack) return "bottom edge at y = " + format_number(p.y - r) + " < 0";
    if (p.y + r > box.height + slack)
        return "top edge at y = " + format_number(p.y + r) + " > " + format_number(box.height);
    return {};
}

// Lists every disc outside a walled box (up to max_listed_problems) in one message.
void check_inside_box(const Scene& scene, const SceneOrigin& origin) {
    if (scene.box.boundary == Boundary::periodic) return;
    std::vector<std::string> problems;
    std::size_t total = 0;
    for (std::size_t i = 0; i < scene.discs.size(); ++i) {
        const std::string why = outside_reason(scene.box, scene.discs[i]);
        if (why.empty()) continue;
        if (++total <= max_listed_problems) {
            problems.push_back(location_text(origin.locate(i)) + ": centre " +
                               point_text(scene.discs[i].position) + ", radius " +
                               format_number(scene.discs[i].radius) + ": " + why);
        }
    }
    if (total == 0) return;
    std::string msg = std::to_string(total) + (total == 1 ? " disc lies" : " discs lie") +
                      " outside the box [0, " + format_number(scene.box.width) + "] x [0, " +
                      format_number(scene.box.height) + "]: ";
    for (std::size_t k = 0; k < problems.size(); ++k) msg += (k ? "; " : "") + problems[k];
    if (total > problems.size())
        msg += "; and " + std::to_string(total - problems.size()) + " more";
    throw_input_error(msg);
}

void check_periodic_sizes(const Scene& scene, const SceneOrigin& origin) {
    if (scene.box.boundary != Boundary::periodic) return;
    // Minimum-image distances are only right when no pair of discs can touch around the box
    // both ways, i.e. r_i + r_j <= half the shorter side.
    const double limit = std::min(scene.box.width, scene.box.height) / 4.0;
    for (std::size_t i = 0; i < scene.discs.size(); ++i) {
        if (scene.discs[i].radius > limit) {
            fail_at(origin.locate(i), "radius",
                    "too large for the periodic box (" + format_number(scene.discs[i].radius) +
                        " > min(width, height) / 4 = " + format_number(limit) + ")");
        }
    }
}

// A cell size that keeps the grid's filing cost O(N): twice the median radius, doubled while
// the big discs would be filed in too many cells.
double overlap_cell_size(const Scene& scene) {
    std::vector<double> radii;
    radii.reserve(scene.discs.size());
    for (const Disc& d : scene.discs) radii.push_back(d.radius);
    auto mid = radii.begin() + static_cast<std::ptrdiff_t>(radii.size() / 2);
    std::nth_element(radii.begin(), mid, radii.end());
    double cell = 2.0 * *mid;
    const double budget = 16.0 * static_cast<double>(radii.size()) + 64.0;
    for (;;) {
        double filings = 0.0;
        for (double r : radii) filings += std::pow(2.0 * r / cell + 2.0, 2.0);
        if (filings <= budget) return cell;
        cell *= 2.0;
    }
}

bool overlapping(const Box& box, const Disc& a, const Disc& b) noexcept {
    const double sum = a.radius + b.radius;
    const double limit = sum * (1.0 - contact_tolerance);
    return norm2(box.displacement(a.position, b.position)) < limit * limit;
}

[[noreturn]] void fail_overlap(const Scene& scene, const SceneOrigin& origin, std::size_t i,
                               std::size_t other) {
    const Disc& d = scene.discs[i];
    const Disc& e = scene.discs[other];
    const double gap = norm(scene.box.displacement(e.position, d.position)) - e.radius - d.radius;
    throw_input_error(location_text(origin.locate(i)) + ": overlaps " +
                      location_text(origin.locate(other)) + " at t = 0 (centres " +
                      point_text(e.position) + " and " + point_text(d.position) +
                      ", overlap depth " + format_number(-gap) + ")");
}

// --- Jams: discs that cannot move along an axis but are given a velocity along it.

/// A bend in a row of touching discs by an offset delta across the row shortens it by about
/// delta^2 / sigma per contact; below sqrt(contact_tolerance) sigma that is under the contact
/// tolerance, so such a row is as straight as "touching" can tell.
const double row_alignment = std::sqrt(contact_tolerance);

/// Union-find over discs: the straight rows of touching discs along one axis.
class Rows {
  public:
    explicit Rows(std::size_t n) : parent_(n) {
        for (std::size_t i = 0; i < n; ++i) parent_[i] = static_cast<std::uint32_t>(i);
    }
    std::uint32_t find(std::uint32_t i) {
        while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
        return i;
    }
    /// Joins the rows of a and b; false when they were one row already (the row closes a ring).
    bool unite(std::uint32_t a, std::uint32_t b) {
        a = find(a);
        b = find(b);
        if (a == b) return false;
        parent_[std::max(a, b)] = std::min(a, b);  // the root is the row's first disc
        return true;
    }

  private:
    std::vector<std::uint32_t> parent_;
};

enum RowFlag : std::uint8_t { low_wall = 1, high_wall = 2, ring = 4 };

struct AxisRows {
    Rows rows;
    std::vector<std::uint8_t> flags;  ///< RowFlag bits, per disc, then gathered on each root
    explicit AxisRows(std::size_t n) : rows(n), flags(n, 0) {}
};

double along(Vec2 v, int axis) noexcept {
    return axis == 0 ? v.x : v.y;
}
double across(Vec2 v, int axis) noexcept {
    return axis == 0 ? v.y : v.x;
}

// Joins i and j in the rows of each axis their contact lies along (a periodic pair touching both
// ways around the box is a ring of two).
void join_contact(const Box& box, std::uint32_t i, std::uint32_t j, Vec2 d, double sigma,
                  std::array<AxisRows, 2>& axes) {
    for (int axis = 0; axis < 2; ++axis) {
        if (std::abs(across(d, axis)) > row_alignment * sigma) continue;
        AxisRows& a = axes[static_cast<std::size_t>(axis)];
        const double period = axis == 0 ? box.width : box.height;
        const bool both_ways =
            box.boundary == Boundary::periodic &&
            period - std::abs(along(d, axis)) <= sigma * (1.0 + contact_tolerance);
        if (!a.rows.unite(i, j) || both_ways) a.flags[i] |= ring;
    }
}

// Marks the walls disc d touches, per axis.
void flag_walls(const Box& box, const Disc& d, std::uint32_t i, std::array<AxisRows, 2>& axes) {
    if (box.boundary == Boundary::periodic) return;
    const double slack = contact_tolerance * d.radius;
    for (int axis = 0; axis < 2; ++axis) {
        const double p = along(d.position, axis);
        const double extent = axis == 0 ? box.width : box.height;
        std::uint8_t& f = axes[static_cast<std::size_t>(axis)].flags[i];
        if (p - d.radius <= slack) f |= low_wall;
        if (p + d.radius >= extent - slack) f |= high_wall;
    }
}

// Why disc i of a jammed row may not have its velocity, or empty when it may.
std::string jam_reason(const Scene& scene, const SceneOrigin& origin, int axis, std::uint32_t i,
                       std::uint32_t root, std::uint8_t flags, std::size_t row_size) {
    const char* name = axis == 0 ? "x" : "y";
    const double v = along(scene.discs[i].velocity, axis);
    const double extent = axis == 0 ? scene.box.width : scene.box.height;
    if ((flags & low_wall) && (flags & high_wall)) {
        if (v == 0.0) return {};
        std::string why = "moves along " + std::string(name) + " (" + format_number(v) + "), but ";
        if (row_size == 1) {
            why += "the disc is as wide as the box (diameter " +
                   format_number(2.0 * scene.discs[i].radius) + ", " +
                   (axis == 0 ? "width " : "height ") + format_number(extent) + ")";
        } else {
            why += "it is wedged between the walls " + std::string(name) + " = 0 and " + name +
                   " = " + format_number(extent) + " in a straight row of " +
                   std::to_string(row_size) + " touching discs" +
                   (root == i ? "" : " (the first is " + location_text(origin.locate(root)) + ")");
        }
        return why + ": it cannot move along " + name +
               ", and an event-driven simulation would collide forever at t = 0. Give it no " +
               name + " velocity, or leave a gap";
    }
    if (!(flags & ring)) return {};
    const double v_root = along(scene.discs[root].velocity, axis);
    if (v == v_root) return {};
    return "moves along " + std::string(name) + " at " + format_number(v) + ", unlike " +
           location_text(origin.locate(root)) + " (" + format_number(v_root) +
           "), in a straight ring of " + std::to_string(row_size) +
           " touching discs around the periodic box: such a ring can only move along " + name +
           " as a whole, and an event-driven simulation would collide forever at t = 0";
}

// One pass of the O(N) grid over the discs in scene order, each against those before it: refuses
// the first disc that overlaps an earlier one, and collects the straight rows of touching discs.
// Then refuses a disc in a straight row from wall to wall (or around a periodic box) that moves
// along the row: the row cannot move, and the engines would collide at t = 0 forever. Rows, not
// general jams: the engines catch the rest (sim::instant_collision_limit).
void check_contacts(const Scene& scene, const SceneOrigin& origin) {
    const std::size_t n = scene.discs.size();
    if (n == 0) return;
    if (n >= std::numeric_limits<std::uint32_t>::max())
        throw_input_error("too many discs (" + std::to_string(n) + ")");
    std::array<AxisRows, 2> axes{AxisRows(n), AxisRows(n)};
    double max_radius = 0.0;
    for (const Disc& d : scene.discs) max_radius = std::max(max_radius, d.radius);
    detail::DiscGrid grid(scene.box, overlap_cell_size(scene), 4 * n + 64);
    std::vector<std::uint32_t> seen(n, std::numeric_limits<std::uint32_t>::max());
    for (std::uint32_t i = 0; i < n; ++i) {
        const Disc& d = scene.discs[i];
        const Vec2 p = scene.box.wrap(d.position);
        // Widened so that discs touching within the tolerance share a cell.
        const double reach = d.radius + 2.0 * contact_tolerance * (d.radius + max_radius);
        std::uint32_t other = 0;
        const bool overlap = grid.any_near(p, reach, [&](std::uint32_t j) {
            if (seen[j] == i) return false;  // filed in several cells
            seen[j] = i;
            other = j;
            const Disc& e = scene.discs[j];
            if (overlapping(scene.box, e, d)) return true;
            const Vec2 dr = scene.box.displacement(e.position, d.position);
            const double sigma = d.radius + e.radius;
            const double touch = sigma * (1.0 + contact_tolerance);
            if (norm2(dr) <= touch * touch) join_contact(scene.box, i, j, dr, sigma, axes);
            return false;
        });
        if (overlap) fail_overlap(scene, origin, i, other);
        grid.insert(i, p, d.radius);
        flag_walls(scene.box, d, i, axes);
    }
    for (int axis = 0; axis < 2; ++axis) {
        AxisRows& a = axes[static_cast<std::size_t>(axis)];
        std::vector<std::uint32_t> size(n, 0);
        for (std::uint32_t i = 0; i < n; ++i) {
            const std::uint32_t root = a.rows.find(i);
            a.flags[root] |= a.flags[i];
            ++size[root];
        }
        for (std::uint32_t i = 0; i < n; ++i) {
            const std::uint32_t root = a.rows.find(i);
            const std::string why =
                jam_reason(scene, origin, axis, i, root, a.flags[root], size[root]);
            if (!why.empty()) fail_at(origin.locate(i), "velocity", why);
        }
    }
}

}  // namespace

SourceLocation SceneOrigin::locate(std::size_t index) const {
    auto it = std::upper_bound(runs_.begin(), runs_.end(), index,
                               [](std::size_t i, const DiscSource& run) { return i < run.first; });
    if (it == runs_.begin() || index >= std::prev(it)->first + std::prev(it)->count) {
        return {"", 0, "disc " + std::to_string(index + 1)};
    }
    const DiscSource& run = *std::prev(it);
    const std::size_t k = index - run.first;
    if (!run.lines.empty()) {
        const std::string name = run.field.empty() ? "disc" : run.field;
        return {run.file, run.lines[k], name + " " + std::to_string(k + 1)};
    }
    if (run.count == 1) return {run.file, run.line, run.field};  // a [[disc]] table
    return {run.file, run.line, run.field + " disc " + std::to_string(k + 1)};
}

void validate_scene(const Scene& scene, const SceneOrigin& origin) {
    check_box(scene.box);
    for (std::size_t i = 0; i < scene.discs.size(); ++i) {
        // Only build a location (strings) when something is wrong.
        const Disc& d = scene.discs[i];
        if (disc_values_ok(d)) continue;
        check_disc_values(d, origin.locate(i));
    }
    check_inside_box(scene, origin);
    check_periodic_sizes(scene, origin);
    check_contacts(scene, origin);
}

double packing_fraction(const Scene& scene) noexcept {
    double area = 0.0;
    for (const Disc& d : scene.discs) area += std::numbers::pi * d.radius * d.radius;
    return area / scene.box.area();
}

double kinetic_energy(const Scene& scene) noexcept {
    double e = 0.0;
    for (const Disc& d : scene.discs) e += 0.5 * d.mass * norm2(d.velocity);
    return e;
}

std::string scene_summary(const Scene& scene) {
    std::ostringstream s;
    s.precision(4);
    s << "N = " << scene.discs.size() << ", eta = " << packing_fraction(scene) << ", "
      << (scene.box.boundary == Boundary::periodic ? "periodic " : "walls ") << scene.box.width
      << " x " << scene.box.height << ", E = " << kinetic_energy(scene);
    return s.str();
}

}  // namespace collide
