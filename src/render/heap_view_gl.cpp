// The heap renderer's GL half: its context and GlTarget (heap_draw_target.hpp). The layout, in
// heap_view.cpp, links no GL.
#include <memory>
#include <utility>

#include "collide/render/heap_view.hpp"
#include "gl_target.hpp"
#include "heap_draw_target.hpp"

namespace collide::render {

namespace {

class GlHeapTarget final : public HeapDrawTarget {
  public:
    GlHeapTarget(int width, int height, std::unique_ptr<Context> context)
        : target_(width, height, std::move(context)) {}

    void draw(const DrawList& list, Image& out) override {
        target_.draw(list);
        target_.read_pixels(list, out);
    }

  private:
    GlTarget target_;
};

}  // namespace

std::unique_ptr<HeapDrawTarget> make_gl_heap_target(int width, int height,
                                                    std::unique_ptr<Context> context) {
    return std::make_unique<GlHeapTarget>(width, height, std::move(context));
}

HeapRenderer::HeapRenderer(const HeapViewConfig& config, Backend backend, const NoticeSink& notice)
    : HeapRenderer(config, [&] {
          config.validate();  // before creating a context for a config we would reject anyway
          return make_gl_heap_target(config.width, config.height,
                                     make_context(backend, config.width, config.height, notice));
      }()) {}

}  // namespace collide::render
