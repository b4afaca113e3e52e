// The words of scene messages, shared by the TOML reader's files: numbers as they are printed,
// long values clipped, key lists, and the jam a row of spheres makes. Private to src/scene.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "collide/scene/load.hpp"

namespace collide::toml_text {

/// The keys each table of a scene file accepts (an unknown one is refused with a suggestion).
namespace keys {

using Keys = std::vector<std::string>;

inline const Keys top_keys = {"title",    "description", "include",   "box",    "disc",
                              "generate", "render",      "dimension", "sphere", "fcc"};
inline const Keys box_keys = {"width", "height", "depth", "boundary"};
inline const Keys sphere_keys = {"position", "velocity", "radius", "mass", "color", "tag"};
inline const Keys fcc_keys = {"cells", "packing_fraction", "mass", "temperature", "color", "seed",
                              "tag"};
inline const Keys generate3_keys = {"count", "packing_fraction", "radius", "mass", "temperature",
                                    "speed", "region",           "color",  "seed", "tag"};
inline const Keys disc_keys = {"position", "velocity", "radius", "mass", "color", "tag"};
inline const Keys generate_keys = {"count", "packing_fraction", "radius", "mass", "temperature",
                                   "speed", "region",           "color",  "seed", "tag"};
inline const Keys render_keys = {"color_mode", "trails",    "overlays",   "duration",
                                 "speed",      "dt",        "theme",      "caption",
                                 "captions",   "histogram", "replay",     "camera",
                                 "projection", "slab",      "replay_tag", "questions"};
/// [render] keys of one dimension only: the camera of a 3D scene; trails and replays, which
/// spheres do not have.
inline const Keys render_keys3 = {"camera", "projection", "slab"};
inline const Keys render_keys2 = {"trails", "replay", "replay_tag", "questions"};
inline const Keys caption_keys = {"at", "text", "hold", "event", "time"};
inline const Keys question_keys = {"at", "kind", "text", "think"};

}  // namespace keys

/// A number as messages print it (6 significant digits).
std::string num(double v);
/// A value as echoed in a message: whole when short, else its start and its length.
std::string clipped(const std::string& text);
/// Keys joined with ", ".
std::string joined(const std::vector<std::string>& keys);

/// A sphere that cannot move the way its velocity says: its index and why (sphere_jams.cpp).
struct SphereJam {
    std::size_t sphere = 0;
    std::string message;
};
/// The first jammed sphere among those of `s` (walled boxes only), given the touching pairs.
std::optional<SphereJam> find_sphere_jam(
    const SphereScene& s, const std::vector<std::pair<std::size_t, std::size_t>>& contacts);

}  // namespace collide::toml_text
