// EGL backend: a GL 3.3 core context with no window system and no surface. On Mesa's surfaceless
// platform (EGL_MESA_platform_surfaceless) it runs on llvmpipe, like OSMesa, and gives the same
// pixels; on an EGL device (EGL_EXT_platform_device) it reaches a GPU. Mesa 25.1 removed OSMesa:
// this is the offscreen backend where it is gone. The renderer draws into its own FBO, so the
// context needs no surface at all (EGL_KHR_surfaceless_context).
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "backends.hpp"
#include "collide/error.hpp"

namespace collide::render {
namespace {

std::string egl_error_text() {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(eglGetError()));
    return std::string("EGL error ") + code;
}

[[noreturn]] void throw_egl_error(const std::string& what) {
    throw_runtime_error("EGL: " + what + " (" + egl_error_text() + ")");
}

/// Whether the space-separated extension string `list` names `extension`.
bool has_extension(const char* list, std::string_view extension) {
    if (list == nullptr) return false;
    const std::string_view all(list);
    for (std::size_t start = 0; start < all.size();) {
        const std::size_t end = std::min(all.find(' ', start), all.size());
        if (all.substr(start, end - start) == extension) return true;
        start = end + 1;
    }
    return false;
}

bool has_client_extension(std::string_view extension) {
    return has_extension(eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS), extension);
}

// ----------------------------------------------------------------------------------------------
// Devices (EGL_EXT_device_enumeration)

struct Device {
    EGLDeviceEXT handle = EGL_NO_DEVICE_EXT;
    bool hardware = false;  ///< a DRM device that is not Mesa's software device
};

std::vector<Device> list_devices() {
    if (!has_client_extension("EGL_EXT_device_enumeration") ||
        !has_client_extension("EGL_EXT_platform_device")) {
        return {};
    }
    const auto query_devices =
        reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    const auto query_string = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
        eglGetProcAddress("eglQueryDeviceStringEXT"));
    if (query_devices == nullptr || query_string == nullptr) return {};
    EGLint count = 0;
    if (query_devices(0, nullptr, &count) != EGL_TRUE || count <= 0) return {};
    std::vector<EGLDeviceEXT> handles(static_cast<std::size_t>(count));
    if (query_devices(count, handles.data(), &count) != EGL_TRUE) return {};
    std::vector<Device> devices;
    for (EGLint i = 0; i < count; ++i) {
        const char* extensions = query_string(handles[static_cast<std::size_t>(i)], EGL_EXTENSIONS);
        devices.push_back({handles[static_cast<std::size_t>(i)],
                           has_extension(extensions, "EGL_EXT_device_drm") &&
                               !has_extension(extensions, "EGL_MESA_device_software")});
    }
    return devices;
}

/// The device to render on: the first hardware GPU; with `any`, else the first device at all.
EGLDeviceEXT pick_device(bool any) {
    const std::vector<Device> devices = list_devices();
    for (const Device& device : devices) {
        if (device.hardware) return device.handle;
    }
    if (any && !devices.empty()) return devices.front().handle;
    return EGL_NO_DEVICE_EXT;
}

// ----------------------------------------------------------------------------------------------
// Displays

/// The initialised EGL display of `platform` and `native`. EGL displays are process-wide (the same
/// platform and native display give the same handle to every caller), so they are initialised
/// once and left initialised until the process exits: eglTerminate would pull a display from under
/// every other context on it, and each re-initialisation loads the driver again (which
/// eglTerminate unloads, leaving its allocations unnamed for LeakSanitizer).
EGLDisplay initialised_display(EGLenum platform, void* native) {
    // Mirrors EGL's own process-global display table; this is the one place that does.
    static std::mutex mutex;
    static std::set<EGLDisplay> initialised;
    const std::lock_guard lock(mutex);
    const EGLDisplay display = eglGetPlatformDisplay(platform, native, nullptr);
    if (display == EGL_NO_DISPLAY) throw_egl_error("no display on this platform");
    if (initialised.count(display) == 0) {
        EGLint major = 0;
        EGLint minor = 0;
        if (eglInitialize(display, &major, &minor) != EGL_TRUE) {
            throw_egl_error("cannot initialise the display");
        }
        initialised.insert(display);
    }
    return display;
}

// ----------------------------------------------------------------------------------------------
// The context

EGLConfig choose_config(EGLDisplay display) {
    // No surface is ever made, so any config that renders GL will do; none at all where allowed.
    if (has_extension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_no_config_context")) {
        return EGL_NO_CONFIG_KHR;
    }
    const EGLint attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (eglChooseConfig(display, attributes, &config, 1, &count) != EGL_TRUE || count < 1) {
        throw_egl_error("no config renders desktop OpenGL");
    }
    return config;
}

class EglContext final : public Context {
  public:
    EglContext(EGLDisplay display, Backend backend) : display_(display), backend_(backend) {
        const EGLDisplay dpy = display_;
        if (!has_extension(eglQueryString(dpy, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context")) {
            throw_runtime_error(
                "EGL: the display cannot make a context current without a "
                "surface (EGL_KHR_surfaceless_context)");
        }
        if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE) throw_egl_error("no desktop OpenGL");
        const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                     3,
                                     EGL_CONTEXT_MINOR_VERSION,
                                     3,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_NONE};
        context_ = eglCreateContext(dpy, choose_config(dpy), EGL_NO_CONTEXT, attributes);
        if (context_ == EGL_NO_CONTEXT) {
            throw_egl_error("failed to create a GL 3.3 core-profile context");
        }
        make_current();
    }
    ~EglContext() override {
        if (eglGetCurrentContext() == context_) {
            eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        }
        eglDestroyContext(display_, context_);
    }
    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;

    [[nodiscard]] Backend backend() const noexcept override { return backend_; }

    void make_current() override {
        if (eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_) != EGL_TRUE) {
            throw_egl_error("failed to make the context current");
        }
    }

    [[nodiscard]] GlProcLoader proc_loader() const noexcept override {
        // Mesa resolves core GL functions here too (EGL_KHR_get_all_proc_addresses).
        return [](const char* name) -> GlProc { return eglGetProcAddress(name); };
    }

  private:
    EGLDisplay display_;  // process-wide, never terminated (initialised_display)
    Backend backend_;
    EGLContext context_ = EGL_NO_CONTEXT;
};

std::unique_ptr<Context> make_on_device(EGLDeviceEXT device) {
    return std::make_unique<EglContext>(initialised_display(EGL_PLATFORM_DEVICE_EXT, device),
                                        Backend::egl_device);
}

}  // namespace

std::unique_ptr<Context> make_egl_context(Backend backend) {
    if (backend == Backend::egl_device) {
        const EGLDeviceEXT device = pick_device(/*any=*/true);
        if (device == EGL_NO_DEVICE_EXT) {
            throw_runtime_error("EGL: no device to render on (EGL_EXT_platform_device)");
        }
        return make_on_device(device);
    }
    // A hardware GPU when there is one; else Mesa's surfaceless platform (llvmpipe).
    if (const EGLDeviceEXT gpu = pick_device(/*any=*/false); gpu != EGL_NO_DEVICE_EXT) {
        return make_on_device(gpu);
    }
    if (!has_client_extension("EGL_MESA_platform_surfaceless")) {
        throw_runtime_error(
            "EGL: neither a GPU device nor Mesa's surfaceless platform "
            "(EGL_MESA_platform_surfaceless) is available");
    }
    return std::make_unique<EglContext>(
        initialised_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY), Backend::egl);
}

}  // namespace collide::render
