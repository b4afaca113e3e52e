// Hard spheres in 3D: the FCC and random generators, and the fast engine written once for 2 and
// 3 dimensions (analytic collisions, conservation, no overlap, the equation of state).

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "collide/error.hpp"
#include "collide/sim/fast_engine.hpp"
#include "collide/sim/generate3.hpp"
#include "sphere_fixtures.hpp"

using namespace collide;
using sim::FastSphereEngine;

namespace {

using collide::test::fcc_fluid;
using collide::test::sphere;

std::string error_of(const auto& f) {
    try {
        f();
    } catch (const Error& e) {
        CHECK(e.exit_code() == 2);
        return e.what();
    }
    return "";
}

/// Carnahan-Starling: Z = (1 + eta + eta^2 - eta^3) / (1 - eta)^3.
double carnahan_starling(double eta) {
    return (1.0 + eta + eta * eta - eta * eta * eta) / std::pow(1.0 - eta, 3.0);
}

}  // namespace

TEST_CASE("the FCC generator fills the box at the packing fraction, at rest and at kT") {
    const SphereScene scene = fcc_fluid(3, 0.45, 5);
    REQUIRE(scene.spheres.size() == 4 * 27);
    double volume = 0.0;
    Vec3 momentum{};
    double kinetic = 0.0;
    for (const Sphere& s : scene.spheres) {
        volume += 4.0 / 3.0 * std::numbers::pi * std::pow(s.radius, 3.0);
        momentum += s.mass * s.velocity;
        kinetic += 0.5 * s.mass * norm2(s.velocity);
    }
    CHECK(volume == doctest::Approx(0.45).epsilon(1e-12));
    CHECK(norm(momentum) < 1e-12);
    CHECK(2.0 * kinetic / (3.0 * 108.0) == doctest::Approx(1.0).epsilon(1e-12));
    // Nearest neighbours at half a face diagonal, apart.
    const double a = 1.0 / 3.0;
    CHECK(2.0 * scene.spheres[0].radius < a / std::sqrt(2.0));
}

TEST_CASE("too dense to generate: the FCC and random generators name the field") {
    CHECK(error_of([] { (void)fcc_fluid(3, 0.75); }).find("fcc.packing_fraction") !=
          std::string::npos);
    SphereScene walled;
    walled.box = Box3{1.0, 1.0, 1.0, Boundary::walls};
    FccSpec lattice;
    lattice.packing_fraction = 0.3;  // outer spheres would cross the walls above pi / 12
    CHECK(error_of([&] { generate_fcc(walled, lattice); }).find("cross the walls") !=
          std::string::npos);
    lattice.packing_fraction = 0.25;
    CHECK_NOTHROW(generate_fcc(walled, lattice));
    SphereScene flat;
    flat.box = Box3{1.0, 1.0, 0.1, Boundary::periodic};  // cells squashed along z
    FccSpec spec;
    spec.cells = {4, 4, 4};
    spec.packing_fraction = 0.5;
    const std::string squashed = error_of([&] { generate_fcc(flat, spec); });
    CHECK(squashed.find("fcc.packing_fraction") != std::string::npos);
    CHECK(squashed.find("too dense to generate") != std::string::npos);
    SphereScene random;
    random.box = Box3{1.0, 1.0, 1.0, Boundary::walls};
    SphereGenerateSpec gen;
    gen.packing_fraction = 0.4;
    gen.radius = 0.05;
    const std::string dense = error_of([&] { generate_spheres(random, gen); });
    CHECK(dense.find("generate.packing_fraction") != std::string::npos);
    CHECK(dense.find("[[fcc]]") != std::string::npos);
}

TEST_CASE("random spheres do not overlap and lie inside a walled box") {
    SphereScene scene;
    scene.box = Box3{1.0, 2.0, 1.5, Boundary::walls};
    SphereGenerateSpec gen;
    gen.packing_fraction = 0.25;
    gen.radius = 0.06;
    gen.seed = 3;
    generate_spheres(scene, gen);
    REQUIRE(scene.spheres.size() > 100);
    std::vector<Vec3> positions;
    std::vector<double> radii;
    for (const Sphere& s : scene.spheres) {
        CHECK(scene.box.contains(s.position, s.radius));
        positions.push_back(s.position);
        radii.push_back(s.radius);
    }
    CHECK(sim::max_overlap(positions, radii, scene.box) <= 0.0);
}

TEST_CASE("random spheres in a region (a box inside the box) lie entirely inside it") {
    SphereScene scene;
    scene.box = Box3{1.0, 1.0, 2.0, Boundary::walls};
    SphereGenerateSpec gen;
    gen.packing_fraction = 0.2;  // of the region: twice the spheres the half box's share gives
    gen.radius = 0.04;
    gen.seed = 9;
    gen.region_min = {0.0, 0.0, 1.0};
    gen.region_max = Vec3{1.0, 1.0, 2.0};
    generate_spheres(scene, gen);
    const double one = 4.0 / 3.0 * std::numbers::pi * std::pow(gen.radius, 3.0);
    CHECK(static_cast<double>(scene.spheres.size()) == std::round(0.2 * 1.0 / one));
    for (const Sphere& s : scene.spheres) {
        CHECK(s.position.z - s.radius >= 1.0);
        CHECK(scene.box.contains(s.position, s.radius));
    }
    // A second block in the other half avoids the first.
    gen.region_min = {0.0, 0.0, 0.0};
    gen.region_max = Vec3{1.0, 1.0, 1.0};
    gen.seed = 10;
    const std::size_t first = scene.spheres.size();
    generate_spheres(scene, gen);
    REQUIRE(scene.spheres.size() == 2 * first);
    std::vector<Vec3> positions;
    std::vector<double> radii;
    for (const Sphere& s : scene.spheres) {
        positions.push_back(s.position);
        radii.push_back(s.radius);
    }
    CHECK(sim::max_overlap(positions, radii, scene.box) <= 0.0);
}

TEST_CASE("bad 3D regions name generate.region") {
    SphereScene scene;
    scene.box = Box3{1.0, 1.0, 1.0, Boundary::walls};
    SphereGenerateSpec gen;
    gen.count = 10;
    gen.radius = 0.05;
    gen.region_max = Vec3{1.0, 1.0, 1.5};  // deeper than the box
    std::string e = error_of([&] { generate_spheres(scene, gen); });
    CHECK(e.find("generate.region") != std::string::npos);
    CHECK(e.find("inside the box") != std::string::npos);
    gen.region_min = {0.5, 0.0, 0.0};
    gen.region_max = Vec3{0.4, 1.0, 1.0};  // upside down along x
    e = error_of([&] { generate_spheres(scene, gen); });
    CHECK(e.find("generate.region") != std::string::npos);
    CHECK(e.find("second corner") != std::string::npos);
    gen.region_min = {0.0, 0.0, 0.0};
    gen.region_max = Vec3{0.05, 1.0, 1.0};  // thinner than a sphere
    e = error_of([&] { generate_spheres(scene, gen); });
    CHECK(e.find("generate.radius") != std::string::npos);
    CHECK(e.find("does not fit the region") != std::string::npos);
    gen.count = 0;
    gen.packing_fraction = 0.4;  // of a small region: too dense there although the box is not
    gen.region_max = Vec3{0.5, 0.5, 0.5};
    e = error_of([&] { generate_spheres(scene, gen); });
    CHECK(e.find("generate.packing_fraction") != std::string::npos);
    CHECK(e.find("of the region is too dense") != std::string::npos);
}

TEST_CASE("3D: a head-on collision along a diagonal exchanges the velocities of equal spheres") {
    SphereScene scene;
    scene.box = Box3{2.0, 2.0, 2.0, Boundary::walls};
    const Vec3 u = (1.0 / std::sqrt(3.0)) * Vec3{1.0, 1.0, 1.0};
    const double r = 0.1;
    scene.spheres = {sphere(Vec3{1.0, 1.0, 1.0} - 0.5 * u, 0.5 * u, r),
                     sphere(Vec3{1.0, 1.0, 1.0} + 0.5 * u, -0.5 * u, r)};
    FastSphereEngine engine(scene);
    std::vector<CollisionRecord> log;
    engine.set_collision_listener([&](const CollisionRecord& c) { log.push_back(c); });
    engine.advance_to(1.0);
    REQUIRE(!log.empty());
    CHECK(log[0].kind == CollisionKind::pair);
    CHECK(log[0].t == doctest::Approx((1.0 - 2.0 * r) / 1.0).epsilon(1e-12));  // gap 0.8 at 1
    const SphereSnapshot s = engine.snapshot();
    CHECK(s.spheres[0].velocity.x == doctest::Approx(-0.5 * u.x).epsilon(1e-12));
    CHECK(s.spheres[1].velocity.z == doctest::Approx(0.5 * u.z).epsilon(1e-12));
    CHECK(engine.check_invariants());
}

TEST_CASE("3D: a sphere bounces off the front and back walls (z)") {
    SphereScene scene;
    scene.box = Box3{1.0, 1.0, 1.0, Boundary::walls};
    scene.spheres = {sphere({0.5, 0.5, 0.5}, {0.0, 0.0, 1.0}, 0.1)};
    FastSphereEngine engine(scene);
    std::vector<CollisionRecord> log;
    engine.set_collision_listener([&](const CollisionRecord& c) { log.push_back(c); });
    engine.advance_to(1.3);
    REQUIRE(log.size() == 2);
    CHECK(log[0].kind == CollisionKind::zwall);
    CHECK(log[0].t == doctest::Approx(0.4));
    CHECK(log[1].kind == CollisionKind::zwall);
    CHECK(log[1].t == doctest::Approx(1.2));  // across the box and back: 0.8 more
    const Measurements m = engine.measurements();
    CHECK(m.collisions_wall == 2);
    CHECK(engine.snapshot().spheres[0].position.z == doctest::Approx(0.2));
}

TEST_CASE("3D fast engine: energy and momentum conserved to round-off, no overlap, invariants") {
    for (const Boundary boundary : {Boundary::periodic, Boundary::walls}) {
        CAPTURE(static_cast<int>(boundary));
        SphereScene scene = fcc_fluid(4, 0.4, 2);
        double eta = 0.4;
        if (boundary == Boundary::walls) {
            // The lattice in the middle of a larger walled box, clear of the walls.
            scene.box = Box3{1.2, 1.2, 1.2, Boundary::walls};
            for (Sphere& s : scene.spheres) {
                s.position += Vec3{0.1, 0.1, 0.1};
                REQUIRE(scene.box.contains(s.position, s.radius));
            }
            eta = 0.4 / (1.2 * 1.2 * 1.2);
        }
        FastSphereEngine engine(scene);
        // Lists from packing 0.38; the walled box's 0.23 uses cell crossings.
        const bool lists = boundary == Boundary::periodic;
        CHECK(engine.uses_neighbour_lists() == lists);
        const Measurements m0 = engine.measurements();
        CHECK(m0.temperature == doctest::Approx(1.0).epsilon(1e-12));
        for (int k = 1; k <= 10; ++k) {
            engine.advance_to(0.02 * k);
            CHECK(engine.check_invariants());  // lists symmetric and complete, heap, cells
        }
        const Measurements m = engine.measurements();
        CHECK(m.collisions_pair > 1000);
        CHECK((m.list_rebuilds > 100) == lists);
        CHECK((m.cell_crossings == 0) == lists);
        CHECK(std::abs(m.kinetic_energy - m0.kinetic_energy) <= 1e-12 * m0.kinetic_energy);
        CHECK(m.max_overlap <= 1e-9 * 2.0 * scene.spheres[0].radius);
        CHECK(m.packing_fraction == doctest::Approx(eta).epsilon(1e-12));
        CHECK(m.msd > 0.0);
        if (boundary == Boundary::periodic) {
            CHECK(std::hypot(m.momentum.x, m.momentum.y, m.momentum_z) < 1e-12);
        } else {
            CHECK(m.collisions_wall > 0);
        }
    }
}

TEST_CASE(
    "3D fast engine: a crystal's longer lists grow, and the caged spheres keep the invariants") {
    // At packing 0.7 a sphere has 18 centres within 1.5 diameters (the first two FCC shells):
    // more than a list's first 16 slots. In the walled box (packing 0.405) the lists meet walls.
    for (const Boundary boundary : {Boundary::periodic, Boundary::walls}) {
        CAPTURE(static_cast<int>(boundary));
        SphereScene scene = fcc_fluid(4, 0.7, 5);
        if (boundary == Boundary::walls) {
            scene.box = Box3{1.2, 1.2, 1.2, Boundary::walls};
            for (Sphere& s : scene.spheres) {
                s.position += Vec3{0.1, 0.1, 0.1};
                REQUIRE(scene.box.contains(s.position, s.radius));
            }
        }
        FastSphereEngine engine(scene);
        REQUIRE(engine.uses_neighbour_lists());
        if (boundary == Boundary::periodic) {
            CHECK(engine.list_slots() == 32);  // doubled from 16
            // 3 cells per axis: 9.5 centres per cell on average, more than the first 8 slots.
            CHECK(engine.cell_slots() == 16);
        }
        const Measurements m0 = engine.measurements();
        for (int k = 1; k <= 5; ++k) {
            engine.advance_to(0.02 * k);
            CHECK(engine.check_invariants());
        }
        const Measurements m = engine.measurements();
        CHECK(m.collisions_pair > 1000);
        if (boundary == Boundary::walls) {
            CHECK(m.collisions_wall > 0);
            CHECK(m.list_rebuilds > 0);
        }
        CHECK(std::abs(m.kinetic_energy - m0.kinetic_energy) <= 1e-12 * m0.kinetic_energy);
        CHECK(m.max_overlap <= 1e-9);
    }
}

TEST_CASE("3D fast engine: a box too narrow for the lists' cells runs on cell crossings") {
    // 4 diameters wide: three cells of one diameter fit, three of 1.5 do not.
    SphereScene scene;
    scene.box = Box3{0.4, 0.4, 0.4, Boundary::periodic};
    scene.spheres = {sphere({0.05, 0.2, 0.2}, {1.0, 0.1, 0.0}, 0.05),
                     sphere({0.25, 0.21, 0.2}, {-1.0, 0.0, 0.2}, 0.05),
                     sphere({0.2, 0.05, 0.3}, {0.0, 0.7, -0.4}, 0.05)};
    FastSphereEngine engine(scene);
    CHECK_FALSE(engine.uses_neighbour_lists());
    engine.advance_to(2.0);
    CHECK(engine.check_invariants());
    const Measurements m = engine.measurements();
    CHECK(m.collisions_pair > 0);
    CHECK(m.cell_crossings > 0);
    CHECK(m.list_rebuilds == 0);
    CHECK(m.max_overlap <= 1e-12);
}

TEST_CASE("3D fast engine: the same scene gives the same collisions (determinism)") {
    const SphereScene scene = fcc_fluid(3, 0.45, 9);
    std::vector<std::vector<CollisionRecord>> logs(2);
    for (auto& log : logs) {
        FastSphereEngine engine(scene);
        engine.set_collision_listener([&](const CollisionRecord& c) { log.push_back(c); });
        engine.advance_to(0.1);
    }
    REQUIRE(logs[0].size() == logs[1].size());
    REQUIRE(logs[0].size() > 100);
    for (std::size_t k = 0; k < logs[0].size(); ++k) {
        CHECK(logs[0][k].t == logs[1][k].t);
        CHECK(logs[0][k].a == logs[1][k].a);
        CHECK(logs[0][k].b == logs[1][k].b);
    }
}

// A quick check of the equation of state; tests/physics runs the long one (label slow).
TEST_CASE("3D fast engine: Z from the collision virial near Carnahan-Starling (N = 500, short)") {
    for (const double eta : {0.30, 0.45}) {
        CAPTURE(eta);
        FastSphereEngine engine(fcc_fluid(5, eta, 4));
        const double sigma = 2.0 * std::cbrt(eta * 3.0 / (4.0 * std::numbers::pi * 500.0));
        engine.advance_to(20.0 * sigma);  // melt the crystal (times in sigma / sqrt(kT / m))
        const Measurements a = engine.measurements();
        engine.advance_to(a.t + 60.0 * sigma);
        const Measurements b = engine.measurements();
        const double z =
            1.0 + ((b.compressibility - 1.0) * b.t - (a.compressibility - 1.0) * a.t) / (b.t - a.t);
        CHECK(z == doctest::Approx(carnahan_starling(eta)).epsilon(0.02));
    }
}
