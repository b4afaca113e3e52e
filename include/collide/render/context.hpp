#pragma once
/// \file
/// GL context backends behind one narrow interface: create (make_context), make current, hand out
/// GL entry points, destroy (the destructor). Every backend renders into a framebuffer object the
/// renderer owns, so the drawing and readback path is identical whichever backend is in use; an
/// EGL-surfaceless backend (Mesa >= 25.1 drops OSMesa) only has to implement this interface.

#include <functional>
#include <memory>
#include <string>
#include <string_view>

namespace collide::render {

/// Which GL context backend to use.
enum class Backend {
    automatic,  ///< OSMesa (no display needed, no GPU): the default for video
    osmesa,     ///< OSMesa 3.3+ core profile rendering into a buffer we own (llvmpipe)
    glfw,       ///< a hidden GLFW window's context (needs a display, e.g. Xvfb); falls back to
                ///< OSMesa with a one-line notice when no display is available
};

/// "osmesa" / "glfw" / "auto".
[[nodiscard]] std::string_view backend_name(Backend backend) noexcept;

/// Parses "osmesa", "glfw" or "auto"; throws collide::Error (input) naming `option` otherwise.
[[nodiscard]] Backend parse_backend(std::string_view text, std::string_view option = "--backend");

/// Receives one-line notices (e.g. "GLFW: no display, falling back to OSMesa"). An empty sink
/// means "write the line to stderr".
using NoticeSink = std::function<void(const std::string&)>;

/// A GL entry point and the loader that finds one by name (the signature of
/// OSMesaGetProcAddress / glfwGetProcAddress / eglGetProcAddress).
using GlProc = void (*)();
using GlProcLoader = GlProc (*)(const char* name);

/// An owned GL 3.3+ core-profile context. Move-only by ownership (held in a unique_ptr);
/// destroying it destroys the context, so GL objects must be destroyed first (the Renderer
/// declares its GL objects after its context for exactly that reason).
class Context {
  public:
    Context() = default;
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;
    virtual ~Context() = default;

    /// The backend actually in use (after any fallback).
    [[nodiscard]] virtual Backend backend() const noexcept = 0;
    /// Makes this context current on the calling thread. Throws collide::Error (runtime).
    virtual void make_current() = 0;
    /// The function the GL loader uses to resolve entry points of this context.
    [[nodiscard]] virtual GlProcLoader proc_loader() const noexcept = 0;
};

/// Creates a context able to render frames of `width` x `height` pixels (the renderer draws into
/// an FBO of that size). Backend::glfw without a display falls back to OSMesa with one notice,
/// never failing for that reason. Throws collide::Error (runtime) when no context can be made,
/// (input) when width/height are not positive.
[[nodiscard]] std::unique_ptr<Context> make_context(Backend backend, int width, int height,
                                                    const NoticeSink& notice = {});

}  // namespace collide::render
