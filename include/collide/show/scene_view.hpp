#pragma once
/// \file
/// Which scene a collision video runs: discs, or spheres planned through discs standing in.
#include "collide/assert.hpp"
#include "collide/scene.hpp"
#include "collide/scene3.hpp"

namespace collide::show {

/// The scene as the engines run it: a 2D scene of discs, or a 3D scene of spheres seen through
/// a camera, planned through discs standing in for its spheres (show::stand_in_scene). Built
/// once where the scene is loaded; every class after it asks which kind it holds, never tests a
/// pointer. Refers to scenes its owner keeps alive.
class SceneView {
  public:
    /// A 2D scene of discs.
    explicit SceneView(const Scene& discs) noexcept : discs_(&discs) {}
    /// A 3D scene, with `stand_in` its discs for planning (pace, speeds, hints).
    SceneView(const SphereScene& spheres, const Scene& stand_in) noexcept
        : discs_(&stand_in), spheres_(&spheres) {}

    [[nodiscard]] bool three_d() const noexcept { return spheres_ != nullptr; }
    /// The discs the video is planned through: the scene in 2D, the stand-in in 3D.
    [[nodiscard]] const Scene& discs() const noexcept { return *discs_; }
    /// The spheres of a 3D scene; only when three_d().
    [[nodiscard]] const SphereScene& spheres() const {
        COLLIDE_ASSERT(three_d(), "a 2D scene has no spheres");
        return *spheres_;
    }

  private:
    const Scene* discs_;
    const SphereScene* spheres_ = nullptr;
};

}  // namespace collide::show
