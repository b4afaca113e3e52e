// Issue 44 item 4: the boxes fill the frame. Every built-in 2D scene at every preset, read back
// from --layout-json (the thumbnail path lays a frame out as the video does).
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../support/temp_dir.hpp"
#include "run_collide.hpp"
#include "thumbnail_layout.hpp"

using collide::test::run_collide;
using collide::test::TempDir;

namespace {

const std::vector<std::string> scenes_2d = {"billiards",      "brownian",  "dense-fluid",
                                            "diffusion",      "gas",       "maxwell-boltzmann",
                                            "newtons-cradle", "tunnelling"};

struct Variant {
    const char* options;
    double min_share;  ///< the boxes' (and a large plot's) area over the frame's
};

double area(const nlohmann::json& rect) {
    return (rect.at(2).get<double>() - rect.at(0).get<double>()) *
           (rect.at(3).get<double>() - rect.at(1).get<double>());
}

/// The boxes' share of the frame; in maxwell-boltzmann, whose subject is the histogram, the
/// boxes and the histogram together.
double boxes_share(const nlohmann::json& layout, const std::string& scene) {
    double boxes = 0.0;
    for (const nlohmann::json& panel : layout.at("panels")) boxes += area(panel.at("box"));
    if (scene == "maxwell-boltzmann" && layout.contains("plot")) boxes += area(layout.at("plot"));
    return boxes / (layout.at("width").get<double>() * layout.at("height").get<double>());
}

}  // namespace

void check_share(const TempDir& dir, const std::string& scene, const char* preset,
                 const Variant& variant) {
    CAPTURE(preset);
    CAPTURE(scene);
    CAPTURE(variant.options);
    const nlohmann::json layout = thumbnail_layout(dir, scene, preset, variant.options);
    CHECK(boxes_share(layout, scene) >= variant.min_share);
    // No text was shrunk to make room: capitals >= 2.8 % of the frame height.
    const double min_cap = 0.028 * layout.at("height").get<double>() - 0.05;
    for (const nlohmann::json& slot : layout.at("text"))
        CHECK(slot.at("cap_height").get<double>() >= min_cap);
}

TEST_CASE("the boxes fill the frame: >= 55 % of 16:9 in every 2D scene at every preset") {
    TempDir dir("layout_share");
    for (const char* preset : {"l", "m", "h", "k"})
        for (const std::string& scene : scenes_2d) check_share(dir, scene, preset, {"", 0.55});
}

TEST_CASE("one box beside its text, and the queue strip: the boxes' share at every preset") {
    // The layout depends on the frame's size and the scene's lines only: the three presets of
    // 16:9 and both modes. One square box cannot fill a 16:9 frame: it takes the frame's height.
    TempDir dir("layout_share_queue");
    for (const char* preset : {"l", "m", "h"}) {
        for (const std::string& scene : scenes_2d) {
            check_share(dir, scene, preset, {"--mode event", 0.45});
            check_share(dir, scene, preset, {"--queue --mode event", 0.45});
            check_share(dir, scene, preset, {"--queue --code --mode event", 0.45});
            // Two boxes over the queue strip keep 35 % under three rows of text too (the
            // time-driven panel's note where dt is longer than a frame: tunnelling, every scene
            // at -q h); with --code the listing stands right of them, the column under it.
            check_share(dir, scene, preset, {"--queue", 0.35});
            check_share(dir, scene, preset, {"--queue --code", 0.35});
        }
    }
}
