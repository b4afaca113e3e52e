#pragma once
// Internal: the concrete context backends behind make_context / open_preview.

#include <memory>
#include <string>

#include "collide/render/context.hpp"

namespace collide::render {

/// OSMesa core-profile context. Throws collide::Error (runtime) when Mesa refuses.
[[nodiscard]] std::unique_ptr<Context> make_osmesa_context(int width, int height);

/// A hidden GLFW window's context, or null when GLFW cannot initialise (no display); `why`
/// then says what GLFW reported. Throws collide::Error (runtime) for other failures.
[[nodiscard]] std::unique_ptr<Context> try_make_glfw_context(int width, int height,
                                                             std::string& why);

/// Sends `line` to the sink, or to stderr when the sink is empty.
void emit_notice(const NoticeSink& notice, const std::string& line);

}  // namespace collide::render
