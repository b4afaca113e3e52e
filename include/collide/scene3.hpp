#pragma once
/// \file
/// A 3D scene: hard spheres in a box with a depth (`dimension = 3` in a TOML scene). The
/// simulation library runs it with the same engines as the 2D Scene, written once for both
/// dimensions (collide/space.hpp), and drawn as shaded spheres by `collide render`.

#include <string>
#include <vector>

#include "collide/box3.hpp"
#include "collide/disc.hpp"
#include "collide/scene.hpp"
#include "collide/vec3.hpp"

namespace collide {

/// One hard sphere. Units as for Disc: box lengths, box lengths per time unit, mass units.
struct Sphere {
    Vec3 position;         ///< centre at t = 0
    Vec3 velocity;         ///< at t = 0
    double radius = 0.01;  ///< > 0
    double mass = 1.0;     ///< > 0 and finite
    Rgb8 color{0, 0, 0};
    std::string tag;  ///< optional label ("tracer"): mean squared displacement
};

struct SphereScene {
    std::string name;
    std::string title;
    std::string description;
    Box3 box;
    std::vector<Sphere> spheres;
    RenderHints render;  ///< `[render]`, as a 2D scene's (collide render draws spheres)
};

}  // namespace collide
