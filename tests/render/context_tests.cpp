// Context backends: OSMesa by default (EGL where OSMesa is not built), EGL surfaceless with the
// same pixels, GLFW when a display exists (same pixels again); without a display GLFW gives a
// one-line notice and the offscreen default, never a failure. The display-dependent tests run under
// `xvfb-run -a` through extra ctest entries (tests/CMakeLists.txt) and skip when DISPLAY is unset.
#include <doctest/doctest.h>

#include <cstdlib>
#include <memory>
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

/// What `auto` stands for in this build: OSMesa where built, else EGL.
Backend offscreen_default() {
    return is_available(Backend::osmesa) ? Backend::osmesa : Backend::egl;
}

FrameContent one_panel(const Snapshot& s) {
    FrameContent frame;
    frame.panels = {{&s, "", {}}};
    return frame;
}

TEST_CASE("auto renders offscreen: OSMesa where built, else EGL, with no display") {
    ::unsetenv("DISPLAY");
    ::unsetenv("WAYLAND_DISPLAY");
    REQUIRE((is_available(Backend::osmesa) || is_available(Backend::egl)));
    Renderer renderer(test::small_config(false));
    CHECK(renderer.backend() == offscreen_default());
    const Snapshot s = test::gas_snapshot(10, 0.05, {1.0, 1.0, Boundary::walls}, 2);
    CHECK(renderer.render(one_panel(s)).width == 320);
    CHECK_THROWS_AS((void)make_context(Backend::automatic, 0, 10), Error);
}

TEST_CASE("backend names parse back, and unknown names list the known ones") {
    for (const Backend backend :
         {Backend::automatic, Backend::osmesa, Backend::egl, Backend::egl_device, Backend::glfw}) {
        CHECK(parse_backend(backend_name(backend)) == backend);
    }
    CHECK_THROWS_WITH_AS((void)parse_backend("vulkan", "--gl"),
                         doctest::Contains("--gl: expected a GL backend (auto, osmesa, egl, "
                                           "egl-device or glfw), got 'vulkan'"),
                         Error);
}

TEST_CASE("a backend this build lacks is refused with the list of those it has") {
    const std::vector<Backend> available = available_backends();
    REQUIRE(available.size() >= 3);  // auto, glfw and at least one offscreen backend
    CHECK(available.front() == Backend::automatic);
    std::string listed;
    for (const Backend backend : available) {
        listed += (listed.empty() ? "" : ", ") + std::string(backend_name(backend));
    }
    bool some_missing = false;
    for (const Backend backend : {Backend::osmesa, Backend::egl, Backend::egl_device}) {
        if (is_available(backend)) continue;
        some_missing = true;
        CHECK_THROWS_WITH_AS((void)make_context(backend, 16, 16),
                             doctest::Contains(("(available: " + listed + ")").c_str()), Error);
    }
    if (!some_missing) CHECK(listed == "auto, osmesa, egl, egl-device, glfw");
}

TEST_CASE("EGL surfaceless gives the same pixels as OSMesa") {
    if (!is_available(Backend::osmesa) || !is_available(Backend::egl)) {
        COLLIDE_SKIP_TEST("this build lacks OSMesa or EGL");
    }
    const Snapshot a = test::gas_snapshot(80, 0.03, {1.0, 1.0, Boundary::walls}, 4);
    const Snapshot b = test::gas_snapshot(80, 0.03, {1.0, 1.0, Boundary::periodic}, 5);
    const RenderConfig config = test::small_config(true);
    Image from_egl;
    {
        Renderer egl(config, Backend::egl);
        // On a machine with a GPU, `egl` takes it: different rasteriser, different pixels.
        if (egl.backend() != Backend::egl) {
            COLLIDE_SKIP_TEST("EGL chose a GPU device here, not the surfaceless platform");
        }
        from_egl = egl.render(sample_frame(a, b));
    }
    Renderer osmesa(config, Backend::osmesa);
    const Image from_osmesa = osmesa.render(sample_frame(a, b));
    test::dump_if_requested(from_egl, "context_egl");
    REQUIRE(from_egl.rgba.size() == from_osmesa.rgba.size());
    CHECK(from_egl.rgba == from_osmesa.rgba);
}

TEST_CASE("an EGL device context renders") {
    if (!is_available(Backend::egl_device)) {
        COLLIDE_SKIP_TEST("this build has no EGL");
    }
    std::unique_ptr<Context> context;
    try {
        context = make_context(Backend::egl_device, 320, 180);
    } catch (const Error& e) {
        COLLIDE_SKIP_TEST("no EGL device here: " << e.what());
    }
    CHECK(context->backend() == Backend::egl_device);
    Renderer renderer(test::small_config(false), std::move(context));
    const Snapshot s = test::gas_snapshot(10, 0.05, {1.0, 1.0, Boundary::walls}, 2);
    const Image image = renderer.render(one_panel(s));
    CHECK(image.width == 320);
    // Something was drawn: the frame is not one flat colour.
    bool varied = false;
    for (std::size_t i = 4; i < image.rgba.size() && !varied; ++i) {
        varied = image.rgba[i] != image.rgba[i % 4];
    }
    CHECK(varied);
}

TEST_CASE("without a display, GLFW falls back to the offscreen default with one notice") {
    ::unsetenv("DISPLAY");
    ::unsetenv("WAYLAND_DISPLAY");
    std::vector<std::string> notices;
    const NoticeSink sink = [&](const std::string& line) { notices.push_back(line); };
    Renderer renderer(test::small_config(false), Backend::glfw, sink);
    CHECK(renderer.backend() == offscreen_default());
    REQUIRE(notices.size() == 1);
    CHECK(notices[0].find("rendering with " + std::string(backend_name(offscreen_default()))) !=
          std::string::npos);
    CHECK(notices[0].find('\n') == std::string::npos);
    // And it renders.
    const Snapshot s = test::gas_snapshot(10, 0.05, {1.0, 1.0, Boundary::walls}, 2);
    CHECK(renderer.render(one_panel(s)).width == 320);

    notices.clear();
    const auto preview = open_preview(320, 180, "collide", sink);
    CHECK(preview == nullptr);
    CHECK(notices.size() == 1);
}

TEST_CASE("display: the GLFW backend produces the same pixels as the offscreen one") {
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
    Renderer offscreen(config, Backend::automatic);
    const Image from_osmesa = offscreen.render(sample_frame(a, b));
    test::dump_if_requested(from_glfw, "context_glfw");
    CHECK(notices.empty());
    REQUIRE(from_glfw.rgba.size() == from_osmesa.rgba.size());
    CHECK(from_glfw.rgba == from_osmesa.rgba);
}

TEST_CASE("display: the preview window shows frames") {
    if (!have_display()) {
        COLLIDE_SKIP_TEST("DISPLAY is not set (the xvfb ctest entry runs this under xvfb-run)");
    }
    const auto frame_of = [](const Snapshot& s) {
        FrameContent frame;
        frame.panels = {{&s, "", {}}};
        return frame;
    };
    std::vector<Snapshot> snapshots;
    for (unsigned seed = 2; seed < 22; ++seed) {
        snapshots.push_back(test::gas_snapshot(10, 0.05, {1.0, 1.0, Boundary::walls}, seed));
    }
    std::vector<Image> expected;  // the frames (trails and all) when nothing else draws
    {
        Renderer alone(test::small_config(false), Backend::glfw);
        for (const Snapshot& s : snapshots) expected.push_back(alone.render(frame_of(s)));
    }
    // As `collide render --preview` does: the window first, then the renderer on GLFW (one GL
    // implementation for both: docs/renderer.md, "Preview"), every frame rendered then shown.
    const auto preview = open_preview(320, 180, "collide test");
    REQUIRE(preview != nullptr);
    Renderer renderer(test::small_config(false), Backend::glfw);
    REQUIRE(renderer.backend() == Backend::glfw);
    for (std::size_t i = 0; i < snapshots.size(); ++i) {
        const Image image = renderer.render(frame_of(snapshots[i]));
        CHECK(image.rgba == expected[i].rgba);  // the preview's drawing leaves the frames alone
        CHECK(preview->show(image));
    }
}

}  // namespace
}  // namespace collide::render
