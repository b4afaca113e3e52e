// OSMesa backend: a core-profile context on Mesa's software rasteriser (llvmpipe), no display
// and no GPU needed. The renderer draws into its own FBO, so the OSMesa colour buffer is only
// what OSMesaMakeCurrent insists on binding: we keep it tiny.
#include <GL/osmesa.h>

#include <array>
#include <memory>
#include <type_traits>
#include <vector>

#include "backends.hpp"
#include "collide/error.hpp"

namespace collide::render {
namespace {

// OSMesaMakeCurrent needs a colour buffer; every frame goes to the renderer's FBO instead.
constexpr int binding_buffer_size = 16;

class OsmesaContext final : public Context {
  public:
    OsmesaContext() {
        const std::array<int, 15> attributes = {OSMESA_FORMAT,
                                                OSMESA_RGBA,
                                                OSMESA_DEPTH_BITS,
                                                0,
                                                OSMESA_STENCIL_BITS,
                                                0,
                                                OSMESA_ACCUM_BITS,
                                                0,
                                                OSMESA_PROFILE,
                                                OSMESA_CORE_PROFILE,
                                                OSMESA_CONTEXT_MAJOR_VERSION,
                                                3,
                                                OSMESA_CONTEXT_MINOR_VERSION,
                                                3,
                                                0};
        // Owned from here on, so that a failure below (make_current) does not leak it.
        context_.reset(OSMesaCreateContextAttribs(attributes.data(), nullptr));
        if (context_ == nullptr) {
            throw_runtime_error("OSMesa: failed to create a GL 3.3 core-profile context");
        }
        buffer_.assign(static_cast<std::size_t>(binding_buffer_size) * binding_buffer_size, 0);
        make_current();
    }
    OsmesaContext(const OsmesaContext&) = delete;
    OsmesaContext& operator=(const OsmesaContext&) = delete;

    [[nodiscard]] Backend backend() const noexcept override { return Backend::osmesa; }

    void make_current() override {
        if (!OSMesaMakeCurrent(context_.get(), buffer_.data(), GL_UNSIGNED_BYTE,
                               binding_buffer_size, binding_buffer_size)) {
            throw_runtime_error("OSMesa: failed to make the context current");
        }
    }

    [[nodiscard]] GlProcLoader proc_loader() const noexcept override {
        return [](const char* name) -> GlProc { return OSMesaGetProcAddress(name); };
    }

  private:
    struct Destroy {
        void operator()(OSMesaContext context) const noexcept { OSMesaDestroyContext(context); }
    };
    std::unique_ptr<std::remove_pointer_t<OSMesaContext>, Destroy> context_;
    std::vector<std::uint32_t> buffer_;  // RGBA8 pixels of the binding buffer
};

}  // namespace

std::unique_ptr<Context> make_osmesa_context() {
    return std::make_unique<OsmesaContext>();
}

}  // namespace collide::render
