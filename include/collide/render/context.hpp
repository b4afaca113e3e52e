#pragma once
/// \file
/// GL context backends behind one narrow interface: create (make_context), make current, hand out
/// GL entry points, destroy (the destructor). Every backend renders into a framebuffer object the
/// renderer owns, so the drawing and readback path is identical whichever backend is in use:
/// OSMesa, EGL (surfaceless or on a device; where Mesa >= 25.1 dropped OSMesa) and GLFW.

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace collide::render {

/// Which GL context backend to use. Which ones a build has depends on the libraries found at
/// configure time (available_backends()); GLFW is always there.
enum class Backend {
    automatic,   ///< the offscreen default: OSMesa where built, else EGL
    osmesa,      ///< OSMesa 3.3+ core profile rendering into a buffer we own (llvmpipe)
    egl,         ///< EGL without a window system: a hardware GPU device when there is one, else
                 ///< Mesa's surfaceless platform (llvmpipe, same pixels as OSMesa)
    egl_device,  ///< EGL on a device (EGL_EXT_platform_device), even Mesa's software one
    glfw,        ///< a hidden GLFW window's context (needs a display, e.g. Xvfb); falls back to
                 ///< the automatic backend with a one-line notice when no display is available
};

/// "auto" / "osmesa" / "egl" / "egl-device" / "glfw".
[[nodiscard]] std::string_view backend_name(Backend backend) noexcept;

/// Parses a backend name (see backend_name); throws collide::Error (input) naming `option` and
/// listing the names otherwise.
[[nodiscard]] Backend parse_backend(std::string_view text, std::string_view option = "--gl");

/// The backends this build can create, "auto" first (what --gl accepts here).
[[nodiscard]] std::vector<Backend> available_backends();

/// Whether this build can create `backend`.
[[nodiscard]] bool is_available(Backend backend);

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
/// an FBO of that size). Backend::glfw without a display falls back to the automatic backend with
/// one notice, never failing for that reason. Throws collide::Error: (input) when width/height
/// are not positive or `backend` is not built in (the message lists those that are), (runtime)
/// when no context can be made.
[[nodiscard]] std::unique_ptr<Context> make_context(Backend backend, int width, int height,
                                                    const NoticeSink& notice = {});

}  // namespace collide::render
