#include "collide/render/context.hpp"

#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <iostream>
#include <string>

#include "backends.hpp"
#include "collide/error.hpp"
#include "collide/printable.hpp"

namespace collide::render {
namespace {

// What a software GL context needs, in MiB (gl_headroom_bytes).
constexpr std::size_t gl_headroom_base_mib = 128;
constexpr std::size_t gl_headroom_mib_per_core = 8;

std::string names_of(const std::vector<Backend>& backends) {
    std::string out;
    for (const Backend backend : backends) {
        if (!out.empty()) out += ", ";
        out += backend_name(backend);
    }
    return out;
}

/// The offscreen backend `automatic` stands for in this build.
Backend default_offscreen() {
    return is_available(Backend::osmesa) ? Backend::osmesa : Backend::egl;
}

/// The address space a software GL context (Mesa's llvmpipe, under OSMesa, EGL and Xvfb's GLX)
/// takes on top of the program before it draws a frame: LLVM compiling the shaders, the
/// rasteriser's threads (one 8 MiB stack each, one per core) and their tiles. Measured: about
/// 100 MiB plus 8 MiB a core at 640x360; see require_gl_headroom.
std::size_t gl_headroom_bytes() {
    constexpr std::size_t mib = 1024 * 1024;
    const long cores = sysconf(_SC_NPROCESSORS_ONLN);
    return (gl_headroom_base_mib +
            gl_headroom_mib_per_core * static_cast<std::size_t>(std::clamp(cores, 1L, 64L))) *
           mib;
}

/// LLVM does not survive an allocation that fails: under an address-space limit (`ulimit -v`)
/// near what a run needs, llvmpipe's shader compilation crashed (SIGSEGV, "double free") instead
/// of failing. So before any context, its headroom must be there: reserved (no memory is
/// touched) and given back at once, or the run stops here with the one "out of memory" words.
/// What this promises: the limit left that much room at this moment; a limit so near that the
/// frames and the encoder outgrow it later still fails as any allocation does.
void require_gl_headroom() {
    rlimit limit{};
    if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return;
    const std::size_t headroom = gl_headroom_bytes();
    void* probe =
        mmap(nullptr, headroom, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
    if (probe != MAP_FAILED) {
        munmap(probe, headroom);
        return;
    }
    throw_runtime_error("out of memory: the address-space limit (ulimit -v) of " +
                        std::to_string(limit.rlim_cur / (1024 * 1024)) +
                        " MB leaves less than the " + std::to_string(headroom / (1024 * 1024)) +
                        " MB the software GL renderer needs to start; raise the limit, or use "
                        "fewer discs or a smaller frame");
}

}  // namespace

void emit_notice(const NoticeSink& notice, const std::string& line) {
    if (notice) {
        notice(line);
    } else {
        std::cerr << printable_text(line) << '\n';
    }
}

std::unique_ptr<Context> make_context(Backend backend, int width, int height,
                                      const NoticeSink& notice) {
    if (width <= 0 || height <= 0) {
        throw_input_error("render context: width and height must be positive, got " +
                          std::to_string(width) + "x" + std::to_string(height));
    }
    if (!is_available(backend)) {
        throw_input_error(
            "GL backend '" + std::string(backend_name(backend)) +
            "' is not built into this collide (available: " + names_of(available_backends()) + ")");
    }
    require_gl_headroom();
    if (backend == Backend::glfw) {
        std::string why;
        if (auto context = try_make_glfw_context(width, height, why)) return context;
        backend = default_offscreen();
        emit_notice(notice, "notice: GLFW unavailable (" + why + "); rendering with " +
                                std::string(backend_name(backend)));
    }
    if (backend == Backend::automatic) backend = default_offscreen();
    switch (backend) {
        case Backend::osmesa:
#if COLLIDE_HAVE_OSMESA
            return make_osmesa_context();
#else
            break;
#endif
        case Backend::egl:
        case Backend::egl_device:
#if COLLIDE_HAVE_EGL
            return make_egl_context(backend);
#else
            break;
#endif
        case Backend::automatic:
        case Backend::glfw:
            break;
    }
    throw_runtime_error("render context: no backend for '" + std::string(backend_name(backend)) +
                        "'");
}

}  // namespace collide::render
