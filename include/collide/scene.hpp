#pragma once
/// \file
/// A scene: the box, the discs at t = 0, and optional rendering hints. Produced by the scene
/// loaders (algs4 text, TOML, generators), consumed by the engines and the CLI.

#include <optional>
#include <string>
#include <vector>

#include "collide/box.hpp"
#include "collide/disc.hpp"

namespace collide {

/// Rendering defaults a scene may carry in `[render]`; the CLI overrides every one of them.
struct RenderHints {
    std::optional<std::string> color_mode;  ///< "scene", "speed", "mass" (or "tag")
    std::optional<bool> trails;             ///< draw trails for tagged discs
    std::optional<bool> overlays;           ///< counters and plots on screen
    std::optional<double> duration;         ///< seconds of video
    std::optional<double> speed;            ///< simulation time units per second of video
    std::optional<double> dt;               ///< time-driven quantum
    /// Where each numeric hint was written, "file:line: render.dt", so that a hint the CLI
    /// refuses (too long, too much work) is named where the user can fix it; empty = unknown.
    std::string duration_at;
    std::string speed_at;
    std::string dt_at;
};

struct Scene {
    std::string name;   ///< short name (file stem or built-in name), used for default outputs
    std::string title;  ///< human title shown on screen
    Box box;
    std::vector<Disc> discs;
    RenderHints render;
};

}  // namespace collide
