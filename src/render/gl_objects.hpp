#pragma once
// Internal: the GL function table of one context and move-only RAII owners of GL objects.
// Every owner keeps a pointer to the function table of the context that created it; the owner
// must die before that context (the Renderer declares its context first for that reason).

#include <glad/gl.h>

#include <string>

namespace collide::render {

/// A GL object name plus how to delete it. Move-only; deleting needs the context current.
class GlObject {
  public:
    using Deleter = void (*)(const GladGLContext&, GLuint);

    GlObject() = default;
    GlObject(const GladGLContext& gl, GLuint name, Deleter deleter) noexcept
        : gl_(&gl), name_(name), deleter_(deleter) {}
    GlObject(GlObject&& other) noexcept { swap(other); }
    GlObject& operator=(GlObject&& other) noexcept {
        GlObject(std::move(other)).swap(*this);
        return *this;
    }
    GlObject(const GlObject&) = delete;
    GlObject& operator=(const GlObject&) = delete;
    ~GlObject() {
        if (name_ != 0) deleter_(*gl_, name_);
    }

    [[nodiscard]] GLuint get() const noexcept { return name_; }

  private:
    void swap(GlObject& other) noexcept {
        std::swap(gl_, other.gl_);
        std::swap(name_, other.name_);
        std::swap(deleter_, other.deleter_);
    }

    const GladGLContext* gl_ = nullptr;
    GLuint name_ = 0;
    Deleter deleter_ = nullptr;
};

[[nodiscard]] GlObject make_buffer(const GladGLContext& gl);
[[nodiscard]] GlObject make_vertex_array(const GladGLContext& gl);
[[nodiscard]] GlObject make_texture(const GladGLContext& gl);
[[nodiscard]] GlObject make_framebuffer(const GladGLContext& gl);
[[nodiscard]] GlObject make_renderbuffer(const GladGLContext& gl);
/// Compiles and links a program; throws collide::Error (runtime) with the GL info log, naming
/// `what` (e.g. "disc shader").
[[nodiscard]] GlObject make_program(const GladGLContext& gl, const char* vertex_source,
                                    const char* fragment_source, const std::string& what);

/// Throws collide::Error (runtime) naming `where` if GL recorded an error.
void check_gl(const GladGLContext& gl, const char* where);

}  // namespace collide::render
