#pragma once
// Scenes for the 3D tests: an FCC crystal of hard spheres in a periodic unit cube.

#include <cstddef>
#include <cstdint>

#include "collide/scene3.hpp"
#include "collide/sim/generate3.hpp"

namespace collide::test {

/// A sphere at p moving at v, radius r, mass m.
inline Sphere sphere(Vec3 p, Vec3 v, double r, double m = 1.0) {
    Sphere s;
    s.position = p;
    s.velocity = v;
    s.radius = r;
    s.mass = m;
    return s;
}

/// 4 * cells^3 spheres on an FCC lattice at packing fraction `eta` in a periodic unit cube, with
/// the generator's velocities for `seed`.
inline SphereScene fcc_fluid(std::size_t cells, double eta, std::uint64_t seed = 1) {
    SphereScene scene;
    scene.name = "fcc";
    scene.box = Box3{1.0, 1.0, 1.0, Boundary::periodic};
    FccSpec spec;
    spec.cells = {cells, cells, cells};
    spec.packing_fraction = eta;
    spec.seed = seed;
    generate_fcc(scene, spec);
    return scene;
}

}  // namespace collide::test
