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
    // The frame just drawn: its layout and the strings drawn in it. Before any frame, the
    // rectangles alone.
    if (impl_->builder.layout().panels.size() == frame.panels.size() &&
        !impl_->builder.layout().panels.empty()) {
        return render::layout_json(impl_->builder.layout(), config().overlays, config().width,
                                   config().height, &impl_->builder.drawn_text());
    }
    return render::layout_json(impl_->builder.layout_for(frame), config().overlays, config().width,
                               config().height);
}

Backend Renderer::backend() const noexcept {
    return impl_->target.backend();
}
const RenderConfig& Renderer::config() const noexcept {
    return impl_->builder.config();
}

}  // namespace collide::render
