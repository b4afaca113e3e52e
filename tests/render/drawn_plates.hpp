#pragma once
// What the lesson painter drew over one box, read back for the label tests: the plates of
// --layout-json's other_text (headings, replay labels), the box's layout to place discs in pixels,
// and whether a plate comes near a disc.

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "collide/render/renderer.hpp"
#include "layout.hpp"

namespace collide::render::test {

/// A text drawn outside the layout's lines, with its rectangle in pixels.
struct Plate {
    std::string text;
    RectF rect;
};

/// The plates of `frame`, the frame `renderer` drew last: other_text of its layout JSON.
inline std::vector<Plate> plates(const Renderer& renderer, const FrameContent& frame) {
    const nlohmann::json json = nlohmann::json::parse(renderer.layout_json(frame));
    std::vector<Plate> out;
    for (const auto& t : json["other_text"]) {
        const auto& r = t["rect"];
        out.push_back(
            {t["text"].get<std::string>(),
             {r[0].get<float>(), r[1].get<float>(), r[2].get<float>(), r[3].get<float>()}});
    }
    return out;
}

/// Whether rectangle r comes within `margin` pixels of the circle.
inline bool touches(RectF r, PointF c, float radius, float margin) {
    const float nx = std::clamp(c.x, r.x0, r.x1);
    const float ny = std::clamp(c.y, r.y0, r.y1);
    return std::hypot(nx - c.x, ny - c.y) < radius + margin;
}

/// The one panel of a lesson frame of `config`'s size showing `box`, as the renderer lays it out.
inline PanelLayout one_panel_layout(const RenderConfig& config, Box box) {
    LayoutInput in;
    in.width = config.width;
    in.height = config.height;
    in.boxes = {box};
    return lesson_layout(in).panels.at(0);
}

}  // namespace collide::render::test
