// The frame pipeline of the renderer: lay out panels and strip, build disc instances and overlay
// triangles on the CPU, then draw them with a handful of GL calls into an FBO and read it back.
#include "collide/render/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <optional>
#include <string>

#include "collide/error.hpp"
#include "frame_builder.hpp"
#include "gl_target.hpp"

namespace collide::render {

// ---------------------------------------------------------------------------------------------
// Config

void RenderConfig::validate() const {
    const auto fail = [](const char* field, const std::string& reason) {
        throw_input_error(std::string("render.") + field + ": " + reason);
    };
    const auto check_side = [&](const char* field, int side) {
        if (side < min_frame_side || side > max_frame_side) {
            fail(field, "must be in [" + std::to_string(min_frame_side) + ", " +
                            std::to_string(max_frame_side) + "], got " + std::to_string(side));
        }
    };
    check_side("width", width);
    check_side("height", height);
    if (!std::isfinite(speed_min) || speed_min < 0.0) fail("speed_min", "must be finite and >= 0");
    if (!std::isfinite(speed_max) || !(speed_max > speed_min)) {
        fail("speed_max", "must be finite and > speed_min");
    }
    if (!std::isfinite(mass_min) || !(mass_min > 0.0)) fail("mass_min", "must be finite and > 0");
    if (!std::isfinite(mass_max) || mass_max < mass_min) {
        fail("mass_max", "must be finite and >= mass_min");
    }
    if (trail_length < 2 || trail_length > 1024) {
        fail("trail_length", "must be in [2, 1024], got " + std::to_string(trail_length));
    }
    if (overlays != OverlayLevel::none && font_path.empty()) {
        fail("font_path", "must name a TrueType font");
    }
}

// ---------------------------------------------------------------------------------------------
// Renderer::Impl: the frame builder (CPU) feeding the GL target.

struct Renderer::Impl {
    FrameBuilder builder;
    GlTarget target;  // owns the context: destroyed first, its objects with it

    Impl(const RenderConfig& config, std::unique_ptr<Context> context)
        : builder(config), target(config.width, config.height, std::move(context)) {}

    void draw(const FrameContent& frame) { target.draw(builder.build(frame)); }
    void read_pixels(Image& out) { target.read_pixels(last_list(), out); }
    const DrawList& last_list() { return builder.draw_list(); }
};

// ---------------------------------------------------------------------------------------------
// Renderer

Renderer::Renderer(const RenderConfig& config, Backend backend, const NoticeSink& notice)
    : Renderer(config, [&] {
          config.validate();  // before creating a context for a config we would reject anyway
          return make_context(backend, config.width, config.height, notice);
      }()) {}

Renderer::Renderer(const RenderConfig& config, std::unique_ptr<Context> context)
    : impl_(std::make_unique<Impl>(config, std::move(context))) {}

Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

Image Renderer::render(const FrameContent& frame) {
    Image image;
    render(frame, image);
    return image;
}

void Renderer::render(const FrameContent& frame, Image& out) {
    impl_->draw(frame);
    impl_->read_pixels(out);
}

void Renderer::draw(const FrameContent& frame) {
    impl_->draw(frame);
}
void Renderer::read_pixels(Image& out) {
    impl_->read_pixels(out);
}

std::string Renderer::layout_json(const FrameContent& frame) const {
    return render::layout_json(impl_->builder.layout_for(frame), config().width, config().height);
}

Backend Renderer::backend() const noexcept {
    return impl_->target.backend();
}
const RenderConfig& Renderer::config() const noexcept {
    return impl_->builder.config();
}

}  // namespace collide::render
