// Context backends: OSMesa by default; GLFW when a display exists (same pixels as OSMesa); without
// a display a one-line notice and OSMesa, never a failure. The display-dependent tests run under
// `xvfb-run -a` through extra ctest entries (tests/CMakeLists.txt) and skip when DISPLAY is unset.
#include <doctest/doctest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "../support/skip.hpp"
#include "collide/error.hpp"
#include "collide/render/preview.hpp"
#include "render_fixtures.hpp"

namespace collide::render {
namespace {

bool have_display() {
    const char* display = std::getenv("DISPLAY");
    return display != nullptr && *display != '\0';
}

FrameContent sample_frame(const Snapshot& a, const Snapshot& b) {
    FrameContent frame;
    frame.panels = {{&a, "Time-driven", {"steps 10"}}, {&b, "Event-driven", {"events 99"}}};
    frame.time_text = "t = 1.00";
    frame.energy_drift = {{{0.0, 0.0}, {1.0, 0.02}}, {{0.0, 0.0}, {1.0, 0.0}}};
    return frame;
}

TEST_CASE("the default backend is OSMesa and needs no display") {
    Renderer renderer(test::small_config(false));
    CHECK(renderer.backend() == Backend::osmesa);
    CHECK(backend_name(renderer.backend()) == "osmesa");
    CHECK(parse_backend("glfw") == Backend::glfw);
    CHECK_THROWS_AS((void)parse_backend("vulkan"), Error);
    CHECK_THROWS_AS((void)make_context(Backend::osmesa, 0, 10), Error);
}

TEST_CASE("without a display, GLFW falls back to OSMesa with one notice") {
    ::unsetenv("DISPLAY");
    ::unsetenv("WAYLAND_DISPLAY");
    std::vector<std::string> notices;
    const NoticeSink sink = [&](const std::string& line) { notices.push_back(line); };
    Renderer renderer(test::small_config(false), Backend::glfw, sink);
    CHECK(renderer.backend() == Backend::osmesa);
    REQUIRE(notices.size() == 1);
    CHECK(notices[0].find("OSMesa") != std::string::npos);
    CHECK(notices[0].find('\n') == std::string::npos);
    // And it renders.
    const Snapshot s = test::gas_snapshot(10, 0.05, {1.0, 1.0, Boundary::walls}, 2);
    FrameContent frame;
    frame.panels = {{&s, "", {}}};
    CHECK(renderer.render(frame).width == 320);

    notices.clear();
    const auto preview = open_preview(320, 180, "collide", sink);
    CHECK(preview == nullptr);
    CHECK(notices.size() == 1);
}

TEST_CASE("display: the GLFW backend produces the same pixels as OSMesa") {
    if (!have_display()) {
        COLLIDE_SKIP_TEST("DISPLAY is not set (the xvfb ctest entry runs this under xvfb-run)");
    }
    const Snapshot a = test::gas_snapshot(80, 0.03, {1.0, 1.0, Boundary::walls}, 4);
    const Snapshot b = test::gas_snapshot(80, 0.03, {1.0, 1.0, Boundary::periodic}, 5);
    const RenderConfig config = test::small_config(true);
    std::vector<std::string> notices;
    const NoticeSink sink = [&](const std::string& line) { notices.push_back(line); };
    Image from_glfw;
    {
        Renderer glfw(config, Backend::glfw, sink);
        REQUIRE_MESSAGE(glfw.backend() == Backend::glfw, "GLFW did not start on DISPLAY");
        from_glfw = glfw.render(sample_frame(a, b));
    }
    Renderer osmesa(config, Backend::osmesa);
    const Image from_osmesa = osmesa.render(sample_frame(a, b));
    test::dump_if_requested(from_glfw, "context_glfw");
    CHECK(notices.empty());
    REQUIRE(from_glfw.rgba.size() == from_osmesa.rgba.size());
    CHECK(from_glfw.rgba == from_osmesa.rgba);
}

TEST_CASE("display: the preview window shows frames") {
    if (!have_display()) {
        COLLIDE_SKIP_TEST("DISPLAY is not set (the xvfb ctest entry runs this under xvfb-run)");
    }
    Renderer renderer(test::small_config(false), Backend::osmesa);
    const Snapshot s = test::gas_snapshot(10, 0.05, {1.0, 1.0, Boundary::walls}, 2);
    FrameContent frame;
    frame.panels = {{&s, "", {}}};
    const Image image = renderer.render(frame);
    const auto preview = open_preview(320, 180, "collide test");
    REQUIRE(preview != nullptr);
    CHECK(preview->show(image));
    CHECK(preview->show(image));
    // The renderer still works after the preview's context was current.
    CHECK(renderer.render(frame).rgba == image.rgba);
}

}  // namespace
}  // namespace collide::render
