#include "collide/render/context.hpp"

#include <iostream>
#include <string>

#include "backends.hpp"
#include "collide/error.hpp"

namespace collide::render {

std::string_view backend_name(Backend backend) noexcept {
    switch (backend) {
        case Backend::automatic:
            return "auto";
        case Backend::osmesa:
            return "osmesa";
        case Backend::glfw:
            return "glfw";
    }
    return "auto";
}

Backend parse_backend(std::string_view text, std::string_view option) {
    if (text == "auto") return Backend::automatic;
    if (text == "osmesa") return Backend::osmesa;
    if (text == "glfw") return Backend::glfw;
    throw_input_error(std::string(option) + ": unknown backend '" + std::string(text) +
                      "' (expected osmesa, glfw or auto)");
}

void emit_notice(const NoticeSink& notice, const std::string& line) {
    if (notice) {
        notice(line);
    } else {
        std::cerr << line << '\n';
    }
}

std::unique_ptr<Context> make_context(Backend backend, int width, int height,
                                      const NoticeSink& notice) {
    if (width <= 0 || height <= 0) {
        throw_input_error("render context: width and height must be positive, got " +
                          std::to_string(width) + "x" + std::to_string(height));
    }
    if (backend == Backend::glfw) {
        std::string why;
        if (auto context = try_make_glfw_context(width, height, why)) return context;
        emit_notice(notice, "notice: GLFW unavailable (" + why + "); rendering with OSMesa");
    }
    return make_osmesa_context(width, height);
}

}  // namespace collide::render
