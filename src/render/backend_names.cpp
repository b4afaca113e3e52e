// The backends' names and which of them this build has: apart from context.cpp, which creates
// the contexts, so that `collide` checks --gl before it execs collide-draw without linking GL.

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "collide/named_values.hpp"
#include "collide/render/context.hpp"

namespace collide::render {
namespace {

constexpr std::array<NamedValue<Backend>, 5> backend_names{{{"auto", Backend::automatic},
                                                            {"osmesa", Backend::osmesa},
                                                            {"egl", Backend::egl},
                                                            {"egl-device", Backend::egl_device},
                                                            {"glfw", Backend::glfw}}};

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

}  // namespace collide::render
