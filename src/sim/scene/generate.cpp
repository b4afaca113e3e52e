// Random disc generators. Phases: resolve the region and count -> place (random sequential
// addition, or a jittered triangular lattice when that cannot reach the density) -> velocities.

#include "collide/sim/generate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <utility>
#include <vector>

#include "collide/error.hpp"
#include "scene/disc_grid.hpp"
#include "scene/generator_errors.hpp"
#include "scene/random.hpp"

namespace collide {

namespace {

using detail::DiscGrid;
using detail::Rng;

// Lattice neighbours keep at least this relative gap, so no two discs start in exact contact.
constexpr double min_lattice_gap = 1e-6;

// Random placement tries this many candidate positions per disc (on average) before giving up
// and falling back to the lattice.
constexpr double random_attempts_per_disc = 200.0;

using detail::fail;
using detail::num;

// Where generated centres may go.
struct Placement {
    Vec2 lo;  // centre rectangle (walls or sub-region)
    Vec2 hi;
    bool wraps = false;  // the region is the whole periodic box: centres anywhere, wrapped
    double region_area = 0.0;
};

Placement resolve_region(const Box& box, const GenerateSpec& spec, const std::string& prefix) {
    const Vec2 lo = spec.region_min;
    const Vec2 hi = spec.region_max.value_or(Vec2{box.width, box.height});
    if (!(hi.x > lo.x) || !(hi.y > lo.y))
        fail(prefix, "region", "the second corner must lie above and right of the first");
    const double slack = 1e-12 * std::max(box.width, box.height);
    if (lo.x < -slack || lo.y < -slack || hi.x > box.width + slack || hi.y > box.height + slack) {
        fail(prefix, "region",
             "[[" + num(lo.x) + ", " + num(lo.y) + "], [" + num(hi.x) + ", " + num(hi.y) +
                 "]] extends outside the box [0, " + num(box.width) + "] x [0, " + num(box.height) +
                 "]");
    }
    Placement p;
    p.region_area = (hi.x - lo.x) * (hi.y - lo.y);
    p.wraps = box.boundary == Boundary::periodic && lo.x <= slack && lo.y <= slack &&
              hi.x >= box.width - slack && hi.y >= box.height - slack;
    if (p.wraps) {
        p.lo = {0.0, 0.0};
        p.hi = {box.width, box.height};
    } else {
        const double r = spec.radius;
        p.lo = {lo.x + r, lo.y + r};
        p.hi = {hi.x - r, hi.y - r};
        if (p.hi.x < p.lo.x || p.hi.y < p.lo.y)
            fail(prefix, "radius", "discs of radius " + num(r) + " do not fit in the region");
    }
    return p;
}

std::size_t resolve_count(const GenerateSpec& spec, const Placement& where,
                          const std::string& prefix) {
    const double disc_area = std::numbers::pi * spec.radius * spec.radius;
    double count = static_cast<double>(spec.count);
    if (spec.count == 0) count = std::round(spec.packing_fraction * where.region_area / disc_area);
    if (count < 1.0)
        fail(prefix, "packing_fraction",
             "gives no disc at all in the region (radius " + num(spec.radius) + ")");
    if (count > static_cast<double>(max_generated_discs)) {
        fail(prefix, spec.count ? "count" : "packing_fraction",
             "asks for " + num(count) + " discs (at most " + std::to_string(max_generated_discs) +
                 ")");
    }
    const double eta = count * disc_area / where.region_area;
    // A count derived from a valid packing fraction may round up by half a disc: let it.
    if (spec.count != 0 && eta > max_generated_packing_fraction + 1e-9) {
        fail(prefix, spec.count ? "count" : "packing_fraction",
             std::to_string(static_cast<std::size_t>(count)) + " discs of radius " +
                 num(spec.radius) + " give packing fraction " + num(eta) +
                 " in the region, above the maximum " + num(max_generated_packing_fraction) +
                 " the generator can reach (close packing is 0.9069)");
    }
    return static_cast<std::size_t>(count);
}

// The discs already in the scene, filed in a grid sized for the new discs. Keeps its own
// compact copy of centres and radii: a Disc (with its tag string) is ~90 bytes, and at 10^6
// discs each candidate test would otherwise miss the cache on it.
class Occupancy {
  public:
    Occupancy(const Scene& scene, double radius, std::size_t expected_new)
        : box_(scene.box),
          grid_(scene.box, 2.0 * radius, 4 * (scene.discs.size() + expected_new) + 64) {
        placed_.reserve(scene.discs.size() + expected_new);
        for (const Disc& d : scene.discs) add(d.position, d.radius);
    }

    // Would a disc at p with radius r overlap anything added so far?
    [[nodiscard]] bool blocked(Vec2 p, double r) const {
        return grid_.any_near(p, r, [&](std::uint32_t j) {
            const Placed& d = placed_[j];
            const double sum = d.radius + r;
            return norm2(box_.displacement(d.centre, p)) < sum * sum;
        });
    }

    void add(Vec2 centre, double radius) {
        const Vec2 c = box_.wrap(centre);
        grid_.insert(static_cast<std::uint32_t>(placed_.size()), c, radius);
        placed_.push_back({c, radius});
    }

  private:
    struct Placed {
        Vec2 centre;
        double radius;
    };
    Box box_;
    DiscGrid grid_;
    std::vector<Placed> placed_;
};

double existing_area_in(const Scene& scene, Vec2 lo, Vec2 hi) {
    double area = 0.0;
    for (const Disc& d : scene.discs) {
        const Vec2 p = d.position;
        if (p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y)
            area += std::numbers::pi * d.radius * d.radius;
    }
    return area;
}

Disc new_disc(const GenerateSpec& spec, Vec2 position) {
    Disc d;
    d.position = position;
    d.radius = spec.radius;
    d.mass = spec.mass;
    d.color = spec.color;
    d.tag = spec.tag;
    return d;
}

// Orders discs [first, end) by rows of cells of side `cell`: neighbours in space become
// neighbours in memory, which the engines' caches (and validation) like. Deterministic.
void sort_spatially(std::vector<Disc>& discs, std::size_t first, double cell) {
    auto key = [cell](const Disc& d) {
        return std::pair{std::floor(d.position.y / cell), std::floor(d.position.x / cell)};
    };
    std::stable_sort(discs.begin() + static_cast<std::ptrdiff_t>(first), discs.end(),
                     [&](const Disc& a, const Disc& b) { return key(a) < key(b); });
}

// Random sequential addition; false (and scene unchanged) when the attempt budget runs out.
bool place_randomly(Scene& scene, const GenerateSpec& spec, const Placement& where,
                    std::size_t count, Rng& rng) {
    const std::size_t first = scene.discs.size();
    scene.discs.reserve(first + count);
    Occupancy occupancy(scene, spec.radius, count);
    auto attempts = static_cast<double>(count) * random_attempts_per_disc + 1000.0;
    while (scene.discs.size() < first + count) {
        if (--attempts < 0.0) {
            scene.discs.resize(first, Disc{});
            return false;
        }
        const Vec2 p{rng.uniform(where.lo.x, where.hi.x), rng.uniform(where.lo.y, where.hi.y)};
        const Vec2 q = scene.box.wrap(p);
        if (occupancy.blocked(q, spec.radius)) continue;
        scene.discs.push_back(new_disc(spec, q));
        occupancy.add(q, spec.radius);
    }
    sort_spatially(scene.discs, first, 4.0 * spec.radius);
    return true;
}

// A triangular lattice: rows along x, odd rows shifted by half a column.
struct Lattice {
    Vec2 origin;
    double ax = 0.0;       // spacing along a row
    double ay = 0.0;       // spacing between rows
    std::size_t cols = 0;  // sites in even rows
    std::size_t odd_cols = 0;
    std::size_t rows = 0;

    [[nodiscard]] std::size_t sites() const noexcept {
        return (rows + 1) / 2 * cols + rows / 2 * odd_cols;
    }
    [[nodiscard]] double neighbour_distance() const noexcept {
        // Along a row, to the next row, and to the same column two rows on (short when rows are
        // squeezed together in a periodic box).
        double d = std::min(ax, std::hypot(0.5 * ax, ay));
        d = std::min(d, 2.0 * ay);
        return d;
    }
    template <class Visit>
    void for_each_site(Visit&& visit) const {
        for (std::size_t row = 0; row < rows; ++row) {
            const bool odd = row % 2 == 1;
            const std::size_t n = odd ? odd_cols : cols;
            for (std::size_t c = 0; c < n; ++c) {
                visit(Vec2{origin.x + (static_cast<double>(c) + (odd ? 0.5 : 0.0)) * ax,
                           origin.y + static_cast<double>(row) * ay});
            }
        }
    }
};

// The widest-spaced lattice with at least `count` sites in the centre rectangle (walls or a
// sub-region), centred in it. Sites per spacing fall as the spacing grows: bisect.
Lattice rectangle_lattice(const Placement& where, double spacing) {
    const double lx = where.hi.x - where.lo.x;
    const double ly = where.hi.y - where.lo.y;
    Lattice l;
    l.ax = spacing;
    l.ay = spacing * std::numbers::sqrt3 / 2.0;
    l.cols = static_cast<std::size_t>(std::floor(lx / l.ax)) + 1;
    l.odd_cols =
        lx >= 0.5 * l.ax ? static_cast<std::size_t>(std::floor((lx - 0.5 * l.ax) / l.ax)) + 1 : 0;
    l.rows = static_cast<std::size_t>(std::floor(ly / l.ay)) + 1;
    const double used_x = static_cast<double>(l.cols - 1) * l.ax;
    const double used_y = static_cast<double>(l.rows - 1) * l.ay;
    l.origin = {where.lo.x + 0.5 * (lx - used_x), where.lo.y + 0.5 * (ly - used_y)};
    if (l.odd_cols > 0 && l.odd_cols == l.cols)
        l.origin.x = where.lo.x + 0.5 * (lx - used_x - 0.5 * l.ax);
    return l;
}

class LatticePlacer {
  public:
    LatticePlacer(Scene& scene, const GenerateSpec& spec, const Placement& where, std::size_t count,
                  Rng& rng, const std::string& prefix)
        : scene_(scene), spec_(spec), where_(where), count_(count), rng_(rng), prefix_(prefix) {}

    void run() {
        const Lattice lattice = choose();
        const std::vector<Vec2> free = free_sites(lattice);
        const double jitter =
            0.5 * (lattice.neighbour_distance() - 2.0 * spec_.radius) * (1.0 - 1e-6);
        place(pick(free.size()), free, jitter);
    }

  private:
    // Sites of `lattice` where a disc (with room to jitter) does not touch an existing disc.
    std::vector<Vec2> free_sites(const Lattice& lattice) const {
        std::vector<Vec2> sites;
        sites.reserve(lattice.sites());
        const double jitter =
            0.5 * std::max(0.0, lattice.neighbour_distance() - 2.0 * spec_.radius);
        if (scene_.discs.empty()) {
            lattice.for_each_site([&](Vec2 p) { sites.push_back(scene_.box.wrap(p)); });
            return sites;
        }
        const Occupancy occupancy(scene_, spec_.radius + jitter, lattice.sites());
        lattice.for_each_site([&](Vec2 p) {
            const Vec2 q = scene_.box.wrap(p);
            if (!occupancy.blocked(q, spec_.radius + jitter)) sites.push_back(q);
        });
        return sites;
    }

    [[nodiscard]] bool roomy(const Lattice& lattice) const {
        return lattice.neighbour_distance() >= 2.0 * spec_.radius * (1.0 + min_lattice_gap);
    }

    std::size_t free_count(const Lattice& lattice) const {
        if (scene_.discs.empty()) return lattice.sites();
        return free_sites(lattice).size();
    }

    // The widest lattice with at least `target` sites; then, if discs already there block too
    // many sites, ask for proportionally more sites until enough are free.
    Lattice choose() const {
        std::size_t target = count_;
        constexpr int max_rounds = 40;
        for (int round = 0; round < max_rounds; ++round) {
            const Lattice lattice = where_.wraps ? periodic_for(target) : rectangle_for(target);
            if (!roomy(lattice)) break;
            const std::size_t free = free_count(lattice);
            if (free >= count_) return lattice;
            const double grow =
                free == 0 ? 2.0 : 1.02 * static_cast<double>(count_) / static_cast<double>(free);
            target =
                std::max(target + 1,
                         static_cast<std::size_t>(std::ceil(static_cast<double>(target) * grow)));
        }
        too_dense();
    }

    // Sites per spacing fall as the spacing grows: bisect for the widest with `target` sites.
    Lattice rectangle_for(std::size_t target) const {
        const double lx = where_.hi.x - where_.lo.x;
        const double ly = where_.hi.y - where_.lo.y;
        // Start a hair above the accepted minimum so rounding in hypot cannot reject it.
        double lo = 2.0 * spec_.radius * (1.0 + 2.0 * min_lattice_gap);
        if (rectangle_lattice(where_, lo).sites() < target)
            return rectangle_lattice(where_, 0.0 + 2.0 * spec_.radius);
        double hi = 2.0 * std::max(lx, ly) + 4.0 * spec_.radius;
        for (int i = 0; i < 100 && hi - lo > 1e-12 * lo; ++i) {
            const double mid = 0.5 * (lo + hi);
            (rectangle_lattice(where_, mid).sites() >= target ? lo : hi) = mid;
        }
        return rectangle_lattice(where_, lo);
    }

    // Periodic whole box: whole numbers of columns and (even) rows so the lattice tiles the
    // torus. Tries every even row count with the fewest columns that give `target` sites.
    Lattice periodic_for(std::size_t target) const {
        const Box& box = scene_.box;
        Lattice best;
        for (std::size_t rows = 2; rows <= 2 * (target + 1); rows += 2) {
            Lattice l;
            l.rows = rows;
            l.ay = box.height / static_cast<double>(rows);
            l.cols = l.odd_cols = (target + rows - 1) / rows;
            l.ax = box.width / static_cast<double>(l.cols);
            l.origin = {0.25 * l.ax, 0.5 * l.ay};
            if (best.rows == 0 || l.neighbour_distance() > best.neighbour_distance()) best = l;
            if (l.ay < spec_.radius) break;  // rows closer than a radius: only worse from here
        }
        return best;
    }

    [[noreturn]] void too_dense() const {
        fail(prefix_, spec_.count ? "count" : "packing_fraction",
             "cannot place " + std::to_string(count_) + " discs of radius " + num(spec_.radius) +
                 " in the region without overlaps; lower the count or packing fraction, or the "
                 "radius");
    }

    // `count_` distinct site indices out of n, in increasing order (spatial order: good for the
    // engines' caches); random vacancies help the lattice melt.
    std::vector<std::size_t> pick(std::size_t n) {
        std::vector<std::size_t> index(n);
        for (std::size_t i = 0; i < n; ++i) index[i] = i;
        for (std::size_t i = 0; i < count_; ++i) std::swap(index[i], index[i + rng_.below(n - i)]);
        index.resize(count_);
        std::sort(index.begin(), index.end());
        return index;
    }

    void place(const std::vector<std::size_t>& chosen, const std::vector<Vec2>& sites,
               double jitter) {
        scene_.discs.reserve(scene_.discs.size() + chosen.size());
        for (std::size_t i : chosen) {
            Vec2 p = sites[i];
            // A random shift inside a disc of radius `jitter` keeps every pair apart.
            const double rho = jitter * std::sqrt(rng_.uniform());
            const double phi = 2.0 * std::numbers::pi * rng_.uniform();
            const Vec2 q = p + Vec2{rho * std::cos(phi), rho * std::sin(phi)};
            if (where_.wraps) {
                p = scene_.box.wrap(q);
            } else if (q.x >= where_.lo.x && q.x <= where_.hi.x && q.y >= where_.lo.y &&
                       q.y <= where_.hi.y) {
                p = q;
            }
            scene_.discs.push_back(new_disc(spec_, p));
        }
    }

    Scene& scene_;
    const GenerateSpec& spec_;
    const Placement& where_;
    std::size_t count_;
    Rng& rng_;
    const std::string& prefix_;
};

// Maxwell-Boltzmann at exactly kT (kinetic temperature of the block), zero total momentum.
void thermal_velocities(std::vector<Disc>& discs, std::size_t first, double kT, Rng& rng) {
    const std::size_t n = discs.size() - first;
    Vec2 mean{};
    for (std::size_t i = first; i < discs.size(); ++i) {
        const double sigma = std::sqrt(kT / discs[i].mass);
        discs[i].velocity = {sigma * rng.normal(), sigma * rng.normal()};
        mean += discs[i].velocity;
    }
    mean *= 1.0 / static_cast<double>(n);  // equal masses: the mean velocity carries the momentum
    double energy = 0.0;
    for (std::size_t i = first; i < discs.size(); ++i) {
        discs[i].velocity -= mean;
        energy += 0.5 * discs[i].mass * norm2(discs[i].velocity);
    }
    const double target = static_cast<double>(n) * kT;
    const double scale = energy > 0.0 ? std::sqrt(target / energy) : 0.0;
    for (std::size_t i = first; i < discs.size(); ++i) discs[i].velocity *= scale;
}

// Every disc at the same speed; consecutive pairs fly in opposite directions.
void fixed_speed_velocities(std::vector<Disc>& discs, std::size_t first, double speed, Rng& rng) {
    for (std::size_t i = first; i < discs.size(); i += 2) {
        const double phi = 2.0 * std::numbers::pi * rng.uniform();
        discs[i].velocity = {speed * std::cos(phi), speed * std::sin(phi)};
        if (i + 1 < discs.size()) discs[i + 1].velocity = -discs[i].velocity;
    }
}

}  // namespace

void GenerateSpec::validate(const std::string& field_prefix) const {
    auto bad = [&](const std::string& field, const std::string& reason) {
        fail(field_prefix, field, reason);
    };
    if (!std::isfinite(radius) || !(radius > 0.0))
        bad("radius", "must be a finite number > 0 (got " + num(radius) + ")");
    if (!std::isfinite(mass) || !(mass > 0.0))
        bad("mass", "must be a finite number > 0 (got " + num(mass) + ")");
    if (!std::isfinite(temperature) || temperature < 0.0)
        bad("temperature", "must be a finite number >= 0 (got " + num(temperature) + ")");
    if (speed && (!std::isfinite(*speed) || *speed < 0.0))
        bad("speed", "must be a finite number >= 0 (got " + num(*speed) + ")");
    if (count == 0) {
        if (!std::isfinite(packing_fraction) || !(packing_fraction > 0.0)) {
            bad("count", "give count > 0 or packing_fraction > 0");
        }
        if (packing_fraction > max_generated_packing_fraction) {
            bad("packing_fraction", num(packing_fraction) + " is above the maximum " +
                                        num(max_generated_packing_fraction) +
                                        " the generator can reach (close packing is 0.9069)");
        }
    } else if (packing_fraction != 0.0) {
        bad("packing_fraction", "give either count or packing_fraction, not both");
    }
    if (!std::isfinite(region_min.x) || !std::isfinite(region_min.y))
        bad("region", "corners must be finite numbers");
    if (region_max && (!std::isfinite(region_max->x) || !std::isfinite(region_max->y)))
        bad("region", "corners must be finite numbers");
}

void generate_discs(Scene& scene, const GenerateSpec& spec, const std::string& field_prefix) {
    spec.validate(field_prefix);
    const Placement where = resolve_region(scene.box, spec, field_prefix);
    const std::size_t count = resolve_count(spec, where, field_prefix);
    if (scene.discs.size() + count >= std::numeric_limits<std::uint32_t>::max())
        fail(field_prefix, "count", "too many discs");
    Rng rng(spec.seed);
    const std::size_t first = scene.discs.size();

    const Vec2 region_lo = spec.region_min;
    const Vec2 region_hi = spec.region_max.value_or(Vec2{scene.box.width, scene.box.height});
    const double eta = (static_cast<double>(count) * std::numbers::pi * spec.radius * spec.radius +
                        existing_area_in(scene, region_lo, region_hi)) /
                       where.region_area;
    const bool random_done =
        eta <= random_placement_limit && place_randomly(scene, spec, where, count, rng);
    if (!random_done) LatticePlacer(scene, spec, where, count, rng, field_prefix).run();

    if (spec.speed) {
        fixed_speed_velocities(scene.discs, first, *spec.speed, rng);
    } else {
        thermal_velocities(scene.discs, first, spec.temperature, rng);
    }
}

}  // namespace collide
