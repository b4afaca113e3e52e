#pragma once
/// \file
/// The view of a panel of spheres (a `dimension = 3` scene): what the renderer paints for one
/// panel, filled by the presentation layer (show::SphereCamera) from a SphereSnapshot. Positions
/// are already projected onto the screen by the camera (orthographic or perspective); the renderer
/// lights and shades what it is handed, casting each pixel's ray from the eye it is given, and
/// decides nothing about the view. Plain values (types layer).

#include <cstdint>
#include <vector>

#include "collide/disc.hpp"
#include "collide/vec2.hpp"

namespace collide {

/// One sphere as the camera sees it. Screen coordinates are the panel's screen box (the stand-in
/// Snapshot's box: x right, y up, in box units); depth runs 0 (nearest the viewer) .. 1 (farthest).
struct SphereSprite {
    Vec2 at;             ///< the centre's projection, screen box units
    double depth = 0.5;  ///< the centre's depth, 0..1
    /// Screen box units: how large the sphere looks at `at` (orthographic: its radius; under a
    /// perspective its radius times the scale at its centre's distance).
    double radius = 0.0;
    /// The sphere's radius in depth units: the surface's depth is depth - radius_depth * z.
    double radius_depth = 0.0;
    /// Speed and mass choose the colour in ColorMode::speed and ColorMode::mass (as a disc's).
    double speed = 0.0;
    double mass = 1.0;
    Rgb8 color;           ///< the scene's colour (ColorMode::scene)
    bool tagged = false;  ///< ColorMode::tag
    /// The sphere itself in screen space, which a perspective ray cast needs (SphereView::
    /// eye_distance > 0): its centre's foot on the screen plane (the plane through the box's
    /// centre facing the camera, where the scale is 1; screen box units), the centre's height
    /// above that plane towards the viewer, and its radius. Orthographic: plane_at == at.
    Vec2 plane_at;
    double height = 0.0;
    double ball_radius = 0.0;
};

/// One edge of the box, projected: drawn behind the spheres (back edges) or over them (the edges
/// nearer the viewer than the box's centre), so that the box reads as a box around them.
struct BoxEdge {
    Vec2 from;  ///< screen box units
    Vec2 to;
    bool front = false;  ///< nearer the viewer: drawn over the spheres, fainter
};

/// Everything drawn of a panel of spheres. Spheres are listed farthest first (the renderer draws
/// them in this order, so the soft edge of a near sphere blends over the far one behind it; the
/// depth buffer sorts out the ones that intersect).
struct SphereView {
    std::vector<SphereSprite> spheres;
    std::vector<BoxEdge> edges;  ///< the box's 12 edges
    /// The camera: 0 for an orthographic one (every ray runs straight into depth), else the eye's
    /// distance above the screen plane, screen box units, looking down at `eye_at` (the screen
    /// box's centre): the renderer casts each pixel's ray from there.
    double eye_distance = 0.0;
    Vec2 eye_at;
    /// The key light's direction towards the light, in screen space (x right, y up, z towards the
    /// viewer), unit length.
    double light_x = -0.45;
    double light_y = 0.6;
    double light_z = 0.66;
    double ambient = 0.3;  ///< share of the colour lit by the ambient term alone, 0..1
    /// Depth cue: the farthest surface is darkened by this share (0: none), towards the box fill,
    /// so that depth still reads on a projector at the back of a hall.
    double depth_cue = 0.5;
};

}  // namespace collide
