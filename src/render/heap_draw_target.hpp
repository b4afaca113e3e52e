#pragma once
// Internal: the heap renderer's drawing half behind one call. heap_view.cpp lays frames out and
// builds their DrawList on the CPU; heap_view_gl.cpp draws them through GlTarget. Apart, the
// layout (HeapRenderer::fits, which `collide heap` runs before it becomes collide-draw) links
// no GL.

#include <memory>

#include "collide/image.hpp"
#include "collide/render/context.hpp"
#include "draw_list.hpp"

namespace collide::render {

class HeapDrawTarget {
  public:
    virtual ~HeapDrawTarget() = default;
    /// Draws `list` and reads it back into `out` (width x height RGBA8, rows top-down).
    virtual void draw(const DrawList& list, Image& out) = 0;
};

/// A target that draws with GL in `context` (GlTarget). Throws as GlTarget's constructor.
[[nodiscard]] std::unique_ptr<HeapDrawTarget> make_gl_heap_target(int width, int height,
                                                                  std::unique_ptr<Context> context);

}  // namespace collide::render
