#pragma once
/// \file
/// How a class sees a panel of spheres (`dimension = 3` scenes): the camera (an orthographic or a
/// perspective view from above one corner, fixed or slowly orbiting in video time), the projection
/// of a SphereSnapshot into the renderer's SphereView, and the stand-in discs that let the rest of
/// the collision video (layout, figures, speed plot, failure marks) work unchanged on the screen's
/// projection. Pure functions (unit-tested in tests/show): the same snapshot and video time give
/// the same view.

#include <cstdint>

#include "collide/render_options.hpp"
#include "collide/scene.hpp"
#include "collide/scene3.hpp"
#include "collide/snapshot.hpp"
#include "collide/snapshot3.hpp"
#include "collide/view/spheres.hpp"

namespace collide::show {

/// `--camera`: a fixed view, or one that turns slowly about the box's vertical axis (the enum
/// lives with the other render options, so that a scene file can name it).
using CameraMotion = collide::CameraMotion;
/// `--projection`: orthographic or perspective.
using Projection = collide::Projection;

/// The perspective eye's distance from the box's centre, in half diagonals of the box: the whole
/// box in a field of view of about 40 degrees, near corners about 1.5 times larger than the centre
/// plane, far ones about 0.75 times (depth reads at once, the box still reads as a box).
inline constexpr double eye_distance_in_half_diagonals = 3.0;

/// Seconds of moving video per turn of the orbit: slow enough to follow single spheres, fast
/// enough that a 20 s video shows the box from half way round.
inline constexpr double orbit_seconds = 40.0;

/// The camera at one frame: turned by `yaw` about the vertical (y) axis, then tilted down by
/// `pitch` to see the top; radians.
struct Camera {
    double yaw = 0.6;     ///< about 35 degrees: one corner of the box towards the viewer
    double pitch = 0.42;  ///< about 24 degrees from above
    /// `--slab W`: only the spheres whose centres lie within W/2 (box units) of the plane through
    /// the box's centre that faces the camera, so that the inside of a dense system shows; 0: all.
    double slab = 0.0;
    Projection projection = Projection::orthographic;
};

/// The camera of a frame shown `video_seconds` into the moving picture (a card or a hold does not
/// turn it): the fixed view, or the fixed view turned by a whole turn per orbit_seconds.
[[nodiscard]] Camera camera_at(CameraMotion motion, double video_seconds, double slab = 0.0,
                               Projection projection = Projection::orthographic) noexcept;

/// A panel of spheres as the camera sees it: the view the renderer paints and the stand-in
/// snapshot that carries the panel's box (the screen box: the same for every camera angle, so the
/// layout never moves while the camera turns), the spheres' projected positions, apparent radii
/// and speeds (Snapshot::dimension = 3) and the time-driven engine's failures projected onto the
/// screen (Snapshot::exits: where each escaped sphere left the box).
struct ProjectedPanel {
    Snapshot screen;
    SphereView view;
};

/// Projects `snapshot` through `camera`. O(N log N): spheres are sorted far to near. Under a
/// perspective, a sphere that reaches the eye (only a time-driven sphere that escaped its box
/// can) is left out of the view; its stand-in disc stays.
[[nodiscard]] ProjectedPanel project(const SphereSnapshot& snapshot, Camera camera);
/// The same, filling `out` (its storage reused from frame to frame).
void project(const SphereSnapshot& snapshot, Camera camera, ProjectedPanel& out);

/// The screen box of a box of spheres, `largest_radius` the largest sphere's: wide and high
/// enough for the box seen from any yaw at Camera's pitch, in its projection.
[[nodiscard]] Box screen_box(const Box3& box, double largest_radius, Camera camera) noexcept;

/// A scene of discs standing in for `scene`'s spheres in what a render plans from a scene (pace,
/// duration, colour ranges, captions, work): the same box width and height, each sphere a disc at
/// its (x, y) with velocity (vx, |(vy, vz)|), so speeds and energies are the spheres'. The title,
/// description and [render] hints are the scene's.
[[nodiscard]] Scene stand_in_scene(const SphereScene& scene);

}  // namespace collide::show
