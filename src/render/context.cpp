#include "collide/render/context.hpp"

#include <array>
#include <iostream>
#include <string>

#include "backends.hpp"
#include "collide/error.hpp"
#include "collide/named_values.hpp"
#include "collide/printable.hpp"

namespace collide::render {
namespace {

constexpr std::array<NamedValue<Backend>, 5> backend_names{{{"auto", Backend::automatic},
                                                            {"osmesa", Backend::osmesa},
                                                            {"egl", Backend::egl},
                                                            {"egl-device", Backend::egl_device},
                                                            {"glfw", Backend::glfw}}};

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

}  // namespace

std::string_view backend_name(Backend backend) noexcept {
    return name_of(backend, backend_names, "auto");
}

Backend parse_backend(std::string_view text, std::string_view option) {
    return parse_named(text, option, backend_names, "a GL backend");
}

bool is_available(Backend backend) {
    switch (backend) {
        case Backend::osmesa:
            return COLLIDE_HAVE_OSMESA != 0;
        case Backend::egl:
        case Backend::egl_device:
            return COLLIDE_HAVE_EGL != 0;
        case Backend::automatic:
        case Backend::glfw:
            return true;
    }
    return false;
}

std::vector<Backend> available_backends() {
    std::vector<Backend> out;
    for (const NamedValue<Backend>& entry : backend_names) {
        if (is_available(entry.value)) out.push_back(entry.value);
    }
    return out;
}

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
