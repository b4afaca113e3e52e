#pragma once
/// \file
/// Validation of scenes (std-only): every loader runs it before a scene reaches an engine, so
/// engines may assume finite values, positive radii and masses, discs inside the box and no
/// overlaps at t = 0. Errors name the file, line and field where each disc came from.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "collide/scene.hpp"

namespace collide {

/// Where one disc (or a scene key) was written: for messages "file:line: field: reason".
struct SourceLocation {
    std::string file;   ///< file name as the user gave it (may be empty)
    int line = 0;       ///< 1-based; 0 = unknown
    std::string field;  ///< "disc 3", "disc[2].radius", "generate[0]" ... (may be empty)
};

/// Where a run of consecutive discs of a scene came from.
struct DiscSource {
    std::size_t first = 0;   ///< index in Scene::discs of the run's first disc
    std::size_t count = 0;   ///< number of discs in the run
    std::string file;        ///< file the run was read from
    std::vector<int> lines;  ///< one line per disc (algs4 files), or empty
    int line = 0;            ///< line of the block when `lines` is empty ([[disc]], [[generate]])
    /// Name in messages: with `lines`, "disc" => "disc 3" (1-based); a one-disc run ("disc[2]")
    /// is named as is; a longer run ("generate[0]") => "generate[0] disc 17".
    std::string field;
};

/// The origin of every disc of a scene, for error messages. An empty origin names discs by index.
class SceneOrigin {
  public:
    /// Appends a run; runs must be added in disc order.
    void add(DiscSource run) { runs_.push_back(std::move(run)); }
    /// Where disc `index` came from; O(log runs).
    [[nodiscard]] SourceLocation locate(std::size_t index) const;
    [[nodiscard]] const std::vector<DiscSource>& runs() const noexcept { return runs_; }

  private:
    std::vector<DiscSource> runs_;
};

/// Overlaps smaller than this fraction of the radius sum are contacts, not overlaps: the algs4
/// files place touching discs (billiard racks, diffusion walls) whose distance rounds to a few
/// 1e-14 below the sum of radii.
inline constexpr double contact_tolerance = 1e-9;

/// The range of magnitudes the engines compute with: box sides, coordinates and velocity
/// components at most max_scene_magnitude; radii and masses within [min, max]. Why: the collision
/// formulas multiply up to four such numbers (2 m_i m_j (dv . dr), v^2 r^2), and beyond this
/// range a product overflows to infinity (a NaN velocity, a run that never ends) or underflows to
/// zero (no impulse: the discs pass through each other). SI units fit, from molecules (1e-26 kg,
/// 1e-10 m) to planets (1e30 kg, 1e11 m).
inline constexpr double max_scene_magnitude = 1e50;
inline constexpr double min_scene_magnitude = 1e-50;

/// How many problems of one kind a validation message lists before "and N more".
inline constexpr std::size_t max_listed_problems = 5;

/// Checks a scene and throws Error(input) on the first kind of problem found, naming where it
/// comes from: box size not positive/finite; a position, velocity, radius or mass not finite;
/// radius <= 0; mass <= 0; any of them outside the range of max_scene_magnitude /
/// min_scene_magnitude; discs outside a walled box (every such disc is listed, up to
/// max_listed_problems); a disc too large for a periodic box (radius > min(width, height) / 4);
/// two discs overlapping at t = 0 (the first pair in scene order is named); a disc that cannot move
/// along an axis but has a velocity along it (field `velocity`): as wide as the box, wedged from
/// wall to wall in a straight row of touching discs, or moving unlike the rest of a straight ring
/// of touching discs around a periodic box (the event-driven engines would collide forever at
/// t = 0; rows within sqrt(contact_tolerance) of straight count as straight).
/// Complexity O(N) expected (a cell grid), memory O(N).
void validate_scene(const Scene& scene, const SceneOrigin& origin = {});

/// Area fraction eta = sum(pi r^2) / box area (REFERENCE.md); O(N).
[[nodiscard]] double packing_fraction(const Scene& scene) noexcept;

/// Total kinetic energy sum(m v^2 / 2); O(N).
[[nodiscard]] double kinetic_energy(const Scene& scene) noexcept;

/// One-line summary "N = 1000, eta = 0.196, walls 1 x 1, E = 0.5" (used by `collide check`).
[[nodiscard]] std::string scene_summary(const Scene& scene);

}  // namespace collide
