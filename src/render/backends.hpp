#pragma once
// Internal: the concrete context backends behind make_context / open_preview.

#include <memory>
#include <string>

#include "collide/render/context.hpp"

namespace collide::render {

/// OSMesa core-profile context (built when COLLIDE_HAVE_OSMESA). Throws collide::Error (runtime)
/// when Mesa refuses. No size: every frame goes to the renderer's own framebuffer.
[[nodiscard]] std::unique_ptr<Context> make_osmesa_context();

/// EGL core-profile context without a surface (built when COLLIDE_HAVE_EGL): Backend::egl takes a
/// hardware GPU device when there is one, else Mesa's surfaceless platform; Backend::egl_device
/// any device. Throws collide::Error (runtime) when EGL cannot make one.
[[nodiscard]] std::unique_ptr<Context> make_egl_context(Backend backend);

/// A hidden GLFW window's context, or null when GLFW cannot initialise (no display); `why`
/// then says what GLFW reported. Throws collide::Error (runtime) for other failures.
[[nodiscard]] std::unique_ptr<Context> try_make_glfw_context(int width, int height,
                                                             std::string& why);

/// Sends `line` to the sink, or to stderr when the sink is empty.
void emit_notice(const NoticeSink& notice, const std::string& line);

}  // namespace collide::render
